// Jacobi's elliptic functions and the third-kind integral by theta series (elliptic_theta.hpp) against the
// argument halving (jacobi_ellipj_reduced) and Carlson's form (elliptic_f_pi_reduced), themselves checked against
// Boost and mpmath, and against mpmath, over the three forms of the series (in q about b and about the zero, and
// transformed), both quarters, and parameters from m = 1e-280 to 1 − m = 1e-100 and n from −1e-12 to −1e12.
#include "test_numbers.hpp"
#include "rigiddyn/exact/elliptic.hpp"
#include "rigiddyn/exact/elliptic_theta.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rigiddyn {
namespace {

using rigiddyn::test::kEps;

// (m, kc) from kc, with m = 1 − kc² formed as the free body forms it (m from kc where kc² ≤ 1/2)
EllipticParameter parameter_from_kc(double kc) {
  return elliptic_parameter_kc(1.0 - kc * kc, kc, std::log(kc));
}

EllipticParameter parameter_from_m(double m) { return elliptic_parameter(m, 1.0 - m); }

// The bound of both forms' difference: each is a handful of roundings of quantities bounded by the integral's
// own scale Π(n|m)(1 + |w|/K) (the theta form: its linear part (Π/K) w, three roundings, and S arg Θ with
// arg Θ from at most 9 terms of the sum, each rounded to ~2 eps of it, S |arg Θ| ≤ Π(n|m)), so 16 eps each,
// 32 eps both: a bound relative to Π, which is small (~π/(2√−n)) where −n is large.
double difference_bound(double w, double pi_complete, double K) {
  return 32.0 * kEps * pi_complete * (1.0 + std::abs(w) / K);
}

// Jacobi's functions: each form a few roundings relative (the theta quotients: sums of at most 9 terms whose
// leading term dominates, each rounded to ~2 eps of the sum; the halving: a few ulps, elliptic.hpp), 16 eps each,
// but for the theta form's angle πw/(2K) or πw/(2K'), rounded to eps of itself, which moves e^(−α) (the transformed
// cn and dn, ~e^−|w| in their tails) by eps |α| ≤ eps |w| relative: 32 eps (1 + |w|) for both
void expect_functions_match(const JacobiSnCnDn& theta, const JacobiSnCnDn& halving, double w, const std::string& what) {
  const double relative = 32.0 * kEps * (1.0 + std::abs(w));
  EXPECT_NEAR(theta.sn, halving.sn, relative * std::abs(halving.sn)) << what;
  EXPECT_NEAR(theta.cn, halving.cn, relative * std::abs(halving.cn)) << what;
  EXPECT_NEAR(theta.dn, halving.dn, relative * std::abs(halving.dn)) << what;
}

std::string describe(double n, const EllipticParameter& p, double w, bool odd) {
  std::ostringstream out;
  out.precision(17);
  out << "n = " << n << ", m = " << p.m << ", kc = " << p.kc << ", w = " << w << ", odd quarter " << odd;
  return out.str();
}

void expect_matches_carlson(double n, const EllipticParameter& p) {
  ASSERT_TRUE(EllipticTheta::applies(n, p)) << "n = " << n << ", m = " << p.m;
  const double pi_complete = complete_ellippi(n, p);
  const EllipticTheta theta(n, p, pi_complete);
  for (int i = -12; i <= 12; ++i) {
    const double w = 0.75 * p.K * i / 12.0;
    const JacobiSnCnDn f = jacobi_ellipj_reduced(w, p);
    for (bool odd : {false, true}) {
      const double carlson = elliptic_f_pi_reduced(f, odd, n, p).pi;
      EXPECT_NEAR(theta.reduced(w, odd), carlson, difference_bound(w, pi_complete, p.K)) << describe(n, p, w, odd);
      expect_functions_match(theta.evaluate(w, odd).f, f, w, describe(n, p, w, odd));
    }
  }
}

TEST(EllipticTheta, MatchesCarlsonBelowAndAboveKEqualsKPrime) {
  // K ≤ K' for m ≤ 1/2 (the series in q), K > K' above (the imaginary transformation)
  for (double m : {1e-280, 1e-30, 1e-6, 0.01, 0.1046, 0.3, 0.5, 0.5000001, 0.7, 0.9, 0.999}) {
    for (double n : {-1e-12, -1e-3, -0.2, -1.0, -3.0, -10.0, -1e3, -1e6, -1e12}) {
      expect_matches_carlson(n, parameter_from_m(m));
    }
  }
}

TEST(EllipticTheta, MatchesCarlsonNearTheSeparatrix) {
  // 1 − m down to 1e-100 (K ≈ 116), where the series in q would need hundreds of terms
  for (double kc : {1e-2, 7e-3, 1e-8, 1e-20, 1e-50}) {
    for (double n : {-1e-6, -0.5, -3.0, -1e4}) expect_matches_carlson(n, parameter_from_kc(kc));
  }
}

TEST(EllipticTheta, MatchesCarlsonAtRandomParameters) {
  // m = 10^−300..1 and 1 − m = 10^−100..1, n = −10^−12..−10^12, |w| ≤ 3K/4, either quarter
  std::mt19937_64 rng(20261205);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int checked = 0;
  for (int i = 0; i < 4000; ++i) {
    const double decades = -300.0 * uniform(rng) * uniform(rng);
    const EllipticParameter p = uniform(rng) < 0.5 ? parameter_from_m(std::pow(10.0, decades))
                                                   : parameter_from_kc(std::pow(10.0, decades / 6.0));
    const double n = -std::pow(10.0, 24.0 * uniform(rng) - 12.0);
    if (!EllipticTheta::applies(n, p)) continue;  // m/(m − n) below 2^−1000, or K > 256
    const double pi_complete = complete_ellippi(n, p);
    const EllipticTheta theta(n, p, pi_complete);
    const double w = (2.0 * uniform(rng) - 1.0) * 0.75 * p.K;
    const bool odd = uniform(rng) < 0.5;
    const JacobiSnCnDn f = jacobi_ellipj_reduced(w, p);
    const double carlson = elliptic_f_pi_reduced(f, odd, n, p).pi;
    ASSERT_NEAR(theta.reduced(w, odd), carlson, difference_bound(w, pi_complete, p.K)) << describe(n, p, w, odd);
    expect_functions_match(theta.evaluate(w, odd).f, f, w, describe(n, p, w, odd));
    ++checked;
  }
  EXPECT_GT(checked, 3000);  // the series apply to most of the sample
}

// Π(am u, n|m) for |u| ≤ K from mpmath at 40 digits:
//   python3 -c 'import mpmath as mp; mp.mp.dps = 40
//   for m, n, u in [(0.1046, -3, 0.7), (0.5, -0.2, -1.1), (0.99995, -3, 2.5), (1e-6, -3, 1.2)]:
//       m, n = mp.mpf(m), mp.mpf(n); print(mp.nstr(mp.ellippi(n, mp.asin(mp.ellipfun("sn", u, m=m)), m), 20))'
// (m and n the doubles shown, each |u| below K so that am u = asin sn u)
TEST(EllipticTheta, MatchesMpmath) {
  struct Reference {
    double m, n, u, pi;
  };
  constexpr Reference kReferences[] = {
      {0.1046, -3.0, 0.7, 0.51830815310932735575},
      {0.5, -0.2, -1.1, -1.0407921126926159258},
      {0.99995, -3.0, 2.5, 1.0759078989992601986},
      {1e-6, -3.0, 1.2, 0.68940051458716743961},
  };
  for (const Reference& r : kReferences) {
    const EllipticParameter p = parameter_from_m(r.m);
    const EllipticTheta theta(r.n, p, complete_ellippi(r.n, p));
    EXPECT_NEAR(theta.reduced(r.u, false), r.pi, difference_bound(r.u, complete_ellippi(r.n, p), p.K)) << "m = " << r.m;
  }
}

TEST(EllipticTheta, OddInTheArgumentAndZeroAtZero) {
  for (double m : {0.3, 0.7}) {  // the series in q (about the zero for n = −2) and the transformed one
    const EllipticParameter p = parameter_from_m(m);
    const EllipticTheta theta(-2.0, p, complete_ellippi(-2.0, p));
    for (bool odd : {false, true}) {
      EXPECT_EQ(theta.reduced(0.0, odd), 0.0);
      EXPECT_EQ(theta.reduced(-0.4, odd), -theta.reduced(0.4, odd));  // computed at |w|, signed after
      const JacobiSnCnDn at_zero = theta.evaluate(0.0, odd).f, minus = theta.evaluate(-0.4, odd).f,
                         plus = theta.evaluate(0.4, odd).f;
      EXPECT_EQ(at_zero.sn, 0.0);
      EXPECT_NEAR(at_zero.cn, 1.0, 4.0 * kEps);  // the quotient of a sum and its own value at 0: two roundings
      EXPECT_NEAR(at_zero.dn, 1.0, 4.0 * kEps);
      EXPECT_EQ(minus.sn, -plus.sn);
      EXPECT_EQ(minus.cn, plus.cn);
      EXPECT_EQ(minus.dn, plus.dn);
    }
  }
}

TEST(EllipticTheta, RefusesWhereTheSeriesDoNotApply) {
  const EllipticParameter p = parameter_from_m(0.5);
  EXPECT_FALSE(EllipticTheta::applies(0.5, p));   // n > 0
  EXPECT_FALSE(EllipticTheta::applies(0.0, p));
  EXPECT_FALSE(EllipticTheta::applies(-1.0, parameter_from_m(0.0)));
  EXPECT_FALSE(EllipticTheta::applies(-1.0, parameter_from_kc(1e-200)));  // K ≈ 462 > kMaxQuarterPeriod
  EXPECT_THROW(EllipticTheta(0.5, p, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace rigiddyn
