// Revolute joint (Featherstone Table 4.1): a rotation by the angle q [rad] about a unit axis a, the
// same vector in the joint frame J and the successor frame L (it is the rotation's own axis):
//   X_J(q) = (Rot(a, q), 0),  S = [a; 0],  nq = nv = 1,  q ⊕ qd dt = q + qd dt.
#pragma once
#include <Eigen/Core>

#include <cmath>

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/exp_log.hpp"
#include "rigiddyn/spatial/transform.hpp"
#include "rigiddyn/tree/joints/motion_subspace.hpp"

namespace rigiddyn {

struct RevoluteJoint {
  static constexpr int nq = 1, nv = 1;
  // axis: any finite non-zero 3-vector, normalised here; throws std::invalid_argument naming "axis".
  explicit RevoluteJoint(const Eigen::Vector3d& axis_ = Eigen::Vector3d::UnitZ()) : axis(unit_axis(axis_)) {}

  Eigen::Vector3d axis;  // a, unit, in J and in L

  Transform transform(const JointVector& q) const { return Transform::unchecked(rotvec_to_matrix(axis * q[0]), Eigen::Vector3d::Zero()); }
  MotionSubspace motion_subspace() const {
    MotionSubspace S(6, 1);
    S << axis, Eigen::Vector3d::Zero();
    return S;
  }
  void integrate(const JointVector& q, const JointVector& qd, double dt, JointVectorOut q_out) const {
    q_out[0] = q[0] + qd[0] * dt;
  }
  void neutral(JointVectorOut q) const { q[0] = 0.0; }

  // A finite non-zero axis, normalised (shared with PrismaticJoint).
  static Eigen::Vector3d unit_axis(const Eigen::Vector3d& axis) {
    const double norm = axis.norm();
    if (!(std::isfinite(norm) && norm > 0.0)) throw_invalid("axis", "a finite non-zero 3-vector", axis.transpose().eval());
    return axis / norm;
  }
};

}  // namespace rigiddyn
