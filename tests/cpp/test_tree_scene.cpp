// A kinematic tree as bodies of a scene (tree/tree_link.hpp, scene/kinds/tree_slot.hpp): a one-link tree on a ball
// joint is the pivoted body (the same trajectory to round-off); a double pendulum loaded by the scene's
// UniformGravity runs the same RK4 map as a hand loop around the articulated-body algorithm with the tree's own
// gravity; its energy error falls at the method's order; a free-floating tree keeps its momenta; the links' records
// are the links' motions; springs, dampers and motors in its joints are the joint forces of the articulated-body
// algorithm; bad layouts and the methods a tree cannot take are refused, naming the value.
#include <gtest/gtest.h>

#include "test_numbers.hpp"
#include "invalid_argument_message.hpp"
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"
#include "rigiddyn/so3/exp_log.hpp"
#include "rigiddyn/tree/aba.hpp"
#include "rigiddyn/tree/energy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

namespace {

using namespace rigiddyn;

using rigiddyn::test::kEps;
using test::message_of;

SimulationOptions with(Method method, double dt, std::int64_t steps) {
  SimulationOptions o;
  o.method = method, o.dt = dt, o.steps = steps;
  return o;
}

// Appends every link of `tree` to `scene` (rigiddyn::add_tree) and their joint states (q_i, v_i) of (q, v) to `states`.
void add_tree(Scene& scene, const Tree& tree, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
              std::vector<BodyState>& states) {
  rigiddyn::add_tree(scene, std::make_shared<const Tree>(tree));
  for (const Link& link : tree.links()) {
    states.push_back(JointState{q.segment(link.idx_q, link.nq), v.segment(link.idx_v, link.nv)});
  }
}

SpatialInertia rod(double mass) {  // 1 m along the link's x axis, its centre of mass at the middle
  return SpatialInertia(mass, Eigen::Vector3d(0.5, 0.0, 0.0), Eigen::Vector3d(1e-3, mass / 12, mass / 12).asDiagonal());
}

Tree double_pendulum(const Eigen::Vector3d& gravity = Eigen::Vector3d::Zero()) {
  Tree tree(gravity);
  tree.add_link("upper", -1, RevoluteJoint(Eigen::Vector3d::UnitY()), rod(2.0));
  tree.add_link("lower", 0, RevoluteJoint(Eigen::Vector3d::UnitY()), rod(1.0),
                Transform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 0.0, 0.0)));
  return tree;
}

// `steps` RK4 steps of h [s] of (q̇, v̇) = (v, accel(q, v)) from (q, v), in place: the hand loop
template <class Acceleration>
void hand_rk4(const Acceleration& accel, double h, int steps, Eigen::VectorXd& q, Eigen::VectorXd& v) {
  for (int n = 0; n < steps; ++n) {
    const Eigen::VectorXd k1q = v, k1v = accel(q, v);
    const Eigen::VectorXd k2q = v + 0.5 * h * k1v, k2v = accel(q + 0.5 * h * k1q, k2q);
    const Eigen::VectorXd k3q = v + 0.5 * h * k2v, k3v = accel(q + 0.5 * h * k2q, k3q);
    const Eigen::VectorXd k4q = v + h * k3v, k4v = accel(q + h * k3q, k4q);
    q += h / 6.0 * (k1q + 2.0 * k2q + 2.0 * k3q + k4q);
    v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
  }
}

Scene gravity_scene() {
  Scene scene;
  scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}});
  return scene;
}

