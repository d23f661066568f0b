// A kinematic tree in a scene, performance: an RK4 step of the scene model (the tree's links as bodies under a
// UniformGravity element: forward kinematics for the elements' view of the links, the element's power, the
// articulated-body algorithm with the gravity the tree applies as its base's acceleration, the works and impulses the
// records' balance needs) against a hand-written RK4 loop around the same algorithm (aba with the tree's own gravity,
// q̇ = v, scratch sized once: the least a tree's RK4 step can cost here).
//   rk4_step/<nv>   nv = 2: a double pendulum of rods; nv = 7: a chain of seven revolute joints (an arm), random
//                   axes, placements and inertias (fixed seed).
// Before timing, the two must reach the same state after 100 steps of 1 ms to 1e-9 of its size (the same map: they
// differ by a few ε per evaluation where their arithmetic is ordered differently, which 100 steps of a map whose
// tangent stays O(10) over 0.1 s carry to ~1e-12), or the baseline reports an error. ctest runs it with
// RIGIDDYN_BENCH_SMALL=1 (fewer steps).
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"
#include "rigiddyn/tree/aba.hpp"

#include <memory>
#include <random>
#include <string>

namespace {

using namespace rigiddyn;

constexpr double kDt = 1e-3;
const Eigen::Vector3d kGravity(0.0, 0.0, -9.81);

// nv = 2: two rods of 1 kg and 1 m hinged about y; nv = 7: an arm of random revolute joints
Tree bench_tree(std::int64_t nv, const Eigen::Vector3d& gravity) {
  Tree tree(gravity);
  if (nv == 2) {
    const SpatialInertia rod(1.0, Eigen::Vector3d(0.5, 0.0, 0.0), Eigen::Vector3d(1e-3, 1.0 / 12, 1.0 / 12).asDiagonal());
    tree.add_link("upper", -1, RevoluteJoint(Eigen::Vector3d::UnitY()), rod);
    tree.add_link("lower", 0, RevoluteJoint(Eigen::Vector3d::UnitY()), rod,
                  Transform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 0.0, 0.0)));
    return tree;
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int parent = -1;
  for (int k = 0; k < 7; ++k) {
    const SpatialInertia inertia(1.0 + 0.5 * u(rng), Eigen::Vector3d(0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng)),
                                 Eigen::Vector3d(0.1, 0.12, 0.15).asDiagonal().toDenseMatrix());
    const Transform X_T = Transform::from_quat(
        Eigen::Quaterniond(Eigen::AngleAxisd(u(rng), Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized())),
        Eigen::Vector3d(u(rng), u(rng), 0.2));
    parent = tree.add_link("link" + std::to_string(k), parent, RevoluteJoint(Eigen::Vector3d(u(rng), u(rng), u(rng))),
                           inertia, X_T);
  }
  return tree;
}

Eigen::VectorXd start_q(std::int64_t nv) { return Eigen::VectorXd::LinSpaced(nv, 0.3, -0.4); }

// The scene of the tree's links under UniformGravity, and their states at (start_q, 0)
struct TreeScene {
  CompiledScene compiled;
  std::vector<BodyState> initial;
};
TreeScene tree_scene(std::int64_t nv) {
  const auto tree = std::make_shared<const Tree>(bench_tree(nv, Eigen::Vector3d::Zero()));
  Scene scene;
  scene.elements.push_back(UniformGravity{kGravity, {}});
  std::vector<BodyState> initial;
  const Eigen::VectorXd q = start_q(nv);
  add_tree(scene, tree);
  for (int i = 0; i < tree->num_links(); ++i) initial.push_back(JointState{q.segment(i, 1), Eigen::VectorXd::Zero(1)});
  return {compile_scene(scene, Method::rk4), std::move(initial)};
}

