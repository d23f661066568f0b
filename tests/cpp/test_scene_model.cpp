// SceneModel (scene/scene_model.hpp) and compile_scene (scene/compile.hpp): independent bodies in one
// scene move as they do alone, under every method; a particle carries no attitude; N-body momentum is
// conserved to round-off; every refusal and warning of compile and of the scene's simulate/step.
#include <gtest/gtest.h>

#include "test_inputs.hpp"
#include "test_numbers.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

// EXPECT_THAT(text, HasSubstr(part)) without gmock
#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

using rigiddyn::test::kEps;

// Every method that steps (Method::exact is refused for more than one body).
std::vector<Method> stepping_methods() {
  std::vector<Method> out;
  for (const MethodInfo& info : method_table()) {
    if (info.method != Method::exact) out.push_back(info.method);
  }
  return out;
}

using test::tumbling_state;

// A body-fixed force and couple on for t in [t_start, t_end) [s].
using test::window;

// Largest difference between body b's columns of a scene run and a one-body trajectory, over all records.
double largest_difference(const SceneSimulation& scene, std::size_t b, const Trajectory& one) {
  const std::size_t nb = static_cast<std::size_t>(scene.body_count);
  double d = 0.0;
  EXPECT_EQ(scene.size(), one.size());
  for (std::size_t r = 0; r < std::min(scene.size(), one.size()); ++r) {
    for (int i = 0; i < 3; ++i) {
      d = std::max(d, std::abs(scene.p_W[3 * (r * nb + b) + i] - one.p_W[3 * r + i]));
      d = std::max(d, std::abs(scene.v_W[3 * (r * nb + b) + i] - one.v_W[3 * r + i]));
      d = std::max(d, std::abs(scene.w_B[3 * (r * nb + b) + i] - one.w_B[3 * r + i]));
    }
    for (int i = 0; i < 4; ++i) d = std::max(d, std::abs(scene.q_WB[4 * (r * nb + b) + i] - one.q_WB[4 * r + i]));
  }
  return d;
}

// Three independent bodies (rigid under a scheduled window of loads that switches inside a step,
// particle and planar body under gravity in their own frames) in one scene give, for every method, the
// runs each body makes alone on today's one-body models.
TEST(SceneModel, IndependentBodiesMoveAsTheyDoAlone) {
  const RigidBody rigid(2.0, Eigen::Vector3d(1.0, 2.0, 3.0));
  const Particle particle(0.7);
  const PlanarBody planar(1.5, 0.4);
  const Eigen::Vector3d g_W(0.0, 0.0, -9.81), g_plane(0.3, -9.81, 0.0);
  Scene scene;
  scene.bodies = {rigid, particle, planar};
  scene.elements.push_back(ScheduledLoads{0, {window(0.0125, 0.1037)}, Eigen::Vector3d::Zero()});
  scene.elements.push_back(UniformGravity{g_W, {1}});
  scene.elements.push_back(UniformGravity{g_plane, {2}});
  ParticleState p0{Eigen::Vector3d(1.0, 2.0, 3.0), Eigen::Vector3d(-0.5, 0.25, 4.0)};
  PlanarBodyState s0{Eigen::Vector2d(0.3, -0.2), 0.7, Eigen::Vector2d(1.0, 2.0), -1.5};
  for (const Method method : stepping_methods()) {
    SCOPED_TRACE(method_info(method).name);
    SimulationOptions o;
    o.method = method;
    o.dt = 0.01;
    o.steps = 200;
    const SceneSimulation run = simulate(scene, {tumbling_state(), p0, s0}, o);
    SimulationOptions alone = o;
    alone.loads = {window(0.0125, 0.1037)};
    const Trajectory a = simulate(rigid, tumbling_state(), alone);
    // the scene splits every body's step at the switch times: so do the runs alone (a zero load with the
    // same window), else the order-1 methods differ by O(dt²) there
    AppliedLoad same_switches;
    same_switches.t_start = 0.0125, same_switches.t_end = 0.1037;
    alone.loads = {same_switches};
    alone.gravity_W = g_W;
    const Trajectory b = simulate(particle, p0, alone);
    alone.gravity_W = g_plane;
    const Trajectory c = simulate(planar, s0, alone);
    // Bound: the two computations differ only by the association of a few products per step (e.g.
    // (h/m) f against h (f/m), the kick of the exact work formula against today's kick), ≤ 4 ε |y| per
    // component and step (|y| ≤ 60 here: p, v under gravity over 2 s). The difference made at a step reaches
    // the end through the flow's Jacobian, ≤ 10 over 2 s for these motions (|ω| ≤ 1.1 rad/s, Lyapunov rate
    // ≤ |ω|). The implicit midpoint's two solvers (Newton on the rigid body alone, the fixed point in the
    // scene) each stop at a relative correction of 1e-14: 2e-14 |y| per step instead of 4 ε. Over N = 200 steps:
    const double per_step = method == Method::implicit_midpoint ? 2e-14 : 4.0 * kEps;
    const double bound = 200.0 * per_step * 60.0 * 10.0;
    EXPECT_LE(largest_difference(run, 0, a), bound);
    EXPECT_LE(largest_difference(run, 1, b), bound);
    EXPECT_LE(largest_difference(run, 2, c), bound);
  }
}

