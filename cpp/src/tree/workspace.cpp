#include "rigiddyn/tree/workspace.hpp"

namespace rigiddyn {

TreeWorkspace::TreeWorkspace(const Tree& tree)
    : X_up(tree.num_links()),
      X_W(tree.num_links()),
      v(tree.num_links()),
      a(tree.num_links()),
      c(tree.num_links()),
      f(tree.num_links()),
      h(tree.num_links()),
      I_C(tree.num_links(), Matrix6d::Zero()),
      U(tree.num_links()),
      S_W(tree.num_links()),
      D_inv(tree.num_links()),
      u(tree.num_links()),
      zero_v(Eigen::VectorXd::Zero(tree.nv())),
      tau(tree.nv()),
      qdd(tree.nv()),
      p(tree.nv()),
      p_dot(tree.nv()),
      H(tree.nv(), tree.nv()) {
  for (int i = 0; i < tree.num_links(); ++i) {
    const int nv = tree.link(i).nv;
    U[i].resize(6, nv);
    S_W[i].resize(6, nv);
    D_inv[i].resize(nv, nv);
    u[i].resize(nv);
  }
}

bool TreeWorkspace::fits(const Tree& tree) const {
  if (static_cast<int>(X_up.size()) != tree.num_links() || H.rows() != tree.nv()) return false;
  for (int i = 0; i < tree.num_links(); ++i) {
    if (U[i].cols() != tree.link(i).nv) return false;
  }
  return true;
}

}  // namespace rigiddyn
