// simulate and step of a scene (scene/simulate_scene.hpp): 'exact' on one body declared as a scene gives the
// closed form's numbers bitwise; the work–energy equation with gravity and springs; a
// time-dependent force is evaluated at every stage time (RK4 keeps order 4 on f(t) = sin t); a
// compiled-in CustomForce equals the type-erased FunctionForce; step equals simulate's first step.
#include <gtest/gtest.h>

#include "test_inputs.hpp"
#include "test_numbers.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace rigiddyn {
namespace {

using rigiddyn::test::kEps;

using test::tumbling_state;

using test::window;

// The scene's columns equal the trajectory's bitwise.
void expect_same_records(const SceneSimulation& scene, const Trajectory& one) {
  EXPECT_EQ(scene.t, one.t);
  EXPECT_EQ(scene.p_W, one.p_W);
  EXPECT_EQ(scene.q_WB, one.q_WB);
  EXPECT_EQ(scene.v_W, one.v_W);
  EXPECT_EQ(scene.w_B, one.w_B);
  EXPECT_EQ(scene.kinetic_energy, one.kinetic_energy);
  EXPECT_EQ(scene.total_energy, one.total_energy);
}

// 'exact' on one body declared as a scene runs the closed form of simulate(body, ...): the same numbers bitwise,
// torque-free and under uniform gravity with constant loads through the centre of mass (every other method runs the
// scene model's one-body layout: test_one_body_layout.cpp).
TEST(SimulateScene, ExactOnOneBodyIsTheClosedFormBitwise) {
  const RigidBody rigid(2.0, Eigen::Vector3d(1.0, 2.0, 3.0));
  const Eigen::Vector3d g_W(0.0, 0.0, -9.81);
  AppliedLoad push;
  push.force = Eigen::Vector3d(0.1, -0.3, 0.2);
  for (const bool loaded : {false, true}) {
    SCOPED_TRACE(loaded ? "gravity and loads" : "torque-free");
    SimulationOptions o;
    o.method = Method::exact;
    o.dt = 0.01;
    o.steps = 100;
    o.record_every = 3;
    Scene scene;
    scene.bodies = {rigid};
    SimulationOptions today = o;
    if (loaded) {
      scene.elements.push_back(UniformGravity{g_W, {}});
      scene.elements.push_back(ScheduledLoads{0, {push}, Eigen::Vector3d::Zero()});
      today.gravity_W = g_W;
      today.loads = {push};
    }
    const CompiledScene compiled = compile_scene(scene, Method::exact);
    ASSERT_TRUE(compiled.one_body_path());
    const SceneSimulation run = simulate(compiled, {tumbling_state()}, o);
    const Trajectory expected = simulate(rigid, tumbling_state(), today);
    expect_same_records(run, expected);
    if (!loaded) continue;
    // the work is split between gravity (−ΔV) and the loads (the rest), which add up to the body's work;
    // the sum rounds once: ≤ ε |work| per record
    for (std::size_t r = 0; r < run.size(); ++r) {
      EXPECT_NEAR(run.work[2 * r] + run.work[2 * r + 1], expected.work[r], 2.0 * kEps * (std::abs(run.work[2 * r]) + std::abs(run.work[2 * r + 1])));
    }
  }
}

// Bodies linked by springs (to each other and to a world anchor, at points off their centres of mass)
// under gravity. With exact_flow_kick the free part keeps every kinetic energy exactly and each kick
// changes it by exactly the work it records, so T2 − T1 = Σ element work to round-off; and the
// elements are conservative, so each element's work is −ΔV_e and T + V is conserved to the method's error.
TEST(SimulateScene, WorkEnergyWithGravityAndSprings) {
  Scene scene;
  scene.bodies = {RigidBody(2.0, Eigen::Vector3d(1.0, 2.0, 3.0)), RigidBody(1.0, Eigen::Vector3d(0.5, 0.5, 0.5)), Particle(0.7)};
  scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}});
  scene.elements.push_back(SpringDamper{0, Eigen::Vector3d(0.3, 0.0, 0.1), 1, Eigen::Vector3d(0.0, -0.2, 0.0), 40.0, 0.5, 0.0});
  scene.elements.push_back(SpringDamper{0, Eigen::Vector3d(0.0, 0.2, 0.0), -1, Eigen::Vector3d(0.0, 0.0, 3.0), 60.0, 0.0, 0.0});
  scene.elements.push_back(SpringDamper{2, Eigen::Vector3d::Zero(), 1, Eigen::Vector3d(0.1, 0.0, 0.0), 25.0, 0.3, 0.0});
  RigidBodyState a = tumbling_state(), b;
  b.p_W = Eigen::Vector3d(1.0, -0.5, 1.5), b.w_B = Eigen::Vector3d(0.0, 2.0, -1.0), b.v_W = Eigen::Vector3d(0.3, 0.0, 0.0);
  const ParticleState c{Eigen::Vector3d(1.5, 0.0, 1.0), Eigen::Vector3d(0.0, 0.2, 0.0)};
  SimulationOptions o;
  o.method = Method::exact_flow_kick;
  o.dt = 1e-3;
  o.steps = 2000;
  o.record_every = 100;
  const SceneSimulation run = simulate(scene, {a, b, c}, o);
  ASSERT_FALSE(run.diverged);
  const std::size_t ne = 4, n = run.size();
  double scale = 0.0;  // the largest |T| and |work| reached [J]
  for (std::size_t r = 0; r < n; ++r) {
    scale = std::max(scale, std::abs(run.kinetic_energy[r]));
    for (std::size_t e = 0; e < ne; ++e) scale = std::max(scale, std::abs(run.work[ne * r + e]));
  }
  for (std::size_t r = 0; r < n; ++r) {
    double work = 0.0;
    for (std::size_t e = 0; e < ne; ++e) work += run.work[ne * r + e];
    // Bound: each of the 2 kicks per step rounds T's change and the work's sum by ≤ 8 ε scale (5 terms of
    // a few products each); the exact free flow keeps ½ ω·I ω to ~16 ε κ T (κ = 3, exact_step_roundoff).
    // Over the steps up to record r:
    const double steps = 100.0 * static_cast<double>(r);
    EXPECT_NEAR(run.kinetic_energy[r] - run.kinetic_energy[0], work, steps * (16.0 + 48.0) * kEps * scale) << "record " << r;
  }
  // T + V is conserved by the exact flow of a conservative scene; the splitting's energy error is
  // O(h²) with a bounded constant: here the force stiffness k/m ≤ 60 s⁻² and |ω| ≤ 2.5 rad/s give
  // (h² /12)(k/m + |ω|²) T-relative ≈ 1e-5; allow 1e-4 of the energy scale.
  for (std::size_t r = 0; r < n; ++r) EXPECT_NEAR(run.total_energy[r], run.total_energy[0], 1e-4 * scale);
}

