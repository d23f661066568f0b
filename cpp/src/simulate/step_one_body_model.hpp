// Private to cpp/src/simulate: the body's state alone after one step of a one-body scene's fixed-size model (what step
// of a body reads), beside step_one_body_model (scene/one_body_layouts.hpp), which adds the mass and the works.
#pragma once
#include "rigiddyn/scene/one_body_layouts.hpp"

namespace rigiddyn::detail {

// step_one_body_state of each layout (one_body_runs_*.cpp) and fast model (one_body_runs_fast.cpp)
template <class Model>
BodyState step_one_body_state(const Model& model, const std::vector<BodyState>& state, const SimulationOptions& options,
                              const std::vector<AppliedLoad>& switch_schedule);

// The body's state after one step of `one_body` (not monostate) from `state` (step_scene.cpp)
BodyState step_one_body_model_state(const OneBodyModel& one_body, const std::vector<BodyState>& state,
                                    const SimulationOptions& options, const std::vector<AppliedLoad>& switch_schedule);

}  // namespace rigiddyn::detail
