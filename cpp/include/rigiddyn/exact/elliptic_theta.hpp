// Jacobi's elliptic functions and the third-kind integral Π(am u, n|m) of one (m, n) at many arguments, from theta
// series: per argument one sincos or one exp and a few multiply-adds, instead of the argument halving of
// jacobi_ellipj_reduced and a Carlson duplication sequence (elliptic.hpp), for a closed form evaluated at many times.
//
// Jacobi's functions are quotients of theta functions of ζ = πu/(2K) with the nome q = e^(−πK'/K), K' = K(1 − m)
// (DLMF 22.2.4–6):
//   sn u = ϑ3(0) ϑ1(ζ)/(ϑ2(0) ϑ4(ζ)),   cn u = ϑ4(0) ϑ2(ζ)/(ϑ2(0) ϑ4(ζ)),   dn u = ϑ4(0) ϑ3(ζ)/(ϑ3(0) ϑ4(ζ)).
// For the third kind, with n = m sn²(a|m), Jacobi's integral Π_J(u, a) = u Z(a) + ½ ln(Θ(u − a)/Θ(u + a)) (Whittaker
// & Watson, §22.74) and Π(am u, n|m) = u + sn a/(cn a dn a) Π_J(u, a), Θ(u) = ϑ4(πu/(2K)). For n < 0 the point
// a = i b is imaginary (sn(ib|m) = i sc(b|1 − m), DLMF 22.6.iv): b = F(φ_b|1 − m) with sin² φ_b = −n/(m − n), and
// the logarithm is −2i arg Θ(u + ib) (Θ has real coefficients), so that
//   Π(am u, n|m) = (Π(n|m)/K) u + S arg Θ(u + i b),   S = √(−n/((m − n)(1 − n))),
// the linear part following from Π(am(u + 2K)) = Π(am u) + 2Π(n|m). Θ has no zero on the line u + ib (its zeros
// lie at iK' + 2jK, b < K') and is positive at u = 0, so the continuous argument is the principal one; it is odd
// in u. The quarter-shifted argument Θ(K + z) = ϑ3(πz/(2K)) serves the odd quarters.
//
// Three forms of the series, chosen per (m, n), each converging at least as e^(−π) per order and keeping the
// argument's precision where Θ(u + ib) passes close to its zero iK' (b → K', where −n/m is large and the integral
// is a steep step of height ~π/√(−n)):
//   K ≤ K', b ≤ ε = K' − b:  the series in q: Θ(w + ib) = 1 + 2 Σ_{j≥1} (∓1)^j q^(j²) [cosh(jy) cos(2jζ) −
//                            i sinh(jy) sin(2jζ)], y = πb/K ((−1)^j for Θ, 1 for the shifted ϑ3);
//   K ≤ K', b > ε:           the series in q about the zero, Θ(z + iK') = i q^(−1/4) e^(−iπz/(2K)) ϑ1(πz/(2K))
//                            (DLMF 20.2.12): arg Θ(w + ib) = π/2 − ζ + arg ϑ1(ζ − iπε/(2K)), arg Θ(K + w + ib) =
//                            −ζ + arg ϑ2(ζ − iπε/(2K));
//   K > K':                  Jacobi's imaginary transformation (DLMF §20.7(viii)) to the nome q' = e^(−πK/K'),
//                            under which ϑ1, ϑ2, ϑ3, ϑ4 of ζ become −i ϑ1, ϑ4, ϑ3, ϑ2 of ζK/(iK') times a common
//                            factor √(K/K') e^(−ζ²K/(πK')), whose phase is linear in w and which Jacobi's quotients
//                            cancel: with α = πw/(2K') and β = πb/(2K'),
//                              sn = [ϑ3(0)/ϑ4(0)] (−i ϑ1(iα))/ϑ2(iα),  cn = [ϑ2(0)/ϑ4(0)] ϑ4(iα)/ϑ2(iα),
//                              dn = [ϑ2(0)/ϑ3(0)] ϑ3(iα)/ϑ2(iα)  (all of nome q', hyperbolic functions of α),
//                              arg Θ(w + ib) = −π w b/(2KK') + arg ϑ2(β − iα),
//                              arg Θ(K + w + ib) = −π w b/(2KK') + arg ϑ3(β − iα).
#pragma once
#include "rigiddyn/exact/elliptic.hpp"

#include <array>

namespace rigiddyn {

class EllipticTheta {
 public:
  // Whether the series apply: n < 0, 0 < m, kc > 0 and K ≤ kMaxQuarterPeriod (beyond it, kc < ~1e-110, the
  // transformed series' scaled terms would leave the double range; elliptic.hpp's functions serve there).
  static bool applies(double n, const EllipticParameter& p);
  static constexpr double kMaxQuarterPeriod = 256.0;

