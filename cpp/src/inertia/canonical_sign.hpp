// The sign convention of a direction the inertia layer reports (principal axes, symmetry planes' normals).
#pragma once
#include <Eigen/Core>

namespace rigiddyn::detail {

// v with its largest-magnitude component made positive (the first such component on a tie)
inline Eigen::Vector3d canonical_sign(const Eigen::Vector3d& v) {
  Eigen::Index k;
  v.cwiseAbs().maxCoeff(&k);
  return v(k) < 0.0 ? Eigen::Vector3d(-v) : v;
}

}  // namespace rigiddyn::detail
