#include "rigiddyn/so3/mrp.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/quaternion.hpp"

namespace rigiddyn {

Eigen::Vector3d quat_to_mrp(const Eigen::Quaterniond& q) {
  const Eigen::Quaterniond c = quat_canonical(q);
  return c.vec() / (1.0 + c.w());
}

Eigen::Quaterniond mrp_to_quat(const Eigen::Vector3d& p) {
  require_finite(p, "mrp");
  const double norm = p.stableNorm();
  if (norm <= 1.0) {
    // (2 p, 1 - |p|²) / (1 + |p|²)
    const double n2 = norm * norm;
    const Eigen::Vector3d v = (2.0 / (1.0 + n2)) * p;
    return Eigen::Quaterniond((1.0 - n2) / (1.0 + n2), v.x(), v.y(), v.z());
  }
  // |p| > 1, s = 1/|p|: 2 p / (1 + |p|²) = 2 s (p/|p|) / (1 + s²), (1 - |p|²)/(1 + |p|²) = (s² - 1)/(s² + 1)
  const double s = 1.0 / norm;
  const Eigen::Vector3d v = (2.0 * s / (1.0 + s * s)) * (p * s);
  return Eigen::Quaterniond((s * s - 1.0) / (s * s + 1.0), v.x(), v.y(), v.z());
}

}  // namespace rigiddyn
