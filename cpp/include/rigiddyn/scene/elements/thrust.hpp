// Thrust: the force of the mass a body exchanges (docs/fixed_point_frames_mass.md §3). A body with a MassFlow
// (scene/mass_flow.hpp) loses (ṁ < 0) or gains (ṁ > 0) mass at the rate ṁ(t); the mass moves with the velocity
// u_rel relative to the body. The "Rigid body kinematics and dynamics" notes' eq. (4.36), f = d(m v)/dt,
// written for the body and the exchanged mass together, gives d(m v)/dt = f + ṁ (v + u_rel), i.e.
//   m v̇ = f + ṁ u_rel:
// the thrust f_T = ṁ u_rel [N] acts on the body like an applied force (ṁ < 0 and u_rel backwards: a push
// forwards). It is applied at the body point C + r_B (r_B in B, from the centre of mass), which adds the
// torque r_B × f_B about the centre of mass (Craig, "Rigid Body Dynamics" slides, moment of a force about G).
// "W" is the scene frame. No potential.
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/element_traits.hpp"
#include "rigiddyn/scene/elements/element_checks.hpp"
#include "rigiddyn/scene/mass_flow.hpp"
#include "rigiddyn/so3/integrate.hpp"  // Frame

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

namespace rigiddyn {

class ThrustTerm;

// The spec: the thrust of body `body` (which must have a MassFlow), u_rel [m/s] the velocity of the
// exchanged mass relative to the body, in `frame` (Frame::body: in B, turning with the body; Frame::world:
// in the scene frame), applied at r_B [m] (in B, from the centre of mass; zero: through it).
struct Thrust {
  static constexpr const char* element_type = "Thrust";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "The thrust of a body whose mass changes (its MassFlow, given to Scene.add_body): f = (dm/dt) u_rel [N] "
      "(\"Rigid body kinematics and dynamics\" notes, eq. (4.36): d(m v)/dt = f + (dm/dt)(v + u_rel), so m "
      "dv/dt = f + (dm/dt) u_rel), u_rel the velocity of the mass leaving (dm/dt < 0: u_rel backwards pushes "
      "forwards) or joining the body, relative to it, in `frame` ('body': in B, turning with the body; 'world':"
      " in the scene frame W), applied at r_B in B from the centre of mass (adds the torque r_B x f_B). "
      "Scene.add refuses it (ValueError naming element.body) on a body without a MassFlow. No potential; its "
      "power is in SceneResult.power.";
  static constexpr const char* example = R"py(A rocket particle that burns half its mass at 10 m/s exhaust speed gains 10 ln 2 m/s (Tsiolkovsky):

>>> rocket = rd.Scene([rd.Particle(2.0)], elements=[rd.Thrust(body=0, u_rel=(-10.0, 0.0, 0.0), frame="world")],
...                   mass_flows=[rd.MassFlow(rate=-0.5)])
>>> result = rd.simulate(rocket, [rd.ParticleState()], 0.01, duration=2.0, method="rk4")
>>> round(float(result.mass[-1, 0]), 12), bool(np.isclose(result.v_W[-1, 0, 0], 10 * np.log(2.0), rtol=1e-9))
(1.0, True))py";  // the docstring's Examples (run as doctests)
  static constexpr bool keyword_only = false;  // its Python class also takes its fields by position
  using Term = ThrustTerm;  // what compile makes of it
  int body = 0;
  Eigen::Vector3d u_rel = Eigen::Vector3d::Zero();
  Frame frame = Frame::body;
  Eigen::Vector3d r_B = Eigen::Vector3d::Zero();

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        body_field("body", &Thrust::body, "index of the body (one with a MassFlow) whose exchanged mass pushes it"),
        vector_field("u_rel", &Thrust::u_rel, "m/s", "(3,) velocity of the exchanged mass relative to the body, in `frame` [m/s]")
            .must_be_given(),
        ElementField<Thrust, Frame>{"frame", &Thrust::frame, FieldKind::frame, "",
                                    "'body' (u_rel in B, turning with the body) or 'world' (in the scene frame W)"},
        vector_field("r_B", &Thrust::r_B, "m", "(3,) point of application in B, from the centre of mass [m]"));
  }
};

