// Jacobi elliptic functions and elliptic integrals, accurate up to the parameter m = 1.
//
// Conventions (DLMF 22 and 19, as mpmath and SciPy): the parameter m = k² ∈ [0, 1] and its
// complement mc = 1 − m are BOTH passed in, because near m = 1 the complement cannot be recovered
// from m (1 − m is known only to ~1e-16 absolutely). Callers that know mc accurately (the free rigid
// body computes it without cancellation) pass it; others pass mc = 1 − m.
//   K(m)            = R_F(0, mc, 1)                                   (DLMF 19.25.1)
//   Π(n|m)          = R_F(0, mc, 1) + (n/3) R_J(0, mc, 1, 1 − n)      (DLMF 19.25.2), n < 1
//   Π(am u, n|m)    = ∫₀^u dv / (1 − n sn²(v|m))  (the Legendre Π(φ, n|m) at φ = am u, DLMF 19.2.7)
// Carlson's R_F and R_J: duplication algorithm (cpp/src/exact/carlson.cpp).
#pragma once

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
  double mc;  // complement 1 − m, in [0, 1]
  double K;   // quarter period K(m) = R_F(0, mc, 1); +inf when mc = 0
};

// Checks 0 ≤ m ≤ 1, 0 ≤ mc ≤ 1 and |m + mc − 1| ≤ 4 eps (std::invalid_argument otherwise) and
// computes K.
EllipticParameter elliptic_parameter(double m, double mc);

// Carlson's symmetric integrals (DLMF 19.16.1-2): R_F(x, y, z) for x, y, z ≥ 0 with at most one
// zero; R_J(x, y, z, p) for x, y, z ≥ 0 with at most one zero and p > 0.
// Throw std::invalid_argument outside these domains.
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

// Complete elliptic integral of the third kind Π(n|m) for n < 1, mc > 0.
double ellippi(double n, double m, double mc);

// Jacobi elliptic functions of u (any finite real) for the parameter (m, mc). Absolute error a few
// ulps for |u| ≲ K, growing only as eps·|u| for large |u| (the reduction u mod 4K). mc = 0 gives
// (tanh u, sech u, sech u).
JacobiSnCnDn jacobi_ellipj(double u, double m, double mc);
JacobiSnCnDn jacobi_ellipj(double u, const EllipticParameter& p);

// Π(am u, n|m) for any real u and n < 1, using the quasi-periodicity
// Π(am(v + 2jK), n|m) = Π(am v, n|m) + 2j Π(n|m) after reducing u to v ∈ [−K, K].
double ellippi_am(double u, double n, double m, double mc);
double ellippi_am(double u, double n, const EllipticParameter& p);

// Π(am v, n|m) from the elliptic functions of v, valid for v ∈ [−K, K] (|am v| ≤ π/2), n < 1:
// Π = sn R_F(cn², dn², 1) + (n/3) sn³ R_J(cn², dn², 1, 1 − n sn²)   (DLMF 19.25.14).
double ellippi_sncndn(const JacobiSnCnDn& f, double n);

// Both integrals of v ∈ [−K, K] from its elliptic functions, for the cost of Π alone:
// F = v = sn R_F(cn², dn², 1) and Π(am v, n|m) as in ellippi_sncndn.
struct EllipticFPi {
  double f;
  double pi;
};
EllipticFPi elliptic_f_pi_sncndn(const JacobiSnCnDn& f, double n);

}  // namespace rigiddyn
