#include "rigiddyn/tree/tree_link.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/quaternion.hpp"

#include <cmath>
#include <string>

namespace rigiddyn {

JointState checked_state(const TreeLink& body, const JointState& state, const std::string& name) {
  const Link& link = body.tree->link(body.link);
  const std::string joint = std::string("the ") + joint_kind(link.joint) + " joint of link '" + link.name + "'";
  if (state.q.size() != link.nq) {
    throw_invalid(name + ".q", std::to_string(link.nq) + " coordinates (" + joint + ")", state.q.size());
  }
  if (state.v.size() != link.nv) {
    throw_invalid(name + ".v", std::to_string(link.nv) + " velocities (" + joint + ")", state.v.size());
  }
  checked_state(state, name);
  if (joint_has_quaternion(link.joint)) {
    const double norm = state.q.tail<4>().norm();
    if (!(std::abs(norm - 1.0) <= unit_quaternion_tolerance)) {
      throw_invalid(name + ".q", "a unit quaternion (x, y, z, w) in its last four entries, |q| within 1e-6 of 1 (" +
                                     joint + ")",
                    state.q.transpose().eval());
    }
  }
  return state;
}

JointState checked_state(const JointState& state, const std::string& name) {
  require_finite(state.q.transpose(), name + ".q");
  require_finite(state.v.transpose(), name + ".v");
  return state;
}

}  // namespace rigiddyn
