// simulate_batch (batch/simulate_batch.hpp) and its thread pool (batch/parallel_for.hpp): a batch equals N
// serial simulate calls bitwise (each body kind and a scene), whatever the thread count; a diverged sample
// stops alone, NaN-padded; per-sample bodies, dt, gravity and loads are each the serial run with that
// parameter; bad input is refused before any thread starts; a failing sample is reported by index (the
// lowest); the monitor stops every sample.
#include <gtest/gtest.h>

#include "invalid_argument_message.hpp"
#include "rigiddyn/batch/parallel_for.hpp"
#include "rigiddyn/batch/simulate_batch.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

#include <atomic>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace rigiddyn {
namespace {

// Whether the `count` doubles at a and b have the same bits (NaN padding included).
bool same_bits(const double* a, const double* b, std::size_t count) {
  return std::memcmp(a, b, count * sizeof(double)) == 0;
}

// Rows [i*n, i*n + run rows) of `batch` (width values a row) are `run` bitwise; the rest are NaN.
void expect_sample_rows(const std::vector<double>& batch, std::size_t i, std::size_t n, std::size_t width,
                        const std::vector<double>& run, const char* name) {
  SCOPED_TRACE(name);
  const std::size_t rows = run.size() / width;
  ASSERT_LE(rows, n);
  EXPECT_TRUE(same_bits(batch.data() + i * n * width, run.data(), rows * width));
  for (std::size_t k = (i * n + rows) * width; k < (i + 1) * n * width; ++k) EXPECT_TRUE(std::isnan(batch[k]));
}

// Sample i of the batch is the serial run `run` bitwise (its rows, filled, diverged, unconverged steps).
void expect_sample(const BatchTrajectory& b, std::size_t i, const Trajectory& run) {
  SCOPED_TRACE("sample " + std::to_string(i));
  const std::size_t n = b.records;
  expect_sample_rows(b.t, i, n, 1, run.t, "t");
  expect_sample_rows(b.p_W, i, n, 3, run.p_W, "p_W");
  expect_sample_rows(b.q_WB, i, n, 4, run.q_WB, "q_WB");
  expect_sample_rows(b.v_W, i, n, 3, run.v_W, "v_W");
  expect_sample_rows(b.w_B, i, n, 3, run.w_B, "w_B");
  expect_sample_rows(b.kinetic_energy, i, n, 1, run.kinetic_energy, "kinetic_energy");
  expect_sample_rows(b.total_energy, i, n, 1, run.total_energy, "total_energy");
  expect_sample_rows(b.angular_momentum_norm, i, n, 1, run.angular_momentum_norm, "angular_momentum_norm");
  expect_sample_rows(b.quaternion_norm_error, i, n, 1, run.quaternion_norm_error, "quaternion_norm_error");
  expect_sample_rows(b.work, i, n, 1, run.work, "work");
  EXPECT_EQ(b.filled[i], static_cast<std::int64_t>(run.size()));
  EXPECT_EQ(b.diverged[i] != 0, run.diverged);
  EXPECT_EQ(b.unconverged_steps[i], run.unconverged_steps);
}

// Two batches hold the same bits in every array.
void expect_same_batch(const BatchTrajectory& a, const BatchTrajectory& b) {
  ASSERT_EQ(a.samples, b.samples);
  ASSERT_EQ(a.records, b.records);
  for (auto member : {&BatchTrajectory::t, &BatchTrajectory::p_W, &BatchTrajectory::q_WB, &BatchTrajectory::v_W,
                      &BatchTrajectory::w_B, &BatchTrajectory::kinetic_energy, &BatchTrajectory::total_energy,
                      &BatchTrajectory::angular_momentum_norm, &BatchTrajectory::quaternion_norm_error,
                      &BatchTrajectory::work}) {
    ASSERT_EQ((a.*member).size(), (b.*member).size());
    EXPECT_TRUE(same_bits((a.*member).data(), (b.*member).data(), (a.*member).size()));
  }
  EXPECT_EQ(a.filled, b.filled);
  EXPECT_EQ(a.diverged, b.diverged);
  EXPECT_EQ(a.unconverged_steps, b.unconverged_steps);
}

// N tumbling states, sample i spinning at a rate that grows with i (all different).
std::vector<RigidBodyState> tumbling_states(std::size_t n) {
  std::vector<RigidBodyState> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double s = 1.0 + 0.1 * static_cast<double>(i);
    out[i].p_W = Eigen::Vector3d(0.5 * s, -1.0, 2.0);
    out[i].q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * s, Eigen::Vector3d(1.0, -1.0, 2.0).normalized()));
    out[i].v_W = Eigen::Vector3d(0.2, 0.1 * s, -0.1);
    out[i].w_B = Eigen::Vector3d(0.3 * s, 1.0, -0.2 * s);
  }
  return out;
}

