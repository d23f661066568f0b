// The one-body layout of the scene model (scene/one_body_scene_model.hpp): a scene of one particle, planar body, rigid
// body (each Euler form) or pinned planar body under at most one UniformGravity and one ScheduledLoads runs on it,
// and moves its body bitwise as the generic scene model does, for every method but 'exact' (the closed form) and
// every element set in either order. The implicit midpoint is held to its solver's tolerance instead: its
// convergence test takes the norm of the layout's shorter coordinates. Under gravity alone the work and the impulses
// are exact from the records: V(t0) − V(t) and, for a free body, m g (t − t0) and Δ(p × m v), which the generic
// model's integrals of a free or planar body's translation match to their rounding. A pivoted body's layout, which
// compile does not choose yet, is held to the same. A layout that never switches refuses a switch schedule.
#include <gtest/gtest.h>

#include "test_numbers.hpp"
#include "rigiddyn/integrators/implicit_midpoint.hpp"
#include "rigiddyn/scene/one_body_scene.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace rigiddyn {
namespace {

using rigiddyn::test::kEps;

struct Case {
  std::string name;
  Body body;
  BodyState state;
  AppliedLoad load;      // the ScheduledLoads' load (on for part of the run: its switches split steps)
  Eigen::Vector3d g_W;   // the UniformGravity's
  Eigen::Vector3d point_B = Eigen::Vector3d::Zero();  // the ScheduledLoads' point of application
};

AppliedLoad load_of(const Eigen::Vector3d& force, const Eigen::Vector3d& torque, Frame frame) {
  AppliedLoad load{force, torque, frame};
  load.t_start = 0.0125, load.t_end = 0.5037;
  return load;
}

std::vector<Case> cases() {
  RigidBodyState tumbling;
  tumbling.p_W = Eigen::Vector3d(0.5, -1.0, 2.0);
  tumbling.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1.0, -1.0, 2.0).normalized()));
  tumbling.v_W = Eigen::Vector3d(0.2, 0.0, -0.1);
  tumbling.w_B = Eigen::Vector3d(0.3, 1.0, 0.2);
  Eigen::Matrix3d full;
  full << 2.0, 0.1, -0.2, 0.1, 3.0, 0.3, -0.2, 0.3, 4.0;
  const AppliedLoad turning = load_of(Eigen::Vector3d(0.1, -0.3, 0.2), Eigen::Vector3d(0.3, -0.2, 0.4), Frame::body);
  const AppliedLoad in_plane = load_of(Eigen::Vector3d(0.2, 0.1, 0.0), Eigen::Vector3d(0.0, 0.0, 0.3), Frame::body);
  const Eigen::Vector3d down(0.0, 0.0, -9.81), plane_down(0.0, -9.81, -1.0);
  return {
      {"particle", Particle(0.5), ParticleState{Eigen::Vector3d(1.0, 2.0, 3.0), Eigen::Vector3d(0.5, 0.0, 2.0)},
       load_of(Eigen::Vector3d(0.3, -0.1, 0.2), Eigen::Vector3d::Zero(), Frame::world), down},
      {"planar", PlanarBody(1.0, 0.3), PlanarBodyState{Eigen::Vector2d(0.1, 0.2), 0.3, Eigen::Vector2d(1.0, 0.0), 0.5},
       in_plane, plane_down},
      {"spherical", RigidBody(2.0, Eigen::Vector3d(1.0, 1.0, 1.0)), tumbling, turning, down},
      {"principal", RigidBody(2.0, Eigen::Vector3d(1.0, 2.0, 3.0)), tumbling, turning, down},
      {"full", RigidBody(2.0, full), tumbling, turning, down},
      // loads that need no attitude, that need R_WB for their torque's impulse alone, and a force off the centre
      {"principal, world force", RigidBody(2.0, Eigen::Vector3d(1.0, 2.0, 3.0)), tumbling,
       load_of(Eigen::Vector3d(0.3, -0.1, 0.2), Eigen::Vector3d::Zero(), Frame::world), down},
      {"principal, body torque", RigidBody(2.0, Eigen::Vector3d(1.0, 2.0, 3.0)), tumbling,
       load_of(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.3, -0.2, 0.4), Frame::body), down},
      {"full, world force off the centre", RigidBody(2.0, full), tumbling,
       load_of(Eigen::Vector3d(0.3, -0.1, 0.2), Eigen::Vector3d::Zero(), Frame::world), down, Eigen::Vector3d(0.1, 0.2, -0.3)},
      {"pinned planar", PivotedPlanarBody(1.0, 0.1, Eigen::Vector2d(0.1, -0.5)), PivotedPlanarBodyState{0.5, 1.0}, in_plane,
       Eigen::Vector3d(0.0, -9.81, 0.0)},
  };
}

