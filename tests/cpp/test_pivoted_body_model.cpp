// PivotedBodyModel<Euler> (scene/fast/pivoted_body_model.hpp), the fast model of one pivoted body under
// uniform gravity and scheduled loads: the heavy top's invariants under RK4, the observed order of every
// method, the pivot's reaction against Newton's law for the centre of mass along the trajectory, the free
// rotation when the pivot is the centre of mass, the loads reduced to O; and the compound pendulum's
// small-amplitude period (the planar kernels).
#include "test_inputs.hpp"
#include "test_numbers.hpp"
#include "error_bounds.hpp"
#include "rigiddyn/dynamics/pivoted_body_dynamics.hpp"
#include "rigiddyn/exact/free_body.hpp"
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/models/rigid_body.hpp"
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/fast/pivoted_body_model.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace {

using namespace rigiddyn;

using rigiddyn::test::kEps;
using rigiddyn::test::kG;

// The heavy top: a symmetric body (A, A, C) about its axis, the centre of mass d = 0.2 m up the axis from
// the tip O. The body frame B is turned by R0 against the principal axes, so I_C and I_O carry products of
// inertia (FullEuler, the general path), and c = R0 (0, 0, d).
const Eigen::Matrix3d kR0 = Eigen::AngleAxisd(0.6, Eigen::Vector3d(1.0, 2.0, -1.0).normalized()).toRotationMatrix();
PivotedBody heavy_top() {
  const Eigen::Matrix3d I_C = kR0 * Eigen::Vector3d(0.05, 0.05, 0.08).asDiagonal() * kR0.transpose();
  return PivotedBody(RigidBody(1.0, I_C), kR0 * Eigen::Vector3d(0.0, 0.0, 0.2), Eigen::Vector3d(0.3, -0.2, 1.0));
}
// tilted 0.5 rad from the vertical, spinning at 12 rad/s about its axis, a little transverse rate
PivotedBodyState top_state() {
  PivotedBodyState s;
  s.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX())) * Eigen::Quaterniond(kR0.transpose());
  s.w_B = kR0 * Eigen::Vector3d(0.5, 0.0, 12.0);
  return s;
}

using TopModel = PivotedBodyModel<FullEuler>;
TopModel top_model(const std::vector<AppliedLoad>& loads = {}, const Eigen::Vector3d& point_B = Eigen::Vector3d::Zero()) {
  return TopModel(heavy_top(), kG, 0, loads, loads.empty() ? -1 : 1, loads.empty() ? 1 : 2, point_B);
}

template <class Integrator, class Model>
typename Model::Coordinates run(const Model& model, typename Model::Coordinates y, double h, int steps) {
  auto work = workspace<Integrator>(model, y);
  for (int i = 0; i < steps; ++i) Integrator::step(model, y, h, work);
  return y;
}

double energy(const SceneSimulation& r, std::size_t i) { return r.total_energy[i]; }
double vertical_momentum(const SceneSimulation& r, std::size_t i) { return r.angular_momentum_O_W[3 * i + 2]; }

// The records of y0 and of y after `steps` RK4 steps of h.
SceneSimulation rk4_records(const TopModel& model, double h, int steps) {
  SceneSimulation out;
  Eigen::Matrix<double, 10, 1> y = TopModel::coordinates(top_state(), 0.0);
  model.record(y, 0.0, out);
  y = run<Rk4>(model, y, h, steps);
  model.record(y, h * steps, out);
  return out;
}

