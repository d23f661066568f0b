// A kinematic tree in the scene model (scene/kinds/body_slot.hpp has the members every kind has; tree/ the
// algorithms): one slot for the whole tree, whose links are consecutive bodies of the scene (tree/tree_link.hpp),
// so that the elements load each link as a body while the joints couple them. The slot reads its links'
// kinematics and wrenches as the arrays that start at the k and wrench it is given (its first body's).
//   y (q nq, v nv): the tree's configuration and velocity (tree/tree.hpp);
//   ξ (q̇ in the tangent of q nv, v̇ nv): per joint, an angle's or offset's rate, a ball joint's ω_L, a free joint's
//   (ω_L, ṗ_JL = R_JL v_L); the retraction q ⊕ Θ adds the vector parts and turns a quaternion q ⊗ exp(Θ_ω).
// Newton–Euler is the articulated-body algorithm (Featherstone Table 7.1, tree/aba.hpp) with each link's wrench
// as its external force: f_ext,i = (τ_B + c_L × f_L, f_L), f_L = R_WLᵀ f_W, the moment taken to L's origin. The
// tree's links have no free motion in closed form: compile refuses the splittings and the implicit gyroscopic
// kick for it. A tree of revolute, prismatic and fixed joints (`canonical`) takes the implicit midpoint rule in its
// canonical coordinates (q, p = H(q) v): the variational midpoint method (scene_model.hpp implicit_midpoint_step).
#pragma once
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/kinds/body_slot.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/so3/dexp_inv.hpp"
#include "rigiddyn/so3/quaternion_kernels.hpp"
#include "rigiddyn/tree/aba.hpp"
#include "rigiddyn/tree/crba.hpp"
#include "rigiddyn/tree/forward_kinematics.hpp"
#include "rigiddyn/tree/momentum.hpp"
#include "rigiddyn/tree/tree_link.hpp"
#include "rigiddyn/tree/workspace.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <vector>

namespace rigiddyn::detail {

// One joint's place in the tree's q, v and its kind as the slot moves it
struct TreeJoint {
  enum Kind { vector, ball, free, fixed } kind;  // vector: revolute or prismatic (q + h v)
  int q, v;                                     // offsets of its q and v segments in the tree's q and v
};

struct TreeSlot : SlotPlace {
  static constexpr bool has_mass_flow = false;
  std::shared_ptr<const Tree> tree;
  int links, nq, nv;
  std::vector<TreeJoint> joints;
  std::vector<Eigen::Vector3d> c_L;  // each link's centre of mass in L [m]
  // scratch, sized here (an evaluation allocates nothing)
  mutable TreeWorkspace ws;
  mutable std::vector<Force> f_ext;
  mutable Eigen::VectorXd q_unit, tau;  // q with unit quaternions; the joint forces (none: the elements load links)
  bool canonical = false;  // every joint revolute, prismatic or fixed: q lies in a vector space, p = H(q) v
  bool fill_quaternions = true;  // each evaluation sets the links' q_WB (a user's force may read them; the records do)
  mutable Eigen::VectorXd p_0, p_dot, rhs;  // the midpoint step's p at its start, ṗ at its midpoint, a solve's p
  mutable Eigen::LLT<Eigen::MatrixXd> H_llt;

  TreeSlot(int body, Eigen::Index at_y, Eigen::Index at_xi, std::shared_ptr<const Tree> tree_)
      : SlotPlace{body, at_y, at_xi}, tree(std::move(tree_)), links(tree->num_links()), nq(tree->nq()), nv(tree->nv()),
        ws(*tree), f_ext(links), q_unit(nq), tau(Eigen::VectorXd::Zero(nv)), p_0(nv), p_dot(nv), rhs(nv), H_llt(nv) {
    for (const Link& link : tree->links()) {
      const TreeJoint::Kind kind = std::holds_alternative<SphericalJoint>(link.joint) ? TreeJoint::ball
                                   : std::holds_alternative<FreeJoint>(link.joint)    ? TreeJoint::free
                                   : std::holds_alternative<FixedJoint>(link.joint)   ? TreeJoint::fixed
                                                                                      : TreeJoint::vector;
      joints.push_back({kind, link.idx_q, link.idx_v});
      c_L.push_back(link.inertia.com());
    }
    canonical = std::none_of(joints.begin(), joints.end(),
                             [](const TreeJoint& j) { return j.kind == TreeJoint::ball || j.kind == TreeJoint::free; });
  }
  Eigen::Index y_size() const { return nq + nv; }
  Eigen::Index xi_size() const { return 2 * nv; }

