// The scene pipeline's parts for bodies about a fixed point, moving frames and variable mass: pivoted bodies,
// the scene frame and mass flows in SceneModel; each fast one-body model equals the generic model on the same
// scene; mixed scenes keep what they must (energy, the frame equivalence, Tsiolkovsky's momentum bookkeeping);
// the refusals and warnings of compile and simulate.
#include <gtest/gtest.h>

#include "test_inputs.hpp"
#include "test_numbers.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

using rigiddyn::test::kEps;

// A full inertia about the centre of mass: principal moments (1.0, 1.4, 2.1) [kg m²] turned by a fixed rotation.
using test::full_inertia;

PivotedBody heavy_top() { return PivotedBody(RigidBody(2.0, full_inertia()), Eigen::Vector3d(0.1, -0.2, 0.5), Eigen::Vector3d(0.3, 0.0, 1.0)); }

PivotedBodyState top_state() {
  PivotedBodyState s;
  s.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1.0, -1.0, 2.0).normalized()));
  s.w_B = Eigen::Vector3d(0.3, -0.5, 6.0);
  return s;
}

SimulationOptions options(Method method, double dt, std::int64_t steps) {
  SimulationOptions o;
  o.method = method, o.dt = dt, o.steps = steps;
  return o;
}

// The largest |a_i − b_i| relative to max(1, max|b|) over one column.
double column_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double scale = 1.0, diff = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    scale = std::max(scale, std::abs(b[i]));
    diff = std::max(diff, std::abs(a[i] - b[i]));
  }
  return diff / scale;
}

// Every column of two records of the same scene agrees to `tol` (relative to the column's scale).
void expect_same_simulation(const SceneSimulation& a, const SceneSimulation& b, double tol) {
  EXPECT_EQ(a.t, b.t);
  const std::vector<std::pair<const char*, std::pair<const std::vector<double>*, const std::vector<double>*>>> columns = {
      {"p_W", {&a.p_W, &b.p_W}},
      {"q_WB", {&a.q_WB, &b.q_WB}},
      {"v_W", {&a.v_W, &b.v_W}},
      {"w_B", {&a.w_B, &b.w_B}},
      {"kinetic_energy", {&a.kinetic_energy, &b.kinetic_energy}},
      {"potential_energy", {&a.potential_energy, &b.potential_energy}},
      {"total_energy", {&a.total_energy, &b.total_energy}},
      {"linear_momentum_W", {&a.linear_momentum_W, &b.linear_momentum_W}},
      {"angular_momentum_W", {&a.angular_momentum_W, &b.angular_momentum_W}},
      {"pivot_reaction_W", {&a.pivot_reaction_W, &b.pivot_reaction_W}},
      {"angular_momentum_O_W", {&a.angular_momentum_O_W, &b.angular_momentum_O_W}},
      {"mass", {&a.mass, &b.mass}},
      {"work", {&a.work, &b.work}},
      {"power", {&a.power, &b.power}}};
  for (const auto& [name, pair] : columns) EXPECT_LT(column_difference(*pair.first, *pair.second), tol) << name;
}

// The generic model's run of a compiled scene (whatever path compile chose for simulate).
SceneSimulation generic_run(const CompiledScene& compiled, const std::vector<BodyState>& initial, const SimulationOptions& o) {
  const SceneModel& model = compiled.model();
  return detail::run_scene(model, model.coordinates(initial, o.t0), o, compiled.switch_schedule());
}

// Round-off bound of two evaluations of the same equations in different operation orders: each step's
// results differ by at most ~64 ulps of the state (a few dozen operations each rounding differently), and
// over n steps of a run shorter than the flow's e-folding time (here |ω| t and the gravity frequency times
// t are <= 6: growth <= e^6 ≈ 400 in the worst direction) they add up to at most n · 64 eps · 400.
double round_off_bound(std::int64_t steps) { return static_cast<double>(steps) * 64.0 * kEps * 400.0; }