// RK4 on (q, v) with q̇ = v (revolute joints), v̇ = aba(q, v, 0): stages in vectors sized once
class HandRk4 {
 public:
  explicit HandRk4(const Tree& tree)
      : tree_(tree), ws_(tree), tau_(Eigen::VectorXd::Zero(tree.nv())), k_q_(4, Eigen::VectorXd(tree.nv())),
        k_v_(k_q_), stage_q_(tree.nv()), stage_v_(tree.nv()) {}
  void step(Eigen::VectorXd& q, Eigen::VectorXd& v, double h) {
    static constexpr double c[4] = {0.0, 0.5, 0.5, 1.0};
    for (int s = 0; s < 4; ++s) {
      if (s == 0) {
        stage_q_ = q, stage_v_ = v;
      } else {
        stage_q_ = q + (c[s] * h) * k_q_[s - 1], stage_v_ = v + (c[s] * h) * k_v_[s - 1];
      }
      k_q_[s] = stage_v_;
      k_v_[s] = aba(tree_, stage_q_, stage_v_, tau_, {}, ws_);
    }
    q += (h / 6.0) * (k_q_[0] + 2.0 * k_q_[1] + 2.0 * k_q_[2] + k_q_[3]);
    v += (h / 6.0) * (k_v_[0] + 2.0 * k_v_[1] + 2.0 * k_v_[2] + k_v_[3]);
  }

 private:
  const Tree& tree_;
  TreeWorkspace ws_;
  Eigen::VectorXd tau_;
  std::vector<Eigen::VectorXd> k_q_, k_v_;
  Eigen::VectorXd stage_q_, stage_v_;
};

std::int64_t steps() { return bench::bench_size(20000, 200); }

SimulationOptions rk4_options(std::int64_t n) {
  SimulationOptions o;
  o.method = Method::rk4, o.dt = kDt, o.steps = n, o.record_every = n;  // the first and last records
  return o;
}

void scene_route(benchmark::State& state) {
  const TreeScene s = tree_scene(state.range(0));
  const std::int64_t n = steps();
  for (auto _ : state) benchmark::DoNotOptimize(simulate(s.compiled, s.initial, rk4_options(n)).t.data());
  state.SetItemsProcessed(state.iterations() * n);
}

void hand_route(benchmark::State& state) {
  const std::int64_t nv = state.range(0);
  const Tree tree = bench_tree(nv, kGravity);
  HandRk4 rk4(tree);
  {  // the agreement check (see the header)
    const TreeScene s = tree_scene(nv);
    const SceneSimulation r = simulate(s.compiled, s.initial, rk4_options(100));
    Eigen::VectorXd q = start_q(nv), v = Eigen::VectorXd::Zero(nv);
    for (int k = 0; k < 100; ++k) rk4.step(q, v, kDt);
    const Eigen::Map<const Eigen::VectorXd> q_scene(r.joint_q.data() + nv, nv), v_scene(r.joint_v.data() + nv, nv);
    const double mismatch = std::max((q - q_scene).lpNorm<Eigen::Infinity>(), (v - v_scene).lpNorm<Eigen::Infinity>());
    state.counters["mismatch"] = mismatch;
    if (!(mismatch <= 1e-9 * std::max(1.0, std::max(q.lpNorm<Eigen::Infinity>(), v.lpNorm<Eigen::Infinity>())))) {
      state.SkipWithError("the scene and the hand loop reach different states");
      return;
    }
  }
  const std::int64_t n = steps();
  for (auto _ : state) {
    Eigen::VectorXd q = start_q(nv), v = Eigen::VectorXd::Zero(nv);
    for (std::int64_t k = 0; k < n; ++k) rk4.step(q, v, kDt);
    benchmark::DoNotOptimize(q.data());
  }
  state.SetItemsProcessed(state.iterations() * n);
}

}  // namespace

BENCHMARK(scene_route)->Name("rk4_step:rigiddyn")->Arg(2)->Arg(7)->Unit(benchmark::kMicrosecond);
BENCHMARK(hand_route)->Name("rk4_step:baseline")->Arg(2)->Arg(7)->Unit(benchmark::kMicrosecond);