TEST(PivotedBodyModel, HeavyTopKeepsEnergyAndVerticalMomentumUnderRk4) {
  // Over T = 40 s (≈ 80 turns of spin, several precessions): T + V and H_O·ẑ (gravity's moment about O is
  // horizontal) are invariants. RK4's local error on a motion whose rates are ≤ Ω is ≤ (hΩ)⁵/120 relative
  // to the quantity (the error of y' = iΩy), so after N = T/h steps |ΔE| ≤ N (hΩ)⁵ E_scale / 120, E_scale
  // = T_kin + |V| (H_scale = |H_O|). Ω: the largest body rate of the run (the spin, plus the precession
  // that gravity adds: ≤ 2 |ω0|). The drift at h/2 must drop by 2⁴ to 2⁵: order 4, or 5 where the motion
  // is an oscillation (RK4's leading local error is then orthogonal to ∇E: |R(iθ)|² = 1 − θ⁶/72), within
  // 2^±0.5 for the next order's share at these hΩ.
  const TopModel model = top_model();
  const double T = 40.0, h = 4e-3;
  const int steps = static_cast<int>(T / h);
  const SceneSimulation a = rk4_records(model, h, steps), b = rk4_records(model, h / 2, 2 * steps);
  const double Omega = 2.0 * top_state().w_B.norm();
  const double energy_scale = a.kinetic_energy[0] + std::abs(a.potential_energy[0]);
  const double H_scale = Eigen::Vector3d(&a.angular_momentum_O_W[0]).norm();
  const double per_step = std::pow(h * Omega, 5) / 120.0;
  const double dE = std::abs(energy(a, 1) - energy(a, 0)), dH = std::abs(vertical_momentum(a, 1) - vertical_momentum(a, 0));
  EXPECT_LE(dE, steps * per_step * energy_scale);
  EXPECT_LE(dH, steps * per_step * H_scale);
  const double dE_half = std::abs(energy(b, 1) - energy(b, 0));
  EXPECT_GT(dE / dE_half, 11.0) << dE << " " << dE_half;
  EXPECT_LT(dE / dE_half, 45.0) << dE << " " << dE_half;
  // the top does precess: H_O is not conserved, only its vertical part
  EXPECT_GT((Eigen::Vector3d(&a.angular_momentum_O_W[3]) - Eigen::Vector3d(&a.angular_momentum_O_W[0])).norm(), 0.1 * H_scale);
}

// The error of the state y against y_ref: the attitude angle [rad] and |Δω| / |ω_ref| (q and −q are one
// rotation).
template <class Coordinates>
double state_error(const Coordinates& y, const Coordinates& y_ref) {
  const Eigen::Quaterniond q(y[3], y[0], y[1], y[2]), q_ref(y_ref[3], y_ref[0], y_ref[1], y_ref[2]);
  const double angle = q_ref.angularDistance(q);
  return std::max(angle, (y.template segment<3>(4) - y_ref.template segment<3>(4)).norm() / y_ref.template segment<3>(4).norm());
}

// Step halving over T = 0.5 s: e(h) against RK4 at h/64 (its error (1/64)⁴ of RK4's at h, far below every
// method's at h/4). The observed order log2(e(h/2)/e(h/4)) is the method's within 0.35 (the next term of
// the error expansion at h|ω| ≤ 0.015). 'exact' refuses a body under gravity (the next test runs it).
template <class Euler>
void expect_orders(const PivotedBodyModel<Euler>& model, const PivotedBodyState& s) {
  using Model = PivotedBodyModel<Euler>;
  const double T = 0.5, h = T / 400;
  const typename Model::Coordinates y0 = Model::coordinates(s, 0.0);
  const typename Model::Coordinates reference = run<Rk4>(model, y0, h / 64, 400 * 64);
  for (const MethodInfo& info : method_table()) {
    if (info.method == Method::exact) {
      EXPECT_THROW(visit_method(info.method, [&](auto integrator) { run<decltype(integrator)>(model, y0, h, 1); }),
                   std::invalid_argument);
      continue;
    }
    double e[3];
    for (int k = 0; k < 3; ++k) {
      const int n = 400 << k;
      e[k] = visit_method(info.method, [&](auto integrator) { return state_error(run<decltype(integrator)>(model, y0, T / n, n), reference); });
    }
    EXPECT_NEAR(std::log2(e[1] / e[2]), info.order, 0.35) << info.name << ": errors " << e[0] << " " << e[1] << " " << e[2];
  }
}

