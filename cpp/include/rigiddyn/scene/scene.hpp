// A scene (issues 11, 12): bodies and the force elements acting on them, as data, with the frame its
// states are relative to and each body's mass flow. Compiling it (scene/compile.hpp) gives the model whose
// derivative evaluates only the declared elements (and the frame's fictitious terms that are not
// identically zero); simulate/step (scene/simulate_scene.hpp) run it.
#pragma once
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/elements/drag.hpp"
#include "rigiddyn/scene/elements/function_force.hpp"
#include "rigiddyn/scene/elements/gravity_gradient.hpp"
#include "rigiddyn/scene/elements/mutual_gravity.hpp"
#include "rigiddyn/scene/elements/point_mass_gravity.hpp"
#include "rigiddyn/scene/elements/scheduled_loads.hpp"
#include "rigiddyn/scene/elements/spring_damper.hpp"
#include "rigiddyn/scene/elements/thrust.hpp"
#include "rigiddyn/scene/elements/uniform_gravity.hpp"
#include "rigiddyn/scene/mass_flow.hpp"
#include "rigiddyn/scene/scene_frame.hpp"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace rigiddyn {

// Every force element a scene can declare (one spec per file under scene/elements/).
using Element = std::variant<UniformGravity, PointMassGravity, MutualGravity, GravityGradient, SpringDamper, Drag,
                             ScheduledLoads, FunctionForce, Thrust>;

// Bodies (each of its own kind: Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody), the
// elements acting on them, the frame F the states are relative to (nullopt: W, inertial; "W" in element
// and state names then means F) and each body's mass flow (empty: every mass constant; else one per body,
// nullopt for a constant mass; a body's mass starts at its mass()).
struct Scene {
  std::vector<Body> bodies;
  std::vector<std::string> body_names;  // same length as bodies (or empty); "" → "body<i>"
  std::vector<Element> elements;
  std::optional<SceneFrame> frame;
  std::vector<std::optional<MassFlow>> mass_flows;
};

// True when body i of the scene has a mass flow.
inline bool has_mass_flow(const Scene& scene, std::size_t i) {
  return i < scene.mass_flows.size() && scene.mass_flows[i].has_value();
}

// The compiled term of each element spec (scene_api.md §2): TermOf<UniformGravity> = UniformGravityTerm, ...
template <class Spec>
struct TermOf;
template <>
struct TermOf<UniformGravity> { using type = UniformGravityTerm; };
template <>
struct TermOf<PointMassGravity> { using type = PointMassGravityTerm; };
template <>
struct TermOf<MutualGravity> { using type = MutualGravityTerm; };
template <>
struct TermOf<GravityGradient> { using type = GravityGradientTerm; };
template <>
struct TermOf<SpringDamper> { using type = SpringDamperTerm; };
template <>
struct TermOf<Drag> { using type = DragTerm; };
template <>
struct TermOf<ScheduledLoads> { using type = ScheduledLoadsTerm; };
template <>
struct TermOf<FunctionForce> { using type = FunctionForceTerm; };
template <>
struct TermOf<Thrust> { using type = ThrustTerm; };

// The name of body i in messages and results: body_names[i], or "body<i>" when it is empty or missing.
inline std::string body_name(const Scene& scene, std::size_t i) {
  if (i < scene.body_names.size() && !scene.body_names[i].empty()) return scene.body_names[i];
  return "body" + std::to_string(i);
}

}  // namespace rigiddyn
