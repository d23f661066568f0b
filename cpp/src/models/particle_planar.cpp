#include "rigiddyn/check.hpp"
#include "rigiddyn/models/particle.hpp"
#include "rigiddyn/models/planar_body.hpp"

namespace rigiddyn {

Particle::Particle(double mass) : mass_(mass) { require_positive(mass, "mass"); }

ParticleState checked_state(const ParticleState& state, const std::string& name) {
  require_finite(state.p_W, name + ".p_W");
  require_finite(state.v_W, name + ".v_W");
  return state;
}

ParticleCoordinates to_coordinates(const ParticleState& state, double work) {
  ParticleCoordinates y;
  y << state.p_W, state.v_W, work;
  return y;
}

ParticleState to_particle_state(const ParticleCoordinates& y) { return {y.segment<3>(0), y.segment<3>(3)}; }

PlanarBody::PlanarBody(double mass, double inertia_zz) : mass_(mass), inertia_zz_(inertia_zz) {
  require_positive(mass, "mass");
  require_positive(inertia_zz, "inertia_zz");
}

PlanarBodyState checked_state(const PlanarBodyState& state, const std::string& name) {
  require_finite(state.p_W, name + ".p_W");
  require_finite(state.theta, name + ".theta");
  require_finite(state.v_W, name + ".v_W");
  require_finite(state.omega, name + ".omega");
  return state;
}

PlanarBodyCoordinates to_coordinates(const PlanarBodyState& state, double work) {
  PlanarBodyCoordinates y;
  y << state.p_W, state.theta, state.v_W, state.omega, work;
  return y;
}

PlanarBodyState to_planar_state(const PlanarBodyCoordinates& y) {
  return {y.segment<2>(0), y(2), y.segment<2>(3), y(5)};
}

}  // namespace rigiddyn
