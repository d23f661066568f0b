// Batch runs, performance: simulate_batch of N tumbling bodies × n RK4 steps, recording only
// the first and the last state of each sample (record_every = n), against a hand-written scalar RK4 loop
// over the same samples in the same run.
//   batch_rk4:rigiddyn/threads:T  rigiddyn::simulate_batch(threads = T) (batch/simulate_batch.hpp)
//   batch_rk4:baseline/threads:T  the hand loop below, one sample after the other, the samples split into
//                                 T contiguous blocks on T std::threads (each writes its own block once)
//                                 (ns/op = ns per sample: the ratio line is the per-sample throughput;
//                                 counters ns_per_sample_step (wall) and cpu_ns_per_sample_step (CPU of
//                                 every thread: the cost per core, what to compare on a loaded machine))
//   batch_scaling                 counters scaling_rigiddyn = t(1 thread) / t(2 threads) of simulate_batch
//                                 and scaling_hand, the same of the hand loop, timed alternately in the same
//                                 iterations (the hand loop's figure is what the machine's load allows:
//                                 read the library's against it). Target: >= 1.8 on 2 cores.
//                                 cpu_2_over_1_*: process CPU time of the 2-thread run / the 1-thread run's
//                                 (1 = threading adds no work; independent of the load, unlike the scaling)
// The problem: a T-handle (m = 0.1 kg, I = diag(2, 6.5, 8)e-5 kg m², the tumbling body of
// python/rigiddyn/problems/t_handle.toml), no gravity, no loads; per sample a uniform random attitude and
// w_B with components N(0, 5 rad/s) (so |w| ~ 8 rad/s, dt |w| ~ 0.08, far inside RK4's stability limit
// 2.8); dt = 0.01 s. bench/python/bench_batch.py runs the same problem against MuJoCo.
// Full size: N = 10⁴ samples × n = 10³ steps; ctest (RIGIDDYN_BENCH_SMALL=1): 64 × 100.
// The hand loop is an out-of-line function (hand_rk4_samples), so that
//   valgrind --tool=callgrind --toggle-collect='*hand_rk4_samples*' build/<dir>/bench/bench_batch
//     --benchmark_filter='batch_rk4:baseline/threads:1$'
// counts its instructions alone (and --toggle-collect='*simulate_batch*' the library's).
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "rigiddyn/batch/parallel_for.hpp"
#include "rigiddyn/batch/simulate_batch.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <random>
#include <thread>
#include <vector>

