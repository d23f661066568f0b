// Dynamics in a moving frame, performance: ns per RK4 step, each next to a hand-written loop of
// the same method on plain double arrays in the same run (bench_main.cpp prints rigiddyn/baseline).
//   rotating_particle_rk4        the fast model RotatingFrameParticleModel (one particle in a frame turning at
//                                a constant rate, under gravity) vs a hand loop with the centrifugal and
//                                Coriolis terms inline and the same outputs: p, v, t and the three works.
//   rotating_particle_scene_rk4  the generic SceneModel on the same scene (the terms through its visit),
//                                vs the same hand loop: what the fast path saves.
//   inertial_particle_rk4        the particle's layout without a frame (a term not declared costs nothing; under
//                                gravity alone the layout carries p, v and t, gravity's work exact from the
//                                records) vs the same hand loop without frame terms (p, v and the work of gravity).
// callgrind (instructions per step): every n-step loop is one out-of-line function (model_rk4<Model>,
// hand_rotating_rk4, hand_inertial_rk4); per step = its inclusive Ir / (calls × n), n = 2000 under
// RIGIDDYN_BENCH_SMALL=1:
//   RIGIDDYN_BENCH_SMALL=1 valgrind --tool=callgrind --callgrind-out-file=/tmp/cg.out \
//     build/<dir>/bench/bench_moving_frame --benchmark_min_time=0.01
//   callgrind_annotate --inclusive=yes /tmp/cg.out | grep -E "model_rk4|hand_"   (Ir; calls: --tree=caller)
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "rigiddyn/integrators/rk4.hpp"
#include "rigiddyn/scene/one_body_scene.hpp"
#include "rigiddyn/scene/elements/fictitious_forces.hpp"
#include "rigiddyn/scene/fast/rotating_frame_particle_model.hpp"
#include "rigiddyn/scene/scene_model.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace rigiddyn;

std::int64_t steps() { return bench::bench_size(200000, 2000); }
constexpr double h = 1e-3;
constexpr double mass = 2.0;
const Eigen::Vector3d axis_F(0.0, 0.6, 0.8);
constexpr double rate = 0.5;
const Eigen::Vector3d g_F(0.0, 0.0, -9.81);
const Eigen::Vector3d p0(1.0, 0.0, 0.0), v0(1.0, 2.0, 3.0);

// The baselines take their parameters at run time, as the library does (bench_dynamics.cpp: compile-time
// constants would let the compiler fold a zero component away). Read through a volatile: GCC 12 gave
// garbage for a double passed through benchmark::DoNotOptimize's "+m,r" constraint here (NaN states).
template <class T>
T at_run_time(T value) {
  volatile T opaque = value;
  return opaque;
}

#if defined(__GNUC__) || defined(__clang__)
#define BASELINE_INLINE_LAMBDA __attribute__((always_inline))
#else
#define BASELINE_INLINE_LAMBDA
#endif

// ---- the hand loops ------------------------------------------------------------------------------------

// Each loop of n steps is one out-of-line function (the hand loops and the models' loops alike), so that
// callgrind counts its instructions per call: Ir(function) / (calls × n) is the cost of one step.

