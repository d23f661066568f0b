// Rotating n vectors by n unit quaternions, v_W[i] = R(q_WB[i]) v_B[i]: rigiddyn's per-item path
// (the loop the Python quat_rotate runs: checked_unit_quaternion, then quat_rotate) and the
// unchecked core, against a plain loop over raw (x, y, z, w) / xyz double arrays with the formula
// written out. Also the matrix route, R = quat_to_matrix(q) then R v, against a written-out R(q).
// One op = one vector.
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "rigiddyn/so3/matrix.hpp"
#include "rigiddyn/so3/quaternion.hpp"

namespace {

std::int64_t size() { return rigiddyn::bench::bench_size(1'000'000, 10'000); }

// n random unit quaternions and vectors, as Eigen objects and as raw arrays for the baselines
struct Data {
  std::vector<Eigen::Quaterniond> q_WB;
  std::vector<Eigen::Vector3d> v_B;
  std::vector<double> q_raw;  // (n x 4) x, y, z, w
  std::vector<double> v_raw;  // (n x 3)

  explicit Data(std::int64_t n) {
    std::mt19937_64 gen(42);
    std::normal_distribution<double> normal;
    for (std::int64_t i = 0; i < n; ++i) {
      q_WB.push_back(Eigen::Quaterniond(normal(gen), normal(gen), normal(gen), normal(gen)).normalized());
      v_B.emplace_back(normal(gen), normal(gen), normal(gen));
      q_raw.insert(q_raw.end(), {q_WB.back().x(), q_WB.back().y(), q_WB.back().z(), q_WB.back().w()});
      v_raw.insert(v_raw.end(), {v_B.back().x(), v_B.back().y(), v_B.back().z()});
    }
  }
};

const Data& data() {
  static const Data d(size());
  return d;
}

template <typename Loop>
void run(benchmark::State& state, std::size_t n, Loop loop) {
  for (auto _ : state) loop();
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}

void rotate_checked_rigiddyn(benchmark::State& state) {
  const Data& d = data();
  const std::size_t n = d.q_WB.size();
  std::vector<Eigen::Vector3d> v_W(n);
  const std::string name = "q";
  run(state, n, [&] {
    for (std::size_t i = 0; i < n; ++i) v_W[i] = rigiddyn::quat_rotate(rigiddyn::checked_unit_quaternion(d.q_WB[i], name), d.v_B[i]);
    benchmark::DoNotOptimize(v_W.data());
    benchmark::ClobberMemory();
  });
}

void rotate_rigiddyn(benchmark::State& state) {
  const Data& d = data();
  const std::size_t n = d.q_WB.size();
  std::vector<Eigen::Vector3d> v_W(n);
  run(state, n, [&] {
    for (std::size_t i = 0; i < n; ++i) v_W[i] = rigiddyn::quat_rotate(d.q_WB[i], d.v_B[i]);
    benchmark::DoNotOptimize(v_W.data());
    benchmark::ClobberMemory();
  });
}

// v' = v + 2 w (u × v) + 2 u × (u × v), u = (x, y, z), on raw arrays
void rotate_baseline(benchmark::State& state) {
  const Data& d = data();
  const std::size_t n = d.q_WB.size();
  std::vector<double> out(3 * n);
  const double* q = d.q_raw.data();
  const double* v = d.v_raw.data();
  run(state, n, [&] {
    for (std::size_t i = 0; i < n; ++i) {
      const double x = q[4 * i], y = q[4 * i + 1], z = q[4 * i + 2], w = q[4 * i + 3];
      const double a = v[3 * i], b = v[3 * i + 1], c = v[3 * i + 2];
      const double tx = 2 * (y * c - z * b), ty = 2 * (z * a - x * c), tz = 2 * (x * b - y * a);  // t = 2 u × v
      out[3 * i] = a + w * tx + (y * tz - z * ty);
      out[3 * i + 1] = b + w * ty + (z * tx - x * tz);
      out[3 * i + 2] = c + w * tz + (x * ty - y * tx);
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  });
}

void matrix_rotate_rigiddyn(benchmark::State& state) {
  const Data& d = data();
  const std::size_t n = d.q_WB.size();
  std::vector<Eigen::Vector3d> v_W(n);
  run(state, n, [&] {
    for (std::size_t i = 0; i < n; ++i) v_W[i].noalias() = rigiddyn::quat_to_matrix(d.q_WB[i]) * d.v_B[i];
    benchmark::DoNotOptimize(v_W.data());
    benchmark::ClobberMemory();
  });
}

// R(q) written out, then R v, on raw arrays
void matrix_rotate_baseline(benchmark::State& state) {
  const Data& d = data();
  const std::size_t n = d.q_WB.size();
  std::vector<double> out(3 * n);
  const double* q = d.q_raw.data();
  const double* v = d.v_raw.data();
  run(state, n, [&] {
    for (std::size_t i = 0; i < n; ++i) {
      const double x = q[4 * i], y = q[4 * i + 1], z = q[4 * i + 2], w = q[4 * i + 3];
      const double R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                              {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                              {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
      for (int r = 0; r < 3; ++r) out[3 * i + r] = R[r][0] * v[3 * i] + R[r][1] * v[3 * i + 1] + R[r][2] * v[3 * i + 2];
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  });
}

BENCHMARK(rotate_checked_rigiddyn)->Name("quat_rotate_checked:rigiddyn")->Unit(benchmark::kMillisecond);
BENCHMARK(rotate_baseline)->Name("quat_rotate_checked:baseline")->Unit(benchmark::kMillisecond);
BENCHMARK(rotate_rigiddyn)->Name("quat_rotate:rigiddyn")->Unit(benchmark::kMillisecond);
BENCHMARK(rotate_baseline)->Name("quat_rotate:baseline")->Unit(benchmark::kMillisecond);
BENCHMARK(matrix_rotate_rigiddyn)->Name("matrix_rotate:rigiddyn")->Unit(benchmark::kMillisecond);
BENCHMARK(matrix_rotate_baseline)->Name("matrix_rotate:baseline")->Unit(benchmark::kMillisecond);

}  // namespace
