// The fast variable-mass particle (scene/fast/variable_mass_particle_model.hpp) against
// the closed form of a constant-rate burn in uniform gravity (derived below), Tsiolkovsky's Δv, the
// momentum bookkeeping of the notes' eq. (4.36) on the recorded trajectory, the element terms (Thrust,
// UniformGravity) it replaces, the observed order of every method, the step at which the mass runs out,
// and its argument checks.
#include <gtest/gtest.h>

#include "test_numbers.hpp"
#include "invalid_argument_message.hpp"
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/scene/elements/thrust.hpp"
#include "rigiddyn/scene/elements/uniform_gravity.hpp"
#include "rigiddyn/scene/fast/variable_mass_particle_model.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

using rigiddyn::test::kEps;
using Model = VariableMassParticleModel;
using Y = Model::Coordinates;

// A constant-rate burn: m0 [kg], ṁ [kg/s], u_rel [m/s] in W, g [m/s²], p0 [m], v0 [m/s] at t = 0.
struct Burn {
  double m0, rate;
  Eigen::Vector3d u_rel, g, p0, v0;
};

// The closed form. With m(t) = m0 + ṁ t, the equation m v̇ = m g + ṁ u_rel (notes eq. (4.36)) gives
//   v(t) = v0 + g t + u_rel ∫₀ᵗ ṁ/m ds = v0 + g t + u_rel ln(m/m0),
// and, with x = ṁ t/m0 (so m/m0 = 1 + x and ds = (m0/ṁ) dx),
//   ∫₀ᵗ ln(m(s)/m0) ds = (m0/ṁ) ∫₀ˣ ln(1 + ξ) dξ = (m0/ṁ) ((1 + x) ln(1 + x) − x) = t ((1 + x) ln(1 + x) − x)/x,
//   p(t) = p0 + v0 t + ½ g t² + u_rel t ((1 + x) ln(1 + x) − x)/x.
// ln(1 + x) by log1p; the bracket cancels to ~x²/2, losing ~2/|x| ulps (≤ 40 ulps at the times compared).
struct Exact {
  Eigen::Vector3d p, v;
  double m;
};
Exact exact_at(const Burn& b, double t) {
  const double x = b.rate * t / b.m0, ln = std::log1p(x);
  const double shape = x == 0.0 ? 0.0 : ((1.0 + x) * ln - x) / x;
  return {b.p0 + b.v0 * t + 0.5 * b.g * t * t + b.u_rel * (t * shape), b.v0 + b.g * t + b.u_rel * ln, b.m0 + b.rate * t};
}

// The fast model of the burn: element 0 gravity, element 1 the thrust (the order a scene file declares).
Model model_of(const Burn& b, const std::string& name = "rocket") {
  MassFlow flow;
  flow.rate = b.rate;
  Thrust thrust;
  thrust.frame = Frame::world, thrust.u_rel = b.u_rel;
  return Model(Particle(b.m0), flow, thrust, 1, b.g, 0, 2, name);
}

// Runs `steps` steps of `method` from t = 0 as the scene's run loop does (y's t set to the grid time i dt
// after each step), recording every step into a SceneSimulation.
SceneSimulation run(const Burn& b, Method method, double dt, std::int64_t steps) {
  Model model = model_of(b);
  model.set_time(0.0);
  Y y = model.coordinates({BodyState(ParticleState{b.p0, b.v0})}, 0.0);
  SceneSimulation out;
  out.body_count = 1, out.element_count = 2;
  model.record(y, 0.0, out);
  visit_method(method, [&](auto integrator) {
    auto work = workspace<decltype(integrator)>(model, y);
    for (std::int64_t i = 1; i <= steps; ++i) {
      decltype(integrator)::step(model, y, dt, work);
      y[model.time_index()] = static_cast<double>(i) * dt;
      model.record(y, static_cast<double>(i) * dt, out);
    }
    return 0;
  });
  return out;
}