// A heavy top: I_C = diag(1, 1.5, 0.5) kg m², 2 kg, its centre of mass 0.3 m along its axis from the pivot at
// p_WO = (0.1, 0.2, 0.3) m, under gravity, spinning fast and tilted, in the scene frame `frame` (none: inertial).
// As a pivoted body, and as a one-link tree on a ball joint placed at O: the same equations (Euler's about O; the
// articulated-body algorithm on one link; a moving frame's fictitious forces and torques on the link as on the
// pivoted body, at its centre of mass with its inertia about it), so the same RK4 map, evaluated in another order.
// Each evaluation rounds by a few ε of the terms (|ω|, |α| ~ 30); the top's flow over 1 s amplifies a perturbation
// by at most e^{L t} with L ≲ |ω| = 20/s... far less in practice for a stable top: its tangent map stays O(|ω| t) (a
// quasi-periodic motion), ~20. 200 steps × 10 ε × 30 × 20 ≈ 3e-10 absolute on ω and v, 1e-11 on the attitude and
// the position: the bounds below.
void expect_the_pivoted_body(const std::optional<SceneFrame>& frame) {
  const Eigen::Vector3d inertia(1.0, 1.5, 0.5), c(0.0, 0.0, 0.3), p_WO(0.1, 0.2, 0.3);
  PivotedBodyState top;
  top.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1.0, 0.2, 0.0).normalized()));
  top.w_B = Eigen::Vector3d(0.3, -0.2, 20.0);

  Scene pivoted = gravity_scene();
  pivoted.frame = frame;
  add_body(pivoted, PivotedBody(RigidBody(2.0, inertia), c, p_WO), "top");
  const SceneSimulation a = simulate(pivoted, {top}, with(Method::rk4, 0.005, 200));

  Tree tree;
  tree.add_link("top", -1, SphericalJoint(), SpatialInertia(2.0, c, inertia.asDiagonal()),
                Transform(Eigen::Matrix3d::Identity(), p_WO));
  Scene linked = gravity_scene();
  linked.frame = frame;
  std::vector<BodyState> states;
  add_tree(linked, tree, Eigen::Vector4d(top.q_WB.coeffs()), top.w_B, states);
  const SceneSimulation b = simulate(linked, states, with(Method::rk4, 0.005, 200));

  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(b.w_B[3 * i + k], a.w_B[3 * i + k], 3e-10) << i;
      EXPECT_NEAR(b.p_W[3 * i + k], a.p_W[3 * i + k], 1e-11) << i;
      EXPECT_NEAR(b.v_W[3 * i + k], a.v_W[3 * i + k], 3e-10) << i;
    }
    // q_WB of the tree is R_WL's quaternion (a sign of its own): compare the rotations
    const Eigen::Quaterniond qa(a.q_WB[4 * i + 3], a.q_WB[4 * i], a.q_WB[4 * i + 1], a.q_WB[4 * i + 2]);
    const Eigen::Quaterniond qb(b.q_WB[4 * i + 3], b.q_WB[4 * i], b.q_WB[4 * i + 1], b.q_WB[4 * i + 2]);
    EXPECT_LT(qa.normalized().angularDistance(qb), 1e-11) << i;
    EXPECT_NEAR(b.total_energy[i], a.total_energy[i], 1e-9 * std::abs(a.total_energy[0])) << i;
  }
}

TEST(TreeScene, OneLinkOnABallJointIsThePivotedBody) { expect_the_pivoted_body(std::nullopt); }

// in a frame F turning at 2 rad/s about an inclined axis (the centrifugal and Coriolis terms compile adds)
TEST(TreeScene, OneLinkOnABallJointIsThePivotedBodyInATurningFrame) {
  expect_the_pivoted_body(SceneFrame::rotating(Eigen::Vector3d(0.2, 0.1, 1.0), 2.0));
}

