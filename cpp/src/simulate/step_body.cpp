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

// one_body_layout(body, g_W, loads), kept from the previous call on this thread when its inputs were the same: a loop
// of steps of one body builds its layout once (the build, an eigen-decomposition of a full inertia among it, costs
// more than an RK4 step)
const OneBodyModel& layout_of(const Body& body, const Eigen::Vector3d& g_W, const std::vector<AppliedLoad>& loads) {
  thread_local std::vector<double> last_key, key;
  thread_local OneBodyModel last;
  one_body_key(body, g_W, loads, key);
  if (!same_one_body_key(key, last_key) || last.index() == 0) {
    last = one_body_layout(body, g_W, loads);  // throws before the cache changes
    last_key.swap(key);
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
