// simulate and step (simulate/simulate.hpp): a step that crosses a switch time of the load schedule
// is split there, so every method keeps its order; a switch on the step grid makes
// no sub-step; the monitor stops a run; a recording larger than the memory is refused.
#include <gtest/gtest.h>

#include "test_inputs.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

const RigidBody kFullBody(2.0, Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal().toDenseMatrix());

RigidBodyState initial_state() {
  RigidBodyState s;
  s.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1.0, -1.0, 2.0).normalized()));
  s.v_W = Eigen::Vector3d(0.2, 0.0, -0.1);
  s.w_B = Eigen::Vector3d(0.3, 1.0, 0.2);
  return s;
}

// A body-fixed couple and force on for t in [t_start, t_end) [s].
using test::window;

// Every method that steps (Method::exact evaluates a closed form for torque-free bodies only).
std::vector<Method> finite_order_methods() {
  std::vector<Method> out;
  for (const MethodInfo& info : method_table()) {
    if (info.order > 0) out.push_back(info.method);
  }
  return out;
}

// Record i of a trajectory as a state.
RigidBodyState record(const Trajectory& tr, std::size_t i) {
  RigidBodyState s;
  s.p_W = Eigen::Map<const Eigen::Vector3d>(tr.p_W.data() + 3 * i);
  s.q_WB = Eigen::Quaterniond(Eigen::Map<const Eigen::Vector4d>(tr.q_WB.data() + 4 * i));
  s.v_W = Eigen::Map<const Eigen::Vector3d>(tr.v_W.data() + 3 * i);
  s.w_B = Eigen::Map<const Eigen::Vector3d>(tr.w_B.data() + 3 * i);
  return s;
}

// Largest difference of attitude (geodesic angle [rad]) and of p, v, w.
double difference(const RigidBodyState& a, const RigidBodyState& b) {
  return std::max({a.q_WB.angularDistance(b.q_WB), (a.p_W - b.p_W).norm(), (a.v_W - b.v_W).norm(),
                   (a.w_B - b.w_B).norm()});
}

TEST(Simulate, AStepAcrossASwitchIsTwoStepsMeetingThere) {
  // the couple starts at s = 0.1234 inside step 13 (0.12 -> 0.13): simulate's step 13 must be one
  // step from t_12 to s without it and one from s to t_13 with it
  const double s = 0.1234;
  for (const Method method : finite_order_methods()) {
    SimulationOptions o;
    o.method = method;
    o.dt = 0.01;
    o.steps = 20;
    o.loads = {window(s, 1.0)};
    const Trajectory run = simulate(kFullBody, initial_state(), o);
    SimulationOptions piece = o;
    piece.t0 = 12.0 * o.dt;  // the grid time t_12 as simulate computes it
    piece.dt = s - piece.t0;
    const RigidBodyState at_switch = step(kFullBody, record(run, 12), piece);
    piece.t0 = s;
    piece.dt = 13.0 * o.dt - s;
    const RigidBodyState after = step(kFullBody, at_switch, piece);
    // the same sub-steps from the same state, but for step()'s normalisation of q (one rounding,
    // carried through two steps of size <= 0.01 at |w| ~ 1: a few eps)
    EXPECT_LE(difference(after, record(run, 13)), 1e-14) << method_info(method).name;
    // and the switch matters: without the split the couple would start at 0.13 (a 6e-3 s shift)
    piece.t0 = 12.0 * o.dt;
    piece.dt = o.dt;
    piece.loads = {window(0.13, 1.0)};
    EXPECT_GT(difference(step(kFullBody, record(run, 12), piece), record(run, 13)), 1e-5) << method_info(method).name;
  }
}

TEST(Simulate, ASwitchOnTheStepGridMakesNoSubStep) {
  // 3 * 0.1 = 0.30000000000000004: t_start = 0.3 lies an ulp before the grid time t_3, and acts from
  // step 4 on exactly as t_start = t_3 does (no sub-step of round-off length)
  SimulationOptions o;
  o.method = Method::rk4;
  o.dt = 0.1;
  o.steps = 8;
  o.loads = {window(0.3, 0.7)};
  const Trajectory a = simulate(kFullBody, initial_state(), o);
  o.loads = {window(3.0 * 0.1, 7.0 * 0.1)};
  const Trajectory b = simulate(kFullBody, initial_state(), o);
  EXPECT_EQ(a.q_WB, b.q_WB);
  EXPECT_EQ(a.w_B, b.w_B);
  EXPECT_EQ(a.p_W, b.p_W);
}

