#include "rigiddyn/tree/crba.hpp"

#include "rigiddyn/tree/forward_kinematics.hpp"

namespace rigiddyn {

const Eigen::MatrixXd& crba(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q, TreeWorkspace& ws) {
  link_poses(tree, q, ws);
  const int n = tree.num_links();
  for (int i = 0; i < n; ++i) ws.I_C[i] = tree.link(i).I;
  ws.H.setZero();  // H_ij = 0 where neither of i, j supports the other
  // I^c_λ += X_λi* I^c_i X_λi^-1 = X* I^c X*^T (X_λi^-1 as a motion map is X_λi*^T)
  for (int i = n - 1; i >= 0; --i) {
    const int parent = tree.link(i).parent;
    if (parent < 0) continue;
    const Matrix6d X_star = ws.X_up[i].force_matrix();
    ws.I_C[parent].noalias() += X_star * ws.I_C[i] * X_star.transpose();
  }
  for (int i = 0; i < n; ++i) {
    const Link& link_i = tree.link(i);
    // F = I^c_i S_i (6, nv_i), as U's storage
    auto& F = ws.U[i];
    F.noalias() = ws.I_C[i] * link_i.S;
    auto H_ii = ws.H.block(link_i.idx_v, link_i.idx_v, link_i.nv, link_i.nv);
    H_ii.noalias() = link_i.S.transpose() * F;
    // S^T I^c S is symmetric up to round-off: keep H exactly symmetric (its upper triangle mirrored)
    for (int r = 1; r < link_i.nv; ++r)
      for (int c = 0; c < r; ++c) H_ii(r, c) = H_ii(c, r);
    for (int j = i; tree.link(j).parent >= 0;) {
      F = ws.X_up[j].force_matrix() * F;  // F = X_λj* F
      j = tree.link(j).parent;
      const Link& link_j = tree.link(j);
      // H_ij = F^T S_j, H_ji = H_ij^T
      ws.H.block(link_i.idx_v, link_j.idx_v, link_i.nv, link_j.nv).noalias() = F.transpose() * link_j.S;
      ws.H.block(link_j.idx_v, link_i.idx_v, link_j.nv, link_i.nv) =
          ws.H.block(link_i.idx_v, link_j.idx_v, link_i.nv, link_j.nv).transpose();
    }
  }
  return ws.H;
}

}  // namespace rigiddyn
