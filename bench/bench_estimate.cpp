// The two estimates a run to a tolerance makes of each of its runs, every quantity's and its measure's alone (the
// attitude): from one pass over the common records (estimate_global_error_and_alone, "rigiddyn") against the two
// made apart, estimate_global_error without and with `only` (the "baseline", the same estimates bit for bit: tests/cpp/
// test_global_error_alone.cpp). Rigid bodies I = (1, 2, 3) kg m² in a row on springs under gravity, rk4, dt = 1 ms;
// arguments: bodies, record_every. ns per answer record; callgrind's counts of one call (one iteration):
//   valgrind --tool=callgrind --toggle-collect='(anonymous namespace)::one_pass(*' build/<dir>/bench/bench_estimate \
//       --benchmark_filter='estimate_and_alone:rigiddyn/1/1$' --benchmark_min_time=0.000001
// (and '(anonymous namespace)::apart(*' with the baseline's filter).
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/scene_order.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"
#include "rigiddyn/simulate/global_error.hpp"

#include <utility>
#include <vector>

namespace {

using namespace rigiddyn;
using Estimates = std::pair<GlobalErrorEstimate, GlobalErrorEstimate>;

// The answer run and its runs at 2 dt and 4 dt of `bodies` bodies, recording every `record_every` steps
struct ThreeRuns {
  SimulationOptions options;
  SceneSimulation answer, twice, four_times;
  int order = 0;

  ThreeRuns(int bodies, std::int64_t record_every) {
    Scene scene;
    std::vector<BodyState> states;
    for (int i = 0; i < bodies; ++i) {
      scene.bodies.emplace_back(RigidBody(1.0, Eigen::Vector3d(1.0, 2.0, 3.0)));
      RigidBodyState s;
      s.p_W = Eigen::Vector3d(1.0 * i, 0.0, 0.0);
      s.w_B = Eigen::Vector3d(0.1, 1.0, 0.1);
      states.emplace_back(s);
    }
    scene.elements.emplace_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}});
    for (int i = 0; i + 1 < bodies; ++i) {
      SpringDamper spring;
      spring.body_a = i, spring.body_b = i + 1, spring.stiffness = 10.0, spring.rest_length = 1.0,
      spring.damping = 0.1;
      scene.elements.emplace_back(spring);
    }
    const CompiledScene compiled = compile_scene(scene, Method::rk4);
    options.method = Method::rk4, options.dt = 1e-3, options.steps = bench::bench_size(4000, 400);
    options.record_every = record_every;
    answer = simulate(compiled, states, options);
    const auto coarse = [&](int factor) {
      SimulationOptions c = coarse_options(options, factor);
      c.estimate_records = true;
      return simulate(compiled, states, c);
    };
    twice = coarse(2), four_times = coarse(4);
    order = scene_order(compiled);
  }
};

BENCH_NOINLINE Estimates one_pass(const ErrorRecords& h, const ErrorRecords& h2, const ErrorRecords& h4,
                                  const SimulationOptions& o, int order) {
  return estimate_global_error_and_alone(h, h2, h4, o, order, ErrorMeasure::attitude);
}

BENCH_NOINLINE Estimates apart(const ErrorRecords& h, const ErrorRecords& h2, const ErrorRecords& h4,
                               const SimulationOptions& o, int order) {
  return {estimate_global_error(h, h2, h4, o, order),
          estimate_global_error(h, h2, h4, o, order, {}, ErrorMeasure::attitude)};
}

template <Estimates (*estimates)(const ErrorRecords&, const ErrorRecords&, const ErrorRecords&,
                                 const SimulationOptions&, int)>
void both_estimates(benchmark::State& state) {
  const ThreeRuns runs(static_cast<int>(state.range(0)), state.range(1));
  const ErrorRecords h = answer_records(runs.answer, runs.options, runs.order);
  const ErrorRecords h2 = coarse_records(runs.twice), h4 = coarse_records(runs.four_times);
  for (auto _ : state) benchmark::DoNotOptimize(estimates(h, h2, h4, runs.options, runs.order));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(h.n));
}

void arguments(benchmark::internal::Benchmark* b) { b->Args({1, 1})->Args({1, 4})->Args({10, 1}); }

}  // namespace

BENCHMARK(both_estimates<one_pass>)->Name("estimate_and_alone:rigiddyn")->Apply(arguments);
BENCHMARK(both_estimates<apart>)->Name("estimate_and_alone:baseline")->Apply(arguments);
