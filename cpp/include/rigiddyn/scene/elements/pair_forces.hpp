// The direct sum of MutualGravity (mutual_gravity.hpp) over the pairs i < j of n bodies packed as columns:
//   d = p_j − p_i,   g = G m_i m_j / (|d|² + ε²)^{3/2},   f_i += g d,   f_j −= g d,
// each pair's force computed once and added to one body and subtracted from the other (Newton's third law, pair by
// pair). Three paths (vector_instructions.hpp): the portable one (two pairs per SSE2 instruction, the library's
// baseline), AVX2 + FMA (four pairs per instruction; |d|² + ε² and the sums by fused multiply–adds) and AVX-512
// (eight pairs per instruction, the same operations as AVX2's; a body's last pairs four and one at a time).
//
// The paths agree to round-off: each pair's force differs in its last bits (a fused multiply–add rounds once
// where a product and a sum round twice, and the sums of f_i add the pairs in another order), so for every body and
// component each path is within (n + 8) u Σ_j |f_ij| of the exact sum (u = 2⁻⁵³; the n terms of a sum in any order:
// n u of their absolute sum, Higham, "Accuracy and Stability of Numerical Algorithms", §4.2; 8 u for the pair's own
// rounding), and any two within twice that.
#pragma once
#include <Eigen/Core>

namespace rigiddyn::detail {

// Columns of the pair sum, n rows used (the array may be longer): 0–2 the positions x, y, z [m], 3–5 the forces
// f_x, f_y, f_z [N] (added to), 6 scratch, 7 the masses [kg]. G [m³/(kg s²)], ε² [m²].
void add_pair_forces(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);

// The three paths, callable directly (tests compare them; add_pair_forces takes the one of vector_instructions()).
// add_pair_forces_avx2_fma may be called only where cpu_has_avx2_fma(), add_pair_forces_avx512 where cpu_has_avx512().
void add_pair_forces_portable(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);
void add_pair_forces_avx2_fma(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);
void add_pair_forces_avx512(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2);

}  // namespace rigiddyn::detail
