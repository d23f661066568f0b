// Jacobi's elliptic functions and Π(am u, n|m) for one (m, n) at many arguments by theta series (the header has
// the formulas).
//
// The point ib is kept as b and its complement ε = K' − b, each an incomplete integral of the first kind for the
// parameter 1 − m computed directly (Carlson's R_F), so that neither is a difference of nearby numbers:
//   b = F(φ_b|1 − m), tan φ_b = sc(b|1 − m) = √(−n/m),   ε = F(ψ|1 − m), tan ψ = 1/√(−n)
// (sn(K' − ε) = cd ε and cn(K' − ε) = k sd ε for the parameter 1 − m, whose complementary modulus is k = √m,
// DLMF Table 22.4.3: sc(b) = 1/(k tan am ε)), with F(φ|m') = sin φ R_F(cos² φ, 1 − m' sin² φ, 1) (DLMF 19.25.5).
// Every coefficient is one exp of its whole exponent, so that no factor of it over- or underflows alone.
#include "rigiddyn/exact/elliptic_theta.hpp"

#include "rigiddyn/check.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rigiddyn {

namespace {

// F(φ|m') from sin² φ and cos² φ given as quotients (both formed without cancellation by the caller)
double incomplete_first_kind(double sin2, double cos2, double one_minus_mp_sin2) {
  return std::sqrt(sin2) * elliprf(cos2, one_minus_mp_sin2, 1.0);
}

// the largest order j ≤ max_terms whose bound e^(−exponent(j)) is at least 2^−80
template <class Exponent>
int orders_kept(Exponent exponent, int max_terms) {
  constexpr double kNegligible = 80.0 * M_LN2;
  int j = 0;
  while (j < max_terms && exponent(j + 1) <= kNegligible) ++j;
  return j;
}

// e^(−s) cosh(a) and e^(−s) sinh(a), a ≥ 0 (each a single exp of its whole exponent, so that e^a alone may exceed
// the double range; sinh by expm1 where a is small, without cancellation)
struct Hyperbolic {
  double cosh, sinh;
};

Hyperbolic scaled_cosh_sinh(double a, double s) {
  const double grow = std::exp(a - s), decay = std::exp(-a - s);
  return {0.5 * (grow + decay), a > 0.5 ? 0.5 * (grow - decay) : 0.5 * decay * std::expm1(2.0 * a)};
}

}  // namespace

bool EllipticTheta::applies(double n, const EllipticParameter& p) {
  // m/(m − n) and m(1 − n)/(m − n) enter R_F: both must be normal numbers (R_F takes at most one zero)
  return n < 0.0 && std::isfinite(n) && p.m > 0.0 && p.kc > 0.0 && p.K <= kMaxQuarterPeriod &&
         p.m / (p.m - n) >= 0x1p-1000;
}

EllipticTheta::EllipticTheta(double n, const EllipticParameter& p, double pi_complete) {
  if (!applies(n, p)) {
    throw_invalid("n", "n < 0 with 0 < m < 1 and K(m) <= " + format_value(kMaxQuarterPeriod) + " (m = " + format_value(p.m) + ")", n);
  }
  const double m = p.m, mc = p.mc, K = p.K;
  // K' = K(1 − m) from its complementary modulus k = √m (ln k for k < 2^−27)
  const double k = std::sqrt(m);
  const double K_prime = elliptic_parameter_kc(mc, k, k < 0x1p-27 ? 0.5 * std::log(m) : 0.0).K;
  // b and ε = K' − b (tan φ_b = √(−n/m): sin² = −n/(m − n), cos² = m/(m − n), 1 − (1 − m) sin² = m(1 − n)/(m − n);
  // tan ψ = 1/√(−n): sin² = 1/(1 − n), cos² = −n/(1 − n), 1 − (1 − m) sin² = (m − n)/(1 − n))
  const double b = incomplete_first_kind(-n / (m - n), m / (m - n), m / (m - n) * (1.0 - n));
  const double eps_b = incomplete_first_kind(1.0 / (1.0 - n), -n / (1.0 - n), (m - n) / (1.0 - n));
  slope_ = pi_complete / K;
  scale_ = std::sqrt(-n / (m - n)) / std::sqrt(1.0 - n);
  if (K > K_prime) {
    init_transformed(K, K_prime, b, eps_b);
  } else {
    if (b <= eps_b) {
      init_q_about_b(K, K_prime, b, eps_b);
    } else {
      init_q_about_zero(K, K_prime, eps_b);
    }
    init_jacobi_in_q(M_PI * K_prime / K);
  }
}

