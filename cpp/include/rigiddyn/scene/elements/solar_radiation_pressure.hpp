// Solar radiation pressure on a spacecraft: a cannonball or a flat plate, the Sun's direction fixed or turning at a
// constant rate, a cylindrical planet shadow (Montenbruck & Gill, "Satellite Orbits", §3.4: the flat plate's
// absorbed, specularly and diffusely reflected light, and the cylindrical shadow model; Vallado, "Fundamentals of
// Astrodynamics and Applications", §8.6.4). With ŝ the unit direction towards the Sun, P the radiation pressure
// [N/m²] (4.56e-6 at 1 au) and A the area:
//   cannonball (normal_B = 0):  f_W = −P C_R A ŝ;
//   flat plate (unit normal n̂ = R_WB normal_B, lit on its normal's side, cos θ = n̂·ŝ > 0):
//     f_W = −P A cos θ [(1 − ρ_s) ŝ + 2 (ρ_s cos θ + ρ_d/3) n̂],   none when cos θ <= 0;
// applied at the centre of pressure cp_B: tau_B = cp_B × (R_WBᵀ f_W). ŝ(t) = exp([sun_rate_W]× t) sun_W (the
// Sun's apparent motion, e.g. 1.99e-7 rad/s about the ecliptic pole). In the shadow of a planet of radius R at p_W
// (the cylinder behind it along −ŝ: r·ŝ < 0 and |r − (r·ŝ) ŝ| < R, r = p_body − p_W) there is none. No potential;
// the force switches off at the shadow's edge, inside a step: a run crossing it is not smooth there, and its error
// estimate says so.
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_bodies.hpp"
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

class SolarRadiationPressureTerm;

// The spec: the Sun's direction sun_W at t = 0 turning at sun_rate_W, the pressure, each listed body's area and
// optical model (a cannonball of coefficient reflectivity, or a flat plate of normal normal_B with specular and
// diffuse reflectivities), its centre of pressure cp_B, and the shadowing planet (radius 0: none).
struct SolarRadiationPressure {
  static constexpr const char* element_type = "SolarRadiationPressure";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "Solar radiation pressure on each listed body, at its centre of pressure cp_B: a cannonball (normal_B zero) "
      "f_W = -pressure reflectivity area s, or a flat plate of normal n = R_WB normal_B lit on its normal's side, "
      "f_W = -pressure area cos(t) [(1 - specular) s + 2 (specular cos(t) + diffuse/3) n], cos(t) = n . s > 0; "
      "torque tau_B = cp_B x f_B. s is the unit direction towards the Sun, sun_W at t = 0 turned at sun_rate_W "
      "[rad/s]; none inside the cylindrical shadow of a planet of shadow_radius at shadow_p_W. No potential.";
  static constexpr const char* example = R"py(A 4 m^2 cannonball of reflectivity 1.3 at 1 au is pushed away from the Sun by 4.56e-6 * 1.3 * 4 N:

>>> srp = rd.SolarRadiationPressure(sun_W=(1.0, 0.0, 0.0), area=4.0, reflectivity=1.3)
>>> result = rd.simulate(rd.Scene([rd.Particle(100.0)], elements=[srp]), [rd.ParticleState()], 1.0, steps=1,
...                      method="rk4")
>>> bool(np.allclose(result.v_W[-1, 0] * 100.0, [-4.56e-6 * 1.3 * 4.0, 0.0, 0.0], rtol=1e-12, atol=0))
True)py";  // the docstring's Examples (run as doctests)
  using Term = SolarRadiationPressureTerm;  // what compile makes of it
  Eigen::Vector3d sun_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d sun_rate_W = Eigen::Vector3d::Zero();
  double pressure = 4.56e-6;
  double area = 0.0;
  double reflectivity = 1.0;
  Eigen::Vector3d normal_B = Eigen::Vector3d::Zero();
  double specular = 0.0;
  double diffuse = 0.0;
  Eigen::Vector3d cp_B = Eigen::Vector3d::Zero();
  double shadow_radius = 0.0;
  Eigen::Vector3d shadow_p_W = Eigen::Vector3d::Zero();
  BodyList bodies;

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        vector_field("sun_W", &SolarRadiationPressure::sun_W, "", "(3,) direction towards the Sun in W at t = 0, any length")
            .must_be_given(),
        vector_field("sun_rate_W", &SolarRadiationPressure::sun_rate_W, "rad/s",
                     "(3,) angular velocity at which the Sun's direction turns, in W [rad/s] (zero: fixed)"),
        scalar_field("pressure", &SolarRadiationPressure::pressure, "N/m^2",
                     "radiation pressure P [N/m^2] (4.56e-6: the Sun's at 1 au)").at_least_zero(),
        scalar_field("area", &SolarRadiationPressure::area, "m^2", "lit area A of each body [m^2]").must_be_given().at_least_zero(),
        scalar_field("reflectivity", &SolarRadiationPressure::reflectivity, "",
                     "cannonball coefficient C_R (1: absorbed, 2: mirrored back)").at_least_zero(),
        vector_field("normal_B", &SolarRadiationPressure::normal_B, "",
                     "(3,) a flat plate's normal in B, any length (zero: a cannonball)"),
        scalar_field("specular", &SolarRadiationPressure::specular, "", "a flat plate's specular reflectivity").at_least_zero(),
        scalar_field("diffuse", &SolarRadiationPressure::diffuse, "", "a flat plate's diffuse reflectivity").at_least_zero(),
        vector_field("cp_B", &SolarRadiationPressure::cp_B, "m", "(3,) centre of pressure in B, from the centre of mass [m]"),
        scalar_field("shadow_radius", &SolarRadiationPressure::shadow_radius, "m",
                     "radius of the planet casting a cylindrical shadow [m], 0 for none").at_least_zero(),
        vector_field("shadow_p_W", &SolarRadiationPressure::shadow_p_W, "m", "(3,) centre of that planet in W [m]"),
        bodies_field(&SolarRadiationPressure::bodies));
  }
};

