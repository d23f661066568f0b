#include "rigiddyn/scene/scene.hpp"

#include "rigiddyn/check.hpp"

#include <stdexcept>
#include <utility>

namespace rigiddyn {

void BodyNameIndex::clear() {
  index_.clear();
  indexed_ = 0;
}

void BodyNameIndex::index_from(const Scene& scene, std::size_t first) {
  // reserved for a whole rebuild only: reserving one more each time a body is added would rehash every
  // few bodies (the bucket counts are primes only a few per cent apart), where growing by itself doubles
  if (first == 0) index_.reserve(scene.bodies.size());
  for (std::size_t i = first; i < scene.bodies.size(); ++i) index_.emplace(body_name(scene, i), i);
  indexed_ = scene.bodies.size();
}

std::optional<std::size_t> BodyNameIndex::find(const Scene& scene, const std::string& name) {
  if (indexed_ > scene.bodies.size()) clear();  // bodies were removed
  if (indexed_ < scene.bodies.size()) index_from(scene, indexed_);
  auto hit = index_.find(name);
  if (hit != index_.end() && body_name(scene, hit->second) != name) {  // renamed in place: start again
    clear();
    index_from(scene, 0);
    hit = index_.find(name);
  }
  if (hit == index_.end()) return std::nullopt;
  return hit->second;
}

std::optional<std::size_t> find_body(Scene& scene, const std::string& name) {
  return scene.name_index.find(scene, name);
}

std::size_t add_body(Scene& scene, Body body, const std::string& name, std::optional<MassFlow> flow) {
  const std::size_t index = scene.bodies.size();
  const std::string effective = name.empty() ? "body" + std::to_string(index) : name;
  if (const auto other = find_body(scene, effective)) {
    throw std::invalid_argument("name: expected a name no other body of the scene has ('" + effective + "' is body " +
                                std::to_string(*other) + "'s), got \"" + name + "\"");
  }
  scene.body_names.resize(index, "");
  scene.bodies.push_back(std::move(body));
  scene.body_names.push_back(name);
  if (flow || !scene.mass_flows.empty()) {  // empty while every mass is constant
    scene.mass_flows.resize(index);
    scene.mass_flows.push_back(std::move(flow));
  }
  return index;
}

std::vector<std::size_t> add_tree(Scene& scene, std::shared_ptr<const Tree> tree, const std::string& name) {
  if (!tree) throw_invalid("tree", "a tree", std::string("none"));
  if (tree->num_links() == 0) throw_invalid("tree", "a tree with at least one link", std::string("a tree with none"));
  if (!tree->gravity().isZero(0.0)) {
    throw_invalid("tree.gravity", "zero in a scene (add a UniformGravity element: it loads every link)",
                  tree->gravity().transpose().eval());
  }
  const std::string prefix = name.empty() ? std::string() : name + ".";
  for (const Link& link : tree->links()) {
    if (const auto other = find_body(scene, prefix + link.name)) {
      throw std::invalid_argument("name: expected names for the links that no other body of the scene has ('" + prefix +
                                  link.name + "' is body " + std::to_string(*other) + "'s), got \"" + name + "\"");
    }
  }
  std::vector<std::size_t> indices;
  for (int i = 0; i < tree->num_links(); ++i) indices.push_back(add_body(scene, TreeLink{tree, i}, prefix + tree->link(i).name));
  return indices;
}

}  // namespace rigiddyn
