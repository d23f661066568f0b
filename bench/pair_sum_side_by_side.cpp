// Two versions of one N-body pair-sum kernel (scene/elements/pair_forces.hpp) in one process, timed alternately: the
// driver of bench/python/pair_sum_side_by_side.py, which compiles cpp/src/scene/elements/pair_forces.cpp of two
// revisions with their namespaces renamed (rigiddyn_base, rigiddyn_head) and links both here. On a host whose timings
// drift by a third from one run to the next, alternating the two versions in rounds within one process, and keeping
// the best time of each, separates changes of a few percent that two builds timed one after the other cannot.
//
// RIGIDDYN_SIDE_KERNEL names the kernel (a function of rigiddyn::detail taking (columns, n, G, ε²)); with
// RIGIDDYN_SIDE_POTENTIAL it returns the potential V [J], else it adds the forces to columns 3-5. The columns are a
// cluster of n equal masses of total 1 at normal positions of unit spread (seed 1), softening ε = 0.01 m, G = 1.
// Prints per n: each version's best time per pair [ns], head over base, and the largest difference of their results
// relative to the largest result (forces) or of V.
#include <Eigen/Core>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#ifndef RIGIDDYN_SIDE_KERNEL
#error "RIGIDDYN_SIDE_KERNEL: the kernel's name, e.g. add_pair_forces_avx512"
#endif
#ifdef RIGIDDYN_SIDE_POTENTIAL
using Result = double;
#else
using Result = void;
#endif

namespace rigiddyn_base::detail {
Result RIGIDDYN_SIDE_KERNEL(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);
}
namespace rigiddyn_head::detail {
Result RIGIDDYN_SIDE_KERNEL(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);
}

namespace {

using Kernel = Result (*)(Eigen::ArrayXXd&, Eigen::Index, double, double);
constexpr double G = 1.0, softening2 = 1e-4;

// the kernel's result on `columns`: its forces (columns 3-5, cleared first) or V
double run(Kernel kernel, Eigen::ArrayXXd& columns, Eigen::Index n) {
#ifdef RIGIDDYN_SIDE_POTENTIAL
  return kernel(columns, n, G, softening2);
#else
  columns.block(0, 3, n, 3).setZero();
  kernel(columns, n, G, softening2);
  return 0.0;
#endif
}

// the least time per call [s] of `calls` calls, over 5 loops
double best_seconds(Kernel kernel, Eigen::ArrayXXd& columns, Eigen::Index n, int calls) {
  double best = INFINITY, sink = 0.0;
  for (int loop = 0; loop < 5; ++loop) {
    const auto start = std::chrono::steady_clock::now();
    for (int c = 0; c < calls; ++c) sink += run(kernel, columns, n);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / calls);
  }
  if (sink == 1.0) std::puts("");  // the potentials' sum kept alive
  return best;
}

Eigen::ArrayXXd cluster(Eigen::Index n) {
  Eigen::ArrayXXd columns = Eigen::ArrayXXd::Zero(n, 8);  // x, y, z, f_x, f_y, f_z, scratch, m
  std::mt19937 engine(1);
  std::normal_distribution<double> normal;
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) columns(i, c) = normal(engine);
    columns(i, 7) = 1.0 / static_cast<double>(n);
  }
  return columns;
}

// the two versions' largest difference, relative to the largest force component or to |V|
double difference(Eigen::ArrayXXd& columns, Eigen::Index n) {
  Eigen::ArrayXXd other = columns;
  const double V_base = run(rigiddyn_base::detail::RIGIDDYN_SIDE_KERNEL, columns, n);
  const double V_head = run(rigiddyn_head::detail::RIGIDDYN_SIDE_KERNEL, other, n);
#ifdef RIGIDDYN_SIDE_POTENTIAL
  return std::abs(V_head - V_base) / std::abs(V_base);
#else
  (void)V_base, (void)V_head;
  const auto f_base = columns.block(0, 3, n, 3), f_head = other.block(0, 3, n, 3);
  return (f_head - f_base).abs().maxCoeff() / f_base.abs().maxCoeff();
#endif
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::atoi(argv[1]) : 25;
  std::printf("%s, best of %d alternated rounds\n", RIGIDDYN_SIDE_KERNEL_NAME, rounds);
  std::printf("%6s %14s %14s %10s %12s\n", "n", "base ns/pair", "head ns/pair", "head/base", "difference");
  for (const Eigen::Index n : {12, 24, 50, 100, 300, 1000}) {
    Eigen::ArrayXXd columns = cluster(n);
    const double pairs = 0.5 * static_cast<double>(n) * static_cast<double>(n - 1);
    const int calls = std::max(20, static_cast<int>(2e7 / pairs));
    double base = INFINITY, head = INFINITY;
    for (int r = 0; r < rounds; ++r) {
      base = std::min(base, best_seconds(rigiddyn_base::detail::RIGIDDYN_SIDE_KERNEL, columns, n, calls));
      head = std::min(head, best_seconds(rigiddyn_head::detail::RIGIDDYN_SIDE_KERNEL, columns, n, calls));
    }
    std::printf("%6ld %14.3f %14.3f %10.3f %12.1e\n", static_cast<long>(n), base / pairs * 1e9, head / pairs * 1e9,
                head / base, difference(columns, n));
  }
}
