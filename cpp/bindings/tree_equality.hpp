// Exact equality of joints and trees for the bindings' ==, and of the trees a scene's links hold: the same kind
// and axis; the same gravity and, link by link, names, parents, joints, placements and inertias (bit for bit).
#pragma once
#include "rigiddyn/tree/tree.hpp"

#include <variant>

namespace rigiddyn::bindings {

// The same joint: its kind and, for a revolute or prismatic one, its axis
inline bool same_joint(const Joint& a, const Joint& b) {
  if (a.index() != b.index()) return false;
  if (const auto* r = std::get_if<RevoluteJoint>(&a)) return r->axis == std::get<RevoluteJoint>(b).axis;
  if (const auto* p = std::get_if<PrismaticJoint>(&a)) return p->axis == std::get<PrismaticJoint>(b).axis;
  return true;
}

// The same tree: its gravity, and link by link the names, parents, joints, placements and inertias (exact)
inline bool same_tree(const Tree& a, const Tree& b) {
  if (a.num_links() != b.num_links() || a.gravity() != b.gravity()) return false;
  for (int i = 0; i < a.num_links(); ++i) {
    const Link& x = a.link(i);
    const Link& y = b.link(i);
    if (x.name != y.name || x.parent != y.parent || !same_joint(x.joint, y.joint) ||
        x.X_T.rotation() != y.X_T.rotation() || x.X_T.translation() != y.X_T.translation() ||
        x.inertia.mass() != y.inertia.mass() || x.inertia.com() != y.inertia.com() ||
        x.inertia.inertia_com() != y.inertia.inertia_com()) {
      return false;
    }
  }
  return true;
}

}  // namespace rigiddyn::bindings