// 2 q^(j²) cosh(jy), 2 q^(j²) sinh(jy) with q = e^−R, R = πK'/K, y = πb/K, R − y = πε/K:
// jy − j²R = −j(j − 1)R − j(R − y)
void EllipticTheta::init_q_about_b(double K, double K_prime, double b, double eps_b) {
  series_ = Series::q_about_b;
  const double R = M_PI * K_prime / K, y = M_PI * b / K, R_minus_y = M_PI * eps_b / K;
  angle_per_w_ = M_PI / (2.0 * K);
  terms_ = orders_kept([&](int j) { return j * (j - 1) * R + j * R_minus_y - M_LN2; }, kMaxTerms);
  for (int j = 1; j <= terms_; ++j) {
    const Hyperbolic h = scaled_cosh_sinh(j * y, j * j * R);
    const double sign = (j % 2 == 0) ? 1.0 : -1.0;  // (−1)^j of ϑ4
    even_re_[j] = 2.0 * sign * h.cosh, even_im_[j] = -2.0 * sign * h.sinh;
    odd_re_[j] = 2.0 * h.cosh, odd_im_[j] = -2.0 * h.sinh;
  }
}

// ϑ1(ζ − i e) ∝ Σ (−1)^j q^(j² + j) [sin((2j + 1)ζ) cosh((2j + 1)e) − i cos((2j + 1)ζ) sinh((2j + 1)e)],
// ϑ2(ζ − i e) ∝ Σ q^(j² + j) [cos((2j + 1)ζ) cosh((2j + 1)e) + i sin((2j + 1)ζ) sinh((2j + 1)e)]
// (the common factor 2 q^(1/4) dropped), e = πε/(2K) < R/4 (ε < K'/2)
void EllipticTheta::init_q_about_zero(double K, double K_prime, double eps_b) {
  series_ = Series::q_about_zero;
  const double R = M_PI * K_prime / K, e = M_PI * eps_b / (2.0 * K);
  angle_per_w_ = M_PI / (2.0 * K);
  terms_ = orders_kept([&](int j) { return (j * j + j) * R - (2 * j + 1) * e; }, kMaxTerms);
  const double leading = scaled_cosh_sinh(e, 0.0).cosh;  // every term in units of the leading cosh e (up to ~e^(R/4))
  for (int j = 0; j <= terms_; ++j) {
    const Hyperbolic h = scaled_cosh_sinh((2 * j + 1) * e, (j * j + j) * R);
    const double sign = (j % 2 == 0) ? 1.0 : -1.0;
    even_re_[j] = sign * h.cosh / leading, even_im_[j] = -sign * h.sinh / leading;
    odd_re_[j] = h.cosh / leading, odd_im_[j] = h.sinh / leading;
  }
}

// Jacobi's sums in q = e^−R (their orders q^(j²) decay at least as fast as the phase's: terms_ is theirs or more)
// and the theta constants of their quotients, the sums at ζ = 0
void EllipticTheta::init_jacobi_in_q(double R) {
  terms_ = std::max(terms_, orders_kept([&](int j) { return j * j * R; }, kMaxTerms));
  double theta2_0 = 0.0, theta3_0 = 1.0, theta4_0 = 1.0;
  for (int j = 0; j <= terms_; ++j) {
    const double sign = (j % 2 == 0) ? 1.0 : -1.0;
    const double q_odd = std::exp(-(j * j + j) * R), q_even = j == 0 ? 0.0 : 2.0 * std::exp(-j * j * R);
    theta1_[j] = sign * q_odd, theta2_[j] = q_odd, theta3_[j] = q_even, theta4_[j] = sign * q_even;
    theta2_0 += q_odd, theta3_0 += q_even, theta4_0 += sign * q_even;
  }
  sn_scale_ = theta3_0 / theta2_0, cn_scale_ = theta4_0 / theta2_0, dn_scale_ = theta4_0 / theta3_0;
}

