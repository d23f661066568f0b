// Private to cpp/src/simulate: the closed form of method 'exact' on one rigid body (closed_form.cpp), the run of
// simulate for a one-body scene compiled for 'exact' (CompiledScene::closed_form).
#pragma once
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <vector>

namespace rigiddyn::detail {

// The records of the scene's rigid body from initial[0] (checked: a unit quaternion) at t_i = t0 + i dt, i = 0, k, 2k,
// ... and the last step (k = record_every), under the scene's gravity and loads (compiled.one_body_plan()). Throws
// std::invalid_argument naming the load for a torque ("loads[i].torque"), a body-frame force ("loads[i].force") or a
// schedule that is not constant from t0 ("loads"): the closed form covers a torque-free body under constant
// world-frame forces.
SceneSimulation closed_form_simulation(const CompiledScene& compiled, const std::vector<BodyState>& initial,
                                       const SimulationOptions& options);

}  // namespace rigiddyn::detail
