#include "rigiddyn/tree/energy.hpp"

#include "rigiddyn/tree/forward_kinematics.hpp"

namespace rigiddyn {

double kinetic_energy(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q,
                      const Eigen::Ref<const Eigen::VectorXd>& v, TreeWorkspace& ws) {
  forward_kinematics(tree, q, v, ws);
  double T = 0.0;
  for (int i = 0; i < tree.num_links(); ++i) T += tree.link(i).inertia.kinetic_energy(ws.v[i]);  // 1/2 v_i . I_i v_i
  return T;
}

double potential_energy(const Tree& tree, const Eigen::Ref<const Eigen::VectorXd>& q, TreeWorkspace& ws) {
  link_poses(tree, q, ws);
  double V = 0.0;
  for (int i = 0; i < tree.num_links(); ++i) {
    const SpatialInertia& I = tree.link(i).inertia;
    V -= I.mass() * tree.gravity().dot(ws.X_W[i].act_point(I.com()));  // -m_i g . p_W,Ci
  }
  return V;
}

}  // namespace rigiddyn
