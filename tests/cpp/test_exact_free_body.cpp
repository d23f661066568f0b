// TorqueFreeSolution: Euler's equations and the quaternion kinematics hold along the solution
// (central differences), the invariants are conserved, the branches and published periods; the
// one-step FreeRotationFlow against it.
#include "test_inputs.hpp"
#include "test_numbers.hpp"
#include "rigiddyn/exact/free_body.hpp"

#include "error_bounds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace rigiddyn {
namespace {

using rigiddyn::test::kEps;

using test::initial_attitude;

Eigen::Matrix3d tilted(const Eigen::Vector3d& moments) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.3, -1, 0.2).normalized()).toRotationMatrix();
  return R * moments.asDiagonal() * R.transpose();
}

// max over sample times of the residuals of I ω̇ = (I ω) × ω and q̇ = q ⊗ (0, ω)/2 (central
// differences, h = 1e-4: truncation ~1e-9) and of the drift of L_W and energy
void expect_solves_the_free_body(const Eigen::Matrix3d& I, const Eigen::Vector3d& w0, const std::string& expected_case) {
  const TorqueFreeSolution s(I, initial_attitude(), w0, InertiaCheck::allow_unrealizable);
  EXPECT_EQ(to_string(s.solution_case()), expected_case);
  const double h = 1e-4, G = s.angular_momentum_W().norm();
  for (double t : {0.0, 0.3, 1.7, 5.2, 13.1, -40.3}) {
    const TorqueFreeState a = s.state_at(t - h), b = s.state_at(t + h), c = s.state_at(t);
    const Eigen::Vector3d w_dot = (b.w_B - a.w_B) / (2 * h);
    // central differences: truncation h^2/6 |d3w| (~1e-9 (1 + G^2)) plus the closed form's round-off
    // over 2h (16 eps kappa (1 + |w t|)/h <= 1e-10 at |t| <= 40): 1e-7 (1 + G^2) is far above both
    EXPECT_LT((I * w_dot - (I * c.w_B).cross(c.w_B)).norm(), 1e-7 * (1 + G * G)) << "t = " << t;
    const Eigen::Vector4d q_dot = (b.q_WB.coeffs() - a.q_WB.coeffs()) / (2 * h);
    const Eigen::Quaterniond w_quat(0.0, c.w_B.x(), c.w_B.y(), c.w_B.z());
    EXPECT_LT((q_dot - 0.5 * (c.q_WB * w_quat).coeffs()).norm(), 1e-7 * (1 + G)) << "t = " << t;
    // L_W = R m: the attitude errs by the closed form's bound at t (error_bounds.hpp), m by a few ulps
    EXPECT_LT((c.q_WB * (I * c.w_B) - s.angular_momentum_W()).norm(), test::closed_form_error(I, w0, t) * (1 + G))
        << "t = " << t;
    // on its orbit to a few ulps at any t (only the phase errs): E to ~8 eps, evaluation 4 eps more
    EXPECT_NEAR(0.5 * c.w_B.dot(I * c.w_B), s.kinetic_energy(), 32 * kEps * s.kinetic_energy());
  }
  const TorqueFreeState s0 = s.state_at(0.0);
  // t = 0: "a few ulps" (free_body.hpp)
  EXPECT_LT((s0.w_B - w0).norm(), 8 * kEps * w0.norm());
  EXPECT_LT(s0.q_WB.angularDistance(initial_attitude()), 8 * kEps);
}

TEST(TorqueFreeSolution, SolvesEulerAndKinematicsInEveryBranch) {
  const Eigen::Matrix3d D = Eigen::Vector3d(1, 2, 3).asDiagonal();
  expect_solves_the_free_body(D, {0.3, 0.5, 1.0}, "A");
  expect_solves_the_free_body(D, {-0.3, -0.5, -1.0}, "A");
  expect_solves_the_free_body(D, {1.0, 0.5, 0.3}, "B");
  expect_solves_the_free_body(D, {-1.0, 0.5, -0.3}, "B");
  expect_solves_the_free_body(D, {0.01, 2.0, 0.01}, "A");
  expect_solves_the_free_body(tilted({3, 1, 2}), {0.3, -0.5, 1.0}, "A");
  // Δ2 = 0 exactly: m1² (I2 − I1)/I1 = m3² (I3 − I2)/I3 with m = (6, 1.2, 6)
  expect_solves_the_free_body(Eigen::Vector3d(2, 3, 6).asDiagonal(), {3.0, 0.4, 1.0}, "separatrix");
  expect_solves_the_free_body(Eigen::Vector3d(2, 3, 6).asDiagonal(), {-3.0, -0.4, -1.0}, "separatrix");
  expect_solves_the_free_body(Eigen::Vector3d(1, 1, 3).asDiagonal(), {0.3, -0.5, 1.0}, "symmetric");
  expect_solves_the_free_body(tilted({1, 3, 3}), {0.3, -0.5, 1.0}, "symmetric");
  expect_solves_the_free_body(2.0 * Eigen::Matrix3d::Identity(), {0.3, -0.5, 1.0}, "sphere");
  expect_solves_the_free_body(D, {0.0, 2.0, 0.0}, "separatrix");  // steady spin about the intermediate axis
  expect_solves_the_free_body(D, {0.0, 0.0, 2.0}, "A");
  expect_solves_the_free_body(D, {2.0, 0.0, 0.0}, "B");
}

