#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/scene_order.hpp"

#include "rigiddyn/check.hpp"

#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <type_traits>
#include <variant>

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

// The plan of method 'exact' on a scene of one free body (a particle, a planar or a rigid body) in W without a mass
// flow under at most one UniformGravity (in the plane for a planar body) and at most one ScheduledLoads through the
// centre of mass: the closed form for a rigid body, the layout's exact free flow and exact kicks for the others.
// Returns false otherwise.
bool one_body_plan(const Scene& scene, OneBodyPlan& plan) {
  if (scene.bodies.size() != 1 || is_pivoted(scene.bodies[0]) || body_traits(scene.bodies[0]).has_rotors ||
      body_traits(scene.bodies[0]).is_linked || scene.frame || has_mass_flow(scene, 0)) {
    return false;
  }
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

bool has_frame(const Scene& scene) { return scene.frame.has_value(); }

// True when the scene's elements are at most one UniformGravity and one ScheduledLoads (indices into
// `gravity`, `loads`, -1 when absent) and, with allow_thrust, one Thrust (`thrust`)
bool only_gravity_loads_thrust(const Scene& scene, int& gravity, int& loads, int& thrust, bool allow_loads, bool allow_thrust) {
  gravity = loads = thrust = -1;
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    const Element& element = scene.elements[i];
    int* slot = std::holds_alternative<UniformGravity>(element)                 ? &gravity
                : allow_loads && std::holds_alternative<ScheduledLoads>(element) ? &loads
                : allow_thrust && std::holds_alternative<Thrust>(element)        ? &thrust
                                                                                 : nullptr;
    if (!slot || *slot >= 0) return false;
    *slot = static_cast<int>(i);
  }
  return true;
}

// g [m/s²] of the scene's first UniformGravity element (zero without one)
Eigen::Vector3d gravity_of(const Scene& scene) {
  for (const Element& e : scene.elements) {
    if (const auto* u = std::get_if<UniformGravity>(&e)) return u->g_W;
  }
  return Eigen::Vector3d::Zero();
}

// The fast model (scene/fast/, one_body_layouts.hpp) of a scene that is exactly its case, or monostate. The
// compiled element count `element_count` includes the frame's terms (after the user's elements).
OneBodyModel fast_model_of(const Scene& scene, const detail::FrameTermSet& frame, std::size_t element_count) {
  if (scene.bodies.size() != 1) return std::monostate{};
  int gravity = -1, loads = -1, thrust = -1;
  const Body& body = scene.bodies[0];
  const Eigen::Vector3d g = gravity_of(scene);
  if (const auto* pivoted = std::get_if<PivotedBody>(&body)) {
    if (has_frame(scene) || !only_gravity_loads_thrust(scene, gravity, loads, thrust, true, false)) return std::monostate{};
    const ScheduledLoads* l = loads >= 0 ? &std::get<ScheduledLoads>(scene.elements[loads]) : nullptr;
    return with_euler_form(*pivoted, [&](const auto& euler_O) -> detail::FastOneBodyModels {
      using Euler = std::decay_t<decltype(euler_O)>;
      return PivotedBodyModel<Euler>(*pivoted, g, gravity, l ? l->loads : std::vector<AppliedLoad>{}, loads, element_count,
                                     l ? l->point_B : Eigen::Vector3d::Zero());
    });
  }
  const auto* particle = std::get_if<Particle>(&body);
  if (!particle) return std::monostate{};
  if (has_frame(scene) && scene.frame->constant_rotation && !has_mass_flow(scene, 0) &&
      only_gravity_loads_thrust(scene, gravity, loads, thrust, false, false)) {
    const int n = static_cast<int>(scene.elements.size());
    return detail::FastOneBodyModels(RotatingFrameParticleModel(*particle, *scene.frame, g, gravity, frame.centrifugal ? n : -1,
                                      frame.coriolis ? n + (frame.centrifugal ? 1 : 0) : -1, element_count));
  }
  if (!has_frame(scene) && has_mass_flow(scene, 0) && has_constant_rate(*scene.mass_flows[0]) &&
      only_gravity_loads_thrust(scene, gravity, loads, thrust, false, true) && thrust >= 0) {
    const Thrust& t = std::get<Thrust>(scene.elements[thrust]);
    if (t.frame != Frame::world || !t.r_B.isZero(0.0)) return std::monostate{};
    return detail::FastOneBodyModels(
        VariableMassParticleModel(*particle, *scene.mass_flows[0], t, thrust, g, gravity, element_count, body_name(scene, 0)));
  }
  return std::monostate{};
}