// Runs `make` and expects std::invalid_argument whose message contains `part`.
void expect_error_containing(const std::function<void()>& make, const std::string& part) {
  try {
    make();
    ADD_FAILURE() << "no exception, expected a message containing: " << part;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

// ---------------------------------------------------------------------------------------------------
// fast models = the generic model

TEST(SceneFixedPointFramesMassFast, PivotedBodyModelEqualsGenericModel) {
  Scene scene;
  scene.bodies = {heavy_top()};
  scene.elements = {UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}},
                    ScheduledLoads{0, {AppliedLoad{Eigen::Vector3d(0.3, 0.1, 0.0), Eigen::Vector3d(0.0, 0.2, 0.1), Frame::body}},
                                   Eigen::Vector3d(0.0, 0.1, 0.2)}};
  for (const Method method : {Method::rk4, Method::splitting_dlm, Method::semi_implicit_euler, Method::exact_flow_kick}) {
    const CompiledScene compiled = compile_scene(scene, method);
    const OneBodyModel& one_body = compiled.one_body_model();
    ASSERT_TRUE(one_body_model_if<PivotedBodyModel<SphericalEuler>>(one_body) ||
                one_body_model_if<PivotedBodyModel<PrincipalEuler>>(one_body) ||
                one_body_model_if<PivotedBodyModel<FullEuler>>(one_body));
    const SimulationOptions o = options(method, 1e-3, 500);
    const SceneSimulation fast = simulate(compiled, {top_state()}, o), generic = generic_run(compiled, {top_state()}, o);
    expect_same_simulation(fast, generic, round_off_bound(o.steps));
  }
}

TEST(SceneFixedPointFramesMassFast, RotatingFrameParticleModelEqualsGenericModel) {
  Scene scene;
  scene.bodies = {Particle(1.5)};
  scene.frame = SceneFrame::rotating(Eigen::Vector3d(0.2, 0.3, 1.0), 0.8);
  scene.elements = {UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}}};
  const ParticleState initial{Eigen::Vector3d(1.0, -0.5, 2.0), Eigen::Vector3d(0.3, 0.4, 1.0)};
  // the rate-based methods evaluate the same acceleration; the splittings' kicks take the exact flow of the
  // Coriolis term in both models (two closed forms of the same exponential: they agree to round-off)
  for (const Method method : {Method::rk4, Method::explicit_euler, Method::implicit_midpoint, Method::splitting_dlm,
                              Method::splitting_dlm_yoshida4, Method::exact_flow_kick}) {
    const CompiledScene compiled = compile_scene(scene, method);
    ASSERT_NE(one_body_model_if<RotatingFrameParticleModel>(compiled.one_body_model()), nullptr);
    EXPECT_EQ(compiled.element_names(), (std::vector<std::string>{"elements[0]", "frame.centrifugal", "frame.coriolis"}));
    EXPECT_EQ(compiled.element_types(), (std::vector<std::string>{"UniformGravity", "CentrifugalForce", "CoriolisForce"}));
    const SimulationOptions o = options(method, 1e-3, 500);
    const SceneSimulation fast = simulate(compiled, {initial}, o), generic = generic_run(compiled, {initial}, o);
    expect_same_simulation(fast, generic, round_off_bound(o.steps));
  }
}

TEST(SceneFixedPointFramesMassFast, VariableMassParticleModelEqualsGenericModel) {
  Scene scene;
  scene.bodies = {Particle(10.0)};
  MassFlow flow;
  flow.rate = -2.0;
  scene.mass_flows = {flow};
  scene.elements = {UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}},
                    Thrust{0, Eigen::Vector3d(0.0, -50.0, -300.0), Frame::world, Eigen::Vector3d::Zero()}};
  const ParticleState initial{Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(1.0, 0.0, 0.0)};
  for (const Method method : {Method::rk4, Method::splitting_dlm, Method::semi_implicit_euler, Method::splitting_dlm_yoshida4}) {
    const CompiledScene compiled = compile_scene(scene, method);
    ASSERT_NE(one_body_model_if<VariableMassParticleModel>(compiled.one_body_model()), nullptr);
    const SimulationOptions o = options(method, 1e-3, 2000);  // to m = 6 kg
    const SceneSimulation fast = simulate(compiled, {initial}, o), generic = generic_run(compiled, {initial}, o);
    expect_same_simulation(fast, generic, round_off_bound(o.steps));
    // m += h ṁ per step (RK4: its stages sum to the same): 2000 sums, each rounded to half an ulp of 10
    EXPECT_NEAR(fast.mass.back(), 6.0, 2000 * kEps * 10.0);
  }
}

