// Bodies about a fixed point, performance: the fast model of one pivoted body
// (scene/fast/pivoted_body_model.hpp) stepped by RK4 next to a hand-written RK4 loop of the same equations
// in the same run; target ≤ 1.2×.
//   heavy_top_rk4      the symmetric heavy top under gravity (PrincipalEuler, c on the axis): per step
//                      the model's Rk4::step vs the loop below, both giving q_WB, ω_B and the work of
//                      gravity (the loop skips t and the loads' work, which the model carries: 10 vs 8
//                      coordinates, the model's cost).
//   heavy_top_full_rk4 the same top in a turned body frame (FullEuler: products of inertia about O).
// The loop checks that it integrates the same motion as the model (|Δq|, |Δω| after its steps below 1e-12)
// before it is timed. ctest runs it with RIGIDDYN_BENCH_SMALL=1 (fewer steps).
// Callgrind (instructions per step, machine-independent): the loops are the noinline functions
// *steps_rigiddyn* and *steps_baseline*, e.g.
//   valgrind --tool=callgrind --toggle-collect='*steps_rigiddyn*' --toggle-collect='*steps_baseline*' \
//     build/<dir>/bench/bench_pivoted --benchmark_filter=heavy_top_rk4 --benchmark_min_time=0.01
//   callgrind_annotate --inclusive=yes callgrind.out.<pid> | grep steps_
// (Ir of each function / (its calls × steps per call)).
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "rigiddyn/integrators/rk4.hpp"
#include "rigiddyn/scene/fast/pivoted_body_model.hpp"

#include <cmath>
#include <cstdint>

namespace {

using namespace rigiddyn;

constexpr double kH = 1e-3;         // step [s]
constexpr double kMass = 1.0;       // [kg]
constexpr double kD = 0.2;          // centre of mass up the axis from the tip [m]
const Eigen::Vector3d kMoments(0.05, 0.05, 0.08);  // about C [kg m²]
const Eigen::Vector3d kG(0.0, 0.0, -9.81);

std::int64_t steps() { return bench::bench_size(200000, 2000); }

const Eigen::Matrix3d& turn() {
  static const Eigen::Matrix3d R = Eigen::AngleAxisd(0.6, Eigen::Vector3d(1.0, 2.0, -1.0).normalized()).toRotationMatrix();
  return R;
}

// the top, in its principal frame or turned by R (B = R-turned principal frame)
PivotedBody top(const Eigen::Matrix3d& R) {
  return PivotedBody(RigidBody(kMass, Eigen::Matrix3d(R * kMoments.asDiagonal() * R.transpose())), R * Eigen::Vector3d(0.0, 0.0, kD));
}
PivotedBodyState top_state(const Eigen::Matrix3d& R) {
  PivotedBodyState s;
  s.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX())) * Eigen::Quaterniond(R.transpose());
  s.w_B = R * Eigen::Vector3d(0.5, 0.0, 12.0);
  return s;
}

// ---- the hand-written loop ---------------------------------------------------------------------------
// y = (q_WB x y z w, ω_B, work of gravity): q̇ = ½ q ⊗ (ω, 0), I_O ω̇ + ω × I_O ω = c × m R(q̂)ᵀ g,
// Ẇ = τ·ω, with q̂ = q/|q| in the torque (the model's unit attitude); RK4, q renormalised after the step.
struct LoopTop {
  double I[9], I_inv[9];  // I_O and its inverse, row-major [kg m²]
  double c[3];            // p_OC_B [m]
  double mg[3];           // m g_W [N]
};

LoopTop loop_top(const PivotedBody& body) {
  LoopTop t;
  const Eigen::Matrix3d inverse = body.inertia_O().inverse();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) t.I[3 * i + j] = body.inertia_O()(i, j), t.I_inv[3 * i + j] = inverse(i, j);
    t.c[i] = body.p_OC_B()[i], t.mg[i] = body.mass() * kG[i];
  }
  return t;
}

