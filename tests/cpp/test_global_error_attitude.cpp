// The attitude's global error estimate (simulate/global_error.hpp) reads the recorded quaternions as integrated: its
// angles are those of the unit quaternions whatever the recorded norms and signs (a run's quaternion drifts off the
// unit sphere between its projections, and q and −q are one attitude).
#include "one_body_error_records.hpp"
#include "rigiddyn/simulate/global_error.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace rigiddyn {
namespace {

// A run of one body turning about z: at record i its attitude is the turn by angle(i) [rad], recorded as the
// quaternion (x, y, z, w) scaled by `scale` (negative: the quaternion's opposite); every other quantity agrees.
template <class Angle>
test::OneBodyErrorRecords turning_run(std::size_t n, double dt, double scale, Angle angle) {
  test::OneBodyErrorRecords run(dt);
  for (std::size_t i = 0; i < n; ++i) {
    const double half = 0.5 * angle(i);
    run.push_back({0.0, 0.0, scale * std::sin(half), scale * std::cos(half)}, {0.0, 0.0, 0.0});
  }
  return run;
}

TEST(GlobalErrorAttitude, TheEstimateIsTheSameForQuaternionsOfAnyNormAndSign) {
  // an order-4 error C t h^4 in the angle: the run at 2h is off the run at h by 15 e_h(t), the run at 4h off the run
  // at 2h by 16 · 15 e_h(t) (ratio 2^4 exactly), so that the estimate is e_h(t) = δ t / t_end
  constexpr std::size_t n = 9;
  constexpr double dt = 0.01, delta = 1e-4;
  const auto error_at = [&](std::size_t i) { return delta * static_cast<double>(i) / static_cast<double>(n - 1); };
  const auto answer = [&](std::size_t i) { return 0.3 * static_cast<double>(i); };
  const auto twice = [&](std::size_t i) { return answer(i) + 15.0 * error_at(i); };
  const auto four_times = [&](std::size_t i) { return twice(i) + 16.0 * 15.0 * error_at(i); };
  SimulationOptions o;
  o.dt = dt, o.record_every = 4, o.steps = 4 * static_cast<std::int64_t>(n - 1);
  const auto unit = turning_run(n, dt, 1.0, answer), unit2 = turning_run(n, dt, 1.0, twice),
             unit4 = turning_run(n, dt, 1.0, four_times);
  const GlobalErrorEstimate reference = estimate_global_error(unit.records(), unit2.records(), unit4.records(), o, 4);
  // norms off 1 as far as a run between projections never drifts, and the opposite quaternion in the run at 2h
  const auto h = turning_run(n, dt, 1.0 + 1e-3, answer), h2 = turning_run(n, dt, -(1.0 - 2e-3), twice),
             h4 = turning_run(n, dt, 1.0 + 5e-4, four_times);
  const GlobalErrorEstimate e = estimate_global_error(h.records(), h2.records(), h4.records(), o, 4);
  ASSERT_EQ(e.attitude.size(), n);
  for (std::size_t i = 1; i < n; ++i) {
    EXPECT_EQ(reference.verdict[i], "reliable") << "record " << i;
    EXPECT_EQ(e.verdict[i], reference.verdict[i]) << "record " << i;
    // the angles between the runs (15 e_h ≥ 1.9e-4 rad) are read from quaternion products whose parts round at
    // 2^-52 of |q_a| |q_b| ~ 1: a relative rounding of at most ~1e-11 of the angle, in both estimates alike
    EXPECT_NEAR(e.attitude[i], error_at(i), 1e-10 * error_at(i)) << "record " << i;
    EXPECT_NEAR(e.attitude[i], reference.attitude[i], 1e-10 * reference.attitude[i]) << "record " << i;
  }
}

}  // namespace
}  // namespace rigiddyn