// The elements of the scene: bit 0 a UniformGravity, bit 1 a ScheduledLoads, bit 2 the loads first
std::vector<Element> elements_of(const Case& c, int set) {
  std::vector<Element> out;
  if (set & 1) out.push_back(UniformGravity{c.g_W, {}});
  if (set & 2) out.push_back(ScheduledLoads{0, {c.load}, c.point_B});
  if (set & 4) std::reverse(out.begin(), out.end());
  return out;
}

// max |x| over the records of a column (at least the smallest normal number)
double largest(const std::vector<double>& x) {
  double m = std::numeric_limits<double>::min();
  for (const double v : x) m = std::max(m, std::abs(v));
  return m;
}

void expect_near_columns(const std::vector<double>& layout, const std::vector<double>& generic, double bound, const char* what) {
  ASSERT_EQ(layout.size(), generic.size()) << what;
  for (std::size_t i = 0; i < layout.size(); ++i) EXPECT_NEAR(layout[i], generic[i], bound) << what << "[" << i << "]";
}

// The same column of the layout's run and of the generic model's: bitwise, but for the implicit midpoint: two solves
// of one fixed point, each to the solver's tolerance relative to the state, differ by at most 2 × tolerance × |y| a
// step; over the 100 steps of these short runs (their flows do not amplify a difference tenfold in 1 s),
// 100 × 2 × tolerance × |y| × 10
void expect_column(const std::vector<double>& layout, const std::vector<double>& generic, Method method, const char* what) {
  if (method != Method::implicit_midpoint) {
    EXPECT_EQ(layout, generic) << what;
    return;
  }
  expect_near_columns(layout, generic, 2000.0 * implicit_midpoint_solver::tolerance * (1.0 + largest(generic)), what);
}

