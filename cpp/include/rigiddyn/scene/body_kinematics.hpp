// What a force element sees of a body, and what it returns. Both are taken at the
// body's centre of mass G, the origin of its body frame B (docs/conventions.md "Body state").
#pragma once
#include "rigiddyn/always_inline.hpp"
#include "rigiddyn/spatial/force.hpp"
#include "rigiddyn/spatial/transform.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigiddyn {

// The kinematics of one body at one instant:
//   p_W   position of the centre of mass in W [m];
//   q_WB  unit attitude quaternion, maps B coordinates to W (Hamilton, active);
//   v_W   velocity of the centre of mass, expressed in W [m/s];
//   w_B   angular velocity of B relative to W, expressed in B [rad/s];
//   m     the body's mass now [kg] (set by the model: constant, or the mass coordinate of a body with a
//         MassFlow); elements whose force scales with the mass read it here, never a copy;
//   R_WB  the rotation matrix of q_WB (set with it by set_attitude below; the scene model fills it only when a
//         term turns vectors, scene_model.hpp: an element whose traits declare neither reads_attitude nor
//         has_torque never reads it);
//   joint_q, joint_v  a tree link's joint coordinates and velocities (tree/tree_link.hpp: its segments of the
//         tree's q, with unit quaternions, and v), set by the tree's slot at every evaluation and valid until the
//         next; null for every other kind (the joint elements read them, scene/elements/joint_force.hpp).
// "W" is the scene frame (docs/fixed_point_frames_mass.md §2): W itself when the scene declares no moving
// frame, else F; the kinematics are relative to it.
// Each body kind as elements see it: particle q_WB = identity, w_B = 0; planar body p_W = (x, y, 0),
// q_WB = Rz(θ), v_W = (v_x, v_y, 0), w_B = (0, 0, ω).
// (Their constructors are forced inline, as the members a model calls per evaluation: an evaluation writes only the
// fields it reads once the whole step inlines.)
struct BodyKinematics {
  RIGIDDYN_ALWAYS_INLINE BodyKinematics() {}
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_WB = Eigen::Quaterniond::Identity();
  Eigen::Vector3d v_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_B = Eigen::Vector3d::Zero();
  double m = 0.0;
  Eigen::Matrix3d R_WB = Eigen::Matrix3d::Identity();
  const double* joint_q = nullptr;
  const double* joint_v = nullptr;

  // X_WB, the body's pose (R_WB, p_W; the spatial layer's Transform): its point r_B [m] (from the centre of mass, in B)
  // is at pose().act_point(r_B) in W. Valid where R_WB is (set_attitude).
  Transform pose() const { return Transform::unchecked(R_WB, p_W); }
  // The velocity [m/s] in W of the body's point r_B [m] (from the centre of mass, in B): its twist (w_B, v) at that
  // point, v_W + R_WB (w_B × r_B) (Motion::velocity_at of the twist about the centre of mass, turned to W; written out,
  // the form a spring's evaluation measured cheapest: a Motion built per call is kept in memory).
  Eigen::Vector3d point_velocity_W(const Eigen::Vector3d& r_B) const { return v_W + R_WB * w_B.cross(r_B); }
};

// Sets the attitude of `k`: q_WB (a unit quaternion) and R_WB, its rotation matrix, which the elements use to
// turn vectors between B and W (9 products and 6 sums a vector, against 15 and 15 through the quaternion: a spring
// turns six vectors per evaluation). kinematics_of and the one-body records set the attitude here.
inline void set_attitude(BodyKinematics& k, const Eigen::Quaterniond& q_WB) {
  k.q_WB = q_WB;
  k.R_WB = q_WB.toRotationMatrix();
}

// The wrench on one body, reduced to its centre of mass:
//   f_W    the resultant force, expressed in W [N];
//   tau_B  the resultant torque about the centre of mass, expressed in B [N m].
// Its power on the body is f_W·v_W + tau_B·w_B [W]. A planar body's scene model keeps only f_W's x, y
// parts and tau_B's z part (the plane takes the rest: the constraint reaction).
struct BodyWrench {
  RIGIDDYN_ALWAYS_INLINE BodyWrench() {}
  RIGIDDYN_ALWAYS_INLINE BodyWrench(const Eigen::Vector3d& f_W_, const Eigen::Vector3d& tau_B_) : f_W(f_W_), tau_B(tau_B_) {}
  Eigen::Vector3d f_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d tau_B = Eigen::Vector3d::Zero();

  // Adds the spatial force F_W = (n, f) [N m, N] about the centre of mass in W's axes (Force::at_point of a force at a
  // point r_W from it) to the body of attitude R_WB: f_W += f, tau_B += R_WBᵀ n.
  void add(const Eigen::Matrix3d& R_WB, const Force& F_W) {
    f_W += F_W.linear;
    tau_B += R_WB.transpose() * F_W.angular;
  }
};

// Adds the force f_W [N] (in W) acting at the body point point_B [m] (in B, from the centre of mass) to `wrench`:
// f_W at the centre of mass and its moment tau_B = point_B × (R_WBᵀ f_W) about it (the force at the point, in B);
// returns its power f_W·v_W + tau_B·w_B [W].
inline double add_force_at_point(const BodyKinematics& body, const Eigen::Vector3d& f_W, const Eigen::Vector3d& point_B,
                                 BodyWrench& wrench) {
  const Eigen::Vector3d tau_B = Force::at_point(point_B, body.R_WB.transpose() * f_W).angular;
  wrench.f_W += f_W;
  wrench.tau_B += tau_B;
  return f_W.dot(body.v_W) + tau_B.dot(body.w_B);
}

}  // namespace rigiddyn
