#include "rigiddyn/tree/forward_kinematics.hpp"

namespace rigiddyn {

namespace {

// ws.X_up, ws.X_W from q: X_λi = X_T X_J(q_i), X_Wi = X_Wλ X_λi
void poses(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q, TreeWorkspace& ws) {
  for (int i = 0; i < tree.num_links(); ++i) {
    const Link& link = tree.link(i);
    ws.X_up[i] = link.X_T * joint_transform(link.joint, q.segment(link.idx_q, link.nq));
    ws.X_W[i] = link.parent < 0 ? ws.X_up[i] : ws.X_W[link.parent] * ws.X_up[i];
  }
}

}  // namespace

void link_poses(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q, TreeWorkspace& ws) {
  tree.check_configuration(q);
  poses(tree, q, ws);
}

void link_poses_unchecked(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q, TreeWorkspace& ws) {
  poses(tree, q, ws);
}

void forward_kinematics(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q,
                        const Eigen::Ref<const Eigen::VectorXd>& v, TreeWorkspace& ws) {
  tree.check_configuration(q);
  tree.check_velocity(v, "v");
  forward_kinematics_unchecked(tree, q, v, ws);
}

void forward_kinematics_unchecked(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q,
                                  const Eigen::Ref<const Eigen::VectorXd>& v, TreeWorkspace& ws) {
  poses(tree, q, ws);
  for (int i = 0; i < tree.num_links(); ++i) {
    const Link& link = tree.link(i);
    // v_i = X_λi^-1 v_λ + S_i qd_i
    const Motion v_J = Motion::from_vector(link.S * v.segment(link.idx_v, link.nv));
    ws.v[i] = link.parent < 0 ? v_J : ws.X_up[i].act_inv(ws.v[link.parent]) + v_J;
  }
}

}  // namespace rigiddyn
