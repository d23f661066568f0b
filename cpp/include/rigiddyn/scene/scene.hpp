// A scene: bodies and the force elements acting on them, as data, with the frame its
// states are relative to and each body's mass flow. Compiling it (scene/compile.hpp) gives the model whose
// derivative evaluates only the declared elements (and the frame's fictitious terms that are not
// identically zero); simulate/step (scene/simulate_scene.hpp) run it.
#pragma once
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/elements/element_list.hpp"
#include "rigiddyn/scene/mass_flow.hpp"
#include "rigiddyn/scene/scene_frame.hpp"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

namespace rigiddyn {

struct Scene;

// The bodies' names as a hash index (name → body index), so that add_body checks a name in O(1) and adding
// N bodies takes O(N), not the O(N^2) of comparing each name with every body's. A cache of body_name(scene, i):
// find() first indexes the bodies added since it last looked (all of them again if bodies were removed or a
// hit no longer holds its name), so a Scene edited field by field stays usable; a copy starts empty (it
// refills on its first find). Renaming an indexed body in place is not seen until the index is rebuilt;
// compile_scene checks every name again.
class BodyNameIndex {
 public:
  BodyNameIndex() = default;
  BodyNameIndex(const BodyNameIndex&) {}
  BodyNameIndex& operator=(const BodyNameIndex&) {
    clear();
    return *this;
  }
  BodyNameIndex(BodyNameIndex&&) = default;
  BodyNameIndex& operator=(BodyNameIndex&&) = default;
  ~BodyNameIndex() = default;

  // The index of the body of `scene` named `name` (body_name: "body<i>" for an unnamed one), or nullopt.
  std::optional<std::size_t> find(const Scene& scene, const std::string& name);

 private:
  void clear();
  void index_from(const Scene& scene, std::size_t first);  // bodies first.. (keeping an earlier body's name)

  std::unordered_map<std::string, std::size_t> index_;
  std::size_t indexed_ = 0;  // bodies 0..indexed_-1 are in index_
};

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
  BodyNameIndex name_index;  // kept by add_body (a cache: see BodyNameIndex)
};

// Appends `body` named `name` ("": the default "body<i>") with its mass flow (nullopt: a constant mass) and
// returns its index; O(1) expected (the scene's name_index). std::invalid_argument "name: expected a name no
// other body of the scene has ..." when another body has that name.
std::size_t add_body(Scene& scene, Body body, const std::string& name = "",
                     std::optional<MassFlow> flow = std::nullopt);

// Appends every link of `tree` as a body (a TreeLink, the links sharing the tree), in link order, named
// "<name>.<link's name>" (the link's own name when `name` is empty), and returns their indices. Nothing is added
// when it throws std::invalid_argument naming "tree" (none, or a tree without links), "tree.gravity" (not zero: a scene's
// gravity is its UniformGravity element, which loads every link) or "name" (a link's name another body has).
std::vector<std::size_t> add_tree(Scene& scene, std::shared_ptr<const Tree> tree, const std::string& name = "");

// The index of the body named `name` (body_name), or nullopt; O(1) expected (it updates the name index).
std::optional<std::size_t> find_body(Scene& scene, const std::string& name);

// True when body i of the scene has a mass flow.
inline bool has_mass_flow(const Scene& scene, std::size_t i) {
  return i < scene.mass_flows.size() && scene.mass_flows[i].has_value();
}

// The name of body i in messages and results: body_names[i], or "body<i>" when it is empty or missing.
inline std::string body_name(const Scene& scene, std::size_t i) {
  if (i < scene.body_names.size() && !scene.body_names[i].empty()) return scene.body_names[i];
  return "body" + std::to_string(i);
}

}  // namespace rigiddyn
