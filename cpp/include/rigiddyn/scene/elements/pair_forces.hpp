// The direct sums of MutualGravity (mutual_gravity.hpp) over the pairs i < j of n bodies packed as columns:
//   d = p_j − p_i,   g = G m_i m_j / (|d|² + ε²)^{3/2},   f_i += g d,   f_j −= g d,
// each pair's force computed once and added to one body and subtracted from the other (Newton's third law, pair by
// pair). Three paths (vector_instructions.hpp): the portable one (two pairs per SSE2 instruction, the library's
// baseline: r² √r² and a division); AVX2 + FMA (four pairs per instruction, |d|² + ε² and the sums by fused
// multiply–adds, of each eight pairs four by the division and four by a reciprocal square root refined by Newton's
// steps, so that the divider and the multiply–add units work together, or on CPUs with a faster divider all eight
// by the division: avx2_divides_every_pair below; a body's last pairs by the division, four, then the last 1-3 as a
// block of four with its lanes beyond n off); and AVX-512 (eight pairs per instruction, all by the reciprocal square
// root, the bodies i two at a time: each block of bodies j loaded, and its forces f_j stored, once for both, a last
// block of fewer than eight with its lanes beyond n off; a last body alone, its last pairs four by the division and
// one at a time).
//
// The paths agree to round-off, each pair's force to a relative 24 u (u = 2⁻⁵³, each operation's rounding): d's
// components round once (u each, 2 u in |d|²) and |d|² + ε² four times more (three with fused multiply–adds): r² is
// within 6 u, r^−3 within 9 u. The division's g = G m_i m_j / (r² √r²) adds 5 roundings (15 u with g d's), the
// reciprocal square root's y (within 3 u of 1/√r², pair_forces.cpp) cubed 11 u and the masses 3 u (24 u with g d's,
// 22.5 u with the fused r²). The sums of f_i add the n pairs in another order on each path (n u of their absolute
// sum, Higham, "Accuracy and Stability of Numerical Algorithms", §4.2), so for every body and component each path is
// within (n + 24) u Σ_j |f_ij| of the exact sum, and any two within twice that.
//
// The potential V = −Σ_{i<j} G m_i m_j / √(|d|² + ε²) of the records runs on the same paths: each i's terms m_j / r
// summed (by the division, or as m_j y, y the reciprocal square root of r² above), times G m_i, subtracted from V. A
// term is within 7 u of m_j / r (r² within 6 u, so 1/r within 3 u, and y within 3 u of that; the division's √ and
// quotient round once each; the mass's product once), each i's sum adds at most (n − 1) u of its terms' absolute sum,
// G m_i two roundings and V's sum of the i at most (n − 1) u more: each path within (2 n + 8) u Σ_{i<j} |V_ij| of
// the exact V, and any two within twice that.
#pragma once
#include <Eigen/Core>

namespace rigiddyn::detail {

// Columns of the pair sum, n rows used (the array may be longer): 0–2 the positions x, y, z [m], 3–5 the forces
// f_x, f_y, f_z [N] (added to), 6 scratch, 7 the masses [kg]. G [m³/(kg s²)], ε² [m²]. The path of
// vector_instructions(), but for fewer than 24 bodies AVX2's in place of AVX-512's (a body's few pairs fill few blocks
// of eight: pair_forces.cpp has the figures).
void add_pair_forces(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);

// The three paths, callable directly (tests compare them; add_pair_forces takes the one of vector_instructions()).
// add_pair_forces_avx2_fma may be called only where cpu_has_avx2_fma(), add_pair_forces_avx512 where cpu_has_avx512().
void add_pair_forces_portable(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);
void add_pair_forces_avx2_fma(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);
void add_pair_forces_avx512(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);

// The AVX2 path's two forms (add_pair_forces_avx2_fma takes the one avx2_divides_every_pair says): of each eight pairs
// four by the division and four by the reciprocal square root (mixed), or all eight by the division (division); both
// within the bound above. Which is faster depends on the CPU's divider. Measured, the AVX2 pair sum at N = 1000 on one
// core (`bench_scene --benchmark_filter=pair_sum_avx2`): on Xeons with AVX-512, mixed 1.45 ns per pair against 2.0 by
// the division (docs/perf/scenes.md); on an AMD EPYC (Zen 3, whose divider is the faster), mixed 1.68-1.69 against
// 1.27-1.34 by the division, every pair by the reciprocal square root 2.40; on an Ice Lake Xeon, whose divider is
// faster than the earlier Xeons', mixed 2.0-2.8 against 1.70-1.78 by the division (the rule by vendor below then
// takes the slower form there; where AVX-512 runs, the AVX2 path runs only below 24 bodies, where they differ little).
void add_pair_forces_avx2_fma_mixed(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);
void add_pair_forces_avx2_fma_division(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);

// Whether this CPU's AVX2 path divides every pair (the form measured faster on AMD's CPUs; mixed on the others):
// fixed per process, so that a run's results are the same bits from run to run on a machine.
bool avx2_divides_every_pair();

// V [J] of the same columns (0–2 the positions, 6 scratch, 7 the masses; n rows used), the path of
// vector_instructions() from 12 bodies on (AVX-512) or 20 (AVX2), the portable one below; and the three paths,
// callable directly (on the CPUs the forces' paths need).
double pair_potential(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);
double pair_potential_portable(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);
double pair_potential_avx2_fma(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);
double pair_potential_avx512(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);

}  // namespace rigiddyn::detail
