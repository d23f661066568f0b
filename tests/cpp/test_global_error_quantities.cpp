// The quantities whose estimate is reliable at a record (GlobalErrorEstimate::reliable_quantities,
// simulate/global_error.hpp): a record's verdict covers every quantity, and one quantity may still be reliable where
// another fails its order check: its own ratio r then lies in the narrower window [2^p / 1.25, 2^p · 1.25]; every
// quantity is reliable where the record is; none where a run of the estimate diverged. A run to a tolerance, whose
// certificate estimates its measure alone, refuses the records that judgement refuses on its low side
// (keep_low_orders_refused, simulate/tolerance.hpp).
#include "one_body_error_records.hpp"
#include "rigiddyn/simulate/global_error.hpp"
#include "rigiddyn/simulate/tolerance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace rigiddyn {
namespace {

// The observed ratios r of the attitude and of the position at one record.
struct Ratios {
  double attitude, position;
};

// Three runs (at h, 2h, 4h) of one body that agree on every quantity but its attitude (turned about z) and its
// position: at record i the run at 2h is off the run at h by delta and the run at 4h off the run at 2h by r_i delta,
// r_i of each quantity as given.
class RunsWithRatios {
 public:
  static constexpr double h = 0.01, delta = 0x1p-12;  // delta: 1 + delta exact

  RunsWithRatios(const std::vector<Ratios>& ratios, int factor) : run_(h) {
    for (const Ratios& r : ratios) {
      const auto off = [&](double ratio) { return factor == 1 ? 0.0 : factor == 2 ? delta : delta + ratio * delta; };
      const double half_angle = 0.5 * off(r.attitude);
      run_.push_back({0.0, 0.0, std::sin(half_angle), std::cos(half_angle)}, {1.0 + off(r.position), 0.0, 0.0});
    }
  }
  ErrorRecords records() const { return run_.records(); }

