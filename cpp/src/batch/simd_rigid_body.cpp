// simulate_batch_simd (batch/simd_rigid_body.hpp): RK4 on blocks of L samples in structure-of-arrays form.
// Each block gathers its samples' constants and states into lanes (a lane type V holds one coordinate of L
// samples: an Eigen::Array<double, L, 1> or a generic vector, see SimdLanes), steps them together between
// records with the per-sample arithmetic written once on V, and scatters a record of each lane into its
// sample's rows. A block that is not full (N not a multiple of L) fills its spare lanes with copies of its
// last sample, which are stepped and never written.
//
// Eigen's expression evaluation (operator=, packet access) is forced inline in this translation unit (the
// define below, before any Eigen header): GCC 12 otherwise outlines the assignments of lane expressions from
// the stepping loop ("call is unlikely and code size would grow"), measured 1.5-2x SLOWER than the scalar
// hand loop instead of 2.2x faster. It changes inlining decisions only, never an operation. The sanitizer
// build (RIGIDDYN_SANITIZE_BUILD, CMakeLists.txt) leaves it out, and the clones below: under ASan's
// instrumentation they made this file take ~6 minutes to compile, and the sanitizers check memory, not speed.
#ifndef RIGIDDYN_SANITIZE_BUILD
#define EIGEN_STRONG_INLINE inline __attribute__((always_inline))
#endif
#include "rigiddyn/batch/simd_rigid_body.hpp"

#include "rigiddyn/batch/parallel_for.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/integrators/rk4.hpp"  // rk4_tableau
#include "rigiddyn/models/euler_equations.hpp"
#include "rigiddyn/simulate/run_loop.hpp"  // RIGIDDYN_NOINLINE
#include "rigiddyn/vector_instructions.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace rigiddyn {

namespace {

template <int L>
using Lanes = Eigen::Array<double, L, 1>;

// Lanes as generic vectors of the compiler (GCC/Clang vector_size): element-wise + − × / like the arrays,
// compiled to 256-bit instructions in the AVX2 clone of the stepping loop (Eigen's arrays keep the SSE2
// packets the library is compiled for) and to SSE2 instructions in the default clone. Other compilers: arrays.
#if defined(__GNUC__) || defined(__clang__)
typedef double VectorLanes4 __attribute__((vector_size(4 * sizeof(double))));
typedef double VectorLanes8 __attribute__((vector_size(8 * sizeof(double))));
#else
using VectorLanes4 = Lanes<4>;
using VectorLanes8 = Lanes<8>;
#endif

// The stepping loop compiled three times, for AVX-512F, for AVX2 and for the x86-64 baseline, the one to run chosen
// when the library is loaded (GCC function multiversioning, glibc's ifunc). AVX2 does not include FMA and this file
// is compiled without contracting a product and a sum into one (-ffp-contract=off: AVX-512F has FMA), so every clone
// rounds every operation as the scalar path does (the tests hold for all). Measured (bench/bench_simd.cpp, one core,
// per sample-step against the scalar hand loop): vector8 5.8x in the AVX-512 clone, vector4 3.4-3.6x in the AVX2
// clone, 2.2x in the default one; Eigen's arrays 2.2x in all (their packets are fixed at SSE2 when the library is
// compiled).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && !defined(RIGIDDYN_SANITIZE_BUILD)
#define RIGIDDYN_SIMD_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define RIGIDDYN_SIMD_CLONES
#endif

// The number of samples a lane type holds.
template <class V>
inline constexpr int lanes_in = static_cast<int>(sizeof(V) / sizeof(double));

// x ← 1/sqrt(x), lane by lane (in place: a generic vector returned by value would change the ABI)
template <int L>
RIGIDDYN_ALWAYS_INLINE void inverse_sqrt_in_place(Lanes<L>& x) { x = 1.0 / x.sqrt(); }
template <class V>
RIGIDDYN_ALWAYS_INLINE void inverse_sqrt_in_place(V& x) {
  for (int l = 0; l < lanes_in<V>; ++l) x[l] = 1.0 / std::sqrt(x[l]);
}

// ---- one sample's constants, prepared once as the scalar path prepares them --------------------------------

struct Sample {
  double mass;                // [kg]
  double inverse_mass;        // 1/m [1/kg]
  double dt;                  // [s]
  FullEuler euler;            // I about the centre of mass in B and I⁻¹ (FullEuler's, so the same inverse)
  EulerForm form;             // the form simulate uses (its records' I ω come from it)
  SphericalEuler spherical;   // I = s 1 with s = trace(I)/3, as with_euler_form builds it
  PrincipalEuler principal;   // diag(I)
  Eigen::Vector3d f_W;        // f_W + m g_W [N] in W
  Eigen::Vector3d tau_B;      // [N m] in B
  Eigen::Vector3d g_W;        // [m/s²] in W
  bool loaded;                // f_W + m g_W or tau_B non-zero: the work and v̇ need computing
  RigidBodyCoordinates y0;    // the initial coordinates (q normalised)

