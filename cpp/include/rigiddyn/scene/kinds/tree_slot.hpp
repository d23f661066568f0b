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
// kick for it. The implicit midpoint rule takes a tree as its variational midpoint method (scene_model.hpp
// implicit_midpoint_step; the steps below).
#pragma once
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/kinds/body_slot.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/so3/dexp_inv.hpp"
#include "rigiddyn/so3/quaternion_kernels.hpp"
#include "rigiddyn/tree/aba.hpp"
#include "rigiddyn/tree/forward_kinematics.hpp"
#include "rigiddyn/tree/tree_link.hpp"
#include "rigiddyn/tree/workspace.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

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
  static constexpr bool sets_rotation_matrices = true;  // kinematics sets each link's R_WB (scene_model.hpp)
  std::shared_ptr<const Tree> tree;
  int links, nq, nv;
  std::vector<TreeJoint> joints;
  std::vector<Eigen::Vector3d> c_L;  // each link's centre of mass in L [m]
  // scratch, sized here (an evaluation allocates nothing)
  mutable TreeWorkspace ws;
  mutable std::vector<Force> f_ext;
  mutable Eigen::VectorXd q_unit, tau;  // q with unit quaternions; the joint forces (none: the elements load links)
  mutable const double* q_at = nullptr;  // the configuration load_configuration read: q_unit, or y's own q
  bool has_quaternions = false;          // a ball or free joint
  bool fill_quaternions = true;  // each evaluation sets the links' q_WB (a user's force may read them; the records do)
  mutable bool unloaded = false;   // no link has a wrench (note_wrenches)
  // the variational midpoint step's q and p at its start, the chart points φ̄ of q̄ and φ₁ of q₁, F and p̄ at q̄, a
  // solve's right side
  mutable Eigen::VectorXd q_0, p_0, phi, phi_1, force, p_bar, rhs;
  mutable Eigen::LLT<Eigen::MatrixXd> H_llt;

  TreeSlot(int body, Eigen::Index at_y, Eigen::Index at_xi, std::shared_ptr<const Tree> tree_);
  Eigen::Index y_size() const { return nq + nv; }
  Eigen::Index xi_size() const { return 2 * nv; }

  // the tree's v in y, and its configuration with each quaternion normalised (configuration(): q_unit, or y's own q
  // when the tree has no quaternion)
  Eigen::Map<const Eigen::VectorXd> velocities(const double* y) const { return {y + at_y + nq, nv}; }
  Eigen::Map<const Eigen::VectorXd> configuration() const { return {q_at, nq}; }
  void load_configuration(const double* y) const {
    const double* q = y + at_y;
    q_at = has_quaternions ? q_unit.data() : q;
    if (!has_quaternions) return;
    for (int i = 0; i < nq; ++i) q_unit[i] = q[i];
    for (const TreeJoint& j : joints) {
      if (j.kind == TreeJoint::ball) normalise_quaternion(q_unit.data() + j.q);
      if (j.kind == TreeJoint::free) normalise_quaternion(q_unit.data() + j.q + 3);
    }
  }
  // R_JL of a free joint from configuration()
  Eigen::Matrix3d free_rotation_of(const TreeJoint& j) const { return rotation_at(q_at + j.q + 3); }

  // Each link's kinematics at its centre of mass C (tree forward kinematics, Featherstone §4.2): R_WB = R_WL,
  // p_W = p_WL + R_WL c_L, ω_B = ω_L, v_W = R_WL (v_L + ω_L × c_L) from the link twist [ω_L; v_L] at L's origin;
  // its joint's q (normalised) and v for the joint elements
  void kinematics(const double* y, const StepClock&, BodyKinematics& first) const {
    load_configuration(y);
    forward_kinematics_unchecked(*tree, configuration(), velocities(y), ws);
    BodyKinematics* k = &first;
    for (int i = 0; i < links; ++i) {
      const Eigen::Matrix3d& R_WL = ws.X_W[i].rotation();
      k[i].R_WB = R_WL;
      if (fill_quaternions) k[i].q_WB = Eigen::Quaterniond(R_WL);
      k[i].w_B = ws.v[i].angular;
      k[i].p_W = ws.X_W[i].translation() + R_WL * c_L[i];
      k[i].v_W = R_WL * (ws.v[i].linear + cross_3(ws.v[i].angular, c_L[i]));
      k[i].joint_q = q_at + joints[i].q;  // joints[i]: link i's
      k[i].joint_v = y + at_y + nq + joints[i].v;
    }
  }
  // The tree applies a uniform gravity g_W [m/s²] on all its links itself, as its base's acceleration a₀ = −g
  // (Featherstone §5.3: the same motion as a force m g at each centre of mass, at no cost per link); the gravity
  // element then leaves their wrenches out (UniformGravityTerm::leave_to_tree, scene_model.hpp)
  void apply_gravity(const Eigen::Vector3d& g_W);
  // Whether the elements left every link without a wrench (sum of |components| exactly 0: a NaN or any non-zero
  // component counts as one), from the links' wrenches; the scene model notes it after the elements add theirs, at
  // each evaluation (the tree's own gravity is not a wrench: apply_gravity)
  void note_wrenches(const BodyWrench& first) const {
    const BodyWrench* w = &first;
    double sum = 0.0;
    for (int i = 0; i < links; ++i) sum += w[i].f_W.cwiseAbs().sum() + w[i].tau_B.cwiseAbs().sum();
    unloaded = sum == 0.0;
  }
  // v̇ (ws.qdd) by the articulated-body algorithm under the links' wrenches, after kinematics and note_wrenches at the
  // same y: their forces in the links' frames (external_forces: f_ext, or none when every link is unloaded)
  const Eigen::VectorXd& accelerations(const double* y, const BodyKinematics& first, const BodyWrench& wrench) const {
    if (unloaded) return aba_after_kinematics(*tree, velocities(y), tau, no_external_forces(), ws);
    const BodyKinematics* k = &first;
    const BodyWrench* w = &wrench;
    for (int i = 0; i < links; ++i) {
      const Eigen::Vector3d f_L = k[i].R_WB.transpose() * w[i].f_W;
      f_ext[i].linear = f_L;
      f_ext[i].angular = w[i].tau_B + cross_3(c_L[i], f_L);
    }
    return aba_after_kinematics(*tree, velocities(y), tau, f_ext, ws);
  }
  // the links' forces of the last accelerations
  const std::vector<Force>& external_forces() const { return unloaded ? no_external_forces() : f_ext; }
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
    retract_configuration(q, t, o);
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
  void translate(double* y, double h) const;
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
              Eigen::Vector3d& momentum_first, Eigen::Vector3d& reaction_first) const;
  // The variational midpoint method (Marsden & West 2001; GNI VI.6) on the tree's configuration group, each joint
  // its own factor: R for a revolute or prismatic joint, SO(3) for a ball joint, SO(3) × R³ for a free joint (its
  // rotation and its position p in J). A step from q₀ to q₁ follows the curve of constant joint velocity: ξ = log(R₀ᵀ
  // R₁) for a rotation (its body rate ξ/h), the straight line for a vector part; the discrete Lagrangian is the
  // midpoint rule on it, L_d(q₀, q₁) = h L(q̄, w), q̄ = q₀ ⊕ ξ/2 (q₀ ⊗ exp(ξ/2), (p₀ + p₁)/2, …), w = ξ/h (a free
  // joint's v_L = R̄ᵀ (p₁ − p₀)/h), with the forces at q̄ (the discrete Lagrange–d'Alembert principle). Its discrete
  // Euler–Lagrange equations p₀ = −D₁L_d, p₁ = D₂L_d in the body momenta p = H(q) v (tree/momentum.hpp), with
  // F = ∂T/∂q + Q at q̄ along body perturbations at fixed v (ws.p_dot of generalized_momentum_after_kinematics), J_l
  // the left Jacobian (so3/jacobian.hpp; exp(ξ + δ) = exp(ξ) exp(J_l(ξ)ᵀ δ)) and φ̄ = ξ/2, read per joint:
  //   revolute, prismatic:  p̄ = p₀ + (h/2) F,                               p₁ = p₀ + h F
  //   ball:                 p̄ = J_l(ξ)ᵀ (p₀ + h exp(φ̄) F) − (h/2) J_l(φ̄) F,  J_l(ξ) p₁ = p̄ + (h/2) J_l(φ̄) F
  //   free, position:       p̄_v = R̄ᵀ R₀ p₀_v + (h/2) F_v,                  p₁_v = R₁ᵀ R̄ (p̄_v + (h/2) F_v)
  //   free, rotation:       as a ball joint with F_ω − v̄_L × p̄_v (v_L depends on R̄),
  // then H(q̄) v̄ = p̄ (v̄ = w). L_d is invariant under the symmetries of L (a rigid motion of a floating tree moves
  // q₀ and q₁ alike), so the discrete Noether theorem keeps their momenta (a floating tree's linear and angular
  // momenta, a vertical hinge's under gravity) to round-off; the map is symplectic and symmetric, of order 2; on a
  // tree of revolute, prismatic and fixed joints it is the midpoint rule on (q, p). Steps of the scene's fixed point:
  // p₀ = H(q₀) v₀ at the step's start y0, and the first iterate (q₀ ⊕ φ̄, v₀) with φ̄ = (h/2) ψ(v₀) into mid (a
  // consistent pair: from φ̄ = 0 the first iterate would miss the rotations' terms in ξ, a larger first correction)
  void start_variational_midpoint(const double* y0, double half_h, double* mid) const;
  // One iterate, after the scene's rate at ȳ = mid (its kinematics in ws, the links' forces external_forces(),
  // configuration() its q̄ = q_0 ⊕ φ̄): p̄ from F(ȳ) by the equations above, v̄ = H(q̄)⁻¹ p̄ into `next` and, with φ̄
  // = (h/2) ψ for the chart rate ψ of v̄ (v̄; a free joint's R̄ v̄_L for its position), its configuration q_0 ⊕ φ̄
  // (the pair consistent: a q̄ one iterate behind v̄ would slow the fixed point to a rate O(√h), H(q̄) depending on q̄
  // at first order)
  void variational_midpoint_iterate(const double* mid, double half_h, double* next) const;
  // An iterate whose v̄ was changed (the scene's Anderson mixing) takes its configuration q_0 ⊕ φ̄ from v̄ again
  void recenter_variational_midpoint(double half_h, double* mid) const;
  // q₁ = q_0 ⊕ 2φ̄ and v₁ = H(q₁)⁻¹ p₁ into y1 (whose other coordinates are 2ȳ − y0)
  void finish_variational_midpoint(double h, double* y1) const;

  // from and to the links' JointStates (the states of bodies body … body + links − 1)
  void coordinates(const BodyState& first, double* y) const;
  void states(const double* y, BodyState* first) const;
  // the tree's q and v into the records' joint columns
  void record_internal(const double* y, SceneSimulation& out) const;
  Eigen::Index attitude_y() const { return -1; }  // the links' attitudes are not coordinates

 private:
  // v = H(configuration())⁻¹ rhs (CRBA and a Cholesky solve, no allocation) into the velocities of y
  void solve_velocity(double* y) const;
  // φ̄ = (h/2) ψ for the joint velocities v: the chart rate ψ = v, a free joint's position rate R̄ v_L (R̄ = R₀ exp(φ̄_ω))
  void chart_point_of(const double* v, double half_h) const;
  // R_JL of a free joint in q_0
  Eigen::Matrix3d start_rotation_of(const TreeJoint& j) const;
  // the rotation matrix of the quaternion (x, y, z, w) at x
  static Eigen::Matrix3d rotation_at(const double* x) {
    return Eigen::Quaterniond(x[3], x[0], x[1], x[2]).toRotationMatrix();
  }
  // o ← q ⊕ t for a configuration q and a tangent t of the joints (indexed as v): vector parts added, a quaternion
  // q ⊗ exp(t_ω), a free joint's position p + t_p
  void retract_configuration(const double* q, const double* t, double* o) const {
    for (const TreeJoint& j : joints) {
      if (j.kind == TreeJoint::vector) o[j.q] = q[j.q] + t[j.v];
      if (j.kind == TreeJoint::ball) times_exp(q + j.q, three(t + j.v), o + j.q);
      if (j.kind == TreeJoint::free) {
        for (int i = 0; i < 3; ++i) o[j.q + i] = q[j.q + i] + t[j.v + 3 + i];
        times_exp(q + j.q + 3, three(t + j.v), o + j.q + 3);
      }
    }
  }
  // the q of y ← q_0 ⊕ φ, the chart of the step
  void write_chart_point(const Eigen::VectorXd& chart, double* y) const;
  // q ← q ⊗ exp(h ω) (exact for a constant ω)
  static void turn_quaternion(double* q, const Eigen::Vector3d& w, double h);
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
