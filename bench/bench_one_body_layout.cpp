// One body as a scene, performance: the scene model's one-body layout (scene/one_body_scene_model.hpp, through
// simulate(scene, ...)) against the one-body model of simulate(body, ...) with the same gravity and loads, for each
// method, a particle, a planar body and a rigid body (principal inertia), with no element, under gravity alone, and under gravity
// and a body-frame force and torque switched on for part of the run. Both through the public entries, the run's
// records every 1000th step (the stepping), and for the rigid body under gravity in RK4 every step (the stepping and
// the recording).
//   one_body_<kind>_<elements>_<method>   the layout's run over the one-body model's run
//   one_body_rigid_gravity_rk4_record_every_step   the same, recording every step: a scene's record holds 16 + 20 per
//                                         body + 2 per element doubles (the momenta, impulses, each element's work and
//                                         power), the one-body model's 19
//   one_body_top_<elements>_<method>     a heavy top: the layout it would take over the fast model it takes
// The layout carries t and, with loads, a work per element and the six impulses (the momentum balance reads them);
// the one-body model carries one work. ctest runs it with RIGIDDYN_BENCH_SMALL=1 (fewer steps).
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "rigiddyn/scene/one_body_scene_model.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using namespace rigiddyn;

std::int64_t steps() { return bench::bench_size(100000, 2000); }

struct BodyCase {
  const char* name;
  Body body;
  BodyState state;
};

// g [m/s²]: in the plane of a planar body
Eigen::Vector3d gravity_of(const Body& body) {
  return std::holds_alternative<PlanarBody>(body) ? Eigen::Vector3d(0.0, -9.81, 0.0) : Eigen::Vector3d(0.0, 0.0, -9.81);
}

// A body-frame force and torque on for the first half second (in the plane and about z for a planar body)
AppliedLoad push(const Body& body) {
  const bool planar = std::holds_alternative<PlanarBody>(body);
  AppliedLoad load{Eigen::Vector3d(0.1, -0.3, planar ? 0.0 : 0.2),
                   planar ? Eigen::Vector3d(0.0, 0.0, 0.4) : Eigen::Vector3d(0.3, -0.2, 0.4), Frame::body};
  load.t_end = 0.5;
  return load;
}

std::vector<BodyCase> bodies() {
  RigidBodyState tumbling;
  tumbling.v_W = Eigen::Vector3d(1.0, 0.0, 0.0), tumbling.w_B = Eigen::Vector3d(0.1, 2.0, 0.1);
  PlanarBodyState spinning;
  spinning.v_W = Eigen::Vector2d(1.0, 2.0), spinning.omega = 2.0;
  return {{"particle", Particle(2.0), ParticleState{Eigen::Vector3d::Zero(), Eigen::Vector3d(1.0, 2.0, 3.0)}},
          {"planar", PlanarBody(1.0, 0.5), spinning},
          {"rigid", RigidBody(1.0, Eigen::Vector3d(1.0, 2.0, 3.0)), tumbling}};
}

enum class Elements { none, gravity, gravity_and_loads };
const char* name_of(Elements e) {
  return e == Elements::none ? "none" : e == Elements::gravity ? "gravity" : "gravity_and_loads";
}

SimulationOptions options(Method method, std::int64_t record_every = 1000) {
  SimulationOptions o;
  o.method = method, o.dt = 1e-3, o.steps = steps(), o.record_every = record_every;
  return o;
}

void layout_run(benchmark::State& state, const BodyCase& c, Elements elements, Method method,
                std::int64_t record_every = 1000) {
  Scene scene;
  scene.bodies = {c.body};
  if (elements != Elements::none) scene.elements.push_back(UniformGravity{gravity_of(c.body), {}});
  const bool loads = elements == Elements::gravity_and_loads && !std::holds_alternative<Particle>(c.body);
  if (loads) scene.elements.push_back(ScheduledLoads{0, {push(c.body)}, Eigen::Vector3d::Zero()});
  const CompiledScene compiled = compile_scene(scene, method);
  const SimulationOptions o = options(method, record_every);
  for (auto _ : state) benchmark::DoNotOptimize(simulate(compiled, {c.state}, o));
  state.SetItemsProcessed(state.iterations() * o.steps);
}

void body_run(benchmark::State& state, const BodyCase& c, Elements elements, Method method,
              std::int64_t record_every = 1000) {
  SimulationOptions o = options(method, record_every);
  if (elements != Elements::none) o.gravity_W = gravity_of(c.body);
  if (elements == Elements::gravity_and_loads && !std::holds_alternative<Particle>(c.body)) o.loads = {push(c.body)};
  for (auto _ : state) {
    if (const auto* p = std::get_if<Particle>(&c.body)) {
      benchmark::DoNotOptimize(simulate(*p, std::get<ParticleState>(c.state), o));
    } else if (const auto* planar = std::get_if<PlanarBody>(&c.body)) {
      benchmark::DoNotOptimize(simulate(*planar, std::get<PlanarBodyState>(c.state), o));
    } else {
      benchmark::DoNotOptimize(simulate(std::get<RigidBody>(c.body), std::get<RigidBodyState>(c.state), o));
    }
  }
  state.SetItemsProcessed(state.iterations() * o.steps);
}

// The heavy top (a PivotedBody), which compile gives its fast model: the layout it would take, run directly
// (run_scene), over the scene's run on the fast model; with no element, under gravity, and under gravity and loads
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
  if (elements != Elements::none) scene.elements.push_back(UniformGravity{gravity_of(scene.bodies[0]), {}});
  if (elements == Elements::gravity_and_loads) scene.elements.push_back(ScheduledLoads{0, {push(scene.bodies[0])}, Eigen::Vector3d::Zero()});
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
  detail::with_first_slot(top(), [&](const auto& slot) {
    using Slot = std::decay_t<decltype(slot)>;
    const OneBodySceneModel<Slot, elements> model(slot, 1.0, gravity, 0, loads, 1);
    for (auto _ : state) {
      benchmark::DoNotOptimize(detail::run_scene(model, model.coordinates({top_state()}, o.t0), o, compiled.switch_schedule()));
    }
  });
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
  for (const BodyCase& c : bodies()) {
    for (const Elements e : {Elements::none, Elements::gravity, Elements::gravity_and_loads}) {
      if (e == Elements::gravity_and_loads && std::holds_alternative<Particle>(c.body)) continue;  // no torque on a point
      for (const Method m : methods) {
        const std::string name = std::string("one_body_") + c.name + "_" + name_of(e) + "_" + method_info(m).name;
        benchmark::RegisterBenchmark((name + ":rigiddyn").c_str(), [c, e, m](benchmark::State& s) { layout_run(s, c, e, m); })
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark((name + ":baseline").c_str(), [c, e, m](benchmark::State& s) { body_run(s, c, e, m); })
            ->Unit(benchmark::kMillisecond);
      }
      if (std::string(c.name) == "rigid" && e == Elements::gravity) {
        const std::string name = "one_body_rigid_gravity_rk4_record_every_step";
        benchmark::RegisterBenchmark((name + ":rigiddyn").c_str(),
                                     [c, e](benchmark::State& s) { layout_run(s, c, e, Method::rk4, 1); })
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark((name + ":baseline").c_str(),
                                     [c, e](benchmark::State& s) { body_run(s, c, e, Method::rk4, 1); })
            ->Unit(benchmark::kMillisecond);
      }
    }
  }
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
