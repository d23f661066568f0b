// The Gyrostat body kind (models/gyrostat.hpp, scene/kinds/gyrostat_slot.hpp): a wheel spun up from rest about a
// principal axis turns the body back by exactly −J/I₃₃ times its angle (RK4 exact on the linear ω(t), Ω(t));
// the torque-free gyrostat keeps each wheel's absolute spin a·ω + Ω to round-off and its T and H to the method's
// error; the records agree with kinetic_energy and angular_momentum_B of the state; bad input is refused naming
// the value; the methods and frames it cannot take are refused. The numpy reference comparison is
// tests/python/test_gyrostat.py.
#include <gtest/gtest.h>

#include "test_numbers.hpp"
#include "invalid_argument_message.hpp"
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace {

using namespace rigiddyn;

using rigiddyn::test::kEps;

using test::message_of;

Scene one(const Body& body) {
  Scene s;
  s.bodies = {body};
  return s;
}

SimulationOptions rk4(double dt, std::int64_t steps) {
  SimulationOptions o;
  o.method = Method::rk4, o.dt = dt, o.steps = steps;
  return o;
}

GyrostatState at_rest(std::initializer_list<double> speeds) {
  GyrostatState s;
  s.wheel_speeds = Eigen::VectorXd(static_cast<Eigen::Index>(speeds.size()));
  Eigen::Index k = 0;
  for (double w : speeds) s.wheel_speeds[k++] = w;
  return s;
}

// I = diag(3, 4, 5) kg m², a wheel of J = 1 kg m² along z, the motor at u = 0.5 N m: H = 0, so
// ω = −u t / (I₃₃ − J), Ω = u I₃₃ t / (J (I₃₃ − J)); with h = 3/32 s every product is a binary fraction.
TEST(Gyrostat, WheelSpunUpFromRestTurnsTheBodyBackExactly) {
  const Gyrostat body(RigidBody(5.0, Eigen::Vector3d(3.0, 4.0, 5.0)), {Wheel{Eigen::Vector3d::UnitZ(), 1.0, 0.5}});
  const SceneSimulation r = simulate(one(body), {at_rest({0.0})}, rk4(3.0 / 32.0, 32));
  ASSERT_EQ(r.size(), 33u);
  ASSERT_EQ(r.wheel_speed.size(), 33u);
  for (std::size_t i = 0; i < r.size(); ++i) {
    const double t = r.t[i];
    EXPECT_EQ(r.w_B[3 * i + 2], -0.5 * t / 4.0) << t;
    EXPECT_EQ(r.wheel_speed[i], 0.5 * 5.0 * t / 4.0) << t;
    EXPECT_EQ(r.q_WB[4 * i], 0.0) << t;
    EXPECT_EQ(r.q_WB[4 * i + 1], 0.0) << t;
    for (int c = 0; c < 3; ++c) EXPECT_EQ(r.angular_momentum_W[3 * i + c], 0.0) << t;
  }
  // the motor's work ∫ u Ω dt = u² I₃₃ t² / (2 J (I₃₃ − J)) is quadratic in t: RK4 integrates it exactly, up to
  // the rounding of its accumulation (32 steps × 4 eps of the value)
  const double t = r.t.back(), work = 0.25 * 5.0 * t * t / (2.0 * 4.0);
  EXPECT_NEAR(r.motor_work.back(), work, 32 * 4 * kEps * work);
}

// |ω| ≈ 2.7 rad/s, wheels at 30 and −20 rad/s, no torque: wheel k's absolute spin J (a·ω + Ω) changes by
// u = 0 only: RK4 keeps it (linear in the state) to round-off, steps × 16 eps × 32 rad/s; T and |H| to its error.
TEST(Gyrostat, TorqueFreeKeepsEachWheelsAbsoluteSpin) {
  const Gyrostat body(RigidBody(100.0, Eigen::Vector3d(10.0, 12.0, 15.0)),
                      {Wheel{Eigen::Vector3d::UnitX(), 0.5}, Wheel{Eigen::Vector3d::UnitZ(), 0.8}});
  GyrostatState s = at_rest({30.0, -20.0});
  s.w_B = Eigen::Vector3d(1.5, -1.0, 2.0);
  const SceneSimulation r = simulate(one(body), {s}, rk4(0.01, 2000));
  const std::size_t n = r.size();
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(r.w_B[3 * i] + r.wheel_speed[2 * i], 1.5 + 30.0, n * 16 * kEps * 32.0);
    EXPECT_NEAR(r.w_B[3 * i + 2] + r.wheel_speed[2 * i + 1], 2.0 - 20.0, n * 16 * kEps * 32.0);
  }
  // the drifts at this step (the Python test checks their order): below 1e-8 of the values
  EXPECT_NEAR(r.kinetic_energy.back(), r.kinetic_energy.front(), 1e-8 * r.kinetic_energy.front());
  const Eigen::Vector3d H0(&r.angular_momentum_W[0]), H1(&r.angular_momentum_W[3 * (n - 1)]);
  EXPECT_NEAR(H1.norm(), H0.norm(), 1e-8 * H0.norm());
  // the first record: T and H_B of the state (models/gyrostat.hpp)
  EXPECT_NEAR(r.kinetic_energy.front(), kinetic_energy(body, s), 8 * kEps * r.kinetic_energy.front());
  EXPECT_LT((H0 - angular_momentum_B(body, s)).norm(), 8 * kEps * H0.norm());
}