  // h_B = I ω_B [kg m²/s] by the form simulate uses, so that records match its records bitwise
  Eigen::Vector3d momentum(const Eigen::Vector3d& w) const {
    switch (form) {
      case EulerForm::spherical: return spherical.momentum(w);
      case EulerForm::principal: return principal.momentum(w);
      case EulerForm::full: break;
    }
    return euler.momentum(w);
  }
};

// ---- the lane arithmetic: one expression per coordinate, each on L samples at once ------------------------

template <class V>
struct LaneBodies {
  V inverse_mass, half_h, h, h_6;  // 1/m, h/2, h, h/6 (h = dt [s])
  V I[3][3], I_inv[3][3];          // inertia about the centre of mass in B [kg m²] and its inverse
  V f_W[3], tau_B[3];              // force (gravity included) in W [N], torque in B [N m]
};

// y = (p_W 3, q_WB xyzw 4, v_W 3, w_B 3, work 1), as RigidBodyCoordinates, each entry L lanes
template <class V>
using LaneCoordinates = std::array<V, 14>;

// ẏ of the equations above (simd_rigid_body.hpp), full inertia. Reads y[3..12]; without loads
// (`loaded` false) leaves dy[7..9] and dy[13] unset (v̇ = 0 and Ẇ = 0 exactly: the RK4 update skips them).
template <bool loaded, class V>
RIGIDDYN_ALWAYS_INLINE void lane_rate(const LaneBodies<V>& b, const LaneCoordinates<V>& y, LaneCoordinates<V>& dy) {
  const V &x = y[3], &qy = y[4], &z = y[5], &s = y[6], &w0 = y[10], &w1 = y[11], &w2 = y[12];
  for (int i = 0; i < 3; ++i) dy[i] = y[7 + i];  // ṗ_W = v_W
  // q̇ = ½ q ⊗ (ω_B, 0) (Solà, quaternion kinematics; quat_rate_body)
  dy[3] = 0.5 * (s * w0 + qy * w2 - z * w1);
  dy[4] = 0.5 * (s * w1 + z * w0 - x * w2);
  dy[5] = 0.5 * (s * w2 + x * w1 - qy * w0);
  dy[6] = -0.5 * (x * w0 + qy * w1 + z * w2);
  // Euler's equations ω̇ = I⁻¹ (τ − ω × I ω) (Craig, "Rigid Body Dynamics" slides; FullEuler)
  V Iw[3], n[3];
  for (int i = 0; i < 3; ++i) Iw[i] = b.I[i][0] * w0 + b.I[i][1] * w1 + b.I[i][2] * w2;
  n[0] = b.tau_B[0] - (w1 * Iw[2] - w2 * Iw[1]);
  n[1] = b.tau_B[1] - (w2 * Iw[0] - w0 * Iw[2]);
  n[2] = b.tau_B[2] - (w0 * Iw[1] - w1 * Iw[0]);
  for (int i = 0; i < 3; ++i) dy[10 + i] = b.I_inv[i][0] * n[0] + b.I_inv[i][1] * n[1] + b.I_inv[i][2] * n[2];
  if constexpr (loaded) {
    for (int i = 0; i < 3; ++i) dy[7 + i] = b.inverse_mass * b.f_W[i];  // v̇_W = (f_W + m g_W)/m
    // Ẇ = f_W·v_W + τ_B·ω_B (power of a force at the centre of mass and of a torque, Craig)
    dy[13] = b.f_W[0] * y[7] + b.f_W[1] * y[8] + b.f_W[2] * y[9] + b.tau_B[0] * w0 + b.tau_B[1] * w1 + b.tau_B[2] * w2;
  }
}

// The coordinates lane_rate reads at an RK4 stage: t = y + a k (axpy), or v_W copied when v̇ = 0.
template <bool loaded, class V>
RIGIDDYN_ALWAYS_INLINE void lane_stage(const LaneCoordinates<V>& y, const V& a, const LaneCoordinates<V>& k,
                                       LaneCoordinates<V>& t) {
  for (int i = 3; i < 7; ++i) t[i] = y[i] + a * k[i];
  for (int i = 7; i < 10; ++i) {
    if constexpr (loaded) {
      t[i] = y[i] + a * k[i];
    } else {
      t[i] = y[i];
    }
  }
  for (int i = 10; i < 13; ++i) t[i] = y[i] + a * k[i];
}

// One step of classical RK4 (rk4_tableau, Rk4::step) then q ← q/|q|.
template <bool loaded, class V>
RIGIDDYN_ALWAYS_INLINE void lane_rk4_step(const LaneBodies<V>& b, LaneCoordinates<V>& y) {
  LaneCoordinates<V> k1, k2, k3, k4, t;
  lane_rate<loaded>(b, y, k1);
  lane_stage<loaded>(y, b.half_h, k1, t);  // a21 h = h/2
  lane_rate<loaded>(b, t, k2);
  lane_stage<loaded>(y, b.half_h, k2, t);  // a32 h = h/2
  lane_rate<loaded>(b, t, k3);
  lane_stage<loaded>(y, b.h, k3, t);  // a43 h = h
  lane_rate<loaded>(b, t, k4);
  // y += h/6 (k1 + 2 k2 + 2 k3 + k4), as Rk4::step writes b = (1, 2, 2, 1)/6
  for (int i = 0; i < 14; ++i) {
    if (loaded || i < 7 || (i >= 10 && i < 13)) y[i] += b.h_6 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
  }
  V inverse_norm = y[3] * y[3] + y[4] * y[4] + y[5] * y[5] + y[6] * y[6];
  inverse_sqrt_in_place(inverse_norm);
  for (int i = 3; i < 7; ++i) y[i] *= inverse_norm;
}

// n steps of one block, in two clones (RIGIDDYN_SIMD_CLONES). Out of line (RIGIDDYN_NOINLINE) so that callgrind
// can count it alone (bench/bench_simd.cpp: valgrind --tool=callgrind --toggle-collect='*lane_rk4_steps*' ...).
template <bool loaded, class V>
RIGIDDYN_SIMD_CLONES RIGIDDYN_NOINLINE void lane_rk4_steps(const LaneBodies<V>& b, LaneCoordinates<V>& y, std::int64_t n) {
  LaneCoordinates<V> z = y;  // a local copy: y reached through a reference may alias b
  for (std::int64_t s = 0; s < n; ++s) lane_rk4_step<loaded>(b, z);
  y = z;
}

// ---- the records: the scalar path's expressions per sample ----------------------------------------------------

// Writes row `row` of sample i: time t [s] and the record of the coordinates y.
void put_record(BatchTrajectory& out, std::size_t i, std::size_t row, double t, const Sample& s, const RigidBodyCoordinates& y) {
  const std::size_t r = i * out.records + row;
  const Eigen::Vector3d p_W = y.segment<3>(0), v_W = y.segment<3>(7), w_B = y.segment<3>(10);
  const Eigen::Quaterniond q_WB(y.segment<4>(3));
  const Eigen::Vector3d h_B = s.momentum(w_B);
  const double kinetic = 0.5 * s.mass * v_W.squaredNorm() + 0.5 * w_B.dot(h_B);
  const double potential = -s.mass * s.g_W.dot(p_W);
  out.t[r] = t;
  for (int k = 0; k < 3; ++k) out.p_W[3 * r + k] = p_W[k], out.v_W[3 * r + k] = v_W[k], out.w_B[3 * r + k] = w_B[k];
  for (int k = 0; k < 4; ++k) out.q_WB[4 * r + k] = q_WB.coeffs()[k];
  out.kinetic_energy[r] = kinetic;
  out.total_energy[r] = kinetic + potential;
  out.angular_momentum_norm[r] = h_B.norm();
  out.quaternion_norm_error[r] = q_WB.norm() - 1.0;
  out.work[r] = y(13);
}

// ---- one block ----------------------------------------------------------------------------------------------

// What the blocks share: the stop request, the count of finished samples, the monitor (calling thread only).
struct Control {
  const SimulationOptions& options;
  std::atomic<bool> stop{false};
  std::atomic<std::size_t> samples_done{0};

