#include "rigiddyn/dynamics/planar_body_dynamics.hpp"

#include <Eigen/Geometry>

namespace rigiddyn {

PlanarWrench wrench_at_com(double theta, const Eigen::Vector2d& force, double torque, const Eigen::Vector2d& p_GP,
                           Frame frame) {
  const Eigen::Vector2d f_W = frame == Frame::body ? Eigen::Rotation2Dd(theta) * force : force;
  // torque about G of the force at P plus the applied torque (moment transfer, Craig)
  return {f_W, torque + cross2(p_GP, force)};
}

PlanarAcceleration forward_dynamics(const PlanarBody& body, const PlanarBodyState& /*state*/,
                                    const PlanarWrench& wrench, const Eigen::Vector2d& g_W) {
  return {wrench.f_W / body.mass() + g_W, wrench.tau / body.inertia_zz()};
}

PlanarWrench inverse_dynamics(const PlanarBody& body, const PlanarBodyState& /*state*/,
                              const PlanarAcceleration& acceleration, const Eigen::Vector2d& g_W) {
  return {body.mass() * (acceleration.a_W - g_W), body.inertia_zz() * acceleration.alpha};
}

Eigen::Vector2d linear_momentum(const PlanarBody& body, const PlanarBodyState& state) {
  return body.mass() * state.v_W;
}

double angular_momentum(const PlanarBody& body, const PlanarBodyState& state, const Eigen::Vector2d& p_WP) {
  return body.inertia_zz() * state.omega + cross2(state.p_W - p_WP, linear_momentum(body, state));
}

KineticEnergy kinetic_energy(const PlanarBody& body, const PlanarBodyState& state) {
  return {0.5 * body.mass() * state.v_W.squaredNorm(), 0.5 * body.inertia_zz() * state.omega * state.omega};
}

double potential_energy(const PlanarBody& body, const PlanarBodyState& state, const Eigen::Vector2d& g_W) {
  return -body.mass() * g_W.dot(state.p_W);
}

double power(const PlanarBodyState& state, const PlanarWrench& wrench) {
  return wrench.f_W.dot(state.v_W) + wrench.tau * state.omega;
}

PlanarBodyState apply_impulse(const PlanarBody& body, const PlanarBodyState& state, const Eigen::Vector2d& impulse,
                              const Eigen::Vector2d& p_GP, Frame frame, double angular_impulse) {
  const PlanarWrench J = wrench_at_com(state.theta, impulse, angular_impulse, p_GP, frame);
  PlanarBodyState out = state;
  out.v_W += J.f_W / body.mass();
  out.omega += J.tau / body.inertia_zz();
  return out;
}

}  // namespace rigiddyn
