// The fixed-size models compile_scene chooses for a scene of one body (CompiledScene::one_body_model):
// - the scene model's one-body layouts (scene/one_body_scene_model.hpp): one particle, planar body, rigid body or
//   pinned planar body, in W, without a mass flow, under at most one UniformGravity and one ScheduledLoads; under
//   gravity alone a body takes the layout that integrates its motion alone (OneBodyElements::gravity);
// - the fast models (scene/fast/), each kept for the ratio its header states: a pivoted body in W under gravity and
//   loads (its layout is slower under loads and in RKMK4), a particle in a frame turning at a constant rate, a
//   particle with a constant mass rate and one thrust (neither has a layout: the generic model runs them 5.4× and
//   7.8× slower in RK4).
#pragma once
#include "rigiddyn/scene/fast/pivoted_body_model.hpp"
#include "rigiddyn/scene/fast/rotating_frame_particle_model.hpp"
#include "rigiddyn/scene/fast/variable_mass_particle_model.hpp"
#include "rigiddyn/scene/one_body_scene_model.hpp"
#include "rigiddyn/scene/scene.hpp"
#include "rigiddyn/scene/scene_model.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <stdexcept>
#include <type_traits>
#include <utility>
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

// The fast models
using FastOneBodyModels = std::variant<PivotedBodyModel<SphericalEuler>, PivotedBodyModel<PrincipalEuler>,
                                       PivotedBodyModel<FullEuler>, RotatingFrameParticleModel, VariableMassParticleModel>;

template <class T>
struct is_variant : std::false_type {};
template <class... T>
struct is_variant<std::variant<T...>> : std::true_type {};

// Whether the variant V has the alternative T
template <class T, class V>
struct has_alternative : std::false_type {};
template <class T, class... A>
struct has_alternative<T, std::variant<A...>> : std::disjunction<std::is_same<T, A>...> {};

}  // namespace detail

// The fixed-size model of a one-body scene (std::monostate: the scene has none and runs on SceneModel)
using OneBodyModel =
    std::variant<std::monostate, detail::OneBodyLayoutsOf<OneBodyElements::none>, detail::OneBodyLayoutsOf<OneBodyElements::gravity>,
                 detail::OneBodyLayoutsOf<OneBodyElements::gravity_and_loads>,
                 OneBodySceneModel<detail::PivotedPlanarSlot<detail::FirstPlace>, OneBodyElements::none>,
                 OneBodySceneModel<detail::PivotedPlanarSlot<detail::FirstPlace>, OneBodyElements::gravity>,
                 OneBodySceneModel<detail::PivotedPlanarSlot<detail::FirstPlace>, OneBodyElements::gravity_and_loads>,
                 detail::FastOneBodyModels>;

// The model of type Model in `one_body` (an alternative of it or of one of its variants), or null
template <class Model>
const Model* one_body_model_if(const OneBodyModel& one_body) {
  const Model* out = nullptr;
  std::visit(
      [&](const auto& alternative) {
        using Alternative = std::decay_t<decltype(alternative)>;
        if constexpr (std::is_same_v<Alternative, Model>) {
          out = &alternative;
        } else if constexpr (detail::has_alternative<Model, Alternative>::value) {
          out = std::get_if<Model>(&alternative);
        }
      },
      one_body);
  return out;
}

// The layout of `scene` (checked by compile_scene) with its gravity and loads taken from its compiled `terms`
// (SceneModel::terms), or monostate when the scene is not such a scene.
OneBodyModel one_body_layout_of(const Scene& scene, const std::vector<SceneModel::Term>& terms);

// layout(model) for a layout held by `one_body`, fast(model) for a fast model (both of one return type);
// std::logic_error for monostate (no fixed-size model)
template <class Layout, class Fast>
decltype(auto) visit_one_body(const OneBodyModel& one_body, Layout&& layout, Fast&& fast) {
  using Result = decltype(std::visit(layout, std::declval<const detail::OneBodyLayoutsOf<OneBodyElements::none>&>()));
  return std::visit(
      [&](const auto& alternative) -> Result {
        using Alternative = std::decay_t<decltype(alternative)>;
        if constexpr (std::is_same_v<Alternative, std::monostate>) {
          throw std::logic_error("a one-body path without a model");
        } else if constexpr (std::is_same_v<Alternative, detail::FastOneBodyModels>) {
          return std::visit(fast, alternative);
        } else if constexpr (detail::is_variant<Alternative>::value) {
          return std::visit(layout, alternative);
        } else {
          return layout(alternative);
        }
      },
      one_body);
}

namespace detail {

// run_scene (scene/simulate_scene.hpp) of a layout from the body's state, compiled in its own translation units
// (one_body_runs_*.cpp: the layouts' loops build in parallel)
template <class Model>
SceneSimulation run_one_body(const Model& model, const std::vector<BodyState>& initial, const SimulationOptions& options,
                             const std::vector<AppliedLoad>& switch_schedule);

// step (scene/simulate_scene.hpp) of a layout or a fast model from the body's state, compiled beside the layout's run
// (the fast models' in one_body_runs_fast.cpp)
template <class Model>
SceneState step_one_body(const Model& model, const std::vector<BodyState>& state, const SimulationOptions& options,
                         const std::vector<AppliedLoad>& switch_schedule);

// step of the fixed-size model `one_body` (not monostate) from the body's state (simulate/step_scene.cpp)
SceneState step_one_body_model(const OneBodyModel& one_body, const std::vector<BodyState>& state,
                               const SimulationOptions& options, const std::vector<AppliedLoad>& switch_schedule);

}  // namespace detail

}  // namespace rigiddyn
