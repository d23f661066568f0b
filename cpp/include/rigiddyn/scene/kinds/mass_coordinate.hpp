// What a body with a MassFlow adds to its kind (scene/mass_flow.hpp; the kinds mass_particle_slot.hpp and
// mass_rigid_slot.hpp): its mass m [kg] as a coordinate right after its own block (tangent ṁ), and its mass-flow
// energy E_b [J] among the slots after t (dE_b/dt = its mass-flow power; scene_model.hpp has the balance).
#pragma once
#include "rigiddyn/scene/kinds/body_slot.hpp"
#include "rigiddyn/scene/mass_flow.hpp"

#include <string>

namespace rigiddyn::detail {

struct MassCoordinate {
  Eigen::Index m_y, m_xi;  // the mass in y, ṁ in ξ
  MassFlow flow;
  double m0;                          // the initial mass [kg]
  std::string flow_name, body_name;   // "mass_flows[i]", the body's name (the out-of-mass message)
  Eigen::Index energy;                // its mass-flow energy's rank among the bodies with a MassFlow
  Eigen::Index energy_y = -1, energy_xi = -1;  // where E_b is in y and ξ (set by the model once t's place is known)

  // m in y, when positive; else the out-of-mass error (mass_flow.hpp) at the clock's t, in its step
  double checked_mass(const double* y, const StepClock& clock) const {
    const double m = y[m_y];
    if (!(m > 0.0)) throw_out_of_mass(flow_name, body_name, m, clock.t, clock.step_start);
    return m;
  }
  // ṁ [kg/s] at the clock's t
  double rate_at(const StepClock& clock) const { return mass_rate(flow, clock.t, flow_name); }
};

// m += dm for the body of the mass slot s at fixed velocities, and E_b += the exact change of T that makes
// (s.kinetic_energy_change); the out-of-mass error (at t, in the step from step_start) when the new mass is not
// positive
template <class MassSlot>
void change_mass(const MassSlot& s, double* y, double dm, double t, double step_start) {
  const MassCoordinate& c = s.mass;
  const double m = y[c.m_y], m_new = m + dm;
  if (!(m_new > 0.0)) throw_out_of_mass(c.flow_name, c.body_name, m_new, t, step_start);
  y[c.energy_y] += s.kinetic_energy_change(y, m, m_new);
  y[c.m_y] = m_new;
}

}  // namespace rigiddyn::detail
