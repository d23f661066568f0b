// Jacobi elliptic functions and elliptic integrals, accurate up to the parameter m = 1.
//
// Conventions (DLMF 22 and 19, as mpmath and SciPy): the parameter m = k² ∈ [0, 1] and its
// complement mc = 1 − m are BOTH passed in, because near m = 1 the complement cannot be recovered
// from m (1 − m is known only to ~1e-16 absolutely). Callers that know mc accurately (the free rigid
// body computes it without cancellation) pass it; others pass mc = 1 − m. The complementary modulus
// kc = k' = √mc is kept as well: it stays representable (and K = ln(4/kc) + ... accurate) where mc
// underflows.
//   K(m)            = R_F(0, mc, 1)                                   (DLMF 19.25.1)
//   Π(n|m)          = R_F(0, mc, 1) + (n/3) R_J(0, mc, 1, 1 − n)      (DLMF 19.25.2), n < 1
//   Π(am u, n|m)    = ∫₀^u dv / (1 − n sn²(v|m))  (the Legendre Π(φ, n|m) at φ = am u, DLMF 19.2.7)
// Arguments are reduced by quarter periods, u = l K + w with l an integer and |w| <= K/2, where sn, cn
// and dn of w are computed to a few ulps RELATIVE (also cn, dn ~ √kc at w = K/2), and the functions
// and Π of u follow from those of w (DLMF Table 22.4.3; Π below), so that nothing cancels near u = ±K.
// Carlson's R_F and R_J: duplication algorithm (cpp/src/exact/carlson.cpp).
#pragma once
#include <cmath>

