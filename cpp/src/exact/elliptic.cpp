// Jacobi elliptic functions by argument halving, a Maclaurin series and doubling (the approach of
// Fukushima 2009, written from the double-argument formulas), with the reduction of u to |w| <= K/2 by
// quarter periods (DLMF Table 22.4.3); the third-kind integral on the same reduction.
#include "carlson_core.hpp"
#include "power_of_two.hpp"
#include "numbers.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/exact/elliptic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rigiddyn {

namespace {

using detail::epsilon;
using detail::infinity;
using detail::ln_4;


// below this argument the series for 1 − cn truncated after u^10 is exact to < 1e-17 relative
// (the u^12 term, 2702765 u^12/12! at m = 1, is 0.011 u^10 relative to u²/2)
constexpr double kSeriesThreshold = 1.0 / 32.0;

// y = 1 − cn(u|m) for |u| ≤ kSeriesThreshold, from the Maclaurin series of cn (DLMF 22.10.5):
// cn = 1 − u²/2! + (1 + 4m) u⁴/4! − (1 + 44m + 16m²) u⁶/6! + (1 + 408m + 912m² + 64m³) u⁸/8!
//        − (1 + 3688m + 30768m² + 15808m³ + 256m⁴) u¹⁰/10!
double one_minus_cn_series(double u, double m) {
  const double u2 = u * u;
  const double c4 = (1.0 + 4.0 * m) / 24.0;
  const double c6 = (1.0 + m * (44.0 + 16.0 * m)) / 720.0;
  const double c8 = (1.0 + m * (408.0 + m * (912.0 + 64.0 * m))) / 40320.0;
  const double c10 = (1.0 + m * (3688.0 + m * (30768.0 + m * (15808.0 + 256.0 * m)))) / 3628800.0;
  return u2 * (0.5 - u2 * (c4 - u2 * (c6 - u2 * (c8 - u2 * c10))));
}

// sn, cn, dn for 0 ≤ w ≤ K/2 (where cn ≥ √kc/√(1 + kc) and dn ≥ √kc), each to a few ulps relative.
// Halve w N times below the series threshold, then double N times (DLMF 22.8.2 at equal arguments,
// cn(2w) = (c² − s² d²)/(1 − m s⁴), with 1 − m s⁴ = c²(1 + s²) + mc s⁴ and d² = mc + m c²):
//   while cn >= ½, y = 1 − cn:  1 − cn(2w) = 2 s² d² / (1 − m s⁴),  s² = y(2 − y), c = 1 − y;
//   then cn itself:             cn(2w) = (m c⁴ − mc (1 − 2c²)) / (1 − m s⁴)
// (1 − y would lose cn's relative precision once cn is small: near K/2 when kc ≪ 1, cn ~ √kc).
JacobiSnCnDn sncndn_first_eighth(double w, double m, double mc) {
  int halvings = 0;
  while (w > kSeriesThreshold) {
    w *= 0.5;
    ++halvings;
  }
  double y = one_minus_cn_series(w, m);
  int i = 0;
  for (; i < halvings && y <= 0.5; ++i) {
    const double s2 = y * (2.0 - y);
    const double c = 1.0 - y;
    const double d2 = mc + m * c * c;
    y = 2.0 * s2 * d2 / (c * c * (1.0 + s2) + mc * s2 * s2);
  }
  if (y <= 0.5) {
    const double cn = 1.0 - y;
    return {std::sqrt(y * (2.0 - y)), cn, std::sqrt(mc + m * cn * cn)};
  }
  double c = 1.0 - y;  // exact (Sterbenz) for y in [1/2, 2]
  for (; i < halvings; ++i) {
    const double c2 = c * c, s2 = (1.0 - c) * (1.0 + c);
    c = (m * c2 * c2 - mc * (1.0 - 2.0 * c2)) / (c2 * (1.0 + s2) + mc * s2 * s2);
  }
  return {std::sqrt((1.0 - c) * (1.0 + c)), c, std::sqrt(mc + m * c * c)};
}

// K from kc = √mc (log_kc = ln kc): ln(4/kc) + (kc²/4)(ln(4/kc) − 1) for kc < 2^−27 (DLMF 19.12.1; the
// next term, O(kc⁴ ln kc), is below eps K), else π/(2 AGM(1, kc)) (DLMF 19.8.5): the
// arithmetic-geometric mean converges quadratically; stopping at |a − b| < 2.7 √eps a leaves a
// relative error below eps in (a + b)/2 (at most 6 steps for kc >= 2^−27).
double complete_k(double kc, double log_kc) {
  if (!(log_kc > -infinity)) return infinity;
  if (kc < 0x1p-27) {
    const double L = ln_4 - log_kc;
    return L + 0.25 * kc * kc * (L - 1.0);
  }
  double a = 1.0, b = kc;
  for (int i = 0; std::abs(a - b) >= 2.7 * 0x1p-26 * a; ++i) {
    if (i == 16) throw std::runtime_error("complete_k: AGM did not converge for kc = " + format_value(kc));
    const double mean = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = mean;
  }
  return M_PI / (a + b);
}

void check_parameter(double m, double mc) {
  if (!(m >= 0.0 && m <= 1.0)) throw_invalid("m", "a parameter in [0, 1]", m);
  if (!(mc >= 0.0 && mc <= 1.0)) throw_invalid("mc", "a complement 1 - m in [0, 1]", mc);
  if (!(std::abs((m - 1.0) + mc) <= 4.0 * epsilon)) {
    throw_invalid("mc", "1 - m to within 4 eps (m = " + format_value(m) + ")", mc);
  }
}

void check_characteristic(double n) {
  require_finite(n, "n");
  if (!(n < 1.0)) throw_invalid("n", "a characteristic n < 1", n);
}

// R_J from the pieces of the duplication (arguments at most 1 with z = 1: d0 >= √p_J needs no care)
double rj_of(const carlson::Duplication& d) {
  return times_pow2(d.rj_rest, d.rj_exponent) + 6.0 * d.rc0 / (d.d0[0] * d.d0[1] * d.d0[2]);
}

// u = l K + w with |w| <= 3K/4 (K/2 up to rounding), l integral: one fused reduction unless |u| ≳ K/eps,
// where the remainder is reduced again (then w is no better than u's last bits, and l only approximate).
struct QuarterPeriods {
  double w;
  double l;
};

QuarterPeriods reduce_quarter_periods(double u, double K) {
  QuarterPeriods r{u, 0.0};
  for (int i = 0; std::abs(r.w) > 0.75 * K; ++i) {
    if (i == 40) throw std::runtime_error("reduce_quarter_periods: no reduction of u = " + format_value(u));
    const double l = std::nearbyint(r.w / K);
    r.w = std::fma(-K, l, r.w);  // one rounding: the product in the fma is exact
    r.l += l;
  }
  return r;
}

}  // namespace

