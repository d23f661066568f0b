#include "rigiddyn/so3/matrix.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/quaternion.hpp"

#include <string>

namespace rigiddyn {

void throw_not_rotation_matrix(const Eigen::Matrix3d& R, std::string_view name_view) {
  const std::string name(name_view);
  require_finite(R, name);
  const double orthonormality_error = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(orthonormality_error <= rotation_matrix_tolerance)) {
    throw_invalid(name, "a rotation matrix (orthonormal: max |R^T R - I| <= 1e-6)",
                  format_value(R) + " with max |R^T R - I| = " + format_value(orthonormality_error));
  }
  throw_invalid(name, "a rotation matrix (det +1)", format_value(R) + " with det = " + format_value(R.determinant()));
}

Eigen::Quaterniond matrix_to_quat(const Eigen::Matrix3d& R) {
  // Eigen's Quaternion(Matrix3) is Shepperd's method: divide by the largest of 4w², 4x², 4y², 4z²
  return quat_canonical(Eigen::Quaterniond(R).normalized());
}

}  // namespace rigiddyn
