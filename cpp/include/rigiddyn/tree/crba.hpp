// The composite-rigid-body algorithm (Featherstone Table 6.2): the joint-space inertia matrix H(q)
// (nv, nv), symmetric positive definite, from the composite inertias of the subtrees:
//   I^c_i = I_i + sum over children j of X_ij* I^c_j X_ij^-1     (i = n-1..0)
//   F = I^c_i S_i,  H_ii = S_i^T F;  then up the path j = λ(i), λ(λ(i)), ...:
//   F = X_λj* F (carried to the parent),  H_ij = F^T S_j,  H_ji = H_ij^T.
// Computed with F and each S_j in W (F_W = X_Wi* F, S_W,j = X_Wj S_j: H_ij = F_W^T S_W,j, the pairing of a force and
// a motion being the same in every frame): one transform of F per link instead of one per link and ancestor.
// The kinetic energy is T = 1/2 qd^T H qd.
#pragma once
#include <Eigen/Core>

#include "rigiddyn/tree/tree.hpp"
#include "rigiddyn/tree/workspace.hpp"

namespace rigiddyn {

// H(q) [kg m^2, kg m or kg per pair of coordinates]; writes ws.H and returns it (valid until the next
// call with ws). Throws std::invalid_argument naming q. No allocation.
const Eigen::MatrixXd& crba(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q, TreeWorkspace& ws);
// crba without the check of q (the scene's tree slot: a diverging run is caught by its run loop).
const Eigen::MatrixXd& crba_unchecked(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q, TreeWorkspace& ws);

}  // namespace rigiddyn
