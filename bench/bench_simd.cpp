// SIMD across samples (target: the SIMD path >= 3x the per-sample throughput of the scalar
// hand-written RK4 loop on one core). 10^4 tumbling rigid bodies x 10^3 RK4 steps, recording only the last
// state (RIGIDDYN_BENCH_SMALL=1: 256 x 100), on one thread:
//   tumbling_rk4_<lanes>  simulate_batch_simd with each SimdLanes (eigen2/4/8: Eigen arrays, vector4/8:
//                    generic vectors; the library's default is simd_default_lanes(): vector8 with AVX-512F,
//                    else vector4) on free bodies with per-sample full inertias, vs a hand-written RK4
//                    on a double[13] per sample (bench_dynamics.cpp's raw_full_rk4, per-sample parameters),
//                    run sample after sample;
//   forced_rk4_vector4  the same under gravity, a force through C in W and a torque in B, the work integrated
//                    with the motion (double[14] in the hand loop).
// One op = one sample-step; bench_main prints rigiddyn/baseline (the SIMD speed-up is its inverse). Each
// baseline is checked first to compute the same final states as the SIMD path (relative 1e-12).
// Both stepping loops are out-of-line functions, so that
//   valgrind --tool=callgrind --toggle-collect='*lane_rk4_steps*' build/<dir>/bench/bench_simd --benchmark_filter=tumbling_rk4_vector4:rigiddyn
//   valgrind --tool=callgrind --toggle-collect='*hand_rk4_steps*' build/<dir>/bench/bench_simd --benchmark_filter=tumbling_rk4_vector4:baseline
// count the instructions of each alone (Ir / (samples x steps x iterations): instructions per sample-step).
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "rigiddyn/batch/simd_rigid_body.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace rigiddyn;

std::int64_t samples() { return bench::bench_size(10000, 256); }
std::int64_t steps() { return bench::bench_size(1000, 100); }
constexpr double dt = 1e-3;  // [s]

// n tumbling bodies: per-sample full inertias (principal moments about 1.2, 2, 2.8 kg m² about turned axes),
// attitudes and rates of a few rad/s; forced: gravity, a force in W and a torque in B per sample.
struct Problem {
  std::vector<RigidBody> bodies;
  std::vector<RigidBodyState> initial;
  SimulationOptions common;
  BatchParameters per_sample;
};

Problem tumbling(std::int64_t n, bool forced) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Problem p;
  for (std::int64_t i = 0; i < n; ++i) {
    const Eigen::Quaterniond axes(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized());
    const Eigen::Matrix3d R = axes.toRotationMatrix();
    const Eigen::Vector3d moments(1.2 + 0.1 * u(rng), 2.0 + 0.1 * u(rng), 2.8 + 0.1 * u(rng));
    p.bodies.emplace_back(1.0 + 0.2 * u(rng), Eigen::Matrix3d(R * moments.asDiagonal() * R.transpose()));
    RigidBodyState s;
    s.q_WB = Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized());
    s.v_W = Eigen::Vector3d(u(rng), u(rng), u(rng));
    s.w_B = Eigen::Vector3d(0.3, 2.0, 0.5) + 0.2 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    p.initial.push_back(s);
    if (forced) {
      AppliedLoad force, torque;
      force.force = Eigen::Vector3d(u(rng), u(rng), u(rng));
      torque.frame = Frame::body;
      torque.torque = 0.1 * Eigen::Vector3d(u(rng), u(rng), u(rng));
      p.per_sample.loads.push_back({force, torque});
    }
  }
  p.common.method = Method::rk4;
  p.common.dt = dt;
  p.common.steps = steps();
  p.common.record_every = steps();  // the initial and the last state only
  if (forced) p.common.gravity_W = standard_gravity();
  return p;
}

// ---- the hand-written baseline: y = (p 3, q xyzw 4, v 3, w 3, work 1), full inertia -------------------------
struct Hand {
  double I[9], I_inv[9];      // row-major [kg m²], [1/(kg m²)]
  double a[3], tau[3], f[3];  // (f_W + m g)/m [m/s²], torque in B [N m], f_W + m g [N]
  double y[14];
};

