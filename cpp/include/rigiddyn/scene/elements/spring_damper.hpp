// A linear spring and damper between a point of body a and a point of body b, or a point of body a and a
// point fixed in W (Craig, "Rigid Body Dynamics" slides: the moment r × f of a force applied at a point
// about the centre of mass). With x_a = p_a + R_a point_a_B, x_b = p_b + R_b point_b (or the anchor
// point_b in W), d = x_a − x_b, ℓ = |d|, u = d/ℓ, and the point velocities ẋ = v_W + R (w_B × point_B):
//   f_a = −(k (ℓ − ℓ0) + c ℓ̇) u,  ℓ̇ = u·(ẋ_a − ẋ_b)  (spring and damper both act along the line, so the
//   pair exerts no net moment and conserves linear and angular momentum; with ℓ0 = 0 the spring part is
//   −k d, linear in the state);
// At ℓ = 0 the direction u is undefined: the term then applies no force (with ℓ0 = 0 that is the spring's
// own value there; with ℓ0 > 0 it is the mean over all directions; a trajectory meets this set of measure
// zero only by coincidence) and V = ½ k ℓ0² stays continuous. Damping makes it velocity dependent: power
// −c ℓ̇² beyond −dV/dt.
#pragma once
#include "rigiddyn/always_inline.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/element_traits.hpp"
#include "rigiddyn/scene/elements/element_checks.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

namespace rigiddyn {

class SpringDamperTerm;

// The spec: body_a and point_a_B [m] (in a's frame B, from its centre of mass); body_b = −1 with the
// world anchor point_b [m] in W, or body_b >= 0 with point_b in b's frame B (from its centre of mass);
// stiffness k [N/m], rest_length ℓ0 [m], damping c [N s/m], all >= 0.
struct SpringDamper {
  static constexpr const char* element_type = "SpringDamper";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "A linear spring and damper between point_a_B of body_a (in its frame B, from its centre of mass) and "
      "point_b of body_b (in its B) or, body_b None, the world anchor point_b in W. Force on a: -(stiffness (l "
      "- rest_length) + damping dl/dt) u, u = (x_a - x_b)/l, l = |x_a - x_b| [N], along the line (no force at l"
      " = 0), so the pair conserves momentum and angular momentum; the opposite on b; torque r x f about each "
      "centre of mass. Potential V = stiffness (l - rest_length)^2/2 [J].";
  static constexpr const char* example = R"py(A mass on a spring to a world anchor oscillates at ω = √(k/m): after one period 2π√(m/k) it is back at its
start:

>>> scene = rd.Scene([rd.Particle(2.0)], elements=[rd.SpringDamper(body_a=0, stiffness=8.0)])
>>> start = rd.ParticleState(p_W=(0.1, 0.0, 0.0))
>>> period = 2 * np.pi * np.sqrt(2.0 / 8.0)
>>> result = rd.simulate(scene, [start], period / 1000, steps=1000, method="rk4")
>>> result.p_W[-1, 0].round(9)
array([0.1, 0. , 0. ]))py";  // the docstring's Examples (run as doctests)
  using Term = SpringDamperTerm;  // what compile makes of it
  int body_a = 0;
  Eigen::Vector3d point_a_B = Eigen::Vector3d::Zero();
  int body_b = -1;
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();
  double stiffness = 0.0;
  double rest_length = 0.0;
  double damping = 0.0;

  // What the fields must satisfy together (the Python class checks it when built, the term again): end b
  // is not body a.
  void check_fields() const {
    if (body_b == body_a) {
      throw_invalid("body_b", "None (a world anchor) or a body other than body_a = " + std::to_string(body_a), body_b);
    }
  }

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        body_field("body_a", &SpringDamper::body_a, "index of the body at end a"),
        vector_field("point_a_B", &SpringDamper::point_a_B, "m", "(3,) end a in body a's frame B, from its centre of mass [m]"),
        optional_body_field("body_b", &SpringDamper::body_b, "index of the body at end b, or None: end b is the world anchor point_b"),
        vector_field("point_b", &SpringDamper::point_b, "m",
                     "(3,) end b: in body b's frame B from its centre of mass, or in W if body_b is None [m]"),
        scalar_field("stiffness", &SpringDamper::stiffness, "N/m", "spring stiffness k [N/m]").must_be_given().at_least_zero(),
        scalar_field("rest_length", &SpringDamper::rest_length, "m", "rest length l0 [m]").at_least_zero(),
        scalar_field("damping", &SpringDamper::damping, "N*s/m", "damping coefficient c [N s/m]").at_least_zero());
  }
};

