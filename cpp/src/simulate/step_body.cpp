// step of a particle, a planar body and a rigid body (simulate/simulate.hpp): one step of the layout of the body's
// one-body scene (scene/one_body_scene.hpp), the model simulate of the body runs, built without compiling the scene.
#include "rigiddyn/simulate/simulate.hpp"

#include "check_options.hpp"
#include "step_one_body_model.hpp"

#include "rigiddyn/scene/one_body_scene.hpp"

#include <utility>
#include <variant>
#include <vector>

namespace rigiddyn {

namespace {

// The numbers the layout of a body's one-body scene is made of: the body's kind, mass and inertia, g_W [m/s²], and
// each load's force, torque, frame and window; equal keys, equal layouts
std::vector<double> layout_key(const Body& body, const Eigen::Vector3d& g_W, const std::vector<AppliedLoad>& loads) {
  std::vector<double> key{static_cast<double>(body.index()), mass_of(body), g_W.x(), g_W.y(), g_W.z()};
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
  return key;
}

// one_body_layout(body, g_W, loads), kept from the previous call on this thread when its inputs were the same: a loop
// of steps of one body builds its layout once (the build, an eigen-decomposition of a full inertia among it, costs
// more than an RK4 step)
const OneBodyModel& layout_of(const Body& body, const Eigen::Vector3d& g_W, const std::vector<AppliedLoad>& loads) {
  thread_local std::vector<double> last_key;
  thread_local OneBodyModel last;
  std::vector<double> key = layout_key(body, g_W, loads);
  if (key != last_key || last.index() == 0) {
    last = one_body_layout(body, g_W, loads);  // throws before the cache changes
    last_key = std::move(key);
  }
  return last;
}

// The state after one step of the one-body scene of `body` under o's gravity and loads from `state` (checked)
template <class State>
State step_body(const Body& body, const State& state, const SimulationOptions& o) {
  check_options(o, false);
  return std::get<State>(detail::step_one_body_model_state(layout_of(body, o.gravity_W, o.loads), {BodyState(state)}, o, o.loads));
}

}  // namespace

RigidBodyState step(const RigidBody& body, const RigidBodyState& state, const SimulationOptions& o) {
  return step_body(Body(body), checked_state(state, "state"), o);
}

ParticleState step(const Particle& particle, const ParticleState& state, const SimulationOptions& o) {
  return step_body(Body(particle), checked_state(state), o);
}

PlanarBodyState step(const PlanarBody& body, const PlanarBodyState& state, const SimulationOptions& o) {
  return step_body(Body(body), checked_state(state), o);
}

}  // namespace rigiddyn