  // options.monitor with the samples done (calling thread only); true asks every block to stop
  void ask_monitor() {
    if (options.monitor && !stop.load(std::memory_order_relaxed) &&
        options.monitor(static_cast<std::int64_t>(samples_done.load(std::memory_order_relaxed)))) {
      stop = true;
    }
  }
};

template <class V>
void gather(const std::vector<Sample>& samples, std::size_t first, LaneBodies<V>& b, LaneCoordinates<V>& y) {
  using namespace rk4_tableau;
  for (int l = 0; l < lanes_in<V>; ++l) {
    const Sample& s = samples[std::min(first + l, samples.size() - 1)];  // spare lanes: the last sample again
    b.inverse_mass[l] = s.inverse_mass;
    b.h[l] = a43 * s.dt;
    b.half_h[l] = a21 * s.dt;  // = a32 h
    b.h_6[l] = s.dt / 6.0;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) b.I[r][c][l] = s.euler.inertia(r, c), b.I_inv[r][c][l] = s.euler.inverse_inertia(r, c);
      b.f_W[r][l] = s.f_W[r];
      b.tau_B[r][l] = s.tau_B[r];
    }
    for (int k = 0; k < 14; ++k) y[k][l] = s.y0[k];
  }
}

// The records of the block's lanes at step `step` (row `row`); lanes whose state is non-finite stop (diverged).
template <class V>
void record_lanes(const std::vector<Sample>& samples, std::size_t first, int used, const LaneCoordinates<V>& y,
                  std::int64_t step, std::size_t row, std::array<bool, lanes_in<V>>& active, BatchTrajectory& out,
                  const SimulationOptions& o) {
  for (int l = 0; l < used; ++l) {
    if (!active[l]) continue;
    const std::size_t i = first + l;
    RigidBodyCoordinates yl;
    for (int k = 0; k < 14; ++k) yl[k] = y[k][l];
    put_record(out, i, row, o.t0 + static_cast<double>(step) * samples[i].dt, samples[i], yl);  // grid_time
    out.filled[i] = static_cast<std::int64_t>(row) + 1;
    if (!yl.allFinite()) active[l] = false, out.diverged[i] = 1;
  }
}

