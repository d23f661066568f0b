// A linear spring and damper in a prismatic joint of a tree (a slider's spring, a shock absorber): the joint force
// τ = −k (q − q0) − c q̇ along the joint's axis, on the link and its reaction on the parent
// (scene/elements/joint_spring_damper.hpp has the law and its wrenches).
#pragma once
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/elements/joint_spring_damper.hpp"
#include "rigiddyn/tree/joints/prismatic_joint.hpp"

#include <tuple>

namespace rigiddyn {

// The spec: the link body `body` (its joint prismatic), stiffness k [N/m], rest position q0 [m], damping c
// [N s/m], k and c >= 0.
struct PrismaticSpringDamper {
  static constexpr const char* element_type = "PrismaticSpringDamper";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "A linear spring and damper in the prismatic joint of the tree link `body` (a body of Scene.add_tree): the "
      "joint force -(stiffness (q - rest_position) + damping dq/dt) [N] along the joint's axis, q the joint's "
      "offset [m], on the link and the opposite on its parent (W for a root link), both through the joint's "
      "origin, so that a tree's momenta are conserved. Potential V = stiffness (q - rest_position)^2/2 [J].";
  static constexpr const char* example = R"py(A 2 kg slider on a spring of 8 N/m oscillates at ω = √(k/m) = 2 rad/s about its rest position: after one
period π s it is back at its start:

>>> tree = rd.Tree()
>>> slider = tree.add_link("slider", -1, rd.PrismaticJoint([1.0, 0.0, 0.0]), rd.SpatialInertia(2.0, [0.0, 0.0, 0.0], 0.1 * np.eye(3)))
>>> scene = rd.Scene()
>>> links = scene.add_tree(tree, "rail")
>>> scene.add(rd.PrismaticSpringDamper(body=links[0], stiffness=8.0, rest_position=0.5))
0
>>> result = rd.simulate(scene, tree.joint_states([0.6]), np.pi / 1000, steps=1000, method="rk4")
>>> result.joint_q[-1].round(9)
array([0.6]))py";  // the docstring's Examples (run as doctests)
  static constexpr const char* joint_kind = "prismatic";  // the joint it needs, for messages
  static constexpr const char* rest_key = "rest_position";
  using Term = JointSpringDamperTerm<PrismaticSpringDamper, PrismaticJoint>;  // what compile makes of it
  int body = 0;
  double stiffness = 0.0;
  double rest_position = 0.0;
  double damping = 0.0;

  double rest() const { return rest_position; }

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        body_field("body", &PrismaticSpringDamper::body, "index of the tree link whose prismatic joint holds it"),
        scalar_field("stiffness", &PrismaticSpringDamper::stiffness, "N/m", "spring stiffness k [N/m]").must_be_given().at_least_zero(),
        scalar_field("rest_position", &PrismaticSpringDamper::rest_position, "m", "the joint offset q0 at which the spring is relaxed [m]"),
        scalar_field("damping", &PrismaticSpringDamper::damping, "N*s/m", "damping coefficient c [N s/m]").at_least_zero());
  }
};

}  // namespace rigiddyn
