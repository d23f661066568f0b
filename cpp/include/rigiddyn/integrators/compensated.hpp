// Compensated arithmetic: sums of squares carried as an unevaluated sum hi + lo, accurate to a few ε²
// relative, so that a correction of size ~ε (the normalisation of a quaternion that is unit to
// round-off, splitting_parts.hpp) is computed to ~ε² instead of being rounded to 0 or ±ε.
//
// Error-free transformations (Dekker, Numer. Math. 18, 1971; Ogita, Rump & Oishi, SIAM J. Sci.
// Comput. 26, 2005, Algorithms 3.1–3.2): a·b = p + e and a + b = s + e exactly, p and s the
// rounded results (for finite results without underflow).
#pragma once
#include "rigiddyn/always_inline.hpp"

#include <cmath>

namespace rigiddyn {

// a·b = p + e, p = fl(a·b).
RIGIDDYN_ALWAYS_INLINE void two_product(double a, double b, double& p, double& e) {
  p = a * b;
#ifdef __FMA__
  e = std::fma(a, b, -p);
#else  // Veltkamp's split into 26-bit halves, whose products are exact (no FMA to contract them)
  const auto split = [](double x, double& hi, double& lo) {
    const double c = 134217729.0 * x;  // (2^27 + 1) x
    hi = c - (c - x);
    lo = x - hi;
  };
  double a_hi, a_lo, b_hi, b_lo;
  split(a, a_hi, a_lo);
  split(b, b_hi, b_lo);
  e = ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo;
#endif
}

// a + b = s + e, s = fl(a + b) (Knuth's TwoSum: any order of magnitude).
RIGIDDYN_ALWAYS_INLINE void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double z = s - a;
  e = (a - (s - z)) + (b - z);
}

// Σ x_k² (k < n) as hi + lo, accurate to a few ε² relative: every square and every partial sum
// carries its rounding error along (Ogita, Rump & Oishi, Algorithm 5.3, Dot2).
template <int n>
RIGIDDYN_ALWAYS_INLINE void sum_of_squares(const double* x, double& hi, double& lo) {
  hi = 0.0, lo = 0.0;
  for (int k = 0; k < n; ++k) {
    double p, e, t;
    two_product(x[k], x[k], p, e);
    two_sum(hi, p, hi, t);
    lo += t + e;
  }
}

}  // namespace rigiddyn
