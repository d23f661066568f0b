#include "rigiddyn/so3/mrp.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/quaternion.hpp"

#include <cmath>
#include <limits>

namespace rigiddyn {

Eigen::Quaterniond mrp_to_quat(const Eigen::Vector3d& p) {
  require_finite(p, "mrp");
  const double n2 = p.squaredNorm();  // where it underflows, |p|² < 1e-300 is 0 to round-off in 1 ± |p|²
  if (n2 <= 1.0) {
    // (2 p, 1 - |p|²) / (1 + |p|²)
    const Eigen::Vector3d v = (2.0 / (1.0 + n2)) * p;
    return Eigen::Quaterniond((1.0 - n2) / (1.0 + n2), v.x(), v.y(), v.z());
  }
  // |p|² overflows beyond |p| ~ 1e154: then the scaled norm
  const double norm = n2 <= std::numeric_limits<double>::max() ? std::sqrt(n2) : p.stableNorm();
  // |p| > 1, s = 1/|p|: 2 p / (1 + |p|²) = 2 s (p/|p|) / (1 + s²), (1 - |p|²)/(1 + |p|²) = (s² - 1)/(s² + 1)
  const double s = 1.0 / norm;
  const Eigen::Vector3d v = (2.0 * s / (1.0 + s * s)) * (p * s);
  return Eigen::Quaterniond((s * s - 1.0) / (s * s + 1.0), v.x(), v.y(), v.z());
}

}  // namespace rigiddyn
