// Structure-preserving integrators (implicit_midpoint, splitting_dlm, splitting_dlm_yoshida4,
// exact_flow_kick, exact): observed order against the exact torque-free solution on both sides of
// the intermediate-axis separatrix, order under couples against a fine RK4 reference, work-energy, and
// the "exact" method of simulate. Their invariants over 1e6 steps: integrators/test_invariants_long_run.cpp.
#include <gtest/gtest.h>

#include "error_bounds.hpp"
#include "rigiddyn/exact/free_body.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <cmath>
#include <vector>

namespace rigiddyn {
namespace {

const Eigen::Matrix3d kDiagonal = Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal();
// the same moments turned off the body axes (full Euler form)
Eigen::Matrix3d turned_inertia() {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  return R * kDiagonal * R.transpose();
}
const Eigen::Quaterniond kQ0(Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.3, 0.9, -0.2).normalized()));

// case A (Δ2 > 0: about the largest axis), case B (Δ2 < 0: about the smallest), both near the separatrix
const Eigen::Vector3d kCaseA(0.01, 2.0, 0.01), kCaseB(0.02, 2.0, 0.01), kGeneric(0.3, 0.5, 1.0);

const std::vector<Method> kNewMethods = {Method::implicit_midpoint, Method::splitting_dlm,
                                         Method::splitting_dlm_yoshida4, Method::exact_flow_kick};

double attitude_angle(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return a.angularDistance(b);
}

// final error max(|Δω|, attitude angle) of `method` over [0, T] with n steps, against the closed form
double free_body_error(Method method, const Eigen::Matrix3d& I, const Eigen::Vector3d& w0, double T, int n) {
  const RigidBody body(1.0, I);
  SimulationOptions o;
  o.method = method;
  o.dt = T / n;
  o.steps = n;
  o.record_every = n;
  const Trajectory tr = simulate(body, RigidBodyState{Eigen::Vector3d::Zero(), kQ0, Eigen::Vector3d::Zero(), w0}, o);
  const TorqueFreeState exact = TorqueFreeSolution(I, kQ0, w0).state_at(T);
  const Eigen::Quaterniond q(tr.q_WB[7], tr.q_WB[4], tr.q_WB[5], tr.q_WB[6]);
  const Eigen::Vector3d w(tr.w_B[3], tr.w_B[4], tr.w_B[5]);
  return std::max((w - exact.w_B).norm(), attitude_angle(q, exact.q_WB));
}

