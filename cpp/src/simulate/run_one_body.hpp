// run_one_body and step_one_body (scene/one_body_layouts.hpp) and step_one_body_state (step_one_body_model.hpp): run_scene
// and one step of a one-body layout (or of a fast model), explicitly instantiated per layout in the
// one_body_runs_*.cpp translation units.
#pragma once
#include "rigiddyn/scene/one_body_layouts.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

#include <cstddef>

namespace rigiddyn::detail {

template <class Model>
SceneSimulation run_one_body(const Model& model, const std::vector<BodyState>& initial, const SimulationOptions& options,
                             const std::vector<AppliedLoad>& switch_schedule) {
  return run_scene(model, model.coordinates(initial, options.t0), options, switch_schedule);
}

// One step of options.method from the body's state at options.t0, split at the switch times inside it (run_loop.hpp
// one_step): the coordinates at t0 + dt
template <class Model>
typename Model::Coordinates one_body_step(const Model& model, const std::vector<BodyState>& state,
                                          const SimulationOptions& options, const std::vector<AppliedLoad>& switch_schedule) {
  return one_step(model, model.coordinates(state, options.t0), options, ScenePieces{switch_schedule, model.time_index()});
}

// The body's state after that step (step of a body reads nothing else)
template <class Model>
BodyState step_one_body_state(const Model& model, const std::vector<BodyState>& state, const SimulationOptions& options,
                              const std::vector<AppliedLoad>& switch_schedule) {
  return model.states(one_body_step(model, state, options, switch_schedule))[0];
}

// The step's state at t0 + dt, the body's mass and each element's work over the step as the model records them at the
// step's two ends (as simulate's records of a one-step run: exact gravity's work from its potential)
template <class Model>
SceneState step_one_body(const Model& model, const std::vector<BodyState>& state, const SimulationOptions& options,
                         const std::vector<AppliedLoad>& switch_schedule) {
  const typename Model::Coordinates y = one_body_step(model, state, options, switch_schedule);
  SceneState out;
  out.t = y[model.time_index()];
  out.bodies = model.states(y);
  SceneSimulation ends;
  model.record(model.coordinates(state, options.t0), options.t0, ends);
  model.record(y, out.t, ends);
  out.mass.assign(ends.mass.end() - 1, ends.mass.end());
  out.work.assign(ends.work.end() - static_cast<std::ptrdiff_t>(model.element_count()), ends.work.end());
  return out;
}

}  // namespace rigiddyn::detail

// The explicit instantiations of run_one_body, step_one_body and step_one_body_state (step_one_body_model.hpp) for
// the layout of the slot type SLOT under ELEMENTS
#define RIGIDDYN_RUN_ONE_BODY(SLOT, ELEMENTS)                                                                            \
  template SceneSimulation rigiddyn::detail::run_one_body(                                                             \
      const rigiddyn::OneBodySceneModel<SLOT, rigiddyn::OneBodyElements::ELEMENTS>&, const std::vector<BodyState>&, \
      const SimulationOptions&, const std::vector<AppliedLoad>&);                                                     \
  template SceneState rigiddyn::detail::step_one_body(                                                                 \
      const rigiddyn::OneBodySceneModel<SLOT, rigiddyn::OneBodyElements::ELEMENTS>&, const std::vector<BodyState>&, \
      const SimulationOptions&, const std::vector<AppliedLoad>&);                                                     \
  template BodyState rigiddyn::detail::step_one_body_state(                                                            \
      const rigiddyn::OneBodySceneModel<SLOT, rigiddyn::OneBodyElements::ELEMENTS>&, const std::vector<BodyState>&, \
      const SimulationOptions&, const std::vector<AppliedLoad>&);
