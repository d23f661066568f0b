// step for scenes (scene/simulate_scene.hpp): on the fixed-size model simulate runs for a one-body scene (a layout,
// or a fast model: their steps compiled in one_body_runs_*.cpp), on the scene's model for every other scene.
#include "rigiddyn/scene/simulate_scene.hpp"

#include "step_one_body_model.hpp"

namespace rigiddyn {

namespace {

SceneState step_generic(const SceneModel& model, const std::vector<BodyState>& states, const SimulationOptions& o,
                        const std::vector<AppliedLoad>& switch_schedule) {
  const Eigen::VectorXd y =
      detail::one_step(model, model.coordinates(states, o.t0), o, detail::ScenePieces{switch_schedule, model.time_index()});
  SceneState out;
  out.t = y[model.time_index()];
  out.bodies = model.states(y);
  out.mass = model.masses(y);
  for (std::size_t e = 0; e < model.element_count(); ++e) out.work.push_back(y[model.work_index(e)]);
  return out;
}

}  // namespace

SceneState detail::step_one_body_model(const OneBodyModel& one_body, const std::vector<BodyState>& state,
                                       const SimulationOptions& o, const std::vector<AppliedLoad>& switch_schedule) {
  const auto step_model = [&](const auto& model) { return detail::step_one_body(model, state, o, switch_schedule); };
  return visit_one_body(one_body, step_model, step_model);
}

BodyState detail::step_one_body_model_state(const OneBodyModel& one_body, const std::vector<BodyState>& state,
                                            const SimulationOptions& o, const std::vector<AppliedLoad>& switch_schedule) {
  const auto step_model = [&](const auto& model) { return detail::step_one_body_state(model, state, o, switch_schedule); };
  return visit_one_body(one_body, step_model, step_model);
}

SceneState step(const CompiledScene& compiled, const std::vector<BodyState>& state, const SimulationOptions& o) {
  const std::vector<BodyState> states = detail::checked_scene_input(compiled.scene(), compiled.method(), state, o, false, "state");
  detail::check_masses_over_run(compiled.scene(), o, 1);
  if (compiled.one_body_path() && !compiled.closed_form()) {
    return detail::step_one_body_model(compiled.one_body_model(), states, o, compiled.switch_schedule());
  }
  return step_generic(compiled.model(), states, o, compiled.switch_schedule());
}

SceneState step(const Scene& scene, const std::vector<BodyState>& state, const SimulationOptions& options) {
  return step(compile_scene(scene, options.method), state, options);
}

}  // namespace rigiddyn
