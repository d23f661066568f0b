// simulate_batch_simd (batch/simd_rigid_body.hpp): RK4 on lanes of samples against the scalar reference,
// N scalar simulate(RigidBody, ...) calls, within a stated round-off bound; lanes independent of each other
// (tail lanes, lane count, a diverged lane) bitwise; bad input named.
#include <gtest/gtest.h>

#include "test_numbers.hpp"
#include "invalid_argument_message.hpp"
#include "rigiddyn/batch/simd_rigid_body.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

using rigiddyn::test::kEps;

struct Batch {
  std::vector<RigidBody> bodies;
  std::vector<RigidBodyState> initial;
  SimulationOptions common;
  BatchParameters per_sample;
};

// A body with principal moments (a, b, c) about axes turned by q: a full symmetric inertia.
RigidBody turned_body(double mass, const Eigen::Vector3d& moments, const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d R = q.toRotationMatrix();
  return RigidBody(mass, Eigen::Matrix3d(R * moments.asDiagonal() * R.transpose()));
}

// n tumbling samples: per-sample full inertia (principal moments in [1, 1.5] x [1.6, 2.2] x [2.3, 2.6] kg m²,
// so I_a + I_b >= I_c), attitudes, rates of a few rad/s, velocities; the first sample's inertia diagonal
// (the scalar path's principal form), the second's spherical.
Batch tumbling(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto unit_q = [&] { return Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized()); };
  Batch b;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d moments(1.25 + 0.25 * u(rng), 1.9 + 0.3 * u(rng), 2.45 + 0.15 * u(rng));
    if (i == 0) {
      b.bodies.emplace_back(2.0, moments);
    } else if (i == 1) {
      b.bodies.emplace_back(3.0, Eigen::Vector3d(1.5, 1.5, 1.5));
    } else {
      b.bodies.push_back(turned_body(1.0 + 0.5 * u(rng), moments, unit_q()));
    }
    RigidBodyState s;
    s.p_W = Eigen::Vector3d(u(rng), u(rng), u(rng));
    s.q_WB = unit_q();
    s.v_W = Eigen::Vector3d(u(rng), u(rng), u(rng));
    s.w_B = 3.0 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    b.initial.push_back(s);
  }
  b.common.method = Method::rk4;
  b.common.dt = 1e-2;
  b.common.steps = 400;
  b.common.record_every = 7;  // 400 = 57·7 + 1: the last record is off the record_every grid
  b.common.t0 = 0.25;
  return b;
}

// Sample i's options as simulate_batch builds them.
SimulationOptions options_of(const Batch& b, std::size_t i) {
  SimulationOptions o = b.common;
  if (!b.per_sample.dt.empty()) o.dt = b.per_sample.dt[i];
  if (!b.per_sample.gravity_W.empty()) o.gravity_W = b.per_sample.gravity_W[i];
  if (!b.per_sample.loads.empty()) o.loads = b.per_sample.loads[i];
  return o;
}

BatchTrajectory run(const Batch& b, SimdLanes lanes = simd_default_lanes()) {
  return simulate_batch_simd(b.bodies, b.initial, b.common, b.per_sample, 1, lanes);
}

// The largest |x| of rows [0, rows) of an array of `width` columns (the scale of a quantity along a run).
double scale_of(const std::vector<double>& x, std::size_t rows, std::size_t width) {
  double s = 0.0;
  for (std::size_t k = 0; k < rows * width; ++k) s = std::max(s, std::abs(x[k]));
  return s;
}

