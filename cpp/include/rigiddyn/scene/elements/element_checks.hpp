// Private checks shared by the element terms of this folder (messages "<name>: expected ..., got ...").
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/body.hpp"

#include <Eigen/Core>

#include <cmath>
#include <string>
#include <variant>

namespace rigiddyn::detail {

// A finite scalar >= 0.
inline void require_nonnegative(double value, const std::string& name) {
  if (!(std::isfinite(value) && value >= 0.0)) throw_invalid(name, "a finite number >= 0", value);
}

// A point of `body` given in its frame B, from its centre of mass [m]: finite; zero on a particle (a
// point mass has no attitude to carry an offset); in the body's xy plane (z = 0) on a planar body, free
// or pinned (as scheduled loads' point_B).
inline void require_body_point(const Body& body, const Eigen::Vector3d& point_B, const std::string& name) {
  require_finite(point_B, name);
  if (!has_attitude(body) && !point_B.isZero(0.0)) {
    throw_invalid(name, "zero (a particle is a point)", point_B);
  }
  if (is_planar(body) && point_B.z() != 0.0) {
    throw_invalid(name, "a point in the body's xy plane (z = 0)", point_B);
  }
}

}  // namespace rigiddyn::detail