// Particles carry no attitude: y holds (p, v) for a particle, 13 numbers for a rigid body, then t and
// one work slot per element, then the six impulses; the records give a particle q = identity and ω = 0.
TEST(SceneModel, AParticleCostsNoAttitude) {
  Scene scene;
  scene.bodies = {Particle(1.0), RigidBody(1.0, Eigen::Vector3d(1.0, 1.0, 1.0)), Particle(2.0), PlanarBody(1.0, 1.0)};
  scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {0, 1, 2}});
  scene.elements.push_back(MutualGravity{1.0, 0.0, {}});
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  EXPECT_FALSE(compiled.one_body_path());
  EXPECT_EQ(compiled.model().coordinate_count(), 6 + 13 + 6 + 6 + 1 + 2 + 6);
  EXPECT_EQ(compiled.model().tangent_count(), 6 + 12 + 6 + 6 + 1 + 2 + 6);
  ParticleState p;
  p.p_W = Eigen::Vector3d(3.0, 0.0, 0.0);
  RigidBodyState r;
  r.w_B = Eigen::Vector3d(0.1, 0.2, 0.3);
  ParticleState p2;
  p2.p_W = Eigen::Vector3d(0.0, 4.0, 0.0);
  PlanarBodyState s;
  s.p_W = Eigen::Vector2d(-2.0, -2.0);
  SimulationOptions o;
  o.steps = 3;
  const SceneSimulation run = simulate(compiled, {p, r, p2, s}, o);
  for (std::size_t rec = 0; rec < run.size(); ++rec) {
    for (const std::size_t b : {0u, 2u}) {
      EXPECT_EQ(run.q_WB[4 * (4 * rec + b) + 3], 1.0);
      for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(run.q_WB[4 * (4 * rec + b) + i], 0.0);
        EXPECT_EQ(run.w_B[3 * (4 * rec + b) + i], 0.0);
      }
    }
  }
}

// A run by `method` of `steps` steps of dt [s], recording every `record_every`-th
SimulationOptions run_options(Method method, double dt, std::int64_t steps, std::int64_t record_every) {
  SimulationOptions o;
  o.method = method, o.dt = dt, o.steps = steps, o.record_every = record_every;
  return o;
}

// States at positions[b] [m] and velocities[b] [m/s] (in W): particles for b < particles, then rigid bodies turning at
// w_B = (0.2, -0.1, 0.5) rad/s.
std::vector<BodyState> moving_states(const std::vector<Eigen::Vector3d>& positions,
                                     const std::vector<Eigen::Vector3d>& velocities, std::size_t particles) {
  std::vector<BodyState> states;
  for (std::size_t b = 0; b < positions.size(); ++b) {
    if (b < particles) {
      states.push_back(ParticleState{positions[b], velocities[b]});
    } else {
      RigidBodyState r;
      r.p_W = positions[b], r.v_W = velocities[b], r.w_B = Eigen::Vector3d(0.2, -0.1, 0.5);
      states.push_back(r);
    }
  }
  return states;
}

