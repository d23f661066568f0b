// Linear and quadratic drag on each listed body: a force at the centre of mass opposing its velocity and,
// optionally, a torque opposing its rotation (still-fluid model; Stokes' linear and Newton's quadratic law,
// both coefficients lumped, e.g. c₂ = ½ ρ C_d A):
//   f_W = −(c₁ + c₂ |v_W|) v_W,   tau_B = −(d₁ + d₂ |w_B|) w_B.
// Dissipative (power −(c₁ + c₂|v|)|v|² − (d₁ + d₂|ω|)|ω|² ≤ 0), no potential. A particle has w_B = 0
// and gets no torque.
#pragma once
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_bodies.hpp"
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/element_traits.hpp"
#include "rigiddyn/scene/elements/element_checks.hpp"

#include <Eigen/Core>

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

namespace rigiddyn {

class DragTerm;

// The spec: linear c₁ [N s/m] and quadratic c₂ [N s²/m²] coefficients of the force, angular_linear d₁
// [N m s] and angular_quadratic d₂ [N m s²] of the torque, all >= 0, on `bodies` (empty: every body).
struct Drag {
  static constexpr const char* element_type = "Drag";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "Linear and quadratic drag on the listed bodies: f_W = -(linear + quadratic |v_W|) v_W [N] at the centre "
      "of mass and tau_B = -(angular_linear + angular_quadratic |w_B|) w_B [N m]. Velocity-dependent: the "
      "splitting methods warn (SceneCompatibilityWarning).";
  static constexpr const char* example = R"py(Linear drag slows a particle exponentially, v(t) = v0 exp(-c t/m):

>>> scene = rd.Scene([rd.Particle(2.0)], elements=[rd.Drag(linear=1.0)])
>>> result = rd.simulate(scene, [rd.ParticleState(v_W=(1.0, 0.0, 0.0))], 1e-3, duration=2.0, method="rk4")
>>> bool(np.isclose(result.v_W[-1, 0, 0], np.exp(-1.0), rtol=1e-10))
True)py";  // the docstring's Examples (run as doctests)
  using Term = DragTerm;  // what compile makes of it
  double linear = 0.0;
  double quadratic = 0.0;
  double angular_linear = 0.0;
  double angular_quadratic = 0.0;
  BodyList bodies;

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        scalar_field("linear", &Drag::linear, "N*s/m", "c1 of f_W = -(c1 + c2 |v_W|) v_W [N s/m]").at_least_zero(),
        scalar_field("quadratic", &Drag::quadratic, "N*s^2/m^2", "c2 of f_W = -(c1 + c2 |v_W|) v_W [N s^2/m^2]").at_least_zero(),
        scalar_field("angular_linear", &Drag::angular_linear, "N*m*s", "d1 of tau_B = -(d1 + d2 |w_B|) w_B [N m s/rad]")
            .at_least_zero(),
        scalar_field("angular_quadratic", &Drag::angular_quadratic, "N*m*s^2",
                     "d2 of tau_B = -(d1 + d2 |w_B|) w_B [N m s^2/rad^2]").at_least_zero(),
        bodies_field(&Drag::bodies));
  }
};

// The compiled term.
class DragTerm {
 public:
  // Throws std::invalid_argument "<name>.<coefficient>: ..." for a negative or non-finite coefficient,
  // "<name>.bodies[k]: ..." for an index out of range or repeated.
  DragTerm(const Drag& spec, const std::vector<Body>& bodies, const std::string& name)
      : c1_(spec.linear), c2_(spec.quadratic), d1_(spec.angular_linear), d2_(spec.angular_quadratic),
        bodies_(detail::resolve_bodies(spec.bodies, bodies.size(), name)) {
    detail::require_nonnegative(spec.linear, name + ".linear");
    detail::require_nonnegative(spec.quadratic, name + ".quadratic");
    detail::require_nonnegative(spec.angular_linear, name + ".angular_linear");
    detail::require_nonnegative(spec.angular_quadratic, name + ".angular_quadratic");
  }

  ElementTraits traits() const {
    ElementTraits t{};
    t.reads_attitude = false, t.velocity_dependent = true, t.time_dependent = false;
    t.has_potential = false, t.has_torque = d1_ > 0.0 || d2_ > 0.0, t.has_force = c1_ > 0.0 || c2_ > 0.0;
    return t;
  }

  // Adds f_W and tau_B above to each listed body; returns their power Σ f_W·v_W + tau_B·w_B (<= 0) [W].
  double add_wrenches(double /*t*/, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    double power = 0.0;
    for (const int b : bodies_) {
      const Eigen::Vector3d& v = kinematics[b].v_W;
      const Eigen::Vector3d& w = kinematics[b].w_B;
      const double v2 = v.squaredNorm(), w2 = w.squaredNorm();
      const double force_rate = c1_ + c2_ * std::sqrt(v2);   // [N s/m]
      const double torque_rate = d1_ + d2_ * std::sqrt(w2);  // [N m s]
      wrenches[b].f_W -= force_rate * v;
      wrenches[b].tau_B -= torque_rate * w;
      power -= force_rate * v2 + torque_rate * w2;
    }
    return power;
  }

  double potential(const std::vector<BodyKinematics>& /*kinematics*/) const { return 0.0; }

  const std::vector<int>& bodies() const { return bodies_; }

 private:
  double c1_, c2_, d1_, d2_;
  std::vector<int> bodies_;
};

}  // namespace rigiddyn
