// Dynamics and integrators from C++ (no Python): observed order by step halving, inverse dynamics
// undoes forward dynamics, impulse-momentum, work-energy, form selection, bad inputs.
#include <gtest/gtest.h>

#include "rigiddyn/dynamics/particle_dynamics.hpp"
#include "rigiddyn/dynamics/planar_body_dynamics.hpp"
#include "rigiddyn/dynamics/rigid_body_dynamics.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace rigiddyn {
namespace {

Eigen::Matrix3d inertia_with_products() {
  Eigen::Matrix3d I;
  I << 0.9, 0.05, -0.1, 0.05, 1.4, 0.08, -0.1, 0.08, 1.9;
  return I;
}

RigidBodyState generic_state() {
  RigidBodyState s;
  s.p_W = Eigen::Vector3d(0.1, -0.2, 0.3);
  s.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  s.v_W = Eigen::Vector3d(0.5, 0.2, -0.1);
  s.w_B = Eigen::Vector3d(1.2, -0.7, 2.0);
  return s;
}

SimulationOptions loaded(Method method, double dt, std::int64_t steps) {
  SimulationOptions o;
  o.method = method;
  o.dt = dt;
  o.steps = steps;
  o.record_every = steps;
  o.gravity_W = standard_gravity();
  o.loads = {AppliedLoad{Eigen::Vector3d(0.4, -0.2, 1.0), Eigen::Vector3d(0.05, 0.1, -0.2), Frame::world},
             AppliedLoad{Eigen::Vector3d(0.3, 0.1, -0.2), Eigen::Vector3d(-0.1, 0.2, 0.15), Frame::body}};
  return o;
}

// max-norm difference of the final states (attitude as the geodesic angle)
double difference(const Trajectory& a, const Trajectory& b) {
  const std::size_t n = a.size() - 1, m = b.size() - 1;
  double d = 0.0;
  for (int i = 0; i < 3; ++i) {
    d = std::max({d, std::abs(a.p_W[3 * n + i] - b.p_W[3 * m + i]), std::abs(a.v_W[3 * n + i] - b.v_W[3 * m + i]),
                  std::abs(a.w_B[3 * n + i] - b.w_B[3 * m + i])});
  }
  const Eigen::Quaterniond qa(Eigen::Vector4d(Eigen::Map<const Eigen::Vector4d>(&a.q_WB[4 * n])));
  const Eigen::Quaterniond qb(Eigen::Vector4d(Eigen::Map<const Eigen::Vector4d>(&b.q_WB[4 * m])));
  return std::max(d, qa.angularDistance(qb));
}

// observed order from step halving: e(h) = |y_h - y_{h/2}| ~ C h^p
class OrderTest : public ::testing::TestWithParam<Method> {};

TEST_P(OrderTest, StepHalvingSlopeMatchesTheory) {
  const Method method = GetParam();
  const RigidBody body(2.5, inertia_with_products());
  const int order = method_info(method).order;
  const std::int64_t n0 = order == 4 ? 16 : 200;
  std::vector<double> e;
  for (int k = 0; k < 3; ++k) {
    const std::int64_t n = n0 << k;
    const Trajectory coarse = simulate(body, generic_state(), loaded(method, 1.0 / n, n));
    const Trajectory fine = simulate(body, generic_state(), loaded(method, 0.5 / n, 2 * n));
    e.push_back(difference(coarse, fine));
  }
  const double slope = std::log2(e[0] / e[2]) / 2.0;
  // the next term of the expansion is O(h |ω|) <= 0.05 relative at these steps: the slope moves by
  // far less than 0.2 (errors >= 1e-10, far above round-off)
  EXPECT_NEAR(slope, order, 0.2) << e[0] << " " << e[1] << " " << e[2];
}

INSTANTIATE_TEST_SUITE_P(Methods, OrderTest,
                         ::testing::Values(Method::explicit_euler, Method::semi_implicit_euler,
                                           Method::semi_implicit_euler_implicit_gyroscopic, Method::rk4,
                                           Method::rkmk4));

TEST(Dynamics, InverseUndoesForward) {
  std::mt19937 rng(7);
  std::normal_distribution<double> N;
  const RigidBody body(1.7, inertia_with_products());
  for (int trial = 0; trial < 50; ++trial) {
    RigidBodyState s;
    s.q_WB = Eigen::Quaterniond(N(rng), N(rng), N(rng), N(rng)).normalized();
    s.v_W = Eigen::Vector3d(N(rng), N(rng), N(rng));
    s.w_B = Eigen::Vector3d(N(rng), N(rng), N(rng));
    const ComWrench w{Eigen::Vector3d(N(rng), N(rng), N(rng)), Eigen::Vector3d(N(rng), N(rng), N(rng))};
    const BodyAcceleration a = forward_dynamics(body, s, w, standard_gravity());
    const ComWrench back = inverse_dynamics(body, s, a, standard_gravity());
    // forward then inverse: a solve with I (kappa ~3) and terms <= |w| |I w| + |n| ~ 30 (normal
    // inputs), a few dozen roundings: 30 x 3 x 30 eps = 6e-13
    EXPECT_LT((back.f_W - w.f_W).norm(), 1e-12);
    EXPECT_LT((back.tau_B - w.tau_B).norm(), 1e-12);
  }
}

TEST(Dynamics, ImpulseChangesMomentumByTheImpulse) {
  const RigidBody body(1.3, inertia_with_products());
  const RigidBodyState s = generic_state();
  const Eigen::Vector3d J(0.3, -1.2, 0.7), p_GP_B(0.2, 0.1, -0.4), O(1.0, 2.0, -1.0);
  const RigidBodyState after = apply_impulse(body, s, J, p_GP_B, Frame::body);
  const Eigen::Vector3d J_W = s.q_WB * J, p_WP = s.p_W + s.q_WB * p_GP_B;
  // m (v + J/m) - m v: 3 roundings of numbers <= 4; the moments: x |p_WP - O| <= 4, plus I w terms
  EXPECT_LT((linear_momentum(body, after) - linear_momentum(body, s) - J_W).norm(), 1e-14);
  const Eigen::Vector3d dH = angular_momentum(body, after, O) - angular_momentum(body, s, O);
  EXPECT_LT((dH - (p_WP - O).cross(J_W)).norm(), 1e-13);
}

TEST(Simulate, WorkEnergyRk4) {
  const RigidBody body(2.5, inertia_with_products());
  SimulationOptions o = loaded(Method::rk4, 1e-3, 1000);
  o.record_every = 100;
  const Trajectory tr = simulate(body, generic_state(), o);
  ASSERT_EQ(tr.size(), 11u);
  // T - W is an invariant of the ODE: RK4 changes it by its local error, ~(h |ω|)^5/120 T per step,
  // and by 2 roundings per step of numbers <= max T (worst case linear), 1000 steps
  double T_max = 0.0, w_max = 0.0;
  for (double T : tr.kinetic_energy) T_max = std::max(T_max, T);
  for (double w : tr.w_B) w_max = std::max(w_max, std::abs(w));
  const double tol = 1000 * (2 * std::numeric_limits<double>::epsilon() + std::pow(1e-3 * std::sqrt(3.0) * w_max, 5) / 120) * T_max;
  for (std::size_t i = 0; i < tr.size(); ++i) {
    EXPECT_NEAR(tr.kinetic_energy[i] - tr.kinetic_energy[0], tr.work[i], tol);
  }
}

TEST(Models, EulerFormIsChosenFromTheInertia) {
  EXPECT_EQ(RigidBody(1.0, 0.4 * Eigen::Matrix3d::Identity()).euler_form(), EulerForm::spherical);
  EXPECT_EQ(RigidBody(1.0, Eigen::Vector3d(1, 2, 2.5).asDiagonal().toDenseMatrix()).euler_form(), EulerForm::principal);
  EXPECT_EQ(RigidBody(1.0, inertia_with_products()).euler_form(), EulerForm::full);
}

TEST(Models, ImplicitGyroscopicKickReducesTheResidual) {
  // one Newton step: the residual of I(w' - w) + h w' x I w' = h n is O(h^2) smaller than at w' = w
  const FullEuler euler(inertia_with_products());
  const Eigen::Vector3d w(1.0, 3.0, -0.5), n(0.1, 0.2, 0.3);
  const double h = 0.01;
  auto residual = [&](const Eigen::Vector3d& x) {
    return (inertia_with_products() * (x - w) + h * x.cross(inertia_with_products() * x) - h * n).norm();
  };
  // one Newton step on a quadratic residual leaves h |D x I D| <= h |I| |D|^2, D = w' - w = O(h |w|^2)
  // ~ 0.1 here: O(h) smaller than the initial h |w x I w - n|, i.e. < 1e-3 of it at h = 0.01
  EXPECT_LT(residual(euler.implicit_gyroscopic_kick(w, n, h)), 1e-3 * residual(w));
}

TEST(Models, PrincipalImplicitKickEqualsTheGeneralNewtonStep) {
  // the closed-form diagonal specialisation against the general Jacobian and solve
  const Eigen::Vector3d I(0.7, 1.9, 3.1), w(1.0, 3.0, -0.5), n(0.1, 0.2, 0.3);
  const PrincipalEuler euler(I);
  for (const double h : {1e-3, 0.05, 0.7}) {
    const Eigen::Vector3d general = gyroscopic_newton_kick(I.asDiagonal().toDenseMatrix(), w, n, h);
    // the same Newton step, closed form vs LU: backward stable, cond(J) <= ~10 at h = 0.7: 10 x 4 eps
    EXPECT_LT((euler.implicit_gyroscopic_kick(w, n, h) - general).norm(), 1e-14 * general.norm()) << h;
  }
}

TEST(Models, Solve3x3MatchesLu) {
  Eigen::Matrix3d J;
  J << 2.0, -0.3, 0.5, 0.1, 1.5, -0.7, 0.4, 0.2, 3.0;
  const Eigen::Vector3d b(0.3, -1.1, 2.0);
  const Eigen::Vector3d x = solve_3x3(J.row(0), J.row(1), J.row(2), b);
  EXPECT_LT((x - J.partialPivLu().solve(b)).norm(), 1e-15 * x.norm() * 10);  // cond(J) ~ 3: both ~3 x 4 eps
}

TEST(Models, RigidBodyUsesTheInertiaLayersCheck) {
  const Eigen::Matrix3d hlw = Eigen::Vector3d(2.0, 1.0, 2.0 / 3.0).asDiagonal();  // 1 + 2/3 < 2
  std::string body_message, inertia_message;
  try {
    RigidBody(1.0, hlw);
  } catch (const std::invalid_argument& e) {
    body_message = e.what();
  }
  try {
    checked_inertia(1.0, hlw, InertiaCheck::physical);
  } catch (const std::invalid_argument& e) {
    inertia_message = e.what();
  }
  EXPECT_FALSE(body_message.empty());
  EXPECT_EQ(body_message, inertia_message);
  EXPECT_EQ(RigidBody(1.0, hlw, InertiaCheck::allow_unrealizable).euler_form(), EulerForm::principal);
  // positive semi-definite (valid for the inertia layer) but singular: Euler's equations need I^-1
  EXPECT_THROW(RigidBody(1.0, Eigen::Vector3d(0.0, 1.0, 1.0)), std::invalid_argument);
}

TEST(Models, RigidBodyFromPrincipalMomentsIsTheDiagonalInertia) {
  const Eigen::Vector3d moments(1.0, 2.0, 2.5), hlw(2.0, 1.0, 2.0 / 3.0);
  const RigidBody body(3.0, moments);
  EXPECT_EQ(body.mass(), 3.0);
  EXPECT_EQ(body.inertia_com(), Eigen::Matrix3d(moments.asDiagonal()));  // stored exactly
  EXPECT_EQ(body.euler_form(), EulerForm::principal);
  // the same realizability check as the matrix form
  EXPECT_THROW(RigidBody(1.0, hlw), std::invalid_argument);
  EXPECT_EQ(RigidBody(1.0, hlw, InertiaCheck::allow_unrealizable).inertia_com(), Eigen::Matrix3d(hlw.asDiagonal()));
}

TEST(Dynamics, ParticleInverseUndoesForwardAndImpulseIsMomentum) {
  const Particle particle(1.9);
  const ParticleState s{Eigen::Vector3d(0.1, -0.2, 0.3), Eigen::Vector3d(0.5, 0.2, -0.1)};
  const Eigen::Vector3d f(0.4, -1.0, 0.2), J(0.3, 0.1, -0.7), O(1.0, 2.0, -1.0);
  const Eigen::Vector3d a = forward_dynamics(particle, s, f, standard_gravity());
  // m (f/m + g) - m g: 4 roundings of numbers <= 20 (m g = 18.6), in 3 components
  EXPECT_LT((inverse_dynamics(particle, s, a, standard_gravity()) - f).norm(),
            4 * 20 * std::sqrt(3.0) * std::numeric_limits<double>::epsilon());
  const ParticleState after = apply_impulse(particle, s, J);
  EXPECT_LT((linear_momentum(particle, after) - linear_momentum(particle, s) - J).norm(), 1e-15);  // numbers <= 1.3: 3 roundings
  const Eigen::Vector3d dH = angular_momentum(particle, after, O) - angular_momentum(particle, s, O);
  EXPECT_LT((dH - (s.p_W - O).cross(J)).norm(), 1e-14);
}

TEST(Dynamics, DefaultsAreTheWorldOriginAndNoGravity) {
  // one default for all three models: angular momentum about the world origin O, no gravity
  const RigidBody body(2.0, inertia_with_products());
  const RigidBodyState s = generic_state();
  const Particle particle(2.0);
  const ParticleState ps{s.p_W, s.v_W};
  const PlanarBody planar(2.0, 0.8);
  const PlanarBodyState qs{Eigen::Vector2d(0.3, -1.0), 0.7, Eigen::Vector2d(1.0, -0.4), 1.3};
  const Eigen::Vector3d O = Eigen::Vector3d::Zero();
  EXPECT_EQ(angular_momentum(body, s), angular_momentum(body, s, O));
  EXPECT_EQ(angular_momentum(particle, ps), angular_momentum(particle, ps, O));
  EXPECT_EQ(angular_momentum(planar, qs), angular_momentum(planar, qs, Eigen::Vector2d::Zero()));
  // about O the particle's is p x m v (eq. (4.42)), not zero
  EXPECT_EQ(angular_momentum(particle, ps), s.p_W.cross(2.0 * s.v_W));
  EXPECT_EQ(potential_energy(body, s), 0.0);
  EXPECT_EQ(potential_energy(particle, ps), 0.0);
  EXPECT_EQ(potential_energy(planar, qs), 0.0);
}

TEST(Dynamics, PlanarEqualsSpatialKeptInThePlane) {
  const PlanarBody planar(2.2, 0.8);
  const RigidBody spatial(2.2, Eigen::Vector3d(0.5, 0.6, 0.8));  // principal moments
  const PlanarBodyState ps{Eigen::Vector2d(0.3, -1.0), 0.7, Eigen::Vector2d(1.0, -0.4), 1.3};
  RigidBodyState bs;
  bs.p_W << ps.p_W, 0.0;
  bs.q_WB = Eigen::AngleAxisd(ps.theta, Eigen::Vector3d::UnitZ());
  bs.v_W << ps.v_W, 0.0;
  bs.w_B << 0.0, 0.0, ps.omega;
  const Eigen::Vector2d f(0.4, -0.3), p_GP(0.2, 0.5);
  const double n = 0.25;
  for (const Frame frame : {Frame::world, Frame::body}) {
    const PlanarAcceleration a = forward_dynamics(planar, ps, wrench_at_com(ps.theta, f, n, p_GP, frame));
    const BodyAcceleration a3 = forward_dynamics(
        spatial, bs, wrench_at_com(bs.q_WB, Eigen::Vector3d(f.x(), f.y(), 0), Eigen::Vector3d(0, 0, n),
                                   Eigen::Vector3d(p_GP.x(), p_GP.y(), 0), frame));
    // planar and spatial formulas of one motion: a few roundings of numbers <= 1 each (no gravity)
    EXPECT_LT((Eigen::Vector3d(a.a_W.x(), a.a_W.y(), 0.0) - a3.a_W).norm(), 1e-14);
    EXPECT_LT((Eigen::Vector3d(0.0, 0.0, a.alpha) - a3.alpha_B).norm(), 1e-14);
    const PlanarWrench back = inverse_dynamics(planar, ps, a);
    EXPECT_NEAR(back.tau, n + p_GP.x() * f.y() - p_GP.y() * f.x(), 1e-14);
  }
  const Eigen::Vector2d O(1.0, 1.0);
  EXPECT_NEAR(angular_momentum(planar, ps, O), angular_momentum(spatial, bs, Eigen::Vector3d(O.x(), O.y(), 0)).z(),
              1e-14);
  EXPECT_NEAR(kinetic_energy(planar, ps).total(), kinetic_energy(spatial, bs).total(), 1e-14);
}

TEST(BadInput, Throws) {
  const RigidBody body(1.0, Eigen::Matrix3d::Identity());
  SimulationOptions o;
  o.steps = 1;
  o.dt = 0.0;
  EXPECT_THROW(simulate(body, RigidBodyState{}, o), std::invalid_argument);
  o.dt = 1e-3;
  RigidBodyState bad;
  bad.w_B.x() = NAN;
  EXPECT_THROW(simulate(body, bad, o), std::invalid_argument);
  EXPECT_THROW(RigidBody(1.0, -Eigen::Matrix3d::Identity()), std::invalid_argument);
  EXPECT_THROW(RigidBody(0.0, Eigen::Matrix3d::Identity()), std::invalid_argument);
  EXPECT_THROW(method_from_name("rk5"), std::invalid_argument);
  try {
    simulate(body, bad, o);
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("initial.w_B", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace rigiddyn