EllipticParameter elliptic_parameter(double m, double mc) {
  check_parameter(m, mc);
  const double kc = std::sqrt(mc);
  return {m, mc, kc, complete_k(kc, kc < 0x1p-27 ? std::log(kc) : 0.0)};
}

EllipticParameter elliptic_parameter_kc(double m, double kc, double log_kc) {
  if (!(kc >= 0.0 && kc <= 1.0)) throw_invalid("kc", "a complementary modulus in [0, 1]", kc);
  const double mc = kc * kc;
  check_parameter(m, mc);
  return {m, mc, kc, complete_k(kc, log_kc)};
}

double ellipk(double m, double mc) { return elliptic_parameter(m, mc).K; }

double complete_ellippi(double n, const EllipticParameter& p) {
  if (p.kc < 0x1p-60) {  // the limit m → 1 of the two halves (ellippi_am_separatrix at K/2, twice)
    if (n < 0.0) {
      const double a = std::sqrt(-n);
      return (p.K + a * std::atan(a)) / (1.0 - n);
    }
    if (n > 0.0) {
      const double b = std::sqrt(n);
      return (p.K - b * std::atanh(b)) / (1.0 - n);
    }
    return p.K;
  }
  const double s = 1.0 / std::sqrt(1.0 + p.kc), root_kc = std::sqrt(p.kc);
  const JacobiSnCnDn half{s, root_kc * s, root_kc};  // at K/2 (DLMF 22.5.2)
  return elliptic_f_pi_reduced(half, false, n, p).pi + elliptic_f_pi_reduced(half, true, n, p).pi;
}

