#include "rigiddyn/so3/skew.hpp"

namespace rigiddyn {

Eigen::Matrix3d hat(const Eigen::Vector3d& v) {
  Eigen::Matrix3d S;
  S << 0.0, -v.z(), v.y(),
       v.z(), 0.0, -v.x(),
       -v.y(), v.x(), 0.0;
  return S;
}

Eigen::Vector3d vee(const Eigen::Matrix3d& S) {
  // vee of the skew part (S - S^T)/2
  return 0.5 * Eigen::Vector3d(S(2, 1) - S(1, 2), S(0, 2) - S(2, 0), S(1, 0) - S(0, 1));
}

}  // namespace rigiddyn
