// ns per step of every method and model, next to a hand-written loop of the same method on plain
// double arrays (the "baseline"), in the same run. Free rigid body: I = diag(1, 2, 3) (principal
// form) unless the case says full/sphere; particle and planar body under a constant/body force.
#include <benchmark/benchmark.h>

#include "bench_common.hpp"
#include "rigiddyn/scene/one_body_scene.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <cmath>
#include <type_traits>

namespace {

using namespace rigiddyn;

std::int64_t steps() { return bench::bench_size(200000, 2000); }
constexpr double h = 1e-3;
const Eigen::Vector3d w0(0.3, 2.0, 0.5);

// The baselines take their parameters (mass, inertia, forces) at run time, as the library does:
// compile-time constants would let the compiler fold the arithmetic away (a zero force component,
// a known mass), which no general loop, hand-written or not, can count on.
// A scalar goes through a volatile: benchmark 1.7's DoNotOptimize(double&) uses the asm constraint
// "+m,r", with which GCC 12 at -O2/-O3 hands back a general register that never held the double (every
// value read back as 0: the particle and planar baselines ran on zero mass). Aggregates larger than a
// pointer take DoNotOptimize's "+m" form, which is sound.
template <class T>
T at_run_time(T value) {
  if constexpr (std::is_arithmetic_v<T>) {
    volatile T v = value;
    return v;
  } else {
    benchmark::DoNotOptimize(value);
    return value;
  }
}

// The baselines' helpers are forced inline, as the library's model and integrator functions are
// (RIGIDDYN_ALWAYS_INLINE): an outlined call would make a baseline slower than plain code can be.
#define BASELINE_INLINE RIGIDDYN_ALWAYS_INLINE
#if defined(__GNUC__) || defined(__clang__)
#define BASELINE_INLINE_LAMBDA __attribute__((always_inline))
#else
#define BASELINE_INLINE_LAMBDA
#endif

// ---- hand-written baselines: state y = (p 3, q xyzw 4, v 3, w 3), I diagonal, force f/m --------
struct Raw {
  double y[13];
};
struct RawBody {
  double I[3], f_over_m[3];
};

BASELINE_INLINE void raw_rate(const RawBody& b, const double* y, double* d) {
  const double x = y[3], yy = y[4], z = y[5], s = y[6];
  const double wx = y[10], wy = y[11], wz = y[12];
  d[0] = y[7], d[1] = y[8], d[2] = y[9];
  d[3] = 0.5 * (s * wx + yy * wz - z * wy);
  d[4] = 0.5 * (s * wy + z * wx - x * wz);
  d[5] = 0.5 * (s * wz + x * wy - yy * wx);
  d[6] = -0.5 * (x * wx + yy * wy + z * wz);
  d[7] = b.f_over_m[0], d[8] = b.f_over_m[1], d[9] = b.f_over_m[2];
  d[10] = (b.I[1] - b.I[2]) * wy * wz / b.I[0];
  d[11] = (b.I[2] - b.I[0]) * wz * wx / b.I[1];
  d[12] = (b.I[0] - b.I[1]) * wx * wy / b.I[2];
}

BASELINE_INLINE void raw_normalize(double* q) {
  const double n = 1.0 / std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (int i = 0; i < 4; ++i) q[i] *= n;
}

// q ← q ⊗ exp(θ/2), θ a rotation vector
BASELINE_INLINE void raw_rotate(double* q, const double* th) {
  const double a = std::sqrt(th[0] * th[0] + th[1] * th[1] + th[2] * th[2]);
  const double k = a < 1e-8 ? 0.5 : std::sin(0.5 * a) / a, c = std::cos(0.5 * a);
  const double ex = k * th[0], ey = k * th[1], ez = k * th[2];
  const double x = q[0], y = q[1], z = q[2], s = q[3];
  q[0] = s * ex + x * c + y * ez - z * ey;
  q[1] = s * ey - x * ez + y * c + z * ex;
  q[2] = s * ez + x * ey - y * ex + z * c;
  q[3] = s * c - x * ex - y * ey - z * ez;
}

BASELINE_INLINE void raw_explicit_euler(const RawBody& b, Raw& r) {
  double d[13];
  raw_rate(b, r.y, d);
  for (int i = 0; i < 13; ++i) r.y[i] += h * d[i];
  raw_normalize(r.y + 3);
}

BASELINE_INLINE void raw_rk4(const RawBody& b, Raw& r) {
  double k1[13], k2[13], k3[13], k4[13], t[13];
  raw_rate(b, r.y, k1);
  for (int i = 0; i < 13; ++i) t[i] = r.y[i] + 0.5 * h * k1[i];
  raw_rate(b, t, k2);
  for (int i = 0; i < 13; ++i) t[i] = r.y[i] + 0.5 * h * k2[i];
  raw_rate(b, t, k3);
  for (int i = 0; i < 13; ++i) t[i] = r.y[i] + h * k3[i];
  raw_rate(b, t, k4);
  for (int i = 0; i < 13; ++i) r.y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
  raw_normalize(r.y + 3);
}

// semi-implicit Euler, explicit gyroscopic term: kick, then drift with the exponential
BASELINE_INLINE void raw_semi_implicit_euler(const RawBody& b, Raw& r) {
  double d[13];
  raw_rate(b, r.y, d);
  for (int i = 7; i < 13; ++i) r.y[i] += h * d[i];
  for (int i = 0; i < 3; ++i) r.y[i] += h * r.y[7 + i];
  const double th[3] = {h * r.y[10], h * r.y[11], h * r.y[12]};
  raw_rotate(r.y + 3, th);
  raw_normalize(r.y + 3);
}

// implicit gyroscopic term: one Newton step on I(w' - w) + h w' x I w' = 0 (3x3 solve by Cramer)
BASELINE_INLINE void raw_semi_implicit_euler_implicit(const RawBody& b, Raw& r) {
  double* w = r.y + 10;
  const double Iw[3] = {b.I[0] * w[0], b.I[1] * w[1], b.I[2] * w[2]};
  const double F[3] = {h * (w[1] * Iw[2] - w[2] * Iw[1]), h * (w[2] * Iw[0] - w[0] * Iw[2]),
                       h * (w[0] * Iw[1] - w[1] * Iw[0])};
  // J = I + h (hat(w) I - hat(I w))
  double J[3][3];
  const double W[3][3] = {{0, -w[2], w[1]}, {w[2], 0, -w[0]}, {-w[1], w[0], 0}};
  const double L[3][3] = {{0, -Iw[2], Iw[1]}, {Iw[2], 0, -Iw[0]}, {-Iw[1], Iw[0], 0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) J[i][j] = (i == j ? b.I[i] : 0.0) + h * (W[i][j] * b.I[j] - L[i][j]);
  const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                     J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
  double dx[3];
  for (int c = 0; c < 3; ++c) {
    double M[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) M[i][j] = j == c ? F[i] : J[i][j];
    dx[c] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
             M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) / det;
  }
  for (int i = 0; i < 3; ++i) w[i] -= dx[i], r.y[7 + i] += h * b.f_over_m[i];
  for (int i = 0; i < 3; ++i) r.y[i] += h * r.y[7 + i];
  const double th[3] = {h * w[0], h * w[1], h * w[2]};
  raw_rotate(r.y + 3, th);
  raw_normalize(r.y + 3);
}

// RKMK4: stages through the exponential with dexp^-1 ≈ w + ½ Θ×w + Θ×(Θ×w)/12
BASELINE_INLINE void raw_rkmk4(const RawBody& b, Raw& r) {
  double K[4][13], th[13], t[13], d[13];
  const double c[4] = {0.0, 0.5, 0.5, 1.0};
  for (int s = 0; s < 4; ++s) {
    for (int i = 0; i < 13; ++i) th[i] = s == 0 ? 0.0 : c[s] * h * K[s - 1][i];
    for (int i = 0; i < 13; ++i) t[i] = r.y[i];
    for (int i = 0; i < 3; ++i) t[i] += th[i], t[7 + i] += th[7 + i], t[10 + i] += th[10 + i];
    raw_rotate(t + 3, th + 3);
    raw_rate(b, t, d);
    for (int i = 0; i < 13; ++i) K[s][i] = d[i];
    // the rotation part of the tangent is w (t[10..12]); correct it by dexp^-1
    const double* T = th + 3;
    const double* w = t + 10;
    const double txw[3] = {T[1] * w[2] - T[2] * w[1], T[2] * w[0] - T[0] * w[2], T[0] * w[1] - T[1] * w[0]};
    const double txtxw[3] = {T[1] * txw[2] - T[2] * txw[1], T[2] * txw[0] - T[0] * txw[2], T[0] * txw[1] - T[1] * txw[0]};
    for (int i = 0; i < 3; ++i) K[s][3 + i] = w[i] + 0.5 * txw[i] + txtxw[i] / 12.0;
  }
  for (int i = 0; i < 13; ++i) th[i] = h / 6.0 * (K[0][i] + 2.0 * K[1][i] + 2.0 * K[2][i] + K[3][i]);
  for (int i = 0; i < 3; ++i) r.y[i] += th[i], r.y[7 + i] += th[7 + i], r.y[10 + i] += th[10 + i];
  raw_rotate(r.y + 3, th + 3);
  raw_normalize(r.y + 3);
}

Raw raw_initial() {
  Raw r{};
  r.y[6] = 1.0;
  r.y[10] = w0.x(), r.y[11] = w0.y(), r.y[12] = w0.z();
  return r;
}

template <void (*Step)(const RawBody&, Raw&)>
void baseline(benchmark::State& state) {
  const RawBody b = at_run_time(RawBody{{1.0, 2.0, 3.0}, {0.0, 0.0, 0.0}});
  const std::int64_t n = steps();
  for (auto _ : state) {
    Raw r = raw_initial();
    for (std::int64_t i = 0; i < n; ++i) Step(b, r);
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

// ---- rigiddyn: the library's model and integrator templates ------------------------------------
// n steps of Integrator on the layout from the body state s0, per benchmark iteration
template <class Integrator, class Layout>
void steps_of(benchmark::State& state, const Layout& layout, const BodyState& s0) {
  const std::int64_t n = steps();
  for (auto _ : state) {
    typename Layout::Coordinates y = layout.coordinates({s0}, 0.0);
    auto work = workspace<Integrator>(layout, y);
    for (std::int64_t i = 0; i < n; ++i) Integrator::step(layout, y, h, work);
    benchmark::DoNotOptimize(y);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

// The model simulate() runs for a free body (no loads, no gravity), the layout of its one-body scene, as the baselines, whose run-time zero force stands for "no loads" too.
template <class Integrator, class Euler>
void library(benchmark::State& state, const RigidBody& body) {
  RigidBodyState s0;
  s0.w_B = w0;
  using Layout = OneBodySceneModel<detail::RigidSlot<Euler, detail::FirstPlace>, OneBodyElements::none>;
  steps_of<Integrator>(state, one_body_layout_as<Layout>(body, Eigen::Vector3d::Zero(), {}), s0);
}

template <class Integrator>
void principal(benchmark::State& state) {
  library<Integrator, PrincipalEuler>(state, RigidBody(1.0, Eigen::Vector3d(1.0, 2.0, 3.0)));
}

void full_rk4(benchmark::State& state) {
  Eigen::Matrix3d I;
  I << 1.0, 0.1, 0.0, 0.1, 2.0, 0.05, 0.0, 0.05, 3.0;
  library<Rk4, FullEuler>(state, RigidBody(1.0, I, InertiaCheck::allow_unrealizable));  // the baseline's test inertia
}

// baseline for the full inertia: the same hand-written RK4 with a 3x3 inverse-inertia product
void raw_full_rk4(benchmark::State& state) {
  Eigen::Matrix3d I;
  I << 1.0, 0.1, 0.0, 0.1, 2.0, 0.05, 0.0, 0.05, 3.0;
  const Eigen::Matrix3d Iinv = I.inverse();
  double A[9], B[9];
  for (int i = 0; i < 9; ++i) A[i] = I(i / 3, i % 3), B[i] = Iinv(i / 3, i % 3);
  auto rate = [&](const double* y, double* d) BASELINE_INLINE_LAMBDA {
    const double x = y[3], yy = y[4], z = y[5], s = y[6], wx = y[10], wy = y[11], wz = y[12];
    d[0] = y[7], d[1] = y[8], d[2] = y[9];
    d[3] = 0.5 * (s * wx + yy * wz - z * wy);
    d[4] = 0.5 * (s * wy + z * wx - x * wz);
    d[5] = 0.5 * (s * wz + x * wy - yy * wx);
    d[6] = -0.5 * (x * wx + yy * wy + z * wz);
    d[7] = d[8] = d[9] = 0.0;
    const double L[3] = {A[0] * wx + A[1] * wy + A[2] * wz, A[3] * wx + A[4] * wy + A[5] * wz,
                         A[6] * wx + A[7] * wy + A[8] * wz};
    const double g[3] = {-(wy * L[2] - wz * L[1]), -(wz * L[0] - wx * L[2]), -(wx * L[1] - wy * L[0])};
    for (int i = 0; i < 3; ++i) d[10 + i] = B[3 * i] * g[0] + B[3 * i + 1] * g[1] + B[3 * i + 2] * g[2];
  };
  const std::int64_t n = steps();
  for (auto _ : state) {
    Raw r = raw_initial();
    for (std::int64_t it = 0; it < n; ++it) {
      double k1[13], k2[13], k3[13], k4[13], t[13];
      rate(r.y, k1);
      for (int i = 0; i < 13; ++i) t[i] = r.y[i] + 0.5 * h * k1[i];
      rate(t, k2);
      for (int i = 0; i < 13; ++i) t[i] = r.y[i] + 0.5 * h * k2[i];
      rate(t, k3);
      for (int i = 0; i < 13; ++i) t[i] = r.y[i] + h * k3[i];
      rate(t, k4);
      for (int i = 0; i < 13; ++i) r.y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
      raw_normalize(r.y + 3);
    }
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void sphere_rk4(benchmark::State& state) { library<Rk4, SphericalEuler>(state, RigidBody(1.0, Eigen::Vector3d(2.0, 2.0, 2.0))); }
void raw_sphere_rk4(benchmark::State& state) {
  const RawBody b = at_run_time(RawBody{{2.0, 2.0, 2.0}, {0.0, 0.0, 0.0}});  // the gyroscopic products multiply zero
  const std::int64_t n = steps();
  for (auto _ : state) {
    Raw r = raw_initial();
    for (std::int64_t i = 0; i < n; ++i) raw_rk4(b, r);
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

// ---- particle and planar body under a force (RK4) ----------------------------------------------
void particle_rk4(benchmark::State& state) {
  using Layout = OneBodySceneModel<detail::ParticleSlot<detail::FirstPlace>, OneBodyElements::gravity>;
  const Particle particle(2.0);
  steps_of<Rk4>(state, one_body_layout_as<Layout>(particle, standard_gravity(), {}),
                ParticleState{Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 2, 3)});
}
void raw_particle_rk4(benchmark::State& state) {
  const double g[3] = {at_run_time(0.0), at_run_time(0.0), at_run_time(-9.81)}, m = at_run_time(2.0);
  const std::int64_t n = steps();
  for (auto _ : state) {
    double y[7] = {0, 0, 0, 1, 2, 3, 0};
    auto rate = [&](const double* s, double* d) BASELINE_INLINE_LAMBDA {
      for (int i = 0; i < 3; ++i) d[i] = s[3 + i], d[3 + i] = g[i];
      d[6] = m * (g[0] * s[3] + g[1] * s[4] + g[2] * s[5]);
    };
    for (std::int64_t it = 0; it < n; ++it) {
      double k1[7], k2[7], k3[7], k4[7], t[7];
      rate(y, k1);
      for (int i = 0; i < 7; ++i) t[i] = y[i] + 0.5 * h * k1[i];
      rate(t, k2);
      for (int i = 0; i < 7; ++i) t[i] = y[i] + 0.5 * h * k2[i];
      rate(t, k3);
      for (int i = 0; i < 7; ++i) t[i] = y[i] + h * k3[i];
      rate(t, k4);
      for (int i = 0; i < 7; ++i) y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    benchmark::DoNotOptimize(y);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void planar_rk4(benchmark::State& state) {
  using Layout = OneBodySceneModel<detail::PlanarSlot<detail::FirstPlace>, OneBodyElements::gravity_and_loads>;
  const AppliedLoad push{Eigen::Vector3d(1.0, 0.5, 0.0), Eigen::Vector3d(0.0, 0.0, 0.2), Frame::body};
  steps_of<Rk4>(state, one_body_layout_as<Layout>(PlanarBody(2.0, 0.5), Eigen::Vector3d::Zero(), {push}),
                PlanarBodyState{Eigen::Vector2d::Zero(), 0.0, Eigen::Vector2d(1, 0), 1.0});
}
void raw_planar_rk4(benchmark::State& state) {
  const double m = at_run_time(2.0), I = at_run_time(0.5), fb[2] = {at_run_time(1.0), at_run_time(0.5)},
               nz = at_run_time(0.2);
  const std::int64_t n = steps();
  for (auto _ : state) {
    double y[7] = {0, 0, 0, 1, 0, 1, 0};
    auto rate = [&](const double* s, double* d) BASELINE_INLINE_LAMBDA {
      const double c = std::cos(s[2]), sn = std::sin(s[2]);
      const double fx = c * fb[0] - sn * fb[1], fy = sn * fb[0] + c * fb[1];
      d[0] = s[3], d[1] = s[4], d[2] = s[5], d[3] = fx / m, d[4] = fy / m, d[5] = nz / I;
      d[6] = fx * s[3] + fy * s[4] + nz * s[5];
    };
    for (std::int64_t it = 0; it < n; ++it) {
      double k1[7], k2[7], k3[7], k4[7], t[7];
      rate(y, k1);
      for (int i = 0; i < 7; ++i) t[i] = y[i] + 0.5 * h * k1[i];
      rate(t, k2);
      for (int i = 0; i < 7; ++i) t[i] = y[i] + 0.5 * h * k2[i];
      rate(t, k3);
      for (int i = 0; i < 7; ++i) t[i] = y[i] + h * k3[i];
      rate(t, k4);
      for (int i = 0; i < 7; ++i) y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    benchmark::DoNotOptimize(y);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

// ---- simulate (the public entry: checks, dispatch, recorder every 1000 steps) -------------------
void simulate_rk4(benchmark::State& state) {
  const RigidBody body(1.0, Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal().toDenseMatrix());
  RigidBodyState s0;
  s0.w_B = w0;
  SimulationOptions o;
  o.method = Method::rk4;
  o.dt = h;
  o.steps = steps();
  o.record_every = 1000;
  for (auto _ : state) benchmark::DoNotOptimize(simulate(body, s0, o));
  state.SetItemsProcessed(state.iterations() * o.steps);
}

}  // namespace

BENCHMARK(principal<ExplicitEuler>)->Name("rigid_body_explicit_euler:rigiddyn");
BENCHMARK(baseline<raw_explicit_euler>)->Name("rigid_body_explicit_euler:baseline");
BENCHMARK(principal<SemiImplicitEuler>)->Name("rigid_body_semi_implicit_euler:rigiddyn");
BENCHMARK(baseline<raw_semi_implicit_euler>)->Name("rigid_body_semi_implicit_euler:baseline");
BENCHMARK(principal<SemiImplicitEulerImplicitGyroscopic>)->Name("rigid_body_semi_implicit_euler_implicit_gyroscopic:rigiddyn");
BENCHMARK(baseline<raw_semi_implicit_euler_implicit>)->Name("rigid_body_semi_implicit_euler_implicit_gyroscopic:baseline");
BENCHMARK(principal<Rk4>)->Name("rigid_body_rk4:rigiddyn");
BENCHMARK(baseline<raw_rk4>)->Name("rigid_body_rk4:baseline");
BENCHMARK(principal<Rkmk4>)->Name("rigid_body_rkmk4:rigiddyn");
BENCHMARK(baseline<raw_rkmk4>)->Name("rigid_body_rkmk4:baseline");
BENCHMARK(full_rk4)->Name("rigid_body_full_inertia_rk4:rigiddyn");
BENCHMARK(raw_full_rk4)->Name("rigid_body_full_inertia_rk4:baseline");
BENCHMARK(sphere_rk4)->Name("rigid_body_sphere_rk4:rigiddyn");
BENCHMARK(raw_sphere_rk4)->Name("rigid_body_sphere_rk4:baseline");
BENCHMARK(particle_rk4)->Name("particle_rk4:rigiddyn");
BENCHMARK(raw_particle_rk4)->Name("particle_rk4:baseline");
BENCHMARK(planar_rk4)->Name("planar_body_rk4:rigiddyn");
BENCHMARK(raw_planar_rk4)->Name("planar_body_rk4:baseline");
BENCHMARK(simulate_rk4)->Name("simulate_rigid_body_rk4:rigiddyn");
BENCHMARK(baseline<raw_rk4>)->Name("simulate_rigid_body_rk4:baseline");
