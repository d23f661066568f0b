// Π(am u, n|m) for one (n, m) at many arguments by the theta series of its periodic part (the header has the
// formulas).
//
// The point ib is kept as b and its complement ε = K' − b, each an incomplete integral of the first kind for the
// parameter 1 − m computed directly (Carlson's R_F), so that neither is a difference of nearby numbers:
//   b = F(φ_b|1 − m), tan φ_b = sc(b|1 − m) = √(−n/m),   ε = F(ψ|1 − m), tan ψ = 1/√(−n)
// (sn(K' − ε) = cd ε and cn(K' − ε) = k sd ε for the parameter 1 − m, whose complementary modulus is k = √m,
// DLMF Table 22.4.3: sc(b) = 1/(k tan am ε)), with F(φ|m') = sin φ R_F(cos² φ, 1 − m' sin² φ, 1) (DLMF 19.25.5).
// Every coefficient is one exp of its whole exponent, so that no factor of it over- or underflows alone.
#include "rigiddyn/exact/third_kind_theta.hpp"

#include "rigiddyn/check.hpp"

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

bool ThirdKindTheta::applies(double n, const EllipticParameter& p) {
  // m/(m − n) and m(1 − n)/(m − n) enter R_F: both must be normal numbers (R_F takes at most one zero)
  return n < 0.0 && std::isfinite(n) && p.m > 0.0 && p.kc > 0.0 && p.K <= kMaxQuarterPeriod &&
         p.m / (p.m - n) >= 0x1p-1000;
}

ThirdKindTheta::ThirdKindTheta(double n, const EllipticParameter& p, double pi_complete) {
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
  } else if (b <= eps_b) {
    init_q_about_b(K, K_prime, b, eps_b);
  } else {
    init_q_about_zero(K, K_prime, eps_b);
  }
}

// 2 q^(j²) cosh(jy), 2 q^(j²) sinh(jy) with q = e^−R, R = πK'/K, y = πb/K, R − y = πε/K:
// jy − j²R = −j(j − 1)R − j(R − y)
void ThirdKindTheta::init_q_about_b(double K, double K_prime, double b, double eps_b) {
  series_ = Series::q_about_b;
  const double R = M_PI * K_prime / K, y = M_PI * b / K, R_minus_y = M_PI * eps_b / K;
  x_per_w_ = M_PI / K;
  terms_ = orders_kept([&](int j) { return j * (j - 1) * R + j * R_minus_y - M_LN2; }, kMaxTerms);
  for (int j = 1; j <= terms_; ++j) {
    const Hyperbolic h = scaled_cosh_sinh(j * y, j * j * R);
    const double sign = (j % 2 == 0) ? 1.0 : -1.0;  // (−1)^j of ϑ4
    even_re_[j - 1] = 2.0 * sign * h.cosh, even_im_[j - 1] = -2.0 * sign * h.sinh;
    odd_re_[j - 1] = 2.0 * h.cosh, odd_im_[j - 1] = -2.0 * h.sinh;
  }
}

// ϑ1(x/2 − i e) ∝ Σ (−1)^j q^(j² + j) [sin((2j + 1)x/2) cosh((2j + 1)e) − i cos((2j + 1)x/2) sinh((2j + 1)e)],
// ϑ2(x/2 − i e) ∝ Σ q^(j² + j) [cos((2j + 1)x/2) cosh((2j + 1)e) + i sin((2j + 1)x/2) sinh((2j + 1)e)]
// (the common factor 2 q^(1/4) dropped), e = πε/(2K) < R/4 (ε < K'/2)
void ThirdKindTheta::init_q_about_zero(double K, double K_prime, double eps_b) {
  series_ = Series::q_about_zero;
  const double R = M_PI * K_prime / K, e = M_PI * eps_b / (2.0 * K);
  x_per_w_ = M_PI / (2.0 * K);
  terms_ = orders_kept([&](int j) { return (j * j + j) * R - (2 * j + 1) * e; }, kMaxTerms);
  const double leading = scaled_cosh_sinh(e, 0.0).cosh;  // every term in units of the leading cosh e (up to ~e^(R/4))
  for (int j = 0; j <= terms_; ++j) {
    const Hyperbolic h = scaled_cosh_sinh((2 * j + 1) * e, (j * j + j) * R);
    const double sign = (j % 2 == 0) ? 1.0 : -1.0;
    even_re_[j] = sign * h.cosh / leading, even_im_[j] = -sign * h.sinh / leading;
    odd_re_[j] = h.cosh / leading, odd_im_[j] = h.sinh / leading;
  }
}

