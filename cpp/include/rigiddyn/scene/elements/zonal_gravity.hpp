// The gravity of an oblate central body (the Earth) to its zonal harmonics J2, J3, J4: the field of a body
// symmetric about its pole axis k, fixed at p_W, on each listed body treated as a point mass at its centre of
// mass (Vallado, "Fundamentals of Astrodynamics and Applications", §8.7, the zonal harmonics; Curtis,
// "Orbital Mechanics for Engineering Students", §4.7 for J2). With r = p_body − p_W, r = |r|, u = (r·k)/r the
// sine of the latitude and P_n the Legendre polynomials, the potential per unit mass is
//   U = −GM/r + Σ_{n=2..4} GM J_n R^n P_n(u) / r^{n+1},
// and the force f_W = −m ∇U, term by term (∇u = (k − u r̂)/r):
//   ∇(GM J_n R^n P_n(u)/r^{n+1}) = GM J_n R^n / r^{n+2} [P_n'(u) (k − u r̂) − (n+1) P_n(u) r̂].
// J2 alone gives the classic a = −GM r/r³ [1 − (3/2) J2 (R/r)² (5u² − 1)] off the pole axis and
// [1 − (3/2) J2 (R/r)² (5u² − 3)] along it; it makes a near-circular orbit's node regress at
// dΩ/dt = −(3/2) n J2 (R/p)² cos i.
// No torque about the centre of mass: the zonal terms' gravity-gradient torque on an extended body is
// J_n (R/r)^n of the central term's (about 1e-3 for J2 in low Earth orbit), which GravityGradient gives; a scene
// that needs the attitude to that order declares both. Singular at the centre (r = 0).
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_bodies.hpp"
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/element_traits.hpp"
#include "rigiddyn/scene/elements/element_checks.hpp"

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

namespace rigiddyn {

class ZonalGravityTerm;

// The spec: gravitational parameter gm [m³/s²], reference (equatorial) radius [m] and the zonal coefficients
// j2, j3, j4 of a central body fixed at p_W [m] with its pole along pole_W in W, acting on `bodies` (empty: every
// body).
struct ZonalGravity {
  static constexpr const char* element_type = "ZonalGravity";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "An oblate central body (the Earth) fixed at p_W with its pole along pole_W: on each listed body the force "
      "f_W = -m grad U of the zonal field U = -gm/r + sum_{n=2..4} gm j_n radius^n P_n(u)/r^(n+1), r = |p_body - "
      "p_W|, u the sine of the latitude (P_n the Legendre polynomials), potential V = m U [J]. j2 alone makes a "
      "near-circular orbit's node regress at -(3/2) n j2 (radius/p)^2 cos i. No torque about the centre of mass "
      "(the zonal terms' gravity-gradient torque is j_n (radius/r)^n of GravityGradient's).";
  static constexpr const char* example = R"py(At a point of the equator 7000 km from the Earth's centre, J2 pulls harder than gm/r^2 by (3/2) J2 (R/r)^2:

>>> earth = rd.ZonalGravity(gm=3.986004418e14, radius=6378137.0, j2=1.08262668e-3)
>>> at_rest = rd.ParticleState(p_W=(7e6, 0.0, 0.0))
>>> result = rd.simulate(rd.Scene([rd.Particle(1.0)], elements=[earth]), [at_rest], 1e-3, steps=1, method="rk4")
>>> a_x = result.v_W[-1, 0, 0] / 1e-3  # from rest: v = a dt
>>> expected = -3.986004418e14 / 7e6**2 * (1 + 1.5 * 1.08262668e-3 * (6378137.0 / 7e6) ** 2)
>>> bool(abs(a_x / expected - 1) < 1e-12)
True)py";  // the docstring's Examples (run as doctests)
  using Term = ZonalGravityTerm;  // what compile makes of it
  double gm = 0.0;
  double radius = 0.0;
  double j2 = 0.0;
  double j3 = 0.0;
  double j4 = 0.0;
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d pole_W = Eigen::Vector3d::UnitZ();
  BodyList bodies;

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        scalar_field("gm", &ZonalGravity::gm, "m^3/s^2", "gravitational parameter GM of the central body [m^3/s^2]")
            .must_be_given().above_zero(),
        scalar_field("radius", &ZonalGravity::radius, "m", "reference (equatorial) radius R of the harmonics [m]")
            .must_be_given().above_zero(),
        scalar_field("j2", &ZonalGravity::j2, "", "zonal coefficient J2 (the Earth's: 1.08262668e-3)"),
        scalar_field("j3", &ZonalGravity::j3, "", "zonal coefficient J3 (the Earth's: -2.53265649e-6)"),
        scalar_field("j4", &ZonalGravity::j4, "", "zonal coefficient J4 (the Earth's: -1.61962159e-6)"),
        vector_field("p_W", &ZonalGravity::p_W, "m", "(3,) position of the central body's centre in W [m]"),
        vector_field("pole_W", &ZonalGravity::pole_W, "", "(3,) direction of its pole (symmetry) axis in W, any length"),
        bodies_field(&ZonalGravity::bodies));
  }
};

