// simulate and step for scenes (docs/scenes.md §5): the run loop of the one-body simulate
// (simulate/run_loop.hpp) on a compiled scene's model, recording every body, the energies, the momenta
// and each element's work and power. Usable from C++ directly; the Python binding releases the GIL
// around simulate (a FunctionForce takes it back in its calls).
//
// Time: y carries t, so every method evaluates time-dependent elements at its own stage times; after
// each step the loop sets y's t to the grid time t0 + i dt (no accumulated rounding). ScheduledLoads are
// piecewise constant: a step that crosses one of their switch times is split there (models/loads.hpp).
#pragma once
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/custom_force.hpp"
#include "rigiddyn/scene/scene_model.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/simulate/run_loop.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <cstdint>
#include <type_traits>
#include <vector>

namespace rigiddyn {

// Runs the compiled scene from the body states `initial` (one per body, of its body's kind) at
// options.t0 for options.steps steps of options.method (which must be the method it was compiled for),
// recording every options.record_every-th step (and the first and the last). A scene of one body
// (CompiledScene::one_body_path) runs on the scene model's one-body layout (scene/one_body_layouts.hpp), which moves
// the body bitwise as SceneModel does; 'exact' on one rigid body runs the closed form of the torque-free motion under
// the scene's constant gravity and loads (its records evaluated at the record times; no stepping).
// Throws std::invalid_argument naming the argument for the checks of the one-body simulate (dt, steps,
// record_every, t0, a recording too large) and: options.loads or options.gravity_W given (a scene
// declares them as elements), another method, a wrong number of states or a state of another kind than
// its body ("initial[i]").
SceneSimulation simulate(const CompiledScene& compiled, const std::vector<BodyState>& initial, const SimulationOptions& options);
// compile_scene(scene, options.method) then the above (its warnings are dropped: compile to read them).
SceneSimulation simulate(const Scene& scene, const std::vector<BodyState>& initial, const SimulationOptions& options);

// One step of options.method from `state` at t = options.t0 [s] to t + options.dt (split at the switch
// times inside it, as simulate), on the model simulate runs (a one-body scene's layout or fast model, so that the
// step is bitwise simulate's first; the scene's model, SceneModel, for the others and for 'exact' on one body);
// returns the states at t + dt, the bodies' masses and each element's work over the step [J]. Same checks as
// simulate (options.steps, record_every and monitor are ignored).
SceneState step(const CompiledScene& compiled, const std::vector<BodyState>& state, const SimulationOptions& options);
SceneState step(const Scene& scene, const std::vector<BodyState>& state, const SimulationOptions& options);

// simulate with C++ forces compiled into the model (scene/custom_force.hpp): the scene's elements and
// then each custom force (named "custom_forces[k]" in messages; their work and power columns follow the
// elements'). Compiles, for the model with these forces, every method's loop in the caller's
// translation unit.
template <class... F>
SceneSimulation simulate(const Scene& scene, const std::vector<BodyState>& initial, const SimulationOptions& options,
                         const CustomForce<F>&... custom);

// The record hook of the run loop (simulate/run_loop.hpp, found by argument-dependent lookup): any scene
// model (SceneModel, the fast models of scene/fast/) records itself.
template <class Model>
void append_state(SceneSimulation& out, double t, const Model& model, const typename Model::Coordinates& y) {
  model.record(y, t, out);
}

namespace detail {

// What a controlled run (scene/controller.hpp) adds to a run of the generic model: the pieces it sets itself (a
// sample and the commands held) and the coordinates it follows. Called at the pieces and after each step, never
// inside one, so that the controlled run shares the plain run's compiled loop.
class RunHooks {
 public:
  virtual void piece(SceneModel& model, double t) = 0;  // instead of model.set_time(t)
  virtual void follow(const Eigen::VectorXd& y) = 0;     // the run's coordinates after a (sub-)step

