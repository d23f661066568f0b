// The mechanical energy of a tree under its uniform gravity g (in W):
//   T = sum_i 1/2 v_i . I_i v_i            (v_i the link twists, forward_kinematics.hpp)
//   V = - sum_i m_i g . p_W,Ci             (p_W,Ci = X_Wi c_i: link i's centre of mass in W; V = 0 at W's origin)
#pragma once
#include <Eigen/Core>

#include "rigiddyn/tree/tree.hpp"
#include "rigiddyn/tree/workspace.hpp"

namespace rigiddyn {

// T [J] for q (nq,) and v (nv,). No allocation.
double kinetic_energy(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q,
                      const Eigen::Ref<const Eigen::VectorXd>& v, TreeWorkspace& ws);
// V [J] for q (nq,). No allocation.
double potential_energy(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q, TreeWorkspace& ws);

}  // namespace rigiddyn
