#include "rigiddyn/spatial/transform.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/matrix.hpp"
#include "rigiddyn/so3/quaternion.hpp"
#include "rigiddyn/so3/skew.hpp"

namespace rigiddyn {

Transform Transform::from_quat(const Eigen::Quaterniond& q_AB, const Eigen::Vector3d& translation) {
  require_finite(translation, "translation");
  return Transform(quat_to_matrix(checked_unit_quaternion(q_AB, "q_AB")), translation, Trusted{});
}

Eigen::Quaterniond Transform::quat() const { return matrix_to_quat(R_); }

// Featherstone's X (angular first, B -> A): [[R, 0], [p^ R, R]].
Matrix6d Transform::motion_matrix() const {
  Matrix6d X;
  X << R_, Eigen::Matrix3d::Zero(), hat(p_) * R_, R_;
  return X;
}

// Featherstone's X* = X^-T: [[R, p^ R], [0, R]].
Matrix6d Transform::force_matrix() const {
  Matrix6d X_star;
  X_star << R_, hat(p_) * R_, Eigen::Matrix3d::Zero(), R_;
  return X_star;
}

}  // namespace rigiddyn