// RK4 on y = (p 3, v 3, t, W_g, W_cf, W_co): v̇ = g − Ω × (Ω × p) − 2 Ω × v, the powers m g·v, m a_cf·v,
// m a_co·v; `n` steps of h from y.
BENCH_NOINLINE void hand_rotating_rk4(double* y, std::int64_t n) {
  const double w[3] = {at_run_time(rate * axis_F[0]), at_run_time(rate * axis_F[1]), at_run_time(rate * axis_F[2])};
  const double g[3] = {at_run_time(g_F[0]), at_run_time(g_F[1]), at_run_time(g_F[2])}, m = at_run_time(mass);
  auto rate_of = [&](const double* s, double* d) BASELINE_INLINE_LAMBDA {
    const double c0 = w[1] * s[2] - w[2] * s[1], c1 = w[2] * s[0] - w[0] * s[2], c2 = w[0] * s[1] - w[1] * s[0];  // Ω × p
    const double cf[3] = {c1 * w[2] - c2 * w[1], c2 * w[0] - c0 * w[2], c0 * w[1] - c1 * w[0]};               // −Ω × (Ω × p)
    const double co[3] = {-2.0 * (w[1] * s[5] - w[2] * s[4]), -2.0 * (w[2] * s[3] - w[0] * s[5]), -2.0 * (w[0] * s[4] - w[1] * s[3])};
    for (int i = 0; i < 3; ++i) d[i] = s[3 + i], d[3 + i] = g[i] + cf[i] + co[i];
    d[6] = 1.0;
    d[7] = m * (g[0] * s[3] + g[1] * s[4] + g[2] * s[5]);
    d[8] = m * (cf[0] * s[3] + cf[1] * s[4] + cf[2] * s[5]);
    d[9] = m * (co[0] * s[3] + co[1] * s[4] + co[2] * s[5]);
  };
  for (std::int64_t it = 0; it < n; ++it) {
    double k1[10], k2[10], k3[10], k4[10], t[10];
    rate_of(y, k1);
    for (int i = 0; i < 10; ++i) t[i] = y[i] + 0.5 * h * k1[i];
    rate_of(t, k2);
    for (int i = 0; i < 10; ++i) t[i] = y[i] + 0.5 * h * k2[i];
    rate_of(t, k3);
    for (int i = 0; i < 10; ++i) t[i] = y[i] + h * k3[i];
    rate_of(t, k4);
    for (int i = 0; i < 10; ++i) y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
  }
}

// RK4 on y = (p 3, v 3, W_g): v̇ = g, the power m g·v
BENCH_NOINLINE void hand_inertial_rk4(double* y, std::int64_t n) {
  const double g[3] = {at_run_time(g_F[0]), at_run_time(g_F[1]), at_run_time(g_F[2])}, m = at_run_time(mass);
  auto rate_of = [&](const double* s, double* d) BASELINE_INLINE_LAMBDA {
    for (int i = 0; i < 3; ++i) d[i] = s[3 + i], d[3 + i] = g[i];
    d[6] = m * (g[0] * s[3] + g[1] * s[4] + g[2] * s[5]);
  };
  for (std::int64_t it = 0; it < n; ++it) {
    double k1[7], k2[7], k3[7], k4[7], t[7];
    rate_of(y, k1);
    for (int i = 0; i < 7; ++i) t[i] = y[i] + 0.5 * h * k1[i];
    rate_of(t, k2);
    for (int i = 0; i < 7; ++i) t[i] = y[i] + 0.5 * h * k2[i];
    rate_of(t, k3);
    for (int i = 0; i < 7; ++i) t[i] = y[i] + h * k3[i];
    rate_of(t, k4);
    for (int i = 0; i < 7; ++i) y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
  }
}

void initial_rotating(double* y) {
  const double y0[10] = {p0[0], p0[1], p0[2], v0[0], v0[1], v0[2], 0.0, 0.0, 0.0, 0.0};
  std::copy(y0, y0 + 10, y);
}

// ---- the models ------------------------------------------------------------------------------------------

const SceneFrame& frame() {
  static const SceneFrame f = SceneFrame::rotating(axis_F, rate);
  return f;
}

// n RK4 steps of a model from y
template <class Model>
BENCH_NOINLINE void model_rk4(const Model& model, typename Model::Coordinates& y, std::int64_t n) {
  auto work = workspace<Rk4>(model, y);
  for (std::int64_t i = 0; i < n; ++i) Rk4::step(model, y, h, work);
}

RotatingFrameParticleModel fast_model() { return RotatingFrameParticleModel(Particle(mass), frame(), g_F, 0, 1, 2, 3); }

