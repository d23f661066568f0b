// Rigid transform X_AB (Featherstone's Plücker transform, docs/conventions.md): the pose of frame B
// in frame A, stored as R_AB (B coordinates -> A coordinates) and p_AB (position of B's origin,
// expressed in A) [m]. X_AB maps quantities expressed in B to the same quantities expressed in A,
// so X_AC = X_AB * X_BC.
//
// act/act_inv use the structured 3x3 formulas; motion_matrix()/force_matrix() give the dense 6x6
// forms (angular first) that the tests use as oracles.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/matrix.hpp"
#include "rigiddyn/spatial/force.hpp"
#include "rigiddyn/spatial/motion.hpp"

namespace rigiddyn {

class Transform {
 public:
  // The identity X_AA.
  Transform() = default;
  // rotation: R_AB (3,3), orthonormal with det +1; translation: p_AB (3,) [m].
  // Throws std::invalid_argument naming "rotation"/"translation" on a non-rotation or non-finite input.
  // Inline: it runs per item in loops over arrays of transforms.
  Transform(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation)
      : R_(checked_rotation_matrix(rotation, "rotation")), p_(translation) {
    if (!translation.allFinite()) throw_invalid("translation", "finite values", translation);
  }
  // The same without the checks, for a rotation orthonormal by construction and a finite translation (a joint's
  // transform from its checked configuration, per link and call of the tree algorithms: the checks cost about as
  // much as building the rotation).
  static Transform unchecked(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation) {
    return Transform(rotation, translation, Trusted{});
  }
  // q_AB: unit quaternion (checked, not normalised); translation p_AB [m].
  static Transform from_quat(const Eigen::Quaterniond& q_AB, const Eigen::Vector3d& translation);
  static Transform Identity() { return Transform(); }

  const Eigen::Matrix3d& rotation() const { return R_; }
  const Eigen::Vector3d& translation() const { return p_; }
  // q_AB with w >= 0.
  Eigen::Quaterniond quat() const;

  // Points: p_A = R_AB p_B + p_AB, and back p_B = R_AB^T (p_A - p_AB).
  Eigen::Vector3d act_point(const Eigen::Vector3d& p_B) const { return R_ * p_B + p_; }
  Eigen::Vector3d act_inv_point(const Eigen::Vector3d& p_A) const { return R_.transpose() * (p_A - p_); }

  // Motion in B -> in A: [R w; R v + p x (R w)]  (Featherstone X = [[R, 0], [p^ R, R]]).
  Motion act(const Motion& m_B) const {
    const Eigen::Vector3d w = R_ * m_B.angular;
    return Motion(w, R_ * m_B.linear + p_.cross(w));
  }
  // Force in B -> in A: [R n + p x (R f); R f]  (Featherstone X* = [[R, p^ R], [0, R]]).
  Force act(const Force& f_B) const {
    const Eigen::Vector3d f = R_ * f_B.linear;
    return Force(R_ * f_B.angular + p_.cross(f), f);
  }
  // Motion in A -> in B: [R^T w; R^T (v - p x w)].
  Motion act_inv(const Motion& m_A) const {
    return Motion(R_.transpose() * m_A.angular, R_.transpose() * (m_A.linear - p_.cross(m_A.angular)));
  }
  // Force in A -> in B: [R^T (n - p x f); R^T f].
  Force act_inv(const Force& f_A) const {
    return Force(R_.transpose() * (f_A.angular - p_.cross(f_A.linear)), R_.transpose() * f_A.linear);
  }

  // X_AB * X_BC = X_AC: R_AC = R_AB R_BC, p_AC = R_AB p_BC + p_AB.
  Transform operator*(const Transform& X_BC) const { return Transform(R_ * X_BC.R_, R_ * X_BC.p_ + p_, Trusted{}); }
  // X_BA: R_BA = R_AB^T, p_BA = -R_AB^T p_AB.
  Transform inverse() const { return Transform(R_.transpose(), -(R_.transpose() * p_), Trusted{}); }

  // Dense 6x6 forms, angular first: motion [[R, 0], [p^ R, R]], force [[R, p^ R], [0, R]] = motion^-T.
  Matrix6d motion_matrix() const;
  Matrix6d force_matrix() const;

  // Rotations and translations each equal up to prec relative to the smaller norm (Eigen's isApprox).
  bool is_approx(const Transform& o, double prec = 1e-12) const {
    return R_.isApprox(o.R_, prec) && p_.isApprox(o.p_, prec);
  }

 private:
  // Results of operations on valid transforms skip the validation.
  struct Trusted {};
  Transform(const Eigen::Matrix3d& R, const Eigen::Vector3d& p, Trusted) : R_(R), p_(p) {}

  Eigen::Matrix3d R_ = Eigen::Matrix3d::Identity();  // R_AB
  Eigen::Vector3d p_ = Eigen::Vector3d::Zero();      // p_AB [m]
};

}  // namespace rigiddyn
