// Bodies about a fixed point: PivotedBody / PivotedPlanarBody, the per-body kernels of
// models/pivoted_body.hpp and the dynamics of dynamics/pivoted_body_dynamics.hpp.
#include "invalid_argument_message.hpp"
#include "test_inputs.hpp"
#include "test_numbers.hpp"
#include "rigiddyn/dynamics/pivoted_body_dynamics.hpp"
#include "rigiddyn/dynamics/rigid_body_dynamics.hpp"
#include "rigiddyn/models/pivoted_body.hpp"
#include "rigiddyn/models/pivoted_planar_body.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace {

using namespace rigiddyn;

using rigiddyn::test::kEps;

using rigiddyn::test::expect_invalid;

// A rigid body with products of inertia: principal moments (1, 1.7, 2.2) turned by a fixed rotation.
RigidBody full_body() {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  return RigidBody(2.5, Eigen::Matrix3d(R * Eigen::Vector3d(1.0, 1.7, 2.2).asDiagonal() * R.transpose()));
}

PivotedBodyState some_state() {
  PivotedBodyState s;
  s.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, 0.4, -0.8).normalized()));
  s.w_B = Eigen::Vector3d(0.7, -1.3, 2.1);
  return s;
}

using rigiddyn::test::kG;

// ---- the body ------------------------------------------------------------------------------------

TEST(PivotedBody, ParallelAxisMatchesPointMassSum) {
  // a cloud of point masses: I_C and I_O summed directly (Σ m (|r|² 1 − r rᵀ), r from C or from O)
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-1.0, 1.0), mass(0.5, 2.0);
  constexpr int n = 12;
  Eigen::Matrix<double, 3, n> r;
  Eigen::Matrix<double, n, 1> m;
  for (int i = 0; i < n; ++i) r.col(i) = Eigen::Vector3d(u(rng), u(rng), u(rng)), m[i] = mass(rng);
  const double M = m.sum();
  const Eigen::Vector3d C = r * m / M, O(0.9, -1.4, 0.3);
  const auto point_sum = [&](const Eigen::Vector3d& about, double& scale) {
    Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
    scale = 0.0;
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d d = r.col(i) - about;
      I += m[i] * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
      scale += m[i] * d.squaredNorm();
    }
    return I;
  };
  double scale_C = 0.0, scale_O = 0.0;
  const Eigen::Matrix3d I_C = point_sum(C, scale_C), I_O = point_sum(O, scale_O);
  const PivotedBody body(RigidBody(M, I_C), C - O);
  // Both sides sum at most n + 4 rounded products of size ≤ Σ m|d|² (the larger of the two scales; the
  // parallel-axis route adds m|c|² ≤ Σ m|d|² terms): each entry within γ_{n+4} ≈ (n + 4) ε of that scale,
  // twice (both routes), and C itself carries (n + 2) ε relative rounding, which m|c|² doubles.
  const double tolerance = 4.0 * (n + 4) * kEps * std::max(scale_C, scale_O);
  EXPECT_LE((body.inertia_O() - I_O).cwiseAbs().maxCoeff(), tolerance);
  EXPECT_GT(std::abs(I_O(0, 1)), 1e-3);  // products of inertia present: the full form
  EXPECT_EQ(body.euler_form(), EulerForm::full);
}

TEST(PivotedBody, SymmetricTopIsPrincipalAndPivotAtCentreKeepsTheBody) {
  const PivotedBody top(RigidBody(2.0, Eigen::Vector3d(0.3, 0.3, 0.5)), Eigen::Vector3d(0.0, 0.0, 0.25));
  // I_O = diag(A + m d², A + m d², C): exactly representable here (0.3 + 2·0.0625 = 0.425)
  EXPECT_EQ(top.inertia_O(), Eigen::Matrix3d(Eigen::Vector3d(0.425, 0.425, 0.5).asDiagonal()));
  EXPECT_EQ(top.euler_form(), EulerForm::principal);
  const PivotedBody ball(RigidBody(1.0, Eigen::Vector3d(0.4, 0.4, 0.4)), Eigen::Vector3d::Zero());
  EXPECT_EQ(ball.euler_form(), EulerForm::spherical);
  EXPECT_EQ(ball.inertia_O(), ball.inertia_com());
  EXPECT_EQ(ball.digits_lost(), 0.0);
}

