// The compound pendulum, performance: a PivotedPlanarBody under UniformGravity declared as a scene runs on the scene
// model's one-body layout (scene/one_body_scene_model.hpp); its RK4 steps next to a hand-written RK4 loop of the
// same equations in the same run, and the generic SceneModel's steps of the same scene against the same loop (the
// path the scene took before the layout).
//   compound_pendulum_rk4           the layout's Rk4::step vs the loop
//   compound_pendulum_generic_rk4   SceneModel's Rk4::step vs the loop
// The loop integrates y = (θ, ω, W): θ̇ = ω, I_O ω̇ = (c_W × m g)_z, Ẇ = m g·v_C with c_W = R(θ) c_B and
// v_C = ω ẑ × c_W (plane kinetics about O, Craig); the layout integrates (θ, ω, t) and takes gravity's work from its
// records (V(t0) − V(t), exact), the generic model (θ, ω, t, W). The loop checks that it integrates the same motion
// as the layout (|Δθ|, |Δω| after its steps below 1e-12) before it is timed.
// ctest runs it with RIGIDDYN_BENCH_SMALL=1 (fewer steps).
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "rigiddyn/integrators/rk4.hpp"
#include "rigiddyn/integrators/workspace.hpp"
#include "rigiddyn/scene/compile.hpp"

#include <cmath>
#include <cstdint>

namespace {

using namespace rigiddyn;

constexpr double kH = 1e-3;                      // step [s]
constexpr double kMass = 1.5, kInertia = 0.02;   // [kg], I_C about z [kg m²]
const Eigen::Vector2d kC(0.05, -0.4);            // p_OC_B [m]
const Eigen::Vector3d kG(0.0, -9.81, 0.0);       // in the plane [m/s²]
const PivotedPlanarBodyState kInitial{2.0, 0.5};  // θ [rad] (a large swing), ω [rad/s]

std::int64_t steps() { return bench::bench_size(200000, 2000); }

CompiledScene pendulum_scene() {
  Scene scene;
  scene.bodies = {PivotedPlanarBody(kMass, kInertia, kC)};
  scene.elements = {UniformGravity{kG, {}}};
  return compile_scene(scene, Method::rk4);
}

using Layout = OneBodySceneModel<detail::PivotedPlanarSlot<detail::FirstPlace>, OneBodyElements::gravity>;

const Layout& layout(const CompiledScene& compiled) { return std::get<Layout>(compiled.one_body_model()); }

// ---- the hand-written loop ---------------------------------------------------------------------------
struct LoopPendulum {
  double inverse_I_O;  // 1 / (I_C + m |c|²) [1/(kg m²)]
  double cx, cy;       // p_OC_B [m]
  double fx, fy;       // m g [N]
};

LoopPendulum loop_pendulum() {
  return {1.0 / (kInertia + kMass * kC.squaredNorm()), kC.x(), kC.y(), kMass * kG.x(), kMass * kG.y()};
}

inline void loop_rate(const LoopPendulum& p, const double* y, double* dy) {
  const double s = std::sin(y[0]), c = std::cos(y[0]), w = y[1];
  const double cx = c * p.cx - s * p.cy, cy = s * p.cx + c * p.cy;  // c_W = R(θ) c_B
  dy[0] = w;
  dy[1] = p.inverse_I_O * (cx * p.fy - cy * p.fx);
  dy[2] = p.fx * (-w * cy) + p.fy * (w * cx);
}

BENCH_NOINLINE void steps_baseline(const LoopPendulum& p, double* y, double h, std::int64_t n) {
  double k1[3], k2[3], k3[3], k4[3], s[3];
  for (std::int64_t i = 0; i < n; ++i) {
    loop_rate(p, y, k1);
    for (int j = 0; j < 3; ++j) s[j] = y[j] + 0.5 * h * k1[j];
    loop_rate(p, s, k2);
    for (int j = 0; j < 3; ++j) s[j] = y[j] + 0.5 * h * k2[j];
    loop_rate(p, s, k3);
    for (int j = 0; j < 3; ++j) s[j] = y[j] + h * k3[j];
    loop_rate(p, s, k4);
    for (int j = 0; j < 3; ++j) y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
  }
}

// ---- the models ---------------------------------------------------------------------------------------
template <class Model>
BENCH_NOINLINE void steps_rigiddyn(const Model& model, typename Model::Coordinates& y, double h, std::int64_t n) {
  auto work = workspace<Rk4>(model, y);
  for (std::int64_t i = 0; i < n; ++i) Rk4::step(model, y, h, work);
}

// The largest difference in θ and ω between the loop and the layout after 1000 steps: the same equations rounded
// in other orders (≲ 1000 steps × 1e-15 amplified by the flow over 1 s)
double loop_mismatch() {
  const CompiledScene compiled = pendulum_scene();
  auto y = layout(compiled).coordinates({kInitial}, 0.0);
  steps_rigiddyn(layout(compiled), y, kH, 1000);
  double z[3] = {kInitial.theta, kInitial.omega, 0.0};
  steps_baseline(loop_pendulum(), z, kH, 1000);
  return std::max(std::abs(z[0] - y[0]), std::abs(z[1] - y[1]) / 10.0);
}

void pendulum_baseline(benchmark::State& state) {
  const double mismatch = loop_mismatch();
  state.counters["mismatch"] = mismatch;
  if (!(mismatch < 1e-12)) {
    state.SkipWithError("the hand loop and the layout integrate different motions");
    return;
  }
  const std::int64_t n = steps();
  const LoopPendulum p = loop_pendulum();
  for (auto _ : state) {
    double y[3] = {kInitial.theta, kInitial.omega, 0.0};
    steps_baseline(p, y, kH, n);
    benchmark::DoNotOptimize(y);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * n);
}

template <class Model>
void run_model(benchmark::State& state, const Model& model) {
  const std::int64_t n = steps();
  for (auto _ : state) {
    auto y = model.coordinates({kInitial}, 0.0);
    steps_rigiddyn(model, y, kH, n);
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void pendulum_layout(benchmark::State& state) {
  const CompiledScene compiled = pendulum_scene();
  run_model(state, layout(compiled));
}

void pendulum_generic(benchmark::State& state) {
  const CompiledScene compiled = pendulum_scene();
  run_model(state, compiled.model());
}

}  // namespace

BENCHMARK(pendulum_layout)->Name("compound_pendulum_rk4:rigiddyn")->Unit(benchmark::kMicrosecond);
BENCHMARK(pendulum_baseline)->Name("compound_pendulum_rk4:baseline")->Unit(benchmark::kMicrosecond);
BENCHMARK(pendulum_generic)->Name("compound_pendulum_generic_rk4:rigiddyn")->Unit(benchmark::kMicrosecond);
BENCHMARK(pendulum_baseline)->Name("compound_pendulum_generic_rk4:baseline")->Unit(benchmark::kMicrosecond);
