// run_one_body (scene/one_body_layouts.hpp): run_scene of a one-body layout, explicitly instantiated per layout in
// the one_body_runs_*.cpp translation units.
#pragma once
#include "rigiddyn/scene/one_body_layouts.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

namespace rigiddyn::detail {

template <class Model>
SceneSimulation run_one_body(const Model& model, const std::vector<BodyState>& initial, const SimulationOptions& options,
                             const std::vector<AppliedLoad>& switch_schedule) {
  return run_scene(model, model.coordinates(initial, options.t0), options, switch_schedule);
}

}  // namespace rigiddyn::detail

// The explicit instantiation of run_one_body for the layout of the slot type SLOT under ELEMENTS
#define RIGIDDYN_RUN_ONE_BODY(SLOT, ELEMENTS)                                                                            \
  template SceneSimulation rigiddyn::detail::run_one_body(                                                             \
      const rigiddyn::OneBodySceneModel<SLOT, rigiddyn::OneBodyElements::ELEMENTS>&, const std::vector<BodyState>&, \
      const SimulationOptions&, const std::vector<AppliedLoad>&);
