// No step allocates: every method on every model sizes its workspace once per run
// (integrators/workspace.hpp) and every evaluation writes into scratch sized when the model was built.
//
// The test binary counts every heap allocation of the process: it defines malloc, calloc, realloc and the
// aligned allocators itself (an executable's definitions take precedence over the C library's for every
// shared library, libstdc++'s operator new and Eigen's aligned_malloc included) and forwards them to
// glibc's __libc_* entry points. A run of 1000 steps must then allocate exactly as often as a run of 10
// steps with the same records (the first and the last) and the same switch times: one allocation per step
// would differ by 990; and no member of a scene model's interface may allocate at all.
// Where the counting cannot be installed (not glibc, or under AddressSanitizer, which owns malloc) the
// tests are skipped, saying why.
#include <gtest/gtest.h>

#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "allocation_count.hpp"

namespace rigiddyn {
namespace {

using test::allocations_during;
using test::counts_allocations;
using test::why_not_counted;


RigidBodyState tumbling(const Eigen::Vector3d& p_W) {
  RigidBodyState s;
  s.p_W = p_W;
  s.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1.0, -1.0, 2.0).normalized()));
  s.v_W = Eigen::Vector3d(0.2, 0.0, -0.1);
  s.w_B = Eigen::Vector3d(0.3, 1.0, 0.2);
  return s;
}

struct SceneCase {
  std::string name;
  Scene scene;
  std::vector<BodyState> initial;
  bool torque_free = false;  // the only scenes the method 'exact' takes
  bool whole_motion = false;  // a gyrostat or a tree: the methods that integrate the whole motion only (no splitting,
                              // no implicit gyroscopic kick)
};

// Every body kind (the rigid bodies in each Euler form) under every element that acts on it, a schedule
// whose switches fall inside the shortest run, and springs between bodies.
SceneCase every_body_kind() {
  SceneCase c{"every body kind", {}, {}};
  Scene& s = c.scene;
  Eigen::Matrix3d full;
  full << 2.0, 0.1, 0.0, 0.1, 3.0, 0.2, 0.0, 0.2, 4.0;
  s.bodies = {Particle(1.0),
              PlanarBody(2.0, 0.3),
              RigidBody(1.5, Eigen::Vector3d(1.0, 1.0, 1.0)),
              RigidBody(1.5, Eigen::Vector3d(1.0, 2.0, 3.0)),
              RigidBody(1.5, full),
              PivotedBody(RigidBody(2.0, Eigen::Vector3d(1.0, 1.0, 0.5)), Eigen::Vector3d(0.0, 0.0, 0.5)),
              PivotedPlanarBody(2.0, 0.05, Eigen::Vector2d(0.0, -0.4))};
  c.initial = {ParticleState{Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d(0.0, 1.0, 0.0)},
               PlanarBodyState{Eigen::Vector2d(0.0, 2.0), 0.1, Eigen::Vector2d(0.3, 0.0), 0.5},
               tumbling(Eigen::Vector3d(3.0, 0.0, 0.0)),
               tumbling(Eigen::Vector3d(0.0, 3.0, 0.0)),
               tumbling(Eigen::Vector3d(0.0, 0.0, 3.0)),
               PivotedBodyState{Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX())), Eigen::Vector3d(0.0, 0.0, 5.0)},
               PivotedPlanarBodyState{0.4, 0.0}};
  s.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}});
  s.elements.push_back(Drag{0.1, 0.01, 0.02, 0.001, {}});
  s.elements.push_back(SpringDamper{0, Eigen::Vector3d::Zero(), 3, Eigen::Vector3d(0.1, 0.0, 0.0), 5.0, 1.0, 0.2});
  s.elements.push_back(SpringDamper{4, Eigen::Vector3d(0.0, 0.1, 0.0), -1, Eigen::Vector3d(0.0, 0.0, 4.0), 2.0, 0.5, 0.1});
  s.elements.push_back(MutualGravity{1e-2, 0.1, {0, 2, 3, 4}});
  s.elements.push_back(PointMassGravity{5.0, Eigen::Vector3d(0.0, 0.0, -10.0), 0.0, {0, 2, 3, 4}});
  s.elements.push_back(GravityGradient{5.0, Eigen::Vector3d(0.0, 0.0, -10.0), {2, 3, 4}});
  s.elements.push_back(AtmosphericDrag{1.0, 0.0, 5.0, 8.0, Eigen::Vector3d(0.0, 0.0, -10.0), Eigen::Vector3d(0.0, 0.0, 0.1), 0.5,
                                       Eigen::Vector3d(0.0, 0.0, 0.0), {0, 2, 3, 4}, {}, {}});
  // the same air tabulated: rows 5 m apart (its density found by a binary search, no allocation)
  s.elements.push_back(AtmosphericDrag{0.0, 0.0, 0.0, 8.0, Eigen::Vector3d(0.0, 0.0, -10.0), Eigen::Vector3d(0.0, 0.0, 0.1), 0.5,
                                       Eigen::Vector3d(0.0, 0.0, 0.0), {0, 2, 3, 4}, {0.0, 5.0, 10.0}, {1.0, 0.4, 0.1}});
  s.elements.push_back(ZonalGravity{5.0, 2.0, 1e-2, -1e-3, 2e-3, Eigen::Vector3d(0.0, 0.0, -10.0),
                                    Eigen::Vector3d(0.1, 0.0, 1.0), {0, 2, 3, 4}});
  ReactionWheel wheel;  // spun up inside the first run: its switches fall inside every run
  wheel.body = 4, wheel.axis_B = Eigen::Vector3d(1.0, 2.0, 2.0), wheel.inertia = 0.01;
  wheel.speed = 5.0, wheel.acceleration = 30.0, wheel.t_start = 0.0015, wheel.t_end = 0.0045;
  s.elements.push_back(wheel);
  s.elements.push_back(MagneticDipole{Eigen::Vector3d(0.2, 0.0, 0.1), Eigen::Vector3d(0.0, 1e-3, -2e-3),
                                      Eigen::Vector3d(0.0, 0.0, 1e5), Eigen::Vector3d(0.0, 0.0, -10.0), {}});
  AppliedLoad window{Eigen::Vector3d(0.1, -0.3, 0.2), Eigen::Vector3d(0.3, -0.2, 0.4), Frame::body};
  window.t_start = 0.0025, window.t_end = 0.0065;  // switches inside the first 10 steps of 1 ms
  s.elements.push_back(ScheduledLoads{3, {window}, Eigen::Vector3d(0.1, 0.0, 0.0)});
  return c;
}

