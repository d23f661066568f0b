#include "rigiddyn/dynamics/pivoted_body_dynamics.hpp"

namespace rigiddyn {

// Euler's equations about O in FullEuler, their form for any inertia (as rigid_body_dynamics.cpp does: an
// evaluation exact to round-off, not an integrator's step that may drop terms below 1e-12 relative).
PivotedAcceleration forward_dynamics(const PivotedBody& body, const PivotedBodyState& state, const ComWrench& wrench,
                                     const Eigen::Vector3d& g_W) {
  const BodyWrench at_C{wrench.f_W + body.mass() * g_W, wrench.tau_B};
  const Eigen::Vector3d alpha_B =
      pivoted_angular_acceleration(FullEuler(body.inertia_O()), body.p_OC_B(), state.q_WB, state.w_B, at_C);
  return {alpha_B, pivot_reaction_W(body.mass(), body.p_OC_B(), state.q_WB, state.w_B, alpha_B, at_C.f_W)};
}

PivotedTorque inverse_dynamics(const PivotedBody& body, const PivotedBodyState& state, const Eigen::Vector3d& alpha_B,
                               const Eigen::Vector3d& g_W) {
  const BodyWrench weight{body.mass() * g_W, Eigen::Vector3d::Zero()};
  const Eigen::Vector3d tau_gravity_O = pivoted_torque_O(body.p_OC_B(), state.q_WB, weight);
  const Eigen::Vector3d tau_O = euler_torque(FullEuler(body.inertia_O()), state.w_B, alpha_B) - tau_gravity_O;
  return {tau_O, pivot_reaction_W(body.mass(), body.p_OC_B(), state.q_WB, state.w_B, alpha_B, weight.f_W)};
}

PivotedPlanarAcceleration forward_dynamics(const PivotedPlanarBody& body, const PivotedPlanarBodyState& state,
                                           const ComWrench& wrench, const Eigen::Vector3d& g_W) {
  const Eigen::Vector2d c_W = pivoted_planar_c_W(body.p_OC_B(), state.theta);
  const BodyWrench at_C{wrench.f_W + body.mass() * g_W, wrench.tau_B};
  const double alpha = pivoted_planar_angular_acceleration(body.inertia_O_zz(), c_W, at_C);
  return {alpha, pivoted_planar_reaction_W(body.mass(), c_W, state.omega, alpha, at_C.f_W)};
}

PivotedPlanarTorque inverse_dynamics(const PivotedPlanarBody& body, const PivotedPlanarBodyState& state, double alpha,
                                     const Eigen::Vector3d& g_W) {
  const Eigen::Vector2d c_W = pivoted_planar_c_W(body.p_OC_B(), state.theta);
  const BodyWrench weight{body.mass() * g_W, Eigen::Vector3d::Zero()};
  const double tau_O = body.inertia_O_zz() * alpha - pivoted_planar_torque_O(c_W, weight);
  return {tau_O, pivoted_planar_reaction_W(body.mass(), c_W, state.omega, alpha, weight.f_W)};
}

}  // namespace rigiddyn