SimulationOptions rk4_options(std::int64_t steps, std::int64_t record_every) {
  SimulationOptions o;
  o.method = Method::rk4;
  o.dt = 0.01;
  o.steps = steps;
  o.record_every = record_every;
  return o;
}

const RigidBody kBody(2.0, Eigen::Vector3d(1.0, 2.0, 3.0));

// ---- parallel_for -------------------------------------------------------------------------------------

TEST(ParallelFor, RunsEveryTaskOnceOnAnyThreadCount) {
  for (int threads : {1, 2, 3, 7}) {
    std::vector<std::atomic<int>> runs(23);
    parallel_for(runs.size(), threads, [&](std::size_t k, int worker) {
      EXPECT_GE(worker, 0);
      EXPECT_LT(worker, threads);
      runs[k].fetch_add(1);
    });
    for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
  }
}

TEST(ParallelFor, RethrowsTheLowestTaskFailureAfterRunningTheOthers) {
  std::vector<std::atomic<int>> runs(20);
  try {
    parallel_for(runs.size(), 3, [&](std::size_t k, int) {
      runs[k].fetch_add(1);
      if (k == 13 || k == 5) throw std::invalid_argument("task " + std::to_string(k));
    });
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "task 5");
  }
  for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
}

// The calling thread, out of tasks, calls `wait` while a helper still works: a helper's task that needs a
// wait() call to end ends (if the calling thread takes every task itself, no helper task needs it).
TEST(ParallelFor, CallingThreadCallsWaitWhileHelpersWork) {
  std::atomic<bool> waited{false};
  parallel_for(
      2, 2,
      [&](std::size_t, int worker) {
        while (worker != 0 && !waited.load()) std::this_thread::yield();
      },
      [&] { waited.store(true); }, 1);
  SUCCEED();
}

TEST(ParallelFor, RefusesThreadsBelowOne) {
  bool ran = false;
  for (int threads : {0, -1}) {
    EXPECT_THROW(parallel_for(3, threads, [&](std::size_t, int) { ran = true; }), std::invalid_argument);
  }
  EXPECT_FALSE(ran);
  EXPECT_GE(default_thread_count(), 1);
}

// ---- the batch is N serial runs bitwise ------------------------------------------------------------

TEST(SimulateBatch, RigidBodyBatchIsSerialRunsBitwiseOnAnyThreadCount) {
  const auto initial = tumbling_states(11);
  const SimulationOptions o = rk4_options(50, 3);  // 50 = 16·3 + 2: the last record off the stride
  const BatchTrajectory one = simulate_batch({kBody}, initial, o, {}, 1);
  ASSERT_EQ(one.records, batch_record_count(50, 3));
  for (std::size_t i = 0; i < initial.size(); ++i) expect_sample(one, i, simulate(kBody, initial[i], o));
  for (int threads : {2, 3, 7}) {
    SCOPED_TRACE(threads);
    expect_same_batch(simulate_batch({kBody}, initial, o, {}, threads), one);
  }
}

