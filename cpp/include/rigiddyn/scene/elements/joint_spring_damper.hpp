// A linear spring and damper across a one-degree-of-freedom joint of a tree (revolute_spring_damper.hpp,
// prismatic_spring_damper.hpp): the joint force
//   τ = −k (q − q0) − c q̇   [N m about a revolute joint's axis, N along a prismatic joint's],
// with potential V = ½ k (q − q0)². A joint force τ enters the dynamics as τ_i = S_iᵀ f_i (Featherstone Table 5.1):
// it is the wrench S τ that the parent exerts on the link across the joint, and −S τ that the link exerts on the
// parent (W takes it for a root link), both at the joint's origin, the link frame's origin L, in L. S = [a; 0]
// (a couple τ a) for a revolute joint, S = [0; a] (a force τ a through L's origin) for a prismatic one. The pair
// is internal: it conserves the tree's momenta, and its power over the two bodies is τ q̇ (their relative twist
// across the joint is S q̇, Featherstone §4.4).
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_traits.hpp"
#include "rigiddyn/scene/elements/element_checks.hpp"
#include "rigiddyn/tree/tree_link.hpp"

#include <Eigen/Core>

#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace rigiddyn {

// The compiled term of a spring and damper across a joint of kind JointKind (RevoluteJoint or PrismaticJoint),
// made from its Spec (body, stiffness, damping and rest(): q0).
template <class Spec, class JointKind>
class JointSpringDamperTerm {
 public:
  // Throws std::invalid_argument naming "<name>.body" for a body that is not a tree link (Scene.add_tree) or whose
  // joint is not of JointKind, "<name>.stiffness" / "<name>.damping" for a value negative or not finite and the
  // rest position's field for one not finite.
  JointSpringDamperTerm(const Spec& spec, const std::vector<Body>& bodies, const std::string& name)
      : link_(spec.body), k_(spec.stiffness), q0_(spec.rest()), c_(spec.damping) {
    check_body_index(spec.body, static_cast<int>(bodies.size()), name + ".body");
    const auto* link = std::get_if<TreeLink>(&bodies[spec.body]);
    const std::string expected = std::string("a link of a tree (Scene.add_tree) with a ") + Spec::joint_kind + " joint";
    if (link == nullptr) throw_invalid(name + ".body", expected, std::to_string(spec.body) + " (a " + kind_name(bodies[spec.body]) + ")");
    const Link& joint_link = link->tree->link(link->link);
    const auto* joint = std::get_if<JointKind>(&joint_link.joint);
    if (joint == nullptr) {
      throw_invalid(name + ".body", expected,
                    std::to_string(spec.body) + " ('" + joint_link.name + "', whose joint is " + joint_kind(joint_link.joint) + ")");
    }
    parent_ = joint_link.parent < 0 ? -1 : spec.body - link->link + joint_link.parent;
    axis_L_ = joint->axis;
    c_L_ = joint_link.inertia.com();
    detail::require_nonnegative(spec.stiffness, name + ".stiffness");
    require_finite(spec.rest(), name + "." + Spec::rest_key);
    detail::require_nonnegative(spec.damping, name + ".damping");
  }

  ElementTraits traits() const {
    ElementTraits t{};
    t.reads_attitude = true, t.velocity_dependent = c_ > 0.0, t.time_dependent = false;
    t.has_potential = true, t.has_torque = true, t.has_force = linear;
    return t;
  }

  // Adds S τ to the link and −S τ to its parent (header); returns the power τ q̇ [W].
  double add_wrenches(double /*t*/, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    const BodyKinematics& link = kinematics[link_];
    const double q_dot = link.joint_v[0];
    const double tau = -k_ * (link.joint_q[0] - q0_) - c_ * q_dot;
    const Eigen::Vector3d along_W = link.R_WB * (tau * axis_L_);  // the couple τ a, or the force τ a, in W
    if constexpr (linear) {
      // the force τ a at L's origin: its moment about the centre of mass is (0 − c_L) × τ a
      wrenches[link_].f_W += along_W;
      wrenches[link_].tau_B -= c_L_.cross(tau * axis_L_);
    } else {
      wrenches[link_].tau_B += tau * axis_L_;
    }
    if (parent_ >= 0) {
      const BodyKinematics& parent = kinematics[parent_];
      Eigen::Vector3d moment_W = -along_W;  // the parent's couple, or the moment of its force about its centre of mass
      if constexpr (linear) {
        const Eigen::Vector3d joint_W = link.p_W - link.R_WB * c_L_;  // L's origin in W
        wrenches[parent_].f_W -= along_W;
        moment_W = (joint_W - parent.p_W).cross(-along_W);
      }
      wrenches[parent_].tau_B += parent.R_WB.transpose() * moment_W;
    }
    return tau * q_dot;
  }

  // V = ½ k (q − q0)² [J]
  double potential(const std::vector<BodyKinematics>& kinematics) const {
    const double stretch = kinematics[link_].joint_q[0] - q0_;
    return 0.5 * k_ * stretch * stretch;
  }

 private:
  static constexpr bool linear = std::is_same_v<JointKind, PrismaticJoint>;  // a force, not a couple
  int link_, parent_ = -1;  // the link's body and its parent's (−1: W)
  Eigen::Vector3d axis_L_;  // a, unit, in L (= B's axes)
  Eigen::Vector3d c_L_;     // the link's centre of mass in L [m]
  double k_, q0_, c_;       // [N m/rad, rad, N m s/rad] or [N/m, m, N s/m]
};

}  // namespace rigiddyn