// ẏ (the work rate only when `forced`)
template <bool forced>
RIGIDDYN_ALWAYS_INLINE void hand_rate(const Hand& c, const double* y, double* d) {
  const double x = y[3], yy = y[4], z = y[5], s = y[6], wx = y[10], wy = y[11], wz = y[12];
  d[0] = y[7], d[1] = y[8], d[2] = y[9];
  d[3] = 0.5 * (s * wx + yy * wz - z * wy);
  d[4] = 0.5 * (s * wy + z * wx - x * wz);
  d[5] = 0.5 * (s * wz + x * wy - yy * wx);
  d[6] = -0.5 * (x * wx + yy * wy + z * wz);
  d[7] = c.a[0], d[8] = c.a[1], d[9] = c.a[2];
  const double* A = c.I;
  const double L[3] = {A[0] * wx + A[1] * wy + A[2] * wz, A[3] * wx + A[4] * wy + A[5] * wz, A[6] * wx + A[7] * wy + A[8] * wz};
  const double g[3] = {c.tau[0] - (wy * L[2] - wz * L[1]), c.tau[1] - (wz * L[0] - wx * L[2]), c.tau[2] - (wx * L[1] - wy * L[0])};
  for (int i = 0; i < 3; ++i) d[10 + i] = c.I_inv[3 * i] * g[0] + c.I_inv[3 * i + 1] * g[1] + c.I_inv[3 * i + 2] * g[2];
  if (forced) d[13] = c.f[0] * y[7] + c.f[1] * y[8] + c.f[2] * y[9] + c.tau[0] * wx + c.tau[1] * wy + c.tau[2] * wz;
}

