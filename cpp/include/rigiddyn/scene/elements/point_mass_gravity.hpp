// Newtonian gravity of a fixed attractor (a point mass or a spherically symmetric body) of gravitational
// parameter GM at p_W, on each listed body treated as a point mass at its centre of mass ("Rigid body
// kinematics and dynamics" notes, §4.11, Newton's law of gravitation), with optional Plummer softening ε:
//   r = p_body − p_W,   f_W = −GM m r / (|r|² + ε²)^{3/2},   V = −GM m / √(|r|² + ε²).
// No torque about the centre of mass at this order (GravityGradient adds the next term of an extended
// body). With ε = 0 the field is singular at the attractor: a body that reaches it gets non-finite forces
// (simulate reports the run as diverged).
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

class PointMassGravityTerm;

// The spec: gravitational parameter gm = G M [m³/s²] of an attractor fixed at p_W [m] in W, softening
// length [m] (0: exact Newtonian law), acting on `bodies` (empty: every body).
struct PointMassGravity {
  static constexpr const char* element_type = "PointMassGravity";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "A fixed attractor of gravitational parameter gm at p_W in W: on each listed body f_W = -gm m r/(|r|^2 + "
      "softening^2)^(3/2), r = p_body - p_W, potential V = -gm m/sqrt(|r|^2 + softening^2) [J].";
  static constexpr const char* example = R"py(A particle on a circular orbit of radius 1 about gm = 1 comes back after one period 2π:

>>> scene = rd.Scene([rd.Particle(1.0)], elements=[rd.PointMassGravity(gm=1.0)])
>>> start = rd.ParticleState(p_W=(1.0, 0.0, 0.0), v_W=(0.0, 1.0, 0.0))
>>> result = rd.simulate(scene, [start], 2 * np.pi / 1000, steps=1000, method="rk4")
>>> bool(np.allclose(result.p_W[-1, 0], [1.0, 0.0, 0.0], atol=1e-9))
True)py";  // the docstring's Examples (run as doctests)
  using Term = PointMassGravityTerm;  // what compile makes of it
  double gm = 0.0;
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  double softening = 0.0;
  BodyList bodies;

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        scalar_field("gm", &PointMassGravity::gm, "m^3/s^2", "gravitational parameter GM of the attractor [m^3/s^2]")
            .must_be_given().above_zero(),
        vector_field("p_W", &PointMassGravity::p_W, "m", "(3,) position of the fixed attractor in W [m]"),
        scalar_field("softening", &PointMassGravity::softening, "m", "softening length epsilon [m] (0: none)").at_least_zero(),
        bodies_field(&PointMassGravity::bodies));
  }
};

// The compiled term: the listed bodies (their masses read from the kinematics, k.m).
class PointMassGravityTerm {
 public:
  // Throws std::invalid_argument "<name>.gm: ..." unless gm is finite and > 0, "<name>.p_W: ..." for a
  // non-finite p_W, "<name>.softening: ..." unless finite and >= 0, "<name>.bodies[k]: ..." for an index
  // out of range or repeated.
  PointMassGravityTerm(const PointMassGravity& spec, const std::vector<Body>& bodies, const std::string& name)
      : gm_(spec.gm), p_W_(spec.p_W), softening2_(spec.softening * spec.softening),
        bodies_(detail::resolve_bodies(spec.bodies, bodies.size(), name)) {
    require_positive(spec.gm, name + ".gm");
    require_finite(spec.p_W, name + ".p_W");
    detail::require_nonnegative(spec.softening, name + ".softening");
  }

  static ElementTraits traits() {
    ElementTraits t{};
    t.reads_attitude = false, t.velocity_dependent = false, t.time_dependent = false;
    t.has_potential = true, t.has_torque = false;
    return t;
  }

  // f_W += −GM m r/(|r|²+ε²)^{3/2} on each listed body; returns Σ f_W·v_W [W].
  double add_wrenches(double /*t*/, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    double power = 0.0;
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
      const BodyKinematics& body = kinematics[bodies_[k]];
      const Eigen::Vector3d r = body.p_W - p_W_;
      const double s2 = r.squaredNorm() + softening2_;
      const Eigen::Vector3d f = (-(gm_ * body.m) / (s2 * std::sqrt(s2))) * r;
      wrenches[bodies_[k]].f_W += f;
      power += f.dot(body.v_W);
    }
    return power;
  }

  // V = −Σ GM m / √(|r|²+ε²) [J]
  double potential(const std::vector<BodyKinematics>& kinematics) const {
    double V = 0.0;
    for (const int b : bodies_) {
      V -= gm_ * kinematics[b].m / std::sqrt((kinematics[b].p_W - p_W_).squaredNorm() + softening2_);
    }
    return V;
  }

  const std::vector<int>& bodies() const { return bodies_; }

 private:
  double gm_;                 // GM [m³/s²]
  Eigen::Vector3d p_W_;
  double softening2_;         // ε² [m²]
  std::vector<int> bodies_;
};

}  // namespace rigiddyn