TEST(TorqueFreeSolution, PublishedPeriods) {
  // Hairer, Lubich, Wanner GNI IV.1: I = (2, 1, 2/3), m0 = (cos 1.1, 0, sin 1.1): case B, T = 10.7315
  const Eigen::Vector3d I(2.0, 1.0, 2.0 / 3.0);
  const TorqueFreeSolution hlw(I.asDiagonal(), Eigen::Quaterniond::Identity(),
                               Eigen::Vector3d(std::cos(1.1), 0.0, std::sin(1.1)).cwiseQuotient(I),
                               InertiaCheck::allow_unrealizable);
  EXPECT_EQ(hlw.solution_case(), TorqueFreeCase::B);
  EXPECT_NEAR(hlw.period(), 10.7315, 5e-5);  // published to 4 decimals
}

TEST(TorqueFreeSolution, RejectsBadInput) {
  const Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  EXPECT_THROW(TorqueFreeSolution(Eigen::Vector3d(1, -2, 3).asDiagonal(), q, Eigen::Vector3d(1, 2, 3)),
               std::invalid_argument);
  Eigen::Matrix3d asymmetric = Eigen::Vector3d(1, 2, 3).asDiagonal();
  asymmetric(0, 1) = 0.1;
  EXPECT_THROW(TorqueFreeSolution(asymmetric, q, Eigen::Vector3d(1, 2, 3)), std::invalid_argument);
  EXPECT_THROW(TorqueFreeSolution(Eigen::Matrix3d::Identity(), Eigen::Quaterniond(2, 0, 0, 0), Eigen::Vector3d(1, 2, 3)),
               std::invalid_argument);
  const TorqueFreeSolution s(Eigen::Vector3d(1, 2, 3).asDiagonal(), q, Eigen::Vector3d(1, 2, 3));
  EXPECT_THROW(s.state_at(std::nan("")), std::invalid_argument);
}

// Under the default InertiaCheck::physical, an inertia violating the triangle inequality I1 + I2 >= I3
// is refused with its moments named (as SpatialInertia and RigidBody do); the opt-in accepts it.
TEST(TorqueFreeSolution, RequiresARealizableInertiaByDefault) {
  const Eigen::Matrix3d hlw = Eigen::Vector3d(2.0, 1.0, 2.0 / 3.0).asDiagonal();
  try {
    TorqueFreeSolution(hlw, Eigen::Quaterniond::Identity(), Eigen::Vector3d(1, 2, 3));
    ADD_FAILURE() << "an unrealizable inertia was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("inertia: expected"), std::string::npos) << message;
    EXPECT_NE(message.find("triangle inequality"), std::string::npos) << message;
    EXPECT_NE(message.find("principal moments (0.66666666666666663, 1, 2)"), std::string::npos) << message;
    EXPECT_EQ(message.find("::"), std::string::npos) << message;  // read from Python too
  }
  EXPECT_NO_THROW(TorqueFreeSolution(hlw, Eigen::Quaterniond::Identity(), Eigen::Vector3d(1, 2, 3),
                                     InertiaCheck::allow_unrealizable));
  // the boundary I1 + I2 = I3 (a flat plate) is realizable
  EXPECT_NO_THROW(TorqueFreeSolution(Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal(), Eigen::Quaterniond::Identity(),
                                     Eigen::Vector3d(1, 2, 3)));
}

