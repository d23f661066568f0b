// Variable mass, performance (target: the variable-mass particle ≤ 1.2× a hand-written loop).
//   variable_mass_particle_rk4   the fast model (scene/fast/variable_mass_particle_model.hpp) stepped by
//                                rigiddyn's Rk4, vs a hand-written RK4 on a double[10] of the same
//                                equations and outputs: p, v, m, t, the work of gravity and of the thrust
//                                (m v̇ = m g + ṁ u_rel, notes eq. (4.36)). The hand loop does not check the
//                                mass (the model does, once per evaluation and per step).
//   variable_mass_particle_scene_rk4  the same scene on the generic SceneModel (what would run it without the
//                                fast model), vs the same hand-written loop (it also integrates the impulses).
// Both loops are out-of-line functions (rk4_model_steps, rk4_hand_steps), so that
//   valgrind --tool=callgrind --toggle-collect='*rk4_model_steps*' (or *rk4_hand_steps*)
// counts the instructions of each alone (Ir / steps: instructions per step).
// ctest runs it with RIGIDDYN_BENCH_SMALL=1 (fewer steps).
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "rigiddyn/integrators/rk4.hpp"
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/fast/variable_mass_particle_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace {

using namespace rigiddyn;

constexpr double h = 1e-4;  // [s]
std::int64_t steps() { return bench::bench_size(200000, 2000); }

// The parameters at run time (compile-time constants would let the compiler fold what no general loop
// can): 1000 kg losing 1 kg/s (980 kg after the 20 s of the full run), exhaust 3 km/s, Earth gravity.
// (Through a volatile: Google Benchmark 1.7.1's DoNotOptimize on a double lvalue under GCC -O3 returned 0
// here.)
double at_run_time(double value) {
  volatile double opaque = value;
  return opaque;
}
Eigen::Vector3d at_run_time(const Eigen::Vector3d& value) {
  return Eigen::Vector3d(at_run_time(value.x()), at_run_time(value.y()), at_run_time(value.z()));
}
struct Rocket {
  double m0 = at_run_time(1000.0), rate = at_run_time(-1.0);
  Eigen::Vector3d u_rel = at_run_time(Eigen::Vector3d(30.0, 0.0, -3000.0)), g = at_run_time(Eigen::Vector3d(0.0, 0.0, -9.81));
  Eigen::Vector3d p0 = Eigen::Vector3d(0.0, 0.0, 0.0), v0 = Eigen::Vector3d(10.0, 0.0, 5.0);
};

VariableMassParticleModel model_of(const Rocket& r) {
  MassFlow flow;
  flow.rate = r.rate;
  Thrust thrust;
  thrust.frame = Frame::world, thrust.u_rel = r.u_rel;
  return VariableMassParticleModel(Particle(r.m0), flow, thrust, 1, r.g, 0, 2);
}

// n RK4 steps of the model, as the run loop (simulate/run_loop.hpp) takes them, without records: on its
// own copies of the model and of y (a y reached through a reference may alias the model's parameters, and
// the compiler then reloads them after every store: 1.3× slower here)
BENCH_NOINLINE void rk4_model_steps(const VariableMassParticleModel& model, VariableMassParticleModel::Coordinates& y,
                                    std::int64_t n) {
  const VariableMassParticleModel local = model;
  VariableMassParticleModel::Coordinates z = y;
  auto work = workspace<Rk4>(local, z);
  for (std::int64_t i = 0; i < n; ++i) Rk4::step(local, z, h, work);
  y = z;
}

// The same rocket as a scene, compiled (its generic model: compiled.model())
CompiledScene scene_of(const Rocket& r) {
  Scene scene;
  scene.bodies = {Particle(r.m0)};
  MassFlow flow;
  flow.rate = r.rate;
  scene.mass_flows = {flow};
  Thrust thrust;
  thrust.frame = Frame::world, thrust.u_rel = r.u_rel;
  scene.elements = {UniformGravity{r.g, {}}, thrust};
  return compile_scene(scene, Method::rk4);
}

// n RK4 steps of the generic model (as rk4_model_steps)
BENCH_NOINLINE void rk4_scene_steps(const SceneModel& model, Eigen::VectorXd& y, std::int64_t n) {
  auto work = workspace<Rk4>(model, y);
  for (std::int64_t i = 0; i < n; ++i) Rk4::step(model, y, h, work);
}

// ---- the hand-written loop: y = (p 3, v 3, m, t, W_gravity, W_thrust) -------------------------------------
struct Hand {
  double g[3], thrust[3], rate;  // thrust = ṁ u_rel [N]
};

RIGIDDYN_ALWAYS_INLINE void hand_rate(const Hand& c, const double* y, double* d) {
  const double inverse_mass = 1.0 / y[6];
  for (int i = 0; i < 3; ++i) d[i] = y[3 + i], d[3 + i] = c.g[i] + inverse_mass * c.thrust[i];
  d[6] = c.rate;
  d[7] = 1.0;
  d[8] = y[6] * (c.g[0] * y[3] + c.g[1] * y[4] + c.g[2] * y[5]);
  d[9] = c.thrust[0] * y[3] + c.thrust[1] * y[4] + c.thrust[2] * y[5];
}

// n RK4 steps of the same equations on local copies (as rk4_model_steps)
BENCH_NOINLINE void rk4_hand_steps(const Hand& parameters, double* state, std::int64_t n) {
  const Hand c = parameters;
  double y[10];
  for (int i = 0; i < 10; ++i) y[i] = state[i];
  for (std::int64_t s = 0; s < n; ++s) {
    double k1[10], k2[10], k3[10], k4[10], t[10];
    hand_rate(c, y, k1);
    for (int i = 0; i < 10; ++i) t[i] = y[i] + 0.5 * h * k1[i];
    hand_rate(c, t, k2);
    for (int i = 0; i < 10; ++i) t[i] = y[i] + 0.5 * h * k2[i];
    hand_rate(c, t, k3);
    for (int i = 0; i < 10; ++i) t[i] = y[i] + h * k3[i];
    hand_rate(c, t, k4);
    for (int i = 0; i < 10; ++i) y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
  }
  for (int i = 0; i < 10; ++i) state[i] = y[i];
}

Hand hand_of(const Rocket& r) {
  Hand c{};
  for (int i = 0; i < 3; ++i) c.g[i] = r.g[i], c.thrust[i] = r.rate * r.u_rel[i];
  c.rate = r.rate;
  return c;
}

// The largest relative difference of the two loops' y after 100 steps: the same arithmetic up to the order
// of a few roundings (a few ulps per step), so anything above 1e-12 means they integrate different things.
BENCH_NOINLINE double mismatch(const Rocket& r) {
  const VariableMassParticleModel model = model_of(r);
  VariableMassParticleModel::Coordinates y = model.coordinates({BodyState(ParticleState{r.p0, r.v0})}, 0.0);
  double z[10];
  for (int i = 0; i < 10; ++i) z[i] = y[i];
  rk4_model_steps(model, y, 100);
  rk4_hand_steps(hand_of(r), z, 100);
  double worst = 0.0;
  for (int i = 0; i < 10; ++i) worst = std::max(worst, std::abs(y[i] - z[i]) / std::max(1.0, std::abs(z[i])));
  return worst;
}

void model_rk4(benchmark::State& state) {
  const Rocket r;
  const VariableMassParticleModel model = model_of(r);
  const std::int64_t n = steps();
  for (auto _ : state) {
    VariableMassParticleModel::Coordinates y = model.coordinates({BodyState(ParticleState{r.p0, r.v0})}, 0.0);
    rk4_model_steps(model, y, n);
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void scene_rk4(benchmark::State& state) {
  const Rocket r;
  const CompiledScene compiled = scene_of(r);
  const SceneModel& model = compiled.model();
  const std::int64_t n = steps();
  for (auto _ : state) {
    Eigen::VectorXd y = model.coordinates({BodyState(ParticleState{r.p0, r.v0})}, 0.0);
    rk4_scene_steps(model, y, n);
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void hand_rk4(benchmark::State& state) {
  const Rocket r;
  const double difference = mismatch(r);
  state.counters["max_rel_dy"] = difference;
  if (difference > 1e-12) {
    state.SkipWithError("the hand loop and the model integrate different motions");
    return;
  }
  const Hand c = hand_of(r);
  const std::int64_t n = steps();
  for (auto _ : state) {
    double y[10] = {r.p0[0], r.p0[1], r.p0[2], r.v0[0], r.v0[1], r.v0[2], r.m0, 0.0, 0.0, 0.0};
    rk4_hand_steps(c, y, n);
    benchmark::DoNotOptimize(y);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * n);
}

}  // namespace

BENCHMARK(model_rk4)->Name("variable_mass_particle_rk4:rigiddyn");
BENCHMARK(hand_rk4)->Name("variable_mass_particle_rk4:baseline");
BENCHMARK(scene_rk4)->Name("variable_mass_particle_scene_rk4:rigiddyn");
BENCHMARK(hand_rk4)->Name("variable_mass_particle_scene_rk4:baseline");