// n RK4 steps of one sample on a local copy of its state
template <bool forced>
BENCH_NOINLINE void hand_rk4_steps(const Hand& c, double* state, std::int64_t n) {
  constexpr int m = forced ? 14 : 13;
  double y[14];
  for (int i = 0; i < m; ++i) y[i] = state[i];
  for (std::int64_t it = 0; it < n; ++it) {
    double k1[14], k2[14], k3[14], k4[14], t[14];
    hand_rate<forced>(c, y, k1);
    for (int i = 0; i < m; ++i) t[i] = y[i] + 0.5 * dt * k1[i];
    hand_rate<forced>(c, t, k2);
    for (int i = 0; i < m; ++i) t[i] = y[i] + 0.5 * dt * k2[i];
    hand_rate<forced>(c, t, k3);
    for (int i = 0; i < m; ++i) t[i] = y[i] + dt * k3[i];
    hand_rate<forced>(c, t, k4);
    for (int i = 0; i < m; ++i) y[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    const double inverse_norm = 1.0 / std::sqrt(y[3] * y[3] + y[4] * y[4] + y[5] * y[5] + y[6] * y[6]);
    for (int i = 3; i < 7; ++i) y[i] *= inverse_norm;
  }
  for (int i = 0; i < m; ++i) state[i] = y[i];
}

std::vector<Hand> hand_of(const Problem& p) {
  std::vector<Hand> hands(p.initial.size());
  for (std::size_t k = 0; k < hands.size(); ++k) {
    Hand& c = hands[k];
    const RigidBody& body = p.bodies[k];
    const Eigen::Matrix3d I = body.inertia_com(), I_inv = I.inverse();
    for (int i = 0; i < 9; ++i) c.I[i] = I(i / 3, i % 3), c.I_inv[i] = I_inv(i / 3, i % 3);
    Eigen::Vector3d f_W = body.mass() * p.common.gravity_W, tau = Eigen::Vector3d::Zero();
    if (!p.per_sample.loads.empty()) {
      const ComLoads loads = loads_at(p.per_sample.loads[k], 0.0);
      f_W = loads.f_W + f_W, tau = loads.tau_B;
    }
    for (int i = 0; i < 3; ++i) c.f[i] = f_W[i], c.a[i] = (1.0 / body.mass()) * f_W[i], c.tau[i] = tau[i];
    const RigidBodyCoordinates y = to_coordinates(p.initial[k]);
    for (int i = 0; i < 14; ++i) c.y[i] = y[i];
  }
  return hands;
}

// Every sample's final state by the hand loop, sample after sample (what a scalar batch does).
template <bool forced>
void hand_batch(const std::vector<Hand>& hands, std::int64_t n, std::vector<double>& final_states) {
  for (std::size_t k = 0; k < hands.size(); ++k) {
    double* y = final_states.data() + 14 * k;
    for (int i = 0; i < 14; ++i) y[i] = hands[k].y[i];
    hand_rk4_steps<forced>(hands[k], y, n);
  }
}

// The largest relative difference between the hand loop's final states and the SIMD path's last records:
// the same arithmetic up to a few roundings per step, so anything above 1e-12 means different motions.
template <bool forced>
double mismatch(const Problem& p, const std::vector<Hand>& hands) {
  std::vector<double> hand(14 * hands.size());
  hand_batch<forced>(hands, p.common.steps, hand);
  const BatchTrajectory simd = simulate_batch_simd(p.bodies, p.initial, p.common, p.per_sample, 1);
  double worst = 0.0;
  const auto compare = [&](double a, double b) { worst = std::max(worst, std::abs(a - b) / std::max(1.0, std::abs(b))); };
  for (std::size_t k = 0; k < hands.size(); ++k) {
    const std::size_t last = k * simd.records + simd.records - 1;
    for (int i = 0; i < 3; ++i) {
      compare(hand[14 * k + i], simd.p_W[3 * last + i]);
      compare(hand[14 * k + 7 + i], simd.v_W[3 * last + i]);
      compare(hand[14 * k + 10 + i], simd.w_B[3 * last + i]);
    }
    for (int i = 0; i < 4; ++i) compare(hand[14 * k + 3 + i], simd.q_WB[4 * last + i]);
    if (forced) compare(hand[14 * k + 13], simd.work[last]);
  }
  return worst;
}

void simd(benchmark::State& state, bool forced, SimdLanes lanes) {
  const Problem p = tumbling(samples(), forced);
  for (auto _ : state) {
    const BatchTrajectory out = simulate_batch_simd(p.bodies, p.initial, p.common, p.per_sample, 1, lanes);
    benchmark::DoNotOptimize(out.w_B.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * samples() * steps());
}

template <bool forced>
void hand(benchmark::State& state) {
  const Problem p = tumbling(samples(), forced);
  const std::vector<Hand> hands = hand_of(p);
  const double difference = mismatch<forced>(p, hands);
  state.counters["max_rel_dy"] = difference;
  if (difference > 1e-12) {
    state.SkipWithError("the hand loop and the SIMD path integrate different motions");
    return;
  }
  std::vector<double> final_states(14 * hands.size());
  for (auto _ : state) {
    hand_batch<forced>(hands, steps(), final_states);
    benchmark::DoNotOptimize(final_states.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * samples() * steps());
}

// Each case "<name>:rigiddyn" with its baseline "<name>:baseline" (the baseline does not depend on the lanes;
// registered per case so that bench_main prints each ratio).
struct LaneCase {
  const char* name;
  SimdLanes lanes;
  bool forced;
};
constexpr LaneCase cases[] = {
    {"tumbling_rk4_eigen2", SimdLanes::eigen2, false}, {"tumbling_rk4_eigen4", SimdLanes::eigen4, false},
    {"tumbling_rk4_eigen8", SimdLanes::eigen8, false}, {"tumbling_rk4_vector4", SimdLanes::vector4, false},
    {"tumbling_rk4_vector8", SimdLanes::vector8, false}, {"forced_rk4_eigen4", SimdLanes::eigen4, true},
    {"forced_rk4_vector4", SimdLanes::vector4, true},
};

bool register_cases() {
  for (const LaneCase& c : cases) {
    benchmark::RegisterBenchmark((std::string(c.name) + ":rigiddyn").c_str(),
                                 [c](benchmark::State& state) { simd(state, c.forced, c.lanes); })
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string(c.name) + ":baseline").c_str(),
                                 [c](benchmark::State& state) { c.forced ? hand<true>(state) : hand<false>(state); })
        ->Unit(benchmark::kMillisecond);
  }
  return true;
}
const bool registered = register_cases();

}  // namespace
