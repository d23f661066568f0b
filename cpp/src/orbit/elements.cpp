#include "rigiddyn/orbit/elements.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "numbers.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/orbit/anomaly.hpp"

namespace rigiddyn {

namespace {

using detail::two_pi;

double wrap_positive(double angle) { return angle < 0.0 ? angle + two_pi : angle; }  // (−π, π] → [0, 2π)

// The angle from a to b about the unit normal h_hat (both in the plane normal to it), in (−π, π].
double angle_about(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& h_hat) {
  return std::atan2(h_hat.dot(a.cross(b)), a.dot(b));
}
}  // namespace

ClassicalElements elements_from_state(const Eigen::Vector3d& r_W, const Eigen::Vector3d& v_W, double mu) {
  require_positive(mu, "mu");
  require_finite(r_W, "r_W");
  require_finite(v_W, "v_W");
  const double r = r_W.norm();
  if (!(r > 0.0)) throw_invalid("r_W", "a position away from the central body's centre", r_W.transpose().eval());
  const Eigen::Vector3d h = r_W.cross(v_W);  // specific angular momentum [m²/s]
  const double h_norm = h.norm();
  if (!(h_norm > 0.0)) {
    throw_invalid("r_W, v_W", "a velocity not parallel to the position (r x v != 0: a rectilinear orbit has no plane)",
                  h.transpose().eval());
  }
  const Eigen::Vector3d h_hat = h / h_norm;
  const Eigen::Vector3d e_vec = v_W.cross(h) / mu - r_W / r;  // the eccentricity vector
  ClassicalElements el;
  el.p = h_norm * h_norm / mu;
  el.e = e_vec.norm();
  const double h_xy = std::hypot(h.x(), h.y());
  el.i = std::atan2(h_xy, h.z());
  // the reference direction in the plane: the ascending node z × h, or x_W when there is none
  const bool equatorial = h_xy < equatorial_tolerance * h_norm;
  const Eigen::Vector3d node = equatorial ? Eigen::Vector3d::UnitX() : Eigen::Vector3d(-h.y(), h.x(), 0.0);
  el.raan = equatorial ? 0.0 : wrap_positive(std::atan2(h.x(), -h.y()));
  // the periapsis, or the reference direction when there is none
  const bool circular = el.e < circular_tolerance;
  el.argp = circular ? 0.0 : wrap_positive(angle_about(node, e_vec, h_hat));
  const double nu = angle_about(circular ? node : e_vec, r_W, h_hat);
  el.nu = el.e < 1.0 ? wrap_positive(nu) : nu;
  return el;
}

OrbitState state_from_elements(const ClassicalElements& el, double mu) {
  require_positive(mu, "mu");
  require_positive(el.p, "p");
  orbit_detail::check_eccentricity(el.e);
  orbit_detail::check_angle(el.i, "i");
  orbit_detail::check_angle(el.raan, "raan");
  orbit_detail::check_angle(el.argp, "argp");
  orbit_detail::check_angle(el.nu, "nu");
  const double c_nu = std::cos(el.nu), s_nu = std::sin(el.nu);
  const double denominator = 1.0 + el.e * c_nu;  // r = p/(1 + e cos ν) (the orbit equation)
  if (!(denominator > 0.0)) {
    throw_invalid("nu", "a true anomaly within the asymptotes, 1 + e cos(nu) > 0 for e = " + format_value(el.e), el.nu);
  }
  // P̂, Q̂: the first two columns of R_z(Ω) R_x(i) R_z(ω)
  const Eigen::Matrix3d R_WP = (Eigen::AngleAxisd(el.raan, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(el.i, Eigen::Vector3d::UnitX()) *
                                Eigen::AngleAxisd(el.argp, Eigen::Vector3d::UnitZ()))
                                   .toRotationMatrix();
  const Eigen::Vector3d P = R_WP.col(0), Q = R_WP.col(1);
  const double r = el.p / denominator;
  const double v_scale = std::sqrt(mu / el.p);
  return {r * (c_nu * P + s_nu * Q), v_scale * (-s_nu * P + (el.e + c_nu) * Q)};
}

double semi_latus_rectum(double a, double e) {
  orbit_detail::check_eccentricity(e);
  if (e == 1.0) throw_invalid("e", "e != 1 (a parabola's semi-major axis is infinite: give its p)", e);
  require_finite(a, "a");
  if (e < 1.0 && !(a > 0.0)) throw_invalid("a", "a > 0 for an ellipse (e = " + format_value(e) + " < 1)", a);
  if (e > 1.0 && !(a < 0.0)) throw_invalid("a", "a < 0 for a hyperbola (e = " + format_value(e) + " > 1)", a);
  return a * (1.0 - e) * (1.0 + e);
}

}  // namespace rigiddyn
