// The duplication sequence of Carlson's R_F and R_J, shared by the public integrals (carlson.cpp) and
// the elliptic functions (elliptic.cpp). Private to the exact layer.
//
// The arguments come with their square roots, which the first duplication step uses as given: a
// caller that knows √x (for instance |cn| when x = cn²) keeps full precision where x itself would
// underflow. R_J's first term 6 R_C(1, 1 + e_0)/d_0 is returned in pieces, because d_0 (a product of
// three root sums) can underflow where R_J times the caller's weight is representable.
#pragma once

namespace rigiddyn::carlson {

// x, y, z >= 0 (at most one zero), at most 4, with sx = √x, ... (sx > 0 where x may have underflowed
// to 0 but √x has not); for R_J, p 4^p_offset > 0 with p <= 2^402 and sp = √p (p_offset >= 0: a p
// too large for one scale with x, y, z).
struct Arguments {
  double x, y, z, p;
  double sx, sy, sz, sp;
  int p_offset;
};

// R_F = rf; R_J = 2^rj_exponent rj_rest + 6 rc0/(d0[0] d0[1] d0[2]) with d0 = (√p + √x, √p + √y,
// √p + √z) (rc0 = 0 and d0 = 1 when the series holds without a duplication step or p_offset > 0);
// rj_exponent = −2 p_offset plus the exponent of the unit in which the later terms were summed (0 unless
// they exceed the double range in these scaled units).
struct Duplication {
  double rf;
  double rj_rest;
  int rj_exponent;
  double rc0;
  double d0[3];
};

// R_F alone (rj_rest, rc0 and d0 are 0).
Duplication duplicate_rf(const Arguments& a);
// R_F and R_J from one duplication sequence (R_F's mean follows the same λ as R_J's).
Duplication duplicate_rf_rj(const Arguments& a);

}  // namespace rigiddyn::carlson