// Particles and rigid bodies in a turning frame (the fictitious terms and the exact Coriolis kick).
SceneCase turning_frame() {
  SceneCase c{"turning frame", {}, {}};
  c.scene.bodies = {Particle(1.0), RigidBody(1.5, Eigen::Vector3d(1.0, 2.0, 3.0))};
  c.initial = {ParticleState{Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d(0.0, 1.0, 0.0)}, tumbling(Eigen::Vector3d::Zero())};
  c.scene.frame = SceneFrame::rotating(Eigen::Vector3d(0.0, 0.3, 1.0).normalized(), 0.5);
  c.scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}});
  return c;
}

// A particle and a rigid body losing mass, one of them under thrust.
SceneCase mass_flow() {
  SceneCase c{"mass flow", {}, {}};
  add_body(c.scene, Particle(10.0), "rocket", MassFlow{-0.5, {}, InertiaRule::scaled, {}});
  add_body(c.scene, RigidBody(10.0, Eigen::Vector3d(1.0, 2.0, 3.0)), "stage", MassFlow{-0.2, {}, InertiaRule::scaled, {}});
  c.initial = {ParticleState{Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 1.0)}, tumbling(Eigen::Vector3d::Zero())};
  c.scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}});
  c.scene.elements.push_back(Thrust{0, Eigen::Vector3d(0.0, 0.0, -100.0), Frame::world, Eigen::Vector3d::Zero()});
  return c;
}

// One torque-free body (every method, 'exact' included).
SceneCase torque_free() {
  SceneCase c{"torque free", {}, {}, true};
  c.scene.bodies = {RigidBody(1.5, Eigen::Vector3d(1.0, 2.0, 3.0))};
  c.initial = {tumbling(Eigen::Vector3d::Zero())};
  return c;
}

// A gyrostat with a motor switching inside the shortest run, beside a rigid body on a spring.
SceneCase gyrostat() {
  SceneCase c{"gyrostat", {}, {}, false, true};
  Wheel spun{Eigen::Vector3d(0.0, 0.0, 1.0), 0.05, 0.01, 0.0025, 0.0065};
  Wheel free{Eigen::Vector3d(1.0, 1.0, 0.0), 0.03};
  c.scene.bodies = {Gyrostat(RigidBody(100.0, Eigen::Vector3d(10.0, 12.0, 15.0)), {spun, free}),
                    RigidBody(1.5, Eigen::Vector3d(1.0, 2.0, 3.0))};
  GyrostatState s;
  s.w_B = Eigen::Vector3d(0.1, -0.2, 0.3), s.wheel_speeds = Eigen::Vector2d(100.0, -30.0);
  c.initial = {s, tumbling(Eigen::Vector3d(3.0, 0.0, 0.0))};
  c.scene.elements.push_back(SpringDamper{0, Eigen::Vector3d(0.5, 0.0, 0.0), 1, Eigen::Vector3d::Zero(), 5.0, 1.0, 0.2});
  c.scene.elements.push_back(GravityGradient{5.0, Eigen::Vector3d(0.0, 0.0, -10.0), {0, 1}});
  return c;
}