Eigen::Vector3d three(const std::vector<double>& x, std::size_t row) { return Eigen::Vector3d(&x[3 * row]); }

// The burn of the accuracy tests: 10 kg to 2.5 kg in 15 s, thrust 150 N against a weight of 98 N, a
// sideways exhaust component (u_rel not along g).
const Burn kBurn{10.0, -0.5, Eigen::Vector3d(20.0, -5.0, -300.0), Eigen::Vector3d(0.0, 0.0, -9.81),
                 Eigen::Vector3d(1.0, 2.0, 3.0), Eigen::Vector3d(5.0, -1.0, 0.0)};
constexpr double kBurnTime = 15.0;  // [s]
constexpr double kH = 0.01;         // [s]
constexpr std::int64_t kSteps = 1500;

// RK4 error bounds of this burn at step h over T (a = |ṁ|/m_min = 0.2 s⁻¹, m_min = 2.5 kg, u = |u_rel|):
// v̇ = g + f(t), f = ṁ u_rel/m(t), and the mass is exact at every stage (ṁ constant), so RK4's v update is
// Simpson's rule on f: error ≤ h⁵/2880 max|f⁗| per step, f⁗ = 24 ṁ⁴ ṁ u_rel/m⁵:
//   E_v = T h⁴ u a⁵ / 120.
// Its p update is p0 + h v0 + h²/6 (f0 + 2 f_half), exact for f of degree ≤ 2; the Taylor remainders of
// both sides bound its error by (1/120 + 1/144) h⁵ max|f‴| ≤ h⁵/60 · 6 a⁴ u per step, plus h times the v
// error carried: E_p = T h⁴ u a⁴ / 10 + T E_v.
// Round-off: each step adds, per coordinate, 2 eps |y| (the update) + 8 eps h |ẏ|: over N steps
// R = N (2 eps Y + 8 eps h Ẏ) with Y, Ẏ the largest |y|, |ẏ| along the run.
struct Rk4Bounds {
  double v, p;
};
Rk4Bounds rk4_bounds(const Burn& b, double T, double h) {
  const double m_min = b.m0 + b.rate * T, a = std::abs(b.rate) / m_min, u = b.u_rel.norm();
  const double E_v = T * std::pow(h, 4) * u * std::pow(a, 5) / 120.0;
  const double E_p = T * std::pow(h, 4) * u * std::pow(a, 4) / 10.0 + T * E_v;
  const double N = T / h;
  const double v_max = b.v0.norm() + b.g.norm() * T + u * std::log(b.m0 / m_min);
  const double p_max = b.p0.norm() + v_max * T;
  const double a_max = b.g.norm() + u * a;
  return {E_v + N * (2.0 * kEps * v_max + 8.0 * kEps * h * a_max), E_p + N * (2.0 * kEps * p_max + 8.0 * kEps * h * v_max)};
}

TEST(VariableMassParticleModel, Rk4FollowsTheClosedFormOfTheBurn) {
  const SceneSimulation r = run(kBurn, Method::rk4, kH, kSteps);
  const Rk4Bounds bound = rk4_bounds(kBurn, kBurnTime, kH);
  for (std::size_t i = 0; i < r.size(); i += 100) {
    const Exact e = exact_at(kBurn, r.t[i]);
    // + the closed form's own rounding: 40 ulps of |u| t (the bracket), 4 ulps of |p|
    EXPECT_LE((three(r.p_W, i) - e.p).norm(), bound.p + 40.0 * kEps * kBurn.u_rel.norm() * r.t[i] + 4.0 * kEps * e.p.norm()) << r.t[i];
    EXPECT_LE((three(r.v_W, i) - e.v).norm(), bound.v + 8.0 * kEps * e.v.norm()) << r.t[i];
    EXPECT_NEAR(r.mass[i], e.m, 2.0 * kEps * kBurn.m0 * i) << r.t[i];  // one rounding of m += h ṁ per step
  }
}

