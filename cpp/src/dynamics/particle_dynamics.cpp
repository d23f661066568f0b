#include "rigiddyn/dynamics/particle_dynamics.hpp"

namespace rigiddyn {

Eigen::Vector3d forward_dynamics(const Particle& particle, const ParticleState& /*state*/, const Eigen::Vector3d& f_W,
                                 const Eigen::Vector3d& g_W) {
  return f_W / particle.mass() + g_W;
}

Eigen::Vector3d inverse_dynamics(const Particle& particle, const ParticleState& /*state*/, const Eigen::Vector3d& a_W,
                                 const Eigen::Vector3d& g_W) {
  return particle.mass() * (a_W - g_W);
}

Eigen::Vector3d linear_momentum(const Particle& particle, const ParticleState& state) {
  return particle.mass() * state.v_W;
}

Eigen::Vector3d angular_momentum(const Particle& particle, const ParticleState& state, const Eigen::Vector3d& p_WP) {
  return (state.p_W - p_WP).cross(linear_momentum(particle, state));
}

KineticEnergy kinetic_energy(const Particle& particle, const ParticleState& state) {
  return {0.5 * particle.mass() * state.v_W.squaredNorm(), 0.0};
}

double potential_energy(const Particle& particle, const ParticleState& state, const Eigen::Vector3d& g_W) {
  return -particle.mass() * g_W.dot(state.p_W);
}

double power(const ParticleState& state, const Eigen::Vector3d& f_W) { return f_W.dot(state.v_W); }

ParticleState apply_impulse(const Particle& particle, const ParticleState& state, const Eigen::Vector3d& impulse) {
  return {state.p_W, state.v_W + impulse / particle.mass()};
}

}  // namespace rigiddyn
