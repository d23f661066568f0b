#include "rigiddyn/dynamics/rigid_body_dynamics.hpp"

namespace rigiddyn {

namespace {

// v expressed in B given it is expressed in `frame`.
Eigen::Vector3d to_body(const Eigen::Quaterniond& q_WB, const Eigen::Vector3d& v, Frame frame) {
  return frame == Frame::body ? v : Eigen::Vector3d(q_WB.conjugate() * v);
}

}  // namespace

ComWrench wrench_at_com(const Eigen::Quaterniond& q_WB, const Eigen::Vector3d& force, const Eigen::Vector3d& torque,
                        const Eigen::Vector3d& p_GP, Frame frame) {
  const Eigen::Vector3d f_B = to_body(q_WB, force, frame);
  // torque about G of the force at P plus the applied torque (moment transfer, Craig)
  const Eigen::Vector3d tau_B = to_body(q_WB, torque + p_GP.cross(force), frame);
  return {q_WB * f_B, tau_B};
}

// Euler's equations in FullEuler, their form for any inertia (models/euler_equations.hpp, the one home of
// Euler's equations; the stored I⁻¹ rounds within κ(I) ε, as the solve with I did). Not with_euler_form's
// choice: it drops products of inertia and moment differences below 1e-12 relative, right for an
// integrator's step, not for an evaluation that is exact to round-off.
BodyAcceleration forward_dynamics(const RigidBody& body, const RigidBodyState& state, const ComWrench& wrench,
                                  const Eigen::Vector3d& g_W) {
  return {wrench.f_W / body.mass() + g_W, FullEuler(body.inertia_com()).angular_acceleration(state.w_B, wrench.tau_B)};
}

ComWrench inverse_dynamics(const RigidBody& body, const RigidBodyState& state, const BodyAcceleration& acceleration,
                           const Eigen::Vector3d& g_W) {
  return {body.mass() * (acceleration.a_W - g_W), euler_torque(FullEuler(body.inertia_com()), state.w_B, acceleration.alpha_B)};
}

Eigen::Vector3d linear_momentum(const RigidBody& body, const RigidBodyState& state) { return body.mass() * state.v_W; }

Eigen::Vector3d angular_momentum(const RigidBody& body, const RigidBodyState& state, const Eigen::Vector3d& p_WP) {
  const Eigen::Vector3d H_G_W = state.q_WB * (body.inertia_com() * state.w_B);
  return H_G_W + (state.p_W - p_WP).cross(body.mass() * state.v_W);
}

KineticEnergy kinetic_energy(const RigidBody& body, const RigidBodyState& state) {
  return {0.5 * body.mass() * state.v_W.squaredNorm(), 0.5 * state.w_B.dot(body.inertia_com() * state.w_B)};
}

double potential_energy(const RigidBody& body, const RigidBodyState& state, const Eigen::Vector3d& g_W) {
  return -body.mass() * g_W.dot(state.p_W);
}

double power(const RigidBodyState& state, const ComWrench& wrench) {
  return wrench.f_W.dot(state.v_W) + wrench.tau_B.dot(state.w_B);
}

RigidBodyState apply_impulse(const RigidBody& body, const RigidBodyState& state, const Eigen::Vector3d& impulse,
                             const Eigen::Vector3d& p_GP, Frame frame, const Eigen::Vector3d& angular_impulse) {
  const ComWrench J = wrench_at_com(state.q_WB, impulse, angular_impulse, p_GP, frame);
  RigidBodyState out = state;
  out.v_W += J.f_W / body.mass();
  out.w_B += body.inertia_com().llt().solve(J.tau_B);
  return out;
}

}  // namespace rigiddyn