// The double pendulum loaded by the scene's UniformGravity against a hand RK4 loop of q̈ = ABA(q, q̇) with the tree's
// own gravity: the same equations and the same map (the scene's tree applies the gravity as its base's acceleration
// a_0 = −g too), their arithmetic ordered differently in places, a few ε of m g l ≈ 30 per evaluation at most,
// amplified over 1 s of a chaotic double pendulum released horizontal by at most ~e^{λ t} with λ ≲ 5/s: 400
// evaluations × 4 ε × 30 × e^5 ≈ 1.6e-9, so 1e-8 on the angles and rates.
TEST(TreeScene, DoublePendulumUnderSceneGravityIsTheHandLoopAroundAba) {
  const Eigen::Vector2d q0(0.0, 0.3), v0(0.0, 0.0);
  Scene scene = gravity_scene();
  std::vector<BodyState> states;
  add_tree(scene, double_pendulum(), q0, v0, states);
  const double h = 0.01;
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  SceneState end;
  end.bodies = states;
  for (int n = 0; n < 100; ++n) end = step(compiled, end.bodies, with(Method::rk4, h, 1));

  const Tree tree = double_pendulum(Eigen::Vector3d(0.0, 0.0, -9.81));
  TreeWorkspace ws(tree);
  const Eigen::VectorXd tau = Eigen::VectorXd::Zero(2);
  const auto accel = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v) -> Eigen::VectorXd {
    return aba(tree, q, v, tau, {}, ws);
  };
  Eigen::VectorXd q = q0, v = v0;
  hand_rk4(accel, h, 100, q, v);
  for (int i = 0; i < 2; ++i) {
    const auto& s = std::get<JointState>(end.bodies[i]);
    EXPECT_NEAR(s.q[0], q[i], 1e-8) << i;
    EXPECT_NEAR(s.v[0], v[i], 1e-8) << i;
  }
}

// The links' records are their motions: link 1's centre of mass at p_W = p_WL + R_WL c_L of forward kinematics;
// joint_q and joint_v the tree's q and v; the records' energy the tree's T + V (tree/energy.hpp)
TEST(TreeScene, RecordsAreTheLinksMotionsAndTheTreesEnergy) {
  const Eigen::Vector2d q0(0.4, -0.7), v0(1.5, -2.0);
  Scene scene = gravity_scene();
  std::vector<BodyState> states;
  add_tree(scene, double_pendulum(), q0, v0, states);
  const SceneSimulation r = simulate(scene, states, with(Method::rk4, 0.01, 1));
  const Tree tree = double_pendulum(Eigen::Vector3d(0.0, 0.0, -9.81));
  // upper: R_WL = Ry(q0), c at 0.5 m along its x; lower's origin 1 m along upper's x, its c 0.5 m along its own x
  const Eigen::Matrix3d R0 = Eigen::AngleAxisd(q0[0], Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Matrix3d R1 = R0 * Eigen::AngleAxisd(q0[1], Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Vector3d p1 = R0 * Eigen::Vector3d(1.0, 0.0, 0.0) + R1 * Eigen::Vector3d(0.5, 0.0, 0.0);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.p_W[3 + k], p1[k], 4 * kEps) << k;
  EXPECT_NEAR(r.w_B[3 + 1], v0[0] + v0[1], 4 * kEps);  // ω of the lower link: the sum of the joint rates about y
  ASSERT_EQ(r.joint_q.size(), 4u);  // two records of the tree's q and v
  EXPECT_EQ(r.joint_q[0], q0[0]);
  EXPECT_EQ(r.joint_q[1], q0[1]);
  EXPECT_EQ(r.joint_v[1], v0[1]);
  TreeWorkspace ws(tree);
  const double E = kinetic_energy(tree, q0, v0, ws) + potential_energy(tree, q0, ws);
  EXPECT_NEAR(r.total_energy[0], E, 16 * kEps * 30.0);  // |T|, |V| ≲ 30 J
}

// Each method's global error on the double pendulum released at q = (0.8, -0.4) rad, after 1 s: the joint state at
// h and h/2 against the run of the same method at h/32 (its own error at least 32 times smaller than at h); the
// error falls by 2^p, p the method's order (method.hpp), to within the next term's share: the ratio lies within
// [0.75, 1.25] × 2^p
TEST(TreeScene, GlobalErrorFallsAtEachMethodsOrder) {
  const auto end_state = [](Method method, double h) {
    Scene scene = gravity_scene();
    std::vector<BodyState> states;
    add_tree(scene, double_pendulum(), Eigen::Vector2d(0.8, -0.4), Eigen::Vector2d::Zero(), states);
    const SceneSimulation r = simulate(scene, states, with(method, h, std::lround(1.0 / h)));
    Eigen::Vector4d x;
    const std::size_t n = r.size() - 1;
    x << r.p_W[6 * n + 3], r.p_W[6 * n + 5], r.v_W[6 * n + 3], r.v_W[6 * n + 5];  // the lower link's centre of mass
    return x;
  };
  for (const Method m : {Method::explicit_euler, Method::semi_implicit_euler, Method::rk4, Method::rkmk4,
                         Method::implicit_midpoint}) {
    const int p = method_info(m).order;
    const double h = p == 1 ? 0.002 : 0.01;
    const Eigen::Vector4d reference = end_state(m, h / 32);
    const double ratio = (end_state(m, h) - reference).norm() / (end_state(m, h / 2) - reference).norm();
    EXPECT_GT(ratio, 0.75 * std::pow(2.0, p)) << method_info(m).name;
    EXPECT_LT(ratio, 1.25 * std::pow(2.0, p)) << method_info(m).name;
  }
}

// A free-floating tree (a free joint at the root, a ball joint, a revolute joint) with no element: its linear
// momentum and its angular momentum about W's origin are conserved by the dynamics; RK4 keeps them to its error,
// O(h^4): at h = 1 ms over 1 s with rates ~2 rad/s, |ΔL|, |ΔH| ≲ (2 h)^4 × 10 ~ 1e-10 of their scale, bound 1e-8
TEST(TreeScene, FreeFloatingTreeKeepsItsMomenta) {
  Tree tree;
  tree.add_link("base", -1, FreeJoint(), SpatialInertia(10.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(1.0, 2.0, 2.5).asDiagonal()));
  tree.add_link("arm", 0, SphericalJoint(), rod(2.0), Transform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.5, 0.0, 0.0)));
  tree.add_link("hand", 1, RevoluteJoint(Eigen::Vector3d(0.0, 0.0, 1.0)), rod(0.5),
                Transform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 0.0, 0.0)));
  Eigen::VectorXd q = tree.neutral_configuration(), v(10);
  q.segment<4>(7) = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Eigen::Vector3d(0.0, 1.0, 1.0).normalized())).coeffs();
  v << 0.3, -0.2, 0.5, 0.1, 0.2, -0.1, 1.0, -2.0, 0.5, 2.0;
  Scene scene;
  std::vector<BodyState> states;
  add_tree(scene, tree, q, v, states);
  const SceneSimulation r = simulate(scene, states, with(Method::rk4, 0.001, 1000));
  const std::size_t n = r.size() - 1;
  const Eigen::Map<const Eigen::Vector3d> L0(r.linear_momentum_W.data()), H0(r.angular_momentum_W.data());
  const Eigen::Map<const Eigen::Vector3d> L1(r.linear_momentum_W.data() + 3 * n), H1(r.angular_momentum_W.data() + 3 * n);
  EXPECT_LT((L1 - L0).norm(), 1e-8 * std::max(1.0, L0.norm()));
  EXPECT_LT((H1 - H0).norm(), 1e-8 * std::max(1.0, H0.norm()));
  EXPECT_LT(std::abs(r.kinetic_energy[n] - r.kinetic_energy[0]), 1e-8 * r.kinetic_energy[0]);
  EXPECT_GT((L0).norm(), 1.0);  // the test moves: the tree carries momentum
}

