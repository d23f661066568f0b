// A reaction wheel inside a rigid body (a gyrostat), spinning about the axis a (a unit vector fixed in B) at
// the commanded speed Ω(t) relative to the body: J its moment of inertia about a, h_B = J Ω(t) a its angular
// momentum relative to the body. With I the inertia of the whole body (wheel included), Euler's equation of
// the gyrostat (Hughes, "Spacecraft Attitude Dynamics", the gyrostat's equations of motion) is
//   I ω̇ + ω × (I ω + h_B) = τ − ḣ_B,
// i.e. the rigid body's own equation under the couple
//   tau_B = −ω_B × h_B − ḣ_B,   ḣ_B = J Ω̇(t) a.
// The speed ramps at a constant rate between two times: Ω(t) = speed + acceleration (clamp(t, t_start, t_end)
// − t_start), Ω̇ = acceleration on [t_start, t_end), 0 outside; a run splits its steps at t_start and t_end, as
// at a load's switch times. Its power on the body is tau_B·ω_B = −ḣ_B·ω_B (the term −ω × h does no work):
// at a constant wheel speed the body's kinetic energy ½ ωᵀ I ω and the total angular momentum R_WB (I ω + h_B)
// are conserved. No force, no potential. Rigid bodies, free or pinned; particles and planar bodies refused.
// A controller may command its speed Ω_c at a sample t_k (scene/controller.hpp): the ramp is then replaced by
// the one from Ω(t_k) to Ω_c over [t_k, t_next), t_next the next sample (a rate-limited speed loop, ḣ finite).
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/models/loads.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/element_traits.hpp"
#include "rigiddyn/scene/elements/time_window.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace rigiddyn {

class ReactionWheelTerm;

// The spec: a wheel of moment of inertia `inertia` about axis_B in body `body`, at the commanded speed above.
struct ReactionWheel {
  static constexpr const char* element_type = "ReactionWheel";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "A reaction wheel inside a rigid body (a gyrostat): a wheel of moment of inertia J = inertia about the "
      "unit axis a = axis_B/|axis_B| (fixed in B) spins relative to the body at the commanded speed Omega(t) = "
      "speed + acceleration (clamp(t, t_start, t_end) - t_start), so its relative angular momentum is h_B = J "
      "Omega a. The body's inertia is the whole body's, wheel included; the element applies the couple tau_B "
      "= -w_B x h_B - dh_B/dt [N m] of Euler's equation of the gyrostat, I dw/dt + w x (I w + h) = tau - dh/dt. "
      "A run splits its steps at t_start and t_end. At a constant wheel speed the body's kinetic energy and "
      "the total angular momentum R (I w + h) are conserved; spinning the wheel up about a principal axis turns "
      "the body by -J/I times the wheel's angle. A rigiddyn.Controller may command its speed (a rate-limited "
      "speed loop: from its speed at a sample to the commanded one at the next, at a constant rate). Rigid bodies, "
      "free or pinned.";
  static constexpr const char* example = R"py(A wheel (J = 0.1 kg m²) spun up to 1 rad/s about z turns a body (I = 1 kg m², wheel included) the other way at
J/I × 1 rad/s, so that the total angular momentum stays zero:

>>> body = rd.RigidBody(10.0, [1.0, 1.0, 1.0])
>>> wheel = rd.ReactionWheel(body=0, axis_B=(0.0, 0.0, 1.0), inertia=0.1, acceleration=1.0, t_end=1.0)
>>> result = rd.simulate(rd.Scene([body], elements=[wheel]), [rd.RigidBodyState()], 0.01, duration=2.0,
...                      method="rk4")
>>> result.w_B[-1, 0].round(12)
array([ 0. ,  0. , -0.1]))py";  // the docstring's Examples (run as doctests)
  using Term = ReactionWheelTerm;  // what compile makes of it
  int body = 0;
  Eigen::Vector3d axis_B = Eigen::Vector3d::UnitZ();
  double inertia = 0.0;
  double speed = 0.0;
  double acceleration = 0.0;
  double t_start = 0.0;
  double t_end = std::numeric_limits<double>::infinity();

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        body_field("body", &ReactionWheel::body, "index of the rigid body (free or pinned) that carries the wheel"),
        vector_field("axis_B", &ReactionWheel::axis_B, "", "(3,) the wheel's spin axis in B (normalised; not zero)")
            .must_be_given(),
        scalar_field("inertia", &ReactionWheel::inertia, "kg*m^2", "the wheel's moment of inertia J about its axis [kg m^2]")
            .must_be_given()
            .above_zero(),
        scalar_field("speed", &ReactionWheel::speed, "rad/s", "the wheel's speed relative to the body at t_start [rad/s]"),
        scalar_field("acceleration", &ReactionWheel::acceleration, "rad/s^2",
                     "the rate of the wheel's speed on [t_start, t_end) [rad/s^2]"),
        scalar_field("t_start", &ReactionWheel::t_start, "s", "the start of the ramp [s]"),
        scalar_field("t_end", &ReactionWheel::t_end, "s", "the end of the ramp [s] (inf: none)").may_be_infinite());
  }

  // What the fields must satisfy together: a non-zero axis, a ramp that ends after it starts.
  void check_fields() const {
    if (!axis_B.allFinite() || axis_B.isZero(0.0)) throw_invalid("axis_B", "a finite non-zero vector", axis_B);
    detail::check_window(t_start, t_end);
  }

  // The times at which a run splits its steps: the ramp's start and end.
  std::vector<AppliedLoad> switches() const { return detail::window_switches(t_start, t_end); }
};

