// Free joint (six degrees of freedom, Featherstone Table 4.1 "free"): the successor frame L anywhere
// relative to the joint frame J. Configuration: (p_JL, q_JL) = (x, y, z, qx, qy, qz, qw), the position
// of L's origin in J [m] and the unit quaternion q_JL; velocity: the twist of L relative to J expressed
// in L, V_L = [w_L; v_L] (angular first; v_L the velocity of L's origin, in L):
//   X_J(q) = (R(q_JL), p_JL),  S = 1 (6 x 6),  nq = 7, nv = 6,
//   q ⊕ V dt: q_JL ⊗ exp(w_L dt / 2) and p_JL + R(q_JL) v_L dt (a first-order retraction on
//   R^3 x SO(3), exact for a constant w_L when v_L = 0 and for a constant v_L when w_L = 0).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigiddyn/so3/integrate.hpp"
#include "rigiddyn/spatial/transform.hpp"
#include "rigiddyn/tree/joints/motion_subspace.hpp"
#include "rigiddyn/tree/joints/spherical_joint.hpp"

namespace rigiddyn {

struct FreeJoint {
  static constexpr int nq = 7, nv = 6;

  Transform transform(const JointVector& q) const {
    return Transform::unchecked(SphericalJoint::quaternion(q.tail<4>()).normalized().toRotationMatrix(), q.head<3>());
  }
  MotionSubspace motion_subspace() const { return MotionSubspace::Identity(6, 6); }
  void integrate(const JointVector& q, const JointVector& V_L, double dt, JointVectorOut q_out) const {
    const Eigen::Quaterniond q_JL = SphericalJoint::quaternion(q.tail<4>()).normalized();
    q_out.head<3>() = q.head<3>() + q_JL * Eigen::Vector3d(V_L.tail<3>()) * dt;
    SphericalJoint::set_quaternion(quat_integrate(q_JL, V_L.head<3>(), dt, Frame::body), q_out.tail<4>());
  }
  void neutral(JointVectorOut q) const {
    q.head<3>().setZero();
    SphericalJoint::set_quaternion(Eigen::Quaterniond::Identity(), q.tail<4>());
  }
};

}  // namespace rigiddyn