 private:
  test::OneBodyErrorRecords run_;
};

// The estimate of order 4 (2^p = 16) of runs whose records have the given ratios, of every quantity or of `only`;
// the first record (t = 0, every run alike) at round-off.
GlobalErrorEstimate estimate_of(const std::vector<Ratios>& ratios, std::size_t coarse_records = SIZE_MAX,
                                std::optional<ErrorMeasure> only = std::nullopt) {
  std::vector<Ratios> all{{16.0, 16.0}};
  all.insert(all.end(), ratios.begin(), ratios.end());
  const RunsWithRatios h(all, 1), h2(all, 2), h4(all, 4);
  ErrorRecords r2 = h2.records(), r4 = h4.records();
  r2.n = std::min(r2.n, coarse_records), r4.n = std::min(r4.n, coarse_records);
  SimulationOptions o;
  o.dt = RunsWithRatios::h, o.record_every = 4, o.steps = 4 * static_cast<std::int64_t>(all.size() - 1);
  return estimate_global_error(h.records(), r2, r4, o, 4, {}, only);
}

bool reliable_for(const GlobalErrorEstimate& e, std::size_t i, ErrorMeasure measure) {
  return (e.reliable_quantities.at(i) & measure_bit(measure)) != 0;
}

// the quantities every run agrees on: at round-off, reliable wherever the record is not blocked
constexpr ErrorMeasure agreed[] = {ErrorMeasure::angular_velocity, ErrorMeasure::velocity, ErrorMeasure::energy,
                                   ErrorMeasure::angular_momentum};

TEST(GlobalErrorQuantities, AQuantityInsideTheNarrowWindowIsReliableWhereAnotherFails) {
  // the attitude at order 5.5 (outside the record's window [16 / 1.5, 24]); the position at r = 16, at the narrow
  // window's ends (16 / 1.25 = 12.8 and 20, taken a little inside), and inside the record's window but outside the
  // narrow one (11 and 22.4)
  const std::vector<double> position = {16.0, 12.9, 19.9, 11.0, 22.4};
  std::vector<Ratios> ratios;
  for (const double r : position) ratios.push_back({std::exp2(5.5), r});
  const GlobalErrorEstimate e = estimate_of(ratios);
  ASSERT_EQ(e.reliable_quantities.size(), position.size() + 1);
  for (std::size_t k = 0; k < position.size(); ++k) {
    const std::size_t i = k + 1;
    EXPECT_EQ(e.verdict[i], "not asymptotic: observed order 5.5 where 4 is expected (attitude)") << "record " << i;
    EXPECT_FALSE(reliable_for(e, i, ErrorMeasure::attitude)) << "record " << i;
    EXPECT_EQ(reliable_for(e, i, ErrorMeasure::position), position[k] > 12.8 && position[k] < 20.0)
        << "record " << i << ", r " << position[k];
    for (const ErrorMeasure m : agreed) EXPECT_TRUE(reliable_for(e, i, m)) << "record " << i;
  }
}

TEST(GlobalErrorQuantities, EveryQuantityIsReliableWhereTheRecordIs) {
  // the position inside the record's window and outside the narrow one: reliable with its record
  const GlobalErrorEstimate e = estimate_of({{16.0, 22.4}, {17.0, 11.0}});
  for (std::size_t i = 0; i < e.verdict.size(); ++i) {
    EXPECT_EQ(e.verdict[i], "reliable") << "record " << i;
    EXPECT_EQ(e.reliable_quantities[i], every_measure) << "record " << i;
  }
}

TEST(GlobalErrorQuantities, NoQuantityIsReliableWhereARunOfTheEstimateDiverged) {
  // the runs at 2h and 4h stop after 2 records: the later records are blocked whatever their ratios
  const GlobalErrorEstimate e = estimate_of({{16.0, 16.0}, {16.0, 16.0}, {16.0, 16.0}}, 2);
  EXPECT_EQ(e.reliable_quantities[1], every_measure);
  for (std::size_t i = 2; i < e.verdict.size(); ++i) {
    EXPECT_EQ(e.verdict[i].rfind("step beyond the stability limit", 0), 0U) << e.verdict[i];
    EXPECT_EQ(e.reliable_quantities[i], 0) << "record " << i;
  }
}

TEST(GlobalErrorQuantities, TheRoundOffBoundIsReliableAndNoEstimateIsNot) {
  const RunsWithRatios h({{16.0, 16.0}, {16.0, 16.0}}, 1);
  SimulationOptions o;
  o.dt = RunsWithRatios::h, o.record_every = 4, o.steps = 4;
  EXPECT_EQ(round_off_estimate(h.records(), o).reliable_quantities, std::vector<std::uint8_t>(2, every_measure));
  EXPECT_EQ(no_estimate(3, 1, 4, "no estimate: a test").reliable_quantities, std::vector<std::uint8_t>(3, 0));
}

TEST(GlobalErrorQuantities, ACertificateRefusesALowOrderWhereAnotherQuantityFails) {
  // the attitude failing (order 5.5) or not (r = 16); the position alone inside the record's window at r = 11 (below
  // 16 / 1.25: refused where the attitude fails), 22.4 (above 16 · 1.25: an over-estimate, kept) and 16
  const std::vector<Ratios> ratios = {{std::exp2(5.5), 11.0}, {std::exp2(5.5), 22.4}, {std::exp2(5.5), 16.0},
                                      {16.0, 11.0}};
  const GlobalErrorEstimate all = estimate_of(ratios);
  GlobalErrorEstimate position = estimate_of(ratios, SIZE_MAX, ErrorMeasure::position);
  for (std::size_t i = 0; i < position.verdict.size(); ++i) ASSERT_EQ(position.verdict[i], "reliable") << i;
  keep_low_orders_refused(all, ErrorMeasure::position, position);
  EXPECT_EQ(position.verdict[1], "not asymptotic: observed order 3.5 where 4 is expected (position, below 2^p / 1.25 "
                                 "where another quantity of its record fails its check)");
  EXPECT_EQ(position.reliable_quantities[1], 0);
  for (const std::size_t i : {0, 2, 3, 4}) EXPECT_EQ(position.verdict[i], "reliable") << "record " << i;
  // refused unless its estimate is negligible (at most the tolerance / 16)
  const double epsilon = position.position[1];
  EXPECT_EQ(first_unreliable(position, ErrorMeasure::position, 15.0 * epsilon), 1U);
  EXPECT_EQ(first_unreliable(position, ErrorMeasure::position, 17.0 * epsilon), position.verdict.size());
}

}  // namespace
}  // namespace rigiddyn
