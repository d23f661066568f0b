#include "rigiddyn/so3/axis_angle.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/quaternion.hpp"

#include <cmath>

namespace rigiddyn {

Eigen::Quaterniond axis_angle_to_quat(const Eigen::Vector3d& axis, double angle) {
  require_finite(axis, "axis");
  require_finite(angle, "angle");
  const double length = axis.norm();
  if (!(length > 0.0)) throw_invalid("axis", "a non-zero vector", axis.transpose());
  const Eigen::Vector3d xyz = (std::sin(0.5 * angle) / length) * axis;
  return Eigen::Quaterniond(std::cos(0.5 * angle), xyz.x(), xyz.y(), xyz.z());
}

AxisAngle quat_to_axis_angle(const Eigen::Quaterniond& q) {
  const Eigen::Quaterniond p = quat_canonical(q);  // w >= 0: angle in [0, pi]
  const double s = p.vec().norm();                  // sin(angle/2)
  if (s == 0.0) return {Eigen::Vector3d::UnitX(), 0.0};
  return {p.vec() / s, 2.0 * std::atan2(s, p.w())};
}

}  // namespace rigiddyn
