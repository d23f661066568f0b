// The scene of one body that simulate and step of a body run, and its layout without a compile
// (scene/one_body_scene.hpp).
#include "rigiddyn/scene/one_body_scene.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/compile.hpp"

#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

namespace rigiddyn {

namespace {

// one_body_scene's checks (std::invalid_argument naming gravity or loads[i]): a PlanarBody's gravity in its plane (the
// plane would take the rest silently), and with_loads, loads that are finite and that the body's kind can take
void check_one_body(const Body& body, const Eigen::Vector3d& g_W, const std::vector<AppliedLoad>& loads, bool with_loads) {
  if (std::holds_alternative<PlanarBody>(body) && g_W.z() != 0.0) {
    throw_invalid("gravity", "gravity in the xy plane (z = 0) for a PlanarBody", g_W);
  }
  if (with_loads) {
    check_loads(loads);
    ScheduledLoadsTerm::check_loads_for_kind(body, loads, "loads");
  }
}

}  // namespace

Scene one_body_scene(const Body& body, const Eigen::Vector3d& g_W, const std::vector<AppliedLoad>& loads,
                     bool with_gravity, bool with_loads) {
  check_one_body(body, g_W, loads, with_loads);
  Scene scene;
  scene.bodies.push_back(body);
  if (with_gravity) scene.elements.push_back(UniformGravity{g_W, {}});
  if (with_loads) scene.elements.push_back(ScheduledLoads{0, loads, Eigen::Vector3d::Zero()});
  return scene;
}

Scene one_body_scene(const Body& body, const Eigen::Vector3d& g_W, const std::vector<AppliedLoad>& loads) {
  return one_body_scene(body, g_W, loads, !g_W.isZero(0.0), !loads.empty());
}

OneBodyModel one_body_layout(const Body& body, const Eigen::Vector3d& g_W, const std::vector<AppliedLoad>& loads) {
  const bool with_gravity = !g_W.isZero(0.0), with_loads = !loads.empty();  // one_body_scene's elements
  check_one_body(body, g_W, loads, with_loads);
  const std::vector<Body> bodies{body};
  std::optional<UniformGravityTerm> gravity;
  std::optional<ScheduledLoadsTerm> schedule;
  const int gravity_element = with_gravity ? 0 : -1, loads_element = with_loads ? gravity_element + 1 : -1;
  if (with_gravity) gravity.emplace(UniformGravity{g_W, {}}, bodies, "elements[0]");
  if (with_loads) {
    schedule.emplace(ScheduledLoads{0, loads, Eigen::Vector3d::Zero()}, bodies,
                     "elements[" + std::to_string(loads_element) + "]");
  }
  return one_body_layout_of(body, std::move(gravity), gravity_element, std::move(schedule), loads_element);
}

void one_body_key(const Body& body, const Eigen::Vector3d& g_W, const std::vector<AppliedLoad>& loads,
                  std::vector<double>& key) {
  // a pinned body's pivot, a gyrostat's wheels are not in the key: two such bodies of one mass would share it
  if (!std::holds_alternative<Particle>(body) && !std::holds_alternative<PlanarBody>(body) &&
      !std::holds_alternative<RigidBody>(body)) {
    throw std::invalid_argument(std::string("one_body_key: expected a Particle, PlanarBody or RigidBody, got a ") +
                                kind_name(body));
  }
  key.assign({static_cast<double>(body.index()), mass_of(body), g_W.x(), g_W.y(), g_W.z()});
  if (const auto* rigid = std::get_if<RigidBody>(&body)) {
    key.insert(key.end(), rigid->inertia_com().data(), rigid->inertia_com().data() + 9);
  } else if (const auto* planar = std::get_if<PlanarBody>(&body)) {
    key.push_back(planar->inertia_zz());
  }
  for (const AppliedLoad& load : loads) {
    key.insert(key.end(), load.force.data(), load.force.data() + 3);
    key.insert(key.end(), load.torque.data(), load.torque.data() + 3);
    key.insert(key.end(), {static_cast<double>(load.frame), load.t_start, load.t_end});
  }
}

bool same_one_body_key(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

}  // namespace rigiddyn
