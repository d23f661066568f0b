// simulate of a particle and a planar body (simulate/simulate.hpp): their own translation unit, so that it builds
// beside simulate.cpp (the rigid body's runs).
#include "rigiddyn/simulate/simulate.hpp"

#include "append_record.hpp"

#include "rigiddyn/check.hpp"

#include <string>
#include <type_traits>

namespace rigiddyn {

namespace {

void check_particle_loads(const SimulationOptions& o) {
  for (std::size_t i = 0; i < o.loads.size(); ++i) {
    if (!o.loads[i].torque.isZero(0.0)) {
      throw_invalid("loads[" + std::to_string(i) + "].torque", "zero (a particle takes no torque)", o.loads[i].torque);
    }
  }
}

void check_planar_loads(const SimulationOptions& o) {
  for (std::size_t i = 0; i < o.loads.size(); ++i) {
    const std::string name = "loads[" + std::to_string(i) + "]";
    if (o.loads[i].force.z() != 0.0) throw_invalid(name + ".force", "a force in the xy plane (z = 0)", o.loads[i].force);
    if (!o.loads[i].torque.head<2>().isZero(0.0)) {
      throw_invalid(name + ".torque", "a torque about z only (x = y = 0)", o.loads[i].torque);
    }
  }
  if (o.gravity_W.z() != 0.0) throw_invalid("gravity", "gravity in the xy plane (z = 0)", o.gravity_W);
}

}  // namespace

Trajectory simulate(const Particle& particle, const ParticleState& initial, const SimulationOptions& o) {
  check_options(o, true);
  check_particle_loads(o);
  const ParticleModel model(particle, o.gravity_W);
  const ParticleCoordinates y = to_coordinates(checked_state(initial, "initial"));
  return visit_method(o.method, [&](auto integrator) { return run_one_body<decltype(integrator)>(model, y, o); });
}

Trajectory simulate(const PlanarBody& body, const PlanarBodyState& initial, const SimulationOptions& o) {
  check_options(o, true);
  check_planar_loads(o);
  const PlanarBodyModel model(body, o.gravity_W);
  const PlanarBodyCoordinates y = to_coordinates(checked_state(initial, "initial"));
  return visit_method(o.method, [&](auto integrator) { return run_one_body<decltype(integrator)>(model, y, o); });
}

}  // namespace rigiddyn
