// A link of a kinematic tree as a body of a scene (docs/guide/trees.md, "A tree in a scene"): the scene holds one
// body per link, consecutive and in link order, so that force elements act on each link as on any body (at its
// centre of mass, in axes parallel to the link frame L), while the tree's joints couple their motions. The state
// of a link's body is its joint's: q_i and v_i, the link's segments of the tree's q and v (tree/tree.hpp).
#pragma once
#include "rigiddyn/tree/tree.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>

namespace rigiddyn {

// Link `link` of `tree` (shared by the tree's links in a scene: the scene's copy of the tree).
struct TreeLink {
  std::shared_ptr<const Tree> tree;
  int link = 0;

  double mass() const { return tree->link(link).inertia.mass(); }
  // I_C [kg m²]: about the link's centre of mass, in axes parallel to L (the body frame B of its body)
  const Eigen::Matrix3d& inertia_com() const { return tree->link(link).inertia.inertia_com(); }
  // c_L [m]: the centre of mass in the link frame L
  const Eigen::Vector3d& com() const { return tree->link(link).inertia.com(); }
  const std::string& name() const { return tree->link(link).name; }
};

// The state of a tree link's joint: q (its nq coordinates: an angle [rad], an offset [m], a unit quaternion
// (x, y, z, w), or (p_JL [m], q_JL)) and v (its nv velocities, as in Tree's v).
struct JointState {
  Eigen::VectorXd q, v;
};

// state with its sizes those of `body`'s joint, finite, each quaternion within unit_quaternion_tolerance of unit
// norm; std::invalid_argument naming `name` otherwise.
JointState checked_state(const TreeLink& body, const JointState& state, const std::string& name = "state");
// The same without the body (its finite values only): the scene's generic check before the body's.
JointState checked_state(const JointState& state, const std::string& name = "state");

}  // namespace rigiddyn
