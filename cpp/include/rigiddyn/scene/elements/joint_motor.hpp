// A motor in a one-degree-of-freedom joint of a tree (revolute_motor.hpp, prismatic_motor.hpp): the constant joint
// force τ [N m about a revolute joint's axis, N along a prismatic joint's] on [t_start, t_end) (by default all of
// time), none outside,
// applied as the wrench pair of joint_force.hpp (power τ q̇; no potential: the motor may do any work). The schedule
// is piecewise constant: the run loop splits every step at t_start and t_end (switches()) and sets the piece
// between the sub-steps (set_time), as for ScheduledLoads; a derivative evaluation never looks at the time. A
// controller (scene/controller.hpp) may command the force at its samples: the command then replaces the window and
// holds until the next one.
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_traits.hpp"
#include "rigiddyn/scene/elements/joint_force.hpp"
#include "rigiddyn/scene/elements/time_window.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace rigiddyn {

// The compiled term of a motor in a joint of kind JointKind (RevoluteJoint or PrismaticJoint), made from its Spec
// (body, value(): τ, t_start, t_end).
template <class Spec, class JointKind>
class JointMotorTerm {
 public:
  // Throws std::invalid_argument naming "<name>.body" for a body that is not a tree link (Scene.add_tree) or whose
  // joint is not of JointKind, the force's field for one not finite, "<name>.t_start" for NaN and "<name>.t_end" for
  // one not after t_start.
  JointMotorTerm(const Spec& spec, const std::vector<Body>& bodies, const std::string& name)
      : joint_(spec.body, bodies, name + ".body", Spec::joint_kind), value_(spec.value()), t_start_(spec.t_start),
        t_end_(spec.t_end) {
    require_finite(spec.value(), name + "." + Spec::value_key);
    if (std::isnan(spec.t_start)) throw_invalid(name + ".t_start", "a time (-inf: on from any time)", spec.t_start);
    detail::check_window(spec.t_start, spec.t_end, name + ".");
    set_time(0.0);
  }

  ElementTraits traits() const {
    ElementTraits t = joint_.traits();
    t.velocity_dependent = false, t.has_potential = false;
    t.time_dependent = std::isfinite(t_start_) || std::isfinite(t_end_);  // on a bounded part of time only
    return t;
  }

  // Sets the force of the piece that contains t [s]: τ on [t_start, t_end), 0 outside.
  void set_time(double t) { tau_ = t >= t_start_ && t < t_end_ ? value_ : 0.0; }

  // A controller's command at a sample: the force τ [N m or N] from now on, in place of the window (the sample
  // times are unused: the command is held, not ramped).
  void command_scalar(double tau, double /*t_k*/, double /*t_next*/, double /*t*/) {
    value_ = tau, tau_ = tau;
    t_start_ = -std::numeric_limits<double>::infinity(), t_end_ = std::numeric_limits<double>::infinity();
  }

  // Adds the pair of the piece's τ; returns its power τ q̇ [W].
  double add_wrenches(double /*t*/, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    if (tau_ == 0.0) return 0.0;
    return joint_.add(tau_, kinematics, wrenches);
  }

  double potential(const std::vector<BodyKinematics>& /*kinematics*/) const { return 0.0; }

 private:
  detail::JointForce<JointKind> joint_;
  double value_, t_start_, t_end_;  // τ [N m or N] on [t_start, t_end) [s]
  double tau_ = 0.0;                // τ of the current piece
};

}  // namespace rigiddyn
