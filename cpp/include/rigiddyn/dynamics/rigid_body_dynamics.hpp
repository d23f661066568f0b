// Newton–Euler dynamics of one rigid body about its centre of mass G (Craig "Equations of motion",
// "Principle of linear/angular impulse and momentum", "Kinetic energy"; Rigid-body notes §4.11):
//   m a_G = f,  I α + ω × I ω = τ_G,   H_G = I ω,  T = ½ m v·v + ½ ω·I ω.
// Frames: f_W, v_W, a_W in W; ω_B, α_B, τ_B and the inertia in B (Euler's equations live in B).
// Gravity: g_W defaults to zero everywhere (docs/conventions.md, "no gravity unless asked").
#pragma once
#include "rigiddyn/models/rigid_body.hpp"
#include "rigiddyn/so3/integrate.hpp"  // Frame

#include <Eigen/Core>

namespace rigiddyn {

// The resultant of applied loads reduced to G: force f_W [N] in W and torque tau_B [N m] about G in B.
struct ComWrench {
  Eigen::Vector3d f_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d tau_B = Eigen::Vector3d::Zero();
};

// Accelerations: of the centre of mass a_W [m/s²] in W, angular α_B = ω̇_B [rad/s²] in B.
struct BodyAcceleration {
  Eigen::Vector3d a_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d alpha_B = Eigen::Vector3d::Zero();
};

// A force `force` [N] applied at point P and a torque `torque` [N m], both expressed in `frame`,
// with p_GP [m] the position of P relative to G, also expressed in `frame`, reduced to G:
// f = force, τ_G = torque + p_GP × force (moment transfer), then f to W and τ_G to B.
ComWrench wrench_at_com(const Eigen::Quaterniond& q_WB, const Eigen::Vector3d& force, const Eigen::Vector3d& torque,
                        const Eigen::Vector3d& p_GP, Frame frame);

// Forward dynamics: a_W = f_W/m + g_W, α_B = I⁻¹ (τ_B − ω × I ω).
BodyAcceleration forward_dynamics(const RigidBody& body, const RigidBodyState& state, const ComWrench& wrench,
                                  const Eigen::Vector3d& g_W = Eigen::Vector3d::Zero());

// Inverse dynamics, the wrench the motion requires: f_W = m (a_W − g_W), τ_B = I α + ω × I ω.
ComWrench inverse_dynamics(const RigidBody& body, const RigidBodyState& state, const BodyAcceleration& acceleration,
                           const Eigen::Vector3d& g_W = Eigen::Vector3d::Zero());

// Linear momentum L = m v_W [kg m/s] in W.
Eigen::Vector3d linear_momentum(const RigidBody& body, const RigidBodyState& state);

// Angular momentum about the point P fixed in W at p_WP [m] (default: the world origin O, as the
// "Rigid body kinematics and dynamics" notes define it, eq. (4.65)), expressed in W [kg m²/s]:
// H_P = R_WB I ω_B + (p_WG − p_WP) × m v_W. About the centre of mass: p_WP = state.p_W (H_G = R_WB I ω_B).
Eigen::Vector3d angular_momentum(const RigidBody& body, const RigidBodyState& state,
                                 const Eigen::Vector3d& p_WP = Eigen::Vector3d::Zero());

// T = T_translation + T_rotation [J], T_translation = ½ m v·v, T_rotation = ½ ω·I ω.
struct KineticEnergy {
  double translational = 0.0;
  double rotational = 0.0;
  double total() const { return translational + rotational; }
};
KineticEnergy kinetic_energy(const RigidBody& body, const RigidBodyState& state);

// Potential energy of uniform gravity g_W [m/s²] in W: V = −m g_W·p_WG [J] (zero at the origin of W;
// zero without gravity, the default).
double potential_energy(const RigidBody& body, const RigidBodyState& state,
                        const Eigen::Vector3d& g_W = Eigen::Vector3d::Zero());

// Power of a wrench reduced to G [W]: P = f_W·v_W + τ_B·ω_B.
double power(const RigidBodyState& state, const ComWrench& wrench);

// Impulse–momentum (Craig): an impulse `impulse` [N s] at point P (p_GP [m] from G) and an
// angular impulse `angular_impulse` [N m s], both in `frame`, change the velocities instantly:
//   m Δv = impulse,  I Δω_B = (p_GP × impulse + angular_impulse) in B.  Position and attitude unchanged.
RigidBodyState apply_impulse(const RigidBody& body, const RigidBodyState& state, const Eigen::Vector3d& impulse,
                             const Eigen::Vector3d& p_GP, Frame frame,
                             const Eigen::Vector3d& angular_impulse = Eigen::Vector3d::Zero());

}  // namespace rigiddyn