TEST(PivotedBodyModel, EveryMethodHasItsOrder) {
  // the heavy top in its principal frame (PrincipalEuler: B along the axes of I_O, c on the symmetry axis)
  const PivotedBody top(RigidBody(1.0, Eigen::Vector3d(0.05, 0.05, 0.08)), Eigen::Vector3d(0.0, 0.0, 0.2));
  ASSERT_EQ(top.euler_form(), EulerForm::principal);
  PivotedBodyState s;
  s.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()));
  s.w_B = Eigen::Vector3d(0.5, 0.0, 12.0);
  expect_orders(PivotedBodyModel<PrincipalEuler>(top, kG, 0, {}, -1, 1), s);
  // an asymmetric body with products of inertia about O (FullEuler) under gravity and a body-fixed load.
  // (Not the symmetric top in a turned frame: the DLM free rotation of a FullEuler whose I has a repeated
  // moment stalls at ~1e-9 relative, for RigidBodyModel as well, which hides Yoshida's fourth order.)
  const Eigen::Matrix3d I_C = kR0 * Eigen::Vector3d(0.05, 0.065, 0.08).asDiagonal() * kR0.transpose();
  const PivotedBody body(RigidBody(1.0, I_C), Eigen::Vector3d(0.05, -0.1, 0.2));
  ASSERT_EQ(body.euler_form(), EulerForm::full);
  AppliedLoad load;
  load.force = Eigen::Vector3d(0.5, 0.0, 1.0), load.torque = Eigen::Vector3d(0.0, 0.1, 0.0), load.frame = Frame::body;
  expect_orders(PivotedBodyModel<FullEuler>(body, kG, 0, {load}, 1, 2), top_state());
}

TEST(PivotedBodyModel, TorqueFreeAboutThePivotIsEulerPoinsotWithTheInertiaAboutO) {
  // No gravity, c ≠ 0: the free rotation about O with I_O. 'exact' and exact_flow_kick step the closed form of
  // I_O; after N steps they agree with TorqueFreeSolution(I_O) within N steps' round-off amplified by the
  // flow (error_bounds.hpp: 16 ε κ per step, times the sum of the flow's Jacobians, plus the closed form's).
  const PivotedBody body = heavy_top();
  const PivotedBodyModel<FullEuler> model(body, Eigen::Vector3d::Zero(), -1, {}, -1, 0);
  const PivotedBodyState s = top_state();
  const double T = 2.0;
  const int n = 50;
  const TorqueFreeSolution exact(body.inertia_O(), s.q_WB, s.w_B);
  const TorqueFreeState end = exact.state_at(T);
  Eigen::Matrix<double, 10, 1> y_end;
  y_end << end.q_WB.coeffs(), end.w_B, T, 0.0, 0.0;
  const Eigen::Matrix3d& I = body.inertia_O();
  const double bound = test::to_euclidean(I, s.w_B) *
                       (test::exact_step_roundoff(I) * test::torque_free_amplification_sum(I, s.q_WB, s.w_B, T, n) +
                        test::closed_form_error(I, s.w_B, T));
  for (const Method m : {Method::exact, Method::exact_flow_kick}) {
    const auto y = visit_method(m, [&](auto integrator) {
      return run<decltype(integrator)>(model, TopModel::coordinates(s, 0.0), T / n, n);
    });
    EXPECT_LE(state_error(y, y_end) * s.w_B.norm(), bound) << method_info(m).name;
  }
}