TEST(SimulateBatch, ParticleAndPlanarBatchesAreSerialRunsBitwise) {
  const SimulationOptions o = rk4_options(40, 7);
  std::vector<ParticleState> particles(5);
  std::vector<PlanarBodyState> planars(5);
  for (std::size_t i = 0; i < 5; ++i) {
    particles[i].p_W = Eigen::Vector3d(1.0, 0.1 * i, 0.0);
    particles[i].v_W = Eigen::Vector3d(0.0, 1.0, 0.5 * i);
    planars[i].p_W = Eigen::Vector2d(0.2 * i, 1.0);
    planars[i].theta = 0.1 * i;
    planars[i].v_W = Eigen::Vector2d(1.0, -0.5);
    planars[i].omega = 1.0 + i;
  }
  BatchParameters gravity;  // per-sample gravity, in the plane for the planar body
  for (std::size_t i = 0; i < 5; ++i) gravity.gravity_W.emplace_back(0.1 * i, -9.81, 0.0);
  const Particle particle(1.5);
  const PlanarBody planar(2.0, 0.3);
  const BatchTrajectory bp = simulate_batch({particle}, particles, o, gravity, 2);
  const BatchTrajectory bq = simulate_batch({planar}, planars, o, gravity, 2);
  for (std::size_t i = 0; i < 5; ++i) {
    SimulationOptions oi = o;
    oi.gravity_W = gravity.gravity_W[i];
    expect_sample(bp, i, simulate(particle, particles[i], oi));
    expect_sample(bq, i, simulate(planar, planars[i], oi));
  }
}

// Each per-sample parameter gives the serial run with that parameter (the others common).
TEST(SimulateBatch, PerSampleBodiesDtGravityAndLoadsAreTheSerialRuns) {
  const std::size_t n = 6;
  const auto initial = tumbling_states(n);
  SimulationOptions o = rk4_options(30, 4);
  o.gravity_W = Eigen::Vector3d(0.0, 0.0, -9.81);
  o.loads = {AppliedLoad{Eigen::Vector3d(0.1, 0.0, 0.0), Eigen::Vector3d(0.0, 0.2, 0.0), Frame::body}};
  std::vector<RigidBody> bodies;
  BatchParameters p;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = 1.0 + 0.25 * static_cast<double>(i);
    bodies.emplace_back(s, Eigen::Vector3d(1.0, 1.5, 2.0) * s);
    p.dt.push_back(0.01 * s);
    p.gravity_W.emplace_back(0.0, -s, -9.81);
    AppliedLoad window{Eigen::Vector3d(s, 0.0, 0.0), Eigen::Vector3d(0.0, 0.0, 0.1 * s), Frame::world};
    window.t_start = 0.05 * s, window.t_end = 0.2;  // a switch inside the run of most samples
    p.loads.push_back({window});
  }
  const BatchTrajectory b = simulate_batch(bodies, initial, o, p, 3);
  for (std::size_t i = 0; i < n; ++i) {
    SimulationOptions oi = o;
    oi.dt = p.dt[i], oi.gravity_W = p.gravity_W[i], oi.loads = p.loads[i];
    expect_sample(b, i, simulate(bodies[i], initial[i], oi));
  }
  // one parameter at a time: each vector alone per sample
  for (int which = 0; which < 4; ++which) {
    SCOPED_TRACE(which);
    BatchParameters one;
    if (which == 1) one.dt = p.dt;
    if (which == 2) one.gravity_W = p.gravity_W;
    if (which == 3) one.loads = p.loads;
    const BatchTrajectory bi = simulate_batch(which == 0 ? bodies : std::vector<RigidBody>{kBody}, initial, o, one, 2);
    for (std::size_t i = 0; i < n; ++i) {
      SimulationOptions oi = o;
      if (which == 1) oi.dt = p.dt[i];
      if (which == 2) oi.gravity_W = p.gravity_W[i];
      if (which == 3) oi.loads = p.loads[i];
      expect_sample(bi, i, simulate(which == 0 ? bodies[i] : kBody, initial[i], oi));
    }
  }
}

