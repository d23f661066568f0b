// The exact torque-free solution: ns per state_at(t) evaluation, next to one step of a
// hand-written RK4 on Euler's equations + quaternion kinematics (with renormalisation) for one body.
// Problem: I = diag(1, 2, 3) kg m², ω0 = (0.3, 0.5, 1.0) rad/s (case A); and near the separatrix
// ω0 = (0.01, 2, 0.01) rad/s.
#include <benchmark/benchmark.h>

#include "baselines.hpp"
#include "bench_common.hpp"
#include "rigiddyn/exact/free_body.hpp"

namespace {

const Eigen::Vector3d kInertia(1.0, 2.0, 3.0);

Eigen::Vector3d initial_w(int problem) { return problem == 0 ? Eigen::Vector3d(0.3, 0.5, 1.0) : Eigen::Vector3d(0.01, 2.0, 0.01); }

// rigiddyn: n evaluations of the exact state at spread times
void free_body_state_rigiddyn(benchmark::State& state) {
  const std::int64_t n = rigiddyn::bench::bench_size(100000, 1000);
  const rigiddyn::TorqueFreeSolution solution(kInertia.asDiagonal(), Eigen::Quaterniond::Identity(),
                                              initial_w(static_cast<int>(state.range(0))));
  for (auto _ : state) {
    double sum = 0.0;
    for (std::int64_t i = 0; i < n; ++i) {
      const rigiddyn::TorqueFreeState s = solution.state_at(0.01 * static_cast<double>(i));
      sum += s.w_B.x() + s.q_WB.w();
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

// baseline: n steps of classic RK4 on y = (ω, q), q renormalised (bench/baselines.hpp)
void free_body_state_baseline(benchmark::State& state) {
  const std::int64_t n = rigiddyn::bench::bench_size(100000, 1000);
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        rigiddyn::bench::rk4_free_body_baseline(kInertia, initial_w(static_cast<int>(state.range(0))), 0.01, n));
  }
  state.SetItemsProcessed(state.iterations() * n);
}

}  // namespace

// argument: 0 = generic case A, 1 = near the separatrix
BENCHMARK(free_body_state_rigiddyn)->Name("free_body_state:rigiddyn")->Arg(0)->Arg(1);
BENCHMARK(free_body_state_baseline)->Name("free_body_state:baseline")->Arg(0)->Arg(1);
