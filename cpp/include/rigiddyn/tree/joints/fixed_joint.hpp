// Fixed joint (a weld): no motion, X_J = 1, S has no columns, nq = nv = 0. The successor is rigidly
// attached to its parent at the placement X_T.
#pragma once
#include <Eigen/Core>

#include "rigiddyn/spatial/transform.hpp"
#include "rigiddyn/tree/joints/motion_subspace.hpp"

namespace rigiddyn {

struct FixedJoint {
  static constexpr int nq = 0, nv = 0;

  Transform transform(const JointVector&) const { return Transform(); }
  MotionSubspace motion_subspace() const { return MotionSubspace(6, 0); }
  void integrate(const JointVector&, const JointVector&, double, JointVectorOut) const {}
  void neutral(JointVectorOut) const {}
};

}  // namespace rigiddyn