TEST(PivotedBodyModel, PivotAtTheCentreIsTheFreeRigidBody) {
  // c = 0: RK4 on the pivoted model takes the same steps as simulate of the free rigid body (its layout, principal
  // form), with or without gravity (no moment about O = C). The two evaluate the same equations, each written its own
  // way, so their round-off differs (the order of the sums, the compiler's contraction into FMAs): 16 ε per step (scaled), amplified by the flow.
  const Eigen::Vector3d moments(1.0, 2.0, 3.0);
  const PivotedBody body(RigidBody(2.0, moments), Eigen::Vector3d::Zero());
  const PivotedBodyModel<PrincipalEuler> free_pivot(body, Eigen::Vector3d::Zero(), -1, {}, -1, 0);
  const PivotedBodyModel<PrincipalEuler> heavy_pivot(body, kG, 0, {}, -1, 1);
  RigidBodyState r;
  r.q_WB = top_state().q_WB;
  r.w_B = Eigen::Vector3d(0.3, 1.5, -0.4);
  PivotedBodyState p;
  p.q_WB = r.q_WB, p.w_B = r.w_B;
  const double h = 0.01;
  const int n = 1000;
  SimulationOptions o;
  o.method = Method::rk4, o.dt = h, o.steps = n, o.record_every = n;
  const Trajectory free = simulate(RigidBody(2.0, moments), r, o);
  const Eigen::Vector4d q_end(&free.q_WB[4]);
  const Eigen::Vector3d w_end(&free.w_B[3]);
  const Eigen::Matrix3d I = moments.asDiagonal();
  const double bound = test::to_euclidean(I, r.w_B) * 16.0 * kEps * test::inertia_condition(I) *
                       test::torque_free_amplification_sum(I, r.q_WB, r.w_B, h * n, n);
  for (const auto* model : {&free_pivot, &heavy_pivot}) {
    const auto y = run<Rk4>(*model, PivotedBodyModel<PrincipalEuler>::coordinates(p, 0.0), h, n);
    EXPECT_LE((y.segment<4>(0) - q_end).norm(), bound);
    EXPECT_LE((y.segment<3>(4) - w_end).norm(), bound);
  }
  // the pivot holds the weight, exactly
  SceneSimulation out;
  heavy_pivot.record(PivotedBodyModel<PrincipalEuler>::coordinates(p, 0.0), 0.0, out);
  EXPECT_EQ(Eigen::Vector3d(out.pivot_reaction_W.data()), -2.0 * kG);
  EXPECT_EQ(out.power[0], 0.0);
}

TEST(PivotedBodyModel, ReactionIsNewtonForTheCentreOfMassAlongTheTrajectory) {
  // m p̈_C = R + m g along the RK4 trajectory: p̈_C by the five-point central difference of the recorded
  // p_W at spacing δ = h. Its error: truncation δ⁴/90 |p⁽⁶⁾| with |p⁽ᵏ⁾| ≤ |c| (2Ω)ᵏ (C moves on a sphere of
  // radius |c| at body rates ≤ Ω; factor 2 for the rates' own change), rounding (1+16+30+16+1)/12 · ε |p| / δ²,
  // and RK4's trajectory differs from a solution by a local error (hΩ)⁵ |c| per step, i.e. an acceleration
  // error ≲ |c| Ω² (hΩ)⁴ (bounded generously by 10 times that).
  const TopModel model = top_model();
  const PivotedBody body = heavy_top();
  const double h = 2e-4;
  const int n = 2000;
  Eigen::Matrix<double, 10, 1> y = TopModel::coordinates(top_state(), 0.0);
  SceneSimulation out;
  model.record(y, 0.0, out);
  auto work = workspace<Rk4>(model, y);
  for (int i = 1; i <= n; ++i) {
    Rk4::step(model, y, h, work);
    model.record(y, h * i, out);
  }
  double Omega = 0.0, p_max = 0.0;
  for (int i = 0; i <= n; ++i) {
    Omega = std::max(Omega, Eigen::Vector3d(&out.w_B[3 * i]).norm());
    p_max = std::max(p_max, Eigen::Vector3d(&out.p_W[3 * i]).norm());
  }
  const double c = body.p_OC_B().norm();
  const double tolerance = std::pow(h, 4) / 90.0 * c * std::pow(2.0 * Omega, 6) + 64.0 / 12.0 * kEps * p_max / (h * h) +
                           10.0 * c * Omega * Omega * std::pow(h * Omega, 4);
  double worst = 0.0;
  for (int i = 2; i <= n - 2; i += 7) {
    const auto p = [&](int k) { return Eigen::Vector3d(&out.p_W[3 * k]); };
    const Eigen::Vector3d a_fd = (-p(i + 2) + 16.0 * p(i + 1) - 30.0 * p(i) + 16.0 * p(i - 1) - p(i - 2)) / (12.0 * h * h);
    const Eigen::Vector3d R(&out.pivot_reaction_W[3 * i]);
    worst = std::max(worst, (body.mass() * a_fd - (R + body.mass() * kG)).norm());
  }
  EXPECT_LE(worst, body.mass() * tolerance);
  EXPECT_GT(Eigen::Vector3d(&out.pivot_reaction_W[0]).norm(), 1.0);  // a real reaction, not zero
}

