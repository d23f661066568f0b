// A gyrostat in the scene model (scene/kinds/body_slot.hpp has the members every kind has; models/gyrostat.hpp the
// equations): a rigid body with N motor-driven wheels, each wheel's speed relative to the body a coordinate, and
// each motor's work since t0 [J] integrated with the motion (dW_k/dt = u_k Ω_k, the motor's power), so that
// T − T(0) = Σ element works + Σ motor works holds to the method's error.
//   y (p_W 3, q_WB xyzw 4, v_W 3, w_B 3, Ω 1 … N, W 1 … N), ξ (v_W 3, w_B 3, a_W 3, alpha_B 3, Ω̇ 1 … N, P 1 … N);
//   A ω̇ = τ_B − Σ u_k a_k − ω × (I ω + h_w),  Ω̇_k = u_k / J_k − a_k·ω̇,  m a_W = f_W.
// Its wheels' motor torques u_k are piecewise constant: set_time sets them for the piece a step is in. It has no
// free rotation in closed form: compile refuses the splitting methods for it, and the implicit gyroscopic kick.
#pragma once
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/kinds/rigid_slot.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"

#include <stdexcept>
#include <vector>

namespace rigiddyn::detail {

struct GyrostatSlot : SlotPlace, SpatialLayout {
  static constexpr bool has_mass_flow = false;
  static constexpr int wheel = 13, xi_wheel = 12;  // the first wheel speed in y, its rate in ξ
  double inverse_mass;
  Eigen::Matrix3d inertia, transverse, inverse_transverse;  // I (wheels locked), A and A⁻¹ [kg m²], in B
  std::vector<Wheel> wheels;                    // unit axes
  std::vector<double> u;                        // each wheel's motor torque in the current piece [N m]

  int wheel_count() const { return static_cast<int>(wheels.size()); }
  // h_w = Σ J_k Ω_k a_k [kg m²/s]
  Eigen::Vector3d wheel_momentum(const double* x) const {
    Eigen::Vector3d h_w = Eigen::Vector3d::Zero();
    for (int k = 0; k < wheel_count(); ++k) h_w += (wheels[k].inertia * x[wheel + k]) * wheels[k].axis_B;
    return h_w;
  }
  // ω̇ = A⁻¹ (τ_B − Σ u_k a_k − ω × (I ω + h_w)) [rad/s²] at the block x under the wrench
  Eigen::Vector3d angular_acceleration(const double* x, const BodyWrench& wrench) const {
    const Eigen::Vector3d w_B = three(x + w);
    Eigen::Vector3d torque = wrench.tau_B - cross_3(w_B, Eigen::Vector3d(inertia * w_B + wheel_momentum(x)));
    for (int k = 0; k < wheel_count(); ++k) torque -= u[k] * wheels[k].axis_B;
    return inverse_transverse * torque;
  }
  // Ω̇_k = u_k / J_k − a_k·ω̇ [rad/s²]
  double wheel_rate(int k, const Eigen::Vector3d& alpha) const {
    return u[k] / wheels[k].inertia - wheels[k].axis_B.dot(alpha);
  }
  Eigen::Vector3d acceleration_W(const BodyWrench& wrench) const {
    return Eigen::Vector3d(inverse_mass * wrench.f_W[0], inverse_mass * wrench.f_W[1], inverse_mass * wrench.f_W[2]);
  }

