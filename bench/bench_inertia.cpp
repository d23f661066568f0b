// Inertia layer benchmarks, each against a plain hand-written loop doing the same arithmetic:
//  - solid_mesh: exact inertia of a ~100k-triangle closed mesh (rigiddyn includes the closed /
//    oriented topology check; the baseline sums the signed tetrahedra only);
//  - composite: 10k parts placed by transforms;
//  - principal_axes: 1e6 inertias (baseline: Eigen's SelfAdjointEigenSolver called directly).
#include <benchmark/benchmark.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <vector>

#include "bench_common.hpp"
#include "rigiddyn/inertia/mesh.hpp"
#include "rigiddyn/inertia/primitives.hpp"
#include "rigiddyn/inertia/principal_axes.hpp"
#include "rigiddyn/inertia/spatial_inertia.hpp"

namespace {

using namespace rigiddyn;

// A UV sphere with about `triangles` faces (outward).
struct Sphere {
  MeshVertices V;
  MeshFaces F;
};
Sphere uv_sphere(std::int64_t triangles) {
  const int n = std::max(4, static_cast<int>(std::sqrt(triangles / 2.0)));
  const int rings = n - 1;
  Sphere s;
  s.V.resize(2 + rings * n, 3);
  s.V.row(0) << 0, 0, -1;
  for (int k = 0; k < rings; ++k)
    for (int j = 0; j < n; ++j) {
      const double phi = M_PI * (k + 1) / n, t = 2 * M_PI * j / n;
      s.V.row(1 + k * n + j) << std::sin(phi) * std::cos(t), std::sin(phi) * std::sin(t), -std::cos(phi);
    }
  const int top = 1 + rings * n;
  s.V.row(top) << 0, 0, 1;
  const auto ring = [n](int k, int j) { return 1 + k * n + (j % n); };
  s.F.resize(2 * n * rings, 3);
  Eigen::Index f = 0;
  for (int j = 0; j < n; ++j) {
    s.F.row(f++) << 0, ring(0, j + 1), ring(0, j);
    for (int k = 0; k + 1 < rings; ++k) {
      s.F.row(f++) << ring(k, j), ring(k, j + 1), ring(k + 1, j + 1);
      s.F.row(f++) << ring(k, j), ring(k + 1, j + 1), ring(k + 1, j);
    }
    s.F.row(f++) << top, ring(rings - 1, j), ring(rings - 1, j + 1);
  }
  return s;
}

void solid_mesh_rigiddyn(benchmark::State& state) {
  const Sphere s = uv_sphere(bench::bench_size(100000, 2000));
  for (auto _ : state) benchmark::DoNotOptimize(solid_mesh(s.V, s.F, Density{1.0}));
  state.SetItemsProcessed(state.iterations() * s.F.rows());
  state.counters["triangles"] = static_cast<double>(s.F.rows());
}

void solid_mesh_baseline(benchmark::State& state) {
  const Sphere s = uv_sphere(bench::bench_size(100000, 2000));
  for (auto _ : state) {
    double V = 0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
    for (Eigen::Index f = 0; f < s.F.rows(); ++f) {
      const Eigen::Vector3d a = s.V.row(s.F(f, 0)), b = s.V.row(s.F(f, 1)), c = s.V.row(s.F(f, 2));
      const double v = a.dot(b.cross(c)) / 6.0;
      const Eigen::Vector3d sum = a + b + c;
      V += v;
      first += v / 4.0 * sum;
      second += v / 20.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
    }
    const Eigen::Vector3d com = first / V;
    const Eigen::Matrix3d C = second - V * com * com.transpose();
    benchmark::DoNotOptimize(Eigen::Matrix3d(C.trace() * Eigen::Matrix3d::Identity() - C));
  }
  state.SetItemsProcessed(state.iterations() * s.F.rows());
}

std::vector<std::pair<Transform, SpatialInertia>> random_parts(std::int64_t n) {
  std::mt19937 rng(1);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0.1, 1.0);
  std::vector<std::pair<Transform, SpatialInertia>> parts;
  for (std::int64_t i = 0; i < n; ++i) {
    const Eigen::Quaterniond q = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized();
    parts.emplace_back(Transform(q.toRotationMatrix(), Eigen::Vector3d(g(rng), g(rng), g(rng))),
                       solid_box(Eigen::Vector3d(u(rng), u(rng), u(rng)), Mass{u(rng)}));
  }
  return parts;
}

void composite_rigiddyn(benchmark::State& state) {
  const auto parts = random_parts(bench::bench_size(10000, 1000));
  for (auto _ : state) benchmark::DoNotOptimize(composite(parts));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(parts.size()));
}

void composite_baseline(benchmark::State& state) {
  const auto parts = random_parts(bench::bench_size(10000, 1000));
  for (auto _ : state) {
    double m = 0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    Eigen::Matrix3d I_O = Eigen::Matrix3d::Zero();
    for (const auto& [X, part] : parts) {
      const Eigen::Matrix3d& R = X.rotation();
      const Eigen::Vector3d c = R * part.com() + X.translation();
      m += part.mass();
      first += part.mass() * c;
      I_O += R * part.inertia_com() * R.transpose() +
             part.mass() * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
    }
    const Eigen::Vector3d c = first / m;
    benchmark::DoNotOptimize(Eigen::Matrix3d(I_O - m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose())));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(parts.size()));
}

std::vector<Eigen::Matrix3d> random_inertias(std::int64_t n) {
  std::vector<Eigen::Matrix3d> out;
  out.reserve(static_cast<size_t>(n));
  for (const auto& [X, part] : random_parts(std::min<std::int64_t>(n, 1000))) out.push_back(part.transformed(X).inertia_com());
  while (static_cast<std::int64_t>(out.size()) < n) out.push_back(out[out.size() % 1000]);
  return out;
}

void principal_axes_rigiddyn(benchmark::State& state) {
  const auto I = random_inertias(bench::bench_size(1000000, 10000));
  for (auto _ : state)
    for (const auto& Ii : I) benchmark::DoNotOptimize(principal_axes(Ii));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(I.size()));
}

void principal_axes_baseline(benchmark::State& state) {
  const auto I = random_inertias(bench::bench_size(1000000, 10000));
  for (auto _ : state)
    for (const auto& Ii : I) {
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(Ii);
      benchmark::DoNotOptimize(eig.eigenvalues());
      benchmark::DoNotOptimize(eig.eigenvectors());
    }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(I.size()));
}

}  // namespace

BENCHMARK(solid_mesh_rigiddyn)->Name("solid_mesh:rigiddyn")->Unit(benchmark::kMillisecond);
BENCHMARK(solid_mesh_baseline)->Name("solid_mesh:baseline")->Unit(benchmark::kMillisecond);
BENCHMARK(composite_rigiddyn)->Name("composite:rigiddyn")->Unit(benchmark::kMicrosecond);
BENCHMARK(composite_baseline)->Name("composite:baseline")->Unit(benchmark::kMicrosecond);
BENCHMARK(principal_axes_rigiddyn)->Name("principal_axes:rigiddyn")->Unit(benchmark::kMillisecond);
BENCHMARK(principal_axes_baseline)->Name("principal_axes:baseline")->Unit(benchmark::kMillisecond);
