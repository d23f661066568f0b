// Forward kinematics (Featherstone §4.2, the first pass of Table 5.1): for i = 0..n-1
//   X_λi = X_T,i X_J,i(q_i),   X_Wi = X_Wλ X_λi,
//   v_i = X_λi^-1 v_λ + S_i qd_i   (v_i: the twist of link i in W, expressed in L_i; v_world = 0).
#pragma once
#include <Eigen/Core>

#include "rigiddyn/tree/tree.hpp"
#include "rigiddyn/tree/workspace.hpp"

namespace rigiddyn {

// Fills ws.X_up, ws.X_W and ws.v from q (nq,) and v (nv,). Throws std::invalid_argument naming q or v
// (Tree::check_configuration, check_velocity). No allocation.
void forward_kinematics(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q,
                        const Eigen::Ref<const Eigen::VectorXd>& v, TreeWorkspace& ws);

// forward_kinematics without the checks, for callers that keep q and v valid themselves (each quaternion of q of
// unit norm: the scene's tree slot normalises them).
void forward_kinematics_unchecked(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q,
                                  const Eigen::Ref<const Eigen::VectorXd>& v, TreeWorkspace& ws);

// Fills ws.X_up and ws.X_W from q only (the link poses).
void link_poses(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q, TreeWorkspace& ws);
// link_poses without the checks (as forward_kinematics_unchecked).
void link_poses_unchecked(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q, TreeWorkspace& ws);

}  // namespace rigiddyn