// A time-dependent force f_W = (sin t, 0, 0) N on a 1 kg particle from t0 ≠ 0 (closed form below). With
// t in y every method evaluates it at its own stage times and keeps its order: the error shrinks by 2^p
// when dt halves (RK4 16, the splittings 4, ...); with the force frozen per step each would be order 1.
TEST(SimulateScene, TimeDependentForceKeepsEveryMethodsOrder) {
  Scene scene;
  scene.bodies = {Particle(1.0)};
  scene.elements.push_back(FunctionForce{{}, [](double t, const BodyKinematics&, int, Eigen::Vector3d& f_W, Eigen::Vector3d&) {
                                           f_W.x() = std::sin(t);
                                         }});
  const ParticleState p0{Eigen::Vector3d::Zero(), Eigen::Vector3d(0.5, 0.0, 0.0)};
  for (const MethodInfo& info : method_table()) {
    if (info.method == Method::exact) continue;  // refused: the particle is not force-free
    SCOPED_TRACE(info.name);
    const auto error = [&](double dt) {
      SimulationOptions o;
      o.method = info.method;
      o.dt = dt;
      o.steps = std::lround(2.0 / dt);
      o.record_every = o.steps;
      o.t0 = 0.3;  // the force reads the absolute time
      const SceneSimulation run = simulate(scene, {p0}, o);
      const double t0 = o.t0, t1 = run.t.back();
      EXPECT_EQ(t1, t0 + static_cast<double>(o.steps) * dt);  // y's t is reset to the grid time
      // v = v0 + ∫_{t0}^{t} sin s ds = v0 + cos t0 − cos t,  x = x0 + (v0 + cos t0)(t − t0) − (sin t − sin t0)
      const double v = 0.5 + std::cos(t0) - std::cos(t1);
      const double x = (0.5 + std::cos(t0)) * (t1 - t0) - (std::sin(t1) - std::sin(t0));
      const std::size_t last = run.size() - 1;
      return std::max(std::abs(run.p_W[3 * last] - x), std::abs(run.v_W[3 * last] - v));
    };
    // the ratio tends to 2^p as dt → 0; at dt = 0.05/0.025 the next term of the error moves it by < 25 %
    // (measured 16.00 for RK4, 4.00 for the splittings); the errors (≥ 1e-10) are far above round-off
    const double ratio = error(0.05) / error(0.025), expected = std::pow(2.0, info.order);
    EXPECT_GT(ratio, 0.75 * expected);
    EXPECT_LT(ratio, 1.25 * expected);
  }
}