// MutualGravity between particles and rigid bodies: Σ m v is conserved to round-off by every method
// (the pair forces cancel in every kick and every stage; the methods are linear in the forces).
TEST(SceneModel, NBodyMomentumIsConservedToRoundoff) {
  Scene scene;
  scene.bodies = {Particle(1.0), Particle(2.0), Particle(0.5), RigidBody(1.5, Eigen::Vector3d(1.0, 2.0, 3.0)),
                  RigidBody(0.8, Eigen::Vector3d(0.5, 0.5, 0.5))};
  scene.elements.push_back(MutualGravity{1.0, 0.05, {}});
  const std::vector<BodyState> initial =
      moving_states({{1.0, 0.0, 0.0}, {-1.0, 0.5, 0.0}, {0.0, -1.0, 0.3}, {0.3, 0.2, 1.0}, {-0.4, -0.3, -1.0}},
                    {{0.0, 0.5, 0.1}, {0.1, -0.3, 0.0}, {0.4, 0.0, -0.2}, {0.0, 0.0, 0.3}, {-0.2, 0.1, 0.0}}, 3);
  for (const Method method : stepping_methods()) {
    SCOPED_TRACE(method_info(method).name);
    const SceneSimulation run = simulate(scene, initial, run_options(method, 1e-3, 500, 500));
    ASSERT_EQ(run.size(), 2u);
    // Bound: every step updates each v_b by a Δv_b whose Σ m_b Δv_b is 0 up to the rounding of each term,
    // ≤ 4 ε m_b |v_b| per body and step (|v| ≤ 3 m/s here, Σ m = 5.8 kg); the implicit midpoint's fixed point
    // stops at a relative correction of 1e-14 instead. Over 500 steps:
    const double per_step = method == Method::implicit_midpoint ? 1e-14 : 4.0 * kEps;
    const double bound = 500.0 * per_step * 5.8 * 3.0;
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(run.linear_momentum_W[3 + i], run.linear_momentum_W[i], bound);
  }
}

// Elements that are internal alone (ElementTraits zero_net_wrench: mutual gravity, springs between bodies) leave the
// impulses at 0, exactly, without summing them; the motion and the works are those of the same scene with a term
// that has a net wrench (a zero UniformGravity, which makes the model sum the impulses): the same bits, under every
// method (the implicit midpoint's fixed point stops on the motion's coordinates alone).
// (That each element's forces and moments cancel is test_scene_elements.cpp's, beside its trait.)
TEST(SceneModel, InternalElementsAloneLeaveTheImpulsesAtZero) {
  Scene internal;
  internal.bodies = {Particle(1.0), Particle(2.0), RigidBody(1.5, Eigen::Vector3d(1.0, 2.0, 3.0)),
                     RigidBody(0.8, Eigen::Vector3d(0.5, 0.6, 0.7))};
  internal.elements.push_back(MutualGravity{1.0, 0.05, {}});
  const Eigen::Vector3d offset_2(0.1, 0.2, 0.0), offset_3(0.0, -0.1, 0.3), other_offset_2(0.2, 0.0, 0.1);
  internal.elements.push_back(SpringDamper{2, offset_2, 3, offset_3, 5.0, 0.5, 0.2});
  internal.elements.push_back(SpringDamper{0, Eigen::Vector3d::Zero(), 2, other_offset_2, 3.0, 1.0, 0.1});
  Scene summed = internal;
  summed.elements.push_back(UniformGravity{Eigen::Vector3d::Zero(), {}});
  const std::vector<BodyState> initial =
      moving_states({{1.0, 0.0, 0.0}, {-1.0, 0.5, 0.0}, {0.3, 0.2, 1.0}, {-0.4, -0.3, -1.0}},
                    {{0.0, 0.5, 0.1}, {0.1, -0.3, 0.0}, {0.0, 0.0, 0.3}, {-0.2, 0.1, 0.0}}, 2);
  const std::size_t elements = internal.elements.size();
  for (const Method method : stepping_methods()) {
    SCOPED_TRACE(method_info(method).name);
    const SimulationOptions o = run_options(method, 1e-2, 200, 50);
    const SceneSimulation run = simulate(internal, initial, o), reference = simulate(summed, initial, o);
    ASSERT_EQ(run.size(), 5u);
    ASSERT_EQ(run.impulse_W.size(), 3 * run.size());
    for (std::size_t i = 0; i < run.impulse_W.size(); ++i) {
      EXPECT_EQ(run.impulse_W[i], 0.0);
      EXPECT_EQ(run.angular_impulse_W[i], 0.0);
    }
    EXPECT_EQ(run.p_W, reference.p_W);
    EXPECT_EQ(run.q_WB, reference.q_WB);
    EXPECT_EQ(run.v_W, reference.v_W);
    EXPECT_EQ(run.w_B, reference.w_B);
    for (std::size_t i = 0; i < run.size(); ++i) {
      for (std::size_t e = 0; e < elements; ++e) {
        EXPECT_EQ(run.work[i * elements + e], reference.work[i * (elements + 1) + e]);
      }
    }
  }
}

