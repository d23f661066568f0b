// A heavy top (a PivotedBody) under no element, gravity, and gravity with a body-frame force and torque switched on
// for part of the run: the scene model's one-body layout it would take (scene/one_body_scene_model.hpp, run directly)
// over the fast model compile gives it (scene/fast/pivoted_body_model.hpp, through simulate(scene, ...)), for each
// method, the run's records every 1000th step: the ratios that keep the fast model (its header and
// docs/perf/scenes.md §4.1 state them).
//   one_body_top_<elements>_<method>     the layout's run over the fast model's
// ctest runs it with RIGIDDYN_BENCH_SMALL=1 (fewer steps).
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "rigiddyn/scene/one_body_scene_model.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace {

using namespace rigiddyn;

std::int64_t steps() { return bench::bench_size(100000, 2000); }

const Eigen::Vector3d g_W(0.0, 0.0, -9.81);  // [m/s²]

// A body-frame force and torque on for the first half second
AppliedLoad push() {
  AppliedLoad load{Eigen::Vector3d(0.1, -0.3, 0.2), Eigen::Vector3d(0.3, -0.2, 0.4), Frame::body};
  load.t_end = 0.5;
  return load;
}

enum class Elements { none, gravity, gravity_and_loads };
const char* name_of(Elements e) {
  return e == Elements::none ? "none" : e == Elements::gravity ? "gravity" : "gravity_and_loads";
}

SimulationOptions options(Method method) {
  SimulationOptions o;
  o.method = method, o.dt = 1e-3, o.steps = steps(), o.record_every = 1000;
  return o;
}

PivotedBody top() { return PivotedBody(RigidBody(1.0, Eigen::Vector3d(0.05, 0.05, 0.08)), Eigen::Vector3d(0.0, 0.0, 0.2)); }
PivotedBodyState top_state() {
  PivotedBodyState s;
  s.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()));
  s.w_B = Eigen::Vector3d(0.5, 0.0, 12.0);
  return s;
}
Scene top_scene(Elements elements) {
  Scene scene;
  scene.bodies = {top()};
  if (elements != Elements::none) scene.elements.push_back(UniformGravity{g_W, {}});
  if (elements == Elements::gravity_and_loads) scene.elements.push_back(ScheduledLoads{0, {push()}, Eigen::Vector3d::Zero()});
  return scene;
}

template <OneBodyElements elements>
void top_layout_of(benchmark::State& state, Elements e, Method method) {
  const CompiledScene compiled = compile_scene(top_scene(e), method);
  const SimulationOptions o = options(method);
  const auto& terms = compiled.model().terms();
  std::optional<UniformGravityTerm> gravity;
  std::optional<ScheduledLoadsTerm> loads;
  if (!terms.empty()) gravity = std::get<UniformGravityTerm>(terms[0]);
  if (terms.size() > 1) loads = std::get<ScheduledLoadsTerm>(terms[1]);
  // the slot of the top's inertia (diagonal, not spherical: Euler's equations in principal axes), the only layout
  // compiled here (every slot type would instantiate each method's loop three times over)
  using TopSlot = detail::PivotedSlot<PrincipalEuler, detail::FirstPlace>;
  detail::FirstSlots slots;
  Eigen::Index y = 0, xi = 0;
  detail::add_slot(slots, 0, top(), y, xi);
  const std::vector<TopSlot>& top_slots = std::get<std::vector<TopSlot>>(slots);
  if (top_slots.empty()) {
    state.SkipWithError("the top's inertia does not take the principal-axes slot");
    return;
  }
  const OneBodySceneModel<TopSlot, elements> model(top_slots.front(), 1.0, gravity, 0, loads, 1);
  for (auto _ : state) {
    benchmark::DoNotOptimize(detail::run_scene(model, model.coordinates({top_state()}, o.t0), o, compiled.switch_schedule()));
  }
  state.SetItemsProcessed(state.iterations() * o.steps);
}

void top_layout(benchmark::State& state, Elements e, Method method) {
  if (e == Elements::none) return top_layout_of<OneBodyElements::none>(state, e, method);
  if (e == Elements::gravity) return top_layout_of<OneBodyElements::gravity>(state, e, method);
  top_layout_of<OneBodyElements::gravity_and_loads>(state, e, method);
}

void top_fast(benchmark::State& state, Elements e, Method method) {
  const CompiledScene compiled = compile_scene(top_scene(e), method);
  const SimulationOptions o = options(method);
  for (auto _ : state) benchmark::DoNotOptimize(simulate(compiled, {top_state()}, o));
  state.SetItemsProcessed(state.iterations() * o.steps);
}

const Method methods[] = {Method::rk4, Method::rkmk4, Method::splitting_dlm, Method::splitting_dlm_yoshida4,
                          Method::semi_implicit_euler, Method::implicit_midpoint};

bool register_cases() {
  for (const Elements e : {Elements::none, Elements::gravity, Elements::gravity_and_loads}) {
    for (const Method m : methods) {
      const std::string name = std::string("one_body_top_") + name_of(e) + "_" + method_info(m).name;
      benchmark::RegisterBenchmark((name + ":rigiddyn").c_str(), [e, m](benchmark::State& s) { top_layout(s, e, m); })
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark((name + ":baseline").c_str(), [e, m](benchmark::State& s) { top_fast(s, e, m); })
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}
const bool registered = register_cases();

}  // namespace