// Runs the samples [first, first + L) ∩ [0, N) to the end (or to a stop) and writes their rows.
template <class V, bool loaded>
void run_block(const std::vector<Sample>& samples, std::size_t first, Control& control, bool calling_thread,
               BatchTrajectory& out) {
  constexpr int L = lanes_in<V>;
  const SimulationOptions& o = control.options;
  const int used = static_cast<int>(std::min<std::size_t>(L, samples.size() - first));
  LaneBodies<V> b;
  LaneCoordinates<V> y;
  gather(samples, first, b, y);
  std::array<bool, L> active{};
  for (int l = 0; l < used; ++l) active[l] = true;
  record_lanes<V>(samples, first, used, y, 0, 0, active, out, o);
  MonitorPace pace;  // every block checks the stop request at this pace; the calling thread's asks the monitor
  std::int64_t i = 0, next_monitor = pace.interval();
  std::size_t row = 0;
  const auto any_active = [&] { return std::any_of(active.begin(), active.begin() + used, [](bool a) { return a; }); };
  while (i < o.steps && any_active() && !control.stop.load(std::memory_order_relaxed)) {
    const std::int64_t next_record = std::min(o.steps, (i / o.record_every + 1) * o.record_every);
    const std::int64_t until = std::min(next_record, next_monitor);
    lane_rk4_steps<loaded>(b, y, until - i);
    i = until;
    if (i == next_record) record_lanes<V>(samples, first, used, y, i, ++row, active, out, o);
    if (i == next_monitor) {
      const bool stop = pace.check(
          [&](std::int64_t) {
            if (calling_thread) control.ask_monitor();
            return control.stop.load(std::memory_order_relaxed);
          },
          i);
      if (stop) break;
      next_monitor = i + std::min(pace.interval(), std::numeric_limits<std::int64_t>::max() - i);
    }
  }
  control.samples_done += static_cast<std::size_t>(used);
}