// Tsiolkovsky: the speed the thrust alone gives between m0 and m1 is |u_rel| ln(m0/m1) (gravity adds g T,
// integrated exactly by RK4: a polynomial of degree 1).
TEST(VariableMassParticleModel, TsiolkovskyDeltaV) {
  const SceneSimulation r = run(kBurn, Method::rk4, kH, kSteps);
  const std::size_t last = r.size() - 1;
  const double m1 = r.mass[last];
  const Eigen::Vector3d dv_thrust = three(r.v_W, last) - kBurn.v0 - kBurn.g * r.t[last];
  const double tsiolkovsky = kBurn.u_rel.norm() * std::log(kBurn.m0 / m1);
  // RK4's v bound (+ 8 ulps of the subtraction of |v| ≤ 600 m/s); it is 1e-12 of Δv here, under the
  // required 1e-9
  const double bound = rk4_bounds(kBurn, kBurnTime, kH).v + 8.0 * kEps * 600.0;
  EXPECT_LE(std::abs(dv_thrust.norm() - tsiolkovsky), bound);
  EXPECT_LE(bound / tsiolkovsky, 1e-9);
  // along −u_rel (the exhaust pushes the other way)
  EXPECT_LE((dv_thrust.normalized() + kBurn.u_rel.normalized()).norm(), bound / tsiolkovsky * 4.0);
}

// Momentum bookkeeping (notes eq. (4.36)): d(m v)/dt = m g + ṁ (v + u_rel). Integrated from 0 with ṁ
// constant, ∫ ṁ v dt = ṁ (p − p0) and ∫ m dt = m0 t + ṁ t²/2, so on every recorded state
//   J = m v − m0 v0 − g (m0 t + ṁ t²/2) − ṁ (p − p0) − ṁ u_rel t = 0.
TEST(VariableMassParticleModel, MomentumBookkeepingOnTheRecordedTrajectory) {
  const SceneSimulation r = run(kBurn, Method::rk4, kH, kSteps);
  const Rk4Bounds bound = rk4_bounds(kBurn, kBurnTime, kH);
  for (std::size_t i = 0; i < r.size(); ++i) {
    const double t = r.t[i], m = r.mass[i];
    const Eigen::Vector3d mv = three(r.linear_momentum_W, i);
    EXPECT_EQ(mv, m * three(r.v_W, i));  // the record's momentum is m v with the mass now
    const Eigen::Vector3d J = mv - kBurn.m0 * kBurn.v0 - kBurn.g * (kBurn.m0 * t + 0.5 * kBurn.rate * t * t) -
                              kBurn.rate * (three(r.p_W, i) - kBurn.p0) - kBurn.rate * kBurn.u_rel * t;
    // m e_v + |ṁ| e_p, and 16 eps of the terms (each ≤ m0 · 600 + |ṁ| · 5000 + |ṁ| |u| T ≈ 1e4)
    EXPECT_LE(J.norm(), kBurn.m0 * bound.v + std::abs(kBurn.rate) * bound.p + 16.0 * kEps * 1e4) << t;
  }
}

