// Scenes, performance: the cost of a declared scene next to what it replaces, in one run.
//   nbody_gravity_rk4/N             N gravitating particles (MutualGravity), the compiled scene's model
//                                   stepped by RK4, vs a hand-written RK4 on the same direct sum
//                                   (scene_baselines.hpp, the packed columns); N = 10 … 4000 gives the N²
//                                   scaling (counter pair_time = time per pair evaluation, 4 N(N−1)/2 of
//                                   them per step). nbody_gravity_rk4_over_scalar_loop/N: the same scene
//                                   vs the loop summing one pair at a time.
//   pair_sum_avx512_over_avx2/N,    the direct sum of MutualGravity alone (scene/elements/pair_forces.hpp) on
//   pair_sum_avx2_over_portable/N   each path the CPU has, side by side (counter pair_time; a path the CPU
//                                   lacks is skipped): what each vector width gains.
//   pair_sum_avx2_division_over_mixed/N  the AVX2 path's two forms (every pair by the division, or four of each
//                                   eight by the reciprocal square root): which one this CPU's divider favours
//                                   (pair_forces.hpp, avx2_divides_every_pair).
//   pair_potential_over_pair_sum/N  the potential V of a record (the same pairs, pair_potential) over the forces'
//   pair_potential_over_portable/N  sum, both on the path of the process; and over the portable potential.
//   nbody_spheres_over_particles_rk4/N  the same scene with rigid spheres ("rigiddyn") over the particle
//                                   scene ("baseline"): what attitude costs when it is irrelevant.
//   swarm_spheres_over_particles_rk4/N  the same under UniformGravity only (no O(N²) sum to hide it).
//   scene_free_rigid_body_rk4,      one body declared as a scene with no force model vs
//   scene_free_particle_rk4         simulate(RigidBody / Particle, ...) (the public entries, both; the body runs as
//                                   its one-body scene, on the same layout: the two differ by the Trajectory the
//                                   body's simulate reads from the scene's records).
//   scene_generic_free_rigid_body_rk4  the same body with a declared zero Drag, which runs the generic
//                                   SceneModel, vs the body's simulate (its layout).
//   term_<element>/10               10 rigid bodies with one element ("rigiddyn") vs none ("baseline");
//                                   ns/op is per body and evaluation (4 per RK4 step), so the difference
//                                   of the two is the marginal cost of the term ("marginal" lines at exit).
//   term_custom_force/10, term_function_force/10  the weight m g as a user force: compiled in
//                                   (CustomForce) and type-erased (FunctionForce, std::function).
//   term_drag_zero_over_drag/10     a declared Drag with zero coefficients over a non-zero one: equal cost
//                                   (a zero term is evaluated, never skipped by a flag).
//   swarm_spheres_page_faults_rk4/1000  the minor page faults per step of the swarm of 1000 spheres through
//                                   simulate after the first step, in a heap trimmed before each run: 0 when no
//                                   step allocates (counter faults_per_step).
// ctest runs it with RIGIDDYN_BENCH_SMALL=1 (N <= 100, fewer steps).
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "scene_baselines.hpp"
#include "rigiddyn/integrators/rk4.hpp"
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/elements/pair_forces.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"
#include "rigiddyn/simulate/simulate.hpp"
#include "rigiddyn/vector_instructions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include <malloc.h>        // malloc_trim (glibc)
#include <sys/resource.h>  // getrusage (POSIX): the minor page faults
#include <time.h>          // clock_gettime (POSIX): the thread's CPU time

