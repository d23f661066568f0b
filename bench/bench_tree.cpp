// Kinematic trees, performance: the articulated-body algorithm against forward dynamics through the joint-space
// inertia matrix, in one run.
//   forward_dynamics/<nv>   aba(tree, q, v, τ) ("rigiddyn", O(n), Featherstone Table 7.1) vs the route through H:
//                           H from crba, the bias forces C from rnea at zero acceleration, then H qdd = τ − C solved by
//                           Cholesky ("baseline", O(n³), Featherstone §6.1); both with one workspace, allocation-free.
//   Trees: nv = 7, a chain of seven revolute joints (an arm); nv = 38, a free base carrying four chains of eight
//   revolute joints (a humanoid's shape). Random axes, placements and inertias, a random state (fixed seed).
// Before timing, the two must give the same qdd to the bound of the Cholesky route, 64 cond(H) ε |qdd|∞ (a backward
// stable solve of a system of condition cond(H), with ABA's own rounding of the same order), or the baseline reports
// an error. ctest runs it with RIGIDDYN_BENCH_SMALL=1 (fewer calls).
// The instructions per call of each algorithm alone: valgrind --tool=callgrind on this program with
// --toggle-collect='rigiddyn::crba*' (or aba, rnea) and callgrind_annotate.
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "rigiddyn/tree/aba.hpp"
#include "rigiddyn/tree/crba.hpp"
#include "rigiddyn/tree/joints/free_joint.hpp"
#include "rigiddyn/tree/joints/revolute_joint.hpp"
#include "rigiddyn/tree/rnea.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace {

using namespace rigiddyn;

// A random link: mass 0.5–1.5 kg, centre of mass within 0.1 m of the link's origin, principal moments 0.1–0.15 kg m²
SpatialInertia random_inertia(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Eigen::Vector3d c(0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng));
  return SpatialInertia(1.0 + 0.5 * u(rng), c, Eigen::Vector3d(0.1, 0.12, 0.15).asDiagonal().toDenseMatrix());
}

// A chain of `joints` revolute joints under `parent`, each about a random axis, placed 0.2 m along z and up to 1 m
// sideways in its parent's frame, turned by up to 1 rad
void add_chain(Tree& tree, int parent, int joints, const std::string& name, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < joints; ++k) {
    const Eigen::Vector3d axis(u(rng), u(rng), u(rng));
    const Eigen::Vector3d turn_axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    const Transform X_T = Transform::from_quat(Eigen::Quaterniond(Eigen::AngleAxisd(u(rng), turn_axis)),
                                               Eigen::Vector3d(u(rng), u(rng), 0.2));
    parent = tree.add_link(name + std::to_string(k), parent, RevoluteJoint(axis), random_inertia(rng), X_T);
  }
}

// nv = 7: an arm; nv = 38: a free base and four chains of eight joints
Tree bench_tree(std::int64_t nv) {
  std::mt19937 rng(7);
  Tree tree(Eigen::Vector3d(0.0, 0.0, -9.81));
  if (nv == 7) {
    add_chain(tree, -1, 7, "arm", rng);
  } else {
    const int base = tree.add_link("base", -1, FreeJoint{}, random_inertia(rng));
    for (int c = 0; c < 4; ++c) add_chain(tree, base, 8, "limb" + std::to_string(c) + "_", rng);
  }
  return tree;
}

struct TreeState {
  Eigen::VectorXd q, v, tau;
};

// The neutral configuration with every revolute angle in [−1, 1] rad (the free base's pose at its neutral), v and τ
// in [−1, 1]
TreeState random_state(const Tree& tree) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  TreeState s{tree.neutral_configuration(), Eigen::VectorXd(tree.nv()), Eigen::VectorXd(tree.nv())};
  for (const Link& link : tree.links()) {
    if (link.nq == 1) s.q[link.idx_q] = u(rng);
  }
  for (Eigen::Index i = 0; i < tree.nv(); ++i) s.v[i] = u(rng), s.tau[i] = u(rng);
  return s;
}

// Forward dynamics through H: qdd = H⁻¹ (τ − C), with its scratch sized once
class CrbaRoute {
 public:
  explicit CrbaRoute(const Tree& tree) : ws_(tree), llt_(tree.nv()), qdd_(tree.nv()) {}
  const Eigen::VectorXd& operator()(const Tree& tree, const TreeState& s) {
    qdd_ = s.tau - bias_forces(tree, s.q, s.v, ws_);
    llt_.compute(crba(tree, s.q, ws_));
    llt_.solveInPlace(qdd_);
    return qdd_;
  }
  const Eigen::MatrixXd& H(const Tree& tree, const TreeState& s) { return crba(tree, s.q, ws_); }

 private:
  TreeWorkspace ws_;
  Eigen::LLT<Eigen::MatrixXd> llt_;
  Eigen::VectorXd qdd_;
};

std::int64_t calls() { return bench::bench_size(20000, 200); }

void aba_route(benchmark::State& state) {
  const Tree tree = bench_tree(state.range(0));
  const TreeState s = random_state(tree);
  TreeWorkspace ws(tree);
  const std::int64_t n = calls();
  for (auto _ : state) {
    for (std::int64_t i = 0; i < n; ++i) benchmark::DoNotOptimize(aba(tree, s.q, s.v, s.tau, {}, ws).data());
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void crba_route(benchmark::State& state) {
  const Tree tree = bench_tree(state.range(0));
  const TreeState s = random_state(tree);
  CrbaRoute route(tree);
  TreeWorkspace ws(tree);
  // the agreement check (see the header)
  const Eigen::VectorXd qdd_aba = aba(tree, s.q, s.v, s.tau, {}, ws);
  const Eigen::VectorXd qdd_crba = route(tree, s);
  const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(route.H(tree, s)).eigenvalues();
  const double bound = 64.0 * (lambda.maxCoeff() / lambda.minCoeff()) * std::numeric_limits<double>::epsilon() *
                       qdd_crba.lpNorm<Eigen::Infinity>();
  const double mismatch = (qdd_aba - qdd_crba).lpNorm<Eigen::Infinity>();
  state.counters["mismatch_over_bound"] = mismatch / bound;
  if (mismatch > bound) {
    state.SkipWithError("aba and the route through H give different accelerations");
    return;
  }
  const std::int64_t n = calls();
  for (auto _ : state) {
    for (std::int64_t i = 0; i < n; ++i) benchmark::DoNotOptimize(route(tree, s).data());
  }
  state.SetItemsProcessed(state.iterations() * n);
}

}  // namespace

BENCHMARK(aba_route)->Name("forward_dynamics:rigiddyn")->Arg(7)->Arg(38)->Unit(benchmark::kMicrosecond);
BENCHMARK(crba_route)->Name("forward_dynamics:baseline")->Arg(7)->Arg(38)->Unit(benchmark::kMicrosecond);
