#include "rigiddyn/inertia/point_masses.hpp"

#include <string>

#include "rigiddyn/check.hpp"

namespace rigiddyn {

SpatialInertia from_point_masses(const Eigen::Ref<const Eigen::VectorXd>& masses,
                                 const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>& positions) {
  if (masses.size() != positions.rows() || masses.size() == 0) {
    throw_invalid("positions", "one row per mass (" + std::to_string(masses.size()) + " masses, n >= 1)",
                  std::to_string(positions.rows()) + " rows");
  }
  for (Eigen::Index i = 0; i < masses.size(); ++i) {
    if (!(std::isfinite(masses(i)) && masses(i) >= 0.0)) {
      throw_invalid("masses[" + std::to_string(i) + "]", "a finite number >= 0", masses(i));
    }
  }
  require_finite(positions, "positions");
  const double m = masses.sum();  // (4.53)
  require_positive(m, "sum of masses");
  // about a reference point inside the set (the first position), to keep cancellation small
  const Eigen::RowVector3d ref = positions.row(0);
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < masses.size(); ++i) {
    const Eigen::Vector3d r = (positions.row(i) - ref).transpose();
    first += masses(i) * r;
    second += masses(i) * r * r.transpose();
  }
  const Eigen::Vector3d c = first / m;  // (4.54), relative to ref
  // inertia about ref, shifted to the centre (parallel axis)
  return SpatialInertia::from_inertia_about_point(m, ref.transpose() + c, inertia_from_second_moment(second),
                                                  ref.transpose());
}

}  // namespace rigiddyn
