// Springs and drag, performance: the generic scene model against a hand-written loop of the same equations.
//   springs_drag_rk4/N   N rigid bodies (principal inertias) under UniformGravity and Drag (all four
//                        coefficients non-zero), linked in a chain by N − 1 SpringDampers and each hung from
//                        a world anchor by one more (2N − 1 springs, attached off the centres of mass, so
//                        they give torques): the compiled scene's SceneModel stepped by RK4 with one workspace
//                        ("rigiddyn") vs a hand-written, allocation-free RK4 over plain arrays of the same
//                        equations (springs_drag_baseline.hpp, "baseline"). The hand loop integrates the
//                        motion only: the scene model also carries t and one work slot per element (2N + 1
//                        integrals of the elements' powers), which a loop written by hand would not.
//                        ns/op is per body-evaluation (4 per RK4 step and body). N = 10 and 200.
// Before timing, one step of each from the same state must agree to a bound derived below (the two
// integrate the same motion), or the baseline reports an error.
// ctest runs it with RIGIDDYN_BENCH_SMALL=1 (N = 10 only, fewer steps).
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "springs_drag_baseline.hpp"
#include "rigiddyn/integrators/rk4.hpp"
#include "rigiddyn/scene/compile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace {

using namespace rigiddyn;

constexpr double h = 1e-3;  // step [s]

// steps per benchmark iteration: about 8e4 body-evaluations at full size, at least 2 steps
std::int64_t chain_steps(std::int64_t n) { return std::max<std::int64_t>(2, bench::bench_size(20000, 200) / n); }

void set_items(benchmark::State& state, std::int64_t n, std::int64_t steps) {
  state.SetItemsProcessed(state.iterations() * 4 * steps * n);  // body-evaluations: 4 per RK4 step and body
}

// The chain as a scene: the same bodies, states and elements as the hand loop.
std::pair<Scene, std::vector<BodyState>> chain_scene(const bench::SpringsDragChain& c) {
  Scene scene;
  std::vector<BodyState> initial;
  for (std::size_t i = 0; i < c.mass.size(); ++i) {
    scene.bodies.emplace_back(RigidBody(c.mass[i], c.inertia[i]));
    const double* y = c.y0.data() + 13 * i;
    RigidBodyState s;
    s.p_W = Eigen::Vector3d(y[0], y[1], y[2]);
    s.q_WB = Eigen::Quaterniond(y[6], y[3], y[4], y[5]);  // (w, x, y, z)
    s.v_W = Eigen::Vector3d(y[7], y[8], y[9]);
    s.w_B = Eigen::Vector3d(y[10], y[11], y[12]);
    initial.emplace_back(s);
  }
  scene.elements.emplace_back(UniformGravity{c.g_W, {}});
  Drag drag;
  drag.linear = c.linear, drag.quadratic = c.quadratic;
  drag.angular_linear = c.angular_linear, drag.angular_quadratic = c.angular_quadratic;
  scene.elements.emplace_back(drag);
  for (const bench::ChainSpring& k : c.springs) {
    SpringDamper spring;
    spring.body_a = k.a, spring.point_a_B = k.point_a_B;
    spring.body_b = k.b, spring.point_b = k.point_b;
    spring.stiffness = k.stiffness, spring.rest_length = k.rest_length, spring.damping = k.damping;
    scene.elements.emplace_back(spring);
  }
  return {scene, initial};
}

