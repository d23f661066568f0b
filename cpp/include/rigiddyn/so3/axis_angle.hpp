// Axis-angle pairs: the rotation by `angle` [rad] about the unit vector `axis` (right-hand rule).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigiddyn {

// The unit quaternion (sin(angle/2) axis, cos(angle/2)). `axis` may have any non-zero length: it
// is normalised. Throws std::invalid_argument for a zero or non-finite axis or a non-finite angle.
Eigen::Quaterniond axis_angle_to_quat(const Eigen::Vector3d& axis, double angle);

// The axis (unit) and angle in [0, pi] of a unit quaternion. For the identity (angle 0) the axis is
// arbitrary and returned as (1, 0, 0).
struct AxisAngle {
  Eigen::Vector3d axis;
  double angle;
};
AxisAngle quat_to_axis_angle(const Eigen::Quaterniond& q);

}  // namespace rigiddyn