namespace {

using namespace rigiddyn;

std::int64_t samples() { return bench::bench_size(10000, 64); }
std::int64_t steps() { return bench::bench_size(1000, 100); }
constexpr double dt = 0.01;  // [s]

// The parameters at run time (see bench_variable_mass.cpp: compile-time constants would let the compiler
// fold what no general loop can; a scalar through a volatile).
double at_run_time(double value) {
  volatile double opaque = value;
  return opaque;
}

struct Problem {
  double mass = at_run_time(0.1);                                                          // [kg]
  Eigen::Vector3d inertia{at_run_time(2.0e-5), at_run_time(6.5e-5), at_run_time(8.0e-5)};  // [kg m²]
  double h = at_run_time(dt);                                                              // [s]
  std::vector<RigidBodyState> initial;                                                     // (N,)
};

// N tumbling samples from a fixed seed: attitude uniform on SO(3) (a normalised 4-D Gaussian), w_B with
// N(0, 5 rad/s) components, p_W and v_W zero.
Problem make_problem(std::int64_t n_samples) {
  Problem problem;
  std::mt19937_64 engine(20261124);
  std::normal_distribution<double> normal(0.0, 1.0);
  problem.initial.resize(static_cast<std::size_t>(n_samples));
  for (RigidBodyState& s : problem.initial) {
    Eigen::Vector4d q;
    for (int i = 0; i < 4; ++i) q[i] = normal(engine);
    s.q_WB = Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized();
    for (int i = 0; i < 3; ++i) s.w_B[i] = 5.0 * normal(engine);
  }
  return problem;
}

SimulationOptions options_of(const Problem& problem) {
  SimulationOptions o;
  o.method = Method::rk4;
  o.dt = problem.h;
  o.steps = steps();
  o.record_every = steps();  // the first and the last state
  return o;
}

BatchTrajectory run_library(const Problem& problem, int threads) {
  return simulate_batch({RigidBody(problem.mass, problem.inertia)}, problem.initial, options_of(problem), BatchParameters{},
                        threads);
}

// ---- the hand-written loop: y = (p 3, q xyzw 4, v 3, w 3), I diagonal, no loads ---------------------------
// The same equations as the free rigid body's layout in principal axes (scene/one_body_scene_model.hpp): ṗ = v,
// q̇ = ½ q ⊗ (ω, 0), v̇ = 0, I1 ω̇1 = (I2 − I3) ω2 ω3 and cyclic (Euler's equations in principal axes, Craig,
// "Rigid Body Dynamics" slides), classic RK4 then q ← q / |q| (as bench_dynamics.cpp's raw_rk4).
struct HandBody {
  double I[3], I_inv[3];
};

RIGIDDYN_ALWAYS_INLINE void hand_rate(const HandBody& b, const double* y, double* d) {
  const double x = y[3], yy = y[4], z = y[5], s = y[6], wx = y[10], wy = y[11], wz = y[12];
  d[0] = y[7], d[1] = y[8], d[2] = y[9];
  d[3] = 0.5 * (s * wx + yy * wz - z * wy);
  d[4] = 0.5 * (s * wy + z * wx - x * wz);
  d[5] = 0.5 * (s * wz + x * wy - yy * wx);
  d[6] = -0.5 * (x * wx + yy * wy + z * wz);
  d[7] = d[8] = d[9] = 0.0;
  d[10] = b.I_inv[0] * ((b.I[1] - b.I[2]) * wy * wz);
  d[11] = b.I_inv[1] * ((b.I[2] - b.I[0]) * wz * wx);
  d[12] = b.I_inv[2] * ((b.I[0] - b.I[1]) * wx * wy);
}

RIGIDDYN_ALWAYS_INLINE void hand_rk4_step(const HandBody& b, double* y, double h) {
  double k1[13], k2[13], k3[13], k4[13], t[13];
  hand_rate(b, y, k1);
  for (int i = 0; i < 13; ++i) t[i] = y[i] + 0.5 * h * k1[i];
  hand_rate(b, t, k2);
  for (int i = 0; i < 13; ++i) t[i] = y[i] + 0.5 * h * k2[i];
  hand_rate(b, t, k3);
  for (int i = 0; i < 13; ++i) t[i] = y[i] + h * k3[i];
  hand_rate(b, t, k4);
  const double h_6 = h / 6.0;
  for (int i = 0; i < 13; ++i) y[i] += h_6 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
  const double inverse_norm = 1.0 / std::sqrt(y[3] * y[3] + y[4] * y[4] + y[5] * y[5] + y[6] * y[6]);
  for (int i = 3; i < 7; ++i) y[i] *= inverse_norm;
}

// Samples [begin, end): n steps each on a local y, the final y written once into out (13 per sample).
BENCH_NOINLINE void hand_rk4_samples(const HandBody& b, const std::vector<RigidBodyState>& initial, std::size_t begin,
                                     std::size_t end, std::int64_t n, double h, double* out) {
  for (std::size_t k = begin; k < end; ++k) {
    const RigidBodyState& s = initial[k];
    double y[13] = {s.p_W.x(),   s.p_W.y(),   s.p_W.z(),   s.q_WB.x(), s.q_WB.y(), s.q_WB.z(), s.q_WB.w(),
                    s.v_W.x(),   s.v_W.y(),   s.v_W.z(),   s.w_B.x(),  s.w_B.y(),  s.w_B.z()};
    for (std::int64_t i = 0; i < n; ++i) hand_rk4_step(b, y, h);
    std::copy_n(y, 13, out + 13 * k);
  }
}

// The hand loop over every sample on `threads` std::threads, each a contiguous block; returns (N, 13).
std::vector<double> run_hand(const Problem& problem, int threads) {
  const HandBody b{{problem.inertia[0], problem.inertia[1], problem.inertia[2]},
                   {1.0 / problem.inertia[0], 1.0 / problem.inertia[1], 1.0 / problem.inertia[2]}};
  const std::size_t n = problem.initial.size();
  std::vector<double> out(13 * n);
  std::vector<std::thread> pool;
  const auto block = [&](int j) {
    hand_rk4_samples(b, problem.initial, n * j / threads, n * (j + 1) / threads, steps(), problem.h, out.data());
  };
  for (int j = 1; j < threads; ++j) pool.emplace_back(block, j);
  block(0);
  for (std::thread& t : pool) t.join();
  return out;
}

// The largest difference between the final states of the library and of the hand loop over all samples:
// max_k max(|w_lib − w_hand| / |w_hand|, |q_lib − q_hand|). The two run the same operations in the same
// order (the library's RK4 update is h/6 (k1 + 2 k2 + 2 k3 + k4) as here), so they differ only where the
// compiler contracts a different product into an FMA: at most a few ulps per step, eps ~ 1.1e-16, over
// n <= 1e3 steps: <= ~1e-12 before the flow amplifies it. Near the separatrix the flow amplifies a
// perturbation of the energy into a phase error growing with t; the threshold 1e-9 leaves a factor 1e3 for
// that and is still far below the RK4 error at this dt (|w| relative up to 2e-4 after the 10 s of the full
// size, step doubling in bench/python/bench_batch.py), so it tells the same motion from a different one.
double mismatch(const BatchTrajectory& library, const std::vector<double>& hand) {
  double worst = 0.0;
  const std::size_t last = library.records - 1;
  for (std::size_t k = 0; k < library.samples; ++k) {
    const double* w = library.w_B.data() + 3 * (k * library.records + last);
    const double* q = library.q_WB.data() + 4 * (k * library.records + last);
    const double* y = hand.data() + 13 * k;
    const Eigen::Vector3d dw(w[0] - y[10], w[1] - y[11], w[2] - y[12]);
    const Eigen::Vector4d dq(q[0] - y[3], q[1] - y[4], q[2] - y[5], q[3] - y[6]);
    worst = std::max({worst, dw.norm() / Eigen::Vector3d(y[10], y[11], y[12]).norm(), dq.norm()});
  }
  return worst;
}

constexpr double mismatch_bound = 1e-9;

// CPU time of the whole process (every thread) [s]: on a machine shared with other work, the cost per core
// (the wall time also counts the time other processes held the cores).
double process_cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// Counters of a batch benchmark: wall and process CPU ns per sample-step (CPU summed over threads) from the
// totals of every iteration.
struct Clocks {
  std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
  double cpu = process_cpu_seconds();

