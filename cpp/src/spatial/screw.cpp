#include "rigiddyn/spatial/screw.hpp"

#include <cmath>
#include <limits>

#include "rigiddyn/check.hpp"

namespace rigiddyn {

namespace {

// u / |u| for a nonzero u of any size: u scaled by the power of two of its largest entry (exact) before its norm is
// taken, so that a subnormal u keeps a unit direction (its own norm rounds to a multiple of 5e-324: u / |u| is then off
// by tens of per cent, e.g. 0.5 for each entry of (1, 1, 1) 5e-324, whose norm rounds to 1e-323)
Eigen::Vector3d unit(const Eigen::Vector3d& u) {
  const int e = std::ilogb(u.cwiseAbs().maxCoeff());
  const Eigen::Vector3d scaled = u.unaryExpr([e](double x) { return std::ldexp(x, -e); });
  return scaled / scaled.norm();
}

}  // namespace

// Rigid-body notes §4.10 (ISA): direction w/|w|, point (w x v)/|w|^2, pitch (w . v)/|w|^2, magnitude |w|.
Screw twist_to_screw(const Motion& twist) {
  const Vector6d wv = twist.to_vector();
  require_finite(wv.transpose(), "twist");
  const Eigen::Vector3d& w = twist.angular;
  const Eigen::Vector3d& v = twist.linear;
  const double w_norm = w.stableNorm();
  if (w_norm == 0.0) {
    const double v_norm = v.stableNorm();
    if (v_norm == 0.0) throw_invalid("twist", "a nonzero twist (a zero twist has no screw axis)", wv.transpose());
    // pure translation: a screw of infinite pitch along v
    return Screw{unit(v), Eigen::Vector3d::Zero(), std::numeric_limits<double>::infinity(), v_norm};
  }
  // divide by |w| twice rather than by |w|^2, which underflows first
  const Eigen::Vector3d direction = unit(w);
  Screw screw{direction, direction.cross(v) / w_norm, direction.dot(v) / w_norm, w_norm};
  if (!screw.point.allFinite() || !std::isfinite(screw.pitch)) {
    throw_invalid("twist", "an angular part large enough for a finite screw axis", wv.transpose());
  }
  return screw;
}

// w = magnitude direction, v = magnitude (point x direction + pitch direction).
Motion screw_to_twist(const Screw& screw) {
  require_finite(screw.direction, "direction");
  require_finite(screw.point, "point");
  require_finite(screw.magnitude, "magnitude");
  if (std::abs(screw.direction.norm() - 1.0) > 1e-9) throw_invalid("direction", "a unit vector", screw.direction);
  if (std::isinf(screw.pitch) && screw.pitch > 0) return Motion(Eigen::Vector3d::Zero(), screw.magnitude * screw.direction);
  require_finite(screw.pitch, "pitch");
  const Eigen::Vector3d w = screw.magnitude * screw.direction;
  return Motion(w, screw.point.cross(w) + screw.pitch * w);
}

}  // namespace rigiddyn