// The thrust's work W_T = ∫ ṁ u_rel·v dt = ṁ u_rel·(p − p0): RK4 updates W_T by exactly ṁ u_rel· the
// update of p, so they differ only by round-off (N steps of a few eps of |W_T| ≤ |ṁ u| |p|max ≈ 3e5 J).
// Power columns: m g·v and ṁ u_rel·v; the energies and momenta of the record.
TEST(VariableMassParticleModel, RecordsWorkPowerEnergyOfEachElement) {
  const SceneSimulation r = run(kBurn, Method::rk4, kH, kSteps);
  ASSERT_EQ(r.work.size(), 2 * r.size());
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Eigen::Vector3d p = three(r.p_W, i), v = three(r.v_W, i);
    const double m = r.mass[i];
    const Eigen::Vector3d thrust = kBurn.rate * kBurn.u_rel;
    EXPECT_LE(std::abs(r.work[2 * i + 1] - thrust.dot(p - kBurn.p0)), static_cast<double>(i) * 8.0 * kEps * 3e5 + 8.0 * kEps * 3e5);
    EXPECT_EQ(r.power[2 * i], m * kBurn.g.dot(v));
    EXPECT_EQ(r.power[2 * i + 1], thrust.dot(v));
    EXPECT_EQ(r.kinetic_energy[i], 0.5 * m * v.squaredNorm());
    EXPECT_EQ(r.potential_energy[i], -m * kBurn.g.dot(p));
    EXPECT_EQ(r.total_energy[i], r.kinetic_energy[i] + r.potential_energy[i]);
    EXPECT_EQ(three(r.angular_momentum_W, i), p.cross(m * v));
    EXPECT_EQ(Eigen::Vector4d(&r.q_WB[4 * i]), Eigen::Vector4d(0.0, 0.0, 0.0, 1.0));
    EXPECT_TRUE(three(r.w_B, i).isZero(0.0) && three(r.pivot_reaction_W, i).isZero(0.0) &&
                three(r.angular_momentum_O_W, i).isZero(0.0));
  }
  EXPECT_EQ(r.work[0], 0.0);
  EXPECT_EQ(r.work[1], 0.0);
  // gravity's work over the burn is negative (climbing) and the thrust's positive
  EXPECT_LT(r.work[2 * (r.size() - 1)], 0.0);
  EXPECT_GT(r.work[2 * (r.size() - 1) + 1], 0.0);
}

// The fast model's rate equals what the element terms it replaces give (UniformGravityTerm on the mass now,
// ThrustTerm), divided by the mass now, at random states and masses.
TEST(VariableMassParticleModel, RateMatchesTheElementTerms) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1.0, 1.0), mass(0.2, 12.0);
  const Model model = model_of(kBurn);
  const std::vector<Body> bodies{Particle(kBurn.m0)};
  MassFlow flow;
  flow.rate = kBurn.rate;
  Thrust thrust;
  thrust.frame = Frame::world, thrust.u_rel = kBurn.u_rel;
  const UniformGravityTerm gravity(UniformGravity{kBurn.g, {}}, bodies, "elements[0]");
  const ThrustTerm thrust_term(thrust, bodies, {flow}, "elements[1]");
  for (int trial = 0; trial < 50; ++trial) {
    Y y;
    for (int i = 0; i < 11; ++i) y[i] = 100.0 * U(rng);
    y[6] = mass(rng);
    std::vector<BodyKinematics> k(1);
    k[0].p_W = y.segment<3>(0), k[0].v_W = y.segment<3>(3), k[0].m = y[6];
    std::vector<BodyWrench> w(1);
    const double P_gravity = gravity.add_wrenches(y[7], k, w);
    const double P_thrust = thrust_term.add_wrenches(y[7], k, w);
    Y dy, xi;
    model.rate(y, dy);
    // a = f/m against g + (ṁ u)/m: a few roundings of |a| ≤ 10 + 150/0.2
    EXPECT_LE((dy.segment<3>(3) - w[0].f_W / y[6]).norm(), 8.0 * kEps * 760.0);
    EXPECT_EQ(dy.segment<3>(0), y.segment<3>(3));
    EXPECT_EQ(dy[6], kBurn.rate);
    EXPECT_EQ(dy[7], 1.0);
    // powers: a few roundings of |f| |v| ≤ (12 · 10 + 150) · 173
    EXPECT_LE(std::abs(dy[8] - P_gravity), 8.0 * kEps * 270.0 * 173.0);
    EXPECT_LE(std::abs(dy[9] - P_thrust), 8.0 * kEps * 270.0 * 173.0);
    // the mass-flow power ½ ṁ |v|²: a few roundings of it
    EXPECT_LE(std::abs(dy[10] - 0.5 * kBurn.rate * y.segment<3>(3).squaredNorm()), 8.0 * kEps * 0.5 * 0.5 * 3e4);
    model.velocity(y, xi);
    EXPECT_EQ(xi, dy);
  }
}