// ---- a diverged sample stops alone ----------------------------------------------------------------

TEST(SimulateBatch, ADivergedSampleStopsAloneNaNPadded) {
  auto initial = tumbling_states(7);
  // explicit Euler on Euler's equations: the gyroscopic term (I w) x w ~ 1e300 at |w| ~ 1e150 overflows to
  // inf in the first steps, then inf - inf gives NaN; the run stops at its first non-finite record
  initial[4].w_B = Eigen::Vector3d(1e150, 2e150, 3e150);
  SimulationOptions o = rk4_options(20, 1);
  o.method = Method::explicit_euler;
  for (int threads : {1, 2, 3}) {
    SCOPED_TRACE(threads);
    const BatchTrajectory b = simulate_batch({kBody}, initial, o, {}, threads);
    for (std::size_t i = 0; i < initial.size(); ++i) expect_sample(b, i, simulate(kBody, initial[i], o));
    EXPECT_EQ(b.diverged[4], 1);
    EXPECT_LT(b.filled[4], static_cast<std::int64_t>(b.records));  // stopped early: the rest is NaN (above)
    for (std::size_t i = 0; i < initial.size(); ++i) {
      if (i != 4) {
        EXPECT_EQ(b.filled[i], static_cast<std::int64_t>(b.records));
      }
    }
  }
}

// ---- bad input, failing samples, the monitor -----------------------------------------------------------

using test::message_of;

TEST(SimulateBatch, BadInputIsRefusedUpFrontNamingTheArgumentAndBothSizes) {
  const auto initial = tumbling_states(3);
  const SimulationOptions o = rk4_options(10, 1);
  EXPECT_EQ(message_of([&] { simulate_batch({kBody}, std::vector<RigidBodyState>{}, o, {}, 1); }),
            "initial: expected at least one sample, got 0");
  EXPECT_EQ(message_of([&] { simulate_batch({kBody, kBody}, initial, o, {}, 1); }),
            "bodies: expected 1 (shared) or N = 3 (one per sample), got 2");
  EXPECT_EQ(message_of([&] { simulate_batch({}, initial, o, {}, 1); }),
            "bodies: expected 1 (shared) or N = 3 (one per sample), got 0");
  BatchParameters p;
  p.dt = {0.1, 0.2};
  EXPECT_EQ(message_of([&] { simulate_batch({kBody}, initial, o, p, 1); }),
            "dt: expected one step per sample (N = 3) or a common one, got 2");
  p = {};
  p.gravity_W.resize(4, Eigen::Vector3d::Zero());
  EXPECT_EQ(message_of([&] { simulate_batch({kBody}, initial, o, p, 1); }),
            "gravity: expected one gravity vector per sample (N = 3) or a common one, got 4");
  p = {};
  p.loads.resize(1);
  EXPECT_EQ(message_of([&] { simulate_batch({kBody}, initial, o, p, 1); }),
            "loads: expected one load schedule per sample (N = 3) or a common one, got 1");
  EXPECT_EQ(message_of([&] { simulate_batch({kBody}, initial, o, {}, 0); }), "threads: expected an integer >= 1, got 0");
  EXPECT_EQ(message_of([&] { simulate_batch({kBody}, initial, rk4_options(-1, 1), {}, 1); }),
            "steps: expected an integer >= 0, got -1");
  EXPECT_EQ(message_of([&] { simulate_batch({kBody}, initial, rk4_options(5, 0), {}, 1); }),
            "record_every: expected an integer >= 1, got 0");
}

