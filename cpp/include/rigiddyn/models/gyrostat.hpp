// The gyrostat: a rigid body carrying wheels, each spun about an axis fixed in the body by a motor, each
// wheel's speed relative to the body a state (Hughes, "Spacecraft Attitude Dynamics", ch. 3). A reaction-wheel
// spacecraft.
//
// Body data: mass m [kg]; I = inertia_com [kg m²] the WHOLE body's inertia about its centre of mass C in B
// (platform and wheels, each wheel counted as if locked to the platform); wheel k: unit axis a_k in B, axial
// moment J_k [kg m²] (a balanced, axisymmetric wheel), and the motor torque u_k [N m] that drives it relative to
// the body (the body feels −u_k a_k). Ω_k [rad/s]: wheel k's spin relative to the body.
//   H_B = I ω + h_w,  h_w = Σ J_k Ω_k a_k                      (angular momentum about C, in B)
//   I ω̇ + ḣ_w + ω × (I ω + h_w) = τ_B,  J_k (a_k·ω̇ + Ω̇_k) = u_k  (Euler about C; each wheel about its axis)
// so, with the transverse inertia A = I − Σ J_k a_k a_kᵀ (the body with its wheels free to spin),
//   A ω̇ = τ_B − Σ u_k a_k − ω × (I ω + h_w),   Ω̇_k = u_k / J_k − a_k·ω̇,   m v̇_W = f_W,   q̇ = ½ q ⊗ (ω_B, 0).
// Kinetic energy T = ½ m |v|² + ½ ωᵀ A ω + ½ Σ J_k (a_k·ω + Ω_k)²; dT/dt = f·v + τ·ω + Σ u_k Ω_k (the motor puts
// in its torque times the relative speed). Without outside wrench and motor torque, H_W = R H_B, T and each
// wheel's absolute axial spin a_k·ω + Ω_k are constant.
#pragma once
#include "rigiddyn/models/rigid_body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <limits>
#include <string>
#include <vector>

namespace rigiddyn {

// A wheel of a gyrostat: its spin axis axis_B in B (any non-zero length: the unit axis is kept), its axial moment
// of inertia [kg m²] (> 0), and the motor torque [N m] on it about the axis, constant for t_start <= t < t_end [s]
// and zero outside (a run splits its steps at t_start and t_end).
struct Wheel {
  Eigen::Vector3d axis_B = Eigen::Vector3d::UnitZ();
  double inertia = 0.0;
  double motor_torque = 0.0;
  double t_start = 0.0;
  double t_end = std::numeric_limits<double>::infinity();

  // the motor torque at t [s]
  double motor_torque_at(double t) const { return t_start <= t && t < t_end ? motor_torque : 0.0; }
};

// `wheel` with its axis normalised; throws std::invalid_argument naming <prefix>axis_B (non-finite or zero),
// <prefix>inertia (not a finite number > 0), <prefix>motor_torque (non-finite), <prefix>t_start (not finite) or
// <prefix>t_end (not after t_start).
Wheel checked_wheel(const Wheel& wheel, const std::string& prefix = "");

class Gyrostat {
 public:
  // body: the whole body with its wheels locked (mass [kg], inertia_com [kg m²] about its centre of mass, wheels
  // included), and its wheels. Throws std::invalid_argument naming wheels[k].axis_B (non-finite or zero),
  // wheels[k].inertia (not a finite number > 0), wheels[k].motor_torque (non-finite), wheels[k].t_start / t_end
  // (t_start not finite, or t_end <= t_start), or the first wheels[k].inertia that leaves the transverse inertia
  // I − Σ J a aᵀ not positive definite.
  Gyrostat(const RigidBody& body, const std::vector<Wheel>& wheels);

  double mass() const { return body_.mass(); }
  const Eigen::Matrix3d& inertia_com() const { return body_.inertia_com(); }  // I [kg m²], wheels included
  const std::vector<Wheel>& wheels() const { return wheels_; }                // axes normalised
  // A = I − Σ J_k a_k a_kᵀ [kg m²] and its inverse
  const Eigen::Matrix3d& transverse_inertia() const { return transverse_; }
  const Eigen::Matrix3d& inverse_transverse_inertia() const { return inverse_transverse_; }
  // the body with its wheels locked (the rigid body elements see)
  const RigidBody& body() const { return body_; }

 private:
  RigidBody body_;
  std::vector<Wheel> wheels_;
  Eigen::Matrix3d transverse_, inverse_transverse_;
};

// The state of a gyrostat: the rigid body's (docs/conventions.md) and each wheel's speed relative to the body
// [rad/s], in the order of its wheels.
struct GyrostatState {
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_WB = Eigen::Quaterniond::Identity();
  Eigen::Vector3d v_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_B = Eigen::Vector3d::Zero();
  Eigen::VectorXd wheel_speeds;
};

// `state` with q_WB normalised; throws std::invalid_argument naming `name`.p_W / .v_W / .w_B / .wheel_speeds
// (non-finite) or .q_WB (not a unit quaternion within 1e-6).
GyrostatState checked_state(const GyrostatState& state, const std::string& name = "state");
// The same, and a speed per wheel of `body` (`name`.wheel_speeds otherwise).
GyrostatState checked_state(const Gyrostat& body, const GyrostatState& state, const std::string& name = "state");

// The kinematics elements see (body_kinematics.hpp): the rigid body's, with the mass.
BodyKinematics kinematics_of(const Gyrostat& body, const GyrostatState& state);

// H_B = I ω + Σ J_k Ω_k a_k [kg m²/s] and T = ½ m |v|² + ½ ωᵀ A ω + ½ Σ J_k (a_k·ω + Ω_k)² [J] of `state`
Eigen::Vector3d angular_momentum_B(const Gyrostat& body, const GyrostatState& state);
double kinetic_energy(const Gyrostat& body, const GyrostatState& state);

}  // namespace rigiddyn
