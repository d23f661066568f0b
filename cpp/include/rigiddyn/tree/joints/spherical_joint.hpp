// Spherical (ball) joint (Featherstone Table 4.1, "spherical"): any rotation about the common origin of
// the joint frame J and the successor frame L. Configuration: the unit quaternion q_JL = (x, y, z, w)
// (Eigen's coefficient order, docs/conventions.md); velocity: w_L, the angular velocity of L relative
// to J, expressed in L [rad/s]:
//   X_J(q) = (R(q_JL), 0),  S = [1; 0] (6 x 3),  nq = 4, nv = 3,
//   q ⊕ w dt = q_JL ⊗ exp(w_L dt / 2)  (the exact flow for a constant w_L, so3/integrate.hpp).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigiddyn/so3/integrate.hpp"
#include "rigiddyn/spatial/transform.hpp"
#include "rigiddyn/tree/joints/motion_subspace.hpp"

namespace rigiddyn {

struct SphericalJoint {
  static constexpr int nq = 4, nv = 3;

  // q: (x, y, z, w) of a unit quaternion (the tree checks the norm before calling).
  static Eigen::Quaterniond quaternion(const JointVector& q) { return Eigen::Quaterniond(q[3], q[0], q[1], q[2]); }
  static void set_quaternion(const Eigen::Quaterniond& q_JL, JointVectorOut q) { q = q_JL.coeffs(); }

  Transform transform(const JointVector& q) const {
    return Transform::unchecked(quaternion(q).normalized().toRotationMatrix(), Eigen::Vector3d::Zero());
  }
  MotionSubspace motion_subspace() const {
    MotionSubspace S = MotionSubspace::Zero(6, 3);
    S.topRows<3>().setIdentity();
    return S;
  }
  void integrate(const JointVector& q, const JointVector& w_L, double dt, JointVectorOut q_out) const {
    set_quaternion(quat_integrate(quaternion(q).normalized(), w_L, dt, Frame::body), q_out);
  }
  void neutral(JointVectorOut q) const { set_quaternion(Eigen::Quaterniond::Identity(), q); }
};

}  // namespace rigiddyn