  Eigen::Index y_size() const { return 13 + 2 * wheel_count(); }
  Eigen::Index xi_size() const { return 12 + 2 * wheel_count(); }
  int work() const { return wheel + wheel_count(); }        // the first motor work in y
  int xi_power() const { return xi_wheel + wheel_count(); }  // its power in ξ
  void set_time(double t) {
    for (int k = 0; k < wheel_count(); ++k) u[k] = wheels[k].motor_torque_at(t);
  }
  void kinematics(const double* y, const StepClock&, BodyKinematics& k) const { SpatialLayout::kinematics(y + at_y, k); }
  void rate(const double* y, const StepClock&, const BodyKinematics&, const BodyWrench& wrench, double* dy) const {
    const double* x = y + at_y;
    double* dx = dy + at_y;
    const Eigen::Vector3d a = acceleration_W(wrench), alpha = angular_acceleration(x, wrench);
    for (int i = 0; i < 3; ++i) dx[p + i] = x[v + i], dx[v + i] = a[i], dx[w + i] = alpha[i];
    for (int k = 0; k < wheel_count(); ++k) dx[wheel + k] = wheel_rate(k, alpha), dx[work() + k] = u[k] * x[wheel + k];
    quat_rate_body(x + q, three(x + w), dx + q);  // q̇ = ½ q ⊗ (ω_B, 0)
  }
  void velocity(const double* y, const StepClock&, const BodyKinematics&, const BodyWrench& wrench, double* xi) const {
    const double* x = y + at_y;
    double* d = xi + at_xi;
    const Eigen::Vector3d a = acceleration_W(wrench), alpha = angular_acceleration(x, wrench);
    for (int i = 0; i < 3; ++i) d[xi_v + i] = x[v + i], d[xi_w + i] = x[w + i], d[xi_a + i] = a[i], d[xi_a + 3 + i] = alpha[i];
    for (int k = 0; k < wheel_count(); ++k) d[xi_wheel + k] = wheel_rate(k, alpha), d[xi_power() + k] = u[k] * x[wheel + k];
  }
  void retract(const double* y, const double* theta, double* out) const {
    for (int i = 0; i < 3; ++i) out[at_y + p + i] = y[at_y + p + i] + theta[at_xi + xi_v + i];
    times_exp(y + at_y + q, three(theta + at_xi + xi_w), out + at_y + q);
    for (int i = 0; i < 6 + 2 * wheel_count(); ++i) out[at_y + v + i] = y[at_y + v + i] + theta[at_xi + xi_a + i];  // v, ω, Ω, W
  }
  void dexp_inv(const double* theta, double* xi) const { dexp_inv_body(theta + at_xi + xi_w, xi + at_xi + xi_w); }
  void project(double* y) const { normalise_quaternion(y + at_y + q); }
  // velocities += h × accelerations at y (explicit in the gyroscopic term and the wheels' momentum), motor works +=
  // h × their powers at y
  template <class GyroscopicKick>
  void kick(double* y, const BodyKinematics&, const BodyWrench& wrench, double h, const GyroscopicKick&) const {
    double* x = y + at_y;
    const Eigen::Vector3d a = acceleration_W(wrench), alpha = angular_acceleration(x, wrench);
    for (int k = 0; k < wheel_count(); ++k) x[work() + k] += h * u[k] * x[wheel + k], x[wheel + k] += h * wheel_rate(k, alpha);
    for (int i = 0; i < 3; ++i) x[v + i] += h * a[i], x[w + i] += h * alpha[i];
  }
  void translate(double* y, double h) const {
    for (int i = 0; i < 3; ++i) y[at_y + p + i] += h * y[at_y + v + i];
  }
  void turn(double* y, double h) const { SpatialLayout::turn(y + at_y, h); }
  template <class Rotation>
  void free_rotation(double*, double) const {
    throw std::logic_error("free_flow: a gyrostat has no free rotation in closed form (compile refuses the splitting "
                           "methods for it)");
  }
  template <class Kicks>
  double loads_kick(double*, BodyKinematics&, const BodyWrench&, double, const Kicks&) const {
    throw std::logic_error("loads_kick: the splitting methods are refused for a gyrostat (compile)");
  }
  // T = ½ m |v|² + ½ ωᵀ A ω + ½ Σ J_k (a_k·ω + Ω_k)², H_C = R (I ω + h_w)
  void record(const double* y, const BodyKinematics& k, const BodyWrench&, RecordSums& sums, Eigen::Vector3d& momentum_O_W,
              Eigen::Vector3d&) const {
    const double* x = y + at_y;
    sums.add_translation(k);
    double T = 0.5 * k.w_B.dot(transverse * k.w_B);
    for (int i = 0; i < wheel_count(); ++i) {
      const double spin = wheels[i].axis_B.dot(k.w_B) + x[wheel + i];
      T += 0.5 * wheels[i].inertia * spin * spin;
    }
    sums.T += T;
    momentum_O_W = k.q_WB * (inertia * k.w_B + wheel_momentum(x));
    sums.H_W += momentum_O_W;
  }
  // each wheel's speed relative to the body [rad/s] and its motor's work since t0 [J]
  void record_internal(const double* y, SceneSimulation& out) const {
    out.wheel_speed.insert(out.wheel_speed.end(), y + at_y + wheel, y + at_y + wheel + wheel_count());
    out.motor_work.insert(out.motor_work.end(), y + at_y + work(), y + at_y + work() + wheel_count());
  }
  void coordinates(const BodyState& state, double* y) const {
    const auto& s = std::get<GyrostatState>(state);
    SpatialLayout::coordinates(RigidBodyState{s.p_W, s.q_WB, s.v_W, s.w_B}, y + at_y);
    for (int k = 0; k < wheel_count(); ++k) y[at_y + wheel + k] = s.wheel_speeds[k], y[at_y + work() + k] = 0.0;
  }
  BodyState state(const double* y) const {
    const RigidBodyState r = SpatialLayout::state(y + at_y);
    GyrostatState s{r.p_W, r.q_WB, r.v_W, r.w_B, Eigen::VectorXd(wheel_count())};
    for (int k = 0; k < wheel_count(); ++k) s.wheel_speeds[k] = y[at_y + wheel + k];
    return s;
  }
  Eigen::Index attitude_y() const { return at_y + q; }
};

template <class Groups>
void add_slot(Groups& groups, int b, const Gyrostat& body, Eigen::Index& y, Eigen::Index& xi) {
  GyrostatSlot slot{{b, y, xi},          {},           1.0 / body.mass(), body.inertia_com(), body.transverse_inertia(),
                    body.inverse_transverse_inertia(), body.wheels(),
                    std::vector<double>(body.wheels().size(), 0.0)};
  y += slot.y_size(), xi += slot.xi_size();
  std::get<std::vector<GyrostatSlot>>(groups).push_back(std::move(slot));
}

}  // namespace rigiddyn::detail