TEST(SimulateBatch, TheLowestFailingSampleIsRethrownWithItsIndex) {
  auto initial = tumbling_states(9);
  initial[7].p_W.x() = std::nan("");
  initial[3].v_W.y() = std::numeric_limits<double>::infinity();
  const SimulationOptions o = rk4_options(10, 1);
  std::string serial;
  try {
    simulate(kBody, initial[3], o);
  } catch (const std::invalid_argument& e) {
    serial = e.what();
  }
  ASSERT_FALSE(serial.empty());
  for (int threads : {1, 2, 3}) {
    EXPECT_EQ(message_of([&] { simulate_batch({kBody}, initial, o, {}, threads); }), "sample 3: " + serial);
  }
}

TEST(SimulateBatch, MonitorStopsEverySample) {
  const auto initial = tumbling_states(6);
  SimulationOptions o = rk4_options(8192, 1024);
  std::vector<std::int64_t> seen;
  o.monitor = [&](std::int64_t samples_done) {  // called from this thread only: no lock
    seen.push_back(samples_done);
    return true;
  };
  const BatchTrajectory b = simulate_batch({kBody}, initial, o, {}, 1);
  EXPECT_TRUE(b.interrupted);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.front(), 0);
  // the first call comes before any sample starts: none ever starts
  EXPECT_EQ(seen.size(), 1u);
  for (std::size_t i = 0; i < initial.size(); ++i) EXPECT_EQ(b.filled[i], 0);
  // a monitor that stops at its second call: sample 0 (one thread) stopped at its first monitor check (after its
  // first step: its initial record only), the others never started
  seen.clear();
  o.monitor = [&](std::int64_t samples_done) {
    seen.push_back(samples_done);
    return seen.size() == 2;
  };
  const BatchTrajectory c = simulate_batch({kBody}, initial, o, {}, 1);
  EXPECT_TRUE(c.interrupted);
  EXPECT_EQ(seen, (std::vector<std::int64_t>{0, 0}));
  EXPECT_EQ(c.filled[0], 1);
  for (std::size_t i = 1; i < initial.size(); ++i) EXPECT_EQ(c.filled[i], 0);
}

// ---- scenes ---------------------------------------------------------------------------------------------

// Two rigid bodies joined by a spring under gravity (the generic scene path).
Scene spring_scene(double stiffness) {
  Scene s;
  s.bodies = {kBody, RigidBody(1.0, Eigen::Vector3d(0.5, 0.5, 0.8))};
  SpringDamper spring;
  spring.body_a = 0, spring.body_b = 1, spring.point_a_B = Eigen::Vector3d(0.1, 0.0, 0.0);
  spring.stiffness = stiffness, spring.rest_length = 0.5, spring.damping = 0.1;
  s.elements = {UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}}, spring};
  return s;
}

std::vector<std::vector<BodyState>> spring_states(std::size_t n) {
  const auto a = tumbling_states(n);
  std::vector<std::vector<BodyState>> out;
  for (std::size_t i = 0; i < n; ++i) {
    RigidBodyState b = a[n - 1 - i];
    b.p_W += Eigen::Vector3d(1.0, 0.0, 0.0);
    out.push_back({a[i], b});
  }
  return out;
}

