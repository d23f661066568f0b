// Jacobi elliptic functions by argument halving, a Maclaurin series and doubling of 1 − cn
// (the approach of Fukushima 2009, written from the double-argument formulas), with the reduction
// of u to [0, K/2] by periodicity, symmetry and the reflection about K/2 (DLMF 22.4, 22.17).
#include "rigiddyn/exact/elliptic.hpp"

#include "rigiddyn/check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigiddyn {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kInf = std::numeric_limits<double>::infinity();

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

// sn, cn, dn for 0 ≤ w ≤ K/2 (where cn ≥ mc^(1/4)/sqrt(1 + sqrt(mc)) and dn² ≥ sqrt(mc)).
// Halve w N times below the series threshold, then double y = 1 − cn N times:
//   s² = y(2 − y), c = 1 − y, d² = mc + m c²,
//   1 − cn(2w) = 2 s² d² / (1 − m s⁴),  1 − m s⁴ = c²(1 + s²) + mc s⁴   (no cancellation)
// from cn(2w) = (c² − s² d²)/(1 − m s⁴) (DLMF 22.8.2 at equal arguments).
JacobiSnCnDn sncndn_first_eighth(double w, double m, double mc) {
  int halvings = 0;
  while (w > kSeriesThreshold) {
    w *= 0.5;
    ++halvings;
  }
  double y = one_minus_cn_series(w, m);
  for (int i = 0; i < halvings; ++i) {
    const double s2 = y * (2.0 - y);
    const double c = 1.0 - y;
    const double d2 = mc + m * c * c;
    y = 2.0 * s2 * d2 / (c * c * (1.0 + s2) + mc * s2 * s2);
  }
  const double cn = 1.0 - y;
  return {std::sqrt(y * (2.0 - y)), cn, std::sqrt(mc + m * cn * cn)};
}

// sn, cn, dn for 0 ≤ v ≤ K: directly on [0, K/2], else by the reflection w = K − v (DLMF 22.4.3)
// sn(K − w) = cn/dn, cn(K − w) = sqrt(mc) sn/dn, dn(K − w) = sqrt(mc)/dn.
JacobiSnCnDn sncndn_first_quarter(double v, const EllipticParameter& p) {
  if (v <= 0.5 * p.K) return sncndn_first_eighth(v, p.m, p.mc);
  const JacobiSnCnDn f = sncndn_first_eighth(p.K - v, p.m, p.mc);  // exact difference (Sterbenz)
  const double sqrt_mc = std::sqrt(p.mc);
  return {f.cn / f.dn, sqrt_mc * f.sn / f.dn, sqrt_mc / f.dn};
}

}  // namespace

EllipticParameter elliptic_parameter(double m, double mc) {
  if (!(m >= 0.0 && m <= 1.0)) throw_invalid("m", "a parameter in [0, 1]", m);
  if (!(mc >= 0.0 && mc <= 1.0)) throw_invalid("mc", "a complement 1 - m in [0, 1]", mc);
  if (!(std::abs((m - 1.0) + mc) <= 4.0 * kEps)) {
    throw_invalid("mc", "1 - m to within 4 eps (m = " + format_value(m) + ")", mc);
  }
  return {m, mc, mc == 0.0 ? kInf : elliprf(0.0, mc, 1.0)};
}

double ellipk(double m, double mc) { return elliptic_parameter(m, mc).K; }

double ellippi(double n, double m, double mc) {
  const EllipticParameter p = elliptic_parameter(m, mc);
  if (!(n < 1.0)) throw_invalid("n", "a characteristic n < 1", n);
  if (p.mc == 0.0) throw_invalid("mc", "mc > 0 (Π(n|1) diverges)", mc);
  // DLMF 19.25.2
  return p.K + n / 3.0 * elliprj(0.0, p.mc, 1.0, 1.0 - n);
}

JacobiSnCnDn jacobi_ellipj(double u, double m, double mc) {
  require_finite(u, "u");
  return jacobi_ellipj(u, elliptic_parameter(m, mc));
}

JacobiSnCnDn jacobi_ellipj(double u, const EllipticParameter& p) {
  if (p.mc == 0.0) {  // m = 1: DLMF 22.5.3
    const double sech = 1.0 / std::cosh(u);
    return {std::tanh(u), sech, sech};
  }
  // u mod 4K into [−2K, 2K] (one rounding: the product in the fma is exact)
  double v = u;
  if (std::abs(v) > p.K) v = std::fma(-4.0 * p.K, std::nearbyint(u / (4.0 * p.K)), u);
  // sn odd, cn and dn even; sn(2K − v) = sn v, cn(2K − v) = −cn v, dn(2K − v) = dn v (DLMF 22.4)
  const double sn_sign = v < 0.0 ? -1.0 : 1.0;
  v = std::abs(v);
  double cn_sign = 1.0;
  if (v > p.K) {
    v = 2.0 * p.K - v;
    cn_sign = -1.0;
  }
  const JacobiSnCnDn f = sncndn_first_quarter(std::max(v, 0.0), p);
  return {sn_sign * f.sn, cn_sign * f.cn, f.dn};
}


double ellippi_sncndn(const JacobiSnCnDn& f, double n) { return elliptic_f_pi_sncndn(f, n).pi; }

EllipticFPi elliptic_f_pi_sncndn(const JacobiSnCnDn& f, double n) {
  const double cn2 = f.cn * f.cn, dn2 = f.dn * f.dn, sn2 = f.sn * f.sn;
  const CarlsonRfRj r = elliprf_elliprj(cn2, dn2, 1.0, 1.0 - n * sn2);
  return {f.sn * r.rf, f.sn * (r.rf + n / 3.0 * sn2 * r.rj)};
}

double ellippi_am(double u, double n, double m, double mc) {
  require_finite(u, "u");
  if (!(n < 1.0)) throw_invalid("n", "a characteristic n < 1", n);
  return ellippi_am(u, n, elliptic_parameter(m, mc));
}

double ellippi_am(double u, double n, const EllipticParameter& p) {
  if (p.mc == 0.0) return ellippi_sncndn(jacobi_ellipj(u, p), n);  // no period: am u ∈ (−π/2, π/2)
  // u = v + 2jK with v ∈ [−K, K]; sn(v + 2jK) = (−1)^j sn v (DLMF 22.4.2)
  const double j = std::nearbyint(u / (2.0 * p.K));
  const double v = std::fma(-2.0 * p.K, j, u);
  const double pi_v = ellippi_sncndn(jacobi_ellipj(v, p), n);
  if (j == 0.0) return pi_v;
  return pi_v + 2.0 * j * (p.K + n / 3.0 * elliprj(0.0, p.mc, 1.0, 1.0 - n));
}

}  // namespace rigiddyn