// CustomForce<F> compiled in gives the numbers FunctionForce gives (same arithmetic, no indirect call).
TEST(SimulateScene, CustomForceEqualsFunctionForce) {
  const auto force = [](double t, const BodyKinematics& k, int, Eigen::Vector3d& f_W, Eigen::Vector3d& tau_B) {
    f_W = -4.0 * k.p_W + Eigen::Vector3d(std::sin(t), 0.0, 0.0);
    tau_B = Eigen::Vector3d(0.0, 0.1 * std::cos(t), 0.0);
  };
  Scene with_function;
  with_function.bodies = {RigidBody(1.0, Eigen::Vector3d(1.0, 2.0, 3.0)), Particle(2.0)};
  with_function.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -1.0), {}});
  with_function.elements.push_back(FunctionForce{{0}, force});
  Scene bare = with_function;
  bare.elements.pop_back();
  const std::vector<BodyState> initial{tumbling_state(), ParticleState{Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d::Zero()}};
  for (const Method method : {Method::rk4, Method::splitting_dlm, Method::implicit_midpoint}) {
    SimulationOptions o;
    o.method = method;
    o.dt = 0.01;
    o.steps = 100;
    const SceneSimulation a = simulate(with_function, initial, o);
    const SceneSimulation b = simulate(bare, initial, o, custom_force(BodyList{0}, force));
    EXPECT_EQ(a.p_W, b.p_W);
    EXPECT_EQ(a.q_WB, b.q_WB);
    EXPECT_EQ(a.w_B, b.w_B);
    EXPECT_EQ(a.work, b.work);
    EXPECT_EQ(a.power, b.power);
  }
  SimulationOptions exact;
  exact.method = Method::exact;
  Scene one;
  one.bodies = {RigidBody(1.0, Eigen::Vector3d(1.0, 2.0, 3.0))};
  EXPECT_THROW(simulate(one, {tumbling_state()}, exact, custom_force(BodyList{}, force)), std::invalid_argument);
}

// step from the initial state gives simulate's first record, and its time and work.
TEST(SimulateScene, StepIsSimulatesFirstStep) {
  Scene scene;
  scene.bodies = {RigidBody(2.0, Eigen::Vector3d(1.0, 2.0, 3.0)), Particle(1.0)};
  scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}});
  scene.elements.push_back(SpringDamper{0, Eigen::Vector3d(0.1, 0.0, 0.0), 1, Eigen::Vector3d::Zero(), 10.0, 0.0, 0.5});
  scene.elements.push_back(ScheduledLoads{0, {window(0.0031, 0.0077)}, Eigen::Vector3d(0.0, 0.1, 0.0)});
  const std::vector<BodyState> initial{tumbling_state(), ParticleState{Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d::Zero()}};
  for (const MethodInfo& info : method_table()) {
    if (info.method == Method::exact) continue;
    SCOPED_TRACE(info.name);
    SimulationOptions o;
    o.method = info.method;
    o.dt = 0.01;  // the window switches on and off inside the step
    o.steps = 1;
    const SceneSimulation run = simulate(scene, initial, o);
    const SceneState next = step(scene, initial, o);
    EXPECT_EQ(next.t, run.t[1]);
    const auto& r = std::get<RigidBodyState>(next.bodies[0]);
    const auto& p = std::get<ParticleState>(next.bodies[1]);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(r.p_W[i], run.p_W[6 + i]);
      EXPECT_EQ(r.w_B[i], run.w_B[6 + i]);
      EXPECT_EQ(p.v_W[i], run.v_W[9 + i]);
    }
    EXPECT_EQ(r.q_WB.coeffs()[3], run.q_WB[8 + 3]);
    for (std::size_t e = 0; e < 3; ++e) EXPECT_EQ(next.work[e], run.work[3 + e]);
  }
}