// Sample i of the batch against simulate of sample i.
// Round-off bound. The two paths run the same equations; the SIMD path always in the full form of Euler's
// equations (I⁻¹ (τ − ω × I ω) with Eigen's 3×3 inverse), the scalar one in the principal or spherical form
// for a diagonal or isotropic inertia, and a compiler may contract or reorder differently: the rates differ
// by a few ulps, so one step's results differ by at most c1·eps·|y| with c1 ≈ 10 (h|ẏ| < |y| here, and the
// rounding of the update y + Δ itself: 1 ulp). n steps accumulate at most n·c1·eps·|y| (0 for the full
// inertias, where the operations are the same); the flow carries a difference on with growth factor
// `amplification` (1 + the relative phase drift of the integrable free rigid body over a run of ~4
// periods: <= 2; e^{λ t} near the intermediate axis). Bound: 32·n·eps·scale·amplification, with scale the
// largest |entry| of the quantity along the run (for energies and work: the largest of T, T + V and |W|;
// the work integrates a power of that order over the run). |q| − 1 is a few ulps after each normalisation
// on both paths: 8 eps absolute. t: the same expression t0 + i·dt on both paths, bitwise.
void expect_matches_scalar(const BatchTrajectory& batch, const Batch& b, std::size_t i, double amplification) {
  SCOPED_TRACE("sample " + std::to_string(i));
  const Trajectory s = simulate(b.bodies[b.bodies.size() == 1 ? 0 : i], b.initial[i], options_of(b, i));
  ASSERT_EQ(batch.filled[i], static_cast<std::int64_t>(s.size()));
  ASSERT_EQ(batch.diverged[i] != 0, s.diverged);
  const std::size_t rows = s.size(), base = i * batch.records;
  const double steps = static_cast<double>(b.common.steps);
  const double energy_scale = std::max({scale_of(s.kinetic_energy, rows, 1), scale_of(s.total_energy, rows, 1),
                                        scale_of(s.work, rows, 1)});
  const auto expect_near = [&](const std::vector<double>& simd, const std::vector<double>& scalar, std::size_t width,
                               double scale, const char* name) {
    const double bound = 32.0 * steps * kEps * scale * amplification;
    for (std::size_t k = 0; k < rows * width; ++k) {
      ASSERT_NEAR(simd[base * width + k], scalar[k], bound) << name << " entry " << k;
    }
  };
  for (std::size_t r = 0; r < rows; ++r) ASSERT_EQ(batch.t[base + r], s.t[r]) << "t row " << r;
  expect_near(batch.p_W, s.p_W, 3, scale_of(s.p_W, rows, 3), "p_W");
  expect_near(batch.q_WB, s.q_WB, 4, 1.0, "q_WB");
  expect_near(batch.v_W, s.v_W, 3, scale_of(s.v_W, rows, 3), "v_W");
  expect_near(batch.w_B, s.w_B, 3, scale_of(s.w_B, rows, 3), "w_B");
  expect_near(batch.kinetic_energy, s.kinetic_energy, 1, energy_scale, "kinetic_energy");
  expect_near(batch.total_energy, s.total_energy, 1, energy_scale, "total_energy");
  expect_near(batch.work, s.work, 1, energy_scale, "work");
  expect_near(batch.angular_momentum_norm, s.angular_momentum_norm, 1, scale_of(s.angular_momentum_norm, rows, 1),
              "angular_momentum_norm");
  for (std::size_t r = 0; r < rows; ++r) {
    ASSERT_NEAR(batch.quaternion_norm_error[base + r], s.quaternion_norm_error[r], 8.0 * kEps) << "|q| - 1 row " << r;
  }
  for (std::size_t r = rows; r < batch.records; ++r) ASSERT_TRUE(std::isnan(batch.t[base + r])) << "row " << r;
}