TEST(PivotedBody, DigitsLostReportsTheTransferOverTheSmallestMoment) {
  // m|c|² = 3 · (1e3)² = 3e6 against λ_min(I_C) = 0.5: log10(6e6) digits
  const PivotedBody far(RigidBody(3.0, Eigen::Vector3d(0.5, 0.6, 0.9)), Eigen::Vector3d(0.0, 1e3, 0.0));
  // log10 of a ratio computed within 2 ε relative: within 2 ε / ln 10 + ε log10(6e6) absolute
  EXPECT_NEAR(far.digits_lost(), std::log10(6e6), 8.0 * kEps * std::log10(6e6));
  const PivotedBody near(RigidBody(3.0, Eigen::Vector3d(0.5, 0.6, 0.9)), Eigen::Vector3d(0.0, 1e-3, 0.0));
  EXPECT_EQ(near.digits_lost(), 0.0);  // m|c|² below λ_min: nothing lost
}

TEST(PivotedBody, BadInputNamesTheArgument) {
  const RigidBody body = full_body();
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  expect_invalid([&] { PivotedBody(body, Eigen::Vector3d(0.0, nan, 0.0)); }, "p_OC_B");
  expect_invalid([&] { PivotedBody(body, Eigen::Vector3d::Zero(), Eigen::Vector3d(inf, 0.0, 0.0)); }, "p_WO");
  PivotedBodyState s;
  s.q_WB = Eigen::Quaterniond(0.0, 0.0, 0.0, 0.0);
  expect_invalid([&] { checked_state(s, "initial"); }, "initial.q_WB");
  s = PivotedBodyState{};
  s.w_B[1] = nan;
  expect_invalid([&] { checked_state(s); }, "state.w_B");
  s = PivotedBodyState{};
  s.q_WB = Eigen::Quaterniond(2.0, 0.0, 0.0, 0.0);  // |q| = 2: not meant as a rotation
  expect_invalid([&] { checked_state(s); }, "state.q_WB");
  expect_invalid([] { PivotedPlanarBody(0.0, 1.0, Eigen::Vector2d(1.0, 0.0)); }, "mass");
  expect_invalid([] { PivotedPlanarBody(1.0, -1.0, Eigen::Vector2d(1.0, 0.0)); }, "inertia_zz");
  expect_invalid([&] { PivotedPlanarBody(1.0, 1.0, Eigen::Vector2d(nan, 0.0)); }, "p_OC_B");
  expect_invalid([&] { PivotedPlanarBody(1.0, 1.0, Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(0.0, inf)); }, "p_WO");
  expect_invalid([&] { checked_state(PivotedPlanarBodyState{nan, 0.0}); }, "state.theta");
  expect_invalid([&] { checked_state(PivotedPlanarBodyState{0.0, inf}, "x"); }, "x.omega");
  // a unit quaternion within 1e-6 is accepted and normalised
  s = PivotedBodyState{};
  s.q_WB = Eigen::Quaterniond(1.0 + 1e-9, 0.0, 0.0, 0.0);
  EXPECT_NEAR(checked_state(s).q_WB.norm(), 1.0, 2.0 * kEps);
}

// ---- kernels ----------------------------------------------------------------------------------------

TEST(PivotedBody, KinematicsVelocityIsTheDerivativeOfThePosition) {
  // along the rotation at constant ω_B (q(t) = q0 ⊗ exp(ω t)), p_W(t) = p_WO + R(t) c; the central difference
  // over ±δ differs from v by δ²/6 |p'''| ≤ δ²/6 |ω|³ |c| (plus 2 ε |p| / (2δ) of rounding)
  const PivotedBody body(full_body(), Eigen::Vector3d(0.2, -0.4, 0.3), Eigen::Vector3d(1.0, 2.0, -0.5));
  const PivotedBodyState s = some_state();
  const double delta = 1e-5;
  const auto at = [&](double t) {
    PivotedBodyState x = s;
    x.q_WB = s.q_WB * Eigen::Quaterniond(Eigen::AngleAxisd(s.w_B.norm() * t, s.w_B.normalized()));
    return kinematics_of(body, x);
  };
  const BodyKinematics k = kinematics_of(body, s);
  const Eigen::Vector3d fd = (at(delta).p_W - at(-delta).p_W) / (2.0 * delta);
  const double w = s.w_B.norm(), c = body.p_OC_B().norm();
  const double tolerance = delta * delta / 6.0 * w * w * w * c + 8.0 * kEps * k.p_W.norm() / delta;
  EXPECT_LE((fd - k.v_W).norm(), tolerance);
  EXPECT_LE((k.p_W - body.p_WO()).norm() - c, 4.0 * kEps * k.p_W.norm());  // |p − O| = |c|
}