  // the tree's v in y, and its configuration with each quaternion normalised (q_unit)
  Eigen::Map<const Eigen::VectorXd> velocities(const double* y) const { return {y + at_y + nq, nv}; }
  void load_configuration(const double* y) const {
    const double* q = y + at_y;
    for (int i = 0; i < nq; ++i) q_unit[i] = q[i];
    for (const TreeJoint& j : joints) {
      if (j.kind == TreeJoint::ball) normalise_quaternion(q_unit.data() + j.q);
      if (j.kind == TreeJoint::free) normalise_quaternion(q_unit.data() + j.q + 3);
    }
  }
  // R_JL of a free joint from q_unit
  Eigen::Matrix3d free_rotation_of(const TreeJoint& j) const {
    const double* x = q_unit.data() + j.q + 3;
    return Eigen::Quaterniond(x[3], x[0], x[1], x[2]).toRotationMatrix();
  }

  // Each link's kinematics at its centre of mass C (tree forward kinematics, Featherstone §4.2): R_WB = R_WL,
  // p_W = p_WL + R_WL c_L, ω_B = ω_L, v_W = R_WL (v_L + ω_L × c_L) from the link twist [ω_L; v_L] at L's origin;
  // its joint's q (normalised) and v for the joint elements
  void kinematics(const double* y, const StepClock&, BodyKinematics& first) const {
    load_configuration(y);
    forward_kinematics_unchecked(*tree, q_unit, velocities(y), ws);
    BodyKinematics* k = &first;
    for (int i = 0; i < links; ++i) {
      const Eigen::Matrix3d& R_WL = ws.X_W[i].rotation();
      k[i].R_WB = R_WL;
      if (fill_quaternions) k[i].q_WB = Eigen::Quaterniond(R_WL);
      k[i].w_B = ws.v[i].angular;
      k[i].p_W = ws.X_W[i].translation() + R_WL * c_L[i];
      k[i].v_W = R_WL * (ws.v[i].linear + cross_3(ws.v[i].angular, c_L[i]));
      k[i].joint_q = q_unit.data() + tree->link(i).idx_q;
      k[i].joint_v = y + at_y + nq + tree->link(i).idx_v;
    }
  }
  // v̇ (ws.qdd) by the articulated-body algorithm under the links' wrenches, after kinematics at the same y
  const Eigen::VectorXd& accelerations(const double* y, const BodyKinematics& first, const BodyWrench& wrench) const {
    const BodyKinematics* k = &first;
    const BodyWrench* w = &wrench;
    for (int i = 0; i < links; ++i) {
      const Eigen::Vector3d f_L = k[i].R_WB.transpose() * w[i].f_W;
      f_ext[i].linear = f_L;
      f_ext[i].angular = w[i].tau_B + cross_3(c_L[i], f_L);
    }
    return aba_after_kinematics(*tree, velocities(y), tau, f_ext, ws);
  }
  // the tangent of q at y: per joint its rate, ω_L, or (ω_L, R_JL v_L)
  void configuration_tangent(const double* y, double* out) const {
    const double* v = y + at_y + nq;
    for (const TreeJoint& j : joints) {
      if (j.kind == TreeJoint::vector) out[j.v] = v[j.v];
      if (j.kind == TreeJoint::ball || j.kind == TreeJoint::free) {
        for (int i = 0; i < 3; ++i) out[j.v + i] = v[j.v + i];
      }
      if (j.kind == TreeJoint::free) {
        const Eigen::Vector3d p_dot = free_rotation_of(j) * three(v + j.v + 3);
        for (int i = 0; i < 3; ++i) out[j.v + 3 + i] = p_dot[i];
      }
    }
  }