// `steps` RK4 steps of the compiled scene's model per iteration from the initial state, one workspace.
void chain_model(benchmark::State& state) {
  const std::int64_t n = state.range(0), steps = chain_steps(n);
  const auto [scene, initial] = chain_scene(bench::springs_drag_chain(static_cast<std::size_t>(n)));
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  const SceneModel& model = compiled.model();
  const Eigen::VectorXd y0 = model.coordinates(initial, 0.0);
  Eigen::VectorXd y = y0;
  auto work = workspace<Rk4>(model, y);
  for (auto _ : state) {
    y = y0;  // same size: no allocation
    for (std::int64_t i = 0; i < steps; ++i) Rk4::step(model, y, h, work);
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  set_items(state, n, steps);
}

// The largest |Δy_i| / (ε max(1, |y_i|)) over every p_W, q_WB, v_W, w_B entry after one RK4 step of the
// hand loop and of the scene's model from the same state (ε the machine epsilon): the mismatch in ulps
// of the state's own scale.
double baseline_mismatch_ulps(const bench::SpringsDragChain& c, bench::SpringsDragRk4Baseline& loop) {
  std::vector<double> y_loop = c.y0;
  loop.step(y_loop, h);
  const auto [scene, initial] = chain_scene(c);
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  Eigen::VectorXd y = compiled.model().coordinates(initial, 0.0);
  auto work = workspace<Rk4>(compiled.model(), y);
  Rk4::step(compiled.model(), y, h, work);
  const double eps = std::numeric_limits<double>::epsilon();
  double ulps = 0.0;
  for (std::size_t i = 0; i < y_loop.size(); ++i) {  // the scene's rigid bodies lie in y as the loop's, 13 each
    const double scale = std::max(1.0, std::abs(y_loop[i]));
    ulps = std::max(ulps, std::abs(y[static_cast<Eigen::Index>(i)] - y_loop[i]) / (eps * scale));
  }
  return ulps;
}

void chain_loop(benchmark::State& state) {
  const std::int64_t n = state.range(0), steps = chain_steps(n);
  const bench::SpringsDragChain c = bench::springs_drag_chain(static_cast<std::size_t>(n));
  bench::SpringsDragRk4Baseline loop(c);
  // Both evaluate the same equations with other roundings (R_WB as a matrix vs the quaternion product,
  // the wrenches summed in another order). After one step from the same state an entry y_i differs by
  //   - the last rounding of y + h/6 (k1 + 2 k2 + 2 k3 + k4) and of the renormalisation: ≤ 2 ε |y_i|;
  //   - h times the rates' rounding: each rate is a sum of ≤ 10 terms of ≤ 20 roundings each, ≤ 200 ε A
  //     with A ≤ 100 (m/s², rad/s²: springs of 20 and 50 N/m stretched ≤ 0.5 m on 1 kg, arms ≤ 0.2 m on
  //     0.1 kg m²), so h · 200 ε A ≤ 20 ε;
  //   - the spring lengths from positions |p_W| ≤ N m, known to ε N m each, which moves the force by
  //     k ε N and v_W by h k ε N / m ≤ 1e-3 · 50 · 200 ε = 10 ε;
  // so |Δy_i| ≲ 32 ε max(1, |y_i|); the bound 256 ε max(1, |y_i|) leaves a margin of 8. A term missing or
  // wrong moves y by at least h times its smallest rate (the angular drag, d₁ |w_B| / I ≈ 0.03 rad/s²:
  // 3e-5 rad/s, about 1e11 ε): far above it.
  constexpr double bound_ulps = 256.0;
  const double ulps = baseline_mismatch_ulps(c, loop);
  state.counters["mismatch_ulps"] = ulps;
  if (!(ulps <= bound_ulps)) {
    state.SkipWithError("the hand loop and the scene integrate different motions");
    return;
  }
  std::vector<double> y = c.y0;
  for (auto _ : state) {
    std::copy(c.y0.begin(), c.y0.end(), y.begin());
    for (std::int64_t i = 0; i < steps; ++i) loop.step(y, h);
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  set_items(state, n, steps);
}

void chain_sizes(benchmark::internal::Benchmark* b) {
  const std::int64_t largest = bench::bench_size(200, 10);
  for (const std::int64_t n : {10, 200})
    if (n <= largest) b->Arg(n);
  b->Unit(benchmark::kMicrosecond);
}

}  // namespace

BENCHMARK(chain_model)->Name("springs_drag_rk4:rigiddyn")->Apply(chain_sizes);
BENCHMARK(chain_loop)->Name("springs_drag_rk4:baseline")->Apply(chain_sizes);