double ellippi(double n, double m, double mc) {
  check_characteristic(n);
  const EllipticParameter p = elliptic_parameter(m, mc);
  if (p.kc == 0.0) throw_invalid("mc", "mc > 0 (Π(n|1) diverges)", mc);
  return complete_ellippi(n, p);
}

JacobiSnCnDn jacobi_ellipj_reduced(double w, const EllipticParameter& p) {
  // kc < 2^-200: the functions of m = 1, (tanh w, sech w, sech w) (DLMF 22.10.ii: their first corrections,
  // (kc²/4)(sinh w cosh w ∓ w) times sech² w or tanh w sech w, are below kc² e^{2|w|}/16 ≤ √kc/2 ≤ 2^-101 relative
  // for |w| ≤ 3K/4, e^K ≈ 4/kc). The doubling would square cn, down to kc^{3/4} there, into the subnormals:
  // below kc ~ 1e-230 it returned cn = dn = 0, which Carlson's R_F does not take.
  if (p.kc < 0x1p-200) {
    const double sech = 1.0 / std::cosh(w);
    return {std::tanh(w), sech, sech};
  }
  const JacobiSnCnDn f = sncndn_first_eighth(std::abs(w), p.m, p.mc);
  return {std::copysign(f.sn, w), f.cn, f.dn};
}

JacobiSnCnDn jacobi_shift_quarter_periods(const JacobiSnCnDn& f, double l, double kc) {
  const double r = quarter_of(l);
  if (r == 0.0) return f;
  if (r == 2.0) return {-f.sn, -f.cn, f.dn};
  const double cd = f.cn / f.dn, kc_nd = kc / f.dn, kc_sd = kc_nd * f.sn;
  return r == 1.0 ? JacobiSnCnDn{cd, -kc_sd, kc_nd} : JacobiSnCnDn{-cd, kc_sd, kc_nd};
}

JacobiSnCnDn jacobi_ellipj(double u, double m, double mc) {
  require_finite(u, "u");
  return jacobi_ellipj(u, elliptic_parameter(m, mc));
}

JacobiSnCnDn jacobi_ellipj(double u, const EllipticParameter& p) {
  if (p.kc == 0.0) {  // m = 1: DLMF 22.5.3
    const double sech = 1.0 / std::cosh(u);
    return {std::tanh(u), sech, sech};
  }
  const QuarterPeriods r = reduce_quarter_periods(u, p.K);
  return jacobi_shift_quarter_periods(jacobi_ellipj_reduced(r.w, p), r.l, p.kc);
}