namespace detail {

// The checks of a Thrust spec against the scene's bodies and mass flows (ThrustTerm, and the fast model of
// scene/fast/variable_mass_particle_model.hpp): std::invalid_argument naming "<name>.body" (out of range, or
// a body without a MassFlow), "<name>.u_rel" (non-finite; on a planar body, out of the plane: u_z ≠ 0 in
// either frame, the plane turns about z), "<name>.frame" (Frame::body on a particle: a point has no axes)
// and "<name>.r_B" (element_checks.hpp's body point).
inline void check_thrust(const Thrust& spec, const std::vector<Body>& bodies,
                         const std::vector<std::optional<MassFlow>>& mass_flows, const std::string& name) {
  check_body_index(spec.body, static_cast<int>(bodies.size()), name + ".body");
  const bool flows = static_cast<std::size_t>(spec.body) < mass_flows.size() && mass_flows[spec.body].has_value();
  if (!flows) {
    throw std::invalid_argument(name + ".body: expected a body with a mass flow (mass_flows[" + std::to_string(spec.body) +
                                "]: a thrust is the force of the mass it exchanges), got body " + std::to_string(spec.body) +
                                " of constant mass");
  }
  const Body& body = bodies[spec.body];
  require_finite(spec.u_rel, name + ".u_rel");
  if (spec.frame != Frame::body && spec.frame != Frame::world) {
    throw_invalid(name + ".frame", "Frame::body or Frame::world", static_cast<int>(spec.frame));
  }
  if (!has_attitude(body) && spec.frame == Frame::body) {
    throw std::invalid_argument(name + ".frame: expected Frame::world on a particle (a point has no axes to turn u_rel "
                                       "with), got Frame::body");
  }
  if (is_planar(body) && spec.u_rel.z() != 0.0) {
    throw_invalid(name + ".u_rel", "a velocity in the plane of the planar body (z = 0)", spec.u_rel);
  }
  require_body_point(body, spec.r_B, name + ".r_B");
}

}  // namespace detail

// The compiled term: the body, u_rel in its frame, r_B and the body's mass flow (ṁ(t) is
// read from it at each evaluation: mass_rate, checked finite).
class ThrustTerm {
 public:
  // spec: the element; bodies, mass_flows: the scene's (mass_flows empty or one per body); name: the
  // element's ("elements[3]"), for messages. Throws std::invalid_argument (detail::check_thrust), e.g.
  // "<name>.body: expected a body with a mass flow ..." for a body of constant mass.
  ThrustTerm(const Thrust& spec, const std::vector<Body>& bodies, const std::vector<std::optional<MassFlow>>& mass_flows,
             const std::string& name)
      : body_(spec.body), u_rel_(spec.u_rel), frame_(spec.frame), r_B_(spec.r_B) {
    detail::check_thrust(spec, bodies, mass_flows, name);
    flow_ = *mass_flows[spec.body];
    flow_name_ = "mass_flows[" + std::to_string(spec.body) + "]";
    torque_ = has_attitude(bodies[spec.body]) && !r_B_.isZero(0.0);
  }

  ElementTraits traits() const {
    ElementTraits t{};
    t.reads_attitude = frame_ == Frame::body || torque_;  // turns u_rel to W, or f_W to B for r_B × f_B
    t.velocity_dependent = false;
    t.time_dependent = !has_constant_rate(flow_);
    t.has_potential = false;
    t.has_torque = torque_;
    return t;
  }

  // f = ṁ(t) u_rel at C + r_B: f_W += f (turned to W when u_rel is in B), tau_B += r_B × f_B on the body
  // (bodies with an attitude only); returns f_W·v_W + tau_B·w_B [W].
  double add_wrenches(double t, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    const BodyKinematics& k = kinematics[body_];
    const double rate = mass_rate(flow_, t, flow_name_);
    const Eigen::Vector3d f = rate * u_rel_;  // in frame_
    const Eigen::Vector3d f_W = frame_ == Frame::body ? Eigen::Vector3d(k.R_WB * f) : f;
    wrenches[body_].f_W += f_W;
    double power = f_W.dot(k.v_W);
    if (torque_) {
      const Eigen::Vector3d f_B = frame_ == Frame::body ? f : Eigen::Vector3d(k.R_WB.transpose() * f);
      const Eigen::Vector3d tau_B = Force::at_point(r_B_, f_B).angular;
      wrenches[body_].tau_B += tau_B;
      power += tau_B.dot(k.w_B);
    }
    return power;
  }

  double potential(const std::vector<BodyKinematics>& /*kinematics*/) const { return 0.0; }

  int body() const { return body_; }
  const Eigen::Vector3d& u_rel() const { return u_rel_; }
  Frame frame() const { return frame_; }
  const Eigen::Vector3d& r_B() const { return r_B_; }
  const MassFlow& mass_flow() const { return flow_; }

 private:
  int body_;
  Eigen::Vector3d u_rel_;  // [m/s] in frame_
  Frame frame_;
  Eigen::Vector3d r_B_;    // [m] in B
  MassFlow flow_;          // the body's (its rate)
  std::string flow_name_;  // "mass_flows[<body>]"
  bool torque_ = false;    // r_B ≠ 0 on a body with an attitude
};

}  // namespace rigiddyn