// q' = e^−R', R' = πK/K'; β = πb/(2K') = π/2 − δ, δ = πε/(2K'): the functions of (2j + 1)β and 2jβ from
// whichever of β and δ is the smaller (the other's sine would lose its relative precision). The theta constants:
// ϑ2(0) ∝ 2 Σ q'^(j² + j), ϑ3(0) = 1 + 2 Σ q'^(j²), ϑ4(0) = 1 + 2 Σ (−1)^j q'^(j²) (ϑ2 in the units of the sums)
void EllipticTheta::init_transformed(double K, double K_prime, double b, double eps_b) {
  series_ = Series::transformed;
  const double R_prime = M_PI * K / K_prime, beta = M_PI * b / (2.0 * K_prime), delta = M_PI * eps_b / (2.0 * K_prime);
  angle_per_w_ = M_PI / (2.0 * K_prime);
  linear_arg_ = -M_PI * b / (2.0 * K * K_prime);
  // the largest scaled term at |w| ≤ 3K/4 (α ≤ 3R'/8): q'^(j² + j) e^(2jα), q'^(j²) e^(2jα)
  terms_ = orders_kept([&](int j) { return R_prime * (j * j - 0.75 * j); }, kMaxTerms);
  double theta2_0 = 0.0, theta3_0 = 1.0, theta4_0 = 1.0;
  for (int j = 0; j <= terms_; ++j) {
    const double odd_multiple = 2 * j + 1, even_multiple = 2 * j;
    const double sign = (j % 2 == 0) ? 1.0 : -1.0;  // of (2j + 1)π/2 and jπ
    if (beta <= delta) {
      even_re_[j] = std::cos(odd_multiple * beta), even_im_[j] = std::sin(odd_multiple * beta);
      odd_re_[j] = std::cos(even_multiple * beta), odd_im_[j] = std::sin(even_multiple * beta);
    } else {
      even_re_[j] = sign * std::sin(odd_multiple * delta), even_im_[j] = sign * std::cos(odd_multiple * delta);
      odd_re_[j] = sign * std::cos(even_multiple * delta), odd_im_[j] = -sign * std::sin(even_multiple * delta);
    }
    theta2_0 += 2.0 * std::exp(-(j * j + j) * R_prime);
    if (j > 0) {
      even_ratio_[j - 1] = std::exp(-2.0 * j * R_prime);
      odd_ratio_[j - 1] = std::exp(-(2.0 * j - 1.0) * R_prime);
      const double q_even = 2.0 * std::exp(-j * j * R_prime);
      theta3_0 += q_even, theta4_0 += sign * q_even;
    }
  }
  sn_scale_ = theta3_0 / theta4_0, cn_scale_ = theta2_0 / theta4_0, dn_scale_ = theta2_0 / theta3_0;
}

EllipticTheta::Evaluation EllipticTheta::evaluate(double w, bool odd_quarter) const {
  const double a = std::abs(w);
  Evaluation e = series_ == Series::transformed ? evaluate_transformed(a, odd_quarter) : evaluate_in_q(a, odd_quarter);
  if (w < 0.0) {  // sn and arg Θ are odd in w, cn and dn even
    e.f.sn = -e.f.sn;
    e.phase.linear = -e.phase.linear, e.phase.im = -e.phase.im;
  }
  return e;
}

double EllipticTheta::reduced(double w, bool odd_quarter) const {
  const Phase p = evaluate(w, odd_quarter).phase;
  return slope_ * w + scale_ * (p.linear + std::atan2(p.im, p.re));
}

// The series in q at w ≥ 0: cos and sin of the multiples kζ, k ≤ 2 terms_ + 1, by rotations through ζ; Jacobi's
// quotients from the odd (ϑ1, ϑ2) and even (ϑ3, ϑ4) multiples; the phase about b from the even ones
// (1 + Σ re_j cos 2jζ + i Σ im_j sin 2jζ), about the zero from the odd ones (even quarter: π/2 − ζ + arg of
// Σ re_j sin((2j + 1)ζ) + i Σ im_j cos((2j + 1)ζ); odd: −ζ + arg of Σ re_j cos((2j + 1)ζ) + i Σ im_j sin((2j + 1)ζ))
EllipticTheta::Evaluation EllipticTheta::evaluate_in_q(double w, bool odd_quarter) const {
  const double zeta = angle_per_w_ * w, c1 = std::cos(zeta), s1 = std::sin(zeta);
  std::array<double, 2 * kMaxTerms + 2> c, s;
  c[0] = 1.0, s[0] = 0.0;
  for (int k = 1; k <= 2 * terms_ + 1; ++k) {
    c[k] = c[k - 1] * c1 - s[k - 1] * s1;
    s[k] = s[k - 1] * c1 + c[k - 1] * s1;
  }
  double t1 = 0.0, t2 = 0.0, t3 = 1.0, t4 = 1.0;
  for (int j = 0; j <= terms_; ++j) {
    t1 += theta1_[j] * s[2 * j + 1];
    t2 += theta2_[j] * c[2 * j + 1];
    t3 += theta3_[j] * c[2 * j];
    t4 += theta4_[j] * c[2 * j];
  }
  const JacobiSnCnDn f{sn_scale_ * t1 / t4, cn_scale_ * t2 / t4, dn_scale_ * t3 / t4};
  const auto& re = odd_quarter ? odd_re_ : even_re_;
  const auto& im = odd_quarter ? odd_im_ : even_im_;
  double sum_re = 0.0, sum_im = 0.0;
  if (series_ == Series::q_about_b) {
    sum_re = 1.0;
    for (int j = 1; j <= terms_; ++j) sum_re += re[j] * c[2 * j], sum_im += im[j] * s[2 * j];
    return {f, {0.0, sum_re, sum_im}};
  }
  for (int j = 0; j <= terms_; ++j) {
    const double cj = c[2 * j + 1], sj = s[2 * j + 1];
    sum_re += re[j] * (odd_quarter ? cj : sj);
    sum_im += im[j] * (odd_quarter ? sj : cj);
  }
  return {f, {odd_quarter ? -zeta : M_PI_2 - zeta, sum_re, sum_im}};
}

