#include "rigiddyn/tree/momentum.hpp"

#include <stdexcept>
#include <string>

#include "rigiddyn/tree/forward_kinematics.hpp"
#include "rigiddyn/tree/rnea.hpp"

namespace rigiddyn {

namespace {

void require_vector_joints(const Tree& tree) {
  for (const Link& link : tree.links()) {
    if (joint_has_quaternion(link.joint)) {
      throw std::invalid_argument(std::string("tree: expected revolute, prismatic or fixed joints (the momentum rate of "
                                              "a rotation group's joint has a further term), got a ") +
                                  joint_kind(link.joint) + " joint at link '" + link.name + "'");
    }
  }
}

}  // namespace

void generalized_momentum_after_kinematics(const Tree& tree, const std::vector<Force>& f_ext, TreeWorkspace& ws) {
  const int n = tree.num_links();
  const Motion a_g_W(Eigen::Vector3d::Zero(), tree.gravity());
  for (int i = 0; i < n; ++i) {
    const Link& link = tree.link(i);
    ws.h[i] = Force::from_vector(link.I * ws.v[i].to_vector());               // h_i = I_i v_i
    ws.f[i] = Force::from_vector(link.I * ws.X_W[i].act_inv(a_g_W).to_vector());  // gravity I_i a_g
    if (!f_ext.empty()) ws.f[i] += f_ext[i];
  }
  for (int i = n - 1; i >= 0; --i) {
    const Link& link = tree.link(i);
    const int parent = link.parent;
    const Motion u = parent < 0 ? Motion::Zero() : ws.X_up[i].act_inv(ws.v[parent]);  // u_i, the parent's twist in L_i
    // p_i = S_iᵀ h^c_i,  ṗ_i = −S_iᵀ (u_i ×* h^c_i) + S_iᵀ f^c_i
    ws.p.segment(link.idx_v, link.nv).noalias() = link.S.transpose() * ws.h[i].to_vector();
    ws.p_dot.segment(link.idx_v, link.nv).noalias() = link.S.transpose() * (ws.f[i].to_vector() - u.cross(ws.h[i]).to_vector());
    if (parent >= 0) {
      ws.h[parent] += ws.X_up[i].act(ws.h[i]);
      ws.f[parent] += ws.X_up[i].act(ws.f[i]);
    }
  }
}

const Eigen::VectorXd& generalized_momentum(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q,
                                            const Eigen::Ref<const Eigen::VectorXd>& v, TreeWorkspace& ws) {
  forward_kinematics(tree, q, v, ws);
  generalized_momentum_after_kinematics(tree, no_external_forces(), ws);
  return ws.p;
}

const Eigen::VectorXd& generalized_momentum_rate(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q,
                                                 const Eigen::Ref<const Eigen::VectorXd>& v,
                                                 const std::vector<Force>& f_ext, TreeWorkspace& ws) {
  require_vector_joints(tree);
  check_external_forces(tree, f_ext);
  forward_kinematics(tree, q, v, ws);
  generalized_momentum_after_kinematics(tree, f_ext, ws);
  return ws.p_dot;
}

}  // namespace rigiddyn