TEST(TreeScene, RefusesTheMethodsATreeCannotTake) {
  Scene scene = gravity_scene();
  std::vector<BodyState> states;
  add_tree(scene, double_pendulum(), Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), states);
  for (const Method m : {Method::splitting_dlm, Method::splitting_dlm_yoshida4, Method::exact_flow_kick, Method::exact,
                         Method::semi_implicit_euler_implicit_gyroscopic}) {
    const std::string message = message_of([&] { compile_scene(scene, m); });
    EXPECT_NE(message.find("method: expected a method that integrates the whole motion"), std::string::npos) << message;
    EXPECT_NE(message.find("'upper'"), std::string::npos) << message;
  }
  for (const Method m : {Method::explicit_euler, Method::semi_implicit_euler, Method::rk4, Method::rkmk4,
                         Method::implicit_midpoint}) {
    const SceneSimulation r = simulate(scene, states, with(m, 0.01, 10));
    EXPECT_EQ(r.size(), 11u) << method_info(m).name;
    EXPECT_FALSE(r.diverged) << method_info(m).name;
  }
}

TEST(TreeScene, RefusesLinksOutOfOrderAndTheTreesOwnGravity) {
  const auto shared = std::make_shared<const Tree>(double_pendulum());
  Scene swapped;
  add_body(swapped, TreeLink{shared, 1}, "lower");
  add_body(swapped, TreeLink{shared, 0}, "upper");
  EXPECT_NE(message_of([&] { compile_scene(swapped, Method::rk4); }).find("expected link 0 of a tree first"), std::string::npos);

  Scene apart;
  add_body(apart, TreeLink{shared, 0}, "upper");
  add_body(apart, Particle(1.0), "ball");
  add_body(apart, TreeLink{shared, 1}, "lower");
  EXPECT_EQ(message_of([&] { compile_scene(apart, Method::rk4); }),
            "bodies[1]: expected link 1 ('lower') of the tree whose link 0 is bodies[0] 'upper' (a tree's links are "
            "consecutive bodies, in order), got a particle");

  // a tree with gravity of its own: refused by add_tree, and by compile when its links were added one by one
  const auto heavy_tree = std::make_shared<const Tree>(double_pendulum(Eigen::Vector3d(0.0, 0.0, -9.81)));
  Scene heavy;
  EXPECT_NE(message_of([&] { rigiddyn::add_tree(heavy, heavy_tree, "pendulum"); })
                .find("tree.gravity: expected zero in a scene (add a UniformGravity element: it loads every link)"),
            std::string::npos);
  EXPECT_TRUE(heavy.bodies.empty());
  add_body(heavy, TreeLink{heavy_tree, 0}, "upper");
  add_body(heavy, TreeLink{heavy_tree, 1}, "lower");
  EXPECT_NE(message_of([&] { compile_scene(heavy, Method::rk4); }).find("the tree's gravity: expected zero in a scene"),
            std::string::npos);
}