Scene two_particles() {
  Scene scene;
  scene.bodies = {Particle(1.0), Particle(2.0)};
  return scene;
}

std::string compile_error(const Scene& scene, Method method) {
  try {
    compile_scene(scene, method);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CompileScene, RefusesAnEmptySceneAndBadNames) {
  EXPECT_EQ(compile_error(Scene{}, Method::rk4), "bodies: expected at least one body, got none");
  Scene scene = two_particles();
  scene.body_names = {"a"};
  EXPECT_EQ(compile_error(scene, Method::rk4), "body_names: expected 2 names (one per body) or none, got 1");
  scene.body_names = {"body1", ""};  // "" is named body1 too
  EXPECT_EQ(compile_error(scene, Method::rk4), "body_names[1]: expected a name no other body has, got \"body1\"");
}

TEST(CompileScene, RefusesExactForAnythingButOneTorqueFreeBody) {
  EXPECT_CONTAINS(compile_error(two_particles(), Method::exact),
                  ("method: 'exact' needs one torque-free body under at most uniform gravity and loads through its "
                   "centre of mass (the closed form and constant forces), got 2 bodies and 0 elements"));
  Scene scene;
  scene.bodies = {RigidBody(1.0, Eigen::Vector3d(1.0, 2.0, 3.0))};
  EXPECT_NO_THROW(compile_scene(scene, Method::exact));
  scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -1.0), {}});
  EXPECT_NO_THROW(compile_scene(scene, Method::exact));  // today's problem: closed form + a constant force
  scene.elements.push_back(Drag{0.1, 0.0, 0.0, 0.0, {}});
  EXPECT_CONTAINS(compile_error(scene, Method::exact), ("got 1 body and 2 elements (UniformGravity, Drag)"));
}

TEST(CompileScene, WarnsOfVelocityDependentElementsUnderKicks) {
  Scene scene = two_particles();
  scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -1.0), {}});
  scene.elements.push_back(Drag{0.1, 0.0, 0.0, 0.0, {}});
  for (const Method method : {Method::splitting_dlm, Method::splitting_dlm_yoshida4, Method::exact_flow_kick}) {
    const CompiledScene compiled = compile_scene(scene, method);
    ASSERT_EQ(compiled.warnings().size(), 1u);
    EXPECT_CONTAINS(compiled.warnings()[0], ("elements[1] (Drag) is velocity-dependent"));
    EXPECT_CONTAINS(compiled.warnings()[0], ("order 1 in the damping, energy behaviour not symplectic"));
  }
  for (const Method method : {Method::rk4, Method::rkmk4, Method::implicit_midpoint, Method::semi_implicit_euler}) {
    EXPECT_TRUE(compile_scene(scene, method).warnings().empty());
  }
}

