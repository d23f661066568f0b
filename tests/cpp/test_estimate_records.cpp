// The records of a coarse run of the global error estimate (SimulationOptions::estimate_records): the columns the
// estimate reads are those of the same run recording every column, bit for bit, and so are the records the estimate
// makes of them (error_records without the answer's round-off size); the columns nothing reads of it stay empty, in a
// run and in a batch.
#include "linked_bodies.hpp"
#include "rigiddyn/batch/batch_global_error.hpp"
#include "rigiddyn/batch/simulate_batch.hpp"
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/one_body_scene.hpp"
#include "rigiddyn/scene/scene_order.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"
#include "rigiddyn/simulate/global_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rigiddyn {
namespace {

using test::linked_bodies;

// A pivoted body, a pivoted planar body, a gyrostat with a wheel and a two-link tree on a free base under gravity, the
// gyrostat on a spring to the tree's second link (the kinds whose records read more than the body's motion: a pivot's
// reaction, a wheel's speed and motor work, the links' joints), and their states.
std::pair<Scene, std::vector<BodyState>> pivots_wheels_and_links() {
  Scene scene;
  const auto arm = std::make_shared<Tree>();
  const SpatialInertia link(2.0, Eigen::Vector3d(0.5, 0.0, 0.0), Eigen::Vector3d(0.01, 0.2, 0.2).asDiagonal());
  arm->add_link("base", -1, FreeJoint(), SpatialInertia(5.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(1.0, 1.5, 2.0).asDiagonal()));
  arm->add_link("elbow", 0, RevoluteJoint(Eigen::Vector3d::UnitZ()), link,
                Transform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.5, 0.0, 0.0)));
  scene.bodies = {PivotedBody(RigidBody(2.0, Eigen::Vector3d(1.0, 1.0, 0.5)), Eigen::Vector3d(0.0, 0.0, 0.5)),
                  PivotedPlanarBody(2.0, 0.05, Eigen::Vector2d(0.0, -0.4)),
                  Gyrostat(RigidBody(10.0, Eigen::Vector3d(1.0, 1.2, 1.5)), {Wheel{Eigen::Vector3d::UnitZ(), 0.05, 0.01}}),
                  TreeLink{arm, 0}, TreeLink{arm, 1}};
  GyrostatState wheel;
  wheel.p_W = Eigen::Vector3d(2.0, 0.0, 0.0), wheel.w_B = Eigen::Vector3d(0.1, -0.2, 0.3);
  wheel.wheel_speeds = Eigen::VectorXd::Constant(1, 50.0);
  Eigen::VectorXd q_base(7);
  q_base << 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0;
  std::vector<BodyState> states{
      PivotedBodyState{Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX())), Eigen::Vector3d(0.0, 0.0, 5.0)},
      PivotedPlanarBodyState{0.4, 0.0}, wheel,
      JointState{q_base, (Eigen::VectorXd(6) << 0.1, 0.2, 0.3, 0.0, 0.1, 0.0).finished()},
      JointState{Eigen::VectorXd::Constant(1, 0.3), Eigen::VectorXd::Constant(1, -1.0)}};
  scene.elements.emplace_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}});
  scene.elements.emplace_back(SpringDamper{2, Eigen::Vector3d(0.2, 0.0, 0.0), 4, Eigen::Vector3d::Zero(), 5.0, 1.0, 0.2});
  return {scene, states};
}

// The run of `scene` from `states` by `method`, recording every column and what the estimate reads alone: the kept
// columns and the estimate's records equal, the others empty in the second (where the first has them).
void expect_estimate_records(const Scene& scene, const std::vector<BodyState>& states, Method method,
                             std::int64_t record_every, const std::string& what) {
  SCOPED_TRACE(what + ", " + method_info(method).name + ", record_every " + std::to_string(record_every));
  const CompiledScene compiled = compile_scene(scene, method);
  SimulationOptions o;
  o.method = method, o.dt = 0.01, o.steps = 101, o.record_every = record_every;
  const SceneSimulation all = simulate(compiled, states, o);
  o.estimate_records = true;
  const SceneSimulation read = simulate(compiled, states, o);
  EXPECT_TRUE(read.estimate_records);
  ASSERT_EQ(all.size(), read.size());
  for (const auto column : {&SceneSimulation::t, &SceneSimulation::p_W, &SceneSimulation::q_WB, &SceneSimulation::v_W,
                            &SceneSimulation::w_B, &SceneSimulation::kinetic_energy, &SceneSimulation::total_energy,
                            &SceneSimulation::angular_momentum_W, &SceneSimulation::work,
                            &SceneSimulation::mass_flow_energy, &SceneSimulation::motor_work}) {
    EXPECT_EQ(all.*column, read.*column);  // bit for bit: the same run
  }
  for (const auto column : {&SceneSimulation::potential_energy, &SceneSimulation::linear_momentum_W,
                            &SceneSimulation::pivot_reaction_W, &SceneSimulation::angular_momentum_O_W,
                            &SceneSimulation::mass, &SceneSimulation::power, &SceneSimulation::impulse_W,
                            &SceneSimulation::angular_impulse_W}) {
    EXPECT_TRUE((read.*column).empty());
  }
  EXPECT_FALSE(all.mass.empty());
  const ErrorRecords a = coarse_records(all), r = coarse_records(read);
  EXPECT_EQ(a.momentum, r.momentum);
  EXPECT_EQ(a.balance, r.balance);
  EXPECT_TRUE(r.momentum_scale.empty());
}

