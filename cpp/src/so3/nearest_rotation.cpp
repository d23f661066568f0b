#include "rigiddyn/so3/nearest_rotation.hpp"

#include "rigiddyn/check.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>

#include <string>

namespace rigiddyn {

namespace {
// M = U S V^T with the singular values S in decreasing order
Eigen::JacobiSVD<Eigen::Matrix3d> svd_of(const Eigen::Matrix3d& M) {
  return Eigen::JacobiSVD<Eigen::Matrix3d>(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
}

// R = U diag(1, 1, det(U V^T)) V^T: flipping the smallest singular direction keeps det R = +1
// at the least cost in |M - R|_F (Kabsch, Umeyama)
Eigen::Matrix3d rotation_of(const Eigen::JacobiSVD<Eigen::Matrix3d>& svd) {
  const Eigen::Matrix3d& U = svd.matrixU();
  const Eigen::Matrix3d& V = svd.matrixV();
  const double d = (U * V.transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return U * Eigen::Vector3d(1.0, 1.0, d).asDiagonal() * V.transpose();
}
}  // namespace

Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& M) {
  require_finite(M, "M");
  return rotation_of(svd_of(M));
}

bool orthonormal_as_scipy(const Eigen::Matrix3d& M) {
  // numpy.isclose(M M^T, I, atol=1e-12) with its default rtol = 1e-5; NaN fails every comparison
  const Eigen::Matrix3d deviation = (M * M.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs();
  const Eigen::Matrix3d bound = Eigen::Matrix3d::Constant(1e-12) + 1e-5 * Eigen::Matrix3d::Identity();
  return (deviation.array() <= bound.array()).all();
}

Eigen::Matrix3d projected_rotation_matrix(const Eigen::Matrix3d& M, std::string_view name_view) {
  const std::string name(name_view);
  if (!M.allFinite()) throw_invalid(name, "a rotation matrix of finite numbers", M);
  const double det = M.determinant();
  if (!(det > 0.0)) {
    throw_invalid(name, "a rotation matrix (det > 0; a reflection or a singular matrix is no rotation)",
                  format_value(M) + " with det = " + format_value(det));
  }
  if (orthonormal_as_scipy(M)) return M;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd = svd_of(M);
  const double deviation = (svd.singularValues().array() - 1.0).abs().maxCoeff();
  if (!(deviation <= near_rotation_tolerance)) {
    throw_invalid(name,
                  "a rotation matrix (orthonormal up to rounding: singular values within 0.05 of 1, "
                  "then projected onto the nearest rotation)",
                  format_value(M) + " with max |sigma - 1| = " + format_value(deviation));
  }
  return rotation_of(svd);
}

}  // namespace rigiddyn