// add_tree names the links "<name>.<link>" and adds nothing when one of those names is taken.
TEST(TreeScene, AddTreeNamesItsLinksAndRefusesATakenName) {
  const auto tree = std::make_shared<const Tree>(double_pendulum());
  Scene scene;
  add_body(scene, Particle(1.0), "arm.lower");
  EXPECT_EQ(message_of([&] { rigiddyn::add_tree(scene, tree, "arm"); }),
            "name: expected names for the links that no other body of the scene has ('arm.lower' is body 0's), got \"arm\"");
  EXPECT_EQ(scene.bodies.size(), 1u);
  EXPECT_EQ(rigiddyn::add_tree(scene, tree, "pendulum"), (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(rigiddyn::add_tree(scene, tree), (std::vector<std::size_t>{3, 4}));
  EXPECT_EQ(scene.body_names, (std::vector<std::string>{"arm.lower", "pendulum.upper", "pendulum.lower", "upper", "lower"}));
  EXPECT_NE(message_of([&] { rigiddyn::add_tree(scene, std::make_shared<const Tree>()); })
                .find("tree: expected a tree with at least one link, got a tree with none"),
            std::string::npos);
  EXPECT_EQ(message_of([&] { rigiddyn::add_tree(scene, nullptr); }), "tree: expected a tree, got none");
}

TEST(TreeScene, RefusesJointStatesOfTheWrongSize) {
  Scene scene = gravity_scene();
  std::vector<BodyState> states;
  add_tree(scene, double_pendulum(), Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), states);
  states[1] = JointState{Eigen::Vector2d(0.0, 0.0), Eigen::VectorXd::Zero(1)};
  const std::string message = message_of([&] { simulate(scene, states, with(Method::rk4, 0.01, 1)); });
  EXPECT_NE(message.find("initial[1].q: expected 1 coordinates (the revolute joint of link 'lower'), got 2"), std::string::npos)
      << message;
}

// A telescoping pendulum: an arm hinged about y at W's origin, a slider along the arm's x, a pole hinged about y
// on the slider, each joint on a spring and damper (RevoluteSpringDamper, PrismaticSpringDamper), the slider and the
// pole driven by motors (PrismaticMotor, RevoluteMotor, on from the start), under the scene's gravity, against a
// hand RK4 loop of q̈ = ABA(q, q̇, τ) with the joint forces τ = u − k (q − q0) − c q̇ and the tree's own gravity: the
// elements' wrench pairs are the joint forces (joint_force.hpp). The same map,
// evaluated two ways, to a few ε of the forces' scale per evaluation (m g l and k q ≈ 30), grown over 1 s by at most
// e^{λ t}, λ ≲ 5/s (the double pendulum's bound above): 1e-8 on the coordinates and rates.
Tree telescope(const Eigen::Vector3d& gravity = Eigen::Vector3d::Zero()) {
  Tree tree(gravity);
  tree.add_link("arm", -1, RevoluteJoint(Eigen::Vector3d::UnitY()), rod(2.0));
  tree.add_link("slider", 0, PrismaticJoint(Eigen::Vector3d::UnitX()),
                SpatialInertia(0.5, Eigen::Vector3d(0.1, 0.0, 0.05), Eigen::Vector3d(0.01, 0.02, 0.02).asDiagonal()),
                Transform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.5, 0.0, 0.0)));
  tree.add_link("pole", 1, RevoluteJoint(Eigen::Vector3d(0.0, 1.0, 0.2)), rod(1.0),
                Transform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.2, 0.0, 0.0)));
  return tree;
}

