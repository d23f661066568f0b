// The symplectic splitting method of Dullweber, Leimkuhler & McLachlan (J. Chem. Phys. 107, 1997)
// and McLachlan & Reich, for the rigid body under loads:
//
//   step(h) = kick(h/2) · [free translation(h), free rotation(h)] · kick(h/2)       (Strang)
//   free rotation(h) = R_a(h/2) R_b(h/2) R_c(h) R_b(h/2) R_a(h/2)
//
// R_i is the exact flow of H_i = m_i²/(2 I_i) about principal axis i (splitting_parts.hpp), with
// (a, b, c) the principal axes by INCREASING moment I_a ≤ I_b ≤ I_c (the note's 1 2 3 2 1). The
// order of the split changes the error constant (Fassò, J. Comput. Phys. 189, 2003): measured on
// I = diag(1, 2, 3) over 10 s at h = 0.05 (four initial ω, both sides of the separatrix), the
// orders with the intermediate axis second (a b c b a, c b a b c) were best, the others 2–10×
// worse. A sphere's free rotation is done exactly (q ⊗ exp(h ω), ω constant).
//
// Order 2 (symmetric); cost per step: 2 derivative evaluations (the kicks; none without loads; 1 between records where
// the loads do not read the velocities: a run merges adjacent kicks, simulate/run_loop.hpp) + 5
// axis rotations (one sin/cos pair each); a full (non-diagonal) inertia adds two turns B ↔ P by its
// principal frame (computed once per inertia, FullEuler). Conserves exactly (to round-off) on a free body: |L|, the spatial
// L_W, unit |q| (SO(3)), their round-off an unbiased walk (≤ 10 ε √N after N steps: the rotations,
// the update of ω and the normalisation of q are written as increments, see principal_axis_flow,
// dlm_principal_increment and unit_quaternion); the energy error stays bounded (symplectic, no
// drift). Under constant loads: the translation is velocity Verlet, exact for a constant
// world-frame force and gravity.
// Written once against the model interface (model_interface.hpp) as
//   step(h) = loads_kick(h/2) · free_flow<DlmRotation<true>>(h) · loads_kick(h/2),
// so every model takes the same composition: the free part of each body comes from the model (a rigid
// body's rotation by dlm_free_rotation below; a particle's and a planar body's free parts have no
// gyroscopic term, and there the step is velocity Verlet, exact for constant loads).
#pragma once
#include "rigiddyn/always_inline.hpp"
#include "rigiddyn/integrators/free_flow_tags.hpp"
#include "rigiddyn/integrators/splitting_parts.hpp"
#include "rigiddyn/integrators/workspace.hpp"
#include "rigiddyn/so3/exp_log.hpp"

#include <cmath>
#include <type_traits>

