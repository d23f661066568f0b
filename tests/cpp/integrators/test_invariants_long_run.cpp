// The invariants of the structure-preserving integrators over 1e6 steps (implicit_midpoint, splitting_dlm,
// splitting_dlm_yoshida4; exact_flow_kick over 1e5): |L| and energy without secular drift on a body tumbling
// near its intermediate axis. Built optimised only (the test preset): the run takes minutes under the
// sanitizers, which check the same code in test_geometric.cpp's shorter runs.
#include <gtest/gtest.h>

#include "../error_bounds.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

const Eigen::Matrix3d kDiagonal = Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal();
const Eigen::Quaterniond kQ0(Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.3, 0.9, -0.2).normalized()));
const Eigen::Vector3d kCaseA(0.01, 2.0, 0.01);  // about the largest axis, near the separatrix (Δ2 > 0)

// max over records of |x_i − x_0| / |x_0| in records [first, last)
double max_relative_change(const std::vector<double>& x, std::size_t first, std::size_t last) {
  double out = 0.0;
  for (std::size_t i = first; i < last; ++i) out = std::max(out, std::abs(x[i] - x[0]) / std::abs(x[0]));
  return out;
}

struct Conservation {
  Method method;
  std::int64_t steps;
  double energy;  // promised bound on max |ΔE|/E
  double momentum;  // promised bound on max |Δ|L||/|L|
  bool truncation;  // energy error dominated by the method's truncation error (checked for drift)
};

// Tumbling near the intermediate axis, h |ω| = 0.02: 1e6 steps (2e5 s, ~1000 flips). The energy
// error of the splittings is bounded (no drift: the last half's maximum is not above the first
// half's by more than a round-off walk), the midpoint's and the exact flow's are at round-off.
TEST(Geometric, InvariantsOverAMillionStepsWithoutDrift) {
  const RigidBody body(1.0, kDiagonal);
  // Bounds: |L| (all four) and the midpoint's energy are kept exactly in exact arithmetic: round-off
  // only, a random walk of <= 2 eps per (sub)step stays within 5 sigma = 10 eps sqrt(N) (the
  // bound for the Lie-Poisson methods); the exact flow's closed form rounds with a bias (~3e-17 per
  // step, exact/free_body.cpp): worst case linear, 4 eps N. The splittings' energy error is
  // bounded, C (h|ω|)^p with h|ω| = 0.02 (backward error analysis; the method table states 8e-3 at
  // h|ω| = 1 for DLM and 2.7e-3 at 0.7 for Yoshida, so C < 1e-2): 1e-4 = (h|ω|)^2/4 and
  // 1e-7 = 0.6 (h|ω|)^4 leave C up to 1/4 and 0.6.
  // The midpoint's energy walks by up to κ = I_max/I_min times that per step: its step rounds each component of ω̄,
  // and T = ½ ω·I ω weighs the components' relative errors by the moments (κ = 3 here).
  const auto walk = [](double n) { return 10.0 * test::kRoundoff * std::sqrt(n); };
  const double kappa = 3.0;
  const std::vector<Conservation> runs = {{Method::implicit_midpoint, 1000000, kappa * walk(1e6), walk(1e6), false},
                                          {Method::splitting_dlm, 1000000, 1e-4, walk(1e6), true},
                                          {Method::splitting_dlm_yoshida4, 1000000, 1e-7, walk(3e6), true},
                                          // a closed form per step (~10 µs): 1e5 steps keep the test fast
                                          {Method::exact_flow_kick, 100000, 4 * test::kRoundoff * 1e5,
                                           4 * test::kRoundoff * 1e5, false}};
  for (const Conservation& c : runs) {
    SimulationOptions o;
    o.method = c.method;
    o.dt = 0.01;
    o.steps = c.steps;
    o.record_every = c.steps / 1000;
    const Trajectory tr = simulate(body, RigidBodyState{Eigen::Vector3d::Zero(), kQ0, Eigen::Vector3d::Zero(), kCaseA}, o);
    const std::size_t n = tr.size(), half = n / 2;
    const std::string name = method_info(c.method).name;
    ASSERT_FALSE(tr.diverged) << name;
    const double dE = max_relative_change(tr.kinetic_energy, 0, n), dL = max_relative_change(tr.angular_momentum_norm, 0, n);
    EXPECT_LT(dE, c.energy) << name;
    EXPECT_LT(dL, c.momentum) << name;
    // no secular drift: the energy error is a function on one closed orbit (E - H~ = h^2 H2(m) +
    // O(h^4), H~ conserved), so the second half's worst is within the first half's up to where the
    // records (every 1000 steps) fall on the orbit (20%) and the round-off walk
    if (c.truncation) {
      EXPECT_LE(max_relative_change(tr.kinetic_energy, half, n),
                1.2 * max_relative_change(tr.kinetic_energy, 0, half) + walk(static_cast<double>(c.steps)))
          << name;
    }
    for (double e : tr.quaternion_norm_error) ASSERT_LT(std::abs(e), 1e-14) << name;  // renormalised: ~2 eps
  }
}

}  // namespace
}  // namespace rigiddyn