// dy = f(y) for the principal (diagonal I) or full form
template <bool principal>
inline void loop_rate(const LoopTop& t, const double* y, double* dy) {
  const double x = y[0], yy = y[1], z = y[2], s = y[3], w0 = y[4], w1 = y[5], w2 = y[6];
  const double n = 1.0 / std::sqrt(x * x + yy * yy + z * z + s * s);
  const double ux = n * x, uy = n * yy, uz = n * z, us = n * s;
  // g_B = R(q̂)ᵀ m g = v − 2 s (u × v) + 2 u × (u × v)
  const double* v = t.mg;
  const double a0 = uy * v[2] - uz * v[1], a1 = uz * v[0] - ux * v[2], a2 = ux * v[1] - uy * v[0];
  const double b0 = uy * a2 - uz * a1, b1 = uz * a0 - ux * a2, b2 = ux * a1 - uy * a0;
  const double g0 = v[0] - 2.0 * us * a0 + 2.0 * b0, g1 = v[1] - 2.0 * us * a1 + 2.0 * b1, g2 = v[2] - 2.0 * us * a2 + 2.0 * b2;
  // τ = c × g_B
  const double t0 = t.c[1] * g2 - t.c[2] * g1, t1 = t.c[2] * g0 - t.c[0] * g2, t2 = t.c[0] * g1 - t.c[1] * g0;
  if constexpr (principal) {
    const double *I = t.I, *J = t.I_inv;
    dy[4] = J[0] * (t0 + (I[4] - I[8]) * w1 * w2);
    dy[5] = J[4] * (t1 + (I[8] - I[0]) * w2 * w0);
    dy[6] = J[8] * (t2 + (I[0] - I[4]) * w0 * w1);
  } else {
    const double* I = t.I;
    const double h0 = I[0] * w0 + I[1] * w1 + I[2] * w2, h1 = I[3] * w0 + I[4] * w1 + I[5] * w2, h2 = I[6] * w0 + I[7] * w1 + I[8] * w2;
    const double r0 = t0 - (w1 * h2 - w2 * h1), r1 = t1 - (w2 * h0 - w0 * h2), r2 = t2 - (w0 * h1 - w1 * h0);
    const double* J = t.I_inv;
    dy[4] = J[0] * r0 + J[1] * r1 + J[2] * r2;
    dy[5] = J[3] * r0 + J[4] * r1 + J[5] * r2;
    dy[6] = J[6] * r0 + J[7] * r1 + J[8] * r2;
  }
  dy[0] = 0.5 * (s * w0 + yy * w2 - z * w1);
  dy[1] = 0.5 * (s * w1 + z * w0 - x * w2);
  dy[2] = 0.5 * (s * w2 + x * w1 - yy * w0);
  dy[3] = -0.5 * (x * w0 + yy * w1 + z * w2);
  dy[7] = t0 * w0 + t1 * w1 + t2 * w2;
}

template <bool principal>
BENCH_NOINLINE void steps_baseline(const LoopTop& t, double* y, double h, std::int64_t n) {
  double k1[8], k2[8], k3[8], k4[8], s[8];
  for (std::int64_t i = 0; i < n; ++i) {
    loop_rate<principal>(t, y, k1);
    for (int j = 0; j < 8; ++j) s[j] = y[j] + 0.5 * h * k1[j];
    loop_rate<principal>(t, s, k2);
    for (int j = 0; j < 8; ++j) s[j] = y[j] + 0.5 * h * k2[j];
    loop_rate<principal>(t, s, k3);
    for (int j = 0; j < 8; ++j) s[j] = y[j] + h * k3[j];
    loop_rate<principal>(t, s, k4);
    for (int j = 0; j < 8; ++j) y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
    const double inverse_norm = 1.0 / std::sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2] + y[3] * y[3]);
    for (int j = 0; j < 4; ++j) y[j] *= inverse_norm;
  }
}