// ---------------------------------------------------------------------------------------------------
// mixed scenes

// The drift of total energy over a run (max |E − E0|).
double energy_drift(const SceneSimulation& r) {
  double drift = 0.0;
  for (const double E : r.total_energy) drift = std::max(drift, std::abs(E - r.total_energy.front()));
  return drift;
}

TEST(SceneFixedPointFramesMassMixed, PivotedBodyWithSpringToParticleConservesEnergy) {
  Scene scene;
  scene.bodies = {heavy_top(), Particle(0.7)};
  scene.elements = {UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}},
                    SpringDamper{0, Eigen::Vector3d(0.0, 0.1, 0.2), 1, Eigen::Vector3d::Zero(), 20.0, 0.3, 0.0}};
  PivotedBodyState top = top_state();
  top.w_B = Eigen::Vector3d(0.3, -0.5, 2.0);
  const std::vector<BodyState> initial = {top, ParticleState{Eigen::Vector3d(0.8, 0.3, 1.2), Eigen::Vector3d(0.0, 0.5, 0.0)}};
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  EXPECT_EQ(compiled.path(), ScenePath::generic);
  // RK4's energy error over a fixed time is C dt⁴: halving dt divides it by ~16; a rate < 10 would mean the
  // energy is not conserved by the equations themselves (then the drift would not shrink with dt).
  const double coarse = energy_drift(simulate(compiled, initial, options(Method::rk4, 4e-3, 500)));
  const double fine = energy_drift(simulate(compiled, initial, options(Method::rk4, 2e-3, 1000)));
  EXPECT_GT(coarse, 0.0);
  EXPECT_GT(coarse / fine, 10.0) << coarse << " " << fine;
  // the pivot's reaction is Newton's law for the top's centre of mass: with ω = 0 and no motion it carries
  // the weight; here it is recorded per body (zero for the particle)
  const SceneSimulation r = simulate(compiled, initial, options(Method::rk4, 2e-3, 10));
  ASSERT_EQ(r.pivot_reaction_W.size(), r.size() * 2 * 3);
  EXPECT_EQ(r.pivot_reaction_W[3], 0.0);
  EXPECT_GT(std::abs(r.pivot_reaction_W[2]), 0.0);
  ASSERT_EQ(r.mass.size(), r.size() * 2);
  EXPECT_EQ(r.mass[0], 2.0);
  EXPECT_EQ(r.mass[1], 0.7);
}

TEST(SceneFixedPointFramesMassMixed, PivotedReactionAndMomentumAboutPivotAtRest) {
  // hanging at rest below the pivot: the reaction holds the weight, H_O = 0, T = 0
  Scene scene;
  scene.bodies = {PivotedBody(RigidBody(2.0, full_inertia()), Eigen::Vector3d(0.0, 0.0, -0.5))};
  scene.elements = {UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}}};
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  const SceneSimulation fast = simulate(compiled, {PivotedBodyState{}}, options(Method::rk4, 1e-3, 1));
  const SceneSimulation generic = generic_run(compiled, {PivotedBodyState{}}, options(Method::rk4, 1e-3, 1));
  for (const SceneSimulation* r : {&fast, &generic}) {
    // R = m a_C − f = 0 − m g: (0, 0, 19.62) to the rounding of one product
    EXPECT_NEAR(r->pivot_reaction_W[2], 19.62, 4 * kEps * 19.62);
    EXPECT_EQ(r->kinetic_energy[0], 0.0);
    EXPECT_EQ(Eigen::Vector3d(&r->angular_momentum_O_W[0]).norm(), 0.0);
  }
}

// The state of a rigid body (constant rotation of F about `axis` at `rate` through W's origin, F = W at
// t = 0) seen from W turned into F at time t: p_F = R_FW p_W, v_F = R_FW (v_W − Ω × p_W), q_FB = R_FW q_WB,
// w_B relative to F = w_B − R_BW Ω.
RigidBodyState into_rotating_frame(const RigidBodyState& s, const Eigen::Vector3d& axis, double rate, double t) {
  const Eigen::Vector3d u = axis.normalized(), Omega = rate * u;
  const Eigen::Quaterniond q_WF(Eigen::AngleAxisd(rate * t, u));
  RigidBodyState out;
  out.p_W = q_WF.conjugate() * s.p_W;
  out.v_W = q_WF.conjugate() * (s.v_W - Omega.cross(s.p_W));
  out.q_WB = q_WF.conjugate() * s.q_WB;
  out.w_B = s.w_B - s.q_WB.conjugate() * Omega;
  return out;
}