// Any finite magnitudes: I -> 2^j I is exact and leaves the motion unchanged, and the
// solution scales the inertia by a power of two itself, so both make the same operations: equal to the
// last bit in every branch, also where the momentum I w (2^±1000 times that of I) is not representable.
// Rates of the motion beyond the double range are refused naming w_B; invariants beyond it are inf.
TEST(TorqueFreeSolution, AnyInertiaScaleGivesTheSameMotion) {
  const Eigen::Vector3d moments(2.0, 3.0, 5.0);
  const Eigen::Vector3d velocities[] = {{0.3, -0.5, 1.1}, {1.0, 0.5, 0.3}, {1e-20, 0.0, 1.0}, {0.0, 1.0, 0.0}};
  const Eigen::Vector3d symmetric_moments[] = {{2.0, 3.0, 5.0}, {2.0, 2.0, 5.0}, {3.0, 3.0, 3.0}};
  for (const Eigen::Vector3d& I : symmetric_moments) {
    for (const Eigen::Vector3d& w0 : velocities) {
      const TorqueFreeSolution ref(I.asDiagonal(), initial_attitude(), w0, InertiaCheck::allow_unrealizable);
      for (int j : {-1000, -300, 300, 1000}) {
        const Eigen::Vector3d I_scaled(std::ldexp(I(0), j), std::ldexp(I(1), j), std::ldexp(I(2), j));
        const TorqueFreeSolution s(I_scaled.asDiagonal(), initial_attitude(), w0, InertiaCheck::allow_unrealizable);
        EXPECT_EQ(s.solution_case(), ref.solution_case());
        for (double t : {0.0, 0.7, -4.0, 13.0}) {
          const TorqueFreeState a = s.state_at(t), b = ref.state_at(t);
          EXPECT_EQ(a.q_WB.coeffs(), b.q_WB.coeffs()) << "j = " << j << ", t = " << t << ", w0 = " << w0.transpose();
          EXPECT_EQ(a.w_B, b.w_B) << "j = " << j << ", t = " << t;
        }
      }
    }
  }
  // L_W = 2^1000 (6e10) and T beyond the double range: inf, the motion unaffected
  const TorqueFreeSolution big(Eigen::Vector3d(std::ldexp(2.0, 1000), std::ldexp(3.0, 1000), std::ldexp(5.0, 1000)).asDiagonal(),
                               initial_attitude(), Eigen::Vector3d(0.3e10, -0.5e10, 1.1e10),
                               InertiaCheck::allow_unrealizable);
  EXPECT_FALSE(big.angular_momentum_W().allFinite());
  EXPECT_EQ(big.kinetic_energy(), std::numeric_limits<double>::infinity());
  // φ would turn at G/I1 ~ 3e600 rad/s
  EXPECT_THROW(TorqueFreeSolution(Eigen::Vector3d(1e-300, 2.0, 3.0).asDiagonal(), initial_attitude(), Eigen::Vector3d::Constant(1e300),
                                  InertiaCheck::allow_unrealizable),
               std::invalid_argument);
  // a phase beyond the double range
  const TorqueFreeSolution fast(moments.asDiagonal(), initial_attitude(), Eigen::Vector3d(0.3e300, -0.5e300, 1.1e300),
                                InertiaCheck::allow_unrealizable);
  EXPECT_TRUE(fast.state_at(1.0).q_WB.coeffs().allFinite());
  EXPECT_THROW(fast.state_at(1e10), std::invalid_argument);
}

// FreeRotationFlow::advance(h) is TorqueFreeSolution(...).state_at(h) to round-off in every branch,
// also for steps crossing half periods of ω and negative steps; and composing steps is the flow.
TEST(FreeRotationFlow, OneStepEqualsTheClosedForm) {
  const Eigen::Matrix3d D = Eigen::Vector3d(1, 2, 3).asDiagonal();
  struct Case {
    Eigen::Matrix3d I;
    Eigen::Vector3d w0;
  };
  const Case cases[] = {{D, {0.3, 0.5, 1.0}},   {D, {-1.0, 0.5, -0.3}},        {D, {0.01, 2.0, 0.01}},
                        {D, {0.02, 2.0, 0.01}}, {tilted({3, 1, 2}), {0.3, -0.5, 1.0}},
                        {Eigen::Vector3d(2, 3, 6).asDiagonal(), {3.0, 0.4, 1.0}},
                        {Eigen::Vector3d(1, 1, 3).asDiagonal(), {0.3, -0.5, 1.0}},
                        {2.0 * Eigen::Matrix3d::Identity(), {0.3, -0.5, 1.0}}, {D, {0.0, 0.0, 2.0}}};
  for (const Case& c : cases) {
    const FreeRotationFlow flow(c.I);
    for (double h : {0.01, 0.7, 5.0, -0.3, 40.0}) {
      const TorqueFreeState exact = TorqueFreeSolution(c.I, initial_attitude(), c.w0,
                                                       InertiaCheck::allow_unrealizable).state_at(h);
      Eigen::Quaterniond q = initial_attitude();
      Eigen::Vector3d w = c.w0;
      flow.advance(q, w, h);
      // the same closed form on the same doubles (the flow caches the principal frame and the
      // parameters it computes the same way): a few ulps apart, not the phase error of either
      EXPECT_LT((w - exact.w_B).norm(), 1e-14 * (1 + c.w0.norm())) << c.w0.transpose() << " h = " << h;
      EXPECT_LT(q.angularDistance(exact.q_WB), 1e-14) << c.w0.transpose() << " h = " << h;
    }
    // 1000 steps of 0.05 s against the closed form at 50 s (round-off grows ~ eps per step), away
    // from the separatrix, where round-off grows exponentially (the flow itself is ill-conditioned)
    const double mc = TorqueFreeSolution(c.I, initial_attitude(), c.w0,
                                         InertiaCheck::allow_unrealizable).parameter_mc();
    if (mc < 0.1 && mc != 1.0) continue;
    Eigen::Quaterniond q = initial_attitude();
    Eigen::Vector3d w = c.w0;
    for (int i = 0; i < 1000; ++i) flow.advance(q, w, 0.05);
    const TorqueFreeState exact = TorqueFreeSolution(c.I, initial_attitude(), c.w0,
                                                     InertiaCheck::allow_unrealizable).state_at(50.0);
    // each step rounds by exact_step_roundoff, carried to 50 s by the flow's Jacobian, plus the
    // closed form's own error at 50 s (error_bounds.hpp)
    const double bound = test::torque_free_amplification_sum(c.I, initial_attitude(), c.w0, 50.0, 1000) *
                             test::exact_step_roundoff(c.I) +
                         test::closed_form_error(c.I, c.w0, 50.0);
    EXPECT_LT((w - exact.w_B).norm(), bound * test::to_euclidean(c.I, c.w0)) << c.w0.transpose();
    EXPECT_LT(q.angularDistance(exact.q_WB), bound * test::to_euclidean(c.I, c.w0)) << c.w0.transpose();
  }
}