// The compiled term.
class ReactionWheelTerm {
 public:
  // Throws std::invalid_argument "<name>.<field>: ..." for a field out of its range (check_fields, a
  // non-finite speed, acceleration or t_start, J <= 0) and "<name>.body: ..." for a body out of range or one
  // without a full inertia (a particle or a planar body).
  ReactionWheelTerm(const ReactionWheel& spec, const std::vector<Body>& bodies, const std::string& name)
      : body_(spec.body), J_(spec.inertia), speed_(spec.speed), acceleration_(spec.acceleration),
        t_start_(spec.t_start), t_end_(spec.t_end) {
    check_body_index(spec.body, static_cast<int>(bodies.size()), name + ".body");
    if (!body_traits(bodies[spec.body]).has_spatial_inertia) {
      throw_invalid(name + ".body", "a rigid body, free or pinned (a wheel needs the body's full inertia)",
                    std::string(kind_name(bodies[spec.body])) + " " + std::to_string(spec.body));
    }
    require_positive(spec.inertia, name + ".inertia");
    require_finite(spec.speed, name + ".speed");
    require_finite(spec.acceleration, name + ".acceleration");
    require_finite(spec.t_start, name + ".t_start");
    try {
      spec.check_fields();
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(name + "." + e.what());
    }
    a_B_ = spec.axis_B.stableNormalized();  // (scaled first: an axis of 1e308 stays an axis)
    set_time(t_start_);
  }

  ElementTraits traits() const {
    ElementTraits t{};
    t.reads_attitude = false, t.velocity_dependent = true, t.time_dependent = acceleration_ != 0.0;
    t.has_potential = false, t.has_torque = true, t.has_force = false, t.needs_attitude = true;
    return t;
  }

  // The piece of the run that starts at t [s] (the run loop calls it at t0 and at each switch time): the
  // ramp's rate inside [t_start, t_end), 0 outside, held over the piece.
  void set_time(double t) { rate_ = t >= t_start_ && t < t_end_ ? acceleration_ : 0.0; }

  // A controller's speed command at the sample t_k [s]: Ω ramps from Ω(t_k) to `speed` [rad/s] at t_next [s]
  // (> t_k) at a constant rate, then holds it; the piece that starts at t [s] (≈ t_k) is set.
  void command_scalar(double speed, double t_k, double t_next, double t) {
    const double from = speed_at(t_k);
    speed_ = from, acceleration_ = (speed - from) / (t_next - t_k), t_start_ = t_k, t_end_ = t_next;
    set_time(t);
  }

  // The wheel's speed relative to the body at t [rad/s].
  double speed_at(double t) const { return speed_ + acceleration_ * (std::clamp(t, t_start_, t_end_) - t_start_); }

  // tau_B = −ω_B × h_B − ḣ_B on the body; returns its power tau_B·ω_B [W].
  double add_wrenches(double t, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    const Eigen::Vector3d& w_B = kinematics[body_].w_B;
    const Eigen::Vector3d tau_B = -(J_ * speed_at(t)) * w_B.cross(a_B_) - (J_ * rate_) * a_B_;
    wrenches[body_].tau_B += tau_B;
    return tau_B.dot(w_B);
  }

  double potential(const std::vector<BodyKinematics>& /*kinematics*/) const { return 0.0; }

  int body() const { return body_; }

 private:
  int body_;
  Eigen::Vector3d a_B_;                 // the unit axis in B
  double J_, speed_, acceleration_;     // [kg m²], [rad/s], [rad/s²]
  double t_start_, t_end_;              // [s]
  double rate_ = 0.0;                   // Ω̇ over the current piece [rad/s²]
};

}  // namespace rigiddyn