template <class V>
void run_block(const std::vector<Sample>& samples, std::size_t first, Control& control, bool calling_thread,
               BatchTrajectory& out) {
  bool loaded = false;
  for (std::size_t i = first; i < std::min(first + lanes_in<V>, samples.size()); ++i) loaded = loaded || samples[i].loaded;
  if (loaded) {
    run_block<V, true>(samples, first, control, calling_thread, out);
  } else {
    run_block<V, false>(samples, first, control, calling_thread, out);
  }
}

// ---- input ------------------------------------------------------------------------------------------------

// f() with "sample <i>: " before the message of the std::invalid_argument it throws
template <class F>
auto for_sample(std::size_t i, F&& f) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("sample " + std::to_string(i) + ": " + e.what());
  }
}

// A per-sample vector has 0 (the common value) or N entries, else std::invalid_argument naming `name`.
void require_per_sample_size(std::size_t size, std::size_t n, const std::string& name) {
  if (size != 0 && size != n) {
    throw std::invalid_argument(name + ": expected 0 (the common value) or " + std::to_string(n) +
                                " (one per sample of initial) values, got " + std::to_string(size));
  }
}

// The constant loads the SIMD path takes: every load without a time window, summing to a force in W and a
// torque in B. Returns their sum (loads_at, as the scalar path sums them).
ComLoads constant_loads(const std::vector<AppliedLoad>& schedule, double t0) {
  check_loads(schedule);
  for (std::size_t k = 0; k < schedule.size(); ++k) {
    if (has_time_window({schedule[k]})) {
      throw std::invalid_argument("loads: expected loads without a time window (the SIMD path takes constant loads), got loads[" +
                                  std::to_string(k) + "] active on [" + format_value(schedule[k].t_start) + ", " +
                                  format_value(schedule[k].t_end) + ") s");
    }
  }
  const ComLoads sum = loads_at(schedule, t0);
  if (!(sum.f_B.isZero(0.0) && sum.tau_W.isZero(0.0))) {
    // each load's part that turns with the body, under its own frame: a torque of a world-frame load, a force
    // of a body-frame one
    std::string got;
    for (std::size_t k = 0; k < schedule.size(); ++k) {
      const bool world = schedule[k].frame == Frame::world;
      const Eigen::Vector3d& part = world ? schedule[k].torque : schedule[k].force;
      if (part.isZero(0.0)) continue;
      got += (got.empty() ? "" : " and ") + ("loads[" + std::to_string(k) + "]") +
             (world ? " (frame 'world') with a torque in W of " + format_value(part.transpose()) + " N m"
                    : " (frame 'body') with a force in B of " + format_value(part.transpose()) + " N");
    }
    throw std::invalid_argument("loads: expected forces in W and torques in B (the SIMD path takes no torque in W nor "
                                "force in B: they turn with the body), got " + got);
  }
  return sum;
}

Sample make_sample(const RigidBody& body, const RigidBodyState& initial, double dt, const Eigen::Vector3d& g_W,
                   const ComLoads& loads) {
  require_positive(dt, "dt");
  require_finite(g_W, "gravity");
  const Eigen::Matrix3d& I = body.inertia_com();
  Sample s{body.mass(),
           1.0 / body.mass(),
           dt,
           FullEuler(I),
           body.euler_form(),
           SphericalEuler(I.trace() / 3.0),
           PrincipalEuler(I.diagonal()),
           loads.f_W + body.mass() * g_W,
           loads.tau_B,
           g_W,
           false,
           to_coordinates(checked_state(initial, "initial"))};
  s.loaded = !(s.f_W.isZero(0.0) && s.tau_B.isZero(0.0));
  return s;
}