TEST(TreeScene, JointSpringsDampersAndMotorsAreTheJointForcesOfAba) {
  const Eigen::Vector3d q0(0.3, 0.1, -0.5), v0(0.5, -0.2, 1.0);
  const Eigen::Vector3d k(20.0, 40.0, 5.0), rest(0.1, 0.2, 0.3), c(0.5, 1.0, 0.2), u(0.0, 3.0, -1.5);
  Scene scene = gravity_scene();
  std::vector<BodyState> states;
  add_tree(scene, telescope(), q0, v0, states);
  scene.elements.push_back(RevoluteSpringDamper{0, k[0], rest[0], c[0]});
  scene.elements.push_back(PrismaticSpringDamper{1, k[1], rest[1], c[1]});
  scene.elements.push_back(RevoluteSpringDamper{2, k[2], rest[2], c[2]});
  scene.elements.push_back(PrismaticMotor{1, u[1]});
  scene.elements.push_back(RevoluteMotor{2, u[2]});
  const double h = 0.01;
  const SceneSimulation r = simulate(scene, states, with(Method::rk4, h, 100));

  const Tree tree = telescope(Eigen::Vector3d(0.0, 0.0, -9.81));
  TreeWorkspace ws(tree);
  const auto accel = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v) -> Eigen::VectorXd {
    const Eigen::VectorXd tau = (u.array() - k.array() * (q - rest).array() - c.array() * v.array()).matrix();
    return aba(tree, q, v, tau, {}, ws);
  };
  Eigen::VectorXd q = q0, v = v0;
  hand_rk4(accel, h, 100, q, v);
  const std::size_t last = r.size() - 1;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(r.joint_q[3 * last + i], q[i], 1e-8) << i;
    EXPECT_NEAR(r.joint_v[3 * last + i], v[i], 1e-8) << i;
  }
  // the springs' potential ½ k (q − q0)² in the records' potential energy, with gravity's
  TreeWorkspace ws0(tree);
  const double V_springs = 0.5 * (k.array() * (q0 - rest).array().square()).sum();
  EXPECT_NEAR(r.potential_energy[0], potential_energy(tree, q0, ws0) + V_springs, 16 * kEps * 30.0);
}

