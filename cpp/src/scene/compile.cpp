#include "rigiddyn/scene/compile.hpp"

#include "rigiddyn/check.hpp"

#include <set>
#include <string>

namespace rigiddyn {

namespace {

// "2 bodies and 1 element (UniformGravity)"
std::string describe_contents(const Scene& scene, std::size_t extra_elements) {
  const std::size_t n = scene.bodies.size(), ne = scene.elements.size() + extra_elements;
  std::string text = std::to_string(n) + (n == 1 ? " body" : " bodies") + " and " + std::to_string(ne) +
                     (ne == 1 ? " element" : " elements");
  if (!scene.elements.empty()) {
    text += " (";
    for (std::size_t i = 0; i < scene.elements.size(); ++i) text += (i ? ", " : "") + element_type_name(scene.elements[i]);
    if (extra_elements > 0) text += ", " + std::to_string(extra_elements) + " CustomForce";
    text += ")";
  }
  return text;
}

void check_names(const Scene& scene) {
  const std::size_t n = scene.bodies.size();
  if (n == 0) throw std::invalid_argument("bodies: expected at least one body, got none");
  if (!scene.body_names.empty() && scene.body_names.size() != n) {
    throw std::invalid_argument("body_names: expected " + std::to_string(n) + " names (one per body) or none, got " +
                                std::to_string(scene.body_names.size()));
  }
  std::set<std::string> seen;
  for (std::size_t i = 0; i < n; ++i) {
    const std::string name = body_name(scene, i);
    if (!seen.insert(name).second) {
      throw std::invalid_argument("body_names[" + std::to_string(i) + "]: expected a name no other body has, got \"" +
                                  name + "\"");
    }
  }
}

// The one-body plan when the scene is exactly one of today's problems: one body, at most one
// UniformGravity (in the plane for a planar body, as today's planar simulate requires) and at most one
// ScheduledLoads through the centre of mass. Returns false otherwise.
bool one_body_plan(const Scene& scene, OneBodyPlan& plan) {
  if (scene.bodies.size() != 1) return false;
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    const Element& element = scene.elements[i];
    if (const auto* g = std::get_if<UniformGravity>(&element)) {
      if (plan.gravity_element >= 0) return false;
      if (std::holds_alternative<PlanarBody>(scene.bodies[0]) && g->g_W.z() != 0.0) return false;
      plan.gravity_W = g->g_W;
      plan.gravity_element = static_cast<int>(i);
    } else if (const auto* l = std::get_if<ScheduledLoads>(&element)) {
      if (plan.loads_element >= 0 || !l->point_B.isZero(0.0)) return false;
      plan.loads = l->loads;
      plan.loads_element = static_cast<int>(i);
    } else {
      return false;
    }
  }
  return true;
}

}  // namespace

std::string element_type_name(const Element& element) {
  static const char* const names[] = {"UniformGravity", "PointMassGravity", "MutualGravity", "GravityGradient",
                                      "SpringDamper",   "Drag",             "ScheduledLoads", "FunctionForce"};
  static_assert(std::variant_size_v<Element> == sizeof names / sizeof names[0], "a name per element type");
  return names[element.index()];
}

std::string scene_features(Method method) {
  switch (method) {
    case Method::exact:
      return "one torque-free body under at most UniformGravity and ScheduledLoads through its centre of mass "
             "(closed form)";
    case Method::splitting_dlm:
    case Method::splitting_dlm_yoshida4:
    case Method::exact_flow_kick:
      return "any bodies and elements; velocity-dependent elements (drag, dampers) with a warning: the kick freezes "
             "velocities (order 1 in the damping, not symplectic)";
    default:
      return "any bodies and elements";
  }
}

namespace detail {

void check_compatibility(Method method, const ElementTraits& traits, const std::string& name, const std::string& type,
                         std::vector<std::string>& warnings) {
  const bool kicks = method == Method::splitting_dlm || method == Method::splitting_dlm_yoshida4 ||
                     method == Method::exact_flow_kick;
  if (kicks && traits.velocity_dependent) {
    warnings.push_back(name + " (" + type + ") is velocity-dependent, and the kicks of '" + method_info(method).name +
                       "' freeze velocities: order 1 in the damping, energy behaviour not symplectic");
  }
}

void check_exact(const Scene& scene, Method method, std::size_t extra_elements) {
  if (method != Method::exact) return;
  OneBodyPlan plan;
  // today's problems of one body (the closed form; constant forces through the centre of mass are exact
  // in its kicks; a torque is refused when the run meets it, as by simulate(body, ...))
  if (extra_elements > 0 || !one_body_plan(scene, plan)) {
    throw std::invalid_argument(
        "method: 'exact' needs one torque-free body under at most uniform gravity and loads through its centre "
        "of mass (the closed form and constant forces), got " +
        describe_contents(scene, extra_elements) + "; use 'exact_flow_kick' (or another method) for this scene");
  }
}

}  // namespace detail

CompiledScene compile_scene(const Scene& scene, Method method) {
  method_info(method);  // throws for a Method out of range
  check_names(scene);
  std::vector<SceneModel::Term> terms = detail::compile_terms<SceneModel::Term>(scene);
  detail::check_exact(scene, method, 0);
  CompiledScene out;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    const ElementTraits traits = std::visit([](const auto& term) { return term.traits(); }, terms[i]);
    detail::check_compatibility(method, traits, "elements[" + std::to_string(i) + "]", element_type_name(scene.elements[i]),
                                out.warnings_);
  }
  for (const Element& element : scene.elements) {
    if (const auto* l = std::get_if<ScheduledLoads>(&element)) {
      out.switch_schedule_.insert(out.switch_schedule_.end(), l->loads.begin(), l->loads.end());
    }
  }
  out.scene_ = std::make_shared<const Scene>(scene);
  out.method_ = method;
  out.model_ = std::make_shared<const SceneModel>(scene.bodies, std::move(terms));
  out.one_body_path_ = one_body_plan(scene, out.plan_);
  return out;
}

}  // namespace rigiddyn
