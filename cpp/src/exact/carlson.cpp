// Carlson's symmetric elliptic integrals R_F and R_J for real arguments by the duplication theorem
// and a fifth-order Taylor series (Carlson, Numer. Algorithms 10, 1995; DLMF 19.36.i):
//
//   λ = √x√y + √y√z + √z√x,  (x, y, z, p, A) ← (· + λ)/4,  repeated until 4^−M Q < A_M,
//   R_F = A_M^−½ (1 − E2/10 + E3/14 + E2²/24 − 3 E2 E3/44),
//   R_J = 4^−M A_M^−3/2 (1 − 3E2/14 + E3/6 + 9E2²/88 − 3E4/22 − 9E2E3/52 + 3E5/26)
//         + 6 Σ_{m<M} 4^−m R_C(1, 1 + e_m)/d_m,
//   d_m = (√p + √x)(√p + √y)(√p + √z),  e_m = Π_i 4^−m (p − x_i)/(√p + √x_i)² (p − x_i initial; at m = 0
//   the ratios (√p − √x_i)/(√p + √x_i)),  1 + e_m = 2√p (p + λ)/d_m (all at step m: the sum of
//   Π(√p ± √x_i) over the signs, so that R_C keeps full precision when p ≪ x, y, z drives 1 + e_m to 0).
//
// Arguments spanning 1e-300..1e300: the public functions scale them by 4^−k, exactly, so that
// the largest is below 4 (R_F(4^−k ·) = 2^k R_F, R_J(4^−k ·) = 8^k R_J, DLMF 19.16.1-2), and pass their
// square roots, which the first step uses as given: a tiny argument may underflow once scaled while its
// root, all that the sequence needs of it, does not. Every later argument is at least λ_0/4. R_J's first
// term 6 R_C/d_0 is combined in the caller's units (d_0 can underflow where R_J is representable).
// The stopping test is then finite and the sequence stops within a bounded number of steps: the bound
// below is never reached for valid input, and is checked (std::runtime_error) rather than assumed.
//
// Written here rather than taken from Boost.Math because Boost's R_J (general domain, policies)
// costs ~1 µs, which dominated the exact free flow; Boost remains the tests' reference.
// Relative error a few ulps (tests/cpp/test_exact_elliptic.cpp compares with Boost, the Python tests
// with SciPy and mpmath).
#include "carlson_core.hpp"
#include "power_of_two.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/exact/elliptic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace rigiddyn {

