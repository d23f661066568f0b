// A Controller of a scene run (scene/controller.hpp) and its shipped laws (scene/control_laws.hpp): the law sees
// t0 + k period exactly; a held thrust is integrated as exactly as the piecewise-constant load it is (no step
// straddles a sample); held wheel torques spin a gyrostat as the closed form says; a commanded ReactionWheel speed
// is reached by its ramp; commanded joint torques are held as motor windows; bad inputs are named.
#include <gtest/gtest.h>

#include "test_numbers.hpp"
#include "invalid_argument_message.hpp"
#include "rigiddyn/scene/control_laws.hpp"
#include "rigiddyn/scene/controller.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

using rigiddyn::test::kEps;

// A 2 kg rigid body with a thruster (a ScheduledLoads without a schedule: the controller commands it).
Scene thruster_scene() {
  Scene scene;
  scene.bodies = {RigidBody(2.0, Eigen::Vector3d(0.5, 0.7, 0.9))};
  scene.elements.push_back(ScheduledLoads{0, {}, Eigen::Vector3d::Zero()});
  return scene;
}

SimulationOptions rk4(double dt, std::int64_t steps, double t0 = 0.0) {
  SimulationOptions o;
  o.method = Method::rk4;
  o.dt = dt;
  o.steps = steps;
  o.t0 = t0;
  return o;
}

using test::message_of;

TEST(Controller, LawSeesTheExactSampleTimes) {
  std::vector<double> seen;
  const Controller controller{0.3, [&](const SampledState& s) {
                                seen.push_back(s.t);
                                return ActuatorCommands{};
                              }};
  const double t0 = 0.7;
  simulate(compile_scene(thruster_scene(), Method::rk4), {RigidBodyState{}}, rk4(0.125, 40, t0), controller);
  std::vector<double> expected;  // the run ends at t0 + 5 s: samples k = 0 .. 16
  for (int k = 0; k <= 16; ++k) expected.push_back(t0 + static_cast<double>(k) * 0.3);
  EXPECT_EQ(seen, expected);
}

// f_k = (k + 1) N held on [t_k, t_k+1), period 0.3 s, dt 0.2 s: v is piecewise linear and rk4 integrates each
// piece exactly, so v(t) = (1/m) [T k (k + 1)/2 + (k + 1)(t − k T)] to round-off (4 eps |v| a step).
TEST(Controller, HeldThrustIsIntegratedExactly) {
  const double period = 0.3, m = 2.0;
  const Controller controller{period, [&](const SampledState& s) {
                                const double k = std::round(s.t / period);
                                return ActuatorCommands{{}, {{0, Eigen::Vector3d(k + 1.0, 0.0, 0.0)}}, {}};
                              }};
  const std::int64_t steps = 30;
  const SceneSimulation r =
      simulate(compile_scene(thruster_scene(), Method::rk4), {RigidBodyState{}}, rk4(0.2, steps), controller);
  for (std::size_t i = 0; i < r.size(); ++i) {
    const double t = r.t[i], k = std::floor(t / period + 1e-9);
    const double v = (period * k * (k + 1.0) / 2.0 + (k + 1.0) * (t - k * period)) / m;
    EXPECT_NEAR(r.v_W[3 * i], v, 4.0 * kEps * static_cast<double>(steps) * std::max(v, 1.0)) << "t = " << t;
  }
}

// A motor torque u held on the z wheel of a gyrostat at rest: A_zz ω̇_z = −u, so ω_z = −u t / A_zz, exact for rk4
// (linear in t); the wheel spins up the other way and the total angular momentum stays zero.
TEST(Controller, HeldWheelTorquesSpinTheGyrostat) {
  const RigidBody body(100.0, Eigen::Vector3d(10.0, 12.0, 15.0));
  Wheel wheel;
  wheel.inertia = 0.05;
  const Gyrostat sat(body, {wheel});
  Scene scene;
  scene.bodies = {sat};
  const double u = 0.01;
  const Controller controller{0.25, [&](const SampledState& s) {
                                EXPECT_EQ(s.wheel_speed.size(), 1u);
                                return ActuatorCommands{{u}, {}, {}};
                              }};
  GyrostatState x0;
  x0.wheel_speeds = Eigen::VectorXd::Zero(1);
  const SceneSimulation r = simulate(compile_scene(scene, Method::rk4), {x0}, rk4(0.1, 20), controller);
  const double A_zz = sat.transverse_inertia()(2, 2);
  EXPECT_NEAR(r.w_B.back(), -u * r.t.back() / A_zz, 64 * kEps * u * r.t.back() / A_zz);
  EXPECT_GT(r.wheel_speed.back(), 0.0);
  // H = R (A ω + h_w) = 0: the sum of two terms of size u t, to their round-off
  EXPECT_NEAR(r.angular_momentum_W.back(), 0.0, 16 * kEps * u * r.t.back());
}