// Error at t = 3 s of `method` at dt = 3 / n under a couple on from 0.5 s to 2 s, against rkmk4 at
// dt = 5e-4 (which divides the switch times: exact switching with or without splitting; its error,
// ~(5e-4 |w|)^4, is below 1e-12 here).
double error_at_horizon(Method method, int n) {
  SimulationOptions o;
  o.loads = {window(0.5, 2.0)};
  o.method = Method::rkmk4;
  o.dt = 5e-4;
  o.steps = 6000;
  o.record_every = o.steps;
  const RigidBodyState reference = record(simulate(kFullBody, initial_state(), o), 1);
  o.method = method;
  o.dt = 3.0 / n;
  o.steps = n;
  o.record_every = n;
  return difference(record(simulate(kFullBody, initial_state(), o), 1), reference);
}

TEST(Simulate, EveryMethodKeepsItsOrderWithLoadsSwitchingInsideSteps) {
  // n = 77 2^k steps over 3 s: 0.5 / dt = 77 2^k / 6 and 2 / dt = 77 2^k / 1.5 are never integers
  for (const Method method : finite_order_methods()) {
    const int order = method_info(method).order;
    const int k0 = order == 1 ? 3 : 0;  // first-order methods reach their asymptotic range later
    std::vector<double> slopes;
    double previous = error_at_horizon(method, 77 << k0);
    for (int k = k0 + 1; k <= k0 + 3; ++k) {
      const double error = error_at_horizon(method, 77 << k);
      slopes.push_back(std::log2(previous / error));
      previous = error;
    }
    // in the asymptotic range the slopes settle (consecutive ones agree to 10 %, as tradeoff's
    // ORDER_AGREEMENT asks) and their deviation from the order shrinks like dt (the next term of the
    // error expansion is O(dt) relative), so the last deviation is about the last change of slope
    // (2x margin, + 0.02 for the reference's error at the smallest errors, ~1e-9 against < 1e-12)
    const double change = std::abs(slopes[2] - slopes[1]);
    EXPECT_LE(change, 0.1 * order) << method_info(method).name << ": slopes " << slopes[0] << ", " << slopes[1]
                                   << ", " << slopes[2];
    EXPECT_NEAR(slopes[2], order, 2.0 * change + 0.02) << method_info(method).name << ": slopes " << slopes[0]
                                                       << ", " << slopes[1] << ", " << slopes[2];
  }
}

TEST(Simulate, StepOverAWindowedLoadSplitsItsStep) {
  // step() from t = 0.12 over 0.01 with the couple starting at 0.1234 equals simulate's step 13
  SimulationOptions o;
  o.method = Method::rkmk4;
  o.dt = 0.01;
  o.steps = 13;
  o.record_every = 1;
  o.loads = {window(0.1234, 1.0)};
  const Trajectory run = simulate(kFullBody, initial_state(), o);
  SimulationOptions one = o;
  one.t0 = 12.0 * o.dt;
  // the same sub-steps, but for step()'s normalisation of q (one rounding): a few eps
  EXPECT_LE(difference(step(kFullBody, record(run, 12), one), record(run, 13)), 1e-14);
}

