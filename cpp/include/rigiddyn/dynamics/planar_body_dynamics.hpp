// Dynamics of a planar rigid body (x, y, θ in the xy plane of W; Craig "plane kinetics"):
//   m a_G = f,  I_zz α = τ_G,  L = m v,  H_P = I_zz ω + (p_G − p_P) × m v,  T = ½ m v·v + ½ I_zz ω².
// In-plane vectors are (2,) in W unless said otherwise; torques and angular quantities are the z
// components (scalars). Gravity g_W defaults to zero (docs/conventions.md). The same names as the rigid body's (rigid_body_dynamics.hpp), as overloads;
// each result equals the spatial body's for a motion kept in the plane.
#pragma once
#include "rigiddyn/dynamics/rigid_body_dynamics.hpp"  // KineticEnergy
#include "rigiddyn/models/planar_body.hpp"
#include "rigiddyn/so3/integrate.hpp"  // Frame

#include <Eigen/Core>

namespace rigiddyn {

// The in-plane resultant reduced to G: force f_W [N] (2,) in W and torque tau [N m] about G (z).
struct PlanarWrench {
  Eigen::Vector2d f_W = Eigen::Vector2d::Zero();
  double tau = 0.0;
};

// Accelerations: of the centre of mass a_W [m/s²] (2,) in W and angular α = θ̈ [rad/s²].
struct PlanarAcceleration {
  Eigen::Vector2d a_W = Eigen::Vector2d::Zero();
  double alpha = 0.0;
};

// 2-D cross product a × b = a_x b_y − a_y b_x (the z component of the 3-D one).
inline double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// A force `force` [N] (2,) at point P and a torque `torque` [N m] (z), with p_GP [m] (2,) the position
// of P relative to G; force and p_GP expressed in `frame` (B turns by θ about z). Reduced to G:
// f_W = R(θ) force (body frame) or force, τ = torque + p_GP × force (the 2-D cross product does not
// depend on the frame).
PlanarWrench wrench_at_com(double theta, const Eigen::Vector2d& force, double torque, const Eigen::Vector2d& p_GP,
                           Frame frame);

// Forward dynamics: a_W = f_W/m + g_W, α = τ / I_zz (no gyroscopic term in plane motion).
PlanarAcceleration forward_dynamics(const PlanarBody& body, const PlanarBodyState& state, const PlanarWrench& wrench,
                                    const Eigen::Vector2d& g_W = Eigen::Vector2d::Zero());

// Inverse dynamics, the wrench the motion requires: f_W = m (a_W − g_W), τ = I_zz α.
PlanarWrench inverse_dynamics(const PlanarBody& body, const PlanarBodyState& state,
                              const PlanarAcceleration& acceleration,
                              const Eigen::Vector2d& g_W = Eigen::Vector2d::Zero());

// Linear momentum L = m v_W [kg m/s] (2,) in W.
Eigen::Vector2d linear_momentum(const PlanarBody& body, const PlanarBodyState& state);

// Angular momentum (z) [kg m²/s] about the point P fixed in W at p_WP [m] (2,) (default: the world
// origin O, as for the spatial body): H_P = I_zz ω + (p_W − p_WP) × m v_W. About G: p_WP = state.p_W.
double angular_momentum(const PlanarBody& body, const PlanarBodyState& state,
                        const Eigen::Vector2d& p_WP = Eigen::Vector2d::Zero());

// T = ½ m v·v (translational) + ½ I_zz ω² (rotational) [J].
KineticEnergy kinetic_energy(const PlanarBody& body, const PlanarBodyState& state);

// Potential energy of uniform in-plane gravity g_W [m/s²] (2,): V = −m g_W·p_W [J] (zero without
// gravity, the default).
double potential_energy(const PlanarBody& body, const PlanarBodyState& state,
                        const Eigen::Vector2d& g_W = Eigen::Vector2d::Zero());

// Power of a wrench reduced to G [W]: P = f_W·v_W + τ ω.
double power(const PlanarBodyState& state, const PlanarWrench& wrench);

// Impulse–momentum (Craig): an impulse [N s] (2,) at point P (p_GP [m] (2,) from G) and an angular
// impulse [N m s] (z), in `frame`, change the velocities instantly: m Δv = impulse,
// I_zz Δω = p_GP × impulse + angular_impulse. Position and angle unchanged.
PlanarBodyState apply_impulse(const PlanarBody& body, const PlanarBodyState& state, const Eigen::Vector2d& impulse,
                              const Eigen::Vector2d& p_GP, Frame frame, double angular_impulse = 0.0);

}  // namespace rigiddyn