TEST(Controller, BadInputsAreNamed) {
  const CompiledScene compiled = compile_scene(thruster_scene(), Method::rk4);
  const auto run = [&](const Controller& c) { simulate(compiled, {RigidBodyState{}}, rk4(0.1, 10), c); };
  const auto none = [](const SampledState&) { return ActuatorCommands{}; };
  EXPECT_NE(message_of([&] { run(Controller{0.0, none}); }).find("controller.period: expected a finite number > 0"),
            std::string::npos);
  EXPECT_NE(message_of([&] { run(Controller{0.1, {}}); }).find("controller.law: expected a law"), std::string::npos);
  const auto commands = [&](ActuatorCommands c) { return Controller{0.25, [c](const SampledState&) { return c; }}; };
  EXPECT_NE(message_of([&] { run(commands({{1.0}, {}, {}})); })
                .find("controller.law(t=0): expected wheel_torque of 0 values (one per gyrostat wheel), got 1"),
            std::string::npos);
  EXPECT_NE(message_of([&] { run(commands({{}, {{2, Eigen::Vector3d::Zero()}}, {}})); })
                .find("controller.law(t=0)[2]: expected the index of an element in [0, 1)"),
            std::string::npos);
  EXPECT_NE(message_of([&] { run(commands({{}, {{0, Eigen::Vector3d(NAN, 0.0, 0.0)}}, {}})); })
                .find("controller.law(t=0)[0]: expected finite values"),
            std::string::npos);
  Scene gravity;
  gravity.bodies = {RigidBody(1.0, Eigen::Vector3d(1.0, 1.0, 1.0))};
  gravity.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}});
  EXPECT_NE(message_of([&] {
              simulate(compile_scene(gravity, Method::rk4), {RigidBodyState{}}, rk4(0.1, 10),
                       commands({{}, {{0, Eigen::Vector3d::Zero()}}, {}}));
            }).find("expected a MagneticDipole or a ScheduledLoads"),
            std::string::npos);
}

// A commanded ReactionWheel speed is reached at the next sample by a constant-rate ramp: about the body's principal
// axis z (at rest) the body turns at w_z = −J (Ω(t) − Ω(0))/I, exactly for rk4 (the rate is constant over each
// sub-step); a speed to another element names it and its type, a non-finite one the sample time.
TEST(Controller, CommandedWheelSpeedIsReachedAtTheNextSample) {
  Scene scene;
  scene.bodies = {RigidBody(10.0, Eigen::Vector3d(2.0, 3.0, 4.0))};
  ReactionWheel wheel;
  wheel.body = 0, wheel.axis_B = Eigen::Vector3d::UnitZ(), wheel.inertia = 0.25, wheel.speed = 1.0;
  scene.elements.push_back(wheel);
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  const Controller speed_loop{0.4, [](const SampledState& s) {
                                return ActuatorCommands{{}, {}, {{0, s.t < 0.2 ? 3.0 : -1.0}}};
                              }};
  const SceneSimulation r = simulate(compiled, {RigidBodyState{}}, rk4(0.08, 15), speed_loop);
  const double w_max = 0.25 * 2.0 / 4.0;
  for (std::size_t i = 0; i < r.t.size(); ++i) {  // Ω: 1 → 3 over [0, 0.4], 3 → −1 over [0.4, 0.8], then −1
    const double t = r.t[i];
    const double omega = t <= 0.4 ? 1.0 + 5.0 * t : t <= 0.8 ? 3.0 - 10.0 * (t - 0.4) : -1.0;
    EXPECT_NEAR(r.w_B[3 * i + 2], -0.25 * (omega - 1.0) / 4.0, 4 * kEps * 16 * w_max) << "t = " << t;
  }
  const auto run = [&](const Scene& s, double speed) {
    simulate(compile_scene(s, Method::rk4), {RigidBodyState{}}, rk4(0.1, 3),
             Controller{0.1, [speed](const SampledState&) { return ActuatorCommands{{}, {}, {{0, speed}}}; }});
  };
  EXPECT_NE(message_of([&] { run(thruster_scene(), 1.0); })
                .find("controller.law(t=0)[0]: expected a ReactionWheel (a speed [rad/s]), a RevoluteMotor (a torque "
                      "[N m]) or a PrismaticMotor (a force [N]), the elements that take a number, got element 0 (a "
                      "ScheduledLoads)"),
            std::string::npos);
  EXPECT_NE(message_of([&] { run(scene, NAN); }).find("controller.law(t=0)[0]: expected a finite number"),
            std::string::npos);
}