RigidBodyState record_state(const SceneSimulation& r, std::size_t i) {
  RigidBodyState s;
  s.p_W = Eigen::Vector3d(&r.p_W[3 * i]);
  s.q_WB.coeffs() = Eigen::Vector4d(&r.q_WB[4 * i]);
  s.v_W = Eigen::Vector3d(&r.v_W[3 * i]);
  s.w_B = Eigen::Vector3d(&r.w_B[3 * i]);
  return s;
}

double state_distance(const RigidBodyState& a, const RigidBodyState& b) {
  const double dq = std::min((a.q_WB.coeffs() - b.q_WB.coeffs()).norm(), (a.q_WB.coeffs() + b.q_WB.coeffs()).norm());
  return std::max({(a.p_W - b.p_W).norm(), (a.v_W - b.v_W).norm(), (a.w_B - b.w_B).norm(), dq});
}

TEST(SceneFixedPointFramesMassMixed, VariableMassBodyWithOffCentreThrustInRotatingFrameEqualsInertialRun) {
  const Eigen::Vector3d axis(0.3, -0.2, 1.0);
  const double rate = 0.7;
  MassFlow flow;
  flow.rate = -1.5;
  Scene inertial;
  inertial.bodies = {RigidBody(20.0, full_inertia())};
  inertial.mass_flows = {flow};
  inertial.elements = {Thrust{0, Eigen::Vector3d(0.0, 0.0, -40.0), Frame::body, Eigen::Vector3d(0.02, -0.01, -0.5)},
                       UniformGravity{Eigen::Vector3d::Zero(), {}}};
  Scene rotating = inertial;
  rotating.frame = SceneFrame::rotating(axis, rate);
  RigidBodyState s0;
  s0.p_W = Eigen::Vector3d(1.0, 0.5, -0.3), s0.v_W = Eigen::Vector3d(0.2, -0.1, 0.4);
  s0.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Eigen::Vector3d(1.0, 1.0, 0.0).normalized()));
  s0.w_B = Eigen::Vector3d(0.4, 0.1, -0.3);
  const RigidBodyState s0_F = into_rotating_frame(s0, axis, rate, 0.0);
  const std::int64_t steps = 400;
  const double dt = 5e-3;
  // each run's RK4 error, estimated by Richardson from the run at dt/2: e(dt) ≈ 16/15 |y_dt − y_dt/2|
  const auto run = [&](const Scene& scene, const RigidBodyState& start, double h, std::int64_t n) {
    return simulate(scene, {start}, options(Method::rk4, h, n));
  };
  const SceneSimulation W = run(inertial, s0, dt, steps), W2 = run(inertial, s0, dt / 2, 2 * steps);
  const SceneSimulation F = run(rotating, s0_F, dt, steps), F2 = run(rotating, s0_F, dt / 2, 2 * steps);
  const double t_end = dt * static_cast<double>(steps);
  const RigidBodyState w_end = record_state(W, steps), f_end = record_state(F, steps);
  const double error_W = 16.0 / 15.0 * state_distance(w_end, record_state(W2, 2 * steps));
  const double error_F = 16.0 / 15.0 * state_distance(f_end, record_state(F2, 2 * steps));
  EXPECT_GT(error_W, 0.0);
  // the two runs are approximations of the same motion: they differ by at most the sum of their errors (a
  // factor 2 for the estimate's own uncertainty) plus the round-off of the transformation (1e-13)
  EXPECT_LT(state_distance(into_rotating_frame(w_end, axis, rate, t_end), f_end), 2.0 * (error_W + error_F) + 1e-13);
  EXPECT_NEAR(F.mass.back(), 20.0 - 1.5 * t_end, 1e-12);
  // the Coriolis term does no work: its power f·v + τ·ω is zero analytically (fictitious_forces.hpp), so the
  // recorded one is the rounding of its few dozen products: within 64 eps of the sizes of its terms,
  // |f||v| = 2 m |Ω| |v|² and |τ||ω| <= 3 λ_max(I) |Ω| |ω|² (I = I_C0 m/m0 <= 2.1 kg m² · m/m0)
  // (power column 3: the two elements, then the centrifugal and Coriolis terms)
  const std::size_t ne = static_cast<std::size_t>(F.element_count);
  ASSERT_EQ(ne, 4u);
  for (std::size_t i = 0; i < F.size(); ++i) {
    const double m = F.mass[i], v2 = Eigen::Vector3d(&F.v_W[3 * i]).squaredNorm(), w2 = Eigen::Vector3d(&F.w_B[3 * i]).squaredNorm();
    const double scale = 2.0 * m * rate * v2 + 3.0 * 2.1 * (m / 20.0) * rate * w2;
    EXPECT_LT(std::abs(F.power[i * ne + 3]), 64.0 * kEps * scale) << i;
  }
}