TEST(PivotedBodyModel, LoadsAreReducedToThePivot) {
  // A world-frame force and couple and a body-frame force and couple, the forces at point_B: the model's α
  // and its reaction agree with forward_dynamics on the wrench reduced to C by wrench_at_com (the moment
  // transfer of rigid_body_dynamics), within the round-off of torques of size |I_O|(|α| + |ω|²) + |c+r||f|.
  const Eigen::Vector3d r_B(0.05, -0.1, 0.3);
  std::vector<AppliedLoad> loads(2);
  loads[0].force = Eigen::Vector3d(1.0, 2.0, -0.5), loads[0].torque = Eigen::Vector3d(0.1, 0.0, 0.3), loads[0].frame = Frame::world;
  loads[1].force = Eigen::Vector3d(-0.4, 0.2, 1.5), loads[1].torque = Eigen::Vector3d(0.0, -0.2, 0.1), loads[1].frame = Frame::body;
  const TopModel model = top_model(loads, r_B);
  const PivotedBodyState s = top_state();
  const auto y = TopModel::coordinates(s, 0.0);
  const ComWrench a = wrench_at_com(s.q_WB, loads[0].force, loads[0].torque, s.q_WB * r_B, Frame::world);
  const ComWrench b = wrench_at_com(s.q_WB, loads[1].force, loads[1].torque, r_B, Frame::body);
  ComWrench sum;
  sum.f_W = a.f_W + b.f_W, sum.tau_B = a.tau_B + b.tau_B;
  const PivotedAcceleration expected = forward_dynamics(heavy_top(), s, sum, kG);
  Eigen::Matrix<double, 9, 1> xi;
  model.velocity(y, xi);
  const double scale = heavy_top().inertia_O().norm() * (expected.alpha_B.norm() + s.w_B.squaredNorm()) +
                       (heavy_top().p_OC_B() + r_B).norm() * (sum.f_W.norm() + 9.81);
  const double kappa = test::inertia_condition(heavy_top().inertia_O());
  EXPECT_LE((xi.segment<3>(3) - expected.alpha_B).norm(), 64.0 * kEps * kappa * scale / heavy_top().inertia_O().norm());
  EXPECT_LE((model.reaction_W(y) - expected.reaction_W).norm(), 64.0 * kEps * kappa * (scale + sum.f_W.norm() + 9.81));
  // the loads' power is f·v_P + τ·ω (v_P of the point of application): their τ_O·ω
  const BodyKinematics k = kinematics_of(heavy_top(), s);
  const Eigen::Vector3d v_P = k.v_W + s.q_WB * s.w_B.cross(r_B);
  const double power = (a.f_W + b.f_W).dot(v_P) + (loads[0].torque.dot(s.q_WB * s.w_B)) + loads[1].torque.dot(s.w_B);
  EXPECT_NEAR(xi[8], power, 64.0 * kEps * scale * s.w_B.norm());
}

TEST(PivotedBodyModel, WorkOfLoadsAndGravityBalancesTheKineticEnergyAcrossASwitch) {
  // T(t) − T(0) = W_gravity + W_loads (work-energy, Craig), W_gravity = V(0) − V(t) (a uniform field), with
  // the loads switched off at t = 0.3 s (set_time between the two pieces, as the run loop does). RK4's
  // error as in the energy test: N (hΩ)⁵/120 of the energies' scale.
  AppliedLoad push;
  push.force = Eigen::Vector3d(0.0, 3.0, 0.0), push.torque = Eigen::Vector3d(0.5, 0.0, 0.0), push.frame = Frame::body;
  push.t_end = 0.3;
  TopModel model = top_model({push}, Eigen::Vector3d(0.0, 0.0, 0.1));
  const double h = 1e-3;
  Eigen::Matrix<double, 10, 1> y = TopModel::coordinates(top_state(), 0.0);
  SceneSimulation out;
  model.set_time(0.0);
  model.record(y, 0.0, out);
  y = run<Rk4>(model, y, h, 300);
  model.set_time(0.3);
  Eigen::Matrix<double, 9, 1> xi;
  model.velocity(y, xi);
  EXPECT_EQ(xi[8], 0.0);  // no load in the second piece
  y = run<Rk4>(model, y, h, 700);
  model.record(y, 1.0, out);
  const double Omega = 2.0 * top_state().w_B.norm();
  const double scale = out.kinetic_energy[0] + std::abs(out.potential_energy[0]) + std::abs(out.work[3]);
  const double bound = 1000 * std::pow(h * Omega, 5) / 120.0 * scale;
  EXPECT_NEAR(out.kinetic_energy[1] - out.kinetic_energy[0], out.work[2] + out.work[3], bound);
  EXPECT_NEAR(out.work[2], out.potential_energy[0] - out.potential_energy[1], bound);
  EXPECT_GT(std::abs(out.work[3]), 0.1);  // the loads did work
  EXPECT_EQ(out.mass, std::vector<double>({1.0, 1.0}));
}

