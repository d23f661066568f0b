// The screw of a twist: its instantaneous screw axis (ISA, Rigid-body notes §4.10-4.11; Chasles/Mozzi).
// A twist [w; v] (expressed in a frame A, v at A's origin) equals a rotation at angular speed |w|
// about the line {point + t direction} plus a translation pitch*|w| along it:
//   direction = w/|w|, point = (w x v)/|w|^2 (the point of the axis closest to A's origin),
//   pitch = (w . v)/|w|^2 [m/rad], magnitude = |w|;
// and back: w = magnitude direction, v = magnitude (point x direction + pitch direction).
// A pure translation (w = 0) has pitch = +inf, direction = v/|v|, point = origin, magnitude = |v|.
#pragma once
#include <Eigen/Core>

#include "rigiddyn/spatial/motion.hpp"

namespace rigiddyn {

struct Screw {
  Eigen::Vector3d direction;  // unit axis direction, in the twist's frame
  Eigen::Vector3d point;      // point on the axis closest to the frame's origin [m]
  double pitch;               // translation per radian [m/rad]; +inf for a pure translation
  double magnitude;           // |w| [rad/s], or |v| [m/s] for a pure translation
};

// Throws std::invalid_argument naming "twist" for a zero twist (no axis) or non-finite entries.
Screw twist_to_screw(const Motion& twist);
// The inverse map; throws std::invalid_argument on a non-unit direction or non-finite entries.
Motion screw_to_twist(const Screw& screw);

}  // namespace rigiddyn