SceneModel scene_model() {
  const std::vector<Body> bodies{Particle(mass)};
  std::vector<SceneModel::Term> terms;
  terms.emplace_back(UniformGravityTerm(UniformGravity{g_F, {}}, bodies, "elements[0]"));
  terms.emplace_back(CentrifugalTerm(frame(), bodies, "frame.centrifugal"));
  terms.emplace_back(CoriolisTerm(frame(), bodies, "frame.coriolis"));
  return SceneModel(bodies, terms);
}

// The largest difference between steps() steps of the hand loop and of the fast model from the same state,
// relative to 1 + |y_i|: the pair must integrate the same motion (the same operations in other orders: a
// few ulps per step, ≲ 1e-13 after 2e5 steps of a bounded motion in a random walk; 1e-10 leaves a factor
// 1000), else the timings compare different work.
double rotating_mismatch() {
  double y_hand[10];
  initial_rotating(y_hand);
  hand_rotating_rk4(y_hand, steps());
  const RotatingFrameParticleModel model = fast_model();
  RotatingFrameParticleModel::Coordinates y = RotatingFrameParticleModel::coordinates(ParticleState{p0, v0}, 0.0);
  model_rk4(model, y, steps());
  double mismatch = 0.0;
  for (int i = 0; i < 10; ++i) mismatch = std::max(mismatch, std::abs(y[i] - y_hand[i]) / (1.0 + std::abs(y_hand[i])));
  return mismatch;
}

void rotating_particle_rk4(benchmark::State& state) {
  const RotatingFrameParticleModel model = fast_model();
  const std::int64_t n = steps();
  for (auto _ : state) {
    RotatingFrameParticleModel::Coordinates y = RotatingFrameParticleModel::coordinates(ParticleState{p0, v0}, 0.0);
    model_rk4(model, y, n);
    benchmark::DoNotOptimize(y);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void rotating_particle_scene_rk4(benchmark::State& state) {
  const SceneModel model = scene_model();
  const std::int64_t n = steps();
  for (auto _ : state) {
    Eigen::VectorXd y = model.coordinates({ParticleState{p0, v0}}, 0.0);
    model_rk4(model, y, n);
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void hand_rotating(benchmark::State& state) {
  const double mismatch = rotating_mismatch();
  state.counters["max_dy"] = mismatch;
  if (mismatch > 1e-10) {
    state.SkipWithError(("the hand loop and the model integrate different motions: " + std::to_string(mismatch)).c_str());
    return;
  }
  const std::int64_t n = steps();
  for (auto _ : state) {
    double y[10];
    initial_rotating(y);
    hand_rotating_rk4(y, n);
    benchmark::DoNotOptimize(y);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void inertial_particle_rk4(benchmark::State& state) {
  using Layout = OneBodySceneModel<detail::ParticleSlot<detail::FirstPlace>, OneBodyElements::gravity>;
  const Layout layout = one_body_layout_as<Layout>(Particle(mass), g_F, {});
  const std::int64_t n = steps();
  for (auto _ : state) {
    Layout::Coordinates y = layout.coordinates({ParticleState{p0, v0}}, 0.0);
    model_rk4(layout, y, n);
    benchmark::DoNotOptimize(y);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void hand_inertial(benchmark::State& state) {
  const std::int64_t n = steps();
  for (auto _ : state) {
    double y[7] = {p0[0], p0[1], p0[2], v0[0], v0[1], v0[2], 0.0};
    hand_inertial_rk4(y, n);
    benchmark::DoNotOptimize(y);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

}  // namespace

BENCHMARK(rotating_particle_rk4)->Name("rotating_particle_rk4:rigiddyn");
BENCHMARK(hand_rotating)->Name("rotating_particle_rk4:baseline");
BENCHMARK(rotating_particle_scene_rk4)->Name("rotating_particle_scene_rk4:rigiddyn");
BENCHMARK(hand_rotating)->Name("rotating_particle_scene_rk4:baseline");
BENCHMARK(inertial_particle_rk4)->Name("inertial_particle_rk4:rigiddyn");
BENCHMARK(hand_inertial)->Name("inertial_particle_rk4:baseline");
