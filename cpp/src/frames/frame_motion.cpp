#include "rigiddyn/frames/frame_motion.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/axis_angle.hpp"
#include "rigiddyn/so3/matrix.hpp"

namespace rigiddyn {

FrameMotion::FrameMotion(Function kinematics_at) : kinematics_at_(std::move(kinematics_at)) {
  if (!kinematics_at_) throw std::invalid_argument("kinematics_at: expected a callable, got an empty function");
}

FrameKinematics FixedPlacement::operator()(double) const {
  FrameKinematics K;
  K.R_PF = R_PF;
  K.p_PF_P = p_PF_P;
  return K;
}

FrameKinematics ConstantRotation::operator()(double t) const {
  // R_PF(t) = exp(rate t [u]x) R_PF0, from the unit axis and the angle (never a rotation vector
  // whose norm could overflow at |rate t| ~ 1e300)
  const double angle = rate * t;
  if (!std::isfinite(angle)) throw_invalid("t", "a time with rate * t finite (rate = " + format_value(rate) + " rad/s)", t);
  FrameKinematics K;
  K.R_PF = quat_to_matrix(axis_angle_to_quat(u_P, angle)) * R_PF0;
  K.w_PF_P = rate * u_P;
  K.p_PF_P = p_PF_P;
  return K;
}

FrameMotion FrameMotion::fixed(const Eigen::Matrix3d& R_PF, const Eigen::Vector3d& p_PF_P) {
  const Eigen::Matrix3d R = checked_rotation_matrix(R_PF, "R_PF");
  require_finite(p_PF_P, "p_PF_P");
  return FrameMotion(FixedPlacement{R, p_PF_P});
}

FrameMotion FrameMotion::constant_rotation(const Eigen::Vector3d& axis_P, double rate,
                                           const Eigen::Matrix3d& R_PF0, const Eigen::Vector3d& p_PF_P) {
  require_finite(axis_P, "axis_P");
  if (axis_P.isZero(0.0)) throw_invalid("axis_P", "a non-zero vector", axis_P);
  require_finite(rate, "rate");
  checked_rotation_matrix(R_PF0, "R_PF0");
  require_finite(p_PF_P, "p_PF_P");
  // any length of the axis, 1e-300 or 1e300
  return FrameMotion(ConstantRotation{axis_P, rate, R_PF0, p_PF_P, axis_P.stableNormalized()});
}

}  // namespace rigiddyn