namespace rigiddyn {

// sn(u|m), cn(u|m), dn(u|m).
struct JacobiSnCnDn {
  double sn;
  double cn;
  double dn;
};

// The parameter of the elliptic functions with its complement and quarter period, checked once.
struct EllipticParameter {
  double m;   // parameter m = k², in [0, 1]
  double mc;  // complement 1 − m, in [0, 1] (may underflow to 0 while kc > 0)
  double kc;  // complementary modulus k' = √mc, in [0, 1]
  double K;   // quarter period K(m) = R_F(0, mc, 1); +inf when kc = 0
};

// Checks 0 ≤ m ≤ 1, 0 ≤ mc ≤ 1 and |m + mc − 1| ≤ 4 eps (std::invalid_argument otherwise) and
// computes kc = √mc and K.
EllipticParameter elliptic_parameter(double m, double mc);

// The same from kc = √(1 − m) and its natural logarithm log_kc (−inf when kc = 0), for callers that
// know k' where mc = k'² (or k' itself) underflows: K = ln(4/k') + (k'²/4)(ln(4/k') − 1) (DLMF 19.12.1)
// for k' < 2^−27, else π/(2 AGM(1, k')). Checks as elliptic_parameter (|m + kc² − 1| ≤ 4 eps).
EllipticParameter elliptic_parameter_kc(double m, double kc, double log_kc);

// Carlson's symmetric integrals (DLMF 19.16.1-2): R_F(x, y, z) for x, y, z ≥ 0 with at most one
// zero; R_J(x, y, z, p) for x, y, z ≥ 0 with at most one zero and p > 0. Finite arguments of any
// magnitude (a few ulps relative, also for arguments spanning 1e-300..1e300). Throw
// std::invalid_argument outside these domains (naming the argument); R_J is +inf where it exceeds the
// double range (R_J ~ 1/√(x y z p) for tiny arguments; R_F never does), and rounds to 0 (or a
// subnormal) below it.
double elliprf(double x, double y, double z);
double elliprj(double x, double y, double z, double p);

// R_F(x, y, z) and R_J(x, y, z, p) together, for the cost of R_J alone (one duplication sequence).
struct CarlsonRfRj {
  double rf;
  double rj;
};
CarlsonRfRj elliprf_elliprj(double x, double y, double z, double p);

// Complete elliptic integral of the first kind K(m), computed from mc (so that K ≈ ½ ln(16/mc)
// keeps full relative precision as m → 1). mc = 0 gives +inf.
double ellipk(double m, double mc);

// Complete elliptic integral of the third kind Π(n|m) for n < 1, mc > 0 (std::invalid_argument
// otherwise). A few ulps for n <= 0.9 (the free body's n is negative); the odd half below cancels as
// n → 1, a relative error of ~eps/(1 − n) (DLMF 19.7.8, Π(n) + Π(m/n) = K + (π/2)√(n/((1 − n)(n − m))),
// would move the loss to n near m; not done).
double ellippi(double n, double m, double mc);
// Π(n|m) for a checked parameter with kc > 0 and n < 1 (unchecked):
// Π(n|m) = Π(am(K/2)) + ∫_{K/2}^{K}, both halves below at w = K/2, where (sn, cn, dn) =
// (1, √kc, √kc·√(1 + kc))/√(1 + kc); for kc < 2^−60 the limit (K + √−n atan √−n)/(1 − n) (n ≤ 0) or
// (K − √n atanh √n)/(1 − n) (n > 0), exact to O(kc K).
double complete_ellippi(double n, const EllipticParameter& p);

// Jacobi elliptic functions of u (any finite real) for the parameter (m, mc). Absolute error a few
// ulps for |u| ≲ K, growing only as eps·|u| for large |u| (the reduction u mod K). kc = 0 gives
// (tanh u, sech u, sech u).
JacobiSnCnDn jacobi_ellipj(double u, double m, double mc);
JacobiSnCnDn jacobi_ellipj(double u, const EllipticParameter& p);

// sn, cn, dn of a reduced argument |w| ≤ K/2 (up to 3K/4 is fine, where a reduction of a huge u leaves it),
// kc > 0: each to a few ulps relative (cn, dn >= √kc/√2 at K/2).
JacobiSnCnDn jacobi_ellipj_reduced(double w, const EllipticParameter& p);
// l mod 4 ∈ {0, 1, 2, 3} of an integer-valued l, exactly for any double (l/4 and its floor are exact).
inline double quarter_of(double l) { return l - 4.0 * std::floor(0.25 * l); }

// The functions of l K + w (l an integer-valued double) from those of w (DLMF Table 22.4.3):
// l ≡ 1 (mod 4): (cd w, −kc sd w, kc nd w); l ≡ 2: (−sn w, −cn w, dn w); l ≡ 3: (−cd w, kc sd w, kc nd w).
JacobiSnCnDn jacobi_shift_quarter_periods(const JacobiSnCnDn& f_w, double l, double kc);

// F and Π of a reduced argument from its elliptic functions f_w (|w| ≤ K/2), n < 1:
// f = w = sn R_F(cn², dn², 1) (DLMF 19.25.5) and, for an even quarter (odd_quarter false),
// pi = Π(am w, n|m) = sn R_F + (n/3) sn³ R_J(cn², dn², 1, 1 − n sn²) (DLMF 19.25.14); for an odd quarter
// pi = Π(am(K + w), n|m) − Π(n|m) = ∫₀^w dv/(1 − n cd² v)
//    = sn/(1 − n) [R_F − n mc sn² R_J(cn², dn², 1, (dn² − n cn²)/(1 − n))/(3(1 − n))]
// (from 1 − n cd² = (1 − n)(1 − n' sn²)/dn², n' = (m − n)/(1 − n), and dn² = (m/n')(1 − n' sn²) + 1 − m/n'),
// so that Π(am(l K + w), n|m) = l Π(n|m) + pi (Π(φ + π) = Π(φ) + 2Π(n|m) and am(u + 2K) = am u + π).
struct EllipticFPi {
  double f;
  double pi;
};
EllipticFPi elliptic_f_pi_reduced(const JacobiSnCnDn& f_w, bool odd_quarter, double n, const EllipticParameter& p);

// Π(am u, n|m) for any finite u and n < 1: l Π(n|m) + the reduced part above, u = l K + w; ±inf where it
// exceeds the double range (|u| near it).
double ellippi_am(double u, double n, double m, double mc);
double ellippi_am(double u, double n, const EllipticParameter& p);
// Π(am u, n|1) = ∫₀^u dv/(1 − n tanh² v) = (u + a atan(a tanh u))/(1 − n), a = √−n (n ≤ 0), or
// (u − b atanh(b tanh u))/(1 − n), b = √n (0 < n < 1): the separatrix m = 1 in elementary form.
double ellippi_am_separatrix(double u, double n);

}  // namespace rigiddyn