void loop_initial(const PivotedBodyState& s, double* y) {
  for (int j = 0; j < 4; ++j) y[j] = s.q_WB.coeffs()[j];
  for (int j = 0; j < 3; ++j) y[4 + j] = s.w_B[j];
  y[7] = 0.0;
}

// ---- the model ---------------------------------------------------------------------------------------
template <class Euler>
BENCH_NOINLINE void steps_rigiddyn(const PivotedBodyModel<Euler>& model, typename PivotedBodyModel<Euler>::Coordinates& y,
                                   double h, std::int64_t n) {
  auto work = workspace<Rk4>(model, y);
  for (std::int64_t i = 0; i < n; ++i) Rk4::step(model, y, h, work);
}

template <class Euler>
PivotedBodyModel<Euler> model_of(const PivotedBody& body) {
  return PivotedBodyModel<Euler>(body, kG, 0, {}, -1, 1);
}

template <class Euler>
void top_rigiddyn(benchmark::State& state, const Eigen::Matrix3d& R) {
  const std::int64_t n = steps();
  const PivotedBodyModel<Euler> model = model_of<Euler>(top(R));
  for (auto _ : state) {
    auto y = PivotedBodyModel<Euler>::coordinates(top_state(R), 0.0);
    steps_rigiddyn(model, y, kH, n);
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * n);
}

// The largest difference in q and ω between the loop and the model after 1000 steps: the same
// equations, rounded in other orders (≲ 1000 steps × 1e-15 amplified by the flow over 1 s).
template <class Euler, bool principal>
double loop_mismatch(const Eigen::Matrix3d& R) {
  const PivotedBodyModel<Euler> model = model_of<Euler>(top(R));
  auto y = PivotedBodyModel<Euler>::coordinates(top_state(R), 0.0);
  steps_rigiddyn(model, y, kH, 1000);
  const LoopTop t = loop_top(top(R));
  double z[8];
  loop_initial(top_state(R), z);
  steps_baseline<principal>(t, z, kH, 1000);
  double mismatch = std::abs(z[7] - y[8]) / 10.0;  // the work [J] against energies of ~10 J
  for (int j = 0; j < 7; ++j) mismatch = std::max(mismatch, std::abs(z[j] - y[j]) / (j < 4 ? 1.0 : 12.0));
  return mismatch;
}

template <class Euler, bool principal>
void top_baseline(benchmark::State& state, const Eigen::Matrix3d& R) {
  const double mismatch = loop_mismatch<Euler, principal>(R);
  state.counters["mismatch"] = mismatch;
  if (!(mismatch < 1e-12)) {
    state.SkipWithError("the hand loop and the model integrate different motions");
    return;
  }
  const std::int64_t n = steps();
  const LoopTop t = loop_top(top(R));
  for (auto _ : state) {
    double y[8];
    loop_initial(top_state(R), y);
    steps_baseline<principal>(t, y, kH, n);
    benchmark::DoNotOptimize(y);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void principal_rigiddyn(benchmark::State& state) { top_rigiddyn<PrincipalEuler>(state, Eigen::Matrix3d::Identity()); }
void principal_baseline(benchmark::State& state) { top_baseline<PrincipalEuler, true>(state, Eigen::Matrix3d::Identity()); }
void full_rigiddyn(benchmark::State& state) { top_rigiddyn<FullEuler>(state, turn()); }
void full_baseline(benchmark::State& state) { top_baseline<FullEuler, false>(state, turn()); }

}  // namespace

BENCHMARK(principal_rigiddyn)->Name("heavy_top_rk4:rigiddyn")->Unit(benchmark::kMicrosecond);
BENCHMARK(principal_baseline)->Name("heavy_top_rk4:baseline")->Unit(benchmark::kMicrosecond);
BENCHMARK(full_rigiddyn)->Name("heavy_top_full_rk4:rigiddyn")->Unit(benchmark::kMicrosecond);
BENCHMARK(full_baseline)->Name("heavy_top_full_rk4:baseline")->Unit(benchmark::kMicrosecond);