// "12.3" (the digits kept, rounded down to one decimal)
std::string one_decimal(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", x);
  return text;
}

// "632.456" or "10000": a distance for a message, to six significant digits
std::string six_digits(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

bool is_splitting(Method method) {
  return method == Method::splitting_dlm || method == Method::splitting_dlm_yoshida4 ||
         method == Method::exact_flow_kick || method == Method::exact;
}

}  // namespace

const char* scene_path_name(ScenePath path) {
  return path == ScenePath::one_body ? "one_body" : "generic";
}

std::string element_type_name(const Element& element) {
  return std::visit(
      [](const auto& spec) -> std::string {
        if constexpr (std::is_same_v<std::decay_t<decltype(spec)>, FunctionForce>) {
          return spec.type_name;  // the name its maker gave it
        } else {
          return std::decay_t<decltype(spec)>::element_type;
        }
      },
      element);
}

std::string scene_features(Method method) {
  switch (method) {
    case Method::exact:
      return "one torque-free body under at most UniformGravity and ScheduledLoads through its centre of mass, or one "
             "torque-free pivoted body (closed form); no moving frame, no mass flow";
    case Method::splitting_dlm:
    case Method::splitting_dlm_yoshida4:
    case Method::exact_flow_kick:
      return "any bodies and elements; velocity-dependent elements (drag, dampers, the Coriolis force) with a warning: "
             "the kick freezes velocities (order 1 in the damping, not symplectic); not a rigid body whose inertia is "
             "a function of its mass";
    default:
      return "any bodies and elements";
  }
}

