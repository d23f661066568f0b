// A linear spring and damper across a one-degree-of-freedom joint of a tree (revolute_spring_damper.hpp,
// prismatic_spring_damper.hpp): the joint force
//   τ = −k (q − q0) − c q̇   [N m about a revolute joint's axis, N along a prismatic joint's],
// with potential V = ½ k (q − q0)², applied as the wrench pair of joint_force.hpp (power τ q̇).
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_traits.hpp"
#include "rigiddyn/scene/elements/element_checks.hpp"
#include "rigiddyn/scene/elements/joint_force.hpp"

#include <string>
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
      : joint_(spec.body, bodies, name + ".body", Spec::joint_kind), k_(spec.stiffness), q0_(spec.rest()), c_(spec.damping) {
    detail::require_nonnegative(spec.stiffness, name + ".stiffness");
    require_finite(spec.rest(), name + "." + Spec::rest_key);
    detail::require_nonnegative(spec.damping, name + ".damping");
  }

  ElementTraits traits() const {
    ElementTraits t = joint_.traits();
    t.velocity_dependent = c_ > 0.0, t.time_dependent = false, t.has_potential = true;
    return t;
  }

  // Adds the pair of τ = −k (q − q0) − c q̇; returns its power τ q̇ [W].
  double add_wrenches(double /*t*/, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    return joint_.add(-k_ * (joint_.q(kinematics) - q0_) - c_ * joint_.q_dot(kinematics), kinematics, wrenches);
  }

  // V = ½ k (q − q0)² [J]
  double potential(const std::vector<BodyKinematics>& kinematics) const {
    const double stretch = joint_.q(kinematics) - q0_;
    return 0.5 * k_ * stretch * stretch;
  }

 private:
  detail::JointForce<JointKind> joint_;
  double k_, q0_, c_;  // [N m/rad, rad, N m s/rad] or [N/m, m, N s/m]
};

}  // namespace rigiddyn
