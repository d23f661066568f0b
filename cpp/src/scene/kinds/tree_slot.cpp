// The tree slot's members that its evaluations do not inline (scene/kinds/tree_slot.hpp states each one's equations):
// its constructor, records, coordinates and variational midpoint steps, compiled once here instead of in every file
// that includes the kind list (their Cholesky and LU solves were instantiated in each).
#include "rigiddyn/scene/kinds/tree_slot.hpp"

#include "rigiddyn/so3/exp_log.hpp"
#include "rigiddyn/so3/jacobian.hpp"
#include "rigiddyn/tree/crba.hpp"
#include "rigiddyn/tree/momentum.hpp"

namespace rigiddyn::detail {

TreeSlot::TreeSlot(int body, Eigen::Index at_y, Eigen::Index at_xi, std::shared_ptr<const Tree> tree_)
    : SlotPlace{body, at_y, at_xi}, tree(std::move(tree_)), links(tree->num_links()), nq(tree->nq()), nv(tree->nv()),
      ws(*tree), f_ext(links), q_unit(nq), tau(Eigen::VectorXd::Zero(nv)), q_0(nq), p_0(nv), phi(nv), phi_1(nv), force(nv),
      p_bar(nv), rhs(nv) {
  for (const Link& link : tree->links()) {
    const TreeJoint::Kind kind = std::holds_alternative<SphericalJoint>(link.joint) ? TreeJoint::ball
                                 : std::holds_alternative<FreeJoint>(link.joint)    ? TreeJoint::free
                                 : std::holds_alternative<FixedJoint>(link.joint)   ? TreeJoint::fixed
                                                                                    : TreeJoint::vector;
    joints.push_back({kind, link.idx_q, link.idx_v});
    has_quaternions = has_quaternions || kind == TreeJoint::ball || kind == TreeJoint::free;
    c_L.push_back(link.inertia.com());
  }
  H_llt.compute(Eigen::MatrixXd::Identity(nv, nv));  // sizes it, and sets its state (copied with the slot)
}

void TreeSlot::apply_gravity(const Eigen::Vector3d& g_W) {
  auto with_gravity = std::make_shared<Tree>(*tree);
  with_gravity->set_gravity(g_W);
  tree = std::move(with_gravity);
}

void TreeSlot::translate(double* y, double h) const {
  load_configuration(y);
  const double* v = y + at_y + nq;
  for (const TreeJoint& j : joints) {
    double* q = y + at_y + j.q;
    if (j.kind == TreeJoint::vector) q[0] += h * v[j.v];
    if (j.kind == TreeJoint::ball) turn_quaternion(q, three(v + j.v), h);
    if (j.kind == TreeJoint::free) {
      const Eigen::Vector3d dp = h * (free_rotation_of(j) * three(v + j.v + 3));
      for (int i = 0; i < 3; ++i) q[i] += dp[i];
      turn_quaternion(q + 3, three(v + j.v), h);
    }
  }
}

void TreeSlot::record(const double*, BodyKinematics& first, const BodyWrench&, RecordSums& sums,
            Eigen::Vector3d& momentum_first, Eigen::Vector3d& reaction_first) const {
  BodyKinematics* k = &first;
  for (int i = 0; i < links; ++i) {
    k[i].q_WB = Eigen::Quaterniond(k[i].R_WB);
    const Eigen::Vector3d h_L = tree->link(i).inertia.inertia_com() * k[i].w_B;
    sums.add_translation(k[i]);
    sums.T += 0.5 * k[i].w_B.dot(h_L);
    (&momentum_first)[i] = k[i].R_WB * h_L;
    sums.H_W += (&momentum_first)[i];
    (&reaction_first)[i].setZero();
  }
}

void TreeSlot::start_variational_midpoint(const double* y0, double half_h, double* mid) const {
  load_configuration(y0);
  q_0 = Eigen::Map<const Eigen::VectorXd>(y0 + at_y, nq);
  forward_kinematics_unchecked(*tree, configuration(), velocities(y0), ws);
  generalized_momentum_after_kinematics(*tree, no_external_forces(), ws);
  p_0 = ws.p;
  chart_point_of(y0 + at_y + nq, half_h);
  write_chart_point(phi, mid);
}

void TreeSlot::variational_midpoint_iterate(const double* mid, double half_h, double* next) const {
  generalized_momentum_after_kinematics(*tree, external_forces(), ws);
  force = ws.p_dot;
  const double* v_bar = mid + at_y + nq;
  for (const TreeJoint& j : joints) {
    if (j.kind == TreeJoint::vector) p_bar[j.v] = p_0[j.v] + half_h * force[j.v];
    if (j.kind == TreeJoint::free) {
      const Eigen::Matrix3d R_0 = start_rotation_of(j), R_bar = R_0 * rotvec_to_matrix(phi.segment<3>(j.v));
      p_bar.segment<3>(j.v + 3) = R_bar.transpose() * (R_0 * p_0.segment<3>(j.v + 3)) + half_h * force.segment<3>(j.v + 3);
      force.segment<3>(j.v) -= three(v_bar + j.v + 3).cross(p_bar.segment<3>(j.v + 3));  // F_ω − v̄_L × p̄_v
    }
    if (j.kind == TreeJoint::ball || j.kind == TreeJoint::free) {  // ξ = 2φ̄
      const Eigen::Vector3d phi_j = phi.segment<3>(j.v), F = force.segment<3>(j.v);
      p_bar.segment<3>(j.v) = left_jacobian(2.0 * phi_j).transpose() *
                                  (p_0.segment<3>(j.v) + (2.0 * half_h) * (rotvec_to_matrix(phi_j) * F)) -
                              half_h * (left_jacobian(phi_j) * F);
    }
  }
  rhs = p_bar;
  solve_velocity(next);
  chart_point_of(next + at_y + nq, half_h);
  write_chart_point(phi, next);
}

void TreeSlot::recenter_variational_midpoint(double half_h, double* mid) const {
  chart_point_of(mid + at_y + nq, half_h);
  write_chart_point(phi, mid);
}

void TreeSlot::finish_variational_midpoint(double h, double* y1) const {
  phi_1 = 2.0 * phi;
  write_chart_point(phi_1, y1);
  for (const TreeJoint& j : joints) {
    if (j.kind == TreeJoint::vector) p_bar[j.v] = p_0[j.v] + h * force[j.v];
    if (j.kind == TreeJoint::free) {
      const Eigen::Matrix3d R_0 = start_rotation_of(j);
      const Eigen::Matrix3d R_bar = R_0 * rotvec_to_matrix(phi.segment<3>(j.v)), R_1 = R_0 * rotvec_to_matrix(phi_1.segment<3>(j.v));
      p_bar.segment<3>(j.v + 3) = R_1.transpose() * (R_bar * (p_bar.segment<3>(j.v + 3) + 0.5 * h * force.segment<3>(j.v + 3)));
    }
    if (j.kind == TreeJoint::ball || j.kind == TreeJoint::free) {
      const Eigen::Vector3d p_tilde = p_bar.segment<3>(j.v) + 0.5 * h * (left_jacobian(phi.segment<3>(j.v)) * force.segment<3>(j.v));
      p_bar.segment<3>(j.v) = left_jacobian(phi_1.segment<3>(j.v)).partialPivLu().solve(p_tilde);
    }
  }
  load_configuration(y1);
  rhs = p_bar;
  solve_velocity(y1);
}

void TreeSlot::coordinates(const BodyState& first, double* y) const {
  for (int i = 0; i < links; ++i) {
    const Link& link = tree->link(i);
    const auto& s = std::get<JointState>((&first)[i]);
    for (int k = 0; k < link.nq; ++k) y[at_y + link.idx_q + k] = s.q[k];
    for (int k = 0; k < link.nv; ++k) y[at_y + nq + link.idx_v + k] = s.v[k];
  }
}

void TreeSlot::states(const double* y, BodyState* first) const {
  for (int i = 0; i < links; ++i) {
    const Link& link = tree->link(i);
    first[i] = JointState{Eigen::Map<const Eigen::VectorXd>(y + at_y + link.idx_q, link.nq),
                          Eigen::Map<const Eigen::VectorXd>(y + at_y + nq + link.idx_v, link.nv)};
  }
}

void TreeSlot::record_internal(const double* y, SceneSimulation& out) const {
  out.joint_q.insert(out.joint_q.end(), y + at_y, y + at_y + nq);
  out.joint_v.insert(out.joint_v.end(), y + at_y + nq, y + at_y + nq + nv);
}

void TreeSlot::solve_velocity(double* y) const {
  H_llt.compute(crba_unchecked(*tree, configuration(), ws));
  H_llt.solveInPlace(rhs);
  Eigen::Map<Eigen::VectorXd>(y + at_y + nq, nv) = rhs;
}

void TreeSlot::chart_point_of(const double* v, double half_h) const {
  for (const TreeJoint& j : joints) {
    if (j.kind == TreeJoint::vector) phi[j.v] = half_h * v[j.v];
    if (j.kind == TreeJoint::ball || j.kind == TreeJoint::free) phi.segment<3>(j.v) = half_h * three(v + j.v);
    if (j.kind == TreeJoint::free) {
      const Eigen::Matrix3d R_bar = start_rotation_of(j) * rotvec_to_matrix(phi.segment<3>(j.v));
      phi.segment<3>(j.v + 3) = half_h * (R_bar * three(v + j.v + 3));
    }
  }
}

Eigen::Matrix3d TreeSlot::start_rotation_of(const TreeJoint& j) const { return rotation_at(q_0.data() + j.q + 3); }

void TreeSlot::write_chart_point(const Eigen::VectorXd& chart, double* y) const {
  retract_configuration(q_0.data(), chart.data(), y + at_y);
}

void TreeSlot::turn_quaternion(double* q, const Eigen::Vector3d& w, double h) {
  const double q0[4] = {q[0], q[1], q[2], q[3]};
  times_exp(q0, h * w, q);
}

}  // namespace rigiddyn::detail
