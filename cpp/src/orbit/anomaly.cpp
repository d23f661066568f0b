#include "rigiddyn/orbit/anomaly.hpp"

#include <cmath>

#include "numbers.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/orbit/kepler_equation.hpp"

namespace rigiddyn {

namespace {

using detail::two_pi;

// e = 1 refused where an eccentric or hyperbolic anomaly is asked.
void check_not_parabolic(double e) {
  if (e == 1.0) throw_invalid("e", "e != 1 (a parabola has no eccentric anomaly: use the true or mean anomaly)", e);
}

// The hyperbola's true anomaly lies between its asymptotes: 1 + e cos ν > 0 (r = p/(1 + e cos ν) > 0).
void check_within_asymptotes(double nu, double e) {
  if (!(1.0 + e * std::cos(nu) > 0.0)) {
    throw_invalid("nu", "a true anomaly within the asymptotes, |nu| < acos(-1/e) = " + format_value(std::acos(-1.0 / e)) +
                            " for e = " + format_value(e),
                  nu);
  }
}
}  // namespace

namespace orbit_detail {
void check_eccentricity(double e) {
  if (!(std::isfinite(e) && e >= 0.0)) throw_invalid("e", "a finite eccentricity >= 0", e);
}
void check_angle(double angle, const char* name) { require_finite(angle, name); }

// x − sin x = x³/3! − x⁵/5! + ... for |x| < 1 (the terms fall by x²/((2k+2)(2k+3)) ≤ 1/20), else directly.
double x_minus_sin(double x) {
  if (std::abs(x) >= 1.0) return x - std::sin(x);
  const double x2 = x * x;
  double term = x * x2 / 6.0, sum = 0.0;
  for (int k = 1; term != 0.0 && std::abs(term) > 1e-17 * std::abs(sum); ++k) {
    sum += term;
    term *= -x2 / ((2 * k + 2) * (2 * k + 3));
  }
  return sum;
}
// sinh x − x = x³/3! + x⁵/5! + ... for |x| < 1, else directly.
double sinh_minus_x(double x) {
  if (std::abs(x) >= 1.0) return std::sinh(x) - x;
  const double x2 = x * x;
  double term = x * x2 / 6.0, sum = 0.0;
  for (int k = 1; term != 0.0 && std::abs(term) > 1e-17 * std::abs(sum); ++k) {
    sum += term;
    term *= x2 / ((2 * k + 2) * (2 * k + 3));
  }
  return sum;
}
}  // namespace orbit_detail

using orbit_detail::check_angle;
using orbit_detail::check_eccentricity;

double true_to_eccentric_anomaly(double nu, double e) {
  check_angle(nu, "nu");
  check_eccentricity(e);
  check_not_parabolic(e);
  const double nu_r = std::remainder(nu, two_pi);  // in [−π, π]; ν − ν_r whole revolutions
  if (e < 1.0) return 2.0 * std::atan(std::sqrt((1.0 - e) / (1.0 + e)) * std::tan(nu_r / 2.0)) + (nu - nu_r);
  check_within_asymptotes(nu_r, e);
  return 2.0 * std::atanh(std::sqrt((e - 1.0) / (e + 1.0)) * std::tan(nu_r / 2.0));
}

double eccentric_to_true_anomaly(double E, double e) {
  check_angle(E, "E");
  check_eccentricity(e);
  check_not_parabolic(e);
  if (e < 1.0) {
    const double E_r = std::remainder(E, two_pi);
    return 2.0 * std::atan(std::sqrt((1.0 + e) / (1.0 - e)) * std::tan(E_r / 2.0)) + (E - E_r);
  }
  return 2.0 * std::atan(std::sqrt((e + 1.0) / (e - 1.0)) * std::tanh(E / 2.0));
}

// M = (1 − e) E + e (E − sin E) and M = (e − 1) H + e (sinh H − H): the forms of Kepler's equation
// that keep their digits near periapsis as e → 1.
double eccentric_to_mean_anomaly(double E, double e) {
  check_angle(E, "E");
  check_eccentricity(e);
  check_not_parabolic(e);
  if (e < 1.0) return (1.0 - e) * E + e * orbit_detail::x_minus_sin(E);
  return (e - 1.0) * E + e * orbit_detail::sinh_minus_x(E);
}

double true_to_mean_anomaly(double nu, double e) {
  check_angle(nu, "nu");
  check_eccentricity(e);
  if (e != 1.0) return eccentric_to_mean_anomaly(true_to_eccentric_anomaly(nu, e), e);
  const double nu_r = std::remainder(nu, two_pi);
  check_within_asymptotes(nu_r, e);
  const double D = std::tan(nu_r / 2.0);
  return D / 2.0 + D * D * D / 6.0;  // Barker's equation
}

double mean_to_true_anomaly(double M, double e) {
  check_angle(M, "M");
  check_eccentricity(e);
  if (e != 1.0) return eccentric_to_true_anomaly(mean_to_eccentric_anomaly(M, e), e);
  // Barker's cubic D³ + 3 D − 6 M = 0: D = w − 1/w, w = ∛(3|M| + √(9 M² + 1)) (Cardano; the product of
  // the two cube roots is −1), odd in M; one Newton step then restores the digits w − 1/w loses for small M.
  const double m = std::abs(M);
  const double w = std::cbrt(3.0 * m + std::hypot(3.0 * m, 1.0));
  double D = w - 1.0 / w;
  D -= (D / 2.0 + D * D * D / 6.0 - m) / ((1.0 + D * D) / 2.0);
  return std::copysign(2.0 * std::atan(D), M);
}

}  // namespace rigiddyn