// Every array of sample i of `a` equal bitwise to sample j of `b` (NaN equal to NaN).
void expect_same_sample(const BatchTrajectory& a, std::size_t i, const BatchTrajectory& b, std::size_t j) {
  ASSERT_EQ(a.records, b.records);
  ASSERT_EQ(a.filled[i], b.filled[j]);
  ASSERT_EQ(a.diverged[i], b.diverged[j]);
  const auto same = [&](const std::vector<double>& x, const std::vector<double>& y, std::size_t width, const char* name) {
    for (std::size_t k = 0; k < a.records * width; ++k) {
      const double u = x[i * a.records * width + k], v = y[j * b.records * width + k];
      ASSERT_TRUE(u == v || (std::isnan(u) && std::isnan(v))) << name << " entry " << k << ": " << u << " vs " << v;
    }
  };
  same(a.t, b.t, 1, "t");
  same(a.p_W, b.p_W, 3, "p_W");
  same(a.q_WB, b.q_WB, 4, "q_WB");
  same(a.v_W, b.v_W, 3, "v_W");
  same(a.w_B, b.w_B, 3, "w_B");
  same(a.kinetic_energy, b.kinetic_energy, 1, "kinetic_energy");
  same(a.total_energy, b.total_energy, 1, "total_energy");
  same(a.angular_momentum_norm, b.angular_momentum_norm, 1, "angular_momentum_norm");
  same(a.quaternion_norm_error, b.quaternion_norm_error, 1, "quaternion_norm_error");
  same(a.work, b.work, 1, "work");
}

TEST(SimdRigidBody, FreeTumblingBodiesMatchScalarSimulate) {
  const Batch b = tumbling(13, 1);  // 13: a tail block at every lane count
  for (const SimdLanes lanes : simd_lane_kinds) {
    SCOPED_TRACE("lanes " + std::to_string(static_cast<int>(lanes)));
    const BatchTrajectory batch = run(b, lanes);
    ASSERT_EQ(batch.samples, 13u);
    ASSERT_EQ(batch.records, 59u);  // step 0, 57 multiples of 7, step 400
    // 400 steps of 0.01 s at |ω| <= 5.2 rad/s: < 4 periods, phase drift amplification <= 2
    for (std::size_t i = 0; i < b.initial.size(); ++i) expect_matches_scalar(batch, b, i, 2.0);
  }
}

TEST(SimdRigidBody, ForcedBodiesPerSampleDtGravityAndLoadsMatchScalarSimulate) {
  Batch b = tumbling(11, 2);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < b.initial.size(); ++i) {
    b.per_sample.dt.push_back(0.005 + 0.01 * std::abs(u(rng)));
    b.per_sample.gravity_W.emplace_back(0.0, 0.5 * u(rng), -9.81);
    AppliedLoad force, torque;
    force.force = Eigen::Vector3d(u(rng), u(rng), u(rng));  // through C, in W
    torque.frame = Frame::body;
    torque.torque = Eigen::Vector3d(u(rng), u(rng), u(rng));  // in B
    if (i == 4) {
      b.per_sample.loads.push_back({});  // one sample without loads in a loaded block
      b.per_sample.gravity_W.back().setZero();
    } else {
      b.per_sample.loads.push_back({force, torque});
    }
  }
  const BatchTrajectory batch = run(b);
  // torques of ~1 N m change |ω| by ~2 rad/s over the run: |ω| <= 8 rad/s, < 6 periods of 4 s, drift <= 2
  for (std::size_t i = 0; i < b.initial.size(); ++i) expect_matches_scalar(batch, b, i, 2.0);
  EXPECT_EQ(batch.work[4 * batch.records + batch.records - 1], 0.0);  // no load, no gravity: no work, exactly
}

TEST(SimdRigidBody, TumblingNearTheIntermediateAxisMatchesScalarSimulate) {
  // I = (1, 2, 3) kg m² (principal, the scalar path's principal form), ω mostly about the intermediate axis:
  // neighbouring orbits separate as e^{λ t}, λ = ω2 sqrt((I2 − I1)(I3 − I2)/(I1 I3)) = 0.577 rad/s at ω2 = 1;
  // a short run (t = 5 s, λ t = 2.9) keeps the amplification e^{λ t} <= 18.
  Batch b;
  b.bodies.emplace_back(1.0, Eigen::Vector3d(1.0, 2.0, 3.0));
  b.bodies.push_back(turned_body(1.0, Eigen::Vector3d(1.0, 2.0, 3.0), Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 1, 0).normalized()))));
  for (int k = 0; k < 2; ++k) {
    RigidBodyState s;
    const Eigen::Vector3d w_principal(1e-3, 1.0, 1e-3);
    s.w_B = k == 0 ? w_principal : Eigen::Vector3d(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 1, 0).normalized()) * w_principal);
    b.initial.push_back(s);
  }
  b.common.dt = 1e-2;
  b.common.steps = 500;
  const BatchTrajectory batch = run(b);
  for (std::size_t i = 0; i < 2; ++i) expect_matches_scalar(batch, b, i, std::exp(0.577 * 5.0));
}

