// Compiling a scene (issue 11, items 1 and 3): the scene is checked (bodies, names, every element's own
// checks, the method's compatibility with it) and turned into an immutable CompiledScene that holds the
// model whose derivative evaluates only the declared elements (SceneModel) — or, for exactly today's
// problems (one body under at most one UniformGravity and one ScheduledLoads through the centre of mass),
// the plan to run today's one-body models, bitwise as today's simulate.
#pragma once
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/scene/scene.hpp"
#include "rigiddyn/scene/scene_model.hpp"

#include <memory>
#include <string>
#include <vector>

namespace rigiddyn {

// What `method` supports of a scene, one line for methods() (e.g. "any bodies and elements" or, for
// exact, "one torque-free body, no element").
std::string scene_features(Method method);

// The name of an element spec's type in messages ("UniformGravity", ...).
std::string element_type_name(const Element& element);

// The one-body plan: today's simulate(body, state, options) with gravity_W and loads taken from the
// scene's elements (indices of those elements, -1 when absent).
struct OneBodyPlan {
  Eigen::Vector3d gravity_W = Eigen::Vector3d::Zero();
  std::vector<AppliedLoad> loads;
  int gravity_element = -1;
  int loads_element = -1;
};

// A scene compiled for one method: immutable; cheap to copy (shares its parts).
class CompiledScene {
 public:
  const Scene& scene() const { return *scene_; }
  Method method() const { return method_; }
  // The compatibility warnings of the scene with the method (item 3), each a sentence naming the
  // element: e.g. a velocity-dependent element under a kick-based splitting.
  const std::vector<std::string>& warnings() const { return warnings_; }
  // The generic model (used by step, and by simulate unless one_body_path()).
  const SceneModel& model() const { return *model_; }
  // True when simulate runs today's one-body model (bitwise today's results); then one_body_plan() holds
  // its gravity and loads.
  bool one_body_path() const { return one_body_path_; }
  const OneBodyPlan& one_body_plan() const { return plan_; }
  // Every load of every ScheduledLoads element: their t_start/t_end are the run's switch times.
  const std::vector<AppliedLoad>& switch_schedule() const { return switch_schedule_; }

 private:
  friend CompiledScene compile_scene(const Scene& scene, Method method);
  std::shared_ptr<const Scene> scene_;
  Method method_ = Method::rk4;
  std::vector<std::string> warnings_;
  std::shared_ptr<const SceneModel> model_;
  bool one_body_path_ = false;
  OneBodyPlan plan_;
  std::vector<AppliedLoad> switch_schedule_;
};

// Checks `scene` and compiles it for `method`. Throws std::invalid_argument "<field>: expected ..., got
// ..." for: no bodies ("bodies"); body_names neither empty nor one per body, or a name used twice
// ("body_names[i]"); an element's bad field ("elements[i].<field>", the element's own checks); and a
// method that cannot run the scene ("method": 'exact' needs one torque-free body and no element).
// Velocity-dependent elements under splitting_dlm, splitting_dlm_yoshida4 or exact_flow_kick compile
// with a warning (warnings()).
CompiledScene compile_scene(const Scene& scene, Method method);

namespace detail {

// The compiled terms of the scene's elements, named "elements[i]" in their messages, as alternatives of
// the variant Term (BasicSceneModel<Extra...>::Term).
template <class Term>
std::vector<Term> compile_terms(const Scene& scene) {
  std::vector<Term> terms;
  terms.reserve(scene.elements.size());
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    const std::string name = "elements[" + std::to_string(i) + "]";
    std::visit(
        [&](const auto& spec) {
          using Spec = std::decay_t<decltype(spec)>;
          terms.emplace_back(typename TermOf<Spec>::type(spec, scene.bodies, name));
        },
        scene.elements[i]);
  }
  return terms;
}

// The compatibility of `method` with an element of `traits` named `name` (type `type`): adds a warning
// for a velocity-dependent element under a kick-based splitting.
void check_compatibility(Method method, const ElementTraits& traits, const std::string& name, const std::string& type,
                         std::vector<std::string>& warnings);

// Throws std::invalid_argument for 'exact' on anything but one body without elements (`extra_elements`:
// the user's compiled-in forces besides the scene's elements).
void check_exact(const Scene& scene, Method method, std::size_t extra_elements);

}  // namespace detail

}  // namespace rigiddyn