namespace carlson {

namespace {

// Q = (3r)^−1/6 max|A0 − x_i| for R_F and (r/4)^−1/6 max|A0 − x_i| for R_J at r = 2^−53
// (Carlson 1995, §2 and §4): the truncated series is then accurate to about r.
const double kRfTolerance = std::pow(3.0 * 0x1p-53, -1.0 / 6.0);
const double kRjTolerance = std::pow(0.25 * 0x1p-53, -1.0 / 6.0);

// Scaled x, y, z lie in [2^−2150, 2]. Where the roots of the largest two set λ, the small arguments
// catch up geometrically (log2 of the exponent range, ~11 steps), then Q <= 2 kRjTolerance ≈ 800
// falls below the limit A (>= ~1e-6, R_F <= ~1e3 there) within ~17 steps. A large p decays by 4 per
// step towards them: at most log4(2^2150) = 1075 steps. The bound is never reached for valid input.
constexpr int kMaxDuplications = 1200;

// R_C(1, y) at y = 1 + e > 0, both given accurately (DLMF 19.2.19-20): atan(√e)/√e for e > 0;
// atanh(t)/t = ln((1 + t)/√y)/t with t = √−e for e < 0 (no cancellation as y → 0); near e = 0 the
// series Σ (−e)^k/(2k + 1), k ≤ 8 (next term < 1e-19 for |e| < 1e-2).
double rc_one(double e, double y) {
  if (std::abs(e) < 1e-2) {
    double series = 1.0 / 17.0;
    for (int k = 7; k >= 0; --k) series = 1.0 / (2 * k + 1) - e * series;
    return series;
  }
  if (e > 0.0) {
    const double s = std::sqrt(e);
    return std::atan(s) / s;
  }
  const double t = std::sqrt(-e);
  return std::log((1.0 + t) / std::sqrt(y)) / t;
}

// R_F's series at the end of the duplication: X, Y the scaled deviations (Z = −X − Y).
double rf_series(double X, double Y, double A) {
  const double Z = -X - Y;
  const double E2 = X * Y - Z * Z, E3 = X * Y * Z;
  return (1.0 - E2 / 10.0 + E3 / 14.0 + E2 * E2 / 24.0 - 3.0 * E2 * E3 / 44.0) / std::sqrt(A);
}

// R_J's series at the end of the duplication: X, Y, Z the scaled deviations, P = −(X + Y + Z)/2.
double rj_series(double X, double Y, double Z) {
  const double P = -0.5 * (X + Y + Z);
  const double XYZ = X * Y * Z, P2 = P * P;
  const double E2 = X * Y + X * Z + Y * Z - 3.0 * P2;
  const double E3 = XYZ + 2.0 * E2 * P + 4.0 * P2 * P;
  const double E4 = (2.0 * XYZ + E2 * P + 3.0 * P2 * P) * P;
  const double E5 = XYZ * P2;
  return 1.0 - 3.0 * E2 / 14.0 + E3 / 6.0 + 9.0 * E2 * E2 / 88.0 - 3.0 * E4 / 22.0 - 9.0 * E2 * E3 / 52.0 + 3.0 * E5 / 26.0;
}

// R_C(1, 1 + e_0) of the first step, from the roots: e_0 = Π (√p − √x_i)/(√p + √x_i) and
// 1 + e_0 = 2√p (p + λ)/d_0, its factors ordered (smallest root sum with 2√p, the other two with
// p + λ >= their product's order) so that no intermediate underflows.
double first_rc(double sp, double p, double lambda, const double (&f)[3], double sx, double sy, double sz) {
  const double e = (sp - sx) / f[0] * ((sp - sy) / f[1]) * ((sp - sz) / f[2]);
  double lo = f[0], mid = f[1], hi = f[2];
  if (lo > mid) std::swap(lo, mid);
  if (mid > hi) std::swap(mid, hi);
  if (lo > mid) std::swap(lo, mid);
  return rc_one(e, (2.0 * sp / lo) * ((p + lambda) / (mid * hi)));
}

// The duplication. R_J = Σ_{m<M} 4^−m 6 R_C,m/d_m + 4^−M R_J(a_M): the sum from the first term on which
// the series contributes (m_s = p_offset, see below) is accumulated as 4^−m_s 2^e_S S with
// S = Σ 4^−(m − m_s) 2^−e_S 6 R_C,m/d_m (the weight 4^−(m − m_s) never underflows, and e_S = 0 unless a
// term would exceed the double range in these scaled units: arguments spanning 1e-300..1e300 give
// 1/d_m up to ~2^1600), so that R_J = 2^(e_S − 2 m_s) (S + 2^−e_S 4^−(M − m_s) R_J(a_M)).
// A p far above x, y, z (p_offset > 0: p, A_J, Q_J in units of 4^p_offset) first decays alone,
// p ← p/4 (λ ≤ 12 is below 2^−390 of it), while p_offset counts down: there R_J's terms are at most
// ~5·2^−597 4^−m and double per step up to the end of the sequence, where they are ≥ 2^190 times
// larger, so they are dropped; the deviations of R_J's series are then 4^(p_offset − m) (A_J0 − x_i) (devJ).
template <bool kWithRj>
Duplication duplicate(const Arguments& a) {
  double x = a.x, y = a.y, z = a.z, p = a.p;
  double sx = a.sx, sy = a.sy, sz = a.sz, sp = a.sp;
  int Kp = kWithRj ? a.p_offset : 0;
  // x, y, z in p's units (negligible beside p when Kp > 0)
  const double xp = times_pow2(x, -2 * Kp), yp = times_pow2(y, -2 * Kp), zp = times_pow2(z, -2 * Kp);
  const double AF0 = (x + y + z) / 3.0, AJ0 = (xp + yp + zp + 2.0 * p) / 5.0;
  double AF = AF0, AJ = AJ0;
  double QF = kRfTolerance * std::max({std::abs(AF0 - x), std::abs(AF0 - y), std::abs(AF0 - z)});
  double QJ = kWithRj ? kRjTolerance * std::max({std::abs(AJ0 - xp), std::abs(AJ0 - yp), std::abs(AJ0 - zp), std::abs(AJ0 - p)})
                      : 0.0;
  const double dx = p - xp, dy = p - yp, dz = p - zp;  // 4^(m − Kp0) (p_m − x_m) once Kp = 0
  // the arguments stay within [min, max] of the initial ones (λ lies in [3 min, 3 max])
  const bool moderate = std::min({x, y, z, p}) >= 0x1p-200 && p <= 0x1p300;
  Duplication out{0.0, 0.0, 0, 0.0, {1.0, 1.0, 1.0}};  // no first term when the series holds at once
  double dev = 1.0, devJ = 1.0;  // 4^−m; 4^(Kp0 − m) once Kp = 0
  double rest = 0.0;             // S
  int rest_exponent = 0;         // e_S
  double weight = 1.0;           // 4^−(m − m_s)
  int m = 0;
  for (; QF >= AF || (kWithRj && (Kp > 0 || QJ >= AJ)); ++m) {
    if (m == kMaxDuplications) {
      throw std::runtime_error("Carlson duplication: no convergence after " + std::to_string(m) +
                               " steps (x, y, z, p scaled = " + format_value(Eigen::Vector4d(a.x, a.y, a.z, a.p)) + ")");
    }
    if (m > 0) sx = std::sqrt(x), sy = std::sqrt(y), sz = std::sqrt(z);
    const double lambda = sx * sy + sy * sz + sz * sx;
    if constexpr (kWithRj) {
      if (Kp > 0) {  // p ≫ x, y, z: the term is dropped, p/4
        --Kp;
        const double lambda_p = times_pow2(lambda, -2 * Kp);
        p += lambda_p, AJ += lambda_p;
      } else {
        if (m > 0) sp = std::sqrt(p);
        const double f[3] = {sp + sx, sp + sy, sp + sz};
        if (m == 0) {
          out.rc0 = first_rc(sp, p, lambda, f, sx, sy, sz);
          std::copy(f, f + 3, out.d0);
        } else if (moderate) {  // |(p − x)(p − y)(p − z)| <= 2^900 and e = that/d² with d in [2^−303, 2^453]
          const double d = f[0] * f[1] * f[2];
          const double e = devJ * devJ * devJ * (dx * dy * dz) / d / d;
          rest += weight * 6.0 * rc_one(e, 2.0 * sp * (p + lambda) / d) / d;
        } else {  // the product could over- or underflow: ratio by ratio, 1/d by exponents
          const double e = (devJ * dx / (f[0] * f[0])) * (devJ * dy / (f[1] * f[1])) * (devJ * dz / (f[2] * f[2]));
          const double rc = rc_one(e, (2.0 * sp / f[0]) * ((p + lambda) / (f[1] * f[2])));
          int e0 = 0, e1 = 0, e2 = 0;
          const double d_mantissa = std::frexp(f[0], &e0) * std::frexp(f[1], &e1) * std::frexp(f[2], &e2);
          const int term_exponent = -(e0 + e1 + e2);  // term = weight 6 rc/d_mantissa 2^term_exponent
          if (term_exponent - rest_exponent > 512) {  // S to the new unit (what underflows is negligible)
            rest = times_pow2(rest, rest_exponent - term_exponent);
            rest_exponent = term_exponent;
          }
          rest += times_pow2(weight * 6.0 * rc / d_mantissa, term_exponent - rest_exponent);
        }
        p = 0.25 * (p + lambda);
        AJ = 0.25 * (AJ + lambda);
        QJ *= 0.25, devJ *= 0.25, weight *= 0.25;
      }
    }
    x = 0.25 * (x + lambda), y = 0.25 * (y + lambda), z = 0.25 * (z + lambda);
    AF = 0.25 * (AF + lambda);
    QF *= 0.25, dev *= 0.25;
  }
  out.rf = rf_series(dev * (AF0 - a.x) / AF, dev * (AF0 - a.y) / AF, AF);
  if constexpr (kWithRj) {
    const double tail = rj_series(devJ * (AJ0 - xp) / AJ, devJ * (AJ0 - yp) / AJ, devJ * (AJ0 - zp) / AJ);
    const int m_s = a.p_offset;
    out.rj_rest = rest + times_pow2(tail / (AJ * std::sqrt(AJ)), -2 * (m - m_s) - rest_exponent);
    out.rj_exponent = rest_exponent - 2 * m_s;
  }
  return out;
}

}  // namespace

Duplication duplicate_rf(const Arguments& a) { return duplicate<false>(a); }
Duplication duplicate_rf_rj(const Arguments& a) { return duplicate<true>(a); }

}  // namespace carlson

