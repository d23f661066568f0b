// Dynamics of a particle (point mass; Rigid-body notes §4.11, Craig "Principle of linear impulse and
// momentum"): m a = f + m g,  L = m v,  H_P = (p − p_P) × m v,  T = ½ m v·v.
// Everything in the world frame W. The same function names as the rigid body's
// (rigid_body_dynamics.hpp), as overloads; a particle has no rotation, so its rotational parts are 0.
#pragma once
#include "rigiddyn/dynamics/rigid_body_dynamics.hpp"  // KineticEnergy
#include "rigiddyn/models/particle.hpp"

#include <Eigen/Core>

namespace rigiddyn {

// Forward dynamics: a_W = f_W/m + g_W [m/s²], for a force f_W [N] and gravity g_W [m/s²], in W.
Eigen::Vector3d forward_dynamics(const Particle& particle, const ParticleState& state, const Eigen::Vector3d& f_W,
                                 const Eigen::Vector3d& g_W = Eigen::Vector3d::Zero());

// Inverse dynamics, the applied force the motion requires: f_W = m (a_W − g_W) [N] in W.
Eigen::Vector3d inverse_dynamics(const Particle& particle, const ParticleState& state, const Eigen::Vector3d& a_W,
                                 const Eigen::Vector3d& g_W = Eigen::Vector3d::Zero());

// Linear momentum L = m v_W [kg m/s] in W.
Eigen::Vector3d linear_momentum(const Particle& particle, const ParticleState& state);

// Angular momentum (moment of momentum) about the point P fixed in W at p_WP [m] (default: the world
// origin O, "Rigid body kinematics and dynamics" notes, eq. (4.42) l = r × m ṙ), in W [kg m²/s]:
// H_P = (p_W − p_WP) × m v_W.
Eigen::Vector3d angular_momentum(const Particle& particle, const ParticleState& state,
                                 const Eigen::Vector3d& p_WP = Eigen::Vector3d::Zero());

// T = ½ m v·v, all translational (rotational = 0) [J].
KineticEnergy kinetic_energy(const Particle& particle, const ParticleState& state);

// Potential energy of uniform gravity g_W [m/s²] in W: V = −m g_W·p_W [J] (zero at the origin of W;
// zero without gravity, the default).
double potential_energy(const Particle& particle, const ParticleState& state,
                        const Eigen::Vector3d& g_W = Eigen::Vector3d::Zero());

// Power of a force f_W [N] (in W) on the particle [W]: P = f_W·v_W.
double power(const ParticleState& state, const Eigen::Vector3d& f_W);

// Impulse–momentum (Craig): an impulse [N s] in W changes the velocity instantly, m Δv = impulse.
ParticleState apply_impulse(const Particle& particle, const ParticleState& state, const Eigen::Vector3d& impulse);

}  // namespace rigiddyn