  void set_counters(benchmark::State& state) const {
    const double sample_steps = static_cast<double>(state.iterations() * samples() * steps());
    const double wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
    state.SetItemsProcessed(state.iterations() * samples());
    state.counters["cpu_ns_per_sample_step"] = (process_cpu_seconds() - cpu) / sample_steps * 1e9;
    state.counters["ns_per_sample_step"] = wall_seconds / sample_steps * 1e9;
  }
};

void library_batch(benchmark::State& state) {
  const Problem problem = make_problem(samples());
  const int threads = static_cast<int>(state.range(0));
  const Clocks clocks;
  for (auto _ : state) {
    BatchTrajectory b = run_library(problem, threads);
    benchmark::DoNotOptimize(b.w_B.data());
    benchmark::ClobberMemory();
  }
  clocks.set_counters(state);
}

void hand_batch(benchmark::State& state) {
  const Problem problem = make_problem(samples());
  const int threads = static_cast<int>(state.range(0));
  const double difference = mismatch(run_library(problem, 1), run_hand(problem, 1));
  state.counters["max_difference"] = difference;
  if (!(difference <= mismatch_bound)) {
    state.SkipWithError("the hand loop and simulate_batch integrate different motions");
    return;
  }
  const Clocks clocks;
  for (auto _ : state) {
    std::vector<double> y = run_hand(problem, threads);
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  clocks.set_counters(state);
}

// t(1 thread) / t(2 threads) of the library and of the hand loop, the four runs alternated in every
// iteration so that a change of the machine's load hits them alike; and the process CPU time of the 2-thread
// run over the 1-thread run's (1 when threading costs no extra work: no false sharing, no contention).
void scaling(benchmark::State& state) {
  const Problem problem = make_problem(samples());
  struct Totals {
    double wall = 0.0, cpu = 0.0;
  };
  Totals library_1, library_2, hand_1, hand_2;
  const auto timed = [](Totals& total, const auto& run) {
    const Clocks start;
    run();
    total.wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - start.wall).count();
    total.cpu += process_cpu_seconds() - start.cpu;
  };
  for (auto _ : state) {
    timed(library_1, [&] { benchmark::DoNotOptimize(run_library(problem, 1).w_B.data()); });
    timed(library_2, [&] { benchmark::DoNotOptimize(run_library(problem, 2).w_B.data()); });
    timed(hand_1, [&] { benchmark::DoNotOptimize(run_hand(problem, 1).data()); });
    timed(hand_2, [&] { benchmark::DoNotOptimize(run_hand(problem, 2).data()); });
  }
  state.counters["scaling_rigiddyn"] = library_1.wall / library_2.wall;
  state.counters["scaling_hand"] = hand_1.wall / hand_2.wall;
  state.counters["cpu_2_over_1_rigiddyn"] = library_2.cpu / library_1.cpu;
  state.counters["cpu_2_over_1_hand"] = hand_2.cpu / hand_1.cpu;
  state.counters["hw_threads"] = default_thread_count();
}

}  // namespace

BENCHMARK(library_batch)->Name("batch_rk4:rigiddyn")->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(hand_batch)->Name("batch_rk4:baseline")->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(scaling)->Name("batch_scaling")->Iterations(3)->UseRealTime()->Unit(benchmark::kMillisecond);
