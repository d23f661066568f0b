// The scratch of the tree algorithms, sized once for a tree so that no algorithm allocates: per-link
// arrays (n links) of transforms, motions, forces and 6x6 inertias, and the joint-space results.
// One workspace serves every algorithm; each overwrites what it uses.
#pragma once
#include <Eigen/Core>

#include <vector>

#include "rigiddyn/spatial/force.hpp"
#include "rigiddyn/spatial/motion.hpp"
#include "rigiddyn/spatial/transform.hpp"
#include "rigiddyn/tree/tree.hpp"

namespace rigiddyn {

// The f_ext of the tree algorithms for no external force on any link (they take an empty list as none).
inline const std::vector<Force>& no_external_forces() {
  static const std::vector<Force> none;
  return none;
}

struct TreeWorkspace {
  explicit TreeWorkspace(const Tree& tree);
  // Whether this workspace was made for a tree of the shape of `tree` (its links and each joint's nv), so that the
  // algorithms can run on `tree` in it.
  bool fits(const Tree& tree) const;

  std::vector<Transform> X_up;  // X_λi: link i in its parent's frame (n)
  std::vector<Transform> X_W;   // X_Wi: link i in W (n)
  std::vector<Motion> v;        // v_i: twist of link i in W, expressed in L_i (n)
  std::vector<Motion> a;        // a_i: its spatial acceleration (n)
  std::vector<Motion> c;        // c_i = v_i x S_i qd_i: the velocity-product acceleration (ABA) (n)
  std::vector<Force> f;         // f_i: the force across joint i (RNEA), or p^A_i, the bias force (ABA) (n)
  std::vector<Force> h;         // h^c_i: the momentum of the subtree at i, in L_i (generalized momentum) (n)
  std::vector<Matrix6d> I_C;    // I^c_i composite (CRBA) or I^A_i articulated (ABA) inertia, about L_i's origin (n)
  std::vector<Eigen::Matrix<double, 6, Eigen::Dynamic, Eigen::ColMajor, 6, 6>> U;  // U_i = I^A_i S_i (6, nv_i)
  std::vector<Eigen::Matrix<double, 6, Eigen::Dynamic, Eigen::ColMajor, 6, 6>> S_W;  // X_Wi S_i: S_i in W (CRBA) (6, nv_i)
  std::vector<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 6, 6>> D_inv;  // (S^T U)^-1
  std::vector<Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 6, 1>> u;  // τ_i - S_i^T p^A_i (nv_i)
  Eigen::VectorXd zero_v;       // (nv,) zeros: the acceleration of bias_forces
  Eigen::VectorXd tau;          // (nv,) the result of rnea and bias_forces
  Eigen::VectorXd qdd;          // (nv,) the result of aba
  Eigen::VectorXd p;            // (nv,) the result of generalized_momentum
  Eigen::VectorXd p_dot;        // (nv,) the result of generalized_momentum_rate
  Eigen::MatrixXd H;            // (nv, nv) the result of crba
};

}  // namespace rigiddyn