// A double pendulum of rods (1 m, centre of mass at the middle) hinged about y, under gravity (element 0), with the
// joint motors `motors` after it.
Scene motored_pendulum(const std::vector<RevoluteMotor>& motors) {
  const auto rod = [](double mass) {
    return SpatialInertia(mass, Eigen::Vector3d(0.5, 0.0, 0.0), Eigen::Vector3d(1e-3, mass / 12, mass / 12).asDiagonal());
  };
  auto tree = std::make_shared<Tree>();
  tree->add_link("upper", -1, RevoluteJoint(Eigen::Vector3d::UnitY()), rod(2.0));
  tree->add_link("lower", 0, RevoluteJoint(Eigen::Vector3d::UnitY()), rod(1.0),
                 Transform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 0.0, 0.0)));
  Scene scene;
  add_tree(scene, tree);
  scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}});
  for (const RevoluteMotor& motor : motors) scene.elements.push_back(motor);
  return scene;
}

// A PD law on the joints (τ_k = −k_p q − k_d v at each sample, from the sampled joint_q and joint_v) commanding a
// RevoluteMotor in each is the run of the same torques as motor windows [t_k, t_k+1): the same switch times, the same
// wrenches in the same order, so the same arithmetic, bit for bit; the law sees the run's joint state at t_k.
TEST(Controller, CommandedJointTorquesAreHeldAsMotorWindows) {
  RevoluteMotor upper, lower;
  upper.body = 0, lower.body = 1;
  const double period = 0.05;
  const std::vector<BodyState> initial{JointState{Eigen::VectorXd::Constant(1, 0.4), Eigen::VectorXd::Zero(1)},
                                       JointState{Eigen::VectorXd::Constant(1, -0.3), Eigen::VectorXd::Constant(1, 1.0)}};
  std::vector<RevoluteMotor> windows;
  const Controller pd{period, [&](const SampledState& s) {
                        EXPECT_EQ(s.joint_q.size(), 2u);
                        ActuatorCommands c;
                        for (int j = 0; j < 2; ++j) {
                          const double tau = -20.0 * s.joint_q[j] - 3.0 * s.joint_v[j];
                          c.scalars.push_back({1 + j, tau});
                          RevoluteMotor window;
                          const double k = std::round(s.t / period);  // t_k = k period, as the run computes it
                          window.body = j, window.torque = tau, window.t_start = k * period, window.t_end = (k + 1) * period;
                          windows.push_back(window);
                        }
                        return c;
                      }};
  const SimulationOptions o = rk4(0.02, 50);  // samples every 2.5 steps: the steps are split at them
  const SceneSimulation controlled = simulate(compile_scene(motored_pendulum({upper, lower}), Method::rk4), initial, o, pd);
  ASSERT_EQ(windows.size(), 2u * 20u);
  const SceneSimulation windowed = simulate(compile_scene(motored_pendulum(windows), Method::rk4), initial, o);
  EXPECT_EQ(controlled.joint_q, windowed.joint_q);
  EXPECT_EQ(controlled.joint_v, windowed.joint_v);
  SampledState seen;
  simulate(compile_scene(motored_pendulum({upper}), Method::rk4), initial, rk4(0.02, 10),
           Controller{0.1, [&](const SampledState& s) {
                        if (s.t > 0.0) seen = s;
                        return ActuatorCommands{};
                      }});
  const SceneSimulation free = simulate(compile_scene(motored_pendulum({upper}), Method::rk4), initial, rk4(0.02, 10));
  EXPECT_EQ(seen.joint_q, std::vector<double>(free.joint_q.begin() + 2 * 5, free.joint_q.begin() + 2 * 6));  // t = 0.1 s
  EXPECT_EQ(seen.joint_v, std::vector<double>(free.joint_v.begin() + 2 * 5, free.joint_v.begin() + 2 * 6));
}

// The PD law's error is the rotation vector to first order, 2 sin(angle/2) about the axis, and its wheel torques
// make the body torque −k_p e − k_d ω through the allocation.
TEST(Controller, PDAttitudeLawCommandsThePDTorque) {
  const Eigen::Quaterniond q_WB(Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()));
  const Eigen::Vector3d e = PDAttitudeLaw::error(q_WB, Eigen::Quaterniond::Identity());
  EXPECT_NEAR(e.x(), 2.0 * std::sin(0.05), 4 * kEps);
  EXPECT_EQ(e.y(), 0.0);
  const PDAttitudeLaw law(2.0, 3.0, -Eigen::MatrixXd::Identity(3, 3), Eigen::Quaterniond::Identity(), 0);
  SampledState s;
  s.p_W = {0.0, 0.0, 0.0}, s.v_W = {0.0, 0.0, 0.0}, s.w_B = {0.0, 0.5, 0.0};
  s.q_WB = {q_WB.x(), q_WB.y(), q_WB.z(), q_WB.w()};
  const ActuatorCommands c = law(s);
  ASSERT_EQ(c.wheel_torque.size(), 3u);
  EXPECT_NEAR(c.wheel_torque[0], 2.0 * e.x(), 4 * kEps);  // u = −τ: the body's torque is −u
  EXPECT_NEAR(c.wheel_torque[1], 3.0 * 0.5, 4 * kEps);
}

}  // namespace
}  // namespace rigiddyn
