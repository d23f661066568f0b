// The structure-preserving integrators (implicit_midpoint, splitting_dlm, splitting_dlm_yoshida4,
// exact_flow_kick) and the exact torque-free solution: ns per step (per evaluation) for one free
// rigid body, each next to the same number of steps of a hand-written RK4 loop on (ω, q) with
// renormalisation (the baseline of every case, so the ratio reads "cost in RK4 steps").
// Problem: I = diag(1, 2, 3) kg m², tumbling near the intermediate axis ω0 = (0.01, 2, 0.01) rad/s,
// h = 0.01 s.
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "rigiddyn/exact/free_body.hpp"
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/models/rigid_body.hpp"

namespace {

const Eigen::Vector3d kInertia(1.0, 2.0, 3.0);
const Eigen::Vector3d kW0(0.01, 2.0, 0.01);
constexpr double kH = 0.01;

std::int64_t steps() { return rigiddyn::bench::bench_size(100000, 1000); }

// rigiddyn: n steps of Integrator on the rigid-body model (principal form, no loads)
template <class Integrator>
void step_rigiddyn(benchmark::State& state) {
  const std::int64_t n = steps();
  const rigiddyn::RigidBodyModel<rigiddyn::PrincipalEuler> model(1.0, rigiddyn::PrincipalEuler(kInertia));
  for (auto _ : state) {
    rigiddyn::RigidBodyState s0;
    s0.w_B = kW0;
    rigiddyn::RigidBodyCoordinates y = rigiddyn::to_coordinates(s0);
    for (std::int64_t i = 0; i < n; ++i) Integrator::step(model, y, kH);
    benchmark::DoNotOptimize(y);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

// rigiddyn: n evaluations of the exact state at spread times
void exact_state_rigiddyn(benchmark::State& state) {
  const std::int64_t n = steps();
  const rigiddyn::TorqueFreeSolution solution(kInertia.asDiagonal(), Eigen::Quaterniond::Identity(), kW0);
  for (auto _ : state) {
    double sum = 0.0;
    for (std::int64_t i = 0; i < n; ++i) {
      const rigiddyn::TorqueFreeState s = solution.state_at(kH * static_cast<double>(i));
      sum += s.w_B.x() + s.q_WB.w();
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

// baseline: n steps of classic RK4 on y = (ω, q), ω̇ = I⁻¹((I ω) × ω), q̇ = q ⊗ (ω, 0)/2, q renormalised
void rk4_baseline(benchmark::State& state) {
  const std::int64_t n = steps();
  const Eigen::Vector3d I = kInertia, I_inv = kInertia.cwiseInverse();
  using Vector7d = Eigen::Matrix<double, 7, 1>;
  const auto f = [&](const Vector7d& y) {
    const Eigen::Vector3d w = y.head<3>();
    const Eigen::Quaterniond q(y(6), y(3), y(4), y(5));
    Vector7d d;
    d.head<3>() = I_inv.cwiseProduct(I.cwiseProduct(w).cross(w));
    const Eigen::Quaterniond q_dot = q * Eigen::Quaterniond(0.0, 0.5 * w.x(), 0.5 * w.y(), 0.5 * w.z());
    d.segment<3>(3) = q_dot.vec();
    d(6) = q_dot.w();
    return d;
  };
  for (auto _ : state) {
    Vector7d y;
    y << kW0, 0.0, 0.0, 0.0, 1.0;
    for (std::int64_t i = 0; i < n; ++i) {
      const Vector7d k1 = f(y);
      const Vector7d k2 = f(y + 0.5 * kH * k1);
      const Vector7d k3 = f(y + 0.5 * kH * k2);
      const Vector7d k4 = f(y + kH * k3);
      y += kH / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      y.tail<4>().normalize();
    }
    benchmark::DoNotOptimize(y);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

}  // namespace

BENCHMARK(step_rigiddyn<rigiddyn::ImplicitMidpoint>)->Name("implicit_midpoint_step:rigiddyn");
BENCHMARK(rk4_baseline)->Name("implicit_midpoint_step:baseline");
BENCHMARK(step_rigiddyn<rigiddyn::SplittingDlm>)->Name("splitting_dlm_step:rigiddyn");
BENCHMARK(rk4_baseline)->Name("splitting_dlm_step:baseline");
BENCHMARK(step_rigiddyn<rigiddyn::Yoshida4>)->Name("splitting_dlm_yoshida4_step:rigiddyn");
BENCHMARK(rk4_baseline)->Name("splitting_dlm_yoshida4_step:baseline");
BENCHMARK(step_rigiddyn<rigiddyn::ExactFlowKick>)->Name("exact_flow_kick_step:rigiddyn");
BENCHMARK(rk4_baseline)->Name("exact_flow_kick_step:baseline");
BENCHMARK(step_rigiddyn<rigiddyn::Rk4>)->Name("rk4_step:rigiddyn");
BENCHMARK(rk4_baseline)->Name("rk4_step:baseline");
BENCHMARK(exact_state_rigiddyn)->Name("exact_state:rigiddyn");
BENCHMARK(rk4_baseline)->Name("exact_state:baseline");