TEST(PivotedBodyModel, IsTheGenericSceneModelOfTheSameScene) {
  // The scene (the top, UniformGravity, ScheduledLoads with a point off C) on the generic SceneModel and on
  // the fast model evaluate the same kernels in other orders: RK4 runs agree to their round-off, 16 ε of
  // the state per step growing at most linearly along the quasi-periodic motion (1 + Ω t), over N steps;
  // the records (energies, momenta, reaction, works and powers) within 64 ε of their scales at the end.
  AppliedLoad load;
  load.force = Eigen::Vector3d(0.5, -1.0, 2.0), load.torque = Eigen::Vector3d(0.1, 0.2, -0.1), load.frame = Frame::body;
  const Eigen::Vector3d r_B(0.02, 0.0, 0.1);
  Scene scene;
  scene.bodies.emplace_back(heavy_top());
  scene.elements.emplace_back(UniformGravity{kG, {}});
  scene.elements.emplace_back(ScheduledLoads{0, {load}, r_B});
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  const SceneModel& generic = compiled.model();
  const TopModel fast = top_model({load}, r_B);
  Eigen::VectorXd yg = generic.coordinates({BodyState(top_state())}, 0.0);
  Eigen::Matrix<double, 10, 1> yf = TopModel::coordinates(top_state(), 0.0);
  ASSERT_EQ(yg.size(), 16);  // the fast model's 10, then the linear and angular impulses of the elements (6)
  const double h = 1e-3;
  const int n = 200;
  auto work_generic = workspace<Rk4>(generic, yg);
  auto work_fast = workspace<Rk4>(fast, yf);
  for (int i = 0; i < n; ++i) Rk4::step(generic, yg, h, work_generic), Rk4::step(fast, yf, h, work_fast);
  const double Omega = 2.0 * top_state().w_B.norm();
  const double bound = n * 16.0 * kEps * (1.0 + Omega * n * h);
  EXPECT_LE((yg.head<4>() - yf.head<4>()).norm(), bound);
  EXPECT_LE((yg.segment<3>(4) - yf.segment<3>(4)).norm(), bound * top_state().w_B.norm());
  SceneSimulation rg, rf;
  generic.record(yg, n * h, rg);
  fast.record(yf, n * h, rf);
  const double energy_scale = rf.kinetic_energy[0] + std::abs(rf.potential_energy[0]) + std::abs(rf.work[1]);
  EXPECT_NEAR(rg.total_energy[0], rf.total_energy[0], 64.0 * kEps * energy_scale + bound * energy_scale);
  for (int e = 0; e < 2; ++e) {
    EXPECT_NEAR(rg.work[e], rf.work[e], (64.0 * kEps + bound) * energy_scale);
    EXPECT_NEAR(rg.power[e], rf.power[e], (64.0 * kEps + bound) * energy_scale * Omega);
  }
  const double force_scale = Eigen::Vector3d(rf.pivot_reaction_W.data()).norm() + 9.81;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(rg.pivot_reaction_W[i], rf.pivot_reaction_W[i], (64.0 * kEps + bound) * force_scale);
    EXPECT_NEAR(rg.angular_momentum_O_W[i], rf.angular_momentum_O_W[i], (64.0 * kEps + bound) * energy_scale / Omega * 4.0);
    EXPECT_NEAR(rg.p_W[i], rf.p_W[i], (64.0 * kEps + bound) * 2.0);
  }
  EXPECT_EQ(rg.mass, rf.mass);
}