TEST(Gyrostat, BadWheelsAreRefusedNamingTheValue) {
  const RigidBody sphere(1.0, Eigen::Vector3d(1.0, 1.0, 1.0));
  EXPECT_EQ(message_of([&] { Gyrostat(sphere, {Wheel{Eigen::Vector3d::Zero(), 0.1}}); }).rfind("wheels[0].axis_B: expected a non-zero axis", 0), 0u);
  EXPECT_EQ(message_of([&] { Gyrostat(sphere, {Wheel{Eigen::Vector3d::UnitZ(), -0.1}}); }).rfind("wheels[0].inertia: expected a finite number > 0", 0), 0u);
  EXPECT_EQ(message_of([&] {
              Gyrostat(sphere, {Wheel{Eigen::Vector3d::UnitZ(), 0.1}, Wheel{Eigen::Vector3d::UnitZ(), 0.1, 0.0, 1.0, 0.5}});
            }).rfind("wheels[1].t_end: expected a time after t_start = 1 s", 0), 0u);
  EXPECT_EQ(message_of([&] {
              Gyrostat(sphere, {Wheel{Eigen::Vector3d::UnitZ(), 0.6}, Wheel{Eigen::Vector3d::UnitZ(), 0.6}});
            }).rfind("wheels[1].inertia: expected an axial inertia that leaves the transverse inertia", 0), 0u);
}

TEST(Gyrostat, RunsRefuseWhatItCannotDo) {
  const Gyrostat body(RigidBody(5.0, Eigen::Vector3d(3.0, 4.0, 5.0)), {Wheel{Eigen::Vector3d::UnitZ(), 1.0}});
  EXPECT_EQ(message_of([&] { simulate(one(body), {at_rest({0.0, 1.0})}, rk4(0.1, 1)); }),
            "initial[0].wheel_speeds: expected 1 speeds (one per wheel of the gyrostat), got 2");
  for (const Method m : {Method::splitting_dlm, Method::splitting_dlm_yoshida4, Method::exact_flow_kick, Method::exact,
                         Method::semi_implicit_euler_implicit_gyroscopic}) {
    EXPECT_EQ(message_of([&] { compile_scene(one(body), m); }).rfind("method: expected a method that integrates the whole motion", 0), 0u)
        << method_info(m).name;
  }
  Scene turning = one(body);
  turning.frame = SceneFrame::rotating(Eigen::Vector3d::UnitZ(), 0.1);
  EXPECT_EQ(message_of([&] { compile_scene(turning, Method::rk4); }).rfind("frame: expected none in a scene with body 0", 0), 0u);
}

}  // namespace
