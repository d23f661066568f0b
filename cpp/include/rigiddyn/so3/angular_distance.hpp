// The angle between two rotations: the geodesic distance on SO(3).
#pragma once
#include <Eigen/Geometry>

#include <cmath>

namespace rigiddyn {

// The angle [rad] in [0, pi] of the rotation q_a^-1 ⊗ q_b that takes q_a to q_b (SciPy's
// (r_a.inv() * r_b).magnitude()): with d = q_a^-1 ⊗ q_b, angle = 2 atan2(|d_xyz|, |d_w|). A metric
// on rotations (symmetric, zero only for equal rotations, triangle inequality), independent of the
// signs of q_a and q_b. The atan2 form keeps full relative accuracy near 0, where acos(|d_w|)
// loses half the digits, and near pi. q_a, q_b unit quaternions.
inline double angular_distance(const Eigen::Quaterniond& q_a, const Eigen::Quaterniond& q_b) {
  const Eigen::Quaterniond d = q_a.conjugate() * q_b;
  return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

}  // namespace rigiddyn