TEST(CompileScene, NamesTheBadFieldOfAnElement) {
  Scene scene = two_particles();
  scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -1.0), {}});
  scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -1.0), {0, 2}});
  EXPECT_CONTAINS(compile_error(scene, Method::rk4), ("elements[1].bodies[1]: expected a body index in [0, 2), got 2"));
  scene.elements.pop_back();
  scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, NAN, -1.0), {}});
  EXPECT_CONTAINS(compile_error(scene, Method::rk4), ("elements[1].g_W: expected finite values"));
  scene.elements.pop_back();
  AppliedLoad torque;
  torque.torque = Eigen::Vector3d(0.0, 0.0, 1.0);
  scene.elements.push_back(ScheduledLoads{1, {torque}, Eigen::Vector3d::Zero()});
  EXPECT_EQ(compile_error(scene, Method::rk4),
            "elements[1].loads[0].torque: expected zero (a particle takes no torque), got [0; 0; 1]");
  scene.elements.back() = ScheduledLoads{1, {}, Eigen::Vector3d(0.1, 0.0, 0.0)};
  EXPECT_EQ(compile_error(scene, Method::rk4), "elements[1].point_B: expected zero (a particle is a point), got [0.1; 0; 0]");
  scene.elements.back() = ScheduledLoads{2, {}, Eigen::Vector3d::Zero()};
  EXPECT_EQ(compile_error(scene, Method::rk4), "elements[1].body: expected a body index in [0, 2), got 2");
  AppliedLoad bad;
  bad.t_start = 1.0, bad.t_end = 0.5;
  scene.elements.back() = ScheduledLoads{0, {bad}, Eigen::Vector3d::Zero()};
  EXPECT_CONTAINS(compile_error(scene, Method::rk4), ("elements[1].loads[0]"));
  Scene planar;
  planar.bodies = {PlanarBody(1.0, 1.0)};
  AppliedLoad out_of_plane;
  out_of_plane.force = Eigen::Vector3d(1.0, 0.0, 1.0);
  planar.elements.push_back(ScheduledLoads{0, {out_of_plane}, Eigen::Vector3d::Zero()});
  EXPECT_EQ(compile_error(planar, Method::rk4),
            "elements[0].loads[0].force: expected a force in the xy plane (z = 0), got [1; 0; 1]");
  planar.elements.back() = ScheduledLoads{0, {}, Eigen::Vector3d(0.0, 0.0, 0.5)};
  EXPECT_EQ(compile_error(planar, Method::rk4),
            "elements[0].point_B: expected a point in the body's xy plane (z = 0), got [0; 0; 0.5]");
}

std::string simulate_error(const Scene& scene, const std::vector<BodyState>& initial, const SimulationOptions& o) {
  try {
    simulate(scene, initial, o);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SimulateScene, RefusesOneBodyOptionsAndBadStates) {
  const Scene scene = two_particles();
  const std::vector<BodyState> initial{ParticleState{}, ParticleState{}};
  SimulationOptions o;
  o.steps = 2;
  EXPECT_EQ(simulate_error(scene, initial, o), "(no error)");
  SimulationOptions with_loads = o;
  with_loads.loads.push_back(AppliedLoad{});
  EXPECT_EQ(simulate_error(scene, initial, with_loads),
            "loads: expected none in the options of a scene (declare a ScheduledLoads element), got 1 loads");
  SimulationOptions with_gravity = o;
  with_gravity.gravity_W = Eigen::Vector3d(0.0, 0.0, -9.81);
  EXPECT_EQ(simulate_error(scene, initial, with_gravity),
            "gravity: expected zero in the options of a scene (declare a UniformGravity element), got [0; 0; -9.81]");
  EXPECT_EQ(simulate_error(scene, {ParticleState{}}, o), "initial: expected 2 body states (one per body), got 1");
  EXPECT_EQ(simulate_error(scene, {ParticleState{}, RigidBodyState{}}, o),
            "initial[1]: expected a ParticleState (body 1 'body1' is a particle), got a RigidBodyState");
  ParticleState bad;
  bad.v_W.x() = NAN;
  EXPECT_CONTAINS(simulate_error(scene, {ParticleState{}, bad}, o), ("initial[1].v_W: expected finite values"));
  SimulationOptions bad_dt = o;
  bad_dt.dt = -1.0;
  EXPECT_EQ(simulate_error(scene, initial, bad_dt), "dt: expected a finite number > 0, got -1");
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  SimulationOptions other = o;
  other.method = Method::rkmk4;
  try {
    simulate(compiled, initial, other);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "method: expected the method the scene was compiled for ('rk4'), got 'rkmk4'");
  }
  try {
    step(compiled, {ParticleState{}}, o);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "state: expected 2 body states (one per body), got 1");
  }
}

}  // namespace
}  // namespace rigiddyn