namespace {

void check_rf_arguments(double x, double y, double z) {
  require_finite(x, "x");
  require_finite(y, "y");
  require_finite(z, "z");
  if (!(x >= 0.0)) throw_invalid("x", "x >= 0", x);
  if (!(y >= 0.0)) throw_invalid("y", "y >= 0", y);
  if (!(z >= 0.0)) throw_invalid("z", "z >= 0", z);
  // name the second zero: R_F and R_J diverge when two of x, y, z vanish
  if (x == 0.0 && y == 0.0) throw_invalid("y", "y > 0 when x = 0 (at most one of x, y, z zero)", y);
  if ((x == 0.0 || y == 0.0) && z == 0.0) throw_invalid("z", "z > 0 when x or y = 0 (at most one of x, y, z zero)", z);
}

void check_p(double p) {
  require_finite(p, "p");
  if (!(p > 0.0)) throw_invalid("p", "p > 0", p);
}

// The arguments times 4^−k and their roots times 2^−k (exact scalings), the largest of x, y, z in
// [1/2, 2); p in units of 4^p_offset when it would exceed 2^400 (p ≫ x, y, z; a tiny p keeps its root).
struct ScaledArguments {
  carlson::Arguments a;
  int k;
};

ScaledArguments scaled_arguments(double x, double y, double z, double p) {
  int e = 0;
  std::frexp(std::max({x, y, z}), &e);  // largest in [2^(e−1), 2^e)
  const int k = static_cast<int>(std::floor(0.5 * e));
  int e_p = 0;
  std::frexp(p, &e_p);
  const int p_offset = std::max(0, (e_p - 2 * k - 400) / 2 + 1);
  const auto value = [](double v, int k4) { return times_pow2(v, -2 * k4); };
  const auto root = [](double v, int k4) { return times_pow2(std::sqrt(v), -k4); };
  return {{value(x, k), value(y, k), value(z, k), value(p, k + p_offset), root(x, k), root(y, k), root(z, k),
           root(p, k + p_offset), p_offset},
          k};
}

// R_J in the caller's units from the scaled duplication: 8^−k 2^rj_exponent rj_rest + 6 rc0/Π(2^k d0_i), the product
// taken by exponents (frexp) so that neither it nor a partial result over- or underflows spuriously.
double rj_unscaled(const carlson::Duplication& d, int k) {
  double mantissa = 1.0;
  int exponent = 0;
  for (double f : d.d0) {
    int e = 0;
    mantissa *= std::frexp(f, &e);
    exponent += e;
  }
  return times_pow2(d.rj_rest, d.rj_exponent - 3 * k) + times_pow2(6.0 * d.rc0 / mantissa, -exponent - 3 * k);
}

}  // namespace

double elliprf(double x, double y, double z) {
  check_rf_arguments(x, y, z);
  const ScaledArguments s = scaled_arguments(x, y, z, 0.0);
  return times_pow2(carlson::duplicate_rf(s.a).rf, -s.k);
}

double elliprj(double x, double y, double z, double p) { return elliprf_elliprj(x, y, z, p).rj; }

CarlsonRfRj elliprf_elliprj(double x, double y, double z, double p) {
  check_rf_arguments(x, y, z);
  check_p(p);
  const ScaledArguments s = scaled_arguments(x, y, z, p);
  const carlson::Duplication d = carlson::duplicate_rf_rj(s.a);
  return {times_pow2(d.rf, -s.k), rj_unscaled(d, s.k)};
}

}  // namespace rigiddyn