double slope(const std::vector<int>& steps, const std::vector<double>& errors) {
  // least-squares slope of log(error) against log(h) ∝ −log(n)
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double k = static_cast<double>(steps.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const double x = -std::log(static_cast<double>(steps[i])), y = std::log(errors[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (k * sxy - sx * sy) / (k * sxx - sx * sx);
}

int order_of(Method m) { return method_info(m).order; }

std::vector<int> step_counts(Method m) {
  return order_of(m) == 4 ? std::vector<int>{100, 200, 400, 800} : std::vector<int>{400, 800, 1600, 3200};
}

struct OrderCase {
  const char* name;
  Eigen::Matrix3d inertia;
  Eigen::Vector3d w0;
};

TEST(Geometric, ObservedOrderAgainstExactSolution) {
  const std::vector<OrderCase> cases = {{"generic diagonal", kDiagonal, kGeneric},
                                        {"generic full inertia", turned_inertia(), kGeneric},
                                        {"case A near separatrix", kDiagonal, kCaseA},
                                        {"case B near separatrix", kDiagonal, kCaseB}};
  for (const OrderCase& c : cases) {
    for (Method m : {Method::implicit_midpoint, Method::splitting_dlm, Method::splitting_dlm_yoshida4}) {
      std::vector<double> errors;
      for (int n : step_counts(m)) errors.push_back(free_body_error(m, c.inertia, c.w0, 8.0, n));
      // the next term of the error expansion is O(h |ω|) <= 0.04 relative at these steps: the slope
      // moves by far less than 0.2; the errors (>= 1e-9) are far above round-off
      EXPECT_NEAR(slope(step_counts(m), errors), order_of(m), 0.2) << method_info(m).name << ", " << c.name;
    }
    // without couples the exact flow + kick splitting is exact: round-off only, each of the 400 steps
    // rounding by exact_step_roundoff, carried to T by the flow's Jacobian (near the separatrix it
    // grows like e^{λ t}: error_bounds.hpp), plus the closed form's own error at T
    const double bound = test::torque_free_amplification_sum(c.inertia, kQ0, c.w0, 8.0, 400) *
                             test::exact_step_roundoff(c.inertia) +
                         test::closed_form_error(c.inertia, c.w0, 8.0);
    EXPECT_LT(free_body_error(Method::exact_flow_kick, c.inertia, c.w0, 8.0, 400),
              bound * test::to_euclidean(c.inertia, c.w0))
        << c.name;
  }
}

// A body under couples and forces of every kind: order against RK4 at a 64× finer step.
TEST(Geometric, ObservedOrderUnderLoads) {
  const RigidBody body(2.5, turned_inertia());
  const RigidBodyState s0{Eigen::Vector3d(0.1, -0.2, 0.3), kQ0, Eigen::Vector3d(0.5, 0.2, -0.1),
                          Eigen::Vector3d(1.2, -0.7, 2.0)};
  SimulationOptions o;
  o.loads = {AppliedLoad{Eigen::Vector3d(0.4, -0.2, 1.0), Eigen::Vector3d(0.05, 0.1, -0.2), Frame::world},
             AppliedLoad{Eigen::Vector3d(0.3, 0.1, -0.2), Eigen::Vector3d(-0.1, 0.2, 0.15), Frame::body}};
  o.gravity_W = standard_gravity();
  const double T = 2.0;
  const auto final_state = [&](Method m, int n) {
    SimulationOptions on = o;
    on.method = m, on.dt = T / n, on.steps = n, on.record_every = n;
    return simulate(body, s0, on);
  };
  const Trajectory ref = final_state(Method::rk4, 64 * 3200);
  for (Method m : kNewMethods) {
    std::vector<double> errors;
    for (int n : step_counts(m)) {
      const Trajectory tr = final_state(m, n);
      double e = 0.0;
      for (std::size_t k = 0; k < 3; ++k) {
        e = std::max({e, std::abs(tr.p_W[3 + k] - ref.p_W[3 + k]), std::abs(tr.v_W[3 + k] - ref.v_W[3 + k]),
                      std::abs(tr.w_B[3 + k] - ref.w_B[3 + k])});
      }
      const Eigen::Quaterniond q(tr.q_WB[7], tr.q_WB[4], tr.q_WB[5], tr.q_WB[6]);
      const Eigen::Quaterniond q_ref(ref.q_WB[7], ref.q_WB[4], ref.q_WB[5], ref.q_WB[6]);
      errors.push_back(std::max(e, attitude_angle(q, q_ref)));
    }
    // the RK4 reference at h/64 errs by (1/64)^4 of an RK4 run at h: far below these errors; the
    // next term of the expansion moves the slope by O(h |ω|) <= 0.02
    EXPECT_NEAR(slope(step_counts(m), errors), order_of(m), 0.2) << method_info(m).name;
  }
}

// Under couples the kicks do exactly the work the kinetic energy gains (the free flow conserves it).
TEST(Geometric, WorkEnergyOfTheExactFlowKick) {
  const RigidBody body(2.5, turned_inertia());
  SimulationOptions o;
  o.method = Method::exact_flow_kick;
  o.dt = 0.01;
  o.steps = 300;
  o.loads = {AppliedLoad{Eigen::Vector3d(0.4, -0.2, 1.0), Eigen::Vector3d(0.05, 0.1, -0.2), Frame::world},
             AppliedLoad{Eigen::Vector3d(0.3, 0.1, -0.2), Eigen::Vector3d(-0.1, 0.2, 0.15), Frame::body}};
  const Trajectory tr = simulate(body, RigidBodyState{Eigen::Vector3d::Zero(), kQ0, Eigen::Vector3d(0.5, 0.2, -0.1), kGeneric}, o);
  // the kicks book exactly the kinetic-energy change they make (the free flow keeps T): round-off,
  // 2 roundings of numbers <= max T (~3 J) per step, 300 steps: 4e-13
  for (std::size_t i = 0; i < tr.size(); ++i) {
    EXPECT_NEAR(tr.kinetic_energy[i] - tr.kinetic_energy[0], tr.work[i], 1e-12) << i;
  }
}

// Exact ballistic translation: a constant world force and gravity are integrated exactly.
TEST(Geometric, TranslationIsExactUnderConstantForce) {
  const RigidBody body(2.0, kDiagonal);
  const RigidBodyState s0{Eigen::Vector3d(1.0, 2.0, 3.0), kQ0, Eigen::Vector3d(0.3, -0.2, 4.0), kGeneric};
  const Eigen::Vector3d f(0.5, -1.0, 2.0);
  for (Method m : {Method::implicit_midpoint, Method::splitting_dlm, Method::splitting_dlm_yoshida4,
                   Method::exact_flow_kick, Method::exact}) {
    SimulationOptions o;
    o.method = m, o.dt = 0.1, o.steps = 20, o.record_every = 20;
    o.loads = {AppliedLoad{f, Eigen::Vector3d::Zero(), Frame::world}};
    o.gravity_W = standard_gravity();
    const Trajectory tr = simulate(body, s0, o);
    const double t = 2.0;
    const Eigen::Vector3d a = f / 2.0 + standard_gravity();
    const Eigen::Vector3d p = s0.p_W + t * s0.v_W + 0.5 * t * t * a, v = s0.v_W + t * a;
    // exact in exact arithmetic: round-off, <= 4 roundings per step of numbers <= 16 (|p|, |v|), 20 steps
    const double roundoff = 4 * 20 * test::kRoundoff * 16.0;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(tr.p_W[3 + k], p(k), roundoff) << method_info(m).name;
      EXPECT_NEAR(tr.v_W[3 + k], v(k), roundoff) << method_info(m).name;
    }
  }
}

TEST(Geometric, ExactMethodRecordsTheClosedForm) {
  const RigidBody body(1.0, turned_inertia());
  SimulationOptions o;
  o.method = Method::exact, o.dt = 0.7, o.steps = 100000, o.record_every = 25000;
  const Trajectory tr = simulate(body, RigidBodyState{Eigen::Vector3d::Zero(), kQ0, Eigen::Vector3d::Zero(), kCaseB}, o);
  const TorqueFreeSolution solution(turned_inertia(), kQ0, kCaseB);
  ASSERT_EQ(tr.size(), 5u);
  for (std::size_t i = 0; i < tr.size(); ++i) {
    const TorqueFreeState s = solution.state_at(tr.t[i]);
    const Eigen::Quaterniond q(tr.q_WB[4 * i + 3], tr.q_WB[4 * i], tr.q_WB[4 * i + 1], tr.q_WB[4 * i + 2]);
    EXPECT_EQ(attitude_angle(q, s.q_WB), 0.0);  // the same code (state_at) on the same doubles
    // on the orbit to a few ulps at any t (only the phase errs): T ~ 2 J, 4 eps of it
    EXPECT_NEAR(tr.kinetic_energy[i], solution.kinetic_energy(), 1e-14);
  }
  // and one step of "exact" is the exact flow over dt
  o.dt = 0.05;
  const RigidBodyState one = step(body, RigidBodyState{Eigen::Vector3d::Zero(), kQ0, Eigen::Vector3d::Zero(), kCaseB}, o);
  // the one-step flow and the closed form: a few ulps of |ω| each (test_exact_free_body.cpp's bound)
  EXPECT_LT((one.w_B - solution.state_at(0.05).w_B).norm(), 1e-14 * (1 + kCaseB.norm()));
}

TEST(Geometric, ExactMethodRejectsCouplesAndBodyForces) {
  const RigidBody body(1.0, kDiagonal);
  SimulationOptions o;
  o.method = Method::exact, o.dt = 0.01, o.steps = 10;
  o.loads = {AppliedLoad{Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 1.0), Frame::world}};
  EXPECT_THROW(simulate(body, RigidBodyState{}, o), std::invalid_argument);
  EXPECT_THROW(step(body, RigidBodyState{}, o), std::invalid_argument);
  o.loads = {AppliedLoad{Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d::Zero(), Frame::body}};
  EXPECT_THROW(simulate(body, RigidBodyState{}, o), std::invalid_argument);
}

TEST(Geometric, SphereKeepsItsAngularVelocity) {
  const RigidBody body(1.0, 0.4 * Eigen::Matrix3d::Identity());
  for (Method m : kNewMethods) {
    SimulationOptions o;
    o.method = m, o.dt = 0.01, o.steps = 100, o.record_every = 100;
    const Trajectory tr = simulate(body, RigidBodyState{Eigen::Vector3d::Zero(), kQ0, Eigen::Vector3d::Zero(), kGeneric}, o);
    // no gyroscopic term, no torque: every method adds exactly zero to ω
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(tr.w_B[3 + k], kGeneric(k), 1e-15) << method_info(m).name;
  }
}

// implicit_midpoint reports the steps whose Newton iteration hit its cap: none at dt|ω| = 0.2, some
// at dt|ω| = 8 near the separatrix (documented failure region from dt|ω| ≈ 3.5); explicit methods 0.
TEST(Geometric, ImplicitMidpointCountsUnconvergedSteps) {
  const RigidBody body(1.0, kDiagonal);
  SimulationOptions o;
  o.method = Method::implicit_midpoint, o.steps = 200, o.record_every = 200;
  o.dt = 0.1;  // |ω| = 2
  const RigidBodyState s0{Eigen::Vector3d::Zero(), kQ0, Eigen::Vector3d::Zero(), kCaseA};
  EXPECT_EQ(simulate(body, s0, o).unconverged_steps, 0);
  o.dt = 4.0;
  const Trajectory coarse = simulate(body, s0, o);
  EXPECT_GT(coarse.unconverged_steps, 0);
  EXPECT_LE(coarse.unconverged_steps, o.steps);
  o.method = Method::rk4;
  EXPECT_EQ(simulate(body, s0, o).unconverged_steps, 0);
}

}  // namespace
}  // namespace rigiddyn