// The compiled term: the listed bodies (their masses read from the kinematics, k.m).
class ZonalGravityTerm {
 public:
  // Throws std::invalid_argument "<name>.gm: ..." / "<name>.radius: ..." unless finite and > 0, "<name>.j2: ..." (j3,
  // j4) unless finite, "<name>.p_W: ..." non-finite, "<name>.pole_W: ..." unless finite and not zero,
  // "<name>.bodies[k]: ..." for an index out of range or repeated.
  ZonalGravityTerm(const ZonalGravity& spec, const std::vector<Body>& bodies, const std::string& name)
      : gm_(spec.gm), radius_(spec.radius), j_{spec.j2, spec.j3, spec.j4}, p_W_(spec.p_W),
        bodies_(detail::resolve_bodies(spec.bodies, bodies.size(), name)) {
    require_positive(spec.gm, name + ".gm");
    require_positive(spec.radius, name + ".radius");
    require_finite(spec.j2, name + ".j2");
    require_finite(spec.j3, name + ".j3");
    require_finite(spec.j4, name + ".j4");
    require_finite(spec.p_W, name + ".p_W");
    require_finite(spec.pole_W, name + ".pole_W");
    if (!(spec.pole_W.norm() > 0.0)) throw_invalid(name + ".pole_W", "a non-zero direction", spec.pole_W);
    k_W_ = spec.pole_W.normalized();
  }

  static ElementTraits traits() {
    ElementTraits t{};
    t.reads_attitude = false, t.velocity_dependent = false, t.time_dependent = false;
    t.has_potential = true, t.has_torque = false;
    return t;
  }

  // f_W += −m ∇U on each listed body; returns Σ f_W·v_W [W].
  double add_wrenches(double /*t*/, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    double power = 0.0;
    for (const int b : bodies_) {
      const BodyKinematics& body = kinematics[b];
      const Eigen::Vector3d f = -body.m * gradient(body.p_W - p_W_);
      wrenches[b].f_W += f;
      power += f.dot(body.v_W);
    }
    return power;
  }

  // V = Σ m U(r) [J]
  double potential(const std::vector<BodyKinematics>& kinematics) const {
    double V = 0.0;
    for (const int b : bodies_) V += kinematics[b].m * potential_per_mass(kinematics[b].p_W - p_W_);
    return V;
  }

  const std::vector<int>& bodies() const { return bodies_; }

 private:
  // P_n(u) and P_n'(u) for n = 2, 3, 4 (Legendre polynomials).
  static std::array<double, 3> legendre(double u) {
    const double u2 = u * u;
    return {0.5 * (3.0 * u2 - 1.0), 0.5 * u * (5.0 * u2 - 3.0), 0.125 * ((35.0 * u2 - 30.0) * u2 + 3.0)};
  }
  static std::array<double, 3> legendre_derivative(double u) {
    const double u2 = u * u;
    return {3.0 * u, 0.5 * (15.0 * u2 - 3.0), 0.5 * u * (35.0 * u2 - 15.0)};
  }

  // U(r) = −GM/r + Σ GM J_n R^n P_n(u) / r^{n+1} [J/kg]
  double potential_per_mass(const Eigen::Vector3d& r_W) const {
    const double r = r_W.norm(), u = r_W.dot(k_W_) / r;
    const std::array<double, 3> P = legendre(u);
    double zonal = 0.0, ratio = 1.0;  // ratio = (R/r)^n
    for (int n = 2; n <= 4; ++n) {
      ratio *= n == 2 ? (radius_ / r) * (radius_ / r) : radius_ / r;
      zonal += j_[n - 2] * ratio * P[n - 2];
    }
    return (gm_ / r) * (zonal - 1.0);
  }

  // ∇U(r) [m/s²]: GM r̂/r² + Σ GM J_n R^n / r^{n+2} [P_n'(u) (k − u r̂) − (n+1) P_n(u) r̂]
  Eigen::Vector3d gradient(const Eigen::Vector3d& r_W) const {
    const double r = r_W.norm();
    const Eigen::Vector3d r_hat = r_W / r;
    const double u = r_hat.dot(k_W_);
    const std::array<double, 3> P = legendre(u), dP = legendre_derivative(u);
    double radial = 1.0, along_k = 0.0, ratio = 1.0;  // the bracket over GM/r², split along r̂ and k
    for (int n = 2; n <= 4; ++n) {
      ratio *= n == 2 ? (radius_ / r) * (radius_ / r) : radius_ / r;
      const double c = j_[n - 2] * ratio;
      radial -= c * (dP[n - 2] * u + (n + 1) * P[n - 2]);
      along_k += c * dP[n - 2];
    }
    return (gm_ / (r * r)) * (radial * r_hat + along_k * k_W_);
  }

  double gm_;                 // GM [m³/s²]
  double radius_;             // R [m]
  std::array<double, 3> j_;   // J2, J3, J4
  Eigen::Vector3d p_W_;
  Eigen::Vector3d k_W_;       // the unit pole axis in W
  std::vector<int> bodies_;
};

}  // namespace rigiddyn
