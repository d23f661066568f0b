// The accuracy check at the end of a run (simulate/accuracy_check.hpp): a balance that closes_under_any_estimate
// closes with every estimate check_accuracy may be given (reliable or not, any bounds), with the same verdicts; one
// that does not may still close under a reliable estimate with large bounds.
#include <gtest/gtest.h>

#include "rigiddyn/simulate/accuracy_check.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

constexpr double level = default_accuracy_level;

// A balance of n records whose every residual is `fraction` of the least allowance estimate_floor · level · scale
// + round-off (scales and round-offs drawn from `random`), with the momentum balances applicable or not.
RunBalance balance_at(double fraction, std::size_t n, bool momentum_applies, std::mt19937& random) {
  std::uniform_real_distribution<double> scale(0.1, 10.0), round_off(0.0, 1e-12);
  RunBalance b(n);
  for (std::size_t q = 0; q < balance_quantity_count; ++q) {
    for (std::size_t i = 0; i < n; ++i) {
      b.scale(q)[i] = scale(random);
      b.round_off(q)[i] = round_off(random);
      const double least = estimate_floor * level * b.scale(q)[i] + b.round_off(q)[i];
      b.residual(q)[i] = (i % 2 == 0 ? 1.0 : -1.0) * fraction * least;
    }
    b.verdict[q] = q == 0 || momentum_applies ? "closed" : "not applicable: a planar body's plane takes forces";
  }
  b.about = "W's origin";
  return b;
}

// An estimate of n records of one body: every verdict `verdict`, every error `size`.
GlobalErrorEstimate estimate_of(std::size_t n, const std::string& verdict, double size) {
  GlobalErrorEstimate e;
  e.order = 4, e.bodies = 1;
  for (auto* v : {&e.attitude, &e.angular_velocity, &e.position, &e.velocity, &e.energy, &e.angular_momentum}) {
    v->assign(n, size);
  }
  e.observed_order.assign(n, 4.0);
  e.verdict.assign(n, verdict);
  return e;
}

// check_accuracy of a copy of b with estimate e (null: none), and bounds `bound` on every residual
std::pair<std::string, RunBalance> checked(const RunBalance& b, const GlobalErrorEstimate* e, double bound) {
  RunBalance copy = b;
  BalanceBounds bounds;
  for (auto& column : bounds) column.assign(b.size(), bound);
  const std::vector<double> t(b.size(), 1.0);
  const std::string message = check_accuracy(copy, AccuracyCheck{e, &bounds, level, &t, "rk4", 0.01});
  return {message, copy};
}

TEST(AccuracyCheck, ABalanceThatClosesUnderAnyEstimateClosesWithEveryOne) {
  std::mt19937 random(7);
  for (const bool momentum : {true, false}) {
    const RunBalance b = balance_at(0.999, 12, momentum, random);
    ASSERT_TRUE(closes_under_any_estimate(b, level));
    const GlobalErrorEstimate reliable_small = estimate_of(12, "reliable", 0.0);
    const GlobalErrorEstimate reliable_large = estimate_of(12, "reliable", 1e3);
    const GlobalErrorEstimate unreliable = estimate_of(12, "not asymptotic: observed order 1.3 where 4 is expected", 0.0);
    for (const auto& [e, bound] : {std::pair<const GlobalErrorEstimate*, double>{nullptr, 0.0},
                                   {&reliable_small, 0.0}, {&reliable_large, 1e3}, {&unreliable, 0.0}}) {
      const auto [message, verdicts] = checked(b, e, bound);
      EXPECT_EQ(message, "");
      EXPECT_EQ(verdicts.verdict, b.verdict);
    }
  }
}

TEST(AccuracyCheck, ABalanceBeyondTheLeastAllowanceIsNotSaidToClose) {
  std::mt19937 random(11);
  RunBalance b = balance_at(0.5, 8, true, random);
  b.residual(2)[5] = 1.01 * (estimate_floor * level * b.scale(2)[5] + b.round_off(2)[5]);
  EXPECT_FALSE(closes_under_any_estimate(b, level));
  // it closes without an estimate (within level · scale) and with a reliable one that allows more; a reliable
  // estimate of zero error leaves the least allowance, which the residual exceeds
  EXPECT_EQ(checked(b, nullptr, 0.0).first, "");
  const GlobalErrorEstimate zero = estimate_of(8, "reliable", 0.0);
  EXPECT_NE(checked(b, &zero, 0.0).first, "");
}

TEST(AccuracyCheck, NonFiniteResidualsAreSkippedAsTheCheckSkipsThem) {
  std::mt19937 random(3);
  RunBalance b = balance_at(0.5, 4, true, random);
  b.residual(0)[1] = std::numeric_limits<double>::infinity();
  b.residual(1)[2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(closes_under_any_estimate(b, level));
  EXPECT_EQ(checked(b, nullptr, 0.0).first, "");
}

}  // namespace
}  // namespace rigiddyn
