// A torsion spring and damper in a revolute joint of a tree (a hinge's spring, a joint's viscous friction): the
// joint torque τ = −k (q − q0) − c q̇ about the joint's axis, on the link and its reaction on the parent
// (scene/elements/joint_spring_damper.hpp has the law and its wrenches).
#pragma once
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/elements/joint_spring_damper.hpp"
#include "rigiddyn/tree/joints/revolute_joint.hpp"

#include <tuple>

namespace rigiddyn {

// The spec: the link body `body` (its joint revolute), stiffness k [N m/rad], rest angle q0 [rad], damping c
// [N m s/rad], k and c >= 0.
struct RevoluteSpringDamper {
  static constexpr const char* element_type = "RevoluteSpringDamper";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "A torsion spring and damper in the revolute joint of the tree link `body` (a body of Scene.add_tree): the "
      "joint torque -(stiffness (q - rest_angle) + damping dq/dt) [N m] about the joint's axis, q the joint's angle "
      "[rad], on the link and the opposite on its parent (W for a root link), so that a tree's momenta are "
      "conserved. Potential V = stiffness (q - rest_angle)^2/2 [J].";
  static constexpr const char* example = R"py(A wheel of I = 0.5 kg m² on a torsion spring of 2 N m/rad turns back and forth at ω = √(k/I) = 2 rad/s:
after one period π s it is back at its start:

>>> tree = rd.Tree()
>>> wheel = tree.add_link("wheel", -1, rd.RevoluteJoint([0.0, 0.0, 1.0]), rd.SpatialInertia(2.0, [0.0, 0.0, 0.0], 0.5 * np.eye(3)))
>>> scene = rd.Scene()
>>> links = scene.add_tree(tree, "shaft")
>>> scene.add(rd.RevoluteSpringDamper(body=links[0], stiffness=2.0))
0
>>> result = rd.simulate(scene, tree.joint_states([0.1]), np.pi / 1000, steps=1000, method="rk4")
>>> result.joint_q[-1].round(9)
array([0.1]))py";  // the docstring's Examples (run as doctests)
  static constexpr const char* joint_kind = "revolute";  // the joint it needs, for messages
  static constexpr const char* rest_key = "rest_angle";
  using Term = JointSpringDamperTerm<RevoluteSpringDamper, RevoluteJoint>;  // what compile makes of it
  int body = 0;
  double stiffness = 0.0;
  double rest_angle = 0.0;
  double damping = 0.0;

  double rest() const { return rest_angle; }

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        body_field("body", &RevoluteSpringDamper::body, "index of the tree link whose revolute joint holds it"),
        scalar_field("stiffness", &RevoluteSpringDamper::stiffness, "N*m/rad", "torsion stiffness k [N m/rad]").must_be_given().at_least_zero(),
        scalar_field("rest_angle", &RevoluteSpringDamper::rest_angle, "rad", "the joint angle q0 at which the spring is relaxed [rad]"),
        scalar_field("damping", &RevoluteSpringDamper::damping, "N*m*s/rad", "damping coefficient c [N m s/rad]").at_least_zero());
  }
};

}  // namespace rigiddyn