// A joint element on a body that is no tree link, or on a link whose joint is of another kind, is refused naming
// the element's body; a bad value naming its field
TEST(TreeScene, JointElementsRefuseBodiesWithoutTheirJoint) {
  Scene scene;
  std::vector<BodyState> states;
  add_body(scene, RigidBody(1.0, Eigen::Vector3d(1.0, 1.0, 1.0)), "box");
  add_tree(scene, telescope(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), states);
  const auto refused = [&](const Element& element) {
    Scene with = scene;
    with.elements.push_back(element);
    return message_of([&] { compile_scene(with, Method::rk4); });
  };
  EXPECT_NE(refused(RevoluteSpringDamper{0, 1.0, 0.0, 0.0}).find("body: expected a link of a tree"), std::string::npos);
  EXPECT_NE(refused(RevoluteSpringDamper{2, 1.0, 0.0, 0.0}).find("'slider', whose joint is prismatic"), std::string::npos);
  EXPECT_NE(refused(PrismaticSpringDamper{1, 1.0, 0.0, 0.0}).find("'arm', whose joint is revolute"), std::string::npos);
  EXPECT_NE(refused(RevoluteSpringDamper{1, -1.0, 0.0, 0.0}).find("stiffness: expected a finite number >= 0"), std::string::npos);
  EXPECT_NE(refused(RevoluteMotor{2, 1.0}).find("'slider', whose joint is prismatic"), std::string::npos);
  EXPECT_NE(refused(PrismaticMotor{2, std::nan("")}).find("force: expected a finite number"), std::string::npos);
  EXPECT_NE(refused(SphericalSpringDamper{2, 1.0}).find("with a spherical joint, got 2 ('slider', whose joint is prismatic)"),
            std::string::npos);
}

// A body on a ball joint (principal axes along L's, centre of mass at the joint) twisted by φ0 = 1.5 rad about its
// principal axis x from the rest attitude q0 = exp(rest_rotation), on a torsion spring k: its rotation from rest
// stays about x (the couple −k φ has no other component, and ω × I ω = 0 about a principal axis), so
// φ(t) = φ0 cos(√(k/I_x) t) exactly, at any amplitude below π. RK4 integrates the joint's quaternion (not linear in
// φ), at hω = 0.004 in its asymptotic range: the error at h is at most twice its step-doubling estimate
// 16/15 |φ_h − φ_h/2|, plus a few ε a step. Its potential is ½ k φ².
TEST(TreeScene, ABallJointsSpringTwistsItsLinkAsTheClosedForm) {
  auto tree = std::make_shared<Tree>();
  tree->add_link("ball", -1, SphericalJoint(), SpatialInertia(3.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.6, 0.9, 1.2).asDiagonal()));
  Scene scene;
  add_tree(scene, tree);
  SphericalSpringDamper spring{0, 2.4};
  spring.rest_rotation = Eigen::Vector3d(0.2, -0.5, 0.3);
  scene.elements.push_back(spring);
  const Eigen::Quaterniond q0 = rotvec_to_quat(spring.rest_rotation);
  const Eigen::Quaterniond start = q0 * rotvec_to_quat(Eigen::Vector3d(1.5, 0.0, 0.0));
  const std::vector<BodyState> initial{JointState{Eigen::Vector4d(start.coeffs()), Eigen::Vector3d::Zero()}};
  const SceneSimulation r = simulate(scene, initial, with(Method::rk4, 0.002, 1000));
  SimulationOptions halved = with(Method::rk4, 0.001, 2000);
  halved.record_every = 2;
  const SceneSimulation r_half = simulate(scene, initial, halved);
  const auto rotation_from_rest = [&](const SceneSimulation& run, std::size_t i) {
    const double* q = run.joint_q.data() + 4 * i;
    return quat_to_rotvec(q0.conjugate() * Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized());
  };
  const double omega = std::sqrt(2.4 / 0.6);
  double error = 0.0, estimate = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Eigen::Vector3d phi = rotation_from_rest(r, i);
    error = std::max(error, std::abs(phi.x() - 1.5 * std::cos(omega * r.t[i])));
    estimate = std::max(estimate, 16.0 / 15.0 * std::abs(phi.x() - rotation_from_rest(r_half, i).x()));
    EXPECT_NEAR(r.potential_energy[i], 0.5 * 2.4 * phi.squaredNorm(), 16 * kEps * 2.7) << "t = " << r.t[i];
  }
  EXPECT_LE(error, 2.0 * estimate + 1000 * 8 * kEps * 1.5);
  scene.elements[0] = SphericalSpringDamper{0, 2.4, Eigen::Vector3d(0.0, NAN, 0.0)};
  EXPECT_NE(message_of([&] { compile_scene(scene, Method::rk4); }).find("rest_rotation: expected finite values"),
            std::string::npos);
}

}  // namespace