// The burn declared as a scene: compile chooses this fast model for a constant rate and the generic
// SceneModel for a rate of t; both follow the closed form within RK4's bound, and a run longer than the
// burn is refused up front naming steps and dt.
TEST(VariableMassParticleModel, SceneRunsOnTheFastPathAndAgreesWithTheGenericOne) {
  Scene scene;
  scene.bodies.emplace_back(Particle(kBurn.m0));
  scene.body_names = {"rocket"};
  MassFlow flow;
  flow.rate = kBurn.rate;
  scene.mass_flows = {flow};
  scene.elements.emplace_back(UniformGravity{kBurn.g, {}});
  Thrust thrust;
  thrust.frame = Frame::world, thrust.u_rel = kBurn.u_rel;
  scene.elements.emplace_back(thrust);
  SimulationOptions o;
  o.method = Method::rk4, o.dt = kH, o.steps = kSteps;
  const std::vector<BodyState> initial{ParticleState{kBurn.p0, kBurn.v0}};
  const CompiledScene fast = compile_scene(scene, o.method);
  EXPECT_STREQ(scene_path_name(fast.path()), "one_body");
  EXPECT_NE(one_body_model_if<VariableMassParticleModel>(fast.one_body_model()), nullptr);
  Scene of_t = scene;
  of_t.mass_flows[0]->rate = 0.0;
  of_t.mass_flows[0]->rate_of_t = [](double) { return kBurn.rate; };
  const CompiledScene generic = compile_scene(of_t, o.method);
  EXPECT_STREQ(scene_path_name(generic.path()), "generic");
  const Rk4Bounds bound = rk4_bounds(kBurn, kBurnTime, kH);
  const Exact e = exact_at(kBurn, kBurnTime);
  for (const CompiledScene* compiled : {&fast, &generic}) {
    const SceneSimulation r = simulate(*compiled, initial, o);
    const std::size_t last = r.size() - 1;
    EXPECT_LE((three(r.p_W, last) - e.p).norm(), bound.p + 40.0 * kEps * kBurn.u_rel.norm() * kBurnTime + 4.0 * kEps * e.p.norm());
    EXPECT_LE((three(r.v_W, last) - e.v).norm(), bound.v + 8.0 * kEps * e.v.norm());
    EXPECT_NEAR(r.mass[last], e.m, 2.0 * kEps * kBurn.m0 * static_cast<double>(kSteps));
  }
  o.steps = 2000;  // the mass runs out at t = 20 s: step 2000 ends there
  try {
    simulate(fast, initial, o);
    ADD_FAILURE() << "a run past the burn-out was not refused";
  } catch (const std::invalid_argument& error) {
    const std::string text = error.what();
    EXPECT_EQ(text.rfind("mass_flows[0]: expected a positive mass, got m = ", 0), 0u) << text;
    EXPECT_NE(text.find("(the body 'rocket' runs out of mass in the step from t = "), std::string::npos) << text;
    EXPECT_NE(text.find("steps, dt: expected a run that ends before the mass runs out at t = 20 s (at most 1999 steps"),
              std::string::npos) << text;
  }
}

// ---- every method, with its observed order -----------------------------------------------------------

// A burn short and strong enough for truncation errors far above round-off at these steps: 10 kg to 4 kg
// in 4 s (|ṁ|/m ≤ 0.375 s⁻¹).
const Burn kShortBurn{10.0, -1.5, Eigen::Vector3d(20.0, -5.0, -300.0), Eigen::Vector3d(0.0, 0.0, -9.81),
                      Eigen::Vector3d(1.0, 2.0, 3.0), Eigen::Vector3d(5.0, -1.0, 0.0)};

