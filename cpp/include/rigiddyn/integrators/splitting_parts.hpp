// The sub-flows the structure-preserving rigid-body methods are built from (splitting_dlm.hpp,
// yoshida4.hpp, exact_flow_kick.hpp). Each is the EXACT flow of one part of the split Newton–Euler
// equations (Craig, "Rigid Body Dynamics" slides), so a composition of them keeps what each part keeps:
//
//   loads part   ṗ = 0, q̇ = 0, m v̇ = f_W(q), I ω̇ = n_B(q)      (a model's loads_kick: v, ω move linearly)
//   free part    ṗ = v, v̇ = 0;  Euler–Poinsot ṁ = m × ω, Ṙ = R ω̂ (a model's free_flow<Rotation>)
//
// The free rotation is split once more, H = Σ m_i²/(2 I_i) over the principal axes
// (Dullweber, Leimkuhler & McLachlan 1997; McLachlan 1993; Reich 1994): the flow of one term
// H_i turns m about the principal axis e_i by −θ and the attitude about it by +θ, θ = h m_i/I_i,
// so |m|, the spatial L_W = R m and unit |q| are exact in every sub-flow (principal_axis_flow).
// Nothing here knows a model or a state layout: the kernels act on one body's quaternion and ω_B.
#pragma once
#include "rigiddyn/integrators/compensated.hpp"
#include "rigiddyn/models/euler_equations.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>

namespace rigiddyn {

// Principal axes of an inertia: moments I_P (3,) [kg m²], the principal frame P in B (q_BP, det +1;
// identity for a diagonal inertia) and the axis indices sorted by increasing moment.
struct PrincipalSplit {
  Eigen::Vector3d moments;
  Eigen::Quaterniond q_BP;
  std::array<int, 3> ascending;
};

inline std::array<int, 3> ascending_axes(const Eigen::Vector3d& I) {
  std::array<int, 3> order{0, 1, 2};
  if (I(order[1]) < I(order[0])) std::swap(order[0], order[1]);
  if (I(order[2]) < I(order[1])) std::swap(order[1], order[2]);
  if (I(order[1]) < I(order[0])) std::swap(order[0], order[1]);
  return order;
}

inline PrincipalSplit principal_split(const PrincipalEuler& e) {
  return {e.inertia, Eigen::Quaterniond::Identity(), ascending_axes(e.inertia)};
}

// A full inertia's principal frame, computed once when the FullEuler was built (principal_decomposition:
// ascending moments, R_BP diag R_BPᵀ = I to round-off for any spacing of the moments). A closed-form 3×3
// eigensolver per step (Eigen's computeDirect) was both slower and inaccurate where two moments coincide:
// for moments (1, 2, 2) in a turned frame it returned 2 ∓ 2.8e-9 and axes 1.5e-9 from orthogonal, so the
// splittings integrated another body (L_W moved 3.5e-9 in 1 s instead of a round-off walk).
inline PrincipalSplit principal_split(const FullEuler& e) { return {e.principal_moments, e.q_BP, {0, 1, 2}}; }

// q / |q| for a quaternion that is unit up to round-off (| |q|² − 1 | ≤ 1e-5), applied as an increment
// q + f q with f = 1/|q| − 1 = −d/2 + 3d²/8 + O(d³), d = |q|² − 1 from a compensated sum of squares
// (the O(d³) ≤ 3e-16 |d| is below round-off). The product q · (1/|q|) rounds 1/|q| ≈ 1 to a double near
// 1 and then each coefficient, the same way at every step of a long run: the attitude turned by a
// biased ~ε per step and the spatial L_W = R m of the splittings drifted linearly (2.8e-12 rad after
// 1e6 Yoshida steps of a tumble); d from a plain sum of squares is quantised to ε/2 and biased
// likewise (1.8e-11 rad after 1e7 steps).
RIGIDDYN_ALWAYS_INLINE Eigen::Quaterniond unit_quaternion(const Eigen::Quaterniond& q) {
  double hi, lo;
  sum_of_squares<4>(q.coeffs().data(), hi, lo);
  if (!(hi > 0.0)) return q;  // zero (or NaN): nothing to normalise
  const double d = (hi - 1.0) + lo;
  const double f = d * (-0.5 + 0.375 * d);
  Eigen::Quaterniond out;
  out.coeffs() = q.coeffs() + f * q.coeffs();
  return out;
}

// The exact flow of H_i = m_i²/(2 I_i) over h [s] (axis i of the principal frame P, moment I_i):
// m_P ← Rot(e_i, −θ) m_P, q_WP ← q_WP ⊗ Rot(e_i, θ), θ = h m_i/I_i (m_i is constant in this flow);
// `half_per_m` = h / (2 I_i) [rad/(kg m²/s)] (precomputed by the caller: no division per flow).
// m_P = m0 + dm is kept as the momentum at the start of the free rotation m0 and its change dm since
// then, and the flow adds its increment to dm, with cos θ − 1 = −2 sin²(θ/2), sin θ = 2 sin(θ/2) cos(θ/2):
//   dm_j += (cos θ − 1) m_j + sin θ m_k,  dm_k += (cos θ − 1) m_k − sin θ m_j.
// The increments round at the scale of dm, far below that of m: |m| moves only by an unbiased walk. The
// product form m_j ← cos θ m_j + sin θ m_k rounds cos θ ≈ 1 first, and at the small, nearly repeating
// angles of a long run that rounding is biased: |L| drifted linearly (+2.5e-12 relative after
// 1e6 steps); adding the increments to m itself still rounds at m's ulp, four times per step, and left a
// bias of ~4e-4 ε per step (Yoshida, ω0 = (0.1, 0.1, 50) rad/s). The rounding of m0 + dm below acts on
// the step's result only at second order (θ times it).
inline void principal_axis_flow(int i, double half_per_m, const Eigen::Vector3d& m0, Eigen::Vector3d& dm,
                                Eigen::Quaterniond& q_WP) {
  const Eigen::Vector3d m_P = m0 + dm;
  const double half = half_per_m * m_P(i);  // θ/2
  const double s_half = std::sin(half), c_half = std::cos(half);
  const double c_minus_1 = -2.0 * s_half * s_half, s = 2.0 * s_half * c_half;  // cos θ − 1, sin θ
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  dm(j) += c_minus_1 * m_P(j) + s * m_P(k);
  dm(k) += c_minus_1 * m_P(k) - s * m_P(j);
  // q_WP ⊗ (cos(θ/2), sin(θ/2) e_i) as an increment likewise, with cos(θ/2) − 1 = −sin²(θ/2)/(1 + cos(θ/2));
  // q_WP ⊗ (0, e_i) = (−v_i; w e_i + v × e_i), v × e_i = v_k e_j − v_j e_k, written out: exact (it only
  // permutes and negates the coefficients)
  Eigen::Quaterniond q_e;
  q_e.w() = -q_WP.vec()(i);
  q_e.vec()(i) = q_WP.w(), q_e.vec()(j) = q_WP.vec()(k), q_e.vec()(k) = -q_WP.vec()(j);
  const double c_half_minus_1 = -s_half * s_half / (1.0 + c_half);
  q_WP.coeffs() += c_half_minus_1 * q_WP.coeffs() + s_half * q_e.coeffs();
}

}  // namespace rigiddyn
