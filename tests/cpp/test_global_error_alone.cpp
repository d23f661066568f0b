// The estimate of every quantity and that of one measure alone from one pass (estimate_global_error_and_alone,
// simulate/global_error.hpp) are the two estimates made apart, estimate_global_error without and with `only`, bit for
// bit: every value, observed order, verdict and reliable quantity, for each measure, where the order checks hold, where
// they fail and where a coarse run goes beyond the stability limit.
#include "linked_bodies.hpp"
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/scene_order.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"
#include "rigiddyn/simulate/global_error.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace rigiddyn {
namespace {

bool same_doubles(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

void expect_same_estimate(const GlobalErrorEstimate& a, const GlobalErrorEstimate& b) {
  EXPECT_EQ(a.order, b.order);
  for (const auto field : {&GlobalErrorEstimate::attitude, &GlobalErrorEstimate::angular_velocity,
                           &GlobalErrorEstimate::position, &GlobalErrorEstimate::velocity, &GlobalErrorEstimate::energy,
                           &GlobalErrorEstimate::angular_momentum, &GlobalErrorEstimate::observed_order}) {
    EXPECT_TRUE(same_doubles(a.*field, b.*field));
  }
  EXPECT_EQ(a.reliable_quantities, b.reliable_quantities);
  ASSERT_EQ(a.verdict.size(), b.verdict.size());
  for (std::size_t i = 0; i < a.verdict.size(); ++i) EXPECT_EQ(a.verdict[i], b.verdict[i]) << "record " << i;
}

TEST(GlobalErrorAlone, EveryQuantityAndOneAloneFromOnePassAreTheEstimatesMadeApart) {
  const auto [scene, states] = test::linked_bodies();
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  const int order = scene_order(compiled);
  // rk4 resolving the springs' motion (checks in their window), at a coarse step (checks failing) and beyond rk4's
  // stability limit at 4 dt (the run at 4h diverges); every step recorded (three of four interpolated) and every 4th
  std::vector<std::string> verdicts_seen;
  for (const auto& [dt, record_every] : {std::pair<double, std::int64_t>{0.01, 1}, {0.01, 4}, {0.08, 1}, {0.2, 4}}) {
    SCOPED_TRACE("dt " + std::to_string(dt) + ", record_every " + std::to_string(record_every));
    SimulationOptions o;
    o.method = Method::rk4, o.dt = dt, o.steps = static_cast<std::int64_t>(8.0 / dt), o.record_every = record_every;
    const SceneSimulation answer = simulate(compiled, states, o);
    const auto coarse = [&](int factor) {
      SimulationOptions c = coarse_options(o, factor);
      c.estimate_records = true;
      return simulate(compiled, states, c);
    };
    const SceneSimulation twice = coarse(2), four_times = coarse(4);
    const ErrorRecords h = answer_records(answer, o, order);
    const ErrorRecords h2 = coarse_records(twice), h4 = coarse_records(four_times);
    const GlobalErrorEstimate all = estimate_global_error(h, h2, h4, o, order);
    for (const std::string& v : all.verdict.texts()) verdicts_seen.push_back(v);
    for (const ErrorMeasure measure : {ErrorMeasure::attitude, ErrorMeasure::angular_velocity, ErrorMeasure::position,
                                       ErrorMeasure::velocity, ErrorMeasure::energy, ErrorMeasure::angular_momentum}) {
      SCOPED_TRACE("measure " + std::to_string(static_cast<int>(measure)));
      const auto [both_all, both_alone] = estimate_global_error_and_alone(h, h2, h4, o, order, measure);
      expect_same_estimate(both_all, all);
      expect_same_estimate(both_alone, estimate_global_error(h, h2, h4, o, order, {}, measure));
    }
  }
  // the cases above reach the verdicts they are meant to (else the comparison checks less than it says)
  const auto seen = [&](const std::string& start) {
    for (const std::string& v : verdicts_seen) {
      if (v.rfind(start, 0) == 0) return true;
    }
    return false;
  };
  EXPECT_TRUE(seen("reliable"));
  EXPECT_TRUE(seen("not asymptotic"));
  EXPECT_TRUE(seen("step beyond the stability limit"));
}

}  // namespace
}  // namespace rigiddyn