  // n < 0 and p with applies(n, p); pi_complete = Π(n|m) (complete_ellippi). Throws std::invalid_argument
  // where the series do not apply.
  EllipticTheta(double n, const EllipticParameter& p, double pi_complete);

  // The argument of Θ(w + ib) (even quarter) or Θ(K + w + ib) (odd) as a part linear in w (rad) and a point
  // (re, im) of magnitude O(1) off the negative real axis (re > 0, but for the series about the zero in an even
  // quarter, whose point lies below the real axis), so that |atan2(im, re)| < π and the half angle is continuous
  // in w, for a caller that needs e^(i arg) rather than the angle (the torque-free body: S times the coefficient of
  // Π in its precession angle is ±1, so the angle's half-angle rotor follows without an atan2).
  struct Phase {
    double linear;
    double re;
    double im;
  };
  // At a reduced argument w (|w| ≤ 3K/4): sn, cn, dn of w, each to a few eps relative (as jacobi_ellipj_reduced),
  // and the phase of the quarter's Θ.
  struct Evaluation {
    JacobiSnCnDn f;
    Phase phase;
  };
  Evaluation evaluate(double w, bool odd_quarter) const;

  // The reduced third-kind integral of elliptic_f_pi_reduced at w (|w| ≤ 3K/4): Π(am w, n|m) for an even quarter,
  // Π(am(K + w), n|m) − Π(n|m) for an odd one, (Π/K) w + S (linear + atan2(im, re)). Error a few eps times
  // Π(n|m)(1 + |w|/K), relative to the integral's own scale also where it is small (−n large);
  // tests/cpp/test_exact_elliptic_theta.cpp compares it with the Carlson form and mpmath.
  double reduced(double w, bool odd_quarter) const;
  double slope() const { return slope_; }  // Π(n|m)/K
  double scale() const { return scale_; }  // S

 private:
  enum class Series { q_about_b, q_about_zero, transformed };  // the three forms above, in their order
  static constexpr int kMaxTerms = 8;
  void init_q_about_b(double K, double K_prime, double b, double eps_b);
  void init_q_about_zero(double K, double K_prime, double eps_b);
  void init_jacobi_in_q(double R);
  void init_transformed(double K, double K_prime, double b, double eps_b);
  Evaluation evaluate_in_q(double w, bool odd_quarter) const;  // at w ≥ 0
  Evaluation evaluate_transformed(double w, bool odd_quarter) const;

  double slope_;        // Π(n|m)/K
  double scale_;        // S
  Series series_;
  double angle_per_w_;  // ζ per w, π/(2K) (series in q), or α per w, π/(2K') (transformed)
  double linear_arg_;   // transformed: the common factor's phase per w, −π b/(2KK')
  int terms_;           // the orders kept (each term below 2^−80 of its sum's scale beyond)
  double sn_scale_, cn_scale_, dn_scale_;  // the quotients of theta constants in sn, cn, dn
  // series in q: Jacobi's sums' coefficients at j = 0..terms_: (−1)^j q^(j² + j) (ϑ1), q^(j² + j) (ϑ2),
  // 2 q^(j²) (ϑ3) and 2 (−1)^j q^(j²) (ϑ4) (both 0 at j = 0: the leading 1 is added apart), ϑ1 and ϑ2 without
  // their common factor 2 q^(1/4)
  std::array<double, kMaxTerms + 1> theta1_{}, theta2_{}, theta3_{}, theta4_{};
  // the phase's coefficients: q about b: 2 q^(j²) cosh(j y) and −2 q^(j²) sinh(j y), signed as the series, at
  // j = 1..terms_ (index j); q about the zero: ϑ1's and ϑ2's q^(j² + j) cosh((2j + 1)e) and q^(j² + j)
  // sinh((2j + 1)e), e = πε/(2K), signed, in units of the leading cosh e, at j = 0..terms_; transformed: cos and sin
  // of (2j + 1)β (ϑ2, j = 0..terms_) and of 2jβ (ϑ3, j = 1..terms_)
  std::array<double, kMaxTerms + 1> even_re_{}, even_im_{}, odd_re_{}, odd_im_{};
  // transformed: q'^(2j) (the growing ratio of the sums with q'^(j² + j)) and q'^(2j − 1) (those with q'^(j²)),
  // j = 1..terms_ (index j − 1)
  std::array<double, kMaxTerms> even_ratio_{}, odd_ratio_{};
};

}  // namespace rigiddyn