double end_error(Method method, std::int64_t n) {
  constexpr double T = 4.0;
  const SceneSimulation r = run(kShortBurn, method, T / static_cast<double>(n), n);
  const Exact e = exact_at(kShortBurn, T);
  const std::size_t last = r.size() - 1;
  return std::max((three(r.p_W, last) - e.p).norm(), (three(r.v_W, last) - e.v).norm());
}

class VariableMassOrder : public ::testing::TestWithParam<Method> {};

TEST_P(VariableMassOrder, StepHalvingSlopeMatchesTheMethodsOrder) {
  const Method method = GetParam();
  // 'exact' steps as exact_flow_kick (a particle's free flow is exact, the thrust's kick is not): order 2
  const int order = method == Method::exact ? 2 : method_info(method).order;
  const std::int64_t n0 = order == 4 ? 32 : order == 2 ? 100 : 400;
  const double e0 = end_error(method, n0), e2 = end_error(method, 4 * n0);
  const double slope = std::log2(e0 / e2) / 2.0;
  // e = C hᵖ (1 + O(h |ṁ|/m)), h |ṁ|/m ≤ 0.05 at these steps: the slope moves by well under 0.2; the errors
  // (≥ 1e-9) are far above round-off (≤ 1e-12 over ≤ 1600 steps)
  EXPECT_NEAR(slope, order, 0.2) << method_info(method).name << ": " << e0 << " " << e2;
  EXPECT_GT(e2, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, VariableMassOrder,
                         ::testing::Values(Method::explicit_euler, Method::semi_implicit_euler,
                                           Method::semi_implicit_euler_implicit_gyroscopic, Method::rk4, Method::rkmk4,
                                           Method::implicit_midpoint, Method::splitting_dlm, Method::splitting_dlm_yoshida4,
                                           Method::exact_flow_kick, Method::exact),
                         [](const ::testing::TestParamInfo<Method>& info) { return method_info(info.param).name; });

// ---- the mass running out ----------------------------------------------------------------------------

// The number after `key` in `text` (NaN if absent).
double number_after(const std::string& text, const std::string& key) {
  const std::size_t at = text.find(key);
  return at == std::string::npos ? std::nan("") : std::stod(text.substr(at + key.size()));
}

// 10 kg at −2 kg/s runs out at t = 5 s; with dt = 0.3 s that is inside the 17th step, from 4.8 s to 5.1 s
// (m = 0.4 kg at its start). Every method takes the 16 steps before it and raises in it, naming the step.
class VariableMassRunsOut : public ::testing::TestWithParam<Method> {};

TEST_P(VariableMassRunsOut, RaisesInTheStepWhereTheMassReachesZero) {
  const Method method = GetParam();
  const Burn burn{10.0, -2.0, Eigen::Vector3d(0.0, 0.0, -300.0), Eigen::Vector3d(0.0, 0.0, -9.81),
                  Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  constexpr double dt = 0.3;
  Model model = model_of(burn, "stage1");
  model.set_time(0.0);
  Y y = model.coordinates({BodyState(ParticleState{})}, 0.0);
  std::string message;
  std::int64_t failed = -1;
  visit_method(method, [&](auto integrator) {
    auto work = workspace<decltype(integrator)>(model, y);
    for (std::int64_t i = 0; i < 20 && failed < 0; ++i) {
      try {
        decltype(integrator)::step(model, y, dt, work);
      } catch (const std::invalid_argument& e) {
        message = e.what(), failed = i;
      }
      y[model.time_index()] = static_cast<double>(i + 1) * dt;
    }
    return 0;
  });
  EXPECT_EQ(failed, 16) << message;
  const std::string prefix = "mass_flows[0]: expected a positive mass, got m = ";
  ASSERT_EQ(message.rfind(prefix, 0), 0u) << message;
  EXPECT_LE(number_after(message, prefix), 0.0) << message;
  // evaluated at a stage or sub-step end inside the step; Yoshida's mass parts keep the t of their sub-step
  // (t0, t0 + 1.35 dt, t0 − 0.35 dt, t0 + dt: integrators/yoshida4.hpp), the first of which meets m < 0 here
  const double t = number_after(message, " kg at t = ");
  if (method == Method::splitting_dlm_yoshida4) {
    EXPECT_NEAR(t, 4.8, 1e-13) << message;
  } else {
    EXPECT_GE(t, 5.0 - 1e-12) << message;
    EXPECT_LE(t, 4.8 + dt + 1e-12) << message;
  }
  // the step start as the method computed it (t0 + a sum of sub-steps): within a few ulps of 4.8 s
  EXPECT_NEAR(number_after(message, "(the body 'stage1' runs out of mass in the step from t = "), 4.8, 1e-13) << message;
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, VariableMassRunsOut,
                         ::testing::Values(Method::explicit_euler, Method::semi_implicit_euler,
                                           Method::semi_implicit_euler_implicit_gyroscopic, Method::rk4, Method::rkmk4,
                                           Method::implicit_midpoint, Method::splitting_dlm, Method::splitting_dlm_yoshida4,
                                           Method::exact_flow_kick, Method::exact),
                         [](const ::testing::TestParamInfo<Method>& info) { return method_info(info.param).name; });

// ---- construction --------------------------------------------------------------------------------------

using test::message_of;

TEST(VariableMassParticleModel, RefusesWhatItCannotRun) {
  const Particle particle(2.0);
  MassFlow flow;
  flow.rate = -0.1;
  Thrust thrust;
  thrust.frame = Frame::world, thrust.u_rel = Eigen::Vector3d(0.0, 0.0, -100.0);
  const Eigen::Vector3d g(0.0, 0.0, -9.81);
  const auto starts = [](const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; };
  EXPECT_NO_THROW(Model(particle, flow, thrust, 1, g, 0, 2));
  EXPECT_NO_THROW(Model(particle, flow, thrust, 0, Eigen::Vector3d::Zero(), -1, 1));
  MassFlow of_t;
  of_t.rate_of_t = [](double) { return -0.1; };
  EXPECT_TRUE(starts(message_of([&] { Model(particle, of_t, thrust, 1, g, 0, 2); }), "mass_flows[0].rate_of_t: expected none"));
  MassFlow infinite;
  infinite.rate = -std::numeric_limits<double>::infinity();
  EXPECT_TRUE(starts(message_of([&] { Model(particle, infinite, thrust, 1, g, 0, 2); }), "mass_flows[0].rate: expected a finite number"));
  Thrust body_frame = thrust;
  body_frame.frame = Frame::body;
  EXPECT_TRUE(starts(message_of([&] { Model(particle, flow, body_frame, 1, g, 0, 2); }), "elements[1].frame: expected Frame::world"));
  EXPECT_TRUE(starts(message_of([&] { Model(particle, flow, thrust, 2, g, 0, 2); }), "thrust_element: expected an index in [0, 2)"));
  EXPECT_TRUE(starts(message_of([&] { Model(particle, flow, thrust, 1, g, 1, 2); }), "gravity_element: expected another element"));
  EXPECT_TRUE(starts(message_of([&] { Model(particle, flow, thrust, 0, g, -1, 1); }), "g_W: expected zero without a gravity element"));
  EXPECT_TRUE(starts(message_of([&] { Model(particle, flow, thrust, 1, Eigen::Vector3d(0.0, std::nan(""), 0.0), 0, 2); }),
                     "g_W: expected finite values"));
  const Model model(particle, flow, thrust, 1, g, 0, 2);
  EXPECT_TRUE(starts(message_of([&] { model.coordinates(ParticleState{}, 0.0, 0.0); }), "mass: expected a finite mass > 0 [kg], got 0"));
  EXPECT_EQ(model.work_index(0), 8);
  EXPECT_EQ(model.work_index(1), 9);
  EXPECT_EQ(model.coordinates({BodyState(ParticleState{})}, 0.5)[model.mass_index()], 2.0);
}

}  // namespace
}  // namespace rigiddyn