  void rate(const double* y, const StepClock&, const BodyKinematics& k, const BodyWrench& wrench, double* dy) const {
    const Eigen::VectorXd& qdd = accelerations(y, k, wrench);
    const double* x = y + at_y;
    double* dq = dy + at_y;
    for (const TreeJoint& j : joints) {
      if (j.kind == TreeJoint::vector) dq[j.q] = x[nq + j.v];
      if (j.kind == TreeJoint::ball) quat_rate_body(x + j.q, three(x + nq + j.v), dq + j.q);  // q̇ = ½ q ⊗ (ω_L, 0)
      if (j.kind == TreeJoint::free) {
        const Eigen::Vector3d p_dot = free_rotation_of(j) * three(x + nq + j.v + 3);  // ṗ_JL = R_JL v_L
        for (int i = 0; i < 3; ++i) dq[j.q + i] = p_dot[i];
        quat_rate_body(x + j.q + 3, three(x + nq + j.v), dq + j.q + 3);
      }
    }
    for (int i = 0; i < nv; ++i) dq[nq + i] = qdd[i];
  }
  void velocity(const double* y, const StepClock&, const BodyKinematics& k, const BodyWrench& wrench, double* xi) const {
    const Eigen::VectorXd& qdd = accelerations(y, k, wrench);
    configuration_tangent(y, xi + at_xi);
    for (int i = 0; i < nv; ++i) xi[at_xi + nv + i] = qdd[i];
  }
  // q ⊕ Θ joint by joint (vector parts added, q ⊗ exp(Θ_ω) for a quaternion), v + Θ_v
  void retract(const double* y, const double* theta, double* out) const {
    const double* q = y + at_y;
    const double* t = theta + at_xi;
    double* o = out + at_y;
    for (const TreeJoint& j : joints) {
      if (j.kind == TreeJoint::vector) o[j.q] = q[j.q] + t[j.v];
      if (j.kind == TreeJoint::ball) times_exp(q + j.q, three(t + j.v), o + j.q);
      if (j.kind == TreeJoint::free) {
        for (int i = 0; i < 3; ++i) o[j.q + i] = q[j.q + i] + t[j.v + 3 + i];
        times_exp(q + j.q + 3, three(t + j.v), o + j.q + 3);
      }
    }
    for (int i = 0; i < nv; ++i) o[nq + i] = q[nq + i] + t[nv + i];
  }
  void dexp_inv(const double* theta, double* xi) const {
    for (const TreeJoint& j : joints) {
      if (j.kind == TreeJoint::ball || j.kind == TreeJoint::free) dexp_inv_body(theta + at_xi + j.v, xi + at_xi + j.v);
    }
  }
  void project(double* y) const {
    for (const TreeJoint& j : joints) {
      if (j.kind == TreeJoint::ball) normalise_quaternion(y + at_y + j.q);
      if (j.kind == TreeJoint::free) normalise_quaternion(y + at_y + j.q + 3);
    }
  }
  // v += h v̇ at y
  template <class GyroscopicKick>
  void kick(double* y, const BodyKinematics& k, const BodyWrench& wrench, double h, const GyroscopicKick&) const {
    const Eigen::VectorXd& qdd = accelerations(y, k, wrench);
    for (int i = 0; i < nv; ++i) y[at_y + nq + i] += h * qdd[i];
  }
  // q ← q ⊕ h (the tangent of q at fixed v): exact for constant joint rates, a free joint's position by R_JL at the
  // start
  void translate(double* y, double h) const {
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
  void turn(double*, double) const {}  // translate moves the whole configuration
  template <class Rotation>
  void free_rotation(double*, double) const {
    throw std::logic_error("free_flow: a tree has no free motion in closed form (compile refuses the splitting "
                           "methods for it)");
  }
  template <class Kicks>
  double loads_kick(double*, BodyKinematics&, const BodyWrench&, double, const Kicks&) const {
    throw std::logic_error("loads_kick: the splitting methods are refused for a tree (compile)");
  }
  // per link: its q_WB (of R_WB), T = ½ m |v|² + ½ ω·I_C ω, H_C = R_WL I_C ω (its momentum_O_W: about its centre of
  // mass); no pivot reaction is recorded (a fixed base's reaction is the tree's, not a link's)
  void record(const double*, BodyKinematics& first, const BodyWrench&, RecordSums& sums,
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
  // The implicit midpoint rule in the canonical coordinates of a canonical tree (GNI VI.6: the variational
  // integrator of the midpoint discrete Lagrangian L_d = h L((q0 + q1)/2, (q1 − q0)/h) with the midpoint forces,
  // which is the midpoint rule on (q, p)):
  //   q̄ = q0 + (h/2) v̄,   H(q̄) v̄ = p0 + (h/2) ṗ(q̄, v̄, t̄),   q1 = q0 + h v̄,   H(q1) v1 = p0 + h ṗ(q̄, v̄, t̄),
  // ṗ = ∂T/∂q + Q by tree/momentum.hpp under the links' wrenches. Steps of the scene's fixed point:
  // p0 = H(q0) v0 at the step's start y0
  void start_canonical_midpoint(const double* y0) const {
    static const std::vector<Force> none;
    load_configuration(y0);
    forward_kinematics_unchecked(*tree, q_unit, velocities(y0), ws);
    generalized_momentum_after_kinematics(*tree, none, ws);
    p_0 = ws.p;
  }
  // v̄ into the velocities of `next` and q̄ = q0 + (h/2) v̄ into its q (so that the next iterate is a consistent pair:
  // a q̄ one iterate behind v̄ would slow the fixed point to a rate O(√h), H(q̄) depending on q̄ at first order), after
  // the scene's rate at the iterate (its kinematics and links' wrenches in ws and f_ext, q_unit its q̄)
  void canonical_midpoint_velocity(const double* y0, double half_h, double* next) const {
    generalized_momentum_after_kinematics(*tree, f_ext, ws);
    p_dot = ws.p_dot;
    rhs = p_0 + half_h * p_dot;
    solve_velocity(next);
    for (int i = 0; i < nq; ++i) next[at_y + i] = y0[at_y + i] + half_h * next[at_y + nq + i];  // nq = nv here
  }
  // v1 into y1 = 2ȳ − y0, whose q is the step's end q1
  void finish_canonical_midpoint(double h, double* y1) const {
    load_configuration(y1);
    rhs = p_0 + h * p_dot;
    solve_velocity(y1);
  }

  // from and to the links' JointStates (the states of bodies body … body + links − 1)
  void coordinates(const BodyState& first, double* y) const {
    for (int i = 0; i < links; ++i) {
      const Link& link = tree->link(i);
      const auto& s = std::get<JointState>((&first)[i]);
      for (int k = 0; k < link.nq; ++k) y[at_y + link.idx_q + k] = s.q[k];
      for (int k = 0; k < link.nv; ++k) y[at_y + nq + link.idx_v + k] = s.v[k];
    }
  }
  void states(const double* y, BodyState* first) const {
    for (int i = 0; i < links; ++i) {
      const Link& link = tree->link(i);
      first[i] = JointState{Eigen::Map<const Eigen::VectorXd>(y + at_y + link.idx_q, link.nq),
                            Eigen::Map<const Eigen::VectorXd>(y + at_y + nq + link.idx_v, link.nv)};
    }
  }
  // the tree's q and v into the records' joint columns
  void record_internal(const double* y, SceneSimulation& out) const {
    out.joint_q.insert(out.joint_q.end(), y + at_y, y + at_y + nq);
    out.joint_v.insert(out.joint_v.end(), y + at_y + nq, y + at_y + nq + nv);
  }
  Eigen::Index attitude_y() const { return -1; }  // the links' attitudes are not coordinates

 private:
  // v = H(q_unit)⁻¹ rhs (CRBA and a Cholesky solve, no allocation) into the velocities of y
  void solve_velocity(double* y) const {
    H_llt.compute(crba_unchecked(*tree, q_unit, ws));
    H_llt.solveInPlace(rhs);
    Eigen::Map<Eigen::VectorXd>(y + at_y + nq, nv) = rhs;
  }
  // q ← q ⊗ exp(h ω) (exact for a constant ω)
  static void turn_quaternion(double* q, const Eigen::Vector3d& w, double h) {
    const double q0[4] = {q[0], q[1], q[2], q[3]};
    times_exp(q0, h * w, q);
  }
};

// The slot of a whole tree, added with its link 0 (the bodies of its other links add nothing: compile checks that
// they follow it in link order)
template <class Groups>
void add_slot(Groups& groups, int b, const TreeLink& body, Eigen::Index& y, Eigen::Index& xi) {
  if (body.link != 0) return;
  TreeSlot slot(b, y, xi, body.tree);
  y += slot.y_size(), xi += slot.xi_size();
  std::get<std::vector<TreeSlot>>(groups).push_back(std::move(slot));
}

}  // namespace rigiddyn::detail