TEST(PivotedBody, AngularMomentumAboutOIsTheRigidBodysAboutTheFixedPoint) {
  // H_O = R I_O ω equals H_C + (p_C − O) × m v_C (rigid_body_dynamics' angular_momentum about P = O):
  // both within a few ε of |I_O||ω|
  const PivotedBody body(full_body(), Eigen::Vector3d(0.2, -0.4, 0.3), Eigen::Vector3d(1.0, 2.0, -0.5));
  const PivotedBodyState s = some_state();
  const BodyKinematics k = kinematics_of(body, s);
  RigidBodyState r;
  r.p_W = k.p_W, r.q_WB = k.q_WB, r.v_W = k.v_W, r.w_B = k.w_B;
  const Eigen::Vector3d H_O = angular_momentum_O_W(body, s);
  const Eigen::Vector3d reference = angular_momentum(body.body(), r, body.p_WO());
  EXPECT_LE((H_O - reference).norm(), 32.0 * kEps * body.inertia_O().norm() * s.w_B.norm());
}

// ---- dynamics ---------------------------------------------------------------------------------------

TEST(PivotedBodyDynamics, ForwardOfInverseIsTheIdentity) {
  const PivotedBody body(full_body(), Eigen::Vector3d(0.1, 0.35, -0.2));
  const PivotedBodyState s = some_state();
  const Eigen::Vector3d alpha(0.4, -2.0, 1.3);
  const PivotedTorque needed = inverse_dynamics(body, s, alpha, kG);
  ComWrench couple;
  couple.tau_B = needed.tau_O_B;  // a couple: the same about C and about O
  const PivotedAcceleration back = forward_dynamics(body, s, couple, kG);
  // forward solves I_O α = τ_O − ω × I_O ω with the stored I_O⁻¹: the round trip loses κ(I_O) times the
  // rounding of the torques, a few ε of |I_O| (|α| + |ω|²) + m |c| |g|, relative to λ_min(I_O)
  const Eigen::Vector3d moments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(body.inertia_O()).eigenvalues();
  const double torque_scale = moments.maxCoeff() * (alpha.norm() + s.w_B.squaredNorm()) +
                              body.mass() * body.p_OC_B().norm() * kG.norm();
  EXPECT_LE((back.alpha_B - alpha).norm(), 32.0 * kEps * torque_scale / moments.minCoeff());
  // the reactions: m a_C − m g on both sides, a_C from α (equal within the bound above times m |c|)
  EXPECT_LE((back.reaction_W - needed.reaction_W).norm(),
            32.0 * kEps * body.mass() * (body.p_OC_B().norm() * (torque_scale / moments.minCoeff() + s.w_B.squaredNorm()) + kG.norm()));
}

TEST(PivotedBodyDynamics, AgreesWithNewtonEulerAboutTheCentreOfMassUnderTheReaction) {
  // An independent route: the free rigid body about C (rigid_body_dynamics, I_C) under gravity, the load
  // and the pivot's reaction R applied at O (at −c from C) moves exactly as the pinned body: a_W = a_C and
  // the same α_B. No parallel-axis theorem on this side.
  const PivotedBody body(full_body(), Eigen::Vector3d(0.1, 0.35, -0.2), Eigen::Vector3d(0.5, 0.5, 1.0));
  const PivotedBodyState s = some_state();
  ComWrench load;
  load.f_W = Eigen::Vector3d(3.0, -1.0, 2.0);
  load.tau_B = Eigen::Vector3d(0.2, 0.5, -0.3);
  const PivotedAcceleration a = forward_dynamics(body, s, load, kG);
  const BodyKinematics k = kinematics_of(body, s);
  RigidBodyState r;
  r.p_W = k.p_W, r.q_WB = k.q_WB, r.v_W = k.v_W, r.w_B = k.w_B;
  const ComWrench at_O = wrench_at_com(s.q_WB, a.reaction_W, Eigen::Vector3d::Zero(), -(s.q_WB * body.p_OC_B()), Frame::world);
  ComWrench total;
  total.f_W = load.f_W + at_O.f_W;
  total.tau_B = load.tau_B + at_O.tau_B;
  const BodyAcceleration free = forward_dynamics(body.body(), r, total, kG);
  // both routes round torques of size |I| (|α| + |ω|²) + |c| |R| and solve with κ(I) ≤ 2.2 here
  const double scale = body.inertia_O().norm() * (a.alpha_B.norm() + s.w_B.squaredNorm()) +
                       body.p_OC_B().norm() * (a.reaction_W.norm() + load.f_W.norm());
  EXPECT_LE((free.alpha_B - a.alpha_B).norm(), 64.0 * kEps * scale);
  EXPECT_LE((free.a_W - pivoted_com_acceleration_W(body.p_OC_B(), s.q_WB, s.w_B, a.alpha_B)).norm(),
            64.0 * kEps * (scale / body.mass() + kG.norm()));
}

