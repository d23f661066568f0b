// SIMD across samples: RK4 on many rigid bodies at once, in structure-of-arrays
// form with one lane per sample, so that one vector instruction advances L samples by the same
// operation. The per-sample arithmetic is classical RK4 (integrators/rk4.hpp) on the Newton–Euler equations of a
// rigid body under a constant force and torque, written once on a lane type (an Eigen::Array<double, L, 1> or a
// generic vector of L doubles, SimdLanes):
//   ṗ_W = v_W,  q̇_WB = ½ q_WB ⊗ (ω_B, 0),  v̇_W = (f_W + m g_W)/m,  ω̇_B = I⁻¹ (τ_B − ω_B × I ω_B),
//   Ẇ = (f_W + m g_W)·v_W + τ_B·ω_B   (Newton–Euler about the centre of mass and the power of the loads,
//                                     Craig, "Rigid Body Dynamics" slides)
// then q renormalised after each step. The records (t, p_W, q_WB, v_W, w_B, energies, |H_G|, |q| − 1, work) are
// computed per sample by the expressions of the scalar path's records (simulate/simulate.hpp). The only differences
// from N scalar simulate(RigidBody, ...) calls (each the layout of the body's one-body scene) are round-offs: a few
// ulps per derivative evaluation (the scalar path uses the principal or spherical form of Euler's equations for a
// diagonal or isotropic inertia, this path always the full form; its operations are in their own order), carried
// by the flow (tests/cpp/test_simd_rigid_body.cpp states the bound). In the row where a sample is found non-finite,
// its non-finite entries may differ (e.g. the work of a sample without loads sharing a block with loaded ones is
// NaN there, 0 in simulate's row).
#pragma once
#include "rigiddyn/batch/batch_result.hpp"
#include "rigiddyn/batch/simulate_batch.hpp"  // BatchParameters
#include "rigiddyn/models/rigid_body.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <vector>

namespace rigiddyn {

// How the SIMD path holds its lanes (one sample per lane); the per-sample arithmetic is the same for all, and
// so are the results, bitwise (tests/cpp/test_simd_rigid_body.cpp). Measured by bench/bench_simd.cpp.
enum class SimdLanes {
  eigen2,   // Eigen::Array<double, 2, 1>: one SSE2 packet (the library is compiled for x86-64's SSE2 baseline,
  eigen4,   // Eigen::Array<double, 4, 1>  and Eigen chooses its packets when compiled, so Eigen's arrays stay
  eigen8,   // Eigen::Array<double, 8, 1>  128-bit wide whatever the machine)
  vector4,  // 4 doubles as a generic vector of the compiler (GCC/Clang vector_size): 512- or 256-bit instructions
  vector8,  // 8 doubles    in the AVX-512 or AVX2 clone of the stepping loop (target_clones, chosen at load time),
            //              SSE2 otherwise
};
// The fastest measured on this machine's instructions (bench/bench_simd.cpp, one core, per sample-step against the
// scalar hand loop): vector8 where the CPU has AVX-512F (5.8x, one 512-bit instruction per operation of 8 samples;
// vector4 3.5x there), else vector4 (3.4-3.6x with AVX2, 2.2x on SSE2 alone; eigen4 2.2x either way).
SimdLanes simd_default_lanes();
// Every SimdLanes.
inline constexpr SimdLanes simd_lane_kinds[] = {SimdLanes::eigen2, SimdLanes::eigen4, SimdLanes::eigen8, SimdLanes::vector4,
                                                SimdLanes::vector8};
// The number of samples a SimdLanes holds (2, 4 or 8); std::invalid_argument naming lanes for another value.
int lane_count(SimdLanes lanes);

// N = initial.size() RK4 runs of rigid bodies, as N calls simulate(bodies[i or 0], initial[i], options_i)
// (options_i = common with the sample's dt [s], gravity_W [m/s²] in W and loads of per_sample), computed
// lane_count(lanes) samples at a time. Returns their records stacked (batch/batch_result.hpp): every record
// of the scalar path, equal to it up to round-off (see the header comment; tests/cpp/test_simd_rigid_body.cpp
// states the bound).
//   bodies   1 (shared) or N: mass [kg] and inertia about the centre of mass in B [kg m²], any symmetric
//            positive definite inertia (products of inertia included)
//   initial  N states (p_W [m], q_WB, v_W [m/s] in W, w_B [rad/s] in B); q normalised as simulate does
//   common   method (rk4 only), dt, steps, record_every, t0, loads, gravity_W, monitor
//   per_sample  per-sample dt, gravity_W and loads (empty: common's)
//   threads  >= 1: the blocks of lane_count(lanes) samples are shared among this many threads
//   lanes    how the lanes are held (SimdLanes; the results do not depend on it)
// Loads: constant schedules only, each sample's loads summing to a force through the centre of mass in W
// and a torque in B (AppliedLoad with frame = world and zero torque, or frame = body and zero force, every
// one without a time window). A sample whose state becomes non-finite stops recording alone (diverged[i] = 1,
// filled[i] rows, NaN after, as simulate: non-finiteness is checked at records); the other samples are
// computed bitwise as without it. common.monitor, if set, is called from the calling thread only (once before
// any block starts, at the pace of simulate's calls, about every monitor_period_seconds of its blocks' steps
// (simulate/monitor_pace.hpp), after each block, and about every 10 ms while it waits for the other threads)
// with the number of samples finished; returning true stops every sample at its next check (at the same
// pace) and sets interrupted: their rows after that stay NaN, filled[i] says how many they have.
// Throws std::invalid_argument naming the argument: "method" (not rk4), "loads" (a time window, a torque in W
// or a force in B, non-finite), "bodies" / "dt" / "gravity" (a size other than 1 or N resp. 0 or N),
// "initial" (no sample), "threads" (< 1), "lanes" (not a SimdLanes), "steps", "record_every", and per sample
// "sample <i>: initial.q_WB: ...", "sample <i>: dt: ..." etc. for a bad per-sample value. Everything is
// checked before any step is taken.
BatchTrajectory simulate_batch_simd(const std::vector<RigidBody>& bodies, const std::vector<RigidBodyState>& initial,
                                    const SimulationOptions& common, const BatchParameters& per_sample, int threads,
                                    SimdLanes lanes);

// The same with simd_default_lanes() lanes.
inline BatchTrajectory simulate_batch_simd(const std::vector<RigidBody>& bodies, const std::vector<RigidBodyState>& initial,
                                           const SimulationOptions& common, const BatchParameters& per_sample, int threads) {
  return simulate_batch_simd(bodies, initial, common, per_sample, threads, simd_default_lanes());
}

}  // namespace rigiddyn