TEST(SceneFixedPointFramesMassMixed, RigidBodyInRotatingFrameKeepsJacobiIntegral) {
  // a rigid body under gravity along the rotation axis, seen from the turning frame: kinetic energy relative to
  // F plus the gravity and centrifugal potentials (Jacobi's integral) is conserved by the equations, so RK4's
  // drift is C dt⁴ (halving dt divides it by ~16; a rate < 10 would mean a non-conserved quantity)
  Scene scene;
  scene.bodies = {RigidBody(3.0, full_inertia())};
  scene.frame = SceneFrame::rotating(Eigen::Vector3d::UnitZ(), 1.3);
  scene.elements = {UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}}};
  RigidBodyState s0;
  s0.p_W = Eigen::Vector3d(1.0, -0.5, 0.3), s0.v_W = Eigen::Vector3d(0.4, 0.2, 1.0), s0.w_B = Eigen::Vector3d(0.5, -0.8, 1.1);
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  EXPECT_EQ(compiled.element_names(), (std::vector<std::string>{"elements[0]", "frame.centrifugal", "frame.coriolis"}));
  const double coarse = energy_drift(simulate(compiled, {s0}, options(Method::rk4, 8e-3, 250)));
  const double fine = energy_drift(simulate(compiled, {s0}, options(Method::rk4, 4e-3, 500)));
  EXPECT_GT(coarse, 0.0);
  EXPECT_GT(coarse / fine, 10.0) << coarse << " " << fine;
}

TEST(SceneFixedPointFramesMassMixed, VariableMassBodyFollowsTsiolkovsky) {
  // thrust along a fixed body axis through C, no rotation: v(t) = v0 + u_rel ln(m(t)/m0) (the momentum
  // bookkeeping d(m v)/dt = ṁ (v + u_rel) integrated)
  MassFlow flow;
  flow.rate = -3.0;
  Scene scene;
  scene.bodies = {RigidBody(30.0, Eigen::Vector3d(1.0, 2.0, 3.0))};
  scene.mass_flows = {flow};
  const Eigen::Vector3d u_rel(0.0, 0.0, -200.0);
  scene.elements = {Thrust{0, u_rel, Frame::body, Eigen::Vector3d::Zero()}};
  RigidBodyState s0;
  s0.v_W = Eigen::Vector3d(5.0, 0.0, 0.0);
  const SceneSimulation r = simulate(scene, {s0}, options(Method::rk4, 1e-2, 800));  // to m = 6 kg
  const double m = r.mass.back();
  EXPECT_NEAR(m, 6.0, 1e-12);
  const Eigen::Vector3d v_exact = s0.v_W + u_rel * std::log(m / 30.0);
  // RK4 on v̇ = ṁ u/(m0 + ṁ t): the local error h⁵ |v⁽⁵⁾|/120 with |v⁽⁵⁾| = 24 |ṁ⁵ u|/m⁵ <= 24·243·200/6⁵ = 150,
  // over 800 steps: 800 · 1e-10 · 150 / 120 = 1e-7
  EXPECT_LT((Eigen::Vector3d(&r.v_W[3 * 800]) - v_exact).norm(), 1e-7);
}

// ---------------------------------------------------------------------------------------------------
// refusals and warnings

