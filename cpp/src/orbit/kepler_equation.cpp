#include "rigiddyn/orbit/kepler_equation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "numbers.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/orbit/anomaly.hpp"

namespace rigiddyn {

namespace {

using detail::epsilon;
using detail::pi;
using detail::two_pi;

// The residual of Kepler's equation at x and its first two derivatives (anomaly.hpp's cancellation-free
// forms; f' = (1 − e) + 2 e sin²(x/2) = 1 − e cos x, and (e − 1) + 2 e sinh²(x/2) = e cosh x − 1).
struct Residual {
  double f, df, d2f;
};
Residual residual(double x, double e, double M) {
  if (e < 1.0) {
    const double s = std::sin(x / 2.0);
    return {(1.0 - e) * x + e * orbit_detail::x_minus_sin(x) - M, (1.0 - e) + 2.0 * e * s * s, e * std::sin(x)};
  }
  const double s = std::sinh(x / 2.0);
  return {(e - 1.0) * x + e * orbit_detail::sinh_minus_x(x) - M, (e - 1.0) + 2.0 * e * s * s, e * std::sinh(x)};
}

// The root of (1 − e) x + e x³/6 = m (m ≥ 0; e < 1 or e > 1 alike with c = |1 − e|, sign s): Cardano's
// real root of x³ + p x − q = 0, p = ±6c/e, q = 6m/e. A starter only (Halley's steps refine it).
double cubic_starter(double m, double e) {
  const double p = 6.0 * (1.0 - e) / e, q = 6.0 * m / e;
  const double disc = q * q / 4.0 + p * p * p / 27.0;
  if (disc < 0.0) return std::cbrt(q);  // not met for e ≤ 1; a rough start suffices
  const double r = std::sqrt(disc);
  return std::cbrt(q / 2.0 + r) + std::cbrt(q / 2.0 - r);
}

// The root of f in [lo, hi] (f increasing, 0 < lo) from x: Halley's step, or a bisection where the step
// leaves the bracket (geometric, √(lo hi), while the bracket spans more than a factor 4: a root of 1e-300 is
// then found in ~10 halvings of the exponent, not ~1000 of the value); stops when a step moves x by at most
// 2 ulps (or the bracket is that narrow).
double solve_bracketed(double x, double lo, double hi, double e, double m) {
  for (int k = 0; k < kepler_max_iterations; ++k) {
    const Residual r = residual(x, e, m);
    if (r.f == 0.0) return x;
    (r.f > 0.0 ? hi : lo) = x;
    const double newton = r.f / r.df;
    const double halley_denominator = 1.0 - newton * r.d2f / (2.0 * r.df);
    double next = x - (halley_denominator > 0.5 ? newton / halley_denominator : newton);
    if (!(next > lo && next < hi)) next = hi > 4.0 * lo ? std::sqrt(lo) * std::sqrt(hi) : lo + (hi - lo) / 2.0;
    const double tolerance = 2.0 * epsilon * std::abs(next) + std::numeric_limits<double>::denorm_min();
    if (std::abs(next - x) <= tolerance || hi - lo <= tolerance) return next;
    x = next;
  }
  return x;
}
}  // namespace

double mean_to_eccentric_anomaly(double M, double e) {
  orbit_detail::check_angle(M, "M");
  orbit_detail::check_eccentricity(e);
  if (e == 1.0) throw_invalid("e", "e != 1 (a parabola has no eccentric anomaly: use mean_to_true_anomaly)", e);
  if (e < 1.0) {
    // reduce to (−π, π], solve for |M| in [0, π] with E in [|M|, min(|M| + e, π)], add the revolutions back
    const double M_r = std::remainder(M, two_pi);
    const double m = std::abs(M_r);
    if (m == 0.0) return M - M_r;
    const double lo = m, hi = std::min(m + e, pi);
    const double start = m >= 1.0 ? m + 0.85 * e : e > 0.5 ? cubic_starter(m, e) : m / (1.0 - e);
    const double E = solve_bracketed(std::clamp(start, lo, hi), lo, hi, e, m);
    return std::copysign(E, M_r) + (M - M_r);
  }
  // hyperbola: H in [asinh(m/e), min(asinh(m/(e − 1)), max(3, ln m + ln 5))] for m = |M| (see the header;
  // e sinh H = m + H ≥ m; for H ≥ 3, sinh H ≥ 2 H, so M ≥ sinh H/2 and H ≤ asinh(2M) ≤ ln(5M))
  const double m = std::abs(M);
  if (m == 0.0) return M;
  const double hi = std::min(std::asinh(m / (e - 1.0)), std::max(3.0, std::log(m) + std::log(5.0)));
  const double start = m < 1.0 ? cubic_starter(m, e) : std::log(2.0 * m / e + 1.0);
  const double lo = std::asinh(m / e);
  const double H = solve_bracketed(std::clamp(start, lo, hi), lo, hi, e, m);
  return std::copysign(H, M);
}

}  // namespace rigiddyn
