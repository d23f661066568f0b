// A motor in a revolute joint of a tree (a hinge's drive, a robot joint's actuator): the joint torque τ about the
// joint's axis on [t_start, t_end), on the link and its reaction on the parent (scene/elements/joint_motor.hpp has
// the schedule, joint_force.hpp the wrenches).
#pragma once
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/elements/joint_motor.hpp"
#include "rigiddyn/scene/elements/time_window.hpp"
#include "rigiddyn/tree/joints/revolute_joint.hpp"

#include <limits>
#include <tuple>
#include <vector>

namespace rigiddyn {

// The spec: the link body `body` (its joint revolute), the torque τ [N m] on [t_start, t_end) [s].
struct RevoluteMotor {
  static constexpr const char* element_type = "RevoluteMotor";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "A motor in the revolute joint of the tree link `body` (a body of Scene.add_tree): the joint torque `torque` "
      "[N m] about the joint's axis on [t_start, t_end) [s] (by default all of time), none outside, on the link and the opposite on its parent "
      "(W for a root link), so that a tree's momenta are conserved; its power is torque dq/dt. A run splits its steps "
      "at t_start and t_end. Several windows: one RevoluteMotor each. A rigiddyn.Controller may command its torque "
      "(held until its next sample, in place of the window).";
  static constexpr const char* example = R"py(A torque of 1 N m for the first second on a wheel of I = 0.5 kg m²: 2 rad/s after it, and 1 + 2 × 2 = 5 rad
turned at t = 3 s:

>>> tree = rd.Tree()
>>> wheel = tree.add_link("wheel", -1, rd.RevoluteJoint([0.0, 0.0, 1.0]), rd.SpatialInertia(2.0, [0.0, 0.0, 0.0], 0.5 * np.eye(3)))
>>> scene = rd.Scene()
>>> links = scene.add_tree(tree, "shaft")
>>> scene.add(rd.RevoluteMotor(body=links[0], torque=1.0, t_end=1.0))
0
>>> result = rd.simulate(scene, tree.joint_states([0.0]), 0.01, duration=3.0, method="rk4")
>>> result.joint_q[-1].round(12), result.joint_v[-1].round(12)
(array([5.]), array([2.])))py";  // the docstring's Examples (run as doctests)
  static constexpr const char* joint_kind = "revolute";  // the joint it needs, for messages
  static constexpr const char* value_key = "torque";
  using Term = JointMotorTerm<RevoluteMotor, RevoluteJoint>;  // what compile makes of it
  int body = 0;
  double torque = 0.0;
  double t_start = -std::numeric_limits<double>::infinity();
  double t_end = std::numeric_limits<double>::infinity();

  double value() const { return torque; }

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        body_field("body", &RevoluteMotor::body, "index of the tree link whose revolute joint it drives"),
        scalar_field("torque", &RevoluteMotor::torque, "N*m", "the joint torque [N m] about the joint's axis").must_be_given(),
        scalar_field("t_start", &RevoluteMotor::t_start, "s", "the time it starts [s] (-inf: on from any time)").may_be_infinite(),
        scalar_field("t_end", &RevoluteMotor::t_end, "s", "the time it stops [s] (inf: never)").may_be_infinite());
  }

  // What the fields must satisfy together: a window that ends after it starts.
  void check_fields() const {
    detail::check_window(t_start, t_end);
  }

  // The times at which a run splits its steps: t_start and t_end.
  std::vector<AppliedLoad> switches() const { return detail::window_switches(t_start, t_end); }
};

}  // namespace rigiddyn
