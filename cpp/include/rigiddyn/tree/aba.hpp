// The articulated-body algorithm (Featherstone Table 7.1): forward dynamics
// qdd = FD(q, qd, τ, f_ext) = H^-1 (τ - C) in O(n), with gravity as the base acceleration a_0 = -a_g.
//   pass 1 (i = 0..n-1):   v_i = X_λi^-1 v_λ + S_i qd_i,  c_i = v_i x S_i qd_i,
//                          I^A_i = I_i,  p^A_i = v_i x* I_i v_i - f_ext,i
//   pass 2 (i = n-1..0):   U_i = I^A_i S_i,  D_i = S_i^T U_i,  u_i = τ_i - S_i^T p^A_i,
//                          I^a = I^A_i - U_i D_i^-1 U_i^T,  p^a = p^A_i + I^a c_i + U_i D_i^-1 u_i,
//                          I^A_λ += X_λi* I^a X_λi^-1,  p^A_λ += X_λi* p^a
//   pass 3 (i = 0..n-1):   a' = X_λi^-1 a_λ + c_i,  qdd_i = D_i^-1 (u_i - U_i^T a'),  a_i = a' + S_i qdd_i
#pragma once
#include <Eigen/Core>

#include <vector>

#include "rigiddyn/spatial/force.hpp"
#include "rigiddyn/tree/tree.hpp"
#include "rigiddyn/tree/workspace.hpp"

namespace rigiddyn {

// qdd (nv,) for q (nq,), v = qd (nv,), the joint forces τ (nv,) and f_ext (as rnea: one force per
// link in its frame, or empty). Writes ws.qdd and returns it (valid until the next call with ws).
// Throws std::invalid_argument naming the bad argument. No allocation.
const Eigen::VectorXd& aba(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q,
                           const Eigen::Ref<const Eigen::VectorXd>& v, const Eigen::Ref<const Eigen::VectorXd>& tau,
                           const std::vector<Force>& f_ext, TreeWorkspace& ws);

// aba's passes 1-3 after forward kinematics at (q, v) filled ws.X_up and ws.v, without the checks (the scene's tree
// slot: its stage coordinates are valid by construction, and a diverging run is caught by its run loop).
const Eigen::VectorXd& aba_after_kinematics(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& v,
                                            const Eigen::Ref<const Eigen::VectorXd>& tau, const std::vector<Force>& f_ext,
                                            TreeWorkspace& ws);

}  // namespace rigiddyn
