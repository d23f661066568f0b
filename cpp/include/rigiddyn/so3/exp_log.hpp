// The exponential and logarithm maps of SO(3) in rotation-vector form: a rotation vector
// rotvec = angle * axis [rad] (axis a unit vector, right-hand rule) is the rotation by `angle`
// about `axis`. Accurate near angle 0 (Taylor series) and near angle pi (atan2 / Shepperd forms).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigiddyn {

// exp: q = (sin(θ/2) rotvec/θ, cos(θ/2)) with θ = |rotvec| (any θ, also > pi; then w < 0).
// Near θ = 0, sin(θ/2)/θ is evaluated by its Taylor series, so tiny rotation vectors are exact.
Eigen::Quaterniond rotvec_to_quat(const Eigen::Vector3d& rotvec);

// log: the rotation vector of a unit quaternion q, angle θ in [0, pi] (q is first taken with
// w >= 0); θ = 2 atan2(|xyz|, w), accurate near 0 and near pi.
Eigen::Vector3d quat_to_rotvec(const Eigen::Quaterniond& q);

// exp into a matrix: R = I + sin θ/θ hat(rotvec) + (1 - cos θ)/θ² hat(rotvec)² (Rodrigues).
Eigen::Matrix3d rotvec_to_matrix(const Eigen::Vector3d& rotvec);

// log of a rotation matrix (assumed orthonormal, see checked_rotation_matrix), angle in [0, pi];
// via Shepperd's quaternion, so it stays accurate at angles near pi where (R - R^T)/2 vanishes.
Eigen::Vector3d matrix_to_rotvec(const Eigen::Matrix3d& R);

}  // namespace rigiddyn
