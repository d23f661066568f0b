// The exact torque-free solution: ns per state_at(t) evaluation, next to one step of a
// hand-written RK4 on Euler's equations + quaternion kinematics (with renormalisation) for one body.
// Problem: I = diag(1, 2, 3) kg m², ω0 = (0.3, 0.5, 1.0) rad/s (case A); and near the separatrix
// ω0 = (0.01, 2, 0.01) rad/s.
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "rigiddyn/exact/free_body.hpp"

namespace {

const Eigen::Vector3d kInertia(1.0, 2.0, 3.0);

Eigen::Vector3d initial_w(int problem) { return problem == 0 ? Eigen::Vector3d(0.3, 0.5, 1.0) : Eigen::Vector3d(0.01, 2.0, 0.01); }

// rigiddyn: n evaluations of the exact state at spread times
void free_body_state_rigiddyn(benchmark::State& state) {
  const std::int64_t n = rigiddyn::bench::bench_size(100000, 1000);
  const rigiddyn::TorqueFreeSolution solution(kInertia.asDiagonal(), Eigen::Quaterniond::Identity(),
                                              initial_w(static_cast<int>(state.range(0))));
  for (auto _ : state) {
    double sum = 0.0;
    for (std::int64_t i = 0; i < n; ++i) {
      const rigiddyn::TorqueFreeState s = solution.state_at(0.01 * static_cast<double>(i));
      sum += s.w_B.x() + s.q_WB.w();
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

// baseline: n steps of classic RK4 on y = (ω, q), ω̇ = I⁻¹((I ω) × ω), q̇ = q ⊗ (0, ω)/2, q renormalised
void free_body_state_baseline(benchmark::State& state) {
  const std::int64_t n = rigiddyn::bench::bench_size(100000, 1000);
  const double h = 0.01;
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
    y << initial_w(static_cast<int>(state.range(0))), 0.0, 0.0, 0.0, 1.0;
    for (std::int64_t i = 0; i < n; ++i) {
      const Vector7d k1 = f(y);
      const Vector7d k2 = f(y + 0.5 * h * k1);
      const Vector7d k3 = f(y + 0.5 * h * k2);
      const Vector7d k4 = f(y + h * k3);
      y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      y.tail<4>().normalize();
    }
    benchmark::DoNotOptimize(y);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

}  // namespace

// argument: 0 = generic case A, 1 = near the separatrix
BENCHMARK(free_body_state_rigiddyn)->Name("free_body_state:rigiddyn")->Arg(0)->Arg(1);
BENCHMARK(free_body_state_baseline)->Name("free_body_state:baseline")->Arg(0)->Arg(1);