// Every check before any step, then the samples' constants.
std::vector<Sample> prepare(const std::vector<RigidBody>& bodies, const std::vector<RigidBodyState>& initial,
                            const SimulationOptions& o, const BatchParameters& per_sample, int threads, SimdLanes lanes) {
  const std::size_t n = initial.size();
  if (threads < 1) throw_invalid("threads", "an integer >= 1", threads);
  lane_count(lanes);  // throws for a value outside SimdLanes
  if (o.method != Method::rk4) {
    throw std::invalid_argument("method: expected rk4 (the SIMD path runs RK4 only), got " + method_info(o.method).name);
  }
  if (n == 0) throw std::invalid_argument("initial: expected at least one sample, got 0");
  if (bodies.size() != 1 && bodies.size() != n) {
    throw std::invalid_argument("bodies: expected 1 (shared) or " + std::to_string(n) + " (one per sample of initial) bodies, got " +
                                std::to_string(bodies.size()));
  }
  require_per_sample_size(per_sample.dt.size(), n, "dt");
  require_per_sample_size(per_sample.gravity_W.size(), n, "gravity");
  require_per_sample_size(per_sample.loads.size(), n, "loads");
  if (o.steps < 0) throw_invalid("steps", "an integer >= 0", o.steps);
  if (o.record_every < 1) throw_invalid("record_every", "an integer >= 1", o.record_every);
  require_finite(o.t0, "t0");
  const ComLoads common_loads = per_sample.loads.empty() ? constant_loads(o.loads, o.t0) : ComLoads{};
  std::vector<Sample> samples;
  samples.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    samples.push_back(for_sample(i, [&] {
      const ComLoads loads = per_sample.loads.empty() ? common_loads : constant_loads(per_sample.loads[i], o.t0);
      return make_sample(bodies[bodies.size() == 1 ? 0 : i], initial[i], per_sample.dt.empty() ? o.dt : per_sample.dt[i],
                         per_sample.gravity_W.empty() ? o.gravity_W : per_sample.gravity_W[i], loads);
    }));
  }
  return samples;
}

template <class V>
void run_blocks(const std::vector<Sample>& samples, int threads, Control& control, BatchTrajectory& out) {
  constexpr std::size_t L = lanes_in<V>;
  const std::size_t blocks = (samples.size() + L - 1) / L;
  // consecutive blocks per task, so that each thread writes contiguous rows
  const std::size_t per_task = std::max<std::size_t>(1, blocks / (8 * static_cast<std::size_t>(threads)));
  const std::size_t tasks = (blocks + per_task - 1) / per_task;
  control.ask_monitor();  // once before any block starts (whichever thread then takes the blocks)
  parallel_for(
      tasks, threads,
      [&](std::size_t k, int worker) {
        for (std::size_t block = k * per_task; block < std::min(blocks, (k + 1) * per_task); ++block) {
          run_block<V>(samples, block * L, control, worker == 0, out);
          if (worker == 0) control.ask_monitor();
        }
      },
      [&] { control.ask_monitor(); });
}

}  // namespace

int lane_count(SimdLanes lanes) {
  switch (lanes) {
    case SimdLanes::eigen2: return 2;
    case SimdLanes::eigen4: case SimdLanes::vector4: return 4;
    case SimdLanes::eigen8: case SimdLanes::vector8: return 8;
  }
  throw_invalid("lanes", "a rigiddyn::SimdLanes", static_cast<int>(lanes));
}

SimdLanes simd_default_lanes() { return cpu_has_avx512() ? SimdLanes::vector8 : SimdLanes::vector4; }

BatchTrajectory simulate_batch_simd(const std::vector<RigidBody>& bodies, const std::vector<RigidBodyState>& initial,
                                    const SimulationOptions& common, const BatchParameters& per_sample, int threads,
                                    SimdLanes lanes) {
  const std::vector<Sample> samples = prepare(bodies, initial, common, per_sample, threads, lanes);
  BatchTrajectory out = empty_batch(samples.size(), batch_record_count(common.steps, common.record_every));
  Control control{common};
  const auto start = std::chrono::steady_clock::now();
  switch (lanes) {
    case SimdLanes::eigen2: run_blocks<Lanes<2>>(samples, threads, control, out); break;
    case SimdLanes::eigen4: run_blocks<Lanes<4>>(samples, threads, control, out); break;
    case SimdLanes::eigen8: run_blocks<Lanes<8>>(samples, threads, control, out); break;
    case SimdLanes::vector4: run_blocks<VectorLanes4>(samples, threads, control, out); break;
    case SimdLanes::vector8: run_blocks<VectorLanes8>(samples, threads, control, out); break;
  }
  out.elapsed_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.interrupted = control.stop;
  return out;
}

}  // namespace rigiddyn
