// The incomplete elliptic integral of the third kind Π(am u, n|m) for one (n, m) at many arguments, from
// Jacobi's theta-function form of its periodic part: a few terms of a theta series per argument instead of a
// Carlson duplication sequence (elliptic.hpp), for a closed form evaluated at many times.
//
// With n = m sn²(a|m), Jacobi's integral Π_J(u, a) = u Z(a) + ½ ln(Θ(u − a)/Θ(u + a)) (Whittaker & Watson,
// §22.74) and Π(am u, n|m) = u + sn a/(cn a dn a) Π_J(u, a). For n < 0 the point a = i b is imaginary
// (sn(ib|m) = i sc(b|1 − m), DLMF 22.6.iv): b = F(φ_b|1 − m) with sin² φ_b = −n/(m − n), and the logarithm
// is −2i arg Θ(u + ib) (Θ has real coefficients), so that
//   Π(am u, n|m) = (Π(n|m)/K) u + S arg Θ(u + i b),   S = √(−n/((m − n)(1 − n))),
// Θ(z) = ϑ4(πz/(2K)|q), q = e^(−πK'/K), K' = K(1 − m); the linear part follows from Π(am(u + 2K)) =
// Π(am u) + 2Π(n|m). Θ has no zero on the line u + ib (its zeros lie at iK' + 2jK, b < K') and is positive at
// u = 0, so the continuous argument is the principal one; it is odd in u. The quarter-shifted argument
// Θ(K + z) = ϑ3(πz/(2K)|q) serves the odd quarters. Three series, each converging at least as e^(−π) per
// order, chosen per (n, m) so that the argument keeps its precision where Θ(u + ib) passes close to its zero
// iK' (b → K', where −n/m is large and the integral is a steep step of height ~π/√(−n)):
//   K ≤ K', b ≤ ε = K' − b:  Θ(w + ib) = 1 + 2 Σ_{j≥1} (∓1)^j q^(j²) [cosh(jy) cos(jx) − i sinh(jy) sin(jx)],
//                            x = πw/K, y = πb/K ((−1)^j for Θ, 1 for the shifted ϑ3);
//   K ≤ K', b > ε:           about the zero, Θ(z + iK') = i q^(−1/4) e^(−iπz/(2K)) H(z) (DLMF 20.2.12 with
//                            H(z) = ϑ1(πz/(2K)|q), H(K + z) = ϑ2(πz/(2K)|q)): arg Θ(w + ib) = π/2 − x/2 +
//                            arg H(w − iε), arg Θ(K + w + ib) = −x/2 + arg ϑ2(π(w − iε)/(2K)|q);
//   K > K':                  Jacobi's imaginary transformation (DLMF §20.7(viii)) with q' = e^(−πK/K'):
//                            arg Θ(w + ib) = −π w b/(2KK') + arg ϑ2(β − iα|q'), arg Θ(K + w + ib) = −π w b/(2KK')
//                            + arg ϑ3(β − iα|q'), α = πw/(2K'), β = πb/(2K') (the Gaussian factor's phase is linear).
// Per argument: one sincos (K ≤ K') or one exp (K > K'), a few multiply-adds and an atan2.
#pragma once
#include "rigiddyn/exact/elliptic.hpp"

#include <array>

namespace rigiddyn {

class ThirdKindTheta {
 public:
  // Whether the series apply: n < 0, 0 < m, kc > 0 and K ≤ kMaxQuarterPeriod (beyond it, kc < ~1e-110, the
  // transformed series' scaled terms would leave the double range; elliptic_f_pi_reduced serves there).
  static bool applies(double n, const EllipticParameter& p);
  static constexpr double kMaxQuarterPeriod = 256.0;

  // n < 0 and p with applies(n, p); pi_complete = Π(n|m) (complete_ellippi). Throws std::invalid_argument
  // where the series do not apply.
  ThirdKindTheta(double n, const EllipticParameter& p, double pi_complete);

  // The reduced third-kind integral of elliptic_f_pi_reduced at the reduced argument w (|w| ≤ 3K/4):
  // Π(am w, n|m) for an even quarter, Π(am(K + w), n|m) − Π(n|m) for an odd one. Error a few eps times
  // Π(n|m)(1 + |w|/K), relative to the integral's own scale also where it is small (−n large);
  // tests/cpp/test_exact_third_kind_theta.cpp compares it with the Carlson form and mpmath.
  double reduced(double w, bool odd_quarter) const;

  // The same as slope() w + scale() (linear + atan2(im, re)): the argument of Θ(w + ib) (even quarter) or
  // Θ(K + w + ib) (odd) as a part linear in w (rad) and a point (re, im) of magnitude O(1) off the negative real
  // axis (re > 0, but for the series about the zero in an even quarter, whose point lies below the real axis), so
  // that |atan2(im, re)| < π and the half angle is continuous in w, for a caller that needs e^(i arg) rather than
  // the angle (the torque-free body: S times the coefficient of Π in its
  // precession angle is ±1, so the angle's half-angle rotor follows without an atan2).
  struct Phase {
    double linear;
    double re;
    double im;
  };
  Phase phase(double w, bool odd_quarter) const;
  double slope() const { return slope_; }  // Π(n|m)/K
  double scale() const { return scale_; }  // S

 private:
  enum class Series { q_about_b, q_about_zero, transformed };  // the three series above, in their order
  static constexpr int kMaxTerms = 8;
  void init_q_about_b(double K, double K_prime, double b, double eps_b);
  void init_q_about_zero(double K, double K_prime, double eps_b);
  void init_transformed(double K, double K_prime, double b, double eps_b);
  Phase phase_about_b(double w, bool odd_quarter) const;  // at w ≥ 0
  Phase phase_about_zero(double w, bool odd_quarter) const;
  Phase phase_transformed(double w, bool odd_quarter) const;

  double slope_;        // Π(n|m)/K
  double scale_;        // S
  Series series_;
  double x_per_w_;      // π/K (q about b), π/(2K) (q about the zero) or α per w, π/(2K') (transformed)
  double linear_arg_;   // transformed: the Gaussian factor's phase per w, −π b/(2KK')
  int terms_;           // the orders kept (each term below 2^−80 of the sum's scale beyond)
  // q about b: 2 q^(j²) cosh(j y) and −2 q^(j²) sinh(j y), signed as the series, at j = 1..terms_ (index j − 1);
  // q about the zero: ϑ1's and ϑ2's q^(j² + j) cosh((2j + 1)e) and q^(j² + j) sinh((2j + 1)e), e = πε/(2K),
  // signed, in units of the leading cosh e, at j = 0..terms_; transformed: cos and sin of (2j + 1)β (ϑ2, j = 0..terms_) and of 2jβ (ϑ3, j = 1..terms_)
  std::array<double, kMaxTerms + 1> even_re_{}, even_im_{}, odd_re_{}, odd_im_{};
  // transformed: q'^(2j) (ϑ2's growing ratio) and q'^(2j − 1) (ϑ3's), j = 1..terms_ (index j − 1)
  std::array<double, kMaxTerms> even_ratio_{}, odd_ratio_{};
};

}  // namespace rigiddyn
