// |L| of the Lie–Poisson splittings (splitting_dlm, splitting_dlm_yoshida4) over 1e7 steps: its
// round-off must be a random walk, |Δ|L||/|L| ≤ 10 ε √N after N steps, not the linear drift of a
// biased rounding (+2.5e-12 after 1e6 steps, ~11 000 ε, before the fix). Registered with the
// label `bench` (10⁷ steps of each method take seconds).
//
// Bound: every sub-flow turns m exactly in exact arithmetic, and the step adds to ω only the increment
// Δm/I accumulated apart from m (principal_axis_flow, dlm_principal_increment): |I ω| then changes by
// the rounding of ω + Δω (≤ ε/2 relative per component and sub-step, its sign set by low-order bits
// that the flow scrambles: unbiased) plus second-order terms: a walk of standard deviation ≤ ε √N
// (|L|: about √3 roundings of ≤ ε/2 per sub-step, less once weighted by the component's share of |L|;
// measured over 16 starts after 1e6 steps: 0.1–0.25 ε √N for |L|, ≤ 1.1 ε √N for L_W). 10 ε √N,
// the bound, is ≥ 9 such deviations, while a bias of 0.01 ε per step (the code before the fix
// had 0.01–0.24) crosses it before 1e6 steps. The spatial L_W = R I ω has the same bound (the
// attitude turns and is normalised by increments as well: unit_quaternion, splitting_parts.hpp). The
// energy error stays the method's bounded oscillation (symplectic): no larger over the last tenth of
// the run than over the first (each 1e6 steps, thousands of nutation periods).
#include <gtest/gtest.h>

#include "rigiddyn/simulate/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rigiddyn {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr std::int64_t kSteps = 10'000'000, kRecordEvery = 10'000;

struct Body {
  const char* name;
  Eigen::Matrix3d inertia;
  Eigen::Vector3d w0_B;
};

// a spin about the major axis, and a tumble; each with I = diag(1, 2, 3) and turned off the
// body axes (full Euler form: the passage B → P → B at every step)
std::vector<Body> bodies() {
  const Eigen::Matrix3d I = Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal();
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  Eigen::Matrix3d turned = R * I * R.transpose();
  turned = 0.5 * (turned + turned.transpose()).eval();
  return {{"spin, principal", I, {0.1, 0.1, 50.0}},
          {"tumble, principal", I, {3.0, 1.0, 2.0}},
          {"spin, full", turned, R * Eigen::Vector3d(0.1, 0.1, 50.0)}};
}

class CasimirLongRun : public ::testing::TestWithParam<Method> {};

TEST_P(CasimirLongRun, AngularMomentumWalksAsRoundOffOverTenMillionSteps) {
  for (const Body& b : bodies()) {
    SimulationOptions o;
    o.method = GetParam();
    o.dt = 1e-3;
    o.steps = kSteps;
    o.record_every = kRecordEvery;
    const Trajectory r = simulate(RigidBody(1.0, b.inertia), RigidBodyState{{0.0, 0.0, 0.0}, Eigen::Quaterniond::Identity(), {0.0, 0.0, 0.0}, b.w0_B}, o);
    ASSERT_FALSE(r.diverged) << b.name;
    const Eigen::Vector3d L0_W = b.inertia * b.w0_B;  // q = identity at t = 0
    const double G0 = L0_W.norm();
    double dE_first = 0.0, dE_last = 0.0, worst = 0.0;  // worst: max(|ΔL|/|L|, |ΔL_W|/|L|) / (ε √n)
    for (std::size_t i = 1; i < r.size(); ++i) {
      const double n = static_cast<double>(i) * kRecordEvery, bound = 10.0 * eps * std::sqrt(n);
      const Eigen::Vector3d w(r.w_B[3 * i], r.w_B[3 * i + 1], r.w_B[3 * i + 2]);
      const Eigen::Quaterniond q(r.q_WB[4 * i + 3], r.q_WB[4 * i], r.q_WB[4 * i + 1], r.q_WB[4 * i + 2]);
      const double dL = std::abs(r.angular_momentum_norm[i] / G0 - 1.0);
      const double dL_W = (q.normalized() * (b.inertia * w) - L0_W).norm() / G0;
      worst = std::max(worst, std::max(dL, dL_W) / (eps * std::sqrt(n)));
      ASSERT_LE(dL, bound) << b.name << ": |L| after " << n << " steps";
      ASSERT_LE(dL_W, bound) << b.name << ": L_W after " << n << " steps";
      const double dE = std::abs(r.kinetic_energy[i] / r.kinetic_energy[0] - 1.0);
      if (i <= r.size() / 10) dE_first = std::max(dE_first, dE);
      if (i >= r.size() - r.size() / 10) dE_last = std::max(dE_last, dE);
    }
    // records every 1e4 steps sample the quasi-periodic energy error at varying phases, so the largest
    // sample of a window varies by a fraction of the amplitude; a drift from 0 would make the last
    // tenth's ~10× the first's
    std::printf("%s, %s: after %lld steps |L| error %.2g, at most %.2f eps sqrt(N) over the run (bound 10); "
                "energy error %.2g (first tenth) / %.2g (last tenth)\n",
                method_info(GetParam()).name.c_str(), b.name, static_cast<long long>(kSteps),
                r.angular_momentum_norm.back() / G0 - 1.0, worst, dE_first, dE_last);
    EXPECT_LE(dE_last, 1.5 * dE_first + 10.0 * eps * std::sqrt(static_cast<double>(kSteps))) << b.name << ": energy error drifts";
  }
}

INSTANTIATE_TEST_SUITE_P(Splittings, CasimirLongRun, ::testing::Values(Method::splitting_dlm, Method::splitting_dlm_yoshida4),
                         [](const ::testing::TestParamInfo<Method>& info) { return method_info(info.param).name; });

}  // namespace
}  // namespace rigiddyn
