// The angle between two rotations: the geodesic distance on SO(3).
#pragma once
#include <Eigen/Geometry>

#include <cmath>

namespace rigiddyn {

// The angle [rad] in [0, pi] of the rotation q_a^-1 ⊗ q_b that takes q_a to q_b (SciPy's
// (r_a.inv() * r_b).magnitude()): with d = q_a^-1 ⊗ q_b, angle = 2 atan2(|d_xyz|, |d_w|). A metric
// on rotations (symmetric, zero only for equal rotations, triangle inequality), independent of the
// signs of q_a and q_b. The atan2 form keeps full relative accuracy near 0, where acos(|d_w|)
// loses half the digits, and near pi. Below |d_xyz| = 2^-9 |d_w| (angles below ~4e-3 rad, as between the runs of a
// global-error estimate) atan x = x − x³/3 + x⁵/5, x = |d_xyz|/|d_w|, to within an ulp of atan2 (the next term,
// x⁷/7, is below 2^-57 of x) at a tenth of its cost. q_a, q_b non-zero quaternions of any norm: d scales with
// |q_a| |q_b|, and the angle is that of the unit quaternions q_a / |q_a|, q_b / |q_b|.
inline double angular_distance(const Eigen::Quaterniond& q_a, const Eigen::Quaterniond& q_b) {
  const Eigen::Quaterniond d = q_a.conjugate() * q_b;
  const double s = d.vec().norm(), c = std::abs(d.w());
  if (s < 0x1p-9 * c) {
    const double x = s / c, x2 = x * x;
    return 2.0 * (x - x * x2 * (1.0 / 3.0 - 0.2 * x2));
  }
  return 2.0 * std::atan2(s, c);
}

}  // namespace rigiddyn
