// The generalized momentum of a tree and its rate by Lagrange's equations (Goldstein, Classical Mechanics §1.4;
// Featherstone §6.2 for the composite quantities):
//   p = ∂T/∂qd = H(q) qd,            p_i = S_iᵀ h^c_i,   h^c_i = Σ_{k in subtree(i)} X_ik* I_k v_k,
//   ṗ = ∂T/∂q + Q,                   (∂T/∂q)_i = −S_iᵀ (u_i ×* h^c_i),   Q_i = S_iᵀ f^c_i,
// with h^c_i the momentum of the subtree at link i and f^c_i the external forces on it (gravity I_k a_g and f_ext,k),
// both in L_i, and u_i = X_λi⁻¹ v_λ = v_i − S_i qd_i the parent's twist in L_i. The derivative of T: turning q_i by
// δ moves L_i by S_i δ in its parent, so that u_i changes by −δ S_i × u_i while S_i qd_i and the twists of the
// subtree relative to L_i do not: δT = h^c_i · δv_i = −δ h^c_i · (S_i × u_i) = −δ S_i · (u_i ×* h^c_i). Its virtual
// work gives Q_i. This holds for a joint whose S_i is constant in L_i with q_i in a vector space (revolute,
// prismatic; a fixed joint has no coordinate); a ball or free joint's momentum rate has the further term of its
// rotation group (Euler–Poincaré), which this file does not compute: generalized_momentum_rate refuses them.
#pragma once
#include <Eigen/Core>

#include <vector>

#include "rigiddyn/spatial/force.hpp"
#include "rigiddyn/tree/tree.hpp"
#include "rigiddyn/tree/workspace.hpp"

namespace rigiddyn {

// p = H(q) qd (nv,) [N m s per angle, N s per offset] for q (nq,) and v = qd (nv,), any joints. Writes ws.p and
// returns it (valid until the next call with ws; ws.p_dot is its scratch). Throws std::invalid_argument naming q or v. No allocation.
const Eigen::VectorXd& generalized_momentum(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q,
                                            const Eigen::Ref<const Eigen::VectorXd>& v, TreeWorkspace& ws);

// ṗ = ∂T/∂q + Q (nv,) [N m per angle, N per offset] under the tree's gravity and f_ext (as rnea: one force per link
// in its frame, or empty), the joint forces τ excluded (ṗ = τ + this). Writes ws.p_dot (and ws.p) and returns
// ws.p_dot. Throws std::invalid_argument naming the bad argument, or the link of a ball or free joint. No allocation.
const Eigen::VectorXd& generalized_momentum_rate(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q,
                                                 const Eigen::Ref<const Eigen::VectorXd>& v,
                                                 const std::vector<Force>& f_ext, TreeWorkspace& ws);

// ws.p and ws.p_dot after forward kinematics at (q, v) filled ws.X_up, ws.X_W and ws.v, without the checks (the
// scene's tree slot). For a ball or free joint ws.p_dot is ∂T/∂q + Q along its body perturbations (q ⊗ exp(δ)), its
// momentum rate less the rotation group's term: what the variational midpoint method of kinds/tree_slot.hpp takes.
void generalized_momentum_after_kinematics(const Tree& tree, const std::vector<Force>& f_ext, TreeWorkspace& ws);

}  // namespace rigiddyn