TEST(EstimateRecords, GenericModelKeepsWhatTheEstimateReads) {
  const auto [scene, states] = linked_bodies();
  ASSERT_EQ(compile_scene(scene, Method::rk4).path(), ScenePath::generic);
  // (a coarse run leaves the impulses out of its evaluations: every method's kept columns still the same bits)
  for (const Method method : {Method::rk4, Method::splitting_dlm, Method::rkmk4, Method::implicit_midpoint}) {
    for (const std::int64_t every : {1, 3}) expect_estimate_records(scene, states, method, every, "linked bodies");
  }
}

TEST(EstimateRecords, PivotsWheelsAndLinksKeepWhatTheEstimateReads) {
  // their records without the elements' wrenches: the kinematics alone (no pivot reaction, no power)
  const auto [scene, states] = pivots_wheels_and_links();
  for (const std::int64_t every : {1, 3}) expect_estimate_records(scene, states, Method::rk4, every, "pivots and wheels");
}

TEST(EstimateRecords, OneBodyLayoutsKeepWhatTheEstimateReads) {
  RigidBodyState s;
  s.v_W = Eigen::Vector3d(1.0, 0.0, 2.0), s.w_B = Eigen::Vector3d(0.1, 1.0, 0.1);
  const RigidBody body(2.0, Eigen::Vector3d(1.0, 2.0, 3.0));
  AppliedLoad push;
  push.force = Eigen::Vector3d(0.5, 0.0, 0.0), push.torque = Eigen::Vector3d(0.0, 0.1, 0.0), push.frame = Frame::body;
  push.t_end = 0.5;  // a switch inside the run
  const Eigen::Vector3d g(0.0, 0.0, -9.81);
  const std::pair<Scene, std::string> cases[] = {{one_body_scene(body, Eigen::Vector3d::Zero(), {}), "a free body"},
                                                 {one_body_scene(body, g, {}), "a body under gravity"},
                                                 {one_body_scene(body, g, {push}), "a body under gravity and a load"}};
  for (const auto& [scene, what] : cases) {
    ASSERT_EQ(compile_scene(scene, Method::rk4).path(), ScenePath::one_body);
    for (const Method method : {Method::rk4, Method::splitting_dlm}) {
      for (const std::int64_t every : {1, 3}) expect_estimate_records(scene, {BodyState(s)}, method, every, what);
    }
  }
}

