#include "rigiddyn/so3/elementary.hpp"

#include <cmath>

namespace rigiddyn {

Eigen::Matrix3d rot_x(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d R;
  R << 1.0, 0.0, 0.0,
       0.0, c, -s,
       0.0, s, c;
  return R;
}

Eigen::Matrix3d rot_y(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d R;
  R << c, 0.0, s,
       0.0, 1.0, 0.0,
       -s, 0.0, c;
  return R;
}

Eigen::Matrix3d rot_z(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d R;
  R << c, -s, 0.0,
       s, c, 0.0,
       0.0, 0.0, 1.0;
  return R;
}

Eigen::Quaterniond elementary_quat(int axis, double angle) {
  Eigen::Quaterniond q(std::cos(0.5 * angle), 0.0, 0.0, 0.0);
  q.vec()[axis] = std::sin(0.5 * angle);
  return q;
}

}  // namespace rigiddyn
