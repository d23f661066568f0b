// Compiling a scene (docs/scenes.md §3): the scene is checked (bodies, names, mass flows,
// every element's own checks, the method's compatibility with it) and turned into an immutable
// CompiledScene that holds the model whose derivative evaluates only the declared elements and the frame's
// fictitious terms that are not identically zero (SceneModel) and, for a scene of one body, the fixed-size model
// simulate runs (scene/one_body_layouts.hpp): the scene model's one-body layout (one particle, planar, rigid or
// pinned planar body under at most one UniformGravity and one ScheduledLoads), or a fast model (scene/fast/: a
// pivoted body under gravity and loads; a particle in a frame turning at a constant rate; a variable-mass particle
// with one thrust) that runs through the same loop and records the same SceneSimulation; 'exact' on one rigid
// body: the closed form of its torque-free motion.
#pragma once
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/scene/one_body_layouts.hpp"
#include "rigiddyn/scene/scene.hpp"
#include "rigiddyn/scene/scene_model.hpp"

#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace rigiddyn {

// What `method` supports of a scene, one line for methods() (e.g. "any bodies and elements" or, for
// exact, "one torque-free body, no element").
std::string scene_features(Method method);

// The name of an element spec's type in messages and records ("UniformGravity", ...; a FunctionForce's type_name).
std::string element_type_name(const Element& element);

// The closed form of method 'exact' on one rigid body: the torque-free motion with the constant gravity_W and loads
// taken from the scene's elements (indices of those elements, -1 when absent).
struct OneBodyPlan {
  Eigen::Vector3d gravity_W = Eigen::Vector3d::Zero();
  std::vector<AppliedLoad> loads;
  int gravity_element = -1;
  int loads_element = -1;
};

// The path simulate runs a compiled scene on.
enum class ScenePath {
  generic,   // SceneModel, any scene
  one_body,  // a fixed-size model of one body (one_body_model: a layout or a fast model; 'exact': the closed form,
             // one_body_plan)
};
// "generic", "one_body"
const char* scene_path_name(ScenePath path);

// A scene compiled for one method: immutable; cheap to copy (shares its parts).
class CompiledScene {
 public:
  const Scene& scene() const { return *scene_; }
  Method method() const { return method_; }
  // The compatibility warnings of the scene with the method, each a sentence naming the
  // element: e.g. a velocity-dependent element under a kick-based splitting.
  const std::vector<std::string>& warnings() const { return warnings_; }
  // The generic model (simulate and step on the generic path).
  const SceneModel& model() const { return *model_; }
  // True when simulate runs a fixed-size model of one body (one_body_model(): a layout, the generic model's
  // arithmetic and bitwise its motion, or a fast model) or, for 'exact' on one rigid body, the closed form of the
  // torque-free motion (one_body_plan() holds its gravity and loads; one_body_model() is then monostate).
  bool one_body_path() const { return path_ == ScenePath::one_body; }
  const OneBodyModel& one_body_model() const { return *one_body_; }
  // True when simulate runs the closed form ('exact' on one rigid body: one_body_plan)
  bool closed_form() const { return one_body_path() && one_body_->index() == 0; }
  const OneBodyPlan& one_body_plan() const { return plan_; }
  // The switch times of the run (their t_start/t_end): every load of every ScheduledLoads element, every element with
  // switches() and every gyrostat wheel's motor-torque window.
  const std::vector<AppliedLoad>& switch_schedule() const { return switch_schedule_; }
  // The path simulate runs.
  ScenePath path() const { return path_; }
  // The compiled terms in the order of the work/power columns: the scene's elements ("elements[i]", their
  // type "UniformGravity", ...), then the frame's fictitious terms that act ("frame.origin", "frame.euler",
  // "frame.centrifugal", "frame.coriolis"; types "FrameOriginForce", "EulerForce", "CentrifugalForce",
  // "CoriolisForce").
  const std::vector<std::string>& element_names() const { return element_names_; }
  const std::vector<std::string>& element_types() const { return element_types_; }
  // What each of those terms depends on and provides (scene/element_traits.hpp), in the same order.
  const std::vector<ElementTraits>& element_traits() const { return element_traits_; }