// The compiled term: the listed bodies.
class SolarRadiationPressureTerm {
 public:
  // Throws std::invalid_argument "<name>.<field>: ..." for a zero or non-finite sun_W, a non-finite vector, a
  // scalar not finite and >= 0, specular + diffuse > 1, a flat plate on a particle (no attitude to carry its
  // normal), a cp_B a listed body cannot carry, and "<name>.bodies[k]: ..." for an index out of range or repeated.
  SolarRadiationPressureTerm(const SolarRadiationPressure& spec, const std::vector<Body>& bodies, const std::string& name)
      : sun_rate_W_(spec.sun_rate_W), pressure_area_(spec.pressure * spec.area), reflectivity_(spec.reflectivity),
        specular_(spec.specular), diffuse_(spec.diffuse), cp_B_(spec.cp_B), shadow_radius_(spec.shadow_radius),
        shadow_p_W_(spec.shadow_p_W), bodies_(detail::resolve_bodies(spec.bodies, bodies.size(), name)) {
    require_finite(spec.sun_W, name + ".sun_W");
    if (!(spec.sun_W.norm() > 0.0)) throw_invalid(name + ".sun_W", "a non-zero direction", spec.sun_W);
    require_finite(spec.sun_rate_W, name + ".sun_rate_W");
    detail::require_nonnegative(spec.pressure, name + ".pressure");
    detail::require_nonnegative(spec.area, name + ".area");
    detail::require_nonnegative(spec.reflectivity, name + ".reflectivity");
    require_finite(spec.normal_B, name + ".normal_B");
    detail::require_nonnegative(spec.specular, name + ".specular");
    detail::require_nonnegative(spec.diffuse, name + ".diffuse");
    if (spec.specular + spec.diffuse > 1.0) {
      throw_invalid(name + ".diffuse", "specular + diffuse <= 1 (the rest is absorbed)", spec.specular + spec.diffuse);
    }
    detail::require_nonnegative(spec.shadow_radius, name + ".shadow_radius");
    require_finite(spec.shadow_p_W, name + ".shadow_p_W");
    sun_W_ = spec.sun_W.normalized();
    plate_ = !spec.normal_B.isZero(0.0);
    if (plate_) normal_B_ = spec.normal_B.normalized();
    for (const int b : bodies_) {
      if (plate_ && !has_attitude(bodies[b])) {
        throw_invalid(name + ".normal_B", "zero on a particle (a cannonball: a particle has no attitude)", spec.normal_B);
      }
      detail::require_body_point(bodies[b], spec.cp_B, name + ".cp_B");
    }
  }

  ElementTraits traits() const {
    ElementTraits t{};
    t.reads_attitude = plate_ || !cp_B_.isZero(0.0), t.velocity_dependent = false;
    t.time_dependent = !sun_rate_W_.isZero(0.0);
    t.has_potential = false, t.has_torque = !cp_B_.isZero(0.0);
    return t;
  }

  // f_W and tau_B above on each listed body in the light; returns Σ f_W·v_W + tau_B·w_B [W].
  double add_wrenches(double t, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    const Eigen::Vector3d s_W = sun_at(t);
    double power = 0.0;
    for (const int b : bodies_) {
      const BodyKinematics& body = kinematics[b];
      if (in_shadow(body.p_W, s_W)) continue;
      power += add_force_at_point(body, force_W(body.R_WB, s_W), cp_B_, wrenches[b]);
    }
    return power;
  }

  double potential(const std::vector<BodyKinematics>& /*kinematics*/) const { return 0.0; }

  const std::vector<int>& bodies() const { return bodies_; }

 private:
  // ŝ(t) = exp([sun_rate_W]× t) sun_W
  Eigen::Vector3d sun_at(double t) const {
    const double angle = sun_rate_W_.norm() * t;
    if (angle == 0.0) return sun_W_;
    return Eigen::AngleAxisd(angle, sun_rate_W_.normalized()) * sun_W_;
  }

  // Behind the planet in its cylindrical shadow: r·ŝ < 0 and |r − (r·ŝ) ŝ| < R.
  bool in_shadow(const Eigen::Vector3d& p_W, const Eigen::Vector3d& s_W) const {
    if (shadow_radius_ == 0.0) return false;
    const Eigen::Vector3d r = p_W - shadow_p_W_;
    const double along = r.dot(s_W);
    return along < 0.0 && (r - along * s_W).squaredNorm() < shadow_radius_ * shadow_radius_;
  }

  Eigen::Vector3d force_W(const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& s_W) const {
    if (!plate_) return (-pressure_area_ * reflectivity_) * s_W;
    const Eigen::Vector3d n_W = R_WB * normal_B_;
    const double cos_theta = n_W.dot(s_W);
    if (cos_theta <= 0.0) return Eigen::Vector3d::Zero();  // lit from behind: the plate's other side has no area here
    return (-pressure_area_ * cos_theta) *
           ((1.0 - specular_) * s_W + (2.0 * (specular_ * cos_theta + diffuse_ / 3.0)) * n_W);
  }

  Eigen::Vector3d sun_W_, sun_rate_W_;
  double pressure_area_;  // P A [N]
  double reflectivity_, specular_, diffuse_;
  bool plate_ = false;
  Eigen::Vector3d normal_B_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d cp_B_;
  double shadow_radius_;
  Eigen::Vector3d shadow_p_W_;
  std::vector<int> bodies_;
};

}  // namespace rigiddyn