TEST(OneBodyLayout, MovesTheBodyBitwiseAsTheGenericModel) {
  for (const Case& c : cases()) {
    for (const int set : {0, 1, 2, 3, 7}) {
      for (const MethodInfo& info : method_table()) {
        if (info.method == Method::exact) continue;  // the closed form (test_scene_simulate.cpp)
        SCOPED_TRACE(c.name + ", elements " + std::to_string(set) + ", " + info.name);
        Scene scene;
        scene.bodies = {c.body};
        scene.elements = elements_of(c, set);
        SimulationOptions o;
        o.method = info.method, o.dt = 0.01, o.steps = 100, o.record_every = 3;
        const CompiledScene compiled = compile_scene(scene, info.method);
        ASSERT_EQ(compiled.path(), ScenePath::one_body);
        ASSERT_EQ(one_body_model_if<detail::FastOneBodyModels>(compiled.one_body_model()), nullptr);  // a layout
        const SceneSimulation layout = simulate(compiled, {c.state}, o);
        const SceneModel& model = compiled.model();
        const SceneSimulation generic =
            detail::run_generic_scene(model, model.coordinates({c.state}, o.t0), o, compiled.switch_schedule(), nullptr);
        ASSERT_EQ(layout.size(), generic.size());
        const bool midpoint = info.method == Method::implicit_midpoint;
        for (const auto column : {&SceneSimulation::t, &SceneSimulation::p_W, &SceneSimulation::q_WB, &SceneSimulation::v_W,
                                  &SceneSimulation::w_B, &SceneSimulation::kinetic_energy, &SceneSimulation::potential_energy,
                                  &SceneSimulation::total_energy, &SceneSimulation::linear_momentum_W,
                                  &SceneSimulation::angular_momentum_W, &SceneSimulation::pivot_reaction_W,
                                  &SceneSimulation::angular_momentum_O_W, &SceneSimulation::mass, &SceneSimulation::power}) {
          expect_column(layout.*column, generic.*column, info.method, "a column");
        }
        const bool constrained = std::holds_alternative<PlanarBody>(c.body) || std::holds_alternative<PivotedPlanarBody>(c.body);
        const bool exact_gravity = set == 1;
        const bool pinned = std::holds_alternative<PivotedPlanarBody>(c.body);
        if (!exact_gravity) {
          expect_column(layout.work, generic.work, info.method, "work");
        } else if (pinned) {
          // gravity's work is V(t0) − V(t) (the pivot does none), where the generic model integrates m g·v_C with
          // the method's error: W + V = V(t0) to the rounding of one difference, 2 ε max|V|
          ASSERT_EQ(layout.work.size(), layout.size());
          for (std::size_t r = 0; r < layout.size(); ++r) {
            EXPECT_NEAR(layout.work[r] + layout.potential_energy[r], layout.potential_energy[0],
                        4.0 * kEps * largest(layout.potential_energy));
          }
        } else {
          // the generic model's work telescopes to m g·(p − p0) in every method (each step adds h m g·v̄ where the
          // position moves by h v̄); the sum of its 100 increments rounds by at most 100 ε Σ|increment| ≤
          // 100 ε m |g| max|v| t, and V(t0) − V(t) by a few ε |V|
          const double m = mass_of(c.body), t = o.dt * static_cast<double>(o.steps);
          const double bound = 100.0 * kEps * m * c.g_W.norm() * (1.0 + largest(generic.v_W)) * t +
                               8.0 * kEps * largest(generic.potential_energy);
          expect_near_columns(layout.work, generic.work, midpoint ? 1e-10 * (1.0 + largest(generic.work)) + bound : bound, "work");
        }
        if (constrained) {
          EXPECT_TRUE(layout.impulse_W.empty());  // its momentum balance is not applicable
          EXPECT_TRUE(layout.angular_impulse_W.empty());
        } else if (!exact_gravity) {
          expect_column(layout.impulse_W, generic.impulse_W, info.method, "impulse_W");
          expect_column(layout.angular_impulse_W, generic.angular_impulse_W, info.method, "angular_impulse_W");
        } else {
          // J = m g (t − t0) against the sum of its 100 h m g: 100 ε |J|; K = Δ(p × m v) against the sum of
          // h p × m g, which telescopes as the work does: 100 ε m |g| max|p| t plus the rounding of the differences
          const double m = mass_of(c.body), t = o.dt * static_cast<double>(o.steps);
          const double J = 100.0 * kEps * largest(generic.impulse_W) * 3.0;
          const double K = 100.0 * kEps * m * c.g_W.norm() * (1.0 + largest(generic.p_W)) * t * 3.0 +
                           8.0 * kEps * largest(generic.angular_momentum_W);
          const double slack = midpoint ? 1e-10 * (1.0 + largest(generic.angular_impulse_W)) : 0.0;
          // explicit Euler's K adds h p_n × m g a step while Δ(p × m v) adds h p_n × m g + h² v_n × m g (its
          // positions move by h v_n): they part by at most steps h² m |g| max|v|
          const double lag = info.method == Method::explicit_euler
                                 ? static_cast<double>(o.steps) * o.dt * o.dt * m * c.g_W.norm() * largest(generic.v_W) * 2.0
                                 : 0.0;
          expect_near_columns(layout.impulse_W, generic.impulse_W, J + slack, "impulse_W");
          expect_near_columns(layout.angular_impulse_W, generic.angular_impulse_W, K + slack + lag, "angular_impulse_W");
        }
        EXPECT_EQ(layout.diverged, generic.diverged);
        EXPECT_EQ(layout.unconverged_steps, generic.unconverged_steps);
      }
    }
  }
}

