// RigidBodyModel<Euler, LoadKind>: a model compiled for the loads of a scene (none / fixed / turning)
// must step exactly as the general model (LoadKind::turning) does on the same loads, for every method
// (those written against the model interface and the structure-preserving ones); load_kind_of picks
// the least kind that covers a schedule; a model refuses loads its kind does not cover.
#include <gtest/gtest.h>

#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/models/rigid_body.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <stdexcept>

namespace rigiddyn {
namespace {

RigidBodyCoordinates generic_coordinates() {
  RigidBodyState s;
  s.p_W = Eigen::Vector3d(0.1, -0.2, 0.3);
  s.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  s.v_W = Eigen::Vector3d(0.5, 0.2, -0.1);
  s.w_B = Eigen::Vector3d(1.2, -0.7, 2.0);
  return to_coordinates(s);
}

// 200 steps of Integrator with a model of `kind` and with the general model, same loads: the same
// arithmetic, so the same coordinates to round-off (the specialised model only skips terms that are
// exactly zero or, in RKMK4's stages, an attitude the velocity does not read).
template <class Integrator, LoadKind kind, class Euler>
void expect_same_steps(const Euler& euler, const Eigen::Vector3d& g_W, const ComLoads& loads) {
  RigidBodyModel<Euler, kind> specialised(2.0, euler, g_W);
  RigidBodyModel<Euler> general(2.0, euler, g_W);
  specialised.set_loads(loads);
  general.set_loads(loads);
  RigidBodyCoordinates a = generic_coordinates(), b = a;
  auto work_a = workspace<Integrator>(specialised, a);
  auto work_b = workspace<Integrator>(general, b);
  for (int i = 0; i < 200; ++i) {
    Integrator::step(specialised, a, 1e-2, work_a);
    Integrator::step(general, b, 1e-2, work_b);
  }
  // the terms the specialised model skips are exactly zero: the same operations on the same numbers
  // (a compiler may reorder a sum: <= 1 rounding of |y| <= ~2 per step, 200 steps: 9e-14)
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-13) << "kind " << static_cast<int>(kind);
  EXPECT_GT((a - generic_coordinates()).norm(), 0.1);  // the body did move
}

template <class Integrator>
void expect_same_steps_every_kind() {
  const PrincipalEuler principal(Eigen::Vector3d(1.0, 2.0, 3.0));
  Eigen::Matrix3d I;
  I << 1.0, 0.1, 0.0, 0.1, 2.0, 0.05, 0.0, 0.05, 3.0;
  const FullEuler full(I);
  ComLoads fixed;
  fixed.f_W = Eigen::Vector3d(0.4, -0.2, 1.0);
  fixed.tau_B = Eigen::Vector3d(-0.1, 0.2, 0.15);
  expect_same_steps<Integrator, LoadKind::none>(principal, Eigen::Vector3d::Zero(), ComLoads{});
  expect_same_steps<Integrator, LoadKind::none>(full, Eigen::Vector3d::Zero(), ComLoads{});
  expect_same_steps<Integrator, LoadKind::fixed>(principal, standard_gravity(), fixed);
  expect_same_steps<Integrator, LoadKind::fixed>(full, standard_gravity(), ComLoads{});
  expect_same_steps<Integrator, LoadKind::fixed>(SphericalEuler(2.0), Eigen::Vector3d::Zero(), fixed);
}

TEST(LoadKinds, SpecialisedModelStepsAsTheGeneralModel) {
  expect_same_steps_every_kind<ExplicitEuler>();
  expect_same_steps_every_kind<SemiImplicitEuler>();
  expect_same_steps_every_kind<SemiImplicitEulerImplicitGyroscopic>();
  expect_same_steps_every_kind<Rk4>();
  expect_same_steps_every_kind<Rkmk4>();
}

// The structure-preserving methods are compositions of the model's loads_kick and free_flow, which
// every kind of RigidBodyModel<Euler, kind> defines alike, so they too step as on the general model.
TEST(LoadKinds, StructurePreservingMethodsStepAsOnTheGeneralModel) {
  expect_same_steps_every_kind<ImplicitMidpoint>();
  expect_same_steps_every_kind<SplittingDlm>();
  expect_same_steps_every_kind<Yoshida4>();
  expect_same_steps_every_kind<ExactFlowKick>();
}

TEST(LoadKinds, RkmkStagesSkipTheAttitudeOnlyWhenTheVelocityIgnoresIt) {
  // under a body-fixed force the stage attitude matters: velocity_at must then retract it
  RigidBodyModel<PrincipalEuler> model(2.0, PrincipalEuler(Eigen::Vector3d(1.0, 2.0, 3.0)));
  ComLoads turning;
  turning.f_B = Eigen::Vector3d(1.0, 0.0, 0.0);
  turning.tau_W = Eigen::Vector3d(0.0, 0.3, 0.0);
  model.set_loads(turning);
  const RigidBodyCoordinates y = generic_coordinates();
  RigidBodyTangent theta;
  theta << 0.01, 0.02, 0.03, 0.3, -0.2, 0.1, 0.01, 0.0, -0.01, 0.02, 0.0, 0.01, 0.0;
  RigidBodyCoordinates stage;
  RigidBodyModel<PrincipalEuler>::retract(y, theta, stage);
  RigidBodyTangent direct, at_stage, at_y;
  model.velocity(stage, direct);
  model.velocity_at(y, theta, at_stage);
  EXPECT_LT((at_stage - direct).cwiseAbs().maxCoeff(), 1e-15);  // the same computation
  // and the attitude does change the velocity here (the test can fail)
  model.velocity(y, at_y);
  EXPECT_GT((at_y - direct).segment<3>(6).norm(), 1e-3);
}

TEST(LoadKinds, LoadKindOfASchedule) {
  const Eigen::Vector3d none = Eigen::Vector3d::Zero(), g = standard_gravity(), f(1.0, 0.0, 0.0);
  EXPECT_EQ(load_kind_of({}, none), LoadKind::none);
  EXPECT_EQ(load_kind_of({AppliedLoad{}}, none), LoadKind::none);  // a zero load is no load
  EXPECT_EQ(load_kind_of({}, g), LoadKind::fixed);
  EXPECT_EQ(load_kind_of({AppliedLoad{f, none, Frame::world}}, none), LoadKind::fixed);
  EXPECT_EQ(load_kind_of({AppliedLoad{none, f, Frame::body}}, none), LoadKind::fixed);
  EXPECT_EQ(load_kind_of({AppliedLoad{f, none, Frame::body}}, none), LoadKind::turning);
  EXPECT_EQ(load_kind_of({AppliedLoad{none, f, Frame::world}}, none), LoadKind::turning);
  // a schedule is covered at every time, also by loads that start later
  AppliedLoad later{f, none, Frame::body};
  later.t_start = 5.0;
  EXPECT_EQ(load_kind_of({AppliedLoad{f, none, Frame::world}, later}, none), LoadKind::turning);
}

TEST(LoadKinds, ModelRefusesLoadsItsKindDoesNotCover) {
  const PrincipalEuler euler(Eigen::Vector3d(1.0, 2.0, 3.0));
  EXPECT_THROW((RigidBodyModel<PrincipalEuler, LoadKind::none>(1.0, euler, standard_gravity())), std::invalid_argument);
  RigidBodyModel<PrincipalEuler, LoadKind::none> free_body(1.0, euler);
  ComLoads world;
  world.f_W = Eigen::Vector3d(1.0, 0.0, 0.0);
  EXPECT_THROW(free_body.set_loads(world), std::invalid_argument);
  RigidBodyModel<PrincipalEuler, LoadKind::fixed> fixed(1.0, euler, standard_gravity());
  fixed.set_loads(world);
  ComLoads body;
  body.f_B = Eigen::Vector3d(1.0, 0.0, 0.0);
  try {
    fixed.set_loads(body);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("loads: expected no body-fixed force"), std::string::npos) << e.what();
  }
}