// 20 steps of 0.01 s of `method`, recorded at every step (the kick–drift–kick tests below)
SimulationOptions twenty_steps_of(Method method) {
  SimulationOptions o;
  o.method = method;
  o.dt = 0.01;
  o.steps = 20;
  return o;
}

// A kick–drift–kick run recorded at every step closes each step for its record, and the next step's opening kick
// repeats the closing kick's wrenches (simulate/run_loop.hpp, merged_steps): the records are the bits of the
// method's steps taken one at a time by step(), from a state to the next. (step() normalises the attitude it is given,
// the run keeps it as integrated: the attitudes are compared at the first record alone; no load here turns a body, so
// that the motion of the centres of mass and ω_B do not depend on them.)
TEST(SimulateScene, RecordedKickDriftKickStepsAreTheMethodsStepsBitwise) {
  Scene scene;
  scene.bodies = {RigidBody(2.0, Eigen::Vector3d(1.0, 2.0, 3.0)), Particle(1.0),
                  RigidBody(1.5, Eigen::Vector3d(0.5, 0.6, 0.7))};
  scene.elements.push_back(MutualGravity{1.0, 0.05, {}});
  scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -1.0), {}});
  RigidBodyState third = tumbling_state();
  third.p_W = Eigen::Vector3d(-1.0, 0.5, 0.2);
  const ParticleState particle{Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d(0.0, 0.3, 0.0)};
  const std::vector<BodyState> initial{tumbling_state(), particle, third};
  for (const Method method : {Method::splitting_dlm, Method::splitting_dlm_yoshida4, Method::exact_flow_kick}) {
    SCOPED_TRACE(method_info(method).name);
    const SimulationOptions o = twenty_steps_of(method);
    const SceneSimulation run = simulate(scene, initial, o);
    ASSERT_EQ(run.t.size(), 21u);
    std::vector<BodyState> state = initial;
    for (std::size_t k = 1; k <= 20; ++k) {
      SimulationOptions one = o;
      one.t0 = run.t[k - 1];
      state = step(scene, state, one).bodies;
      const auto& a = std::get<RigidBodyState>(state[0]);
      const auto& b = std::get<ParticleState>(state[1]);
      for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(a.p_W[i], run.p_W[9 * k + i]) << "record " << k;
        EXPECT_EQ(a.v_W[i], run.v_W[9 * k + i]) << "record " << k;
        EXPECT_EQ(a.w_B[i], run.w_B[9 * k + i]) << "record " << k;
        EXPECT_EQ(b.p_W[i], run.p_W[9 * k + 3 + i]) << "record " << k;
        EXPECT_EQ(b.v_W[i], run.v_W[9 * k + 3 + i]) << "record " << k;
      }
      for (int i = 0; i < 4; ++i) EXPECT_EQ(a.q_WB.coeffs()[i], run.q_WB[12 * k + i]) << "record " << k;
    }
  }
}