// A pivoted body's layout (which compile does not choose yet: its fast model is faster under loads), run directly as
// docs/perf/scenes.md measures it, moves the body bitwise as the generic model does: with no element (its stages
// then leave the attitude unformed, read only through a force), under gravity (the work V(t0) − V(t) to the
// rounding of one difference: the pivot does none) and under gravity and loads, each Euler form about the pivot.
template <OneBodyElements elements>
void expect_pivoted_layout_bitwise(const PivotedBody& body, const PivotedBodyState& state, Method method) {
  Scene scene;
  scene.bodies = {body};
  if (elements != OneBodyElements::none) scene.elements.push_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}});
  if (elements == OneBodyElements::gravity_and_loads) {
    scene.elements.push_back(ScheduledLoads{
        0, {load_of(Eigen::Vector3d(0.1, -0.3, 0.2), Eigen::Vector3d(0.3, -0.2, 0.4), Frame::body)}, Eigen::Vector3d::Zero()});
  }
  const CompiledScene compiled = compile_scene(scene, method);
  SimulationOptions o;
  o.method = method, o.dt = 0.01, o.steps = 100, o.record_every = 3;
  const auto& terms = compiled.model().terms();
  std::optional<UniformGravityTerm> gravity;
  std::optional<ScheduledLoadsTerm> loads;
  if (!terms.empty()) gravity = std::get<UniformGravityTerm>(terms[0]);
  if (terms.size() > 1) loads = std::get<ScheduledLoadsTerm>(terms[1]);
  int slots = 0;
  detail::with_first_slot(body, [&](const auto& slot) {
    ++slots;
    using Slot = std::decay_t<decltype(slot)>;
    const OneBodySceneModel<Slot, elements> layout_model(slot, body.mass(), gravity, 0, loads, 1);
    const SceneSimulation layout =
        detail::run_scene(layout_model, layout_model.coordinates({state}, o.t0), o, compiled.switch_schedule());
    const SceneModel& model = compiled.model();
    const SceneSimulation generic =
        detail::run_generic_scene(model, model.coordinates({state}, o.t0), o, compiled.switch_schedule(), nullptr);
    ASSERT_EQ(layout.size(), generic.size());
    for (const auto column : {&SceneSimulation::t, &SceneSimulation::p_W, &SceneSimulation::q_WB, &SceneSimulation::v_W,
                              &SceneSimulation::w_B, &SceneSimulation::kinetic_energy, &SceneSimulation::potential_energy,
                              &SceneSimulation::total_energy, &SceneSimulation::pivot_reaction_W,
                              &SceneSimulation::angular_momentum_O_W, &SceneSimulation::power}) {
      expect_column(layout.*column, generic.*column, method, "a column");
    }
    if (elements != OneBodyElements::gravity) {
      expect_column(layout.work, generic.work, method, "work");
    } else {
      for (std::size_t r = 0; r < layout.size(); ++r) {  // W + V = V(t0) to the rounding of one difference
        EXPECT_NEAR(layout.work[r] + layout.potential_energy[r], layout.potential_energy[0],
                    4.0 * kEps * largest(layout.potential_energy));
      }
    }
    EXPECT_EQ(layout.diverged, generic.diverged);
  });
  EXPECT_EQ(slots, 1);
}

TEST(OneBodyLayout, MovesAPivotedBodyBitwiseAsTheGenericModel) {
  Eigen::Matrix3d full;
  full << 0.05, 0.004, -0.002, 0.004, 0.06, 0.003, -0.002, 0.003, 0.08;
  const Eigen::Vector3d p_OC_B(0.02, -0.01, 0.2);
  PivotedBodyState state;
  state.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Eigen::Vector3d(1.0, 0.3, 0.0).normalized()));
  state.w_B = Eigen::Vector3d(0.5, -0.3, 12.0);
  // about O: a sphere's inertia stays spherical only with c at O; principal with c on a principal axis; full otherwise
  const std::vector<PivotedBody> bodies = {
      PivotedBody(RigidBody(1.0, Eigen::Vector3d(0.05, 0.05, 0.05)), Eigen::Vector3d::Zero()),
      PivotedBody(RigidBody(1.0, Eigen::Vector3d(0.05, 0.05, 0.08)), Eigen::Vector3d(0.0, 0.0, 0.2)),
      PivotedBody(RigidBody(1.0, full), p_OC_B)};
  for (const PivotedBody& body : bodies) {
    for (const MethodInfo& info : method_table()) {
      if (info.method == Method::exact) continue;
      SCOPED_TRACE(std::string(info.name) + ", inertia about O " + std::to_string(body.inertia_O()(0, 0)));
      expect_pivoted_layout_bitwise<OneBodyElements::none>(body, state, info.method);
      expect_pivoted_layout_bitwise<OneBodyElements::gravity>(body, state, info.method);
      expect_pivoted_layout_bitwise<OneBodyElements::gravity_and_loads>(body, state, info.method);
    }
  }
}