TEST(PivotedBodyModel, BadElementIndicesAreRefused) {
  const PivotedBody body = heavy_top();
  EXPECT_THROW(TopModel(body, kG, 1, {}, -1, 1), std::invalid_argument);     // gravity_element out of range
  EXPECT_THROW(TopModel(body, kG, -1, {}, -1, 0), std::invalid_argument);    // gravity without its element
  EXPECT_THROW(TopModel(body, kG, 0, {AppliedLoad{}}, -1, 1), std::invalid_argument);  // loads without theirs
  EXPECT_THROW(TopModel(body, kG, 0, {}, 0, 1), std::invalid_argument);      // one element twice
}

// ---- the compound pendulum --------------------------------------------------------------------------

TEST(PivotedPlanarBody, SmallAmplitudePeriodIsTwoPiSqrtIOverMgd) {
  // θ̈ = α(θ) from forward_dynamics (the planar kernels), RK4 at h = T0/4000 over 10 periods. The period of
  // the pendulum is T0 (1 + θ0²/16 + 11 θ0⁴/3072 + ...), a series with positive coefficients whose tail after
  // θ0²/16 is ≤ 2 · 11/3072 θ0⁴ for θ0 ≤ 0.1; the measured period (zero crossings of θ − θ_eq, linearly
  // interpolated: time error ≤ h³ ω0²/8 per crossing since |θ''| ≤ ω0² |θ − θ_eq| there; RK4's phase error
  // ≤ 10 · 4000 (h ω0)⁵/120) must fall within that.
  const PivotedPlanarBody body(2.0, 0.05, Eigen::Vector2d(0.3, 0.1), Eigen::Vector2d(0.5, -0.2));
  const Eigen::Vector3d g(0.0, -9.81, 0.0);
  const double d = body.p_OC_B().norm();
  const double omega0 = std::sqrt(body.mass() * 9.81 * d / body.inertia_O_zz()), T0 = 2.0 * M_PI / omega0;
  // equilibrium: R c along g, i.e. Rz(θ_eq) c = (0, −d)
  const double theta_eq = -M_PI / 2.0 - std::atan2(body.p_OC_B().y(), body.p_OC_B().x());
  const double theta0 = 0.05, h = T0 / 4000;
  const auto alpha = [&](double theta) { return forward_dynamics(body, PivotedPlanarBodyState{theta, 0.0}, ComWrench{}, g).alpha; };
  double theta = theta_eq + theta0, omega = 0.0, t = 0.0;
  std::vector<double> crossings;
  while (crossings.size() < 21) {
    const double k1t = omega, k1w = alpha(theta);
    const double k2t = omega + 0.5 * h * k1w, k2w = alpha(theta + 0.5 * h * k1t);
    const double k3t = omega + 0.5 * h * k2w, k3w = alpha(theta + 0.5 * h * k2t);
    const double k4t = omega + h * k3w, k4w = alpha(theta + h * k3t);
    const double next = theta + h / 6.0 * (k1t + 2 * k2t + 2 * k3t + k4t);
    omega += h / 6.0 * (k1w + 2 * k2w + 2 * k3w + k4w);
    const double a = theta - theta_eq, b = next - theta_eq;
    if (a != 0.0 && (a < 0.0) != (b < 0.0)) crossings.push_back(t + h * a / (a - b));
    theta = next, t += h;
  }
  const double period = (crossings[20] - crossings[0]) / 10.0;
  const double series = T0 * (1.0 + theta0 * theta0 / 16.0);
  const double measurement = (2.0 * h * h * h * omega0 * omega0 / 8.0 + 40000.0 * std::pow(h * omega0, 5) / 120.0 * T0) / 10.0;
  EXPECT_NEAR(period, series, 2.0 * 11.0 / 3072.0 * std::pow(theta0, 4) * T0 + measurement);
  EXPECT_GT(period - T0, 0.5 * theta0 * theta0 / 16.0 * T0);  // the amplitude correction is seen
}

}  // namespace
