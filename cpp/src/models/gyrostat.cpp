#include "rigiddyn/models/gyrostat.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/inertia/validity.hpp"
#include "rigiddyn/so3/quaternion.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cmath>
#include <stdexcept>
#include <string>

namespace rigiddyn {

Wheel checked_wheel(const Wheel& wheel, const std::string& prefix) {
  require_finite(wheel.axis_B, prefix + "axis_B");
  if (!(wheel.axis_B.norm() > 0.0)) throw_invalid(prefix + "axis_B", "a non-zero axis", wheel.axis_B);
  require_positive(wheel.inertia, prefix + "inertia");
  require_finite(wheel.motor_torque, prefix + "motor_torque");
  require_finite(wheel.t_start, prefix + "t_start");
  if (!(wheel.t_end > wheel.t_start)) {
    throw_invalid(prefix + "t_end", "a time after t_start = " + format_value(wheel.t_start) + " s", wheel.t_end);
  }
  Wheel out = wheel;
  out.axis_B = wheel.axis_B.stableNormalized();  // (scaled first: an axis of 1e308 stays an axis)
  return out;
}

Gyrostat::Gyrostat(const RigidBody& body, const std::vector<Wheel>& wheels) : body_(body) {
  // A = I − Σ J a aᵀ, refused at the first wheel that leaves it not positive definite (the same tolerance as a
  // rigid body's inertia: Euler's equations of the gyrostat need A⁻¹)
  transverse_ = body_.inertia_com();
  const double tolerance = inertia_relative_tolerance * body_.inertia_com().trace();
  for (std::size_t k = 0; k < wheels.size(); ++k) {
    const Wheel wheel = checked_wheel(wheels[k], "wheels[" + std::to_string(k) + "].");
    transverse_ -= wheel.inertia * wheel.axis_B * wheel.axis_B.transpose();
    const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(transverse_).eigenvalues()(0);
    if (!(smallest > tolerance)) {
      throw_invalid("wheels[" + std::to_string(k) + "].inertia",
                    "an axial inertia that leaves the transverse inertia I − Σ J a aᵀ positive definite (the body "
                    "with its wheels free to spin; its smallest moment would be " + format_value(smallest) + " kg m²)",
                    wheel.inertia);
    }
    wheels_.push_back(wheel);
  }
  inverse_transverse_ = transverse_.inverse();
}

GyrostatState checked_state(const GyrostatState& state, const std::string& name) {
  require_finite(state.p_W, name + ".p_W");
  require_finite(state.v_W, name + ".v_W");
  require_finite(state.w_B, name + ".w_B");
  require_finite(state.wheel_speeds, name + ".wheel_speeds");
  GyrostatState out = state;
  out.q_WB = checked_attitude(state.q_WB, name + ".q_WB");
  return out;
}

GyrostatState checked_state(const Gyrostat& body, const GyrostatState& state, const std::string& name) {
  const auto wheels = static_cast<Eigen::Index>(body.wheels().size());
  if (state.wheel_speeds.size() != wheels) {
    throw std::invalid_argument(name + ".wheel_speeds: expected " + std::to_string(wheels) +
                                " speeds (one per wheel of the gyrostat), got " + std::to_string(state.wheel_speeds.size()));
  }
  return checked_state(state, name);
}

BodyKinematics kinematics_of(const Gyrostat& body, const GyrostatState& state) {
  BodyKinematics k;
  k.p_W = state.p_W, k.v_W = state.v_W, k.w_B = state.w_B, k.m = body.mass();
  set_attitude(k, state.q_WB);
  return k;
}

Eigen::Vector3d angular_momentum_B(const Gyrostat& body, const GyrostatState& state) {
  Eigen::Vector3d H = body.inertia_com() * state.w_B;
  for (std::size_t k = 0; k < body.wheels().size(); ++k) {
    const Wheel& wheel = body.wheels()[k];
    H += wheel.inertia * state.wheel_speeds[static_cast<Eigen::Index>(k)] * wheel.axis_B;
  }
  return H;
}

double kinetic_energy(const Gyrostat& body, const GyrostatState& state) {
  double T = 0.5 * body.mass() * state.v_W.squaredNorm() + 0.5 * state.w_B.dot(body.transverse_inertia() * state.w_B);
  for (std::size_t k = 0; k < body.wheels().size(); ++k) {
    const Wheel& wheel = body.wheels()[k];
    const double spin = wheel.axis_B.dot(state.w_B) + state.wheel_speeds[static_cast<Eigen::Index>(k)];
    T += 0.5 * wheel.inertia * spin * spin;
  }
  return T;
}

}  // namespace rigiddyn
