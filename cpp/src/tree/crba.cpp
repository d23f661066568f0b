#include "rigiddyn/tree/crba.hpp"

#include "rigiddyn/so3/skew.hpp"
#include "rigiddyn/tree/forward_kinematics.hpp"

namespace rigiddyn {

namespace {

// I^c_λ += X_λi* I^c_i X_λi*ᵀ for a rigid-body (composite) inertia in its block form [[I_O, ĥ], [ĥᵀ, m 1]] about the
// link's origin (Featherstone, Rigid Body Dynamics Algorithms, eq. 2.63; h = m c its first moment [kg m], I_O its
// rotational inertia about the origin [kg m²]). With X_λi = (R, p), link i's pose in its parent, the same body in the
// parent's frame has mass m, first moment h' = g + m p, g = R h, and, by the parallel-axis theorem (no division by m),
//   I_O' = R I_O Rᵀ − (ĝ p̂ + p̂ ĝ + m p̂ p̂),
// about 100 flops against the 432 of the dense triple product; the sum keeps the block form exactly.
void add_transformed_inertia(const Transform& X, const Matrix6d& I_i, Matrix6d& I_parent) {
  const double m = I_i(3, 3);
  const Eigen::Vector3d h(I_i(2, 4), I_i(0, 5), I_i(1, 3));  // ĥ is the top-right block
  const Eigen::Matrix3d& R = X.rotation();
  const Eigen::Vector3d g = R * h;
  const Eigen::Matrix3d g_hat = hat(g), p_hat = hat(X.translation());
  const Eigen::Matrix3d h_hat = hat(g + m * X.translation());
  I_parent.topLeftCorner<3, 3>().noalias() += R * I_i.topLeftCorner<3, 3>() * R.transpose();
  I_parent.topLeftCorner<3, 3>().noalias() -= g_hat * p_hat + p_hat * g_hat + m * p_hat * p_hat;
  I_parent.topRightCorner<3, 3>() += h_hat;
  I_parent.bottomLeftCorner<3, 3>() -= h_hat;  // ĥᵀ = −ĥ
  I_parent.bottomRightCorner<3, 3>().diagonal().array() += m;
}

// The motions of `S` (6, k), each column a motion in frame B, in frame A (X = X_AB), into `out` (6, k)
template <class Out>
void act_motions(const Transform& X, const MotionSubspace& S, Out& out) {
  for (Eigen::Index k = 0; k < S.cols(); ++k) {
    const Motion m = X.act(Motion(S.col(k).head<3>(), S.col(k).tail<3>()));
    out.col(k) << m.angular, m.linear;
  }
}

// The same for forces (the columns of F, in place)
template <class Columns>
void act_forces(const Transform& X, Columns& F) {
  for (Eigen::Index k = 0; k < F.cols(); ++k) {
    const Force f = X.act(Force(F.col(k).template head<3>(), F.col(k).template tail<3>()));
    F.col(k) << f.angular, f.linear;
  }
}

// Row and column i of H for a joint of one degree of freedom (revolute, prismatic: most joints of a robot): the loop
// of crba below with F a 6-vector, fixed-size products where the general loop's are of dynamic size.
void one_dof_column(const Tree& tree, TreeWorkspace& ws, int i) {
  const Link& link_i = tree.link(i);
  const Vector6d s_i = link_i.S.col(0);
  Vector6d F = ws.I_C[i] * s_i;
  const Eigen::Index iv = link_i.idx_v;
  ws.H(iv, iv) = s_i.dot(F);
  const Force F_W = ws.X_W[i].act(Force(F.head<3>(), F.tail<3>()));
  F << F_W.angular, F_W.linear;
  for (int j = link_i.parent; j >= 0; j = tree.link(j).parent) {
    const Link& link_j = tree.link(j);
    for (int k = 0; k < link_j.nv; ++k) {
      const double H_ij = F.dot(ws.S_W[j].col(k));
      ws.H(iv, link_j.idx_v + k) = H_ij;
      ws.H(link_j.idx_v + k, iv) = H_ij;
    }
  }
}

}  // namespace

const Eigen::MatrixXd& crba(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q, TreeWorkspace& ws) {
  tree.check_configuration(q);
  return crba_unchecked(tree, q, ws);
}

const Eigen::MatrixXd& crba_unchecked(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q, TreeWorkspace& ws) {
  link_poses_unchecked(tree, q, ws);
  const int n = tree.num_links();
  for (int i = 0; i < n; ++i) ws.I_C[i] = tree.link(i).I;
  ws.H.setZero();  // H_ij = 0 where neither of i, j supports the other
  // I^c_λ += X_λi* I^c_i X_λi^-1 = X* I^c X*^T (X_λi^-1 as a motion map is X_λi*^T)
  for (int i = n - 1; i >= 0; --i) {
    const int parent = tree.link(i).parent;
    if (parent >= 0) add_transformed_inertia(ws.X_up[i], ws.I_C[i], ws.I_C[parent]);
  }
  // S_W,j = X_Wj S_j: each joint's motion subspace in W, so that H_ij = S_jᵀ X_ji* F_i = S_W,jᵀ X_Wi* F_i needs one
  // transform of F_i (to W) for all of i's ancestors j instead of one per ancestor
  for (int j = 0; j < n; ++j) act_motions(ws.X_W[j], tree.link(j).S, ws.S_W[j]);
  for (int i = 0; i < n; ++i) {
    const Link& link_i = tree.link(i);
    if (link_i.nv == 1) {
      one_dof_column(tree, ws, i);
      continue;
    }
    // F = I^c_i S_i (6, nv_i), as U's storage
    auto& F = ws.U[i];
    F.noalias() = ws.I_C[i] * link_i.S;
    auto H_ii = ws.H.block(link_i.idx_v, link_i.idx_v, link_i.nv, link_i.nv);
    H_ii.noalias() = link_i.S.transpose() * F;
    // S^T I^c S is symmetric up to round-off: keep H exactly symmetric (its upper triangle mirrored)
    for (int r = 1; r < link_i.nv; ++r)
      for (int c = 0; c < r; ++c) H_ii(r, c) = H_ii(c, r);
    act_forces(ws.X_W[i], F);  // F in W
    for (int j = link_i.parent; j >= 0; j = tree.link(j).parent) {
      const Link& link_j = tree.link(j);
      // H_ij = F_Wᵀ S_W,j, H_ji = H_ijᵀ
      auto H_ij = ws.H.block(link_i.idx_v, link_j.idx_v, link_i.nv, link_j.nv);
      H_ij.noalias() = F.transpose() * ws.S_W[j];
      ws.H.block(link_j.idx_v, link_i.idx_v, link_j.nv, link_i.nv) = H_ij.transpose();
    }
  }
  return ws.H;
}

}  // namespace rigiddyn
