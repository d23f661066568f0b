// Carlson's symmetric elliptic integrals R_F and R_J for real arguments by the duplication theorem
// and a fifth-order Taylor series (Carlson, Numer. Algorithms 10, 1995; DLMF 19.36.i):
//
//   λ = √x√y + √y√z + √z√x,  (x, y, z, p, A) ← (· + λ)/4,  repeated until 4^−M Q < |A_M|,
//   R_F = A_M^−½ (1 − E2/10 + E3/14 + E2²/24 − 3 E2 E3/44),
//   R_J = 4^−M A_M^−3/2 (1 − 3E2/14 + E3/6 + 9E2²/88 − 3E4/22 − 9E2E3/52 + 3E5/26)
//         + 6 Σ_{m<M} 4^−m R_C(1, 1 + e_m)/d_m,
//   d_m = (√p + √x)(√p + √y)(√p + √z),  e_m = 4^−3m δ/d_m²,  δ = (p − x)(p − y)(p − z) (initial),
//   1 + e_m = 2√p (p + λ)/d_m (all at step m: the sum of Π(√p ± √x_i) over the signs, so that
//   R_C keeps full precision when p ≪ x, y, z drives 1 + e_m to 0).
//
// Written here rather than taken from Boost.Math because Boost's R_J (general domain, policies)
// costs ~1 µs, which dominated the exact free flow; Boost remains the tests' reference.
// Relative error a few ulps (tests/cpp/test_exact_elliptic.cpp compares with Boost and mpmath).
#include "rigiddyn/check.hpp"
#include "rigiddyn/exact/elliptic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigiddyn {

namespace {

// Q = (3r)^−1/6 max|A0 − x_i| for R_F and (r/4)^−1/6 max|A0 − x_i| for R_J at r = 2^−53
// (Carlson 1995, §2 and §4): the truncated series is then accurate to about r.
const double kRfTolerance = std::pow(3.0 * 0x1p-53, -1.0 / 6.0);
const double kRjTolerance = std::pow(0.25 * 0x1p-53, -1.0 / 6.0);

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

// R_F(0, y, z) = π / (2 AGM(√y, √z)) (DLMF 19.22.1 with 19.8.1; Carlson 1995 §3): the
// arithmetic-geometric mean converges quadratically; stopping at |a − b| < 2.7 √eps a leaves a
// relative error below eps in (a + b)/2.
double complete_rf(double y, double z) {
  double a = std::sqrt(y), b = std::sqrt(z);
  while (std::abs(a - b) >= 2.7 * 0x1p-26 * a) {
    const double mean = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = mean;
  }
  return M_PI / (a + b);
}

void check_rf_arguments(double x, double y, double z) {
  require_finite(x, "x");
  require_finite(y, "y");
  require_finite(z, "z");
  if (!(x >= 0.0)) throw_invalid("x", "x >= 0", x);
  if (!(y >= 0.0)) throw_invalid("y", "y >= 0", y);
  if (!(z >= 0.0)) throw_invalid("z", "z >= 0", z);
  if ((x == 0.0) + (y == 0.0) + (z == 0.0) > 1) throw_invalid("x, y, z", "at most one zero", Eigen::Vector3d(x, y, z));
}

}  // namespace

double elliprf(double x, double y, double z) {
  check_rf_arguments(x, y, z);
  if (x == 0.0) return complete_rf(y, z);
  if (y == 0.0) return complete_rf(x, z);
  if (z == 0.0) return complete_rf(x, y);
  const double A0 = (x + y + z) / 3.0;
  double A = A0, Q = kRfTolerance * std::max({std::abs(A0 - x), std::abs(A0 - y), std::abs(A0 - z)});
  double scale = 1.0;  // 4^−m
  const double x0 = x, y0 = y;
  while (Q >= std::abs(A)) {
    const double sx = std::sqrt(x), sy = std::sqrt(y), sz = std::sqrt(z);
    const double lambda = sx * sy + sy * sz + sz * sx;
    x = 0.25 * (x + lambda), y = 0.25 * (y + lambda), z = 0.25 * (z + lambda), A = 0.25 * (A + lambda);
    Q *= 0.25, scale *= 0.25;
  }
  return rf_series(scale * (A0 - x0) / A, scale * (A0 - y0) / A, A);
}

double elliprj(double x, double y, double z, double p) { return elliprf_elliprj(x, y, z, p).rj; }

// Both from one duplication sequence: R_F's mean A_F follows the same λ as R_J's A.
CarlsonRfRj elliprf_elliprj(double x, double y, double z, double p) {
  check_rf_arguments(x, y, z);
  require_finite(p, "p");
  if (!(p > 0.0)) throw_invalid("p", "p > 0", p);
  const double AF0 = (x + y + z) / 3.0, AJ0 = (x + y + z + 2.0 * p) / 5.0;
  const double delta = (p - x) * (p - y) * (p - z);
  double AF = AF0, AJ = AJ0;
  double QF = kRfTolerance * std::max({std::abs(AF0 - x), std::abs(AF0 - y), std::abs(AF0 - z)});
  double QJ = kRjTolerance * std::max({std::abs(AJ0 - x), std::abs(AJ0 - y), std::abs(AJ0 - z), std::abs(AJ0 - p)});
  double scale = 1.0, scale3 = 1.0;  // 4^−m, 4^−3m
  double sum = 0.0;                  // Σ 4^−m R_C(1, 1 + e_m)/d_m
  const double x0 = x, y0 = y, z0 = z;
  while (QF >= std::abs(AF) || QJ >= std::abs(AJ)) {
    const double sx = std::sqrt(x), sy = std::sqrt(y), sz = std::sqrt(z), sp = std::sqrt(p);
    const double lambda = sx * sy + sy * sz + sz * sx;
    const double d = (sp + sx) * (sp + sy) * (sp + sz);
    sum += scale * rc_one(scale3 * delta / (d * d), 2.0 * sp * (p + lambda) / d) / d;
    x = 0.25 * (x + lambda), y = 0.25 * (y + lambda), z = 0.25 * (z + lambda), p = 0.25 * (p + lambda);
    AF = 0.25 * (AF + lambda), AJ = 0.25 * (AJ + lambda);
    QF *= 0.25, QJ *= 0.25, scale *= 0.25, scale3 *= 1.0 / 64.0;
  }
  const double rf = rf_series(scale * (AF0 - x0) / AF, scale * (AF0 - y0) / AF, AF);
  const double rj_tail = rj_series(scale * (AJ0 - x0) / AJ, scale * (AJ0 - y0) / AJ, scale * (AJ0 - z0) / AJ);
  return {rf, scale * rj_tail / (AJ * std::sqrt(AJ)) + 6.0 * sum};
}

}  // namespace rigiddyn