// The transformed series at w ≥ 0, α = πw/(2K'), every sum divided by its largest leading factor so that no term
// leaves the double range: with g = e^(−α) and h = g²,
//   −i ϑ1(iα), ϑ2(iα) ∝ Σ_{j≥0} (±1)^j q'^(j² + j) (h^−j ∓ h^(j+1))      (S1, S2; units q'^(1/4) e^α),
//   ϑ3(iα), ϑ4(iα) = 1 + Σ_{j≥1} (±1)^j q'^(j²) (h^−j + h^j)            (S3, S4),
//   ϑ2(β − iα) ∝ Σ_{j≥0} q'^(j² + j) [cos((2j + 1)β)(h^−j + h^(j+1)) + i sin((2j + 1)β)(h^−j − h^(j+1))],
//   ϑ3(β − iα) = 1 + Σ_{j≥1} q'^(j²) [cos(2jβ)(h^−j + h^j) + i sin(2jβ)(h^−j − h^j)],
// so that sn = sn_scale S1/S2, cn = cn_scale g S4/S2, dn = dn_scale g S3/S2; the growing factors q'^(…) h^−j ≤ 1
// formed as running products (ratios q'^(2j)/h, q'^(2j − 1)/h ≤ 1)
EllipticTheta::Evaluation EllipticTheta::evaluate_transformed(double w, bool odd_quarter) const {
  // g, h and 1 − h each to its own relative precision (1 − h from expm1 where h > 1/2)
  const double alpha = angle_per_w_ * w;
  double g, h, one_minus_h;
  if (alpha < 0.5 * M_LN2) {
    const double g_minus_one = std::expm1(-alpha);
    g = 1.0 + g_minus_one, h = g * g, one_minus_h = -g_minus_one * (2.0 + g_minus_one);
  } else {
    g = std::exp(-alpha), h = g * g, one_minus_h = 1.0 - h;
  }
  // the sums with q'^(j² + j) (j ≥ 0) and with q'^(j²) (j ≥ 1), and the quarter's phase with them
  double s1 = one_minus_h, s2 = 1.0 + h, s3 = 1.0, s4 = 1.0;
  double sum_re = odd_quarter ? 1.0 : even_re_[0] * (1.0 + h), sum_im = odd_quarter ? 0.0 : even_im_[0] * one_minus_h;
  double grow = 1.0, decay = h, grow_b = 1.0, decay_b = 1.0;
  for (int j = 1; j <= terms_; ++j) {
    const double sign = (j % 2 == 0) ? 1.0 : -1.0;
    grow *= even_ratio_[j - 1] / h, decay *= even_ratio_[j - 1] * h;
    grow_b *= odd_ratio_[j - 1] / h, decay_b *= odd_ratio_[j - 1] * h;
    s1 += sign * (grow - decay), s2 += grow + decay;
    s3 += grow_b + decay_b, s4 += sign * (grow_b + decay_b);
    if (odd_quarter) {
      sum_re += odd_re_[j] * (grow_b + decay_b), sum_im += odd_im_[j] * (grow_b - decay_b);
    } else {
      sum_re += even_re_[j] * (grow + decay), sum_im += even_im_[j] * (grow - decay);
    }
  }
  const JacobiSnCnDn f{sn_scale_ * s1 / s2, cn_scale_ * g * s4 / s2, dn_scale_ * g * s3 / s2};
  return {f, {linear_arg_ * w, sum_re, sum_im}};
}

}  // namespace rigiddyn
