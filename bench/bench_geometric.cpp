// The structure-preserving integrators (implicit_midpoint, splitting_dlm, splitting_dlm_yoshida4,
// exact_flow_kick) and the exact torque-free solution: ns per step (per evaluation) for one free
// rigid body, each next to the same number of steps of a hand-written RK4 loop on (ω, q) with
// renormalisation (the baseline of every case, so the ratio reads "cost in RK4 steps").
// Problem: I = diag(1, 2, 3) kg m², tumbling near the intermediate axis ω0 = (0.01, 2, 0.01) rad/s,
// h = 0.01 s.
// Measured (best of 3, shared 2-core machine, `build/<dir>/bench/bench_geometric --benchmark_min_time=0.2`):
// implicit_midpoint 301, splitting_dlm 148, splitting_dlm_yoshida4 430, exact_flow_kick 572 (was 5670
// before FreeRotationFlow and the duplication R_J), rk4 57 ns/step; exact_state 286 ns/evaluation
// (was 1580); hand-written RK4 baseline ~90 ns/step. Since (2026-12-05, `taskset -c 1`, three runs): exact_flow_kick
// 203 ns/step by the addition theorems over a short step (was 538–550), exact_state 85 ns by the theta series (was
// 258); docs/perf/exact.md.
// The splittings' rotations by increments (|L| a round-off walk, not a drift), measured on 2026-11-23 as
// rigiddyn/baseline, median of 3 runs each, before → after: splitting_dlm 1.47 → 1.52,
// splitting_dlm_yoshida4 4.17 → 4.16 (`--benchmark_filter=splitting --benchmark_min_time=0.2`).
#include <benchmark/benchmark.h>

#include "baselines.hpp"
#include "bench_common.hpp"
#include "rigiddyn/exact/free_body.hpp"
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/scene/one_body_scene.hpp"

namespace {

const Eigen::Vector3d kInertia(1.0, 2.0, 3.0);
const Eigen::Vector3d kW0(0.01, 2.0, 0.01);
constexpr double kH = 0.01;

std::int64_t steps() { return rigiddyn::bench::bench_size(100000, 1000); }

// rigiddyn: n steps of Integrator on the model simulate() runs for this body, the layout of its one-body scene
// (principal form, no element)
template <class Integrator>
void step_rigiddyn(benchmark::State& state) {
  using Layout = rigiddyn::OneBodySceneModel<rigiddyn::detail::RigidSlot<rigiddyn::PrincipalEuler, rigiddyn::detail::FirstPlace>,
                                             rigiddyn::OneBodyElements::none>;
  const std::int64_t n = steps();
  const auto layout = rigiddyn::one_body_layout_as<Layout>(rigiddyn::RigidBody(1.0, kInertia), Eigen::Vector3d::Zero(), {});
  for (auto _ : state) {
    rigiddyn::RigidBodyState s0;
    s0.w_B = kW0;
    Layout::Coordinates y = layout.coordinates({s0}, 0.0);
    auto work = rigiddyn::workspace<Integrator>(layout, y);
    for (std::int64_t i = 0; i < n; ++i) Integrator::step(layout, y, kH, work);
    benchmark::DoNotOptimize(y);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

// rigiddyn: n evaluations of the exact state at spread times
void exact_state_rigiddyn(benchmark::State& state) {
  const std::int64_t n = steps();
  const rigiddyn::TorqueFreeSolution solution(kInertia.asDiagonal(), Eigen::Quaterniond::Identity(), kW0);
  for (auto _ : state) {
    double sum = 0.0;
    for (std::int64_t i = 0; i < n; ++i) {
      const rigiddyn::TorqueFreeState s = solution.state_at(kH * static_cast<double>(i));
      sum += s.w_B.x() + s.q_WB.w();
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

// baseline: n steps of classic RK4 on y = (ω, q), q renormalised (bench/baselines.hpp)
void rk4_baseline(benchmark::State& state) {
  const std::int64_t n = steps();
  for (auto _ : state) benchmark::DoNotOptimize(rigiddyn::bench::rk4_free_body_baseline(kInertia, kW0, kH, n));
  state.SetItemsProcessed(state.iterations() * n);
}

}  // namespace

BENCHMARK(step_rigiddyn<rigiddyn::ImplicitMidpoint>)->Name("implicit_midpoint_step:rigiddyn");
BENCHMARK(rk4_baseline)->Name("implicit_midpoint_step:baseline");
BENCHMARK(step_rigiddyn<rigiddyn::SplittingDlm>)->Name("splitting_dlm_step:rigiddyn");
BENCHMARK(rk4_baseline)->Name("splitting_dlm_step:baseline");
BENCHMARK(step_rigiddyn<rigiddyn::Yoshida4>)->Name("splitting_dlm_yoshida4_step:rigiddyn");
BENCHMARK(rk4_baseline)->Name("splitting_dlm_yoshida4_step:baseline");
BENCHMARK(step_rigiddyn<rigiddyn::ExactFlowKick>)->Name("exact_flow_kick_step:rigiddyn");
BENCHMARK(rk4_baseline)->Name("exact_flow_kick_step:baseline");
BENCHMARK(step_rigiddyn<rigiddyn::Rk4>)->Name("rk4_step:rigiddyn");
BENCHMARK(rk4_baseline)->Name("rk4_step:baseline");
BENCHMARK(exact_state_rigiddyn)->Name("exact_state:rigiddyn");
BENCHMARK(rk4_baseline)->Name("exact_state:baseline");