// Across switch times too: a force on the particle switches on and off inside steps 6 and 13 (their split steps come
// between merged steps closed before them, the repeated kick only after a record). A declared Drag with zero
// coefficients reads the velocities, so that the same scene with it merges no kicks and evaluates every one: it adds
// exact zeros, and the two runs recorded at every step move the bodies bitwise alike. Their records agree bitwise
// too: the merged run's, made from its closing kicks' wrenches, sum each element's power as the element does.
TEST(SimulateScene, RecordedKickDriftKickStepsAcrossSwitchesAreTheUnmergedStepsBitwise) {
  Scene merged;
  merged.bodies = {RigidBody(2.0, Eigen::Vector3d(1.0, 2.0, 3.0)), Particle(1.0)};
  merged.elements.push_back(MutualGravity{1.0, 0.05, {}});
  AppliedLoad push{Eigen::Vector3d(0.4, -0.2, 0.1), Eigen::Vector3d(0.0, 0.05, 0.0), Frame::world};
  push.t_start = 0.0531, push.t_end = 0.1277;
  merged.elements.push_back(ScheduledLoads{0, {push}, Eigen::Vector3d::Zero()});
  Scene unmerged = merged;
  unmerged.elements.push_back(Drag{0.0, 0.0, 0.0, 0.0, {}});
  const ParticleState particle{Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d(0.0, 0.3, 0.0)};
  const std::vector<BodyState> initial{tumbling_state(), particle};
  for (const Method method : {Method::splitting_dlm, Method::splitting_dlm_yoshida4, Method::exact_flow_kick}) {
    SCOPED_TRACE(method_info(method).name);
    const SimulationOptions o = twenty_steps_of(method);
    const SceneSimulation a = simulate(merged, initial, o), b = simulate(unmerged, initial, o);
    EXPECT_EQ(a.p_W, b.p_W);
    EXPECT_EQ(a.q_WB, b.q_WB);
    EXPECT_EQ(a.v_W, b.v_W);
    EXPECT_EQ(a.w_B, b.w_B);
    EXPECT_EQ(a.total_energy, b.total_energy);
    EXPECT_EQ(a.angular_momentum_W, b.angular_momentum_W);
    ASSERT_EQ(a.power.size(), 2 * a.t.size());  // MutualGravity's and ScheduledLoads' (and b's Drag third)
    for (std::size_t r = 0; r < a.t.size(); ++r) {
      for (std::size_t e = 0; e < 2; ++e) {
        EXPECT_EQ(a.power[2 * r + e], b.power[3 * r + e]) << "record " << r << ", element " << e;
        EXPECT_EQ(a.work[2 * r + e], b.work[3 * r + e]) << "record " << r << ", element " << e;
      }
    }
  }
}

// The same run evaluates its forces once per kick it gives: a user force (not reading the velocities) counts them.
// Recorded at every step, the first record, the first step's opening kick, each step's inner kicks and its closing
// kick; each later record takes the closing kick's wrenches, and the next step's opening kick repeats them.
TEST(SimulateScene, RecordedKickDriftKickStepsEvaluateTheForcesOncePerKick) {
  int calls = 0;
  const auto spring = [&calls](double, const BodyKinematics& k, int, Eigen::Vector3d& f_W, Eigen::Vector3d& tau_B) {
    ++calls;
    f_W = -4.0 * k.p_W;
    tau_B = Eigen::Vector3d(0.0, 0.1 * k.p_W.x(), 0.0);
  };
  const ElementTraits position_only{true, false, false, false, true};  // reads the attitude, not the velocities
  Scene scene;
  scene.bodies = {RigidBody(1.0, Eigen::Vector3d(1.0, 2.0, 3.0)), Particle(1.0)};  // two bodies: the generic model
  const ParticleState particle{Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d::Zero()};
  const std::vector<BodyState> initial{tumbling_state(), particle};
  const std::pair<Method, int> kicks_per_step[] = {
      {Method::splitting_dlm, 1}, {Method::splitting_dlm_yoshida4, 3}, {Method::exact_flow_kick, 1}};
  for (const auto& [method, kicks] : kicks_per_step) {
    SCOPED_TRACE(method_info(method).name);
    const SimulationOptions o = twenty_steps_of(method);
    calls = 0;
    simulate(scene, initial, o, custom_force(BodyList{0}, spring, position_only));
    EXPECT_EQ(calls, 1 + 1 + kicks * 20);  // the first record, the first opening kick, each step's kicks
  }
}

}  // namespace
}  // namespace rigiddyn
