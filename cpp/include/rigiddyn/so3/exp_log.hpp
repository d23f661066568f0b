// The exponential and logarithm maps of SO(3) in rotation-vector form: a rotation vector
// rotvec = angle * axis [rad] (axis a unit vector, right-hand rule) is the rotation by `angle`
// about `axis`. Accurate near angle 0 (Taylor series) and near angle pi (atan2 / Shepperd forms).
#pragma once
#include "rigiddyn/always_inline.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace rigiddyn {

// exp: q = (sin(θ/2) rotvec/θ, cos(θ/2)) with θ = |rotvec| (any θ, also > pi; then w < 0).
// Near θ = 0, sin(θ/2)/θ is evaluated by its Taylor series, so tiny rotation vectors are exact.
// Inline: the integrators call it once per step or stage, where a call would cost more than the
// arithmetic (sin and cos of the same half-angle, which the compiler fuses into one sincos).
RIGIDDYN_ALWAYS_INLINE Eigen::Quaterniond rotvec_to_quat(const Eigen::Vector3d& rotvec) {
  // Below this angle [rad] sin(θ/2)/θ = 1/2 − θ²/48 + θ⁴/3840 to O(θ⁶) ~ 1e-38, exact in double;
  // above it sin(θ/2)/θ is accurate to round-off for any θ > 0. The series is needed only at θ = 0
  // (and where |rotvec|² underflows), so the threshold sits far below any practical step h|ω|.
  constexpr double small_angle = 1e-6;
  // |rotvec| written out: Eigen's 2-wide norm would reload as one packet the components a caller
  // has just stored one by one (a store-forwarding stall inside integrator loops)
  const double theta = std::sqrt(rotvec.x() * rotvec.x() + rotvec.y() * rotvec.y() + rotvec.z() * rotvec.z());
  const double half = 0.5 * theta;
  const double sin_half = std::sin(half), cos_half = std::cos(half);
  const double t2 = theta * theta;
  const double k = theta < small_angle ? 0.5 - t2 * (1.0 / 48.0) + t2 * t2 * (1.0 / 3840.0) : sin_half / theta;
  return Eigen::Quaterniond(cos_half, k * rotvec.x(), k * rotvec.y(), k * rotvec.z());
}

// log: the rotation vector of a unit quaternion q, angle θ in [0, pi] (q is first taken with
// w >= 0); θ = 2 atan2(|xyz|, w), accurate near 0 and near pi.
Eigen::Vector3d quat_to_rotvec(const Eigen::Quaterniond& q);

// exp into a matrix: R = I + sin θ/θ hat(rotvec) + (1 - cos θ)/θ² hat(rotvec)² (Rodrigues).
Eigen::Matrix3d rotvec_to_matrix(const Eigen::Vector3d& rotvec);

// log of a rotation matrix (assumed orthonormal, see checked_rotation_matrix), angle in [0, pi];
// via Shepperd's quaternion, so it stays accurate at angles near pi where (R - R^T)/2 vanishes.
Eigen::Vector3d matrix_to_rotvec(const Eigen::Matrix3d& R);

}  // namespace rigiddyn