namespace rigiddyn {

// The DLM free rotation in the principal frame P: m_P = I_P ω_P turned by R_a(h/2) R_b(h/2) R_c(h)
// R_b(h/2) R_a(h/2), the attitude q_WP with it. Returns the INCREMENT of ω_P over the step [rad/s],
// Δm_P / I_P with Δm_P accumulated on its own (principal_axis_flow), which the caller adds to ω: the
// rounding of I_P ω_P then acts on the new |I ω| only at second order. Recomputing ω = m_P,end / I_P
// instead rounds m → ω → m the same way at every step for components that barely change (a bias of
// ~0.005 ε per step: |L| drifted linearly, +55 000 ε after 1e7 steps of a tumble with
// I = diag(1.1, 2.3, 3.7)).
inline Eigen::Vector3d dlm_principal_increment(const PrincipalSplit& P, const Eigen::Vector3d& w_P, Eigen::Quaterniond& q_WP,
                                               double h) {
  const Eigen::Vector3d m0 = P.moments.cwiseProduct(w_P);
  Eigen::Vector3d dm = Eigen::Vector3d::Zero();
  const auto [a, b, c] = P.ascending;
  const Eigen::Vector3d quarter = (0.25 * h) * P.moments.cwiseInverse();  // (h/2) / (2 I): the sub-flows over h/2
  principal_axis_flow(a, quarter(a), m0, dm, q_WP);
  principal_axis_flow(b, quarter(b), m0, dm, q_WP);
  principal_axis_flow(c, 2.0 * quarter(c), m0, dm, q_WP);
  principal_axis_flow(b, quarter(b), m0, dm, q_WP);
  principal_axis_flow(a, quarter(a), m0, dm, q_WP);
  return dm.cwiseQuotient(P.moments);
}

// The DLM approximation of the free (Euler–Poinsot) rotation over h [s] of one body with the Euler
// form `euler` (exact for a sphere): q_WB_xyzw (4 doubles, x y z w, unit) and w_B (3 doubles, ω in B
// [rad/s]) are updated in place. The attitude is normalised at the end (unit_quaternion) unless
// `normalise` is false: a composition of free rotations (yoshida4.hpp) normalises once, after the last
// (|q| moves by O(ε) in each). The per-body kernel of every model's free_flow<DlmRotation<normalise>>.
template <bool normalise = true, class Euler>
void dlm_free_rotation(const Euler& euler, double* q_WB_xyzw, double* w_B, double h) {
  // read and written by scalars: Eigen's packet copies of the pointed-to doubles would reload, as one
  // 2-wide load, values the previous sub-flow has just stored one by one (a store-forwarding stall;
  // see euler_equations.hpp)
  const Eigen::Quaterniond q0(q_WB_xyzw[3], q_WB_xyzw[0], q_WB_xyzw[1], q_WB_xyzw[2]);
  const Eigen::Vector3d w0(w_B[0], w_B[1], w_B[2]);
  const auto unit = [](const Eigen::Quaterniond& q) {
    if constexpr (normalise) return unit_quaternion(q);
    else return q;
  };
  Eigen::Quaterniond q1;
  Eigen::Vector3d w1 = w0;
  if constexpr (std::is_same_v<Euler, SphericalEuler>) {
    q1 = unit(q0 * rotvec_to_quat(h * w0));
  } else if constexpr (std::is_same_v<Euler, PrincipalEuler>) {  // P = B
    Eigen::Quaterniond q_WP = q0;
    const Eigen::Vector3d dw = dlm_principal_increment(principal_split(euler), w0, q_WP, h);
    q1 = unit(q_WP);
    w1 = w0 + dw;
  } else {
    const PrincipalSplit P = principal_split(euler);
    Eigen::Quaterniond q_WP = q0 * P.q_BP;
    const Eigen::Vector3d dw_P = dlm_principal_increment(P, P.q_BP.conjugate() * w0, q_WP, h);
    q1 = unit(q_WP * P.q_BP.conjugate());
    w1 = w0 + P.q_BP * dw_P;  // the turns B → P → B by the stored q_BP act on the increment only
  }
  for (int i = 0; i < 4; ++i) q_WB_xyzw[i] = q1.coeffs()[i];
  for (int i = 0; i < 3; ++i) w_B[i] = w1[i];
}

struct SplittingDlm {
  template <class Model>
  using Workspace = NoWorkspace;

  template <class Model>
  RIGIDDYN_ALWAYS_INLINE static void step(const Model& model, typename Model::Coordinates& y, double h, NoWorkspace& /*w*/) {
    model.loads_kick(y, edge_kick * h);
    between_kicks(model, y, h);
    model.loads_kick(y, edge_kick * h);
  }
  // The step opens and closes with loads_kick(edge_kick h): where the model's kicks merge, the run takes a step's
  // closing kick and the next step's opening kick as one (simulate/run_loop.hpp, merged_steps)
  static constexpr double edge_kick = 0.5;
  template <class Model>
  RIGIDDYN_ALWAYS_INLINE static void between_kicks(const Model& model, typename Model::Coordinates& y, double h) {
    model.template free_flow<DlmRotation<true>>(y, h);
  }
};

}  // namespace rigiddyn
