// Dynamics and integrators from C++ (no Python): observed order by step halving, inverse dynamics
// undoes forward dynamics, impulse-momentum, work-energy, form selection, bad inputs.
#include <gtest/gtest.h>

#include "rigiddyn/dynamics/rigid_body_dynamics.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

namespace rigiddyn {
namespace {

Eigen::Matrix3d full_inertia() {
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
  const RigidBody body(2.5, full_inertia());
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
  EXPECT_NEAR(slope, order, 0.2) << e[0] << " " << e[1] << " " << e[2];
}

INSTANTIATE_TEST_SUITE_P(Methods, OrderTest,
                         ::testing::Values(Method::explicit_euler, Method::semi_implicit_euler,
                                           Method::semi_implicit_euler_implicit_gyroscopic, Method::rk4,
                                           Method::rkmk4));

TEST(Dynamics, InverseUndoesForward) {
  std::mt19937 rng(7);
  std::normal_distribution<double> N;
  const RigidBody body(1.7, full_inertia());
  for (int trial = 0; trial < 50; ++trial) {
    RigidBodyState s;
    s.q_WB = Eigen::Quaterniond(N(rng), N(rng), N(rng), N(rng)).normalized();
    s.v_W = Eigen::Vector3d(N(rng), N(rng), N(rng));
    s.w_B = Eigen::Vector3d(N(rng), N(rng), N(rng));
    const ComWrench w{Eigen::Vector3d(N(rng), N(rng), N(rng)), Eigen::Vector3d(N(rng), N(rng), N(rng))};
    const BodyAcceleration a = forward_dynamics(body, s, w, standard_gravity());
    const ComWrench back = inverse_dynamics(body, s, a, standard_gravity());
    EXPECT_LT((back.f_W - w.f_W).norm(), 1e-12);
    EXPECT_LT((back.n_B - w.n_B).norm(), 1e-12);
  }
}

TEST(Dynamics, ImpulseChangesMomentumByTheImpulse) {
  const RigidBody body(1.3, full_inertia());
  const RigidBodyState s = generic_state();
  const Eigen::Vector3d J(0.3, -1.2, 0.7), p_GP_B(0.2, 0.1, -0.4), O(1.0, 2.0, -1.0);
  const RigidBodyState after = apply_impulse(body, s, J, p_GP_B, Frame::body);
  const Eigen::Vector3d J_W = s.q_WB * J, p_WP = s.p_W + s.q_WB * p_GP_B;
  EXPECT_LT((linear_momentum(body, after) - linear_momentum(body, s) - J_W).norm(), 1e-14);
  const Eigen::Vector3d dH = angular_momentum(body, after, O) - angular_momentum(body, s, O);
  EXPECT_LT((dH - (p_WP - O).cross(J_W)).norm(), 1e-13);
}

TEST(Simulate, WorkEnergyRk4) {
  const RigidBody body(2.5, full_inertia());
  SimulationOptions o = loaded(Method::rk4, 1e-3, 1000);
  o.record_every = 100;
  const Trajectory tr = simulate(body, generic_state(), o);
  ASSERT_EQ(tr.size(), 11u);
  for (std::size_t i = 0; i < tr.size(); ++i) {
    EXPECT_NEAR(tr.kinetic_energy[i] - tr.kinetic_energy[0], tr.work[i], 1e-11);
  }
}

TEST(Models, EulerFormIsChosenFromTheInertia) {
  EXPECT_EQ(RigidBody(1.0, 0.4 * Eigen::Matrix3d::Identity()).euler_form(), EulerForm::spherical);
  EXPECT_EQ(RigidBody(1.0, Eigen::Vector3d(1, 2, 2.5).asDiagonal().toDenseMatrix()).euler_form(), EulerForm::principal);
  EXPECT_EQ(RigidBody(1.0, full_inertia()).euler_form(), EulerForm::full);
}

TEST(Models, ImplicitGyroscopicKickReducesTheResidual) {
  // one Newton step: the residual of I(w' - w) + h w' x I w' = h n is O(h^2) smaller than at w' = w
  const FullEuler euler(full_inertia());
  const Eigen::Vector3d w(1.0, 3.0, -0.5), n(0.1, 0.2, 0.3);
  const double h = 0.01;
  auto residual = [&](const Eigen::Vector3d& x) {
    return (full_inertia() * (x - w) + h * x.cross(full_inertia() * x) - h * n).norm();
  };
  EXPECT_LT(residual(euler.implicit_gyroscopic_kick(w, n, h)), 1e-3 * residual(w));
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
