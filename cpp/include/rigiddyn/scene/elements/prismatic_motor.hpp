// A motor in a prismatic joint of a tree (a linear actuator, a slider's drive): the joint force τ along the
// joint's axis on [t_start, t_end), on the link and its reaction on the parent (scene/elements/joint_motor.hpp has
// the schedule, joint_force.hpp the wrenches).
#pragma once
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/elements/joint_motor.hpp"
#include "rigiddyn/scene/elements/time_window.hpp"
#include "rigiddyn/tree/joints/prismatic_joint.hpp"

#include <limits>
#include <tuple>
#include <vector>

namespace rigiddyn {

// The spec: the link body `body` (its joint prismatic), the force τ [N] on [t_start, t_end) [s].
struct PrismaticMotor {
  static constexpr const char* element_type = "PrismaticMotor";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "A motor in the prismatic joint of the tree link `body` (a body of Scene.add_tree): the joint force `force` [N] "
      "along the joint's axis on [t_start, t_end) [s] (by default all of time), none outside, on the link and the opposite on its parent (W "
      "for a root link), both through the joint's origin, so that a tree's momenta are conserved; its power is force "
      "dq/dt. A run splits its steps at t_start and t_end. Several windows: one PrismaticMotor each. A "
      "rigiddyn.Controller may command its force (held until its next sample, in place of the window).";
  static constexpr const char* example = R"py(A force of 4 N for the first second on a 2 kg slider: 2 m/s after it, and 1 + 2 × 2 = 5 m travelled at t = 3 s:

>>> tree = rd.Tree()
>>> slider = tree.add_link("slider", -1, rd.PrismaticJoint([1.0, 0.0, 0.0]), rd.SpatialInertia(2.0, [0.0, 0.0, 0.0], 0.1 * np.eye(3)))
>>> scene = rd.Scene()
>>> links = scene.add_tree(tree, "rail")
>>> scene.add(rd.PrismaticMotor(body=links[0], force=4.0, t_end=1.0))
0
>>> result = rd.simulate(scene, tree.joint_states([0.0]), 0.01, duration=3.0, method="rk4")
>>> result.joint_q[-1].round(12), result.joint_v[-1].round(12)
(array([5.]), array([2.])))py";  // the docstring's Examples (run as doctests)
  static constexpr const char* joint_kind = "prismatic";  // the joint it needs, for messages
  static constexpr const char* value_key = "force";
  using Term = JointMotorTerm<PrismaticMotor, PrismaticJoint>;  // what compile makes of it
  int body = 0;
  double force = 0.0;
  double t_start = -std::numeric_limits<double>::infinity();
  double t_end = std::numeric_limits<double>::infinity();

  double value() const { return force; }

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        body_field("body", &PrismaticMotor::body, "index of the tree link whose prismatic joint it drives"),
        scalar_field("force", &PrismaticMotor::force, "N", "the joint force [N] along the joint's axis").must_be_given(),
        scalar_field("t_start", &PrismaticMotor::t_start, "s", "the time it starts [s] (-inf: on from any time)").may_be_infinite(),
        scalar_field("t_end", &PrismaticMotor::t_end, "s", "the time it stops [s] (inf: never)").may_be_infinite());
  }

  // What the fields must satisfy together: a window that ends after it starts.
  void check_fields() const {
    detail::check_window(t_start, t_end);
  }

  // The times at which a run splits its steps: t_start and t_end.
  std::vector<AppliedLoad> switches() const { return detail::window_switches(t_start, t_end); }
};

}  // namespace rigiddyn
