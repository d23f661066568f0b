// A joint of a kinematic tree: one of the kinds in joints/ (revolute, prismatic, spherical, free,
// fixed), each with its X_J(q), motion subspace S and retraction q ⊕ qd dt. The visitors below
// dispatch on the kind; a joint's configuration and velocity are its segments of the tree's q and v.
#pragma once
#include <string>
#include <variant>

#include "rigiddyn/tree/joints/fixed_joint.hpp"
#include "rigiddyn/tree/joints/free_joint.hpp"
#include "rigiddyn/tree/joints/prismatic_joint.hpp"
#include "rigiddyn/tree/joints/revolute_joint.hpp"
#include "rigiddyn/tree/joints/spherical_joint.hpp"

namespace rigiddyn {

using Joint = std::variant<RevoluteJoint, PrismaticJoint, SphericalJoint, FreeJoint, FixedJoint>;

// Sizes of the joint's configuration q and velocity qd.
inline int joint_nq(const Joint& joint) {
  return std::visit([](const auto& j) { return std::decay_t<decltype(j)>::nq; }, joint);
}
inline int joint_nv(const Joint& joint) {
  return std::visit([](const auto& j) { return std::decay_t<decltype(j)>::nv; }, joint);
}
// Whether the configuration holds a unit quaternion (x, y, z, w) in its last four entries.
inline bool joint_has_quaternion(const Joint& joint) {
  return std::holds_alternative<SphericalJoint>(joint) || std::holds_alternative<FreeJoint>(joint);
}
// X_J(q): the successor frame L in the joint frame J.
inline Transform joint_transform(const Joint& joint, const JointVector& q) {
  return std::visit([&](const auto& j) { return j.transform(q); }, joint);
}
inline MotionSubspace motion_subspace(const Joint& joint) {
  return std::visit([](const auto& j) { return j.motion_subspace(); }, joint);
}
// q_out = q ⊕ qd dt.
inline void joint_integrate(const Joint& joint, const JointVector& q, const JointVector& qd, double dt,
                            JointVectorOut q_out) {
  std::visit([&](const auto& j) { j.integrate(q, qd, dt, q_out); }, joint);
}
// The neutral configuration (angle or offset 0, identity quaternion).
inline void joint_neutral(const Joint& joint, JointVectorOut q) {
  std::visit([&](const auto& j) { j.neutral(q); }, joint);
}
// "revolute", "prismatic", "spherical", "free" or "fixed".
inline const char* joint_kind(const Joint& joint) {
  static constexpr const char* kinds[] = {"revolute", "prismatic", "spherical", "free", "fixed"};
  return kinds[joint.index()];
}

}  // namespace rigiddyn