EllipticFPi elliptic_f_pi_reduced(const JacobiSnCnDn& f, bool odd_quarter, double n, const EllipticParameter& p) {
  const double sn = f.sn, cn = std::abs(f.cn), dn = f.dn;
  const double sn2 = sn * sn, cn2 = cn * cn, dn2 = dn * dn;
  if (!odd_quarter && n < -4.0) {
    // 19.25.14 cancels as −n grows: its two terms tend to ±sn R_F while Π ~ π/(2√(1 − n)), a loss of
    // up to ~(1 + √(1 − n)) (below 6 for n >= −4, where it is kept: it needs no atan2). DLMF 19.7.9
    // with ω² = m/n ∈ [−1/4, 0)
    // (Π(n) + Π(ω²) = F + √c R_C((c − 1)(c − m), (c − n)(c − ω²)), c = 1/sn²) has none: times sn⁴ the R_C
    // arguments are X = cn² dn² and Y = X + sn² (1 − n)(1 − ω²), and R_C(X, Y) = atan(√((Y − X)/X))/√(Y − X)
    // (DLMF 19.2.18), so Π = sign(sn) atan2(|sn| r, cn dn)/r − (ω²/3) sn³ R_J(cn², dn², 1, 1 − ω² sn²),
    // r = √(1 − n) √(1 − ω²)
    const double w2 = p.m / n, pj = 1.0 - w2 * sn2;
    const carlson::Duplication d = carlson::duplicate_rf_rj({cn2, dn2, 1.0, pj, cn, dn, 1.0, std::sqrt(pj), 0});
    const double r = std::sqrt(1.0 - n) * std::sqrt(1.0 - w2);
    const double pi = std::copysign(std::atan2(std::abs(sn) * r, cn * dn) / r, sn) - w2 / 3.0 * sn * sn2 * rj_of(d);
    return {sn * d.rf, pi};
  }
  if (!odd_quarter) {
    // p_J = 1 − n sn² (<= 5 for n >= −4), as (1 − n) + n cn² for n > 0 (like-signed terms)
    const double pj = n <= 0.0 ? 1.0 - n * sn2 : (1.0 - n) + n * cn2;
    const carlson::Duplication d = carlson::duplicate_rf_rj({cn2, dn2, 1.0, pj, cn, dn, 1.0, std::sqrt(pj), 0});
    return {sn * d.rf, sn * (d.rf + n / 3.0 * sn2 * rj_of(d))};
  }
  // p_J = (dn² − n cn²)/(1 − n) as like-signed terms: (mc + (m − n) cn²)/(1 − n) for n <= m, its root
  // from kc and √(m − n) cn (cn² may underflow where cn ~ √kc does not); ((1 − n) + (n − m) sn²)/(1 − n)
  // for n > m
  double sp;
  if (n <= p.m) {
    const double a = std::sqrt(p.m - n) * cn, big = std::max(a, p.kc), small = std::min(a, p.kc);
    sp = big * std::sqrt((1.0 + (small / big) * (small / big)) / (1.0 - n));
  } else {
    sp = std::sqrt(((1.0 - n) + (n - p.m) * sn2) / (1.0 - n));
  }
  const carlson::Duplication d = carlson::duplicate_rf_rj({cn2, dn2, 1.0, sp * sp, cn, dn, 1.0, sp, 0});
  // mc R_J, the first term's kc² taken with the two root sums of cn and dn (each >= √kc)
  const double mc_rj = p.mc * times_pow2(d.rj_rest, d.rj_exponent) + 6.0 * d.rc0 * (p.kc / d.d0[0]) * (p.kc / d.d0[1]) / d.d0[2];
  return {sn * d.rf, sn / (1.0 - n) * (d.rf - n * sn2 * mc_rj / (3.0 * (1.0 - n)))};
}

double ellippi_am_separatrix(double u, double n) {
  if (n < 0.0) {
    const double a = std::sqrt(-n);
    return (u + a * std::atan(a * std::tanh(u))) / (1.0 - n);
  }
  if (n > 0.0) {
    const double b = std::sqrt(n);
    return (u - b * std::atanh(b * std::tanh(u))) / (1.0 - n);
  }
  return u;
}

double ellippi_am(double u, double n, double m, double mc) {
  require_finite(u, "u");
  check_characteristic(n);
  return ellippi_am(u, n, elliptic_parameter(m, mc));
}

double ellippi_am(double u, double n, const EllipticParameter& p) {
  if (p.kc == 0.0) return ellippi_am_separatrix(u, n);  // no period
  const QuarterPeriods r = reduce_quarter_periods(u, p.K);
  const double quarter = quarter_of(r.l);
  const bool odd = quarter == 1.0 || quarter == 3.0;
  const double reduced = elliptic_f_pi_reduced(jacobi_ellipj_reduced(r.w, p), odd, n, p).pi;
  if (r.l == 0.0) return reduced;
  return reduced + r.l * complete_ellippi(n, p);  // ±inf beyond the double range (|u| near it)
}

}  // namespace rigiddyn
