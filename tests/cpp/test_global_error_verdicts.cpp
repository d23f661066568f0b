// The verdict texts of the global error estimate (simulate/global_error.hpp) where the order check fails: each record
// says "not asymptotic: observed order <o> where <p> is expected (<quantity>)" with its own observed order printed as
// printf's "%.2g" prints it, however many records share a text (orders that print alike), at orders that lie a
// rounding error from the tie between two printed values, and in every decade.
#include "one_body_error_records.hpp"
#include "rigiddyn/simulate/global_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

// Three runs (at h, 2h, 4h) that agree on every quantity but the position of their one body: at record i the run at 2h
// is off the run at h by delta and the run at 4h off the run at 2h by 2^x_i delta, so that the record's observed order
// is x_i up to the rounding of the differences (the orders are chosen outside the window of an order 4 method).
class RunsWithOrders {
 public:
  static constexpr double h = 0.01, delta = 0x1p-10;  // delta: 1 + delta exact

  RunsWithOrders(const std::vector<double>& orders, int factor) : run_(h) {
    for (const double order : orders) {
      const double ratio = std::exp2(order);
      const double p = factor == 1 ? 1.0 : factor == 2 ? 1.0 + delta : 1.0 + delta + ratio * delta;
      run_.push_back({0.0, 0.0, 0.0, 1.0}, {p, 0.0, 0.0});
    }
  }
  ErrorRecords records() const { return run_.records(); }

 private:
  test::OneBodyErrorRecords run_;
};

std::string printed(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%.2g", x);
  return text;
}

TEST(GlobalErrorVerdicts, EachRecordPrintsItsOwnObservedOrder) {
  // orders on both sides of the ties between two printed values (5.15 between 5.1 and 5.2, 0.355 between 0.35 and
  // 0.36, 12.5 between 12 and 13), at the decades' ends (0.0995, 0.996, 9.96, 99.4, 99.6), negative, and repeated
  std::vector<double> orders;
  for (const double tie : {5.15, 5.25, 6.05, 7.95, 9.95, 0.355, 0.995, 12.5, 13.5, 99.5, -0.355, -2.45, 3.35}) {
    for (const double offset : {0.0, 1e-15, -1e-15, 1e-9, -1e-9, 1e-7, -1e-7, 1e-3, -1e-3}) {
      orders.push_back(tie + offset);
    }
  }
  for (const double x : {0.0995, 0.996, 9.96, 99.4, 99.6, 150.0, 0.05, -0.05, 5.12, 5.13, 5.12, 1.0, 10.0, 0.1}) {
    orders.push_back(x);
  }
  // every other decade printf's "%.2g" reaches here (its exponent form below 1e-4), ties and ends among them
  for (const double x : {0.0125, 0.01249, 0.001, 0.00995, 0.00155, -0.0455, 0.000125, 1.25e-5, 9.96e-5, 1e-4,
                         3.5e-7, -3.5e-7, 0.0, 0.0}) {
    orders.push_back(x);
  }
  const RunsWithOrders h(orders, 1), h2(orders, 2), h4(orders, 4);
  SimulationOptions o;
  o.dt = RunsWithOrders::h, o.record_every = 4, o.steps = 4 * static_cast<std::int64_t>(orders.size() - 1);
  const GlobalErrorEstimate e = estimate_global_error(h.records(), h2.records(), h4.records(), o, 4);
  ASSERT_EQ(e.verdict.size(), orders.size());
  for (std::size_t i = 0; i < orders.size(); ++i) {
    // the observed order is the one asked for up to the differences' rounding: |Δ log2 r| ≤ ~2^-40 here
    ASSERT_NEAR(e.observed_order[i], orders[i], 1e-9 * (1.0 + std::abs(orders[i]))) << "record " << i;
    EXPECT_EQ(e.verdict[i],
              "not asymptotic: observed order " + printed(e.observed_order[i]) + " where 4 is expected (position)")
        << "record " << i << ", order " << orders[i];
  }
}

}  // namespace
}  // namespace rigiddyn
