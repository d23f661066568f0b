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

}  // namespace rigiddyn
