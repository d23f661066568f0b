// The recursive Newton-Euler algorithm (Featherstone Table 5.1): inverse dynamics
// τ = ID(q, qd, qdd, f_ext) = H(q) qdd + C(q, qd, f_ext). Gravity enters as a fictitious base
// acceleration a_0 = -a_g = [0; -g] (Featherstone §5.3).
//   forward:   v_i = X_λi^-1 v_λ + S_i qd_i
//              a_i = X_λi^-1 a_λ + S_i qdd_i + v_i x S_i qd_i      (c_J = 0 for every joint kind here)
//              f_i = I_i a_i + v_i x* I_i v_i - f_ext,i
//   backward:  τ_i = S_i^T f_i,   f_λ += X_λi* f_i
#pragma once
#include <Eigen/Core>

#include <vector>

#include "rigiddyn/spatial/force.hpp"
#include "rigiddyn/tree/tree.hpp"
#include "rigiddyn/tree/workspace.hpp"

namespace rigiddyn {

// τ (nv,) [N m or N per joint coordinate] for q (nq,), v = qd (nv,), a = qdd (nv,) and the external
// forces f_ext: one per link, each expressed in its link's frame L_i (moment about L_i's origin), or
// empty for none. Writes ws.tau and returns it (valid until the next call with ws). Throws
// std::invalid_argument naming the bad argument. No allocation.
const Eigen::VectorXd& rnea(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q,
                            const Eigen::Ref<const Eigen::VectorXd>& v, const Eigen::Ref<const Eigen::VectorXd>& a,
                            const std::vector<Force>& f_ext, TreeWorkspace& ws);

// C(q, qd) = ID(q, qd, 0): Coriolis, centrifugal and gravity forces (nv,), with no external force.
const Eigen::VectorXd& bias_forces(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q,
                                   const Eigen::Ref<const Eigen::VectorXd>& v, TreeWorkspace& ws);

// Throws std::invalid_argument naming "f_ext" unless it is empty or has one finite force per link.
void check_external_forces(const Tree& tree, const std::vector<Force>& f_ext);

}  // namespace rigiddyn