// A free-floating tree (a free joint, a ball joint, a revolute joint) under gravity, its last link on a spring to a
// rigid body, its revolute joint on a torsion spring and damper.
SceneCase tree() {
  SceneCase c{"tree", {}, {}, false, true};
  const auto arm = std::make_shared<Tree>();
  const SpatialInertia link(2.0, Eigen::Vector3d(0.5, 0.0, 0.0), Eigen::Vector3d(0.01, 0.2, 0.2).asDiagonal());
  arm->add_link("base", -1, FreeJoint(), SpatialInertia(10.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(1.0, 2.0, 2.5).asDiagonal()));
  arm->add_link("shoulder", 0, SphericalJoint(), link, Transform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.5, 0.0, 0.0)));
  arm->add_link("elbow", 1, RevoluteJoint(Eigen::Vector3d::UnitZ()), link,
                Transform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 0.0, 0.0)));
  for (int i = 0; i < 3; ++i) c.scene.bodies.push_back(TreeLink{arm, i});
  c.scene.bodies.push_back(RigidBody(1.5, Eigen::Vector3d(1.0, 2.0, 3.0)));
  Eigen::VectorXd q_base(7);
  q_base << 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0;
  c.initial = {JointState{q_base, (Eigen::VectorXd(6) << 0.1, 0.2, 0.3, 0.0, 0.1, 0.0).finished()},
               JointState{Eigen::Vector4d(0.0, 0.0, 0.0, 1.0), Eigen::Vector3d(0.5, -0.5, 1.0)},
               JointState{Eigen::VectorXd::Constant(1, 0.3), Eigen::VectorXd::Constant(1, -1.0)},
               tumbling(Eigen::Vector3d(3.0, 0.0, 0.0))};
  c.scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}});
  c.scene.elements.push_back(SpringDamper{2, Eigen::Vector3d(0.5, 0.0, 0.0), 3, Eigen::Vector3d::Zero(), 5.0, 1.0, 0.2});
  c.scene.elements.push_back(RevoluteSpringDamper{2, 4.0, 0.1, 0.3});  // the elbow's torsion spring
  return c;
}

// A chain of revolute, prismatic and fixed joints (its implicit midpoint in (q, p): the momenta, CRBA and a Cholesky
// solve at each iterate) under gravity, its slider on a spring to W, its hinge on a torsion spring and damper.
SceneCase chain() {
  SceneCase c{"chain", {}, {}, false, true};
  const auto arm = std::make_shared<Tree>();
  const SpatialInertia link(2.0, Eigen::Vector3d(0.5, 0.0, 0.0), Eigen::Vector3d(0.01, 0.2, 0.2).asDiagonal());
  arm->add_link("hinge", -1, RevoluteJoint(Eigen::Vector3d::UnitY()), link);
  arm->add_link("slider", 0, PrismaticJoint(Eigen::Vector3d::UnitX()), link,
                Transform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 0.0, 0.0)));
  arm->add_link("tool", 1, FixedJoint(), link, Transform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.2, 0.0, 0.0)));
  for (int i = 0; i < 3; ++i) c.scene.bodies.push_back(TreeLink{arm, i});
  c.initial = {JointState{Eigen::VectorXd::Constant(1, 0.4), Eigen::VectorXd::Constant(1, 1.0)},
               JointState{Eigen::VectorXd::Constant(1, 0.1), Eigen::VectorXd::Constant(1, -0.5)},
               JointState{Eigen::VectorXd::Zero(0), Eigen::VectorXd::Zero(0)}};
  c.scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}});
  c.scene.elements.push_back(SpringDamper{1, Eigen::Vector3d::Zero(), -1, Eigen::Vector3d(2.0, 0.0, 0.0), 5.0, 1.0, 0.2});
  c.scene.elements.push_back(RevoluteSpringDamper{0, 4.0, 0.1, 0.3});
  return c;
}

