// Spatial algebra throughput: composing n transforms (X_AC[i] = X_AB[i] * X_BC[i]) and transforming
// n motions (X_AB[i].act(m_B[i])), rigiddyn's Transform/Motion against plain loops over raw
// Matrix3d/Vector3d arrays doing the same arithmetic. One op = one item.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "bench_common.hpp"
#include "rigiddyn/spatial/motion.hpp"
#include "rigiddyn/spatial/transform.hpp"

namespace {

using rigiddyn::Motion;
using rigiddyn::Transform;

std::int64_t size() { return rigiddyn::bench::bench_size(1'000'000, 10'000); }

// n random transforms, motions, and the same data as raw arrays for the baselines.
struct Data {
  std::vector<Transform> X_AB, X_BC;
  std::vector<Motion> m_B;
  std::vector<Eigen::Matrix3d> R_AB, R_BC;
  std::vector<Eigen::Vector3d> p_AB, p_BC, w_B, v_B;

  explicit Data(std::int64_t n) {
    std::mt19937_64 gen(42);
    std::normal_distribution<double> normal;
    auto vec = [&] { return Eigen::Vector3d(normal(gen), normal(gen), normal(gen)); };
    auto rot = [&] {
      return Eigen::Quaterniond(normal(gen), normal(gen), normal(gen), normal(gen)).normalized().toRotationMatrix();
    };
    for (std::int64_t i = 0; i < n; ++i) {
      X_AB.emplace_back(rot(), vec());
      X_BC.emplace_back(rot(), vec());
      m_B.emplace_back(vec(), vec());
      R_AB.push_back(X_AB.back().rotation());
      p_AB.push_back(X_AB.back().translation());
      R_BC.push_back(X_BC.back().rotation());
      p_BC.push_back(X_BC.back().translation());
      w_B.push_back(m_B.back().angular);
      v_B.push_back(m_B.back().linear);
    }
  }
};

const Data& data() {
  static const Data d(size());
  return d;
}

void compose_rigiddyn(benchmark::State& state) {
  const Data& d = data();
  const std::size_t n = d.X_AB.size();
  std::vector<Transform> X_AC(n);
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i) X_AC[i] = d.X_AB[i] * d.X_BC[i];
    benchmark::DoNotOptimize(X_AC.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}

void compose_baseline(benchmark::State& state) {
  const Data& d = data();
  const std::size_t n = d.R_AB.size();
  std::vector<Eigen::Matrix3d> R_AC(n);
  std::vector<Eigen::Vector3d> p_AC(n);
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i) {
      R_AC[i].noalias() = d.R_AB[i] * d.R_BC[i];
      p_AC[i].noalias() = d.R_AB[i] * d.p_BC[i];
      p_AC[i] += d.p_AB[i];
    }
    benchmark::DoNotOptimize(R_AC.data());
    benchmark::DoNotOptimize(p_AC.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}

void act_motion_rigiddyn(benchmark::State& state) {
  const Data& d = data();
  const std::size_t n = d.X_AB.size();
  std::vector<Motion> m_A(n);
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i) m_A[i] = d.X_AB[i].act(d.m_B[i]);
    benchmark::DoNotOptimize(m_A.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}

void act_motion_baseline(benchmark::State& state) {
  const Data& d = data();
  const std::size_t n = d.R_AB.size();
  std::vector<Eigen::Vector3d> w_A(n), v_A(n);
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i) {
      w_A[i].noalias() = d.R_AB[i] * d.w_B[i];
      v_A[i].noalias() = d.R_AB[i] * d.v_B[i];
      v_A[i] += d.p_AB[i].cross(w_A[i]);
    }
    benchmark::DoNotOptimize(w_A.data());
    benchmark::DoNotOptimize(v_A.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}

BENCHMARK(compose_rigiddyn)->Name("compose_transforms:rigiddyn")->Unit(benchmark::kMillisecond);
BENCHMARK(compose_baseline)->Name("compose_transforms:baseline")->Unit(benchmark::kMillisecond);
BENCHMARK(act_motion_rigiddyn)->Name("transform_motions:rigiddyn")->Unit(benchmark::kMillisecond);
BENCHMARK(act_motion_baseline)->Name("transform_motions:baseline")->Unit(benchmark::kMillisecond);

}  // namespace
