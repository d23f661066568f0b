// The one-body layouts compile_scene chooses (scene/one_body_scene_model.hpp): a scene of one particle, planar body,
// rigid body or pinned planar body, in W, without a mass flow, under at most one UniformGravity and one
// ScheduledLoads. Under gravity alone a body takes the layout that integrates its motion alone
// (OneBodyElements::gravity). A pivoted body keeps its fast model (scene/fast/pivoted_body_model.hpp), measured
// faster than its layout under loads.
#pragma once
#include "rigiddyn/scene/one_body_scene_model.hpp"
#include "rigiddyn/scene/scene.hpp"
#include "rigiddyn/scene/scene_model.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <variant>
#include <vector>

namespace rigiddyn {

namespace detail {

template <OneBodyElements elements>
using OneBodyLayoutsOf =
    std::variant<OneBodySceneModel<ParticleSlot<FirstPlace>, elements>, OneBodySceneModel<PlanarSlot<FirstPlace>, elements>,
                 OneBodySceneModel<RigidSlot<SphericalEuler, FirstPlace>, elements>,
                 OneBodySceneModel<RigidSlot<PrincipalEuler, FirstPlace>, elements>,
                 OneBodySceneModel<RigidSlot<FullEuler, FirstPlace>, elements>>;

}  // namespace detail

// The layout of a one-body scene (std::monostate: the scene has none)
using OneBodyLayout =
    std::variant<std::monostate, detail::OneBodyLayoutsOf<OneBodyElements::none>, detail::OneBodyLayoutsOf<OneBodyElements::gravity>,
                 detail::OneBodyLayoutsOf<OneBodyElements::gravity_and_loads>,
                 OneBodySceneModel<detail::PivotedPlanarSlot<detail::FirstPlace>, OneBodyElements::none>,
                 OneBodySceneModel<detail::PivotedPlanarSlot<detail::FirstPlace>, OneBodyElements::gravity>,
                 OneBodySceneModel<detail::PivotedPlanarSlot<detail::FirstPlace>, OneBodyElements::gravity_and_loads>>;

// The layout of `scene` (checked by compile_scene) with its gravity and loads taken from its compiled `terms`
// (SceneModel::terms), or monostate when the scene is not such a scene.
OneBodyLayout one_body_layout_of(const Scene& scene, const std::vector<SceneModel::Term>& terms);

namespace detail {

// run_scene (scene/simulate_scene.hpp) of a layout from the body's state, compiled in its own translation units
// (one_body_runs_*.cpp: the layouts' loops build in parallel)
template <class Model>
SceneSimulation run_one_body(const Model& model, const std::vector<BodyState>& initial, const SimulationOptions& options,
                             const std::vector<AppliedLoad>& switch_schedule);

}  // namespace detail

}  // namespace rigiddyn