 private:
  friend CompiledScene compile_scene(const Scene& scene, Method method);
  std::shared_ptr<const Scene> scene_;
  Method method_ = Method::rk4;
  std::vector<std::string> warnings_;
  std::shared_ptr<const SceneModel> model_;
  std::shared_ptr<const OneBodyModel> one_body_ = std::make_shared<const OneBodyModel>();
  OneBodyPlan plan_;
  std::vector<AppliedLoad> switch_schedule_;
  ScenePath path_ = ScenePath::generic;
  std::vector<std::string> element_names_, element_types_;
  std::vector<ElementTraits> element_traits_;
};

// Checks `scene` and compiles it for `method`. Throws std::invalid_argument "<field>: expected ..., got
// ..." for: no bodies ("bodies"); body_names neither empty nor one per body, or a name used twice
// ("body_names[i]"); mass_flows neither empty nor one per body ("mass_flows"), a bad flow or a flow on a
// body that is not a particle or a rigid body ("mass_flows[i]"); an element's bad field
// ("elements[i].<field>", the element's own checks: a Thrust on a body without a mass flow among them); a
// GravityGradient on a body with a mass flow ("elements[i].bodies"); InertiaRule::function in a moving
// frame ("mass_flows[i].inertia_rule"); and a method that cannot run the scene ("method": 'exact' needs one
// torque-free body, no frame and no mass flow; the splitting methods need InertiaRule::scaled).
// Warnings (warnings()): velocity-dependent elements under splitting_dlm, splitting_dlm_yoshida4 or
// exact_flow_kick; a pivoted body whose inertia about O loses more than 6 digits of I_C.
CompiledScene compile_scene(const Scene& scene, Method method);

namespace detail {

// The fictitious terms of the scene's frame that are not identically zero, in the order frame.origin,
// frame.euler, frame.centrifugal, frame.coriolis: none without a frame (or for a frame at rest); the
// centrifugal and Coriolis terms for a constant rotation; those the frame declares for a general motion (every
// term unless SceneFrame::moving was told otherwise).
using FrameTermSet = FictitiousTerms;
FrameTermSet frame_term_set(const Scene& scene);

// The compiled terms of the scene's elements, named "elements[i]" in their messages, then the frame's
// fictitious terms (frame_term_set), as alternatives of the variant Term (BasicSceneModel<Extra...>::Term).
template <class Term>
std::vector<Term> compile_terms(const Scene& scene) {
  std::vector<Term> terms;
  terms.reserve(scene.elements.size() + 4);
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    const std::string name = "elements[" + std::to_string(i) + "]";
    std::visit(
        [&](const auto& spec) {
          using Spec = std::decay_t<decltype(spec)>;
          if constexpr (std::is_same_v<Spec, Thrust>) {
            terms.emplace_back(ThrustTerm(spec, scene.bodies, scene.mass_flows, name));
          } else {
            terms.emplace_back(typename Spec::Term(spec, scene.bodies, name));
          }
        },
        scene.elements[i]);
  }
  const FrameTermSet frame = frame_term_set(scene);
  if (frame.origin) terms.emplace_back(FrameOriginTerm(*scene.frame, scene.bodies, "frame.origin"));
  if (frame.euler) terms.emplace_back(EulerForceTerm(*scene.frame, scene.bodies, "frame.euler"));
  if (frame.centrifugal) terms.emplace_back(CentrifugalTerm(*scene.frame, scene.bodies, "frame.centrifugal"));
  if (frame.coriolis) terms.emplace_back(CoriolisTerm(*scene.frame, scene.bodies, "frame.coriolis"));
  return terms;
}

// The body names of the scene, one per body (body_name)
std::vector<std::string> body_names_of(const Scene& scene);

// The compatibility of `method` with an element of `traits` named `name` (type `type`): adds a warning
// for a velocity-dependent element under a kick-based splitting.
void check_compatibility(Method method, const ElementTraits& traits, const std::string& name, const std::string& type,
                         std::vector<std::string>& warnings);

// Throws std::invalid_argument for 'exact' on anything but one torque-free body (`extra_elements`: the
// user's compiled-in forces besides the scene's elements).
void check_exact(const Scene& scene, Method method, std::size_t extra_elements);

// The checks of the scene's bodies, names and mass flows, and of the method against them (compile_scene's
// list above, but the elements' own checks).
void check_scene(const Scene& scene, Method method);

}  // namespace detail

}  // namespace rigiddyn