TEST(PivotedBodyDynamics, PivotAtTheCentreHoldsTheWeight) {
  // c = 0: gravity has no moment about O, α is the free body's, and the pivot holds −m g exactly
  const PivotedBody body(full_body(), Eigen::Vector3d::Zero());
  const PivotedBodyState s = some_state();
  const PivotedAcceleration a = forward_dynamics(body, s, ComWrench{}, kG);
  EXPECT_EQ(a.reaction_W, -body.mass() * kG);
  RigidBodyState r;
  r.q_WB = s.q_WB, r.w_B = s.w_B;
  const BodyAcceleration free = forward_dynamics(body.body(), r, ComWrench{});
  EXPECT_LE((a.alpha_B - free.alpha_B).norm(), 16.0 * kEps * (free.alpha_B.norm() + s.w_B.squaredNorm()));
}

TEST(PivotedPlanarBodyDynamics, ForwardOfInverseAndTheSpatialBodyInThePlane) {
  const PivotedPlanarBody body(1.5, 0.2, Eigen::Vector2d(0.3, -0.1), Eigen::Vector2d(1.0, 2.0));
  const PivotedPlanarBodyState s{0.8, -1.7};
  const Eigen::Vector3d g(0.0, -9.81, 0.0);  // in the plane
  const PivotedPlanarTorque needed = inverse_dynamics(body, s, 2.5, g);
  ComWrench couple;
  couple.tau_B.z() = needed.tau_O;
  const PivotedPlanarAcceleration back = forward_dynamics(body, s, couple, g);
  // one division and two products of torques ≤ I_O |α| + m |c| |g|: a few ε relative
  const double torque_scale = body.inertia_O_zz() * 2.5 + body.mass() * body.p_OC_B().norm() * g.norm();
  EXPECT_NEAR(back.alpha, 2.5, 8.0 * kEps * torque_scale / body.inertia_O_zz());
  EXPECT_LE((back.reaction_W - needed.reaction_W).norm(), 16.0 * kEps * body.mass() * (torque_scale + g.norm()));
  // the same body in 3D (in-plane moments arbitrary, c in the xy plane, turning about z) has the same α and
  // in-plane reaction: plane kinetics is Euler's law about O restricted to z
  const PivotedBody spatial(RigidBody(1.5, Eigen::Vector3d(0.15, 0.18, 0.2)), Eigen::Vector3d(0.3, -0.1, 0.0),
                            Eigen::Vector3d(1.0, 2.0, 0.0));
  PivotedBodyState s3;
  s3.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(s.theta, Eigen::Vector3d::UnitZ()));
  s3.w_B = Eigen::Vector3d(0.0, 0.0, s.omega);
  ComWrench load;
  load.f_W = Eigen::Vector3d(0.7, 0.4, 0.0);
  load.tau_B = Eigen::Vector3d(0.0, 0.0, -0.3);
  const PivotedAcceleration a3 = forward_dynamics(spatial, s3, load, g);
  const PivotedPlanarAcceleration a2 = forward_dynamics(body, s, load, g);
  const double scale = (torque_scale + load.f_W.norm() + 1.0) / body.inertia_O_zz() + s.omega * s.omega;
  EXPECT_NEAR(a3.alpha_B.z(), a2.alpha, 32.0 * kEps * scale);
  EXPECT_LE(a3.alpha_B.head<2>().norm(), 32.0 * kEps * scale);
  EXPECT_LE((a3.reaction_W - a2.reaction_W).norm(), 32.0 * kEps * body.mass() * (scale + g.norm()));
  // kinematics in the plane: p_W = O + Rz(θ) c, v_W = ω ẑ × (p_W − O)
  const BodyKinematics k2 = kinematics_of(body, s), k3 = kinematics_of(spatial, s3);
  EXPECT_LE((k2.p_W - k3.p_W).norm(), 8.0 * kEps * k3.p_W.norm());
  EXPECT_LE((k2.v_W - k3.v_W).norm(), 8.0 * kEps * std::abs(s.omega) * body.p_OC_B().norm());
}

}  // namespace