TEST(EstimateRecords, ABatchHoldsWhatTheEstimateReads) {
  // a batch of the linked bodies (two samples, the second moved) and of a free body: the columns it holds are the full
  // batch's, bit for bit, and so are each sample's records as the estimate reads them; the others are not held
  const auto [linked, linked_states] = linked_bodies();
  std::vector<BodyState> moved = linked_states;
  std::get<RigidBodyState>(moved[1]).v_W.x() += 0.3;
  RigidBodyState spin;
  spin.w_B = Eigen::Vector3d(0.1, 1.0, 0.1);
  const RigidBody body(2.0, Eigen::Vector3d(1.0, 2.0, 3.0));
  const std::pair<Scene, std::vector<std::vector<BodyState>>> cases[] = {
      {linked, {linked_states, moved}},
      {one_body_scene(body, Eigen::Vector3d::Zero(), {}), {{BodyState(spin)}, {BodyState(spin)}}}};
  for (const auto& [scene, states] : cases) {
    const std::vector<CompiledScene> compiled{compile_scene(scene, Method::rk4)};
    SimulationOptions o;
    o.method = Method::rk4, o.dt = 0.01, o.steps = 101, o.record_every = 2;
    const BatchSceneSimulation all = simulate_batch(compiled, states, o, {}, 2);
    o.estimate_records = true;
    const BatchSceneSimulation read = simulate_batch(compiled, states, o, {}, 2);
    EXPECT_TRUE(read.estimate_records);
    for (const auto column : {&BatchSceneSimulation::t, &BatchSceneSimulation::p_W, &BatchSceneSimulation::q_WB,
                              &BatchSceneSimulation::v_W, &BatchSceneSimulation::w_B,
                              &BatchSceneSimulation::kinetic_energy, &BatchSceneSimulation::total_energy,
                              &BatchSceneSimulation::angular_momentum_W, &BatchSceneSimulation::work,
                              &BatchSceneSimulation::mass_flow_energy, &BatchSceneSimulation::motor_work}) {
      EXPECT_EQ(all.*column, read.*column);
    }
    for (const auto column : {&BatchSceneSimulation::potential_energy, &BatchSceneSimulation::linear_momentum_W,
                              &BatchSceneSimulation::pivot_reaction_W, &BatchSceneSimulation::angular_momentum_O_W,
                              &BatchSceneSimulation::mass, &BatchSceneSimulation::power}) {
      EXPECT_TRUE((read.*column).empty());
      EXPECT_TRUE(!(all.*column).empty() || (column == &BatchSceneSimulation::power && all.element_count == 0));
    }
    for (std::size_t i = 0; i < states.size(); ++i) {
      const ErrorRecords a = error_records(sample_columns(batch_columns(all), i), false);
      const ErrorRecords r = error_records(sample_columns(batch_columns(read), i), false);
      EXPECT_EQ(a.momentum, r.momentum);
      EXPECT_EQ(a.balance, r.balance);
    }
  }
}

// Whether a and b hold the same bits (NaN where the other has the same NaN).
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(EstimateRecords, TheAnswersSumsAtItsCommonRecordsGiveTheSameEstimate) {
  const auto [scene, states] = linked_bodies();
  const CompiledScene compiled = compile_scene(scene, Method::rk4);
  // (the last: 3 074 multiples of 4 steps, their common records every 16 steps and the last, 2 past a multiple of 16)
  for (const auto& [record_every, steps] : {std::pair<std::int64_t, std::int64_t>{1, 101}, {3, 101}, {4, 101},
                                           {4, 4 * 3074 + 3}}) {
    SCOPED_TRACE("record_every " + std::to_string(record_every) + ", steps " + std::to_string(steps));
    SimulationOptions o;
    o.method = Method::rk4, o.dt = 0.01, o.steps = steps, o.record_every = record_every;
    const SceneSimulation answer = simulate(compiled, states, o);
    const auto coarse = [&](int factor) {
      SimulationOptions c = coarse_options(o, factor);
      c.estimate_records = true;
      return simulate(compiled, states, c);
    };
    const SceneSimulation twice = coarse(2), four_times = coarse(4);  // the records point into their columns
    const ErrorRecords h2 = coarse_records(twice), h4 = coarse_records(four_times);
    const int order = scene_order(compiled);
    const ErrorRecords every = error_records(answer), common = answer_records(answer, o, order);
    const CommonRecords grid = common_records(o);
    for (std::size_t i = 0; i < every.n; ++i) {  // the sums every stride-th record and at the last common one alone
      const bool made = i % grid.stride == 0 || i == grid.last;
      EXPECT_EQ(std::isnan(common.momentum[i]), !made) << "record " << i;
      EXPECT_EQ(std::isnan(common.balance[i]), !made) << "record " << i;
    }
    const GlobalErrorEstimate a = estimate_global_error(every, h2, h4, o, order),
                              b = estimate_global_error(common, h2, h4, o, order);
    for (const auto field : {&GlobalErrorEstimate::attitude, &GlobalErrorEstimate::angular_velocity,
                             &GlobalErrorEstimate::position, &GlobalErrorEstimate::velocity,
                             &GlobalErrorEstimate::energy, &GlobalErrorEstimate::angular_momentum,
                             &GlobalErrorEstimate::observed_order}) {
      EXPECT_TRUE(same_bits(a.*field, b.*field));
    }
    ASSERT_EQ(a.verdict.size(), b.verdict.size());
    for (std::size_t i = 0; i < a.verdict.size(); ++i) EXPECT_EQ(a.verdict[i], b.verdict[i]) << "record " << i;
  }
}

}  // namespace
}  // namespace rigiddyn