TEST(SceneFixedPointFramesMassChecks, Refusals) {
  Scene thrust_without_flow;
  thrust_without_flow.bodies = {Particle(1.0)};
  thrust_without_flow.elements = {Thrust{0, Eigen::Vector3d(1.0, 0.0, 0.0), Frame::world, Eigen::Vector3d::Zero()}};
  expect_error_containing([&] { compile_scene(thrust_without_flow, Method::rk4); }, "elements[0].body: expected a body with a mass flow");

  MassFlow flow;
  flow.rate = -1.0;
  Scene gradient;
  gradient.bodies = {RigidBody(10.0, Eigen::Vector3d(1.0, 2.0, 3.0))};
  gradient.mass_flows = {flow};
  gradient.elements = {GravityGradient{3.986e14, Eigen::Vector3d(0.0, 0.0, -7e6), {}}};
  expect_error_containing([&] { compile_scene(gradient, Method::rk4); }, "elements[0].bodies: expected bodies of constant mass");

  Scene planar_flow;
  planar_flow.bodies = {PlanarBody(1.0, 0.5)};
  planar_flow.mass_flows = {flow};
  expect_error_containing([&] { compile_scene(planar_flow, Method::rk4); }, "mass_flows[0]: expected none for a planar body");

  Scene wrong_count;
  wrong_count.bodies = {Particle(1.0), Particle(2.0)};
  wrong_count.mass_flows = {flow};
  expect_error_containing([&] { compile_scene(wrong_count, Method::rk4); }, "mass_flows: expected 2 entries");

  Scene exact_frame;
  exact_frame.bodies = {RigidBody(1.0, Eigen::Vector3d(1.0, 2.0, 3.0))};
  exact_frame.frame = SceneFrame::rotating(Eigen::Vector3d::UnitZ(), 1.0);
  expect_error_containing([&] { compile_scene(exact_frame, Method::exact); }, "method: 'exact' needs an inertial scene");

  Scene exact_flow = exact_frame;
  exact_flow.frame.reset();
  exact_flow.mass_flows = {flow};
  expect_error_containing([&] { compile_scene(exact_flow, Method::exact); }, "method: 'exact' needs bodies of constant mass");

  Scene exact_top;
  exact_top.bodies = {heavy_top()};
  exact_top.elements = {UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}}};
  expect_error_containing([&] { compile_scene(exact_top, Method::exact); }, "method: 'exact' needs a torque-free pivoted body");
  // allowed: no element, or the centre of mass at the pivot under gravity
  exact_top.elements.clear();
  EXPECT_NO_THROW(compile_scene(exact_top, Method::exact));
  exact_top.bodies = {PivotedBody(RigidBody(2.0, full_inertia()), Eigen::Vector3d::Zero())};
  exact_top.elements = {UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}}};
  EXPECT_NO_THROW(compile_scene(exact_top, Method::exact));

  MassFlow function_rule;
  function_rule.rate = -1.0;
  function_rule.inertia_rule = InertiaRule::function;
  function_rule.inertia_of_mass = [](double m) { return Eigen::Matrix3d(Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal() * m); };
  Scene shaped;
  shaped.bodies = {RigidBody(10.0, Eigen::Vector3d(1.0, 2.0, 3.0))};
  shaped.mass_flows = {function_rule};
  expect_error_containing([&] { compile_scene(shaped, Method::splitting_dlm); }, "method: expected a method that is not a splitting");
  EXPECT_NO_THROW(compile_scene(shaped, Method::rk4));
  shaped.frame = SceneFrame::rotating(Eigen::Vector3d::UnitZ(), 1.0);
  expect_error_containing([&] { compile_scene(shaped, Method::rk4); }, "mass_flows[0].inertia_rule: expected InertiaRule::scaled");
}