 protected:
  ~RunHooks() = default;
};

// The scene's Pieces policy for run_loop.hpp: switch times from every ScheduledLoads element, the
// pieces set by the model (set_time) or by the hooks of a controlled run, y's t set after each step.
struct ScenePieces {
  const std::vector<AppliedLoad>& schedule;
  Eigen::Index time_index;
  RunHooks* hooks = nullptr;  // a controlled run's (the generic model only), or none
  template <class Model>
  void set_piece(Model& model, double t) const {
    if constexpr (std::is_same_v<Model, SceneModel>) {
      if (hooks != nullptr) return hooks->piece(model, t);
    }
    model.set_time(t);
  }
  template <class Coordinates>
  void at_time(Coordinates& y, double t) const {
    y[time_index] = t;
    if constexpr (std::is_same_v<Coordinates, Eigen::VectorXd>) {
      if (hooks != nullptr) hooks->follow(y);
    }
  }
};

// ScenePieces of a fixed-size model (a one-body layout, a fast model), whose t sits at time_index in y, known at
// compile time: at_time's store at a constant index leaves y in registers across the steps, where a store at an
// index read at run time puts y in memory at every step (fixed_place_of_t says for which methods).
template <Eigen::Index time_index>
struct FixedScenePieces {
  static constexpr bool t_place_fixed = true;
  const std::vector<AppliedLoad>& schedule;
  template <class Model>
  static void set_piece(Model& model, double t) { model.set_time(t); }
  template <class Coordinates>
  static void at_time(Coordinates& y, double t) { y[time_index] = t; }
};

// Whether a run of Integrator on a fixed-size model writes t at its constant place (FixedScenePieces), chosen per
// method by measurement (docs/perf/scenes.md §4.1): every method but classical RK4. A kick–drift step updates y in
// place sub-step by sub-step, and y in memory cost a particle's splittings 2–3×; RK4 keeps its four rates live to
// the end of the step, and y in registers besides cost a heavy top's step 123 ns against 76 ns with y in memory.
template <class Integrator>
inline constexpr bool fixed_place_of_t = !std::is_same_v<Integrator, Rk4>;

// The checks of simulate/step on the options and the initial states (see simulate above); returns the
// states with their quaternions normalised.
std::vector<BodyState> checked_scene_input(const Scene& scene, Method compiled_method, const std::vector<BodyState>& initial,
                                           const SimulationOptions& options, bool stepping, const char* states_name);

// An empty SceneSimulation with its records reserved (throws std::invalid_argument naming record_every
// for a recording larger than the memory available), `wheels` the gyrostat wheels recorded.
SceneSimulation reserved_scene_simulation(std::int64_t steps, std::int64_t record_every, std::size_t bodies,
                                          std::size_t elements, std::size_t wheels = 0);

// Whether a model records gyrostat wheels (wheel_count(): the generic model; the fast models have none).
template <class Model, class = void>
struct records_wheels : std::false_type {};
template <class Model>
struct records_wheels<Model, std::void_t<decltype(std::declval<const Model&>().wheel_count())>> : std::true_type {};

// The up-front check of each constant mass rate against the run's steps and dt (check_mass_over_run,
// naming `steps`/`dt`): std::invalid_argument when a body runs out of mass within the run.
void check_masses_over_run(const Scene& scene, const SimulationOptions& options, std::int64_t steps);

// run_loop.hpp's run of options.method on `model` (SceneModel or a fast model: any Coordinates) from y, with a
// controlled run's hooks (the generic model only) or none.
template <class Model>
SceneSimulation run_scene(const Model& model, const typename Model::Coordinates& y, const SimulationOptions& o,
                          const std::vector<AppliedLoad>& switch_schedule, RunHooks* hooks = nullptr) {
  std::size_t wheels = 0;
  if constexpr (records_wheels<Model>::value) wheels = model.wheel_count();
  SceneSimulation out = reserved_scene_simulation(o.steps, o.record_every, model.body_count(), model.element_count(), wheels);
  out.estimate_records = o.estimate_records;
  return visit_method(o.method, [&](auto integrator) {
    if constexpr (has_fixed_size<Model> && fixed_place_of_t<decltype(integrator)>) {
      return run<decltype(integrator)>(model, y, o, FixedScenePieces<Model::time_index()>{switch_schedule}, std::move(out));
    } else {
      return run<decltype(integrator)>(model, y, o, ScenePieces{switch_schedule, model.time_index(), hooks}, std::move(out));
    }
  });
}

// run_scene on the scene's generic model, compiled once for every method (simulate_scene.cpp): the plain and the
// controlled runs share it.
SceneSimulation run_generic_scene(const SceneModel& model, const Eigen::VectorXd& y, const SimulationOptions& o,
                                  const std::vector<AppliedLoad>& switch_schedule, RunHooks* hooks);

}  // namespace detail

template <class... F>
SceneSimulation simulate(const Scene& scene, const std::vector<BodyState>& initial, const SimulationOptions& options,
                         const CustomForce<F>&... custom) {
  detail::check_exact(scene, options.method, sizeof...(F));
  const CompiledScene compiled = compile_scene(scene, options.method);
  const std::vector<BodyState> states = detail::checked_scene_input(scene, options.method, initial, options, true, "initial");
  detail::check_masses_over_run(scene, options, options.steps);
  using Model = BasicSceneModel<CustomForceTerm<F>...>;
  std::vector<typename Model::Term> terms = detail::compile_terms<typename Model::Term>(scene);
  std::size_t k = 0;
  (terms.emplace_back(CustomForceTerm<F>(custom, scene.bodies, "custom_forces[" + std::to_string(k++) + "]")), ...);
  const Model model(scene.bodies, std::move(terms), scene.mass_flows, detail::body_names_of(scene));
  return detail::run_scene(model, model.coordinates(states, options.t0), options, compiled.switch_schedule());
}

}  // namespace rigiddyn
