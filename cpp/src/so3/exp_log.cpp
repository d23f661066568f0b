#include "rigiddyn/so3/exp_log.hpp"

#include "rigiddyn/so3/matrix.hpp"
#include "rigiddyn/so3/quaternion.hpp"

#include <cmath>

namespace rigiddyn {

namespace {

// Below this |t| the Taylor series of atan(t)/t is used: its first omitted term, t^6/7 < 2e-19
// relative, is far below double round-off, while the closed form loses digits as t -> 0.
constexpr double small_angle = 1e-3;

// atan(t)/t; Taylor series 1 - t²/3 + t⁴/5 near 0.
double atan_over_argument(double t) {
  if (std::abs(t) < small_angle) {
    const double t2 = t * t;
    return 1.0 - t2 / 3.0 + t2 * t2 / 5.0;
  }
  return std::atan(t) / t;
}

}  // namespace

Eigen::Vector3d quat_to_rotvec(const Eigen::Quaterniond& q) {
  const Eigen::Quaterniond p = quat_canonical(q);  // w >= 0: angle in [0, pi]
  const double s = p.vec().norm();                  // sin(θ/2)
  const double w = p.w();                           // cos(θ/2)
  // θ = 2 atan2(s, w); rotvec = θ/s * xyz. Near θ = 0 (s << w) θ/s = 2 atan(s/w)/(s/w) / w.
  if (s < w) return (2.0 * atan_over_argument(s / w) / w) * p.vec();
  return (2.0 * std::atan2(s, w) / s) * p.vec();  // s >= 1/√2 here: no division by small numbers
}

Eigen::Matrix3d rotvec_to_matrix(const Eigen::Vector3d& rotvec) {
  // Rodrigues' formula, evaluated through the exact quaternion (same rotation, no 0/0 at θ = 0)
  return quat_to_matrix(rotvec_to_quat(rotvec));
}

Eigen::Vector3d matrix_to_rotvec(const Eigen::Matrix3d& R) { return quat_to_rotvec(matrix_to_quat(R)); }

}  // namespace rigiddyn