namespace detail {

void check_compatibility(Method method, const ElementTraits& traits, const std::string& name, const std::string& type,
                         std::vector<std::string>& warnings) {
  if (kick_freezes_velocities(method, traits)) {
    warnings.push_back(name + " (" + type + ") is velocity-dependent, and the kicks of '" + method_info(method).name +
                       "' freeze velocities: order 1 in the damping, energy behaviour not symplectic");
  }
}

void check_exact(const Scene& scene, Method method, std::size_t extra_elements) {
  if (method != Method::exact) return;
  const auto refuse = [&](const std::string& why) {
    throw std::invalid_argument("method: 'exact' needs " + why + ", got " + describe_contents(scene, extra_elements) +
                                "; use 'exact_flow_kick' (or another method) for this scene");
  };
  if (scene.frame) refuse("an inertial scene (no moving frame: its fictitious forces have no closed form)");
  for (std::size_t i = 0; i < scene.mass_flows.size(); ++i) {
    if (scene.mass_flows[i]) refuse("bodies of constant mass (mass_flows[" + std::to_string(i) + "] is given)");
  }
  if (scene.bodies.size() == 1 && is_pivoted(scene.bodies[0])) {
    // the free rotation about O (Euler–Poinsot with I_O) is exact; forces at the centre of mass are
    // torque-free about O only when it is the pivot (c = 0): then uniform gravity and loads through it
    const Body& body = scene.bodies[0];
    const bool at_pivot = std::holds_alternative<PivotedBody>(body) ? std::get<PivotedBody>(body).p_OC_B().isZero(0.0)
                                                                     : std::get<PivotedPlanarBody>(body).p_OC_B().isZero(0.0);
    int gravity = -1, loads = -1, thrust = -1;
    if (extra_elements == 0 && (scene.elements.empty() || (at_pivot && only_gravity_loads_thrust(scene, gravity, loads, thrust, true, false)))) {
      return;
    }
    refuse("a torque-free pivoted body (no element, or its centre of mass at the pivot under at most uniform gravity "
           "and loads through it)");
  }
  OneBodyPlan plan;
  // one free body: the closed form of a rigid body, or the exact free flow of a particle or a planar body (constant
  // forces through the centre of mass are exact in the kicks; a torque is refused when the run meets it)
  if (extra_elements > 0 || !one_body_plan(scene, plan)) {
    refuse("one torque-free body under at most uniform gravity and loads through its centre of mass (the closed form "
           "and constant forces)");
  }
}

// A body with wheels spinning relative to it (a gyrostat) is refused in a moving frame (the fictitious terms hold
// the body's inertia, not its wheels' momentum) and by the methods that need a closed-form free rotation or an
// implicit gyroscopic kick of its Euler form (the splittings, semi_implicit_euler_implicit_gyroscopic)
void check_rotors(const Scene& scene, std::size_t i, Method method) {
  if (!body_traits(scene.bodies[i]).has_rotors) return;
  const std::string body = "body " + std::to_string(i) + " '" + body_name(scene, i) + "' (a " + kind_name(scene.bodies[i]) + ")";
  if (scene.frame) {
    throw std::invalid_argument("frame: expected none in a scene with " + body +
                                " (the fictitious terms do not carry its wheels' momentum), got a moving frame");
  }
  if (is_splitting(method) || method == Method::semi_implicit_euler_implicit_gyroscopic) {
    throw std::invalid_argument("method: expected a method that integrates the whole motion (explicit_euler, "
                                "semi_implicit_euler, rk4, rkmk4, implicit_midpoint) for " + body +
                                ": it has no closed-form free rotation, got '" + method_info(method).name + "'");
  }
}

// A tree's links are consecutive bodies in link order, all of one tree (tree/tree_link.hpp; kinds/tree_slot.hpp
// holds the tree with its first link), whose own gravity is zero (a UniformGravity element loads its links); its
// links have no free motion in closed form: the splittings and the implicit gyroscopic kick are refused
void check_tree_links(const Scene& scene, Method method) {
  const std::size_t n = scene.bodies.size();
  for (std::size_t i = 0; i < n;) {
    const auto* first = std::get_if<TreeLink>(&scene.bodies[i]);
    if (!first) {
      ++i;
      continue;
    }
    const std::string body = "bodies[" + std::to_string(i) + "] '" + body_name(scene, i) + "'";
    if (!first->tree || first->link != 0) {
      throw std::invalid_argument(body + ": expected link 0 of a tree first, its other links after it in order (a tree "
                                         "is added whole), got " + (first->tree ? "link " + std::to_string(first->link) : "no tree"));
    }
    const Tree& tree = *first->tree;
    if (!tree.gravity().isZero(0.0)) {
      throw_invalid(body + ": the tree's gravity", "zero in a scene (declare a UniformGravity element: it loads every link)",
                    tree.gravity().transpose().eval());
    }
    for (int k = 1; k < tree.num_links(); ++k) {
      const std::size_t b = i + static_cast<std::size_t>(k);
      const auto* link = b < n ? std::get_if<TreeLink>(&scene.bodies[b]) : nullptr;
      if (!link || link->tree != first->tree || link->link != k) {
        throw std::invalid_argument("bodies[" + std::to_string(b) + "]: expected link " + std::to_string(k) + " ('" +
                                    tree.link(k).name + "') of the tree whose link 0 is " + body +
                                    " (a tree's links are consecutive bodies, in order), got " +
                                    (b < n ? std::string("a ") + kind_name(scene.bodies[b]) : std::string("no body")));
      }
    }
    if (is_splitting(method) || method == Method::semi_implicit_euler_implicit_gyroscopic || method == Method::exact) {
      throw std::invalid_argument("method: expected a method that integrates the whole motion (explicit_euler, "
                                  "semi_implicit_euler, rk4, rkmk4, implicit_midpoint) for the tree of " + body +
                                  ": its links, held by joints, have no free motion in closed form, got '" +
                                  method_info(method).name + "'");
    }
    i += static_cast<std::size_t>(tree.num_links());
  }
}

void check_scene(const Scene& scene, Method method) {
  method_info(method);  // throws for a Method out of range
  check_names(scene);
  const std::size_t n = scene.bodies.size();
  if (!scene.mass_flows.empty() && scene.mass_flows.size() != n) {
    throw std::invalid_argument("mass_flows: expected " + std::to_string(n) + " entries (one per body) or none, got " +
                                std::to_string(scene.mass_flows.size()));
  }
  for (std::size_t i = 0; i < scene.mass_flows.size(); ++i) {
    if (!scene.mass_flows[i]) continue;
    const std::string name = "mass_flows[" + std::to_string(i) + "]";
    const Body& body = scene.bodies[i];
    if (!std::holds_alternative<Particle>(body) && !std::holds_alternative<RigidBody>(body)) {
      throw std::invalid_argument(name + ": expected none for a " + kind_name(body) +
                                  " (a mass flow applies to particles and rigid bodies), got a MassFlow on body " +
                                  std::to_string(i) + " '" + body_name(scene, i) + "'");
    }
    check_mass_flow(*scene.mass_flows[i], name);
    if (scene.mass_flows[i]->inertia_rule != InertiaRule::function || !std::holds_alternative<RigidBody>(body)) continue;
    if (scene.frame) {
      throw std::invalid_argument(name + ".inertia_rule: expected InertiaRule::scaled in a moving frame (the fictitious "
                                         "torques scale the initial inertia with the mass), got InertiaRule::function");
    }
    if (is_splitting(method)) {
      throw std::invalid_argument("method: expected a method that is not a splitting for a body whose inertia is a "
                                  "function of its mass (" + name + ": the free rotation needs a fixed inertia), got '" +
                                  method_info(method).name + "'");
    }
  }
  for (std::size_t i = 0; i < n; ++i) check_rotors(scene, i, method);
  check_tree_links(scene, method);
  for (std::size_t e = 0; e < scene.elements.size(); ++e) {
    const auto* gradient = std::get_if<GravityGradient>(&scene.elements[e]);
    if (!gradient) continue;
    for (const int b : resolve_bodies(gradient->bodies, n, "elements[" + std::to_string(e) + "]")) {
      if (has_mass_flow(scene, static_cast<std::size_t>(b))) {
        throw std::invalid_argument("elements[" + std::to_string(e) + "].bodies: expected bodies of constant mass (the "
                                    "gravity gradient holds the inertia about the centre of mass), got body " +
                                    std::to_string(b) + " '" + body_name(scene, b) + "' with a mass flow (mass_flows[" +
                                    std::to_string(b) + "])");
      }
    }
  }
}

FrameTermSet frame_term_set(const Scene& scene) { return scene.frame ? scene.frame->terms : FrameTermSet{}; }

std::vector<std::string> body_names_of(const Scene& scene) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) names.push_back(body_name(scene, i));
  return names;
}

}  // namespace detail