// The compiled term.
class SpringDamperTerm {
 public:
  // Throws std::invalid_argument naming "<name>.<field>": body_a not a body index; body_b neither −1 nor
  // a body index, or equal to body_a; a non-finite point; a non-zero point on a particle; a point off the
  // xy plane (z ≠ 0) on a planar body; stiffness, rest_length or damping negative or non-finite.
  SpringDamperTerm(const SpringDamper& spec, const std::vector<Body>& bodies, const std::string& name)
      : a_(spec.body_a), b_(spec.body_b), point_a_B_(spec.point_a_B), point_b_(spec.point_b), k_(spec.stiffness),
        rest_length_(spec.rest_length), c_(spec.damping) {
    const int n = static_cast<int>(bodies.size());
    check_body_index(spec.body_a, n, name + ".body_a");
    if (spec.body_b != -1) {
      if (spec.body_b < 0 || spec.body_b >= n) {
        throw_invalid(name + ".body_b", "-1 (a world anchor) or a body index in [0, " + std::to_string(n) + ")", spec.body_b);
      }
      if (spec.body_b == spec.body_a) throw_invalid(name + ".body_b", "a body other than body_a", spec.body_b);
    }
    detail::require_body_point(bodies[spec.body_a], spec.point_a_B, name + ".point_a_B");
    if (spec.body_b == -1) {
      require_finite(spec.point_b, name + ".point_b");
    } else {
      detail::require_body_point(bodies[spec.body_b], spec.point_b, name + ".point_b");
    }
    detail::require_nonnegative(spec.stiffness, name + ".stiffness");
    detail::require_nonnegative(spec.rest_length, name + ".rest_length");
    detail::require_nonnegative(spec.damping, name + ".damping");
  }

  ElementTraits traits() const {
    const bool offset = !point_a_B_.isZero(0.0) || (b_ >= 0 && !point_b_.isZero(0.0));
    ElementTraits t{};
    t.reads_attitude = offset, t.velocity_dependent = c_ > 0.0, t.time_dependent = false;
    t.has_potential = true, t.has_torque = offset;
    t.zero_net_wrench = b_ >= 0;  // f_a and −f_a along d = x_a − x_b: their moment (x_a − x_b) × f_a = 0
    return t;
  }

  // Adds f_a, its moment on a, and −f_a with its moment on b (none for a world anchor); returns the power
  // f_a·(ẋ_a − ẋ_b) [W] (= Σ f_W·v_W + tau_B·w_B over both bodies).
  RIGIDDYN_ALWAYS_INLINE double add_wrenches(double /*t*/, const std::vector<BodyKinematics>& kinematics,
                                             std::vector<BodyWrench>& wrenches) const {
    // each end: its point x = p_W + R_WB r_B, its velocity ẋ (the body's twist at the point, point_velocity_W), and the
    // force there moved to the body's centre of mass, in B (Force::at_point(r_B, R_WBᵀ f))
    const BodyKinematics& a = kinematics[a_];
    const Eigen::Vector3d r_a_W = a.R_WB * point_a_B_;  // from a's centre of mass to its point, in W
    Eigen::Vector3d d = a.p_W + r_a_W, relative_velocity = a.point_velocity_W(point_a_B_);
    if (b_ >= 0) {
      const BodyKinematics& b = kinematics[b_];
      d -= b.p_W + b.R_WB * point_b_;
      relative_velocity -= b.point_velocity_W(point_b_);
    } else {
      d -= point_b_;
    }
    const Eigen::Vector3d f_a = force_on_a(d, relative_velocity);
    wrenches[a_].f_W += f_a;
    wrenches[a_].tau_B += Force::at_point(point_a_B_, a.R_WB.transpose() * f_a).angular;
    if (b_ >= 0) {
      const BodyKinematics& b = kinematics[b_];
      wrenches[b_].f_W -= f_a;
      wrenches[b_].tau_B -= Force::at_point(point_b_, b.R_WB.transpose() * f_a).angular;
    }
    return f_a.dot(relative_velocity);
  }

  // V = ½ k (ℓ − ℓ0)² [J]
  double potential(const std::vector<BodyKinematics>& kinematics) const {
    Eigen::Vector3d d = kinematics[a_].pose().act_point(point_a_B_);
    d -= b_ >= 0 ? kinematics[b_].pose().act_point(point_b_) : point_b_;
    const double stretch = d.norm() - rest_length_;
    return 0.5 * k_ * stretch * stretch;
  }

  int body_a() const { return a_; }
  int body_b() const { return b_; }

 private:
  // f_a of the law above from d = x_a − x_b [m] and ẋ_a − ẋ_b [m/s].
  Eigen::Vector3d force_on_a(const Eigen::Vector3d& d, const Eigen::Vector3d& relative_velocity) const {
    const double l = d.norm();
    if (l == 0.0) return Eigen::Vector3d::Zero();  // u undefined (see the header)
    const Eigen::Vector3d u = d / l;
    return -(k_ * (l - rest_length_) + c_ * u.dot(relative_velocity)) * u;
  }

  int a_, b_;                   // body indices; b_ = −1: world anchor
  Eigen::Vector3d point_a_B_;   // [m] in a's B
  Eigen::Vector3d point_b_;     // [m] in b's B, or in W for an anchor
  double k_, rest_length_, c_;  // [N/m], [m], [N s/m]
};

}  // namespace rigiddyn
