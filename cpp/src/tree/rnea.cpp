#include "rigiddyn/tree/rnea.hpp"

#include <string>

#include "rigiddyn/check.hpp"
#include "rigiddyn/tree/forward_kinematics.hpp"

namespace rigiddyn {

void check_external_forces(const Tree& tree, const std::vector<Force>& f_ext) {
  if (f_ext.empty()) return;
  if (static_cast<int>(f_ext.size()) != tree.num_links()) {
    throw_invalid("f_ext", "one force per link (" + std::to_string(tree.num_links()) + ")", f_ext.size());
  }
  for (size_t i = 0; i < f_ext.size(); ++i)
    require_finite(f_ext[i].to_vector().transpose(), "f_ext[" + std::to_string(i) + "]");
}

const Eigen::VectorXd& rnea(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q,
                            const Eigen::Ref<const Eigen::VectorXd>& v, const Eigen::Ref<const Eigen::VectorXd>& a,
                            const std::vector<Force>& f_ext, TreeWorkspace& ws) {
  tree.check_velocity(a, "a");
  check_external_forces(tree, f_ext);
  forward_kinematics(tree, q, v, ws);
  const Motion a_0(Eigen::Vector3d::Zero(), -tree.gravity());  // -a_g
  const int n = tree.num_links();
  for (int i = 0; i < n; ++i) {
    const Link& link = tree.link(i);
    const Motion v_J = Motion::from_vector(link.S * v.segment(link.idx_v, link.nv));
    // a_i = X_λi^-1 a_λ + S_i qdd_i + v_i x S_i qd_i
    const Motion& a_parent = link.parent < 0 ? a_0 : ws.a[link.parent];
    ws.a[i] = ws.X_up[i].act_inv(a_parent) + Motion::from_vector(link.S * a.segment(link.idx_v, link.nv)) +
              ws.v[i].cross(v_J);
    // f_i = I_i a_i + v_i x* I_i v_i - f_ext,i
    ws.f[i] = Force::from_vector(link.I * ws.a[i].to_vector()) +
              ws.v[i].cross(Force::from_vector(link.I * ws.v[i].to_vector()));
    if (!f_ext.empty()) ws.f[i] -= f_ext[i];
  }
  for (int i = n - 1; i >= 0; --i) {
    const Link& link = tree.link(i);
    // τ_i = S_i^T f_i;  f_λ += X_λi* f_i
    ws.tau.segment(link.idx_v, link.nv).noalias() = link.S.transpose() * ws.f[i].to_vector();
    if (link.parent >= 0) ws.f[link.parent] += ws.X_up[i].act(ws.f[i]);
  }
  return ws.tau;
}

const Eigen::VectorXd& bias_forces(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q,
                                   const Eigen::Ref<const Eigen::VectorXd>& v, TreeWorkspace& ws) {
  return rnea(tree, q, v, ws.zero_v, no_external_forces(), ws);
}

}  // namespace rigiddyn