void expect_scene_sample(const BatchSceneSimulation& b, std::size_t i, const SceneSimulation& run) {
  SCOPED_TRACE("sample " + std::to_string(i));
  const std::size_t n = b.records, nb = static_cast<std::size_t>(b.body_count),
                    ne = static_cast<std::size_t>(b.element_count);
  expect_sample_rows(b.t, i, n, 1, run.t, "t");
  expect_sample_rows(b.p_W, i, n, 3 * nb, run.p_W, "p_W");
  expect_sample_rows(b.q_WB, i, n, 4 * nb, run.q_WB, "q_WB");
  expect_sample_rows(b.v_W, i, n, 3 * nb, run.v_W, "v_W");
  expect_sample_rows(b.w_B, i, n, 3 * nb, run.w_B, "w_B");
  expect_sample_rows(b.kinetic_energy, i, n, 1, run.kinetic_energy, "kinetic_energy");
  expect_sample_rows(b.potential_energy, i, n, 1, run.potential_energy, "potential_energy");
  expect_sample_rows(b.total_energy, i, n, 1, run.total_energy, "total_energy");
  expect_sample_rows(b.linear_momentum_W, i, n, 3, run.linear_momentum_W, "linear_momentum_W");
  expect_sample_rows(b.angular_momentum_W, i, n, 3, run.angular_momentum_W, "angular_momentum_W");
  expect_sample_rows(b.pivot_reaction_W, i, n, 3 * nb, run.pivot_reaction_W, "pivot_reaction_W");
  expect_sample_rows(b.angular_momentum_O_W, i, n, 3 * nb, run.angular_momentum_O_W, "angular_momentum_O_W");
  expect_sample_rows(b.mass, i, n, nb, run.mass, "mass");
  expect_sample_rows(b.work, i, n, ne, run.work, "work");
  expect_sample_rows(b.power, i, n, ne, run.power, "power");
  EXPECT_EQ(b.filled[i], static_cast<std::int64_t>(run.size()));
  EXPECT_EQ(b.diverged[i] != 0, run.diverged);
}

TEST(SimulateBatch, SceneBatchIsSerialRunsBitwiseWithSharedOrPerSampleScenes) {
  const std::size_t n = 5;
  const auto initial = spring_states(n);
  const SimulationOptions o = rk4_options(25, 4);
  const CompiledScene shared = compile_scene(spring_scene(20.0), Method::rk4);
  std::vector<CompiledScene> own;
  std::vector<double> dt;
  for (std::size_t i = 0; i < n; ++i) {
    own.push_back(compile_scene(spring_scene(10.0 + 5.0 * i), Method::rk4));
    dt.push_back(0.005 * (1.0 + i));
  }
  for (int threads : {1, 2, 3}) {
    SCOPED_TRACE(threads);
    const BatchSceneSimulation a = simulate_batch({shared}, initial, o, {}, threads);
    const BatchSceneSimulation b = simulate_batch(own, initial, o, dt, threads);
    for (std::size_t i = 0; i < n; ++i) {
      expect_scene_sample(a, i, simulate(shared, initial[i], o));
      SimulationOptions oi = o;
      oi.dt = dt[i];
      expect_scene_sample(b, i, simulate(own[i], initial[i], oi));
    }
  }
}

TEST(SimulateBatch, ASampleWhoseMassRunsOutIsReportedByIndex) {
  // a particle losing 1 kg/s from 1 kg runs out of mass at t = 1 s: sample 2's run (dt 0.1 s, 20 steps)
  // reaches it, the others (dt 0.01 s) end at 0.2 s
  Scene s;
  s.bodies = {Particle(1.0)};
  MassFlow flow;
  flow.rate = -1.0;
  s.mass_flows = {flow};
  const CompiledScene compiled = compile_scene(s, Method::rk4);
  const std::vector<std::vector<BodyState>> initial(4, std::vector<BodyState>{ParticleState{}});
  const SimulationOptions o = rk4_options(20, 1);
  const std::vector<double> dt{0.01, 0.01, 0.1, 0.01};
  const std::string text = message_of([&] { simulate_batch({compiled}, initial, o, dt, 2); });
  EXPECT_EQ(text.rfind("sample 2: mass_flows[0]", 0), 0u) << text;
  // structure mismatch between per-sample scenes is refused up front
  EXPECT_EQ(message_of([&] {
              simulate_batch({compile_scene(spring_scene(1.0), Method::rk4), compiled}, spring_states(2), o, {}, 1);
            }),
            "scenes[1]: expected a scene of 2 bodies, 2 work columns and 0 gyrostat wheels (as scenes[0]), got 1 bodies, 0 "
            "work columns and 0 wheels");
}

}  // namespace
}  // namespace rigiddyn
