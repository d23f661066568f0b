#include "rigiddyn/spatial/cross.hpp"

#include "rigiddyn/so3/skew.hpp"

namespace rigiddyn {

// crm(m) = [[w^, 0], [v^, w^]] (Featherstone, angular first).
Matrix6d motion_cross_matrix(const Motion& m) {
  const Eigen::Matrix3d w_hat = hat(m.angular);
  Matrix6d crm;
  crm << w_hat, Eigen::Matrix3d::Zero(), hat(m.linear), w_hat;
  return crm;
}

// crf(m) = [[w^, v^], [0, w^]] = -crm(m)^T.
Matrix6d force_cross_matrix(const Motion& m) {
  const Eigen::Matrix3d w_hat = hat(m.angular);
  Matrix6d crf;
  crf << w_hat, hat(m.linear), Eigen::Matrix3d::Zero(), w_hat;
  return crf;
}

}  // namespace rigiddyn