namespace {

using namespace rigiddyn;

constexpr double h = 1e-3;            // step [s]
constexpr double G_cluster = 1e-3;     // gravitational constant of the cluster [m³/(kg s²)]: slow motion
constexpr double softening = 0.05;     // [m]: no close encounter changes the (position-independent) cost
const Eigen::Vector3d w0(0.3, 2.0, 0.5);

// steps per benchmark iteration of an N-body case: about 1e6 pair evaluations, at least 2 steps
std::int64_t nbody_steps(std::int64_t n) { return std::max<std::int64_t>(2, 1'000'000 / (n * n)); }

// RK4 evaluates the direct sum 4 times per step, N(N−1)/2 pairs each time
double pair_evaluations(std::int64_t n, std::int64_t steps) { return 4.0 * steps * 0.5 * n * (n - 1); }

void set_pair_counters(benchmark::State& state, std::int64_t n, std::int64_t steps) {
  state.SetItemsProcessed(state.iterations() * steps);
  state.counters["pair_time"] = benchmark::Counter(pair_evaluations(n, steps) * state.iterations(),
                                                   benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

SimulationOptions run_options(std::int64_t steps) {
  SimulationOptions o;
  o.method = Method::rk4;
  o.dt = h;
  o.steps = steps;
  o.record_every = steps;  // first and last record only: the cost per step is the stepping
  return o;
}

// ---- 1, 3: the N-body cluster --------------------------------------------------------------------
enum class ClusterBody { particle, sphere };

// The cluster as a scene: N particles (or N rigid spheres of the same masses, I = 2/5 m r², r = 0.1 m,
// spinning, whose rotation does not affect the gravity between centres of mass) and MutualGravity.
std::pair<Scene, std::vector<BodyState>> cluster_scene(const bench::ParticleCluster& c, ClusterBody kind) {
  Scene scene;
  std::vector<BodyState> initial;
  for (std::size_t i = 0; i < c.mass.size(); ++i) {
    const Eigen::Vector3d p_W(c.p_W[3 * i], c.p_W[3 * i + 1], c.p_W[3 * i + 2]);
    const Eigen::Vector3d v_W(c.v_W[3 * i], c.v_W[3 * i + 1], c.v_W[3 * i + 2]);
    if (kind == ClusterBody::particle) {
      scene.bodies.emplace_back(Particle(c.mass[i]));
      initial.emplace_back(ParticleState{p_W, v_W});
    } else {
      const double I = 0.4 * c.mass[i] * 0.01;
      scene.bodies.emplace_back(RigidBody(c.mass[i], Eigen::Vector3d(I, I, I)));
      RigidBodyState s;
      s.p_W = p_W, s.v_W = v_W, s.w_B = w0;
      initial.emplace_back(s);
    }
  }
  MutualGravity gravity;
  gravity.G = G_cluster;
  gravity.softening = softening;
  scene.elements.emplace_back(gravity);
  return {scene, initial};
}

// `steps` RK4 steps of the compiled scene's model per iteration, as simulate's loop runs them, without
// its first and last records (each one more evaluation, and for MutualGravity the O(N²) potential:
// 35 % of a 2-step run at N = 1000).
void step_model(benchmark::State& state, const Scene& scene, const std::vector<BodyState>& initial, std::int64_t steps) {
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  const SceneModel& model = compiled.model();
  Eigen::VectorXd y = model.coordinates(initial, 0.0);
  auto work = workspace<Rk4>(model, y);
  for (auto _ : state) {
    y = model.coordinates(initial, 0.0);
    for (std::int64_t i = 0; i < steps; ++i) Rk4::step(model, y, h, work);
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
}

void nbody_scene(benchmark::State& state, ClusterBody kind) {
  const std::int64_t n = state.range(0), steps = nbody_steps(n);
  const auto [scene, initial] = cluster_scene(bench::particle_cluster(n), kind);
  step_model(state, scene, initial, steps);
  set_pair_counters(state, n, steps);
}

void nbody_particles(benchmark::State& state) { nbody_scene(state, ClusterBody::particle); }
void nbody_spheres(benchmark::State& state) { nbody_scene(state, ClusterBody::sphere); }

// The largest |Δp_W| [m] between one RK4 step of the hand loop and of the particle scene's model from
// the same cluster: the two must integrate the same motion for the pair to measure the same work.
double baseline_mismatch(const bench::ParticleCluster& c, bench::NBodyRk4Baseline& loop) {
  std::vector<double> y_loop = loop.initial(c);
  loop.step(y_loop, h);
  const auto [scene, initial] = cluster_scene(c, ClusterBody::particle);
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  Eigen::VectorXd y = compiled.model().coordinates(initial, 0.0);
  auto work = workspace<Rk4>(compiled.model(), y);
  Rk4::step(compiled.model(), y, h, work);
  double mismatch = 0.0;
  for (std::size_t i = 0; i < c.mass.size(); ++i)
    for (int k = 0; k < 3; ++k) mismatch = std::max(mismatch, std::abs(y[6 * i + k] - y_loop[6 * i + k]));
  return mismatch;
}

void nbody_loop(benchmark::State& state, bench::PairSum sum) {
  const std::int64_t n = state.range(0), steps = nbody_steps(n);
  const bench::ParticleCluster c = bench::particle_cluster(n);
  bench::NBodyRk4Baseline loop(c.mass, G_cluster, softening, sum);
  // Both sum the same pair forces in other orders: the accelerations agree to about N ulps of the
  // bound |a| ≤ G m_max N / ε² (2.4e3 m/s² at N = 4000), and a step moves p by h²/2 a through them, so
  // the positions after one step agree to ~5e-7 s² · 2.4e3 m/s² · 4000 · 2.2e-16 ≈ 1e-15 m; anything
  // above 1e-12 m is a different computation.
  const double mismatch = baseline_mismatch(c, loop);
  state.counters["max_dp_m"] = mismatch;
  if (mismatch > 1e-12) {
    state.SkipWithError("the hand loop and the scene integrate different motions");
    return;
  }
  for (auto _ : state) {
    std::vector<double> y = loop.initial(c);
    for (std::int64_t i = 0; i < steps; ++i) loop.step(y, h);
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  set_pair_counters(state, n, steps);
}
void nbody_packed_loop(benchmark::State& state) { nbody_loop(state, bench::PairSum::packed); }
void nbody_scalar_loop(benchmark::State& state) { nbody_loop(state, bench::PairSum::scalar); }

// ---- the pair sum alone, path by path ---------------------------------------------------------------
// The columns of N cluster particles (positions, forces, masses: pair_forces.hpp), the forces summed `rounds`
// times per iteration by `path` where the CPU has it.
template <class PairPath>
void pair_sum(benchmark::State& state, PairPath path, bool available) {
  if (!available) {
    state.SkipWithError("this CPU (or build) has no such vector instructions");
    return;
  }
  const std::int64_t n = state.range(0), rounds = std::max<std::int64_t>(1, 1'000'000 / (n * n));
  const bench::ParticleCluster c = bench::particle_cluster(n);
  Eigen::ArrayXXd columns = Eigen::ArrayXXd::Zero(n, 8);
  for (std::int64_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) columns(i, k) = c.p_W[3 * i + k];
    columns(i, 7) = c.mass[i];
  }
  for (auto _ : state) {
    for (std::int64_t r = 0; r < rounds; ++r) {
      if constexpr (std::is_void_v<decltype(path(columns, n, 1.0, 0.0))>) {
        path(columns, n, G_cluster, softening * softening);
      } else {
        benchmark::DoNotOptimize(path(columns, n, G_cluster, softening * softening));  // a potential's V
      }
    }
    benchmark::DoNotOptimize(columns.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * rounds);
  state.counters["pair_time"] = benchmark::Counter(0.5 * n * (n - 1) * rounds * state.iterations(),
                                                   benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
void pair_sum_portable(benchmark::State& state) { pair_sum(state, &detail::add_pair_forces_portable, true); }
void pair_sum_avx2(benchmark::State& state) { pair_sum(state, &detail::add_pair_forces_avx2_fma, cpu_has_avx2_fma()); }
void pair_sum_avx512(benchmark::State& state) { pair_sum(state, &detail::add_pair_forces_avx512, cpu_has_avx512()); }
// the AVX2 path's two forms (pair_forces.hpp: the CPU's divider decides which is faster; avx2_divides_every_pair)
void pair_sum_avx2_division(benchmark::State& state) {
  pair_sum(state, &detail::add_pair_forces_avx2_fma_division, cpu_has_avx2_fma());
}
void pair_sum_avx2_mixed(benchmark::State& state) {
  pair_sum(state, &detail::add_pair_forces_avx2_fma_mixed, cpu_has_avx2_fma());
}
// the pair sum as a record's potential (the path of the process), over the forces' and over the portable potential
void pair_sum_dispatched(benchmark::State& state) { pair_sum(state, &detail::add_pair_forces, true); }
void pair_potential(benchmark::State& state) { pair_sum(state, &detail::pair_potential, true); }
void pair_potential_portable(benchmark::State& state) { pair_sum(state, &detail::pair_potential_portable, true); }

void nbody_sizes(benchmark::internal::Benchmark* b) {
  const std::int64_t largest = bench::bench_size(4000, 100);
  for (const std::int64_t n : {10, 30, 100, 300, 1000, 4000})
    if (n <= largest) b->Arg(n);
  b->Unit(benchmark::kMicrosecond);
}

void size_10_100_1000(benchmark::internal::Benchmark* b) {
  const std::int64_t largest = bench::bench_size(1000, 100);
  for (const std::int64_t n : {10, 100, 1000})
    if (n <= largest) b->Arg(n);
  b->Unit(benchmark::kMicrosecond);
}

// 2 without the O(N²) sum: the same bodies under UniformGravity only, where the per-body work (and so
// what attitude costs) is all there is.
void swarm_scene(benchmark::State& state, ClusterBody kind) {
  const std::int64_t n = state.range(0), steps = bench::bench_size(200, 20);
  auto [scene, initial] = cluster_scene(bench::particle_cluster(n), kind);
  scene.elements = {UniformGravity{standard_gravity(), {}}};
  step_model(state, scene, initial, steps);
  state.SetItemsProcessed(state.iterations() * steps);
}
void swarm_particles(benchmark::State& state) { swarm_scene(state, ClusterBody::particle); }
void swarm_spheres(benchmark::State& state) { swarm_scene(state, ClusterBody::sphere); }

// ---- page faults per step ------------------------------------------------------------------------
// The same swarm of 1000 spheres through simulate (RK4, the first and last records): the minor page
// faults of the steps after the first, per step. Each run starts after malloc_trim has handed the heap's
// free memory back to the system, as a process that freed a large block would have it: a step that
// allocated a stage of the state's size (13 000 doubles) would then fault its pages in again at every
// step. 0 when no step allocates (integrators/workspace.hpp).
long minor_faults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

void swarm_page_faults(benchmark::State& state) {
  const std::int64_t n = 1000, steps = bench::bench_size(100, 20);
  auto [scene, initial] = cluster_scene(bench::particle_cluster(n), ClusterBody::sphere);
  scene.elements = {UniformGravity{standard_gravity(), {}}};
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  const auto faults_of_run = [&](std::int64_t run_steps) {
    malloc_trim(0);
    const long before = minor_faults();
    benchmark::DoNotOptimize(simulate(compiled, initial, run_options(run_steps)));
    return minor_faults() - before;
  };
  long after_first = 0;
  for (auto _ : state) after_first = faults_of_run(steps + 1) - faults_of_run(1);
  state.counters["faults_per_step"] = static_cast<double>(after_first) / static_cast<double>(steps);
}

// ---- 4: one free body as a scene vs simulate of the body ----------------------------------------------
std::int64_t one_body_steps() { return bench::bench_size(200000, 2000); }

RigidBody principal_body() { return RigidBody(1.0, Eigen::Vector3d(1.0, 2.0, 3.0)); }
RigidBodyState spinning() {
  RigidBodyState s;
  s.w_B = w0;
  return s;
}

void body_rigid_body(benchmark::State& state) {
  const RigidBody body = principal_body();
  const SimulationOptions o = run_options(one_body_steps());
  for (auto _ : state) benchmark::DoNotOptimize(simulate(body, spinning(), o));
  state.SetItemsProcessed(state.iterations() * o.steps);
}

// `zero_drag`: declare a Drag with zero coefficients, which takes the scene off the one-body fast path
// onto the generic SceneModel (the same motion).
void scene_rigid_body(benchmark::State& state, bool zero_drag) {
  Scene scene;
  scene.bodies.emplace_back(principal_body());
  if (zero_drag) scene.elements.emplace_back(Drag{});
  const std::vector<BodyState> initial{spinning()};
  const SimulationOptions o = run_options(one_body_steps());
  for (auto _ : state) benchmark::DoNotOptimize(simulate(scene, initial, o));
  state.SetItemsProcessed(state.iterations() * o.steps);
}
void scene_rigid_body_fast(benchmark::State& state) { scene_rigid_body(state, false); }
void scene_rigid_body_generic(benchmark::State& state) { scene_rigid_body(state, true); }

const ParticleState moving_particle{Eigen::Vector3d::Zero(), Eigen::Vector3d(1.0, 2.0, 3.0)};

void body_particle(benchmark::State& state) {
  const Particle particle(2.0);
  const SimulationOptions o = run_options(one_body_steps());
  for (auto _ : state) benchmark::DoNotOptimize(simulate(particle, moving_particle, o));
  state.SetItemsProcessed(state.iterations() * o.steps);
}

void scene_particle(benchmark::State& state) {
  Scene scene;
  scene.bodies.emplace_back(Particle(2.0));
  const std::vector<BodyState> initial{moving_particle};
  const SimulationOptions o = run_options(one_body_steps());
  for (auto _ : state) benchmark::DoNotOptimize(simulate(scene, initial, o));
  state.SetItemsProcessed(state.iterations() * o.steps);
}

// ---- 5: the marginal cost of each declared term ---------------------------------------------------
constexpr int term_bodies = 10;
std::int64_t term_steps() { return bench::bench_size(20000, 500); }

// ns per body and evaluation of each term case, from the thread's CPU clock (as the ratio lines, which
// use Google Benchmark's CPU time; the fastest iteration), printed as "marginal" lines (with − without
// the term) when the program ends.
class MarginalReport {
 public:
  void record(const std::string& name, double ns) {
    auto [it, fresh] = ns_.emplace(name, ns);
    if (!fresh) it->second = std::min(it->second, ns);
  }
  ~MarginalReport() {
    const auto base = ns_.find("none");
    if (base == ns_.end()) return;
    for (const auto& [name, ns] : ns_)
      if (name != "none")
        std::printf("marginal term_%s/%d: %.2f ns per term per body-evaluation (with %.2f, without %.2f)\n",
                    name.c_str(), term_bodies, ns - base->second, ns, base->second);
    std::fflush(stdout);
  }

 private:
  std::map<std::string, double> ns_;
};
MarginalReport marginal_report;

double thread_cpu_ns() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return 1e9 * static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec);
}

// 10 rigid bodies (I = diag(1, 2, 3) kg m², 1 kg) in a row 1 m apart, 7000 km from the origin (an
// attractor there), spinning and moving; one element added to the empty scene by `add`.
template <class Add, class... Custom>
void term_case(benchmark::State& state, const std::string& name, Add add, const CustomForce<Custom>&... custom) {
  Scene scene;
  std::vector<BodyState> initial;
  for (int i = 0; i < term_bodies; ++i) {
    scene.bodies.emplace_back(principal_body());
    RigidBodyState s = spinning();
    s.p_W = Eigen::Vector3d(7.0e6 + i, 0.0, 0.0);
    s.v_W = Eigen::Vector3d(0.0, 7.5e3, 0.1 * i);
    initial.push_back(s);
  }
  add(scene);
  const SimulationOptions o = run_options(term_steps());
  const double evaluations = 4.0 * term_bodies * o.steps;  // per iteration
  for (auto _ : state) {
    const double start = thread_cpu_ns();
    benchmark::DoNotOptimize(simulate(scene, initial, o, custom...));
    marginal_report.record(name, (thread_cpu_ns() - start) / evaluations);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(evaluations));
}

void term_none(benchmark::State& state) {
  term_case(state, "none", [](Scene&) {});
}
void term_uniform_gravity(benchmark::State& state) {
  term_case(state, "uniform_gravity", [](Scene& s) { s.elements.emplace_back(UniformGravity{standard_gravity(), {}}); });
}
void term_point_mass_gravity(benchmark::State& state) {
  term_case(state, "point_mass_gravity", [](Scene& s) {
    PointMassGravity g;
    g.gm = 3.986004418e14;
    s.elements.emplace_back(g);
  });
}
Drag drag(double c) {
  Drag d;
  d.linear = c, d.quadratic = c, d.angular_linear = c, d.angular_quadratic = c;
  return d;
}
void term_drag(benchmark::State& state) {
  term_case(state, "drag", [](Scene& s) { s.elements.emplace_back(drag(1e-3)); });
}
void term_drag_zero(benchmark::State& state) {
  term_case(state, "drag_zero", [](Scene& s) { s.elements.emplace_back(drag(0.0)); });
}
// one spring per body, from a point of the body to a world anchor 1 m away (so ten elements, one term
// per body as for the others)
void term_spring_to_anchor(benchmark::State& state) {
  term_case(state, "spring_to_anchor", [](Scene& s) {
    for (int i = 0; i < term_bodies; ++i) {
      SpringDamper k;
      k.body_a = i;
      k.point_a_B = Eigen::Vector3d(0.1, 0.0, 0.0);
      k.body_b = -1;
      k.point_b = Eigen::Vector3d(7.0e6 + i, 1.0, 0.0);
      k.stiffness = 10.0, k.rest_length = 0.5, k.damping = 0.1;
      s.elements.emplace_back(k);
    }
  });
}
void term_gravity_gradient(benchmark::State& state) {
  term_case(state, "gravity_gradient", [](Scene& s) {
    GravityGradient g;
    g.gm = 3.986004418e14;
    s.elements.emplace_back(g);
  });
}

// The weight m g of a 1 kg body written by the user: compiled in (CustomForce, a lambda the compiler
// can inline) and type-erased (FunctionForce, a std::function: what the Python binding uses).
void weight_of_1kg(double /*t*/, const BodyKinematics& /*body*/, int /*index*/, Eigen::Vector3d& f_W, Eigen::Vector3d& /*tau_B*/) {
  f_W = standard_gravity();
}
void term_custom_force(benchmark::State& state) {
  const auto weight = [](double t, const BodyKinematics& body, int index, Eigen::Vector3d& f_W, Eigen::Vector3d& tau_B) {
    weight_of_1kg(t, body, index, f_W, tau_B);
  };
  term_case(state, "custom_force", [](Scene&) {}, custom_force(BodyList{}, weight));
}
void term_function_force(benchmark::State& state) {
  term_case(state, "function_force", [](Scene& s) { s.elements.emplace_back(FunctionForce{{}, ForceFunction(weight_of_1kg)}); });
}

}  // namespace

BENCHMARK(nbody_particles)->Name("nbody_gravity_rk4:rigiddyn")->Apply(nbody_sizes);
BENCHMARK(nbody_packed_loop)->Name("nbody_gravity_rk4:baseline")->Apply(nbody_sizes);
BENCHMARK(nbody_particles)->Name("nbody_gravity_rk4_over_scalar_loop:rigiddyn")->Apply(size_10_100_1000);
BENCHMARK(nbody_scalar_loop)->Name("nbody_gravity_rk4_over_scalar_loop:baseline")->Apply(size_10_100_1000);
BENCHMARK(pair_sum_avx512)->Name("pair_sum_avx512_over_avx2:rigiddyn")->Apply(size_10_100_1000);
BENCHMARK(pair_sum_avx2)->Name("pair_sum_avx512_over_avx2:baseline")->Apply(size_10_100_1000);
BENCHMARK(pair_sum_avx2)->Name("pair_sum_avx2_over_portable:rigiddyn")->Apply(size_10_100_1000);
BENCHMARK(pair_sum_portable)->Name("pair_sum_avx2_over_portable:baseline")->Apply(size_10_100_1000);
BENCHMARK(pair_sum_avx2_division)->Name("pair_sum_avx2_division_over_mixed:rigiddyn")->Apply(size_10_100_1000);
BENCHMARK(pair_sum_avx2_mixed)->Name("pair_sum_avx2_division_over_mixed:baseline")->Apply(size_10_100_1000);
BENCHMARK(pair_potential)->Name("pair_potential_over_pair_sum:rigiddyn")->Apply(size_10_100_1000);
BENCHMARK(pair_sum_dispatched)->Name("pair_potential_over_pair_sum:baseline")->Apply(size_10_100_1000);
BENCHMARK(pair_potential)->Name("pair_potential_over_portable:rigiddyn")->Apply(size_10_100_1000);
BENCHMARK(pair_potential_portable)->Name("pair_potential_over_portable:baseline")->Apply(size_10_100_1000);
BENCHMARK(nbody_spheres)->Name("nbody_spheres_over_particles_rk4:rigiddyn")->Apply(size_10_100_1000);
BENCHMARK(nbody_particles)->Name("nbody_spheres_over_particles_rk4:baseline")->Apply(size_10_100_1000);
BENCHMARK(swarm_spheres)->Name("swarm_spheres_over_particles_rk4:rigiddyn")->Apply(size_10_100_1000);
BENCHMARK(swarm_particles)->Name("swarm_spheres_over_particles_rk4:baseline")->Apply(size_10_100_1000);
BENCHMARK(swarm_page_faults)->Name("swarm_spheres_page_faults_rk4/1000")->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK(scene_rigid_body_fast)->Name("scene_free_rigid_body_rk4:rigiddyn");
BENCHMARK(body_rigid_body)->Name("scene_free_rigid_body_rk4:baseline");
BENCHMARK(scene_rigid_body_generic)->Name("scene_generic_free_rigid_body_rk4:rigiddyn");
BENCHMARK(body_rigid_body)->Name("scene_generic_free_rigid_body_rk4:baseline");
BENCHMARK(scene_particle)->Name("scene_free_particle_rk4:rigiddyn");
BENCHMARK(body_particle)->Name("scene_free_particle_rk4:baseline");
BENCHMARK(term_uniform_gravity)->Name("term_uniform_gravity:rigiddyn")->Arg(term_bodies);
BENCHMARK(term_none)->Name("term_uniform_gravity:baseline")->Arg(term_bodies);
BENCHMARK(term_point_mass_gravity)->Name("term_point_mass_gravity:rigiddyn")->Arg(term_bodies);
BENCHMARK(term_none)->Name("term_point_mass_gravity:baseline")->Arg(term_bodies);
BENCHMARK(term_drag)->Name("term_drag:rigiddyn")->Arg(term_bodies);
BENCHMARK(term_none)->Name("term_drag:baseline")->Arg(term_bodies);
BENCHMARK(term_spring_to_anchor)->Name("term_spring_to_anchor:rigiddyn")->Arg(term_bodies);
BENCHMARK(term_none)->Name("term_spring_to_anchor:baseline")->Arg(term_bodies);
BENCHMARK(term_gravity_gradient)->Name("term_gravity_gradient:rigiddyn")->Arg(term_bodies);
BENCHMARK(term_none)->Name("term_gravity_gradient:baseline")->Arg(term_bodies);
BENCHMARK(term_custom_force)->Name("term_custom_force:rigiddyn")->Arg(term_bodies);
BENCHMARK(term_none)->Name("term_custom_force:baseline")->Arg(term_bodies);
BENCHMARK(term_function_force)->Name("term_function_force:rigiddyn")->Arg(term_bodies);
BENCHMARK(term_none)->Name("term_function_force:baseline")->Arg(term_bodies);
BENCHMARK(term_drag_zero)->Name("term_drag_zero:rigiddyn")->Arg(term_bodies);
BENCHMARK(term_none)->Name("term_drag_zero:baseline")->Arg(term_bodies);
BENCHMARK(term_drag_zero)->Name("term_drag_zero_over_drag:rigiddyn")->Arg(term_bodies);
BENCHMARK(term_drag)->Name("term_drag_zero_over_drag:baseline")->Arg(term_bodies);