TEST(SimdRigidBody, LanesAreIndependentBitwise) {
  // each lane computes its own sample by element-wise operations, rounded alike in every SimdLanes and in both
  // clones of the stepping loop (no FMA in either): a sample's records do not depend on the lane kind or count,
  // on its neighbours, or on whether it sits in a tail block
  const Batch b = tumbling(9, 4);
  const BatchTrajectory by4 = run(b, SimdLanes::eigen4);
  for (const SimdLanes lanes : simd_lane_kinds) {
    SCOPED_TRACE("lanes " + std::to_string(static_cast<int>(lanes)));
    const BatchTrajectory other = run(b, lanes);
    for (std::size_t i = 0; i < 9; ++i) expect_same_sample(other, i, by4, i);
  }
  for (const std::size_t i : {0u, 5u, 8u}) {
    Batch alone = b;
    alone.bodies = {b.bodies[i]};
    alone.initial = {b.initial[i]};
    expect_same_sample(run(alone, SimdLanes::eigen4), 0, by4, i);
  }
}

TEST(SimdRigidBody, ThreadCountDoesNotChangeTheResult) {
  // blocks are independent and each writes only its samples' rows: bitwise the same on 1, 2 or 3 threads
  const Batch b = tumbling(37, 9);
  const BatchTrajectory one = run(b);
  for (const int threads : {2, 3}) {
    const BatchTrajectory many = simulate_batch_simd(b.bodies, b.initial, b.common, b.per_sample, threads);
    for (std::size_t i = 0; i < 37; ++i) expect_same_sample(many, i, one, i);
  }
}

TEST(SimdRigidBody, ADivergedLaneStopsAloneAndTheOthersAreUntouched) {
  Batch b = tumbling(6, 5);
  Batch blown = b;
  // |ω| ~ 1e155 rad/s: ω × I ω overflows at the first evaluation, the state is NaN after one step
  blown.initial[3].w_B = Eigen::Vector3d(1e155, 2e155, -1e155);
  const BatchTrajectory batch = run(blown);
  const Trajectory scalar = simulate(blown.bodies[3], blown.initial[3], blown.common);
  ASSERT_TRUE(scalar.diverged);  // the premise: the scalar run diverges too
  EXPECT_EQ(batch.diverged[3], 1);
  EXPECT_EQ(batch.filled[3], static_cast<std::int64_t>(scalar.size()));  // step 0 and the first record (step 7)
  EXPECT_EQ(batch.filled[3], 2);
  for (std::size_t r = 2; r < batch.records; ++r) EXPECT_TRUE(std::isnan(batch.t[3 * batch.records + r]));
  const BatchTrajectory clean = run(b);
  for (const std::size_t i : {0u, 1u, 2u, 4u, 5u}) {
    EXPECT_EQ(batch.diverged[i], 0);
    expect_same_sample(batch, i, clean, i);
  }
}

TEST(SimdRigidBody, AMonitorThatAsksToStopStopsEverySample) {
  Batch b = tumbling(3, 6);
  b.common.steps = 12288;
  b.common.record_every = 1000;
  int calls = 0;
  b.common.monitor = [&](std::int64_t) { return ++calls >= 1; };
  const BatchTrajectory batch = run(b);
  EXPECT_GE(calls, 1);
  EXPECT_TRUE(batch.interrupted);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_LT(batch.filled[i], static_cast<std::int64_t>(batch.records));  // stopped before its last record
    EXPECT_EQ(batch.diverged[i], 0);
  }
}