// q' = e^−R', R' = πK/K'; β = πb/(2K') = π/2 − δ, δ = πε/(2K'): the functions of (2j + 1)β and 2jβ from
// whichever of β and δ is the smaller (the other's sine would lose its relative precision)
void ThirdKindTheta::init_transformed(double K, double K_prime, double b, double eps_b) {
  series_ = Series::transformed;
  const double R_prime = M_PI * K / K_prime, beta = M_PI * b / (2.0 * K_prime), delta = M_PI * eps_b / (2.0 * K_prime);
  x_per_w_ = M_PI / (2.0 * K_prime);
  linear_arg_ = -M_PI * b / (2.0 * K * K_prime);
  // the largest scaled term at |w| ≤ 3K/4 (α ≤ 3R'/8): q'^(j² + j) e^(2jα) (ϑ2), q'^(j²) e^(2jα) (ϑ3)
  terms_ = orders_kept([&](int j) { return R_prime * (j * j - 0.75 * j); }, kMaxTerms);
  for (int j = 0; j <= terms_; ++j) {
    const double odd_multiple = 2 * j + 1, even_multiple = 2 * j;
    const double sign = (j % 2 == 0) ? 1.0 : -1.0;  // (2j + 1)π/2 and jπ
    if (beta <= delta) {
      even_re_[j] = std::cos(odd_multiple * beta), even_im_[j] = std::sin(odd_multiple * beta);
      odd_re_[j] = std::cos(even_multiple * beta), odd_im_[j] = std::sin(even_multiple * beta);
    } else {
      even_re_[j] = sign * std::sin(odd_multiple * delta), even_im_[j] = sign * std::cos(odd_multiple * delta);
      odd_re_[j] = sign * std::cos(even_multiple * delta), odd_im_[j] = -sign * std::sin(even_multiple * delta);
    }
    if (j > 0) {
      even_ratio_[j - 1] = std::exp(-2.0 * j * R_prime);
      odd_ratio_[j - 1] = std::exp(-(2.0 * j - 1.0) * R_prime);
    }
  }
}

ThirdKindTheta::Phase ThirdKindTheta::phase(double w, bool odd_quarter) const {
  const double a = std::abs(w);
  Phase p{};
  switch (series_) {
    case Series::q_about_b: p = phase_about_b(a, odd_quarter); break;
    case Series::q_about_zero: p = phase_about_zero(a, odd_quarter); break;
    case Series::transformed: p = phase_transformed(a, odd_quarter); break;
  }
  if (w < 0.0) p.linear = -p.linear, p.im = -p.im;  // arg Θ is odd in w
  return p;
}

double ThirdKindTheta::reduced(double w, bool odd_quarter) const {
  const Phase p = phase(w, odd_quarter);
  return slope_ * w + scale_ * (p.linear + std::atan2(p.im, p.re));
}

// arg Θ(w + ib) (even quarter) or arg Θ(K + w + ib) (odd), w ≥ 0, from the series in q: cos(jx) and sin(jx)
// by rotation
ThirdKindTheta::Phase ThirdKindTheta::phase_about_b(double w, bool odd_quarter) const {
  const double x = x_per_w_ * w, c1 = std::cos(x), s1 = std::sin(x);
  const auto& re = odd_quarter ? odd_re_ : even_re_;
  const auto& im = odd_quarter ? odd_im_ : even_im_;
  double c = c1, s = s1, sum_re = 1.0, sum_im = 0.0;
  for (int j = 0; j < terms_; ++j) {
    sum_re += re[j] * c;
    sum_im += im[j] * s;
    const double c_next = c * c1 - s * s1;
    s = s * c1 + c * s1;
    c = c_next;
  }
  return {0.0, sum_re, sum_im};
}

