// Atmospheric drag on a body orbiting a central body: an exponential or a tabulated atmosphere, co-rotating with
// the planet, acting at a centre of pressure (Vallado, "Fundamentals of Astrodynamics and Applications", §8.6.2,
// the drag acceleration, the exponential density model and its tabulated form, Table 8-4; Curtis, "Orbital
// Mechanics for Engineering Students", §12.4). With r = p_body − p_W, the altitude h = |r| − radius and the
// velocity relative to the air v_rel = v_W − ω_atm × r (ω_atm the atmosphere's angular velocity in W, the planet's
// rotation),
//   ρ = density0 · exp(−(h − altitude0) / scale_height)                 (the exponential model), or
//   ρ = ρ_i · exp(−(h − h_i) / H_i),  H_i = (h_{i+1} − h_i) / ln(ρ_i / ρ_{i+1})   (the table's band h_i <= h < h_{i+1}:
//       log-linear between its rows (h_i, ρ_i), exponential within each band; below the first row the first band's
//       exponential extended, above the last row the last band's, as Vallado's model does above its last row),
//   f_W = −½ ρ (C_D A) |v_rel| v_rel                       (drag_area = C_D A [m²], at the centre of pressure),
//   tau_B = r_cp_B × (R_WBᵀ f_W)                          (its moment about the centre of mass).
// v_rel is the centre of mass's: the rotation's own contribution ω × r_cp at the centre of pressure is left out
// (|ω| |r_cp| ≪ |v_rel| for a spacecraft: 1e-3 rad/s × 1 m against 7.5 km/s). No potential: it dissipates
// (power f·v_rel ≤ 0 relative to the air). A circular orbit decays at da/dt = −ρ (C_D A / m) √(GM a).
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_bodies.hpp"
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/element_traits.hpp"
#include "rigiddyn/scene/elements/element_checks.hpp"
#include "rigiddyn/spatial/motion.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace rigiddyn {

class AtmosphericDragTerm;