// A scene the layout does not carry takes the generic model (or a fast one): two bodies, a third element, a frame.
TEST(OneBodyLayout, OnlyItsScenes) {
  Scene two;
  two.bodies = {Particle(1.0), Particle(2.0)};
  EXPECT_EQ(compile_scene(two, Method::rk4).path(), ScenePath::generic);
  Scene drag;
  drag.bodies = {RigidBody(1.0, Eigen::Vector3d(1.0, 2.0, 3.0))};
  drag.elements = {UniformGravity{}, Drag{}};
  EXPECT_EQ(compile_scene(drag, Method::rk4).path(), ScenePath::generic);
  Scene gravity_twice;
  gravity_twice.bodies = {Particle(1.0)};
  gravity_twice.elements = {UniformGravity{}, UniformGravity{}};
  EXPECT_EQ(compile_scene(gravity_twice, Method::rk4).path(), ScenePath::generic);
  Scene pivoted;
  pivoted.bodies = {PivotedBody(RigidBody(1.0, Eigen::Vector3d(1.0, 1.0, 0.5)), Eigen::Vector3d(0.0, 0.0, 0.3))};
  pivoted.elements = {UniformGravity{}};
  const CompiledScene top = compile_scene(pivoted, Method::rk4);  // its fast model
  EXPECT_EQ(top.path(), ScenePath::one_body);
  EXPECT_NE(one_body_model_if<detail::FastOneBodyModels>(top.one_body_model()), nullptr);
}

TEST(OneBodyKey, RefusesAKindItDoesNotDescribe) {
  // a pinned body's pivot is not in the key: two pinned bodies of one mass would share it
  std::vector<double> key;
  EXPECT_THROW(one_body_key(PivotedPlanarBody(1.0, 0.1, Eigen::Vector2d(0.1, -0.5)), Eigen::Vector3d::Zero(), {}, key),
               std::invalid_argument);
  one_body_key(PlanarBody(1.0, 0.1), Eigen::Vector3d::Zero(), {}, key);
  std::vector<double> same;
  one_body_key(PlanarBody(1.0, 0.1), Eigen::Vector3d::Zero(), {}, same);
  EXPECT_TRUE(same_one_body_key(key, same));
  one_body_key(PlanarBody(1.0, 0.1), Eigen::Vector3d(0.0, -0.0, 0.0), {}, same);  // a zero's sign differs
  EXPECT_FALSE(same_one_body_key(key, same));
}

TEST(OneBodyLayout, ASwitchScheduleGivenToALayoutThatNeverSwitchesIsALogicError) {
  // a layout without ScheduledLoads compiles no split step (run_loop.hpp switches_never): a schedule given to its run
  // or its step anyway (no public call can: compile gives it an empty one) is refused, never skipped in silence
  using Layout = OneBodySceneModel<detail::ParticleSlot<detail::FirstPlace>, OneBodyElements::gravity>;
  const Layout layout = one_body_layout_as<Layout>(Particle(2.0), Eigen::Vector3d(0.0, 0.0, -9.81), {});
  AppliedLoad push{Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d::Zero(), Frame::world};
  push.t_start = 0.005, push.t_end = 0.5;  // switches on inside the first step
  const std::vector<AppliedLoad> schedule = {push};
  const Layout::Coordinates y = layout.coordinates({ParticleState{}}, 0.0);
  for (const Method method : {Method::rk4, Method::splitting_dlm}) {  // t at a run-time index, and at its fixed place
    SimulationOptions o;
    o.method = method, o.dt = 0.01, o.steps = 10;
    EXPECT_THROW(detail::run_scene(layout, y, o, schedule), std::logic_error) << method_info(method).name;
    EXPECT_THROW(detail::one_step(layout, y, o, detail::ScenePieces{schedule, layout.time_index()}), std::logic_error)
        << method_info(method).name;
    EXPECT_NO_THROW(detail::run_scene(layout, y, o, {})) << method_info(method).name;
  }
}

}  // namespace
}  // namespace rigiddyn
