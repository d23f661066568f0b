#include "rigiddyn/simulate/simulate.hpp"

#include "append_record.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/simulate/simulate_exact.hpp"

#include <chrono>
#include <cmath>
#include <type_traits>

namespace rigiddyn {

namespace {

void check_options(const SimulationOptions& o, bool stepping) {
  require_positive(o.dt, "dt");
  require_finite(o.t0, "t0");
  require_finite(o.gravity_W, "gravity");
  if (stepping) {
    if (o.steps < 0) throw_invalid("steps", "an integer >= 0", o.steps);
    if (o.record_every < 1) throw_invalid("record_every", "an integer >= 1", o.record_every);
  }
  check_loads(o.loads);
}

void check_particle_loads(const SimulationOptions& o) {
  for (std::size_t i = 0; i < o.loads.size(); ++i) {
    if (!o.loads[i].torque.isZero(0.0)) {
      throw_invalid("loads[" + std::to_string(i) + "].torque", "zero (a particle takes no couple)", o.loads[i].torque);
    }
  }
}

void check_planar_loads(const SimulationOptions& o) {
  for (std::size_t i = 0; i < o.loads.size(); ++i) {
    const std::string name = "loads[" + std::to_string(i) + "]";
    if (o.loads[i].force.z() != 0.0) throw_invalid(name + ".force", "a force in the xy plane (z = 0)", o.loads[i].force);
    if (!o.loads[i].torque.head<2>().isZero(0.0)) {
      throw_invalid(name + ".torque", "a couple about z only (x = y = 0)", o.loads[i].torque);
    }
  }
  if (o.gravity_W.z() != 0.0) throw_invalid("gravity", "gravity in the xy plane (z = 0)", o.gravity_W);
}

void reserve(Trajectory& out, const SimulationOptions& o) {
  const std::size_t n = static_cast<std::size_t>(o.steps / o.record_every + 2);
  for (auto* v : {&out.t, &out.kinetic_energy, &out.total_energy, &out.angular_momentum_norm,
                  &out.quaternion_norm_error, &out.work}) v->reserve(n);
  for (auto* v : {&out.p_W, &out.v_W, &out.w_B}) v->reserve(3 * n);
  out.q_WB.reserve(4 * n);
}

// The stepping loop, compiled per (model, integrator): records step 0, every record_every-th
// step and the last one; stops after recording a non-finite state.
template <class Integrator, class Model>
Trajectory run(Model model, typename Model::Coordinates y, const SimulationOptions& o) {
  Trajectory out;
  reserve(out, o);
  const bool varying_loads = !is_constant_from(o.loads, o.t0);
  model.set_loads(loads_at(o.loads, o.t0));
  append_record(out, o.t0, model.record(y));
  const auto start = std::chrono::steady_clock::now();
  std::int64_t until_record = o.record_every;
  for (std::int64_t i = 1; i <= o.steps; ++i) {
    if (varying_loads) model.set_loads(loads_at(o.loads, o.t0 + static_cast<double>(i - 1) * o.dt));
    if constexpr (std::is_same_v<decltype(Integrator::step(model, y, o.dt)), bool>) {
      out.unconverged_steps += Integrator::step(model, y, o.dt) ? 0 : 1;  // implicit: converged?
    } else {
      Integrator::step(model, y, o.dt);
    }
    if (--until_record == 0 || i == o.steps) {
      until_record = o.record_every;
      append_record(out, o.t0 + static_cast<double>(i) * o.dt, model.record(y));
      if (!y.allFinite()) {
        out.diverged = true;
        break;
      }
    }
  }
  out.elapsed_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

// True for the integrators written only against model_interface.hpp (any model type works).
template <class Integrator>
inline constexpr bool uses_model_interface_only =
    std::is_same_v<Integrator, ExplicitEuler> || std::is_same_v<Integrator, SemiImplicitEuler> ||
    std::is_same_v<Integrator, SemiImplicitEulerImplicitGyroscopic> || std::is_same_v<Integrator, Rk4> ||
    std::is_same_v<Integrator, Rkmk4>;

template <class Model>
typename Model::Coordinates one_step(Model model, typename Model::Coordinates y, const SimulationOptions& o) {
  model.set_loads(loads_at(o.loads, o.t0));
  visit_method(o.method, [&](auto integrator) { decltype(integrator)::step(model, y, o.dt); });
  return y;
}

}  // namespace

Trajectory simulate(const RigidBody& body, const RigidBodyState& initial, const SimulationOptions& o) {
  check_options(o, true);
  if (o.method == Method::exact) return simulate_exact(body, initial, o);  // closed form, no stepping
  const RigidBodyCoordinates y = to_coordinates(checked_state(initial, "initial"));
  return with_euler_form(body, [&](const auto& euler) {
    using Euler = std::decay_t<decltype(euler)>;
    return visit_method(o.method, [&](auto integrator) {
      using Integrator = decltype(integrator);
      // the methods written only against the model interface run on a model compiled for the loads
      // of this run (LoadKind); the geometric methods use RigidBodyModel<Euler>'s own structure
      if constexpr (uses_model_interface_only<Integrator>) {
        return with_load_kind(o.loads, o.gravity_W, [&](auto kind) {
          return run<Integrator>(RigidBodyModel<Euler, kind.value>(body.mass(), euler, o.gravity_W), y, o);
        });
      } else {
        return run<Integrator>(RigidBodyModel<Euler>(body.mass(), euler, o.gravity_W), y, o);
      }
    });
  });
}

Trajectory simulate(const Particle& particle, const ParticleState& initial, const SimulationOptions& o) {
  check_options(o, true);
  check_particle_loads(o);
  const ParticleModel model(particle, o.gravity_W);
  const ParticleCoordinates y = to_coordinates(checked_state(initial, "initial"));
  return visit_method(o.method, [&](auto integrator) { return run<decltype(integrator)>(model, y, o); });
}

Trajectory simulate(const PlanarBody& body, const PlanarBodyState& initial, const SimulationOptions& o) {
  check_options(o, true);
  check_planar_loads(o);
  const PlanarBodyModel model(body, o.gravity_W);
  const PlanarBodyCoordinates y = to_coordinates(checked_state(initial, "initial"));
  return visit_method(o.method, [&](auto integrator) { return run<decltype(integrator)>(model, y, o); });
}

RigidBodyState step(const RigidBody& body, const RigidBodyState& state, const SimulationOptions& o) {
  check_options(o, false);
  const RigidBodyCoordinates y = to_coordinates(checked_state(state, "state"));
  return with_euler_form(body, [&](const auto& euler) {
    using Euler = std::decay_t<decltype(euler)>;
    return to_rigid_body_state(one_step(RigidBodyModel<Euler>(body.mass(), euler, o.gravity_W), y, o));
  });
}

ParticleState step(const Particle& particle, const ParticleState& state, const SimulationOptions& o) {
  check_options(o, false);
  check_particle_loads(o);
  return to_particle_state(one_step(ParticleModel(particle, o.gravity_W), to_coordinates(checked_state(state)), o));
}

PlanarBodyState step(const PlanarBody& body, const PlanarBodyState& state, const SimulationOptions& o) {
  check_options(o, false);
  check_planar_loads(o);
  return to_planar_state(one_step(PlanarBodyModel(body, o.gravity_W), to_coordinates(checked_state(state)), o));
}

}  // namespace rigiddyn