TEST(FreeRotationFlow, ShortStepsByTheAdditionTheoremsEqualTheClosedForm) {
  // Ordinary motions (moments 1..10 in random principal frames, ω of either case away from the axes and the
  // separatrix) over steps with |λ h| ≤ π/4: the flow's short-step path (the Jacobi functions and Π advanced by
  // their addition theorems from the momentum) against the closed form evaluated at h. Both are a handful of
  // roundings of quantities of the motion's scale: ω within 16 eps of the largest rate |I ω|/I_min, the attitude
  // within 16 eps (1 + the angle turned), each form's few ulps with a factor of 2.
  std::mt19937_64 rng(20261205);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int checked = 0;
  for (int i = 0; i < 400; ++i) {
    const Eigen::Vector3d moments(1.0 + 9.0 * uniform(rng), 1.0 + 9.0 * uniform(rng), 1.0 + 9.0 * uniform(rng));
    const Eigen::Quaterniond frame = Eigen::Quaterniond(Eigen::Vector4d::Random()).normalized();
    const Eigen::Matrix3d I = frame.toRotationMatrix() * moments.asDiagonal() * frame.toRotationMatrix().transpose();
    const Eigen::Vector3d w0 = Eigen::Vector3d(2.0 * uniform(rng) - 1.0, 2.0 * uniform(rng) - 1.0, 2.0 * uniform(rng) - 1.0);
    const double h = (uniform(rng) - 0.3) * 0.5 / w0.norm();  // |λ h| of the order of |h ω| ≤ 0.35
    const TorqueFreeSolution solution(I, initial_attitude(), w0, InertiaCheck::allow_unrealizable);
    if (solution.parameter_mc() < 0.01 || solution.parameter_m() < 1e-6) continue;  // the full path's cases
    const TorqueFreeState exact = solution.state_at(h);
    Eigen::Quaterniond q = initial_attitude();
    Eigen::Vector3d w = w0;
    FreeRotationFlow(I).advance(q, w, h);
    const double largest_rate = test::max_rate(I, w0), angle = largest_rate * std::abs(h);
    EXPECT_LT((w - exact.w_B).norm(), 16.0 * kEps * largest_rate) << w0.transpose() << " h = " << h;
    EXPECT_LT(q.angularDistance(exact.q_WB), 16.0 * kEps * (1.0 + angle)) << w0.transpose() << " h = " << h;
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

TEST(FreeRotationFlow, NonFiniteStateBecomesNaN) {
  const FreeRotationFlow flow(Eigen::Vector3d(1, 2, 3).asDiagonal());
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  Eigen::Vector3d w(std::nan(""), 1.0, 0.0);
  flow.advance(q, w, 0.1);
  EXPECT_TRUE(std::isnan(w.x()) && std::isnan(q.w()));
  EXPECT_THROW(FreeRotationFlow(Eigen::Vector3d(1, -2, 3).asDiagonal()), std::invalid_argument);
}

}  // namespace
}  // namespace rigiddyn
