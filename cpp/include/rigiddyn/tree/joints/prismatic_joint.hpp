// Prismatic joint (Featherstone Table 4.1): a translation by q [m] along a unit axis a, the same
// vector in the joint frame J and the successor frame L (no rotation between them):
//   X_J(q) = (1, a q),  S = [0; a],  nq = nv = 1,  q ⊕ qd dt = q + qd dt.
#pragma once
#include <Eigen/Core>

#include "rigiddyn/spatial/transform.hpp"
#include "rigiddyn/tree/joints/motion_subspace.hpp"
#include "rigiddyn/tree/joints/revolute_joint.hpp"

namespace rigiddyn {

struct PrismaticJoint {
  static constexpr int nq = 1, nv = 1;
  // axis: any finite non-zero 3-vector, normalised here; throws std::invalid_argument naming "axis".
  explicit PrismaticJoint(const Eigen::Vector3d& axis_ = Eigen::Vector3d::UnitZ())
      : axis(RevoluteJoint::unit_axis(axis_)) {}

  Eigen::Vector3d axis;  // a, unit, in J and in L

  Transform transform(const JointVector& q) const { return Transform::unchecked(Eigen::Matrix3d::Identity(), axis * q[0]); }
  MotionSubspace motion_subspace() const {
    MotionSubspace S(6, 1);
    S << Eigen::Vector3d::Zero(), axis;
    return S;
  }
  void integrate(const JointVector& q, const JointVector& qd, double dt, JointVectorOut q_out) const {
    q_out[0] = q[0] + qd[0] * dt;
  }
  void neutral(JointVectorOut q) const { q[0] = 0.0; }
};

}  // namespace rigiddyn