TEST(LoadKinds, SimulateAgreesAcrossASwitchOfKinds) {
  // a schedule whose body-fixed force starts later runs on the general model from the start and
  // matches a run that is split at the switch (first part free, second part turning)
  RigidBody body(2.0, Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal().toDenseMatrix());
  RigidBodyState s0;
  s0.w_B = Eigen::Vector3d(0.3, 2.0, 0.5);
  SimulationOptions o;
  o.method = Method::rk4;
  o.dt = 1e-2;
  o.steps = 200;
  o.record_every = 100;
  AppliedLoad later{Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d::Zero(), Frame::body};
  later.t_start = 1.0;
  o.loads = {later};
  const Trajectory whole = simulate(body, s0, o);
  o.loads = {};
  o.steps = 100;
  const Trajectory first = simulate(body, s0, o);  // LoadKind::none
  RigidBodyState mid;
  mid.p_W = Eigen::Map<const Eigen::Vector3d>(first.p_W.data() + 3);
  mid.q_WB = Eigen::Quaterniond(Eigen::Map<const Eigen::Vector4d>(first.q_WB.data() + 4));
  mid.v_W = Eigen::Map<const Eigen::Vector3d>(first.v_W.data() + 3);
  mid.w_B = Eigen::Map<const Eigen::Vector3d>(first.w_B.data() + 3);
  o.loads = {AppliedLoad{Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d::Zero(), Frame::body}};
  o.t0 = 1.0;
  const Trajectory second = simulate(body, mid, o);  // LoadKind::turning
  // the same steps on the same numbers (the first half's turning-load terms are exactly zero, the
  // restart state is the recorded one): at most a reordered sum per step, 200 x eps x |y| (<= 5)
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(whole.p_W[6 + i], second.p_W[3 + i], 1e-12);
    EXPECT_NEAR(whole.w_B[6 + i], second.w_B[3 + i], 1e-12);
  }
}

}  // namespace
}  // namespace rigiddyn
