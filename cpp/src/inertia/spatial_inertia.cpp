#include "rigiddyn/inertia/spatial_inertia.hpp"

#include "rigiddyn/check.hpp"

namespace rigiddyn {

SpatialInertia::SpatialInertia(double mass, const Eigen::Vector3d& com, const Eigen::Matrix3d& inertia_com)
    : mass_(mass), com_(com), inertia_com_(inertia_com) {
  require_positive(mass, "mass");
  require_finite(com, "com");
  require_finite(inertia_com, "inertia_com");
  const double scale = inertia_com.cwiseAbs().maxCoeff();
  if ((inertia_com - inertia_com.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale) {
    throw_invalid("inertia_com", "a symmetric matrix", inertia_com);
  }
}

}  // namespace rigiddyn