// arg Θ(w + ib) = π/2 − x + arg ϑ1(x − iπε/(2K)) (even quarter) or arg Θ(K + w + ib) = −x + arg ϑ2(x − iπε/(2K))
// (odd), x = πw/(2K), w ≥ 0: the odd multiples of x by rotations through 2x
ThirdKindTheta::Phase ThirdKindTheta::phase_about_zero(double w, bool odd_quarter) const {
  const double x = x_per_w_ * w, c1 = std::cos(x), s1 = std::sin(x);
  const double c2 = (c1 - s1) * (c1 + s1), s2 = 2.0 * s1 * c1;
  double c = c1, s = s1, sum_re = 0.0, sum_im = 0.0;
  for (int j = 0; j <= terms_; ++j) {
    if (odd_quarter) {
      sum_re += odd_re_[j] * c;
      sum_im += odd_im_[j] * s;
    } else {
      sum_re += even_re_[j] * s;
      sum_im += even_im_[j] * c;
    }
    const double c_next = c * c2 - s * s2;
    s = s * c2 + c * s2;
    c = c_next;
  }
  return {odd_quarter ? -x : M_PI_2 - x, sum_re, sum_im};
}

// arg ϑ2(β − iα|q') (even quarter) or arg ϑ3(β − iα|q') (odd), α = πw/(2K') ≥ 0, every term divided by the
// largest of the leading one, so that none leaves the double range: with h = e^(−2α),
//   ϑ2 ∝ Σ_{j≥0} q'^(j² + j) [cos((2j + 1)β)(h^−j + h^(j+1)) + i sin((2j + 1)β)(h^−j − h^(j+1))],
//   ϑ3 = 1 + Σ_{j≥1} q'^(j²) [cos(2jβ)(h^−j + h^j) + i sin(2jβ)(h^−j − h^j)],
// the growing factors q'^(…) h^−j ≤ 1 formed as running products (ratios q'^(2j)/h, q'^(2j − 1)/h ≤ 1)
ThirdKindTheta::Phase ThirdKindTheta::phase_transformed(double w, bool odd_quarter) const {
  // h and 1 − h each to its own relative precision (1 − h from expm1 where h > 1/2)
  const double two_alpha = 2.0 * x_per_w_ * w;
  double h, h_minus_one;
  if (two_alpha < M_LN2) {
    h_minus_one = std::expm1(-two_alpha), h = 1.0 + h_minus_one;
  } else {
    h = std::exp(-two_alpha), h_minus_one = h - 1.0;
  }
  double sum_re, sum_im, grow = 1.0, decay;
  if (odd_quarter) {
    sum_re = 1.0, sum_im = 0.0, decay = 1.0;
    for (int j = 1; j <= terms_; ++j) {
      const double ratio = odd_ratio_[j - 1];
      grow *= ratio / h;
      decay *= ratio * h;
      sum_re += odd_re_[j] * (grow + decay);
      sum_im += odd_im_[j] * (grow - decay);
    }
  } else {
    decay = h;
    sum_re = even_re_[0] * (1.0 + h), sum_im = even_im_[0] * -h_minus_one;
    for (int j = 1; j <= terms_; ++j) {
      const double ratio = even_ratio_[j - 1];
      grow *= ratio / h;
      decay *= ratio * h;
      sum_re += even_re_[j] * (grow + decay);
      sum_im += even_im_[j] * (grow - decay);
    }
  }
  return {linear_arg_ * w, sum_re, sum_im};
}

}  // namespace rigiddyn