TEST(SimdRigidBody, ZeroStepsRecordsTheInitialState) {
  Batch b = tumbling(3, 7);
  b.common.steps = 0;
  const BatchTrajectory batch = run(b);
  ASSERT_EQ(batch.records, 1u);
  // n = 0 steps: the bound is 0, the initial records are the same expressions on the same numbers (I ω by
  // the form simulate uses), so equal bitwise
  for (std::size_t i = 0; i < 3; ++i) expect_matches_scalar(batch, b, i, 1.0);
}

using test::message_of;

TEST(SimdRigidBody, BadInputNamesTheArgument) {
  const Batch good = tumbling(3, 8);
  const auto refused = [&](Batch b, int threads = 1, SimdLanes lanes = simd_default_lanes()) {
    return message_of([&] { simulate_batch_simd(b.bodies, b.initial, b.common, b.per_sample, threads, lanes); });
  };
  Batch b = good;
  b.common.method = Method::explicit_euler;
  EXPECT_EQ(refused(b).rfind("method: expected rk4", 0), 0u) << refused(b);
  b = good;
  AppliedLoad windowed;
  windowed.force = Eigen::Vector3d(1, 0, 0);
  windowed.t_end = 1.0;
  b.common.loads = {windowed};
  EXPECT_EQ(refused(b).rfind("loads: expected loads without a time window", 0), 0u) << refused(b);
  b = good;
  b.per_sample.loads = {{}, {windowed}, {}};
  EXPECT_EQ(refused(b).rfind("sample 1: loads: expected loads without a time window", 0), 0u) << refused(b);
  b = good;
  AppliedLoad world_torque;
  world_torque.torque = Eigen::Vector3d(0, 0, 1);  // frame world: a torque in W turns with the body
  b.common.loads = {world_torque};
  EXPECT_EQ(refused(b).rfind("loads: expected forces in W and torques in B", 0), 0u) << refused(b);
  b = good;
  b.bodies.push_back(b.bodies[0]);  // 4 bodies for 3 samples
  EXPECT_EQ(refused(b).rfind("bodies: expected 1 (shared) or 3", 0), 0u) << refused(b);
  b = good;
  b.per_sample.dt = {1e-2, 1e-2};
  EXPECT_EQ(refused(b).rfind("dt: expected 0 (the common value) or 3", 0), 0u) << refused(b);
  b = good;
  b.per_sample.gravity_W = {Eigen::Vector3d::Zero()};
  EXPECT_EQ(refused(b).rfind("gravity: expected 0 (the common value) or 3", 0), 0u) << refused(b);
  b = good;
  b.per_sample.loads = {{}, {}};
  EXPECT_EQ(refused(b).rfind("loads: expected 0 (the common value) or 3", 0), 0u) << refused(b);
  b = good;
  b.per_sample.dt = {1e-2, -1.0, 1e-2};
  EXPECT_EQ(refused(b).rfind("sample 1: dt: expected a finite number > 0", 0), 0u) << refused(b);
  b = good;
  b.initial[2].p_W.x() = std::nan("");
  EXPECT_EQ(refused(b).rfind("sample 2: initial.p_W: expected finite values", 0), 0u) << refused(b);
  b = good;
  b.initial.clear();
  EXPECT_EQ(refused(b).rfind("initial: expected at least one sample", 0), 0u) << refused(b);
  EXPECT_EQ(refused(good, 0).rfind("threads: expected an integer >= 1", 0), 0u) << refused(good, 0);
  EXPECT_EQ(refused(good, 1, static_cast<SimdLanes>(17)).rfind("lanes: expected a rigiddyn::SimdLanes", 0), 0u);
  b = good;
  b.common.steps = -1;
  EXPECT_EQ(refused(b).rfind("steps: expected an integer >= 0", 0), 0u) << refused(b);
  b = good;
  b.common.record_every = 0;
  EXPECT_EQ(refused(b).rfind("record_every: expected an integer >= 1", 0), 0u) << refused(b);
}

}  // namespace
}  // namespace rigiddyn
