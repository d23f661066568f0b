// MonitorPace (simulate/monitor_pace.hpp): the steps between two monitor calls follow the wall time the steps
// take, so that a run answers its monitor as fast for an expensive step as for a cheap one.
#include "rigiddyn/simulate/monitor_pace.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <thread>
#include <vector>

namespace rigiddyn {
namespace {

const auto never_stop = [](std::int64_t) { return false; };

TEST(MonitorPace, StartsWithOneStep) { EXPECT_EQ(MonitorPace().interval(), 1); }

TEST(MonitorPace, StepsSlowerThanThePeriodGetACallAfterEachStep) {
  // each interval's steps take 2 periods (a sleep lasts at least that long): the interval stays one step
  MonitorPace pace;
  const auto two_periods = std::chrono::duration<double>(2.0 * monitor_period_seconds);
  for (int k = 0; k < 5; ++k) {
    std::this_thread::sleep_for(two_periods);
    pace.check(never_stop, k);
    EXPECT_EQ(pace.interval(), 1);
  }
}

TEST(MonitorPace, CheapStepsGrowTheIntervalAndSlowOnesShrinkIt) {
  MonitorPace pace;
  // intervals of no steps at all take far less than half the period: each check doubles the interval (40 checks:
  // a growth unless every one of them was preempted for half a period)
  for (int k = 0; k < 40; ++k) pace.check(never_stop, k);
  const std::int64_t grown = pace.interval();
  EXPECT_GT(grown, 1);
  EXPECT_LE(grown, MonitorPace::max_interval);
  // then steps that took 4 periods: the interval shrinks to at most a quarter of itself
  std::this_thread::sleep_for(std::chrono::duration<double>(4.0 * monitor_period_seconds));
  pace.check(never_stop, 40);
  EXPECT_LE(pace.interval(), std::max<std::int64_t>(1, grown / 4));
}

TEST(MonitorPace, TheCallsOwnTimeIsNotTheSteps) {
  // a monitor that takes 2 periods (a Python callback, a wait for the GIL) around steps that take none: the
  // interval still grows
  MonitorPace pace;
  const auto slow_monitor = [](std::int64_t) {
    std::this_thread::sleep_for(std::chrono::duration<double>(2.0 * monitor_period_seconds));
    return false;
  };
  for (int k = 0; k < 5; ++k) pace.check(slow_monitor, k);
  EXPECT_GT(pace.interval(), 1);
}

TEST(MonitorPace, ReturnsWhatTheMonitorReturnsWithTheStepsDone) {
  MonitorPace pace;
  std::vector<std::int64_t> seen;
  EXPECT_TRUE(pace.check([&](std::int64_t steps_done) { return seen.push_back(steps_done), true; }, 7));
  EXPECT_FALSE(pace.check([&](std::int64_t steps_done) { return seen.push_back(steps_done), false; }, 9));
  EXPECT_EQ(seen, (std::vector<std::int64_t>{7, 9}));
}

}  // namespace
}  // namespace rigiddyn