TEST(SceneFixedPointFramesMassChecks, MassRunningOut) {
  MassFlow flow;
  flow.rate = -2.0;
  Scene scene;
  scene.bodies = {Particle(1.0)};
  scene.mass_flows = {flow};
  // a constant rate: refused up front, naming steps and dt (1 kg at 2 kg/s: out at t = 0.5 s)
  expect_error_containing([&] { simulate(scene, {ParticleState{}}, options(Method::rk4, 0.1, 10)); }, "steps, dt");
  EXPECT_NO_THROW(simulate(scene, {ParticleState{}}, options(Method::rk4, 0.1, 4)));
  // a rate of t: the model raises at the step where the mass is no longer positive
  flow.rate = 0.0;
  flow.rate_of_t = [](double t) { return -4.0 * t; };  // m = 1 − 2 t²: out at t = 0.707 s
  scene.mass_flows = {flow};
  for (const Method method : {Method::rk4, Method::splitting_dlm, Method::semi_implicit_euler}) {
    expect_error_containing([&] { simulate(scene, {ParticleState{}}, options(method, 0.1, 10)); },
                            "mass_flows[0]: expected a positive mass, got m = ");
    expect_error_containing([&] { simulate(scene, {ParticleState{}}, options(method, 0.1, 10)); },
                            "(the body 'body0' runs out of mass in the step from t = 0.7");
  }
}

TEST(SceneFixedPointFramesMassChecks, DigitsLostWarning) {
  Scene scene;
  // I_C ~ 1 kg m², m |c|² = 1e8: ~8 digits lost
  scene.bodies = {PivotedBody(RigidBody(1.0, Eigen::Vector3d(1.0, 1.0, 1.0)), Eigen::Vector3d(0.0, 0.0, 1e4))};
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  ASSERT_EQ(compiled.warnings().size(), 1u);
  EXPECT_NE(compiled.warnings()[0].find("bodies[0] 'body0': the pivot is 10000 m from the centre of mass; the inertia "
                                        "about O keeps only ~8.0 of the 16 digits"),
            std::string::npos)
      << compiled.warnings()[0];
  scene.bodies = {heavy_top()};
  EXPECT_TRUE(compile_scene(scene, Method::rk4).warnings().empty());
}

TEST(SceneFixedPointFramesMassChecks, FrameTermsOfAGeneralMotion) {
  Scene scene;
  scene.bodies = {Particle(1.0), RigidBody(2.0, full_inertia())};
  scene.frame = SceneFrame::moving(FrameMotion([](double t) {
    FrameKinematics k;
    k.R_PF = Eigen::AngleAxisd(0.5 * t * t, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    k.w_PF_P = Eigen::Vector3d(0.0, 0.0, t), k.alpha_PF_P = Eigen::Vector3d(0.0, 0.0, 1.0);
    k.p_PF_P = Eigen::Vector3d(t * t, 0.0, 0.0), k.v_PF_P = Eigen::Vector3d(2.0 * t, 0.0, 0.0);
    k.a_PF_P = Eigen::Vector3d(2.0, 0.0, 0.0);
    return k;
  }));
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  EXPECT_EQ(compiled.path(), ScenePath::generic);
  EXPECT_EQ(compiled.element_names(), (std::vector<std::string>{"frame.origin", "frame.euler", "frame.centrifugal", "frame.coriolis"}));
  const SceneSimulation r = simulate(compiled, {ParticleState{}, RigidBodyState{}}, options(Method::rk4, 1e-2, 10));
  EXPECT_EQ(r.work.size(), r.size() * 4);
  // at rest at F's origin: the frame-origin force −m a_O acts first, along −x
  EXPECT_LT(r.p_W[3 * 2 * 10], 0.0);
}

TEST(SceneFixedPointFramesMassChecks, StepReportsMasses) {
  MassFlow flow;
  flow.rate = -0.5;
  Scene scene;
  scene.bodies = {Particle(1.0), PivotedPlanarBody(2.0, 0.3, Eigen::Vector2d(0.0, -0.4))};
  scene.mass_flows = {flow, std::nullopt};
  scene.elements = {UniformGravity{Eigen::Vector3d(0.0, -9.81, 0.0), {}}};
  const SceneState s = step(scene, {ParticleState{}, PivotedPlanarBodyState{0.3, 0.0}}, options(Method::rk4, 0.1, 1));
  ASSERT_EQ(s.mass.size(), 2u);
  EXPECT_NEAR(s.mass[0], 0.95, 4 * kEps);
  EXPECT_EQ(s.mass[1], 2.0);
  // the pendulum swings back towards θ = 0 (R c points along g at θ = 0)
  EXPECT_LT(std::get<PivotedPlanarBodyState>(s.bodies[1]).omega, 0.0);
}

}  // namespace
}  // namespace rigiddyn