// The methods compile refuses for a gyrostat or a tree: the splittings and the implicit gyroscopic kick
bool refused_for_whole_motion(Method m) {
  return m == Method::splitting_dlm || m == Method::splitting_dlm_yoshida4 || m == Method::exact_flow_kick ||
         m == Method::exact || m == Method::semi_implicit_euler_implicit_gyroscopic;
}

std::vector<SceneCase> every_case() {
  std::vector<SceneCase> cases;
  cases.push_back(every_body_kind());
  cases.push_back(turning_frame());
  cases.push_back(mass_flow());
  cases.push_back(torque_free());
  cases.push_back(gyrostat());
  cases.push_back(tree());
  cases.push_back(chain());
  return cases;
}

SimulationOptions options(Method method, std::int64_t steps) {
  SimulationOptions o;
  o.method = method;
  o.dt = 1e-3;
  o.steps = steps;
  o.record_every = steps;  // the first and the last state: the same records for every length
  return o;
}

TEST(AllocationFree, NoSceneRunAllocatesPerStep) {
  if (!counts_allocations) GTEST_SKIP() << why_not_counted;  // in the test body: a skip returns from it
  for (const SceneCase& c : every_case()) {
    for (const MethodInfo& info : method_table()) {
      if (info.method == Method::exact && !c.torque_free) continue;
      if (c.whole_motion && refused_for_whole_motion(info.method)) continue;
      SCOPED_TRACE(c.name + ", " + info.name);
      const CompiledScene compiled = compile_scene(c.scene, info.method);
      simulate(compiled, c.initial, options(info.method, 10));  // what a first run initialises once per process
      const std::int64_t short_run = allocations_during([&] { simulate(compiled, c.initial, options(info.method, 10)); });
      const std::int64_t long_run = allocations_during([&] { simulate(compiled, c.initial, options(info.method, 1000)); });
      EXPECT_EQ(long_run, short_run) << "allocations in 1000 steps against 10 steps";
      EXPECT_GT(short_run, 0);  // the counting works: a run allocates its records
    }
  }
}

TEST(AllocationFree, NoSceneEvaluationAllocates) {
  if (!counts_allocations) GTEST_SKIP() << why_not_counted;  // in the test body: a skip returns from it
  // every member of the model interface an integrator calls (models/model_interface.hpp), on vectors sized once
  for (const SceneCase& c : every_case()) {
    SCOPED_TRACE(c.name);
    const CompiledScene compiled = compile_scene(c.scene, Method::rk4);
    const SceneModel& model = compiled.model();
    Eigen::VectorXd y = model.coordinates(c.initial, 0.0), dy(y.size()), stage(y.size());
    Eigen::VectorXd xi(model.tangent_count()), theta = Eigen::VectorXd::Constant(model.tangent_count(), 1e-3);
    const auto evaluate_all = [&] {
      model.rate(y, dy);
      model.velocity(y, xi);
      model.retract(y, theta, stage);
      model.velocity_at(y, theta, xi);
      model.dexp_inv(theta, xi);
      model.kick(y, 1e-3);
      model.drift(y, 1e-3);
      model.implicit_midpoint_step(y, 1e-3);
      if (!c.whole_motion) {  // the members of the methods a gyrostat or a tree is refused
        model.kick_implicit_gyroscopic(y, 1e-3);
        model.loads_kick(y, 1e-3);
        model.free_flow<DlmRotation<true>>(y, 1e-3);
        model.free_flow<ExactRotation>(y, 1e-3);
      }
      model.project(y);
    };
    evaluate_all();  // the first evaluation sizes MutualGravity's thread-local scratch columns, once per thread
    EXPECT_EQ(allocations_during(evaluate_all), 0);
  }
}

TEST(AllocationFree, NoOneBodyRunAllocatesPerStep) {
  if (!counts_allocations) GTEST_SKIP() << why_not_counted;  // in the test body: a skip returns from it
  const RigidBody body(2.0, Eigen::Vector3d(1.0, 2.0, 3.0));
  for (const MethodInfo& info : method_table()) {
    SCOPED_TRACE(info.name);
    const auto run = [&](std::int64_t steps) {
      SimulationOptions o = options(info.method, steps);
      if (info.method != Method::exact) o.gravity_W = Eigen::Vector3d(0.0, 0.0, -9.81);
      return allocations_during([&] { simulate(body, tumbling(Eigen::Vector3d::Zero()), o); });
    };
    EXPECT_EQ(run(1000), run(10));
  }
}

}  // namespace
}  // namespace rigiddyn
