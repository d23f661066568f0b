// The method registry's documented behaviour at the extremes, from C++: the stability_limit and
// exact_torque_free metadata, implicit midpoint's Newton iteration converging (energy and |L| kept
// to the solver tolerance) for a moment ratio of 1e6 and the flat plate I3 = I1 + I2, the splitting
// methods keeping |L| exactly even far beyond their stability limit, and the exact methods staying
// at round-off on a torque-free body at any step.
#include <gtest/gtest.h>

#include "error_bounds.hpp"
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigiddyn {
namespace {

SimulationOptions torque_free(Method method, double dt, std::int64_t steps) {
  SimulationOptions o;
  o.method = method;
  o.dt = dt;
  o.steps = steps;
  o.record_every = 1;
  return o;
}

RigidBodyState spinning(const Eigen::Vector3d& w_B) {
  RigidBodyState s;
  s.w_B = w_B;
  return s;
}

// max over the records of |x_k / x_0 - 1|
double max_relative_drift(const std::vector<double>& x) {
  double d = 0.0;
  for (double v : x) d = std::max(d, std::abs(v / x.front() - 1.0));
  return d;
}

TEST(MethodTable, StabilityLimitsAndExactness) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(method_info(Method::explicit_euler).stability_limit, 0.0);
  EXPECT_DOUBLE_EQ(method_info(Method::rk4).stability_limit, 2.0 * std::sqrt(2.0));  // |R(iy)| = 1 at y = 2 sqrt 2
  EXPECT_EQ(method_info(Method::exact).stability_limit, inf);
  EXPECT_EQ(method_info(Method::exact_flow_kick).stability_limit, inf);
  EXPECT_EQ(method_info(Method::semi_implicit_euler_implicit_gyroscopic).stability_limit, inf);
  for (const MethodInfo& info : method_table()) {
    EXPECT_GE(info.stability_limit, 0.0) << info.name;
    // exactly the methods built on the closed-form torque-free flow are exact on a torque-free body
    EXPECT_EQ(info.exact_torque_free, info.method == Method::exact || info.method == Method::exact_flow_kick)
        << info.name;
    EXPECT_EQ(info.order == 0, info.method == Method::exact) << info.name;  // order 0: no truncation error
  }
}

// implicit midpoint conserves the quadratic invariants of Euler's equations whenever its Newton
// iteration converges: energy and |L| to ~1e-14 on the extreme bodies of tests/python/test_extremes.py.
TEST(ImplicitMidpoint, NewtonConvergesForExtremeMomentRatiosAndTheFlatPlate) {
  struct Case {
    Eigen::Vector3d moments, w_B;
    double dt;
  };
  const Case cases[] = {
      {{1e-6, 1.0, 1.0}, {10.0, 1.0, 0.5}, 1e-3},                      // moment ratio 1e6
      {{1.0 / 12, 1.0 / 3, 5.0 / 12}, {0.5, 1.0, 2.0}, 1e-2},         // flat plate I3 = I1 + I2
      {{1.0 / 12, 1.0 / 3, 5.0 / 12}, {0.5, 1.0, 2.0}, 1.0},          // same at dt |w| = 2.3 (< limit 3)
  };
  for (const Case& c : cases) {
    const RigidBody body(1.0, c.moments.asDiagonal());
    const Trajectory r = simulate(body, spinning(c.w_B), torque_free(Method::implicit_midpoint, c.dt, 500));
    ASSERT_FALSE(r.diverged);
    // quadratic invariants, kept exactly by the midpoint rule; Newton converges quadratically, so
    // the 1e-14 stop leaves ~1e-28: round-off only, a random walk of <= 4 eps per step: 5 sigma =
    // 20 eps sqrt(500) = 1e-13
    EXPECT_LT(max_relative_drift(r.kinetic_energy), 1e-13) << c.moments.transpose() << " dt " << c.dt;
    EXPECT_LT(max_relative_drift(r.angular_momentum_norm), 1e-13) << c.moments.transpose() << " dt " << c.dt;
  }
}

// The DLM sub-flows are exact rotations, so |L| is kept to round-off at ANY step, even at dt |w| = 10
// (ten times the documented stability limit, where the energy error is O(1)).
TEST(Splitting, KeepsAngularMomentumExactlyBeyondItsStabilityLimit) {
  const RigidBody body(1.0, Eigen::Vector3d(2.0, 6.5, 8.0).asDiagonal());
  for (Method method : {Method::splitting_dlm, Method::splitting_dlm_yoshida4}) {
    ASSERT_LE(10.0 * method_info(method).stability_limit, 10.0);
    const Trajectory r = simulate(body, spinning({0.1, 10.0, 0.0}), torque_free(method, 1.0, 1000));  // dt |w| = 10
    ASSERT_FALSE(r.diverged);
    // exact rotations of m: round-off only, a random walk of <= 2 eps per sub-flow step (1 for DLM,
    // 3 for Yoshida's triple jump): 5 sigma = 10 eps sqrt(N)
    const double substeps = method == Method::splitting_dlm ? 1000.0 : 3000.0;
    EXPECT_LT(max_relative_drift(r.angular_momentum_norm), 10 * test::kRoundoff * std::sqrt(substeps))
        << method_info(method).name;
  }
}

// exact and exact_flow_kick: the error on a torque-free body is round-off at any dt (no observed order).
TEST(ExactMethods, RoundOffAtAnyStepOnATorqueFreeBody) {
  const RigidBody body(1.0, Eigen::Vector3d(2.0, 6.5, 8.0).asDiagonal());
  const RigidBodyState start = spinning({0.1, 10.0, 0.0});
  const Trajectory truth = simulate(body, start, torque_free(Method::exact, 1.0, 1));
  for (Method method : {Method::exact, Method::exact_flow_kick}) {
    for (std::int64_t steps : {1, 10, 1000}) {
      const Trajectory r = simulate(body, start, torque_free(method, 1.0 / steps, steps));
      const std::size_t n = r.size() - 1;
      // each step rounds by exact_step_roundoff, carried to t = 1 s by the flow's Jacobian (a spin
      // near the unstable axis: it grows like e^{λ t}), plus the closed form's own error at 1 s
      const Eigen::Matrix3d I = Eigen::Vector3d(2.0, 6.5, 8.0).asDiagonal();
      const double bound = (test::torque_free_amplification_sum(I, start.q_WB, start.w_B, 1.0, static_cast<int>(steps)) *
                                test::exact_step_roundoff(I) +
                            2 * test::closed_form_error(I, start.w_B, 1.0)) *
                           std::max(1.0, test::max_rate(I, start.w_B));
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(r.w_B[3 * n + i], truth.w_B[3 + i], bound) << method_info(method).name << " steps " << steps;
      }
    }
  }
}

}  // namespace
}  // namespace rigiddyn