// The spec: the atmosphere of a central body of `radius` centred at p_W, exponential (density0 at altitude0,
// scale_height) or tabulated (rows table_altitude, table_density), turning with omega_W, and each listed body's drag area C_D A and centre of pressure cp_B (in its B,
// from its centre of mass).
struct AtmosphericDrag {
  static constexpr const char* element_type = "AtmosphericDrag";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "Drag of an atmosphere turning with its planet: on each listed body f_W = -(1/2) rho "
      "drag_area |v_rel| v_rel [N] at its centre of pressure cp_B, v_rel = v_W - omega_W x r, r = p_body - p_W, h = "
      "|r| - radius; torque tau_B = cp_B x f_B [N m]. The density is exponential, rho = density0 "
      "exp(-(h - altitude0)/scale_height), or tabulated: given rows (table_altitude[i], table_density[i]) (at least "
      "2, altitudes increasing, densities > 0), rho is log-linear between rows, rho_i exp(-(h - h_i)/H_i) with H_i "
      "= (h_{i+1} - h_i)/ln(rho_i/rho_{i+1}) in the band h_i <= h < h_{i+1} (Vallado, Fundamentals of Astrodynamics "
      "and Applications, Table 8-4); below the first row the first band's exponential is extended, above the last "
      "row the last band's (density0, altitude0 and scale_height are then left at 0). "
      "drag_area is C_D A [m^2] (the ballistic coefficient is m/(C_D A)). No potential: it dissipates. A circular "
      "orbit decays at da/dt = -rho (drag_area/m) sqrt(gm a).";
  static constexpr const char* example = R"py(A body 400 km up at 7670 m/s in still air of 3e-12 kg/m^3 loses energy at (1/2) rho (C_D A) v^3:

>>> air = rd.AtmosphericDrag(density0=3e-12, altitude0=400e3, scale_height=60e3, radius=6378137.0,
...                          drag_area=2.2 * 4.0)
>>> start = rd.ParticleState(p_W=(6778137.0, 0.0, 0.0), v_W=(0.0, 7670.0, 0.0))
>>> result = rd.simulate(rd.Scene([rd.Particle(500.0)], elements=[air]), [start], 0.01, steps=1, method="rk4")
>>> expected = -0.5 * 3e-12 * 8.8 * 7670.0**3 * 0.01  # the work of one step of 0.01 s [J]
>>> bool(abs(result.work[-1, 0] / expected - 1) < 1e-6)
True

A table of two rows, 3e-12 kg/m^3 at 400 km and 3e-12/e at 460 km, is the exponential of scale height 60 km in
that band:

>>> table = rd.AtmosphericDrag(table_altitude=(400e3, 460e3), table_density=(3e-12, 3e-12 / np.e),
...                            radius=6378137.0, drag_area=8.8)
>>> result = rd.simulate(rd.Scene([rd.Particle(500.0)], elements=[table]), [start], 0.01, steps=1, method="rk4")
>>> bool(abs(result.work[-1, 0] / expected - 1) < 1e-6)
True)py";  // the docstring's Examples (run as doctests)
  using Term = AtmosphericDragTerm;  // what compile makes of it
  double density0 = 0.0;
  double altitude0 = 0.0;
  double scale_height = 0.0;
  double radius = 0.0;
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d omega_W = Eigen::Vector3d::Zero();
  double drag_area = 0.0;
  Eigen::Vector3d cp_B = Eigen::Vector3d::Zero();
  BodyList bodies;
  std::vector<double> table_altitude, table_density;  // the table's rows (empty: the exponential model)

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        scalar_field("density0", &AtmosphericDrag::density0, "kg/m^3",
                     "air density at altitude0 [kg/m^3] (the exponential model; 0 with a table)")
            .at_least_zero(),
        scalar_field("altitude0", &AtmosphericDrag::altitude0, "m",
                     "reference altitude of density0 [m] (the exponential model; 0 with a table)"),
        scalar_field("scale_height", &AtmosphericDrag::scale_height, "m",
                     "scale height H of the density [m] (the exponential model, > 0; 0 with a table)")
            .at_least_zero(),
        scalar_field("radius", &AtmosphericDrag::radius, "m", "radius of the central body (altitude 0) [m]")
            .must_be_given().at_least_zero(),
        vector_field("p_W", &AtmosphericDrag::p_W, "m", "(3,) centre of the central body in W [m]"),
        vector_field("omega_W", &AtmosphericDrag::omega_W, "rad/s",
                     "(3,) angular velocity of the atmosphere in W [rad/s] (the planet's rotation; zero: still air)"),
        scalar_field("drag_area", &AtmosphericDrag::drag_area, "m^2", "drag coefficient times area C_D A of each body [m^2]")
            .must_be_given().at_least_zero(),
        vector_field("cp_B", &AtmosphericDrag::cp_B, "m",
                     "(3,) centre of pressure in each body's B, from its centre of mass [m] (zero on a particle)"),
        bodies_field(&AtmosphericDrag::bodies),
        array_field("table_altitude", &AtmosphericDrag::table_altitude, "m",
                    "(n,) the density table's altitudes [m], increasing (empty: the exponential model)"),
        array_field("table_density", &AtmosphericDrag::table_density, "kg/m^3",
                    "(n,) the density [kg/m^3] > 0 at each altitude of table_altitude"));
  }

  // What the fields must satisfy together: the exponential model (scale_height > 0) without a table; with one, at
  // least 2 rows of increasing finite altitudes and finite densities > 0, the exponential model's fields left at 0.
  void check_fields() const {
    if (table_altitude.empty() && table_density.empty()) {
      if (!(scale_height > 0.0)) throw_invalid("scale_height", "a finite number > 0", scale_height);
      return;
    }
    if (table_density.size() != table_altitude.size()) {
      throw_invalid("table_density", "one density per altitude of table_altitude (" +
                                         std::to_string(table_altitude.size()) + ")",
                    std::to_string(table_density.size()) + " densities");
    }
    if (table_altitude.size() < 2) {
      throw_invalid("table_altitude", "at least 2 rows (altitude, density)", std::to_string(table_altitude.size()));
    }
    for (std::size_t i = 0; i < table_altitude.size(); ++i) {
      const std::string row = "[" + std::to_string(i) + "]";
      if (!std::isfinite(table_altitude[i])) throw_invalid("table_altitude" + row, "a finite altitude [m]", table_altitude[i]);
      if (i > 0 && !(table_altitude[i] > table_altitude[i - 1])) {
        throw_invalid("table_altitude" + row,
                      "an altitude [m] above table_altitude[" + std::to_string(i - 1) + "] = " +
                          format_value(table_altitude[i - 1]) + " (increasing altitudes)",
                      table_altitude[i]);
      }
      if (!(std::isfinite(table_density[i]) && table_density[i] > 0.0)) {
        throw_invalid("table_density" + row, "a finite density > 0 [kg/m^3]", table_density[i]);
      }
    }
    const std::pair<const char*, double> exponential[] = {
        {"density0", density0}, {"altitude0", altitude0}, {"scale_height", scale_height}};
    for (const auto& [key, value] : exponential) {
      if (value != 0.0) throw_invalid(key, "0 with a density table (the table replaces the exponential model)", value);
    }
  }
};

