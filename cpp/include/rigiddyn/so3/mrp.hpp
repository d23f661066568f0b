// Modified Rodrigues parameters (MRP): p = axis tan(angle/4) = v / (1 + w) for a unit quaternion
// (v, w) (Shuster, "A survey of attitude representations", J. Astronaut. Sci. 41 (1993)).
// q and -q give the two "shadow" sets p and -p/|p|², one with |p| <= 1 (angle <= pi), as SciPy's
// Rotation.as_mrp / from_mrp.
#pragma once
#include "rigiddyn/so3/quaternion.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace rigiddyn {

// The MRP of a unit quaternion with |p| <= 1: q is first taken with w >= 0, so 1 + w >= 1 and the
// division is well conditioned for every rotation (|p| = 1 at angle pi). Inline: it runs per item in
// the array loops.
inline Eigen::Vector3d quat_to_mrp(const Eigen::Quaterniond& q) {
  if (q.w() == 0.0) {  // a half turn: quat_canonical's tie rule picks the sign
    const Eigen::Quaterniond c = quat_canonical(q);
    return c.vec() / (1.0 + c.w());
  }
  // c = sign(w) q: c.vec() / (1 + c.w()) = q.vec() / (w + sign(w)), the same numbers without a branch on
  // the sign (random signs would mispredict it)
  return q.vec() / (q.w() + std::copysign(1.0, q.w()));
}

// The unit quaternion ((2 p, 1 - |p|²) / (1 + |p|²)) of any finite p (either shadow set; w < 0
// when |p| > 1). Written in s = min(|p|, 1/|p|) so that |p|² neither overflows nor loses p's
// direction for |p| up to the largest double. Throws std::invalid_argument for a non-finite p.
Eigen::Quaterniond mrp_to_quat(const Eigen::Vector3d& p);

}  // namespace rigiddyn
