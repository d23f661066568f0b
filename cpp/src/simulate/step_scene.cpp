// step for scenes (scene/simulate_scene.hpp), on the scene's model for every scene.
#include "rigiddyn/scene/simulate_scene.hpp"

namespace rigiddyn {

SceneState step(const CompiledScene& compiled, const std::vector<BodyState>& state, const SimulationOptions& o) {
  const std::vector<BodyState> states = detail::checked_scene_input(compiled.scene(), compiled.method(), state, o, false, "state");
  detail::check_masses_over_run(compiled.scene(), o, 1);
  const SceneModel& model = compiled.model();
  const Eigen::VectorXd y = detail::one_step(model, model.coordinates(states, o.t0), o,
                                             detail::ScenePieces{compiled.switch_schedule(), model.time_index()});
  SceneState out;
  out.t = y[model.time_index()];
  out.bodies = model.states(y);
  out.mass = model.masses(y);
  for (std::size_t e = 0; e < model.element_count(); ++e) out.work.push_back(y[model.work_index(e)]);
  return out;
}

SceneState step(const Scene& scene, const std::vector<BodyState>& state, const SimulationOptions& options) {
  return step(compile_scene(scene, options.method), state, options);
}

}  // namespace rigiddyn