// The compiled term: the listed bodies.
class AtmosphericDragTerm {
 public:
  // Throws std::invalid_argument "<name>.<field>: ..." for a density0, radius or drag_area that is not finite and
  // >= 0, a scale_height not finite and > 0 (without a table), a bad table (check_fields), a non-finite altitude0,
  // p_W or omega_W, a cp_B a listed body cannot carry (non-zero on a particle, out of a planar body's plane), and
  // "<name>.bodies[k]: ..." for an index out of range or repeated.
  AtmosphericDragTerm(const AtmosphericDrag& spec, const std::vector<Body>& bodies, const std::string& name)
      : density0_(spec.density0), altitude0_(spec.altitude0), scale_height_(spec.scale_height), radius_(spec.radius),
        p_W_(spec.p_W), air_W_(spec.omega_W, Eigen::Vector3d::Zero()), half_drag_area_(0.5 * spec.drag_area), cp_B_(spec.cp_B),
        bodies_(detail::resolve_bodies(spec.bodies, bodies.size(), name)), h_(spec.table_altitude),
        rho_(spec.table_density) {
    detail::require_nonnegative(spec.density0, name + ".density0");
    require_finite(spec.altitude0, name + ".altitude0");
    detail::require_nonnegative(spec.scale_height, name + ".scale_height");
    try {
      spec.check_fields();
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(name + "." + e.what());
    }
    // the slope k_i = −1/H_i = ln(ρ_{i+1}/ρ_i)/(h_{i+1} − h_i) of each band's log-density [1/m]
    for (std::size_t i = 0; i + 1 < h_.size(); ++i) k_.push_back(std::log(rho_[i + 1] / rho_[i]) / (h_[i + 1] - h_[i]));
    detail::require_nonnegative(spec.radius, name + ".radius");
    require_finite(spec.p_W, name + ".p_W");
    require_finite(spec.omega_W, name + ".omega_W");
    detail::require_nonnegative(spec.drag_area, name + ".drag_area");
    for (const int b : bodies_) detail::require_body_point(bodies[b], spec.cp_B, name + ".cp_B");
  }

  ElementTraits traits() const {
    ElementTraits t{};
    t.reads_attitude = !cp_B_.isZero(0.0), t.velocity_dependent = true, t.time_dependent = false;
    t.has_potential = false, t.has_torque = !cp_B_.isZero(0.0);
    return t;
  }

  // f_W and tau_B above on each listed body; returns Σ f_W·v_W + tau_B·w_B [W].
  double add_wrenches(double /*t*/, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    double power = 0.0;
    for (const int b : bodies_) {
      const BodyKinematics& body = kinematics[b];
      const Eigen::Vector3d r_W = body.p_W - p_W_;
      const Eigen::Vector3d v_rel = body.v_W - air_W_.velocity_at(r_W);
      const Eigen::Vector3d f_W = (-half_drag_area_ * density(r_W.norm() - radius_) * v_rel.norm()) * v_rel;
      power += add_force_at_point(body, f_W, cp_B_, wrenches[b]);
    }
    return power;
  }

  double potential(const std::vector<BodyKinematics>& /*kinematics*/) const { return 0.0; }

  const std::vector<int>& bodies() const { return bodies_; }

 private:
  // ρ(h) [kg/m³]: density0 exp(−(h − altitude0)/H), or ρ_i exp(k_i (h − h_i)) in the table's band i that holds h
  // (the first below the table, the last above it)
  double density(double altitude) const {
    if (h_.empty()) return density0_ * std::exp(-(altitude - altitude0_) / scale_height_);
    const auto above = std::upper_bound(h_.begin() + 1, h_.end() - 1, altitude);  // h_{i+1}, i in [0, n − 2]
    const auto i = static_cast<std::size_t>(above - h_.begin()) - 1;
    return rho_[i] * std::exp(k_[i] * (altitude - h_[i]));
  }

  double density0_, altitude0_, scale_height_, radius_;
  Eigen::Vector3d p_W_;
  Motion air_W_;  // the atmosphere's twist about the central body's centre, in W: (omega_W, 0), turning with it
  double half_drag_area_;  // C_D A / 2 [m²]
  Eigen::Vector3d cp_B_;
  std::vector<int> bodies_;
  std::vector<double> h_, rho_, k_;  // the table's altitudes [m], densities [kg/m³], bands' slopes [1/m] (or empty)
};

}  // namespace rigiddyn
