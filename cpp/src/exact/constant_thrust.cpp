// The constant-rate burn in closed form (exact/constant_thrust.hpp).
#include "rigiddyn/exact/constant_thrust.hpp"

#include "rigiddyn/check.hpp"

#include <cmath>
#include <limits>

namespace rigiddyn {

namespace {

// h(x)/x with h(x) = (1 + x) ln(1 + x) − x = ∫₀ˣ ln(1 + y) dy, x > −1: for |x| < 1/4 the series
// Σ_{k≥2} (−1)^k x^(k−1)/(k (k − 1)) (Taylor of ln(1 + y), integrated term by term) summed from its
// smallest term up; 40 terms leave (1/4)^40/1560 < 1e-27 relative to x/2. Else the closed form.
double h_over_x(double x) {
  if (std::abs(x) < 0.25) {
    double sum = 0.0;
    // Horner in −x: Σ_{k=2..41} (−x)^(k−2)/(k (k − 1)), times x below
    for (int k = 41; k >= 2; --k) sum = sum * (-x) + 1.0 / (k * (k - 1.0));
    return x * sum;
  }
  // ((1 + x) ln(1 + x) − x)/x; for x > 1 as (1 + 1/x) ln(1 + x) − 1, whose product cannot overflow
  // (1 + x stays a factor of a huge x otherwise: inf/x for x > 1e305)
  if (x > 1.0) return (1.0 + 1.0 / x) * std::log1p(x) - 1.0;
  return ((1.0 + x) * std::log1p(x) - x) / x;
}

}  // namespace

ConstantThrustSolution::ConstantThrustSolution(double m0, double rate, const Eigen::Vector3d& u_rel_W,
                                               const Eigen::Vector3d& g_W, const Eigen::Vector3d& p0_W,
                                               const Eigen::Vector3d& v0_W)
    : m0_(m0), rate_(rate), u_rel_W_(u_rel_W), g_W_(g_W), p0_W_(p0_W), v0_W_(v0_W) {
  require_positive(m0, "m0");
  require_finite(rate, "rate");
  require_finite(u_rel_W, "u_rel_W");
  require_finite(g_W, "g_W");
  require_finite(p0_W, "p0_W");
  require_finite(v0_W, "v0_W");
}

ConstantThrustState ConstantThrustSolution::at(double t) const {
  require_finite(t, "t");
  const double m = mass_at(t);
  if (!(m > 0.0)) {
    throw_invalid("t", "a time at which the mass m0 + rate t is positive (burn-out at t = " +
                           format_value(burnout_time()) + " s)", t);
  }
  const double x = rate_ * t / m0_;  // m(t)/m0 = 1 + x
  ConstantThrustState s;
  s.mass = m;
  s.v_W = v0_W_ + g_W_ * t + u_rel_W_ * std::log1p(x);
  // ½ g t² as (g t)(t/2): t² alone overflows for |t| > 1.3e154 where the product may not (and a zero g
  // component would give 0 · inf = NaN)
  s.p_W = p0_W_ + v0_W_ * t + (g_W_ * t) * (0.5 * t) + u_rel_W_ * (t * h_over_x(x));
  if (!(s.p_W.allFinite() && s.v_W.allFinite())) {
    throw_invalid("t", "a time at which the state is within the double range", t);
  }
  return s;
}

double ConstantThrustSolution::delta_v(double m1) const {
  require_positive(m1, "m1");
  const double speed = u_rel_W_.stableNorm();  // scaled: no overflow of the squares for |u_rel| > 1e154
  if (speed == 0.0) return 0.0;                // no thrust (ln(m0/m1) may be beyond the range below)
  // ln(m0/m1): for m0/2 ≤ m1 ≤ 2 m0 as −ln(1 + (m1 − m0)/m0), whose difference is exact (Sterbenz) where
  // ln(m0/m1) of the rounded ratio would lose eps/|ln(m0/m1)|; elsewhere |ln(m0/m1)| > ln 2 and the
  // ratio's rounding costs < 1.5 eps relative (log1p's argument would round to −1 as m1 ≪ m0); where the
  // ratio leaves the normal range, ln m0 − ln m1 (|difference| > 708: no cancellation)
  const double ratio = m0_ / m1;
  double log_ratio;
  if (m1 >= 0.5 * m0_ && m1 <= 2.0 * m0_) {
    log_ratio = -std::log1p((m1 - m0_) / m0_);
  } else if (std::isfinite(ratio) && ratio >= std::numeric_limits<double>::min()) {
    log_ratio = std::log(ratio);
  } else {
    log_ratio = std::log(m0_) - std::log(m1);
  }
  const double dv = speed * log_ratio;
  if (!std::isfinite(dv)) throw_invalid("m1", "a mass for which |u_rel| ln(m0/m1) is within the double range", m1);
  return dv;
}

double ConstantThrustSolution::burnout_time() const {
  return rate_ < 0.0 ? -m0_ / rate_ : std::numeric_limits<double>::infinity();
}

}  // namespace rigiddyn