TEST(Simulate, MonitorSeesTheStepsAndStopsTheRun) {
  SimulationOptions o;
  o.method = Method::rk4;
  o.dt = 1e-3;
  o.steps = 100000;
  o.record_every = 1000;
  std::vector<std::int64_t> seen;
  o.monitor = [&seen](std::int64_t steps_done) {
    seen.push_back(steps_done);
    return steps_done >= 20000;
  };
  const Trajectory run = simulate(kFullBody, initial_state(), o);
  EXPECT_TRUE(run.interrupted);
  // the first call after the first step, then at the pace of the wall clock (monitor_pace.hpp): steps that
  // only grow, the last at the stop
  ASSERT_GE(seen.size(), 2u);
  EXPECT_EQ(seen.front(), 1);
  for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_GT(seen[i], seen[i - 1]);
  EXPECT_GE(seen.back(), 20000);
  EXPECT_LT(seen.back(), o.steps);
  // the records so far: steps 0, 1000, ... up to the stop
  EXPECT_EQ(run.size(), static_cast<std::size_t>(seen.back() / 1000 + 1));
  // the exact method evaluates only the records: the monitor at records, after the first one
  o.method = Method::exact;
  seen.clear();
  const Trajectory exact = simulate(kFullBody, RigidBodyState{}, o);
  EXPECT_TRUE(exact.interrupted);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.front(), 1000);
  for (std::int64_t steps_done : seen) EXPECT_EQ(steps_done % 1000, 0);
  EXPECT_GE(seen.back(), 20000);
  EXPECT_EQ(exact.size(), static_cast<std::size_t>(seen.back() / 1000 + 1));
  // a monitor that never stops changes nothing
  o.method = Method::rk4;
  o.monitor = [](std::int64_t) { return false; };
  const Trajectory whole = simulate(kFullBody, initial_state(), o);
  o.monitor = nullptr;
  const Trajectory plain = simulate(kFullBody, initial_state(), o);
  EXPECT_FALSE(whole.interrupted);
  EXPECT_EQ(whole.q_WB, plain.q_WB);
  EXPECT_EQ(whole.size(), 101u);
}

// A monitor that never stops changes no bit of a run, in any method, wherever the wall clock puts its calls: a
// kick-drift-kick method's merged kicks (run_loop.hpp, merged_steps) run on across a call (its first calls come
// after steps 1, 3, 7, ..., inside the first record interval), so that the run does not depend on the machine's speed.
TEST(Simulate, AMonitorThatNeverStopsChangesNoBit) {
  SimulationOptions o;
  o.dt = 1e-3;
  o.steps = 20000;
  o.record_every = 5000;
  o.gravity_W = standard_gravity();
  AppliedLoad load{Eigen::Vector3d(0.3, -0.1, 0.2), Eigen::Vector3d(0.02, 0.01, -0.03), Frame::world};
  load.t_end = 7.3004;  // a switch inside a step of the second record interval: the merged steps close before it
  o.loads = {load};
  for (const MethodInfo& info : method_table()) {
    if (info.method == Method::exact) continue;  // it has no kick (the loads above are not its case either)
    SCOPED_TRACE(info.name);
    o.method = info.method;
    o.monitor = [](std::int64_t) { return false; };
    const Trajectory monitored = simulate(kFullBody, initial_state(), o);
    o.monitor = nullptr;
    const Trajectory plain = simulate(kFullBody, initial_state(), o);
    EXPECT_EQ(monitored.p_W, plain.p_W);
    EXPECT_EQ(monitored.q_WB, plain.q_WB);
    EXPECT_EQ(monitored.v_W, plain.v_W);
    EXPECT_EQ(monitored.w_B, plain.w_B);
    EXPECT_EQ(monitored.work, plain.work);
  }
}

TEST(Simulate, ExactMethodRecordsTheSameSteps) {
  SimulationOptions o;
  o.method = Method::exact;
  o.dt = 0.1;
  o.steps = 10;
  o.record_every = 3;
  o.t0 = 1.0;
  const Trajectory run = simulate(kFullBody, initial_state(), o);
  // steps 0, 3, 6, 9 and the last, 10
  const std::vector<double> expected{1.0, 1.0 + 3 * 0.1, 1.0 + 6 * 0.1, 1.0 + 9 * 0.1, 1.0 + 10 * 0.1};
  ASSERT_EQ(run.t.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_DOUBLE_EQ(run.t[i], expected[i]);
}

TEST(Simulate, RecordingLargerThanTheMemoryIsRefused) {
  SimulationOptions o;
  // 2^50 + 2 records of a rigid body without elements, 16 + 20 doubles each (simulate_scene.cpp,
  // reserved_scene_simulation): 3.24e17 bytes, which no machine has
  o.steps = std::int64_t{1} << 50;
  o.record_every = 1;
  try {
    simulate(kFullBody, initial_state(), o);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("record_every: expected a recording that fits in the memory available", 0), 0u) << what;
    EXPECT_NE(what.find("which would need 324 PB"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace rigiddyn
