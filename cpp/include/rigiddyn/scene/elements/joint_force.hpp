// A joint force of a one-degree-of-freedom joint of a tree (a revolute or a prismatic joint, tree/joints/) as the
// bodies' wrenches, for the joint elements (joint_spring_damper.hpp, joint_motor.hpp; a spherical joint's couple:
// spherical_spring_damper.hpp). A joint force τ [N m about a revolute joint's axis, N along a prismatic joint's]
// enters the dynamics as τ_i = S_iᵀ f_i (Featherstone Table 5.1): it is the wrench S τ that the parent exerts on the
// link across the joint, and −S τ that the link exerts on the parent (W takes it for a root link), both at the
// joint's origin, the link frame's origin L, in L. S = [a; 0] (a couple τ a) for a revolute joint, S = [0; a] (a
// force τ a through L's origin) for a prismatic one. The pair is internal: it conserves the tree's momenta, and its
// power over the two bodies is τ q̇ (their relative twist across the joint is S q̇, Featherstone §4.4).
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_traits.hpp"
#include "rigiddyn/tree/tree_link.hpp"

#include <Eigen/Core>

#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace rigiddyn::detail {

// The tree link of body `body` whose joint is of kind JointKind (kind_name "revolute", "prismatic" or "spherical" for
// messages), and *parent its parent's body (−1: W). Throws std::invalid_argument naming `name` for a body index out of
// range, a body that is not a tree link (Scene.add_tree) or one whose joint is not of JointKind.
template <class JointKind>
const Link& joint_link(int body, const std::vector<Body>& bodies, const std::string& name, const char* kind_name, int* parent) {
  check_body_index(body, static_cast<int>(bodies.size()), name);
  const auto* link = std::get_if<TreeLink>(&bodies[body]);
  const std::string expected = std::string("a link of a tree (Scene.add_tree) with a ") + kind_name + " joint";
  if (link == nullptr) throw_invalid(name, expected, std::to_string(body) + " (a " + rigiddyn::kind_name(bodies[body]) + ")");
  const Link& joint_link = link->tree->link(link->link);
  if (!std::holds_alternative<JointKind>(joint_link.joint)) {
    throw_invalid(name, expected,
                  std::to_string(body) + " ('" + joint_link.name + "', whose joint is " + joint_kind(joint_link.joint) + ")");
  }
  *parent = joint_link.parent < 0 ? -1 : body - link->link + joint_link.parent;
  return joint_link;
}

// Adds the couple couple_L [N m] (in L, B's axes) to the link `link` and −couple_L to its parent `parent` (−1: W, which
// takes it): a couple acts alike at every point, so no moment arm enters.
inline void add_couple_pair(int link, int parent, const Eigen::Vector3d& couple_L, const std::vector<BodyKinematics>& kinematics,
                            std::vector<BodyWrench>& wrenches) {
  wrenches[link].tau_B += couple_L;
  if (parent >= 0) wrenches[parent].tau_B -= kinematics[parent].R_WB.transpose() * (kinematics[link].R_WB * couple_L);
}

// The joint of the link body `body`, of kind JointKind (RevoluteJoint or PrismaticJoint; kind_name "revolute" or
// "prismatic" for messages), and the wrench pair of a force in it.
template <class JointKind>
class JointForce {
 public:
  // Throws std::invalid_argument naming `name` for a body index out of range, a body that is not a tree link
  // (Scene.add_tree) or one whose joint is not of JointKind.
  JointForce(int body, const std::vector<Body>& bodies, const std::string& name, const char* kind_name) : link_(body) {
    const Link& link = joint_link<JointKind>(body, bodies, name, kind_name, &parent_);
    axis_L_ = std::get<JointKind>(link.joint).axis;
    c_L_ = link.inertia.com();
  }

  // What the pair needs and gives: the attitudes (to turn a and the moment arms), a torque, and a force for a
  // prismatic joint
  ElementTraits traits() const {
    ElementTraits t{};
    t.reads_attitude = true, t.has_torque = true, t.has_force = linear;
    return t;
  }

  // The joint's q and q̇ at the evaluation (the link's joint coordinates, body_kinematics.hpp)
  double q(const std::vector<BodyKinematics>& kinematics) const { return kinematics[link_].joint_q[0]; }
  double q_dot(const std::vector<BodyKinematics>& kinematics) const { return kinematics[link_].joint_v[0]; }

  // Adds S τ to the link and −S τ to its parent (header); returns the power τ q̇ [W].
  double add(double tau, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    if constexpr (linear) {
      // the force τ a at L's origin: its moment about the link's centre of mass is (0 − c_L) × τ a; on the parent
      // −τ a, whose moment about the parent's centre of mass is (p_L − p_P) × (−τ a)
      const BodyKinematics& link = kinematics[link_];
      const Eigen::Vector3d along_W = link.R_WB * (tau * axis_L_);
      wrenches[link_].f_W += along_W;
      wrenches[link_].tau_B += Force::at_point(-c_L_, tau * axis_L_).angular;
      if (parent_ >= 0) {
        const BodyKinematics& parent = kinematics[parent_];
        const Eigen::Vector3d joint_W = link.pose().act_point(-c_L_);  // L's origin in W
        wrenches[parent_].add(parent.R_WB, Force::at_point(joint_W - parent.p_W, -along_W));
      }
    } else {
      add_couple_pair(link_, parent_, tau * axis_L_, kinematics, wrenches);
    }
    return tau * q_dot(kinematics);
  }

 private:
  static constexpr bool linear = std::is_same_v<JointKind, PrismaticJoint>;  // a force, not a couple
  int link_, parent_ = -1;  // the link's body and its parent's (−1: W)
  Eigen::Vector3d axis_L_;  // a, unit, in L (= B's axes)
  Eigen::Vector3d c_L_;     // the link's centre of mass in L [m]
};

}  // namespace rigiddyn::detail