CompiledScene compile_scene(const Scene& scene, Method method) {
  detail::check_scene(scene, method);
  std::vector<SceneModel::Term> terms = detail::compile_terms<SceneModel::Term>(scene);
  detail::check_exact(scene, method, 0);
  CompiledScene out;
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    const ElementTraits traits = std::visit([](const auto& term) { return term.traits(); }, terms[i]);
    out.element_names_.push_back("elements[" + std::to_string(i) + "]");
    out.element_types_.push_back(element_type_name(scene.elements[i]));
    out.element_traits_.push_back(traits);
    detail::check_compatibility(method, traits, out.element_names_.back(), out.element_types_.back(), out.warnings_);
  }
  const detail::FrameTermSet frame = detail::frame_term_set(scene);
  const std::pair<bool, const char*> frame_terms[] = {{frame.origin, "origin"}, {frame.euler, "euler"},
                                                      {frame.centrifugal, "centrifugal"}, {frame.coriolis, "coriolis"}};
  const char* const frame_types[] = {"FrameOriginForce", "EulerForce", "CentrifugalForce", "CoriolisForce"};
  for (int k = 0; k < 4; ++k) {
    if (!frame_terms[k].first) continue;
    out.element_names_.push_back(std::string("frame.") + frame_terms[k].second);
    out.element_types_.push_back(frame_types[k]);
    const ElementTraits traits = std::visit([](const auto& term) { return term.traits(); }, terms[out.element_names_.size() - 1]);
    out.element_traits_.push_back(traits);
    // the Coriolis term is velocity-dependent but linear in the velocities: every model's loads kick takes its
    // exact flow (so3/coriolis_flow.hpp exact_linear_kick, the fast particle model's closed form), so the
    // kick-based splittings keep their order with it and warrant no warning
    if (k == 3) continue;
    detail::check_compatibility(method, traits, out.element_names_.back(), out.element_types_.back(), out.warnings_);
  }
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const auto* pivoted = std::get_if<PivotedBody>(&scene.bodies[i]);
    if (!pivoted || !(pivoted->digits_lost() > 6.0)) continue;
    out.warnings_.push_back("bodies[" + std::to_string(i) + "] '" + body_name(scene, i) + "': the pivot is " +
                            six_digits(pivoted->p_OC_B().norm()) + " m from the centre of mass; the inertia about O "
                            "keeps only ~" + one_decimal(16.0 - pivoted->digits_lost()) +
                            " of the 16 digits of the inertia about the centre of mass");
  }
  for (const Body& body : scene.bodies) {  // a gyrostat's motor torques switch at their wheels' t_start and t_end
    if (const auto* gyrostat = std::get_if<Gyrostat>(&body)) {
      for (const Wheel& wheel : gyrostat->wheels()) {
        AppliedLoad window;
        window.t_start = wheel.t_start, window.t_end = wheel.t_end;
        out.switch_schedule_.push_back(window);
      }
    }
  }
  for (const Element& element : scene.elements) {  // the switch times of every element that has some
    std::visit(
        [&](const auto& spec) {
          if constexpr (has_switches<std::decay_t<decltype(spec)>>::value) {
            const std::vector<AppliedLoad> switches = spec.switches();
            out.switch_schedule_.insert(out.switch_schedule_.end(), switches.begin(), switches.end());
          }
        },
        element);
  }
  out.scene_ = std::make_shared<const Scene>(scene);
  out.method_ = method;
  const std::size_t element_count = terms.size();
  out.model_ = std::make_shared<const SceneModel>(scene.bodies, std::move(terms), scene.mass_flows, detail::body_names_of(scene));
  if (method == Method::exact && std::holds_alternative<RigidBody>(scene.bodies[0]) && one_body_plan(scene, out.plan_)) {
    out.path_ = ScenePath::one_body;  // the closed form
  } else if (auto layout = one_body_layout_of(scene, out.model_->terms()); layout.index() != 0) {
    out.path_ = ScenePath::one_body;
    out.one_body_ = std::make_shared<const OneBodyModel>(std::move(layout));
  } else if (auto fast = fast_model_of(scene, frame, element_count); fast.index() != 0) {
    out.path_ = ScenePath::one_body;
    out.one_body_ = std::make_shared<const OneBodyModel>(std::move(fast));
  }
  return out;
}

}  // namespace rigiddyn
