// Rotation matrices R in SO(3) and their conversion to and from unit quaternions.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string_view>

namespace rigiddyn {

// Tolerance of checked_rotation_matrix: R is accepted when max_ij |(R^T R - I)_ij| <=
// rotation_matrix_tolerance and det R > 0 (so det R = +1 to about the same tolerance). Error
// messages quote the value 1e-6: keep them in step.
inline constexpr double rotation_matrix_tolerance = 1e-6;

// Throws the std::invalid_argument of checked_rotation_matrix for an R that failed its test
// (out of line and cold: the message is built only on failure).
[[noreturn]] void throw_not_rotation_matrix(const Eigen::Matrix3d& R, std::string_view name);

// R itself when R is a rotation matrix (orthonormal, det +1 within rotation_matrix_tolerance);
// throws std::invalid_argument naming `name` on a non-finite entry, a non-orthonormal matrix or
// a reflection (det -1). Inline: it guards constructors (Transform) that run per item in loops.
inline Eigen::Matrix3d checked_rotation_matrix(const Eigen::Matrix3d& R, std::string_view name) {
  // NaN or ±inf entries make the error NaN, which fails the comparison
  const double orthonormality_error = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(orthonormality_error <= rotation_matrix_tolerance && R.determinant() > 0.0)) throw_not_rotation_matrix(R, name);
  return R;
}

// R(q) of a unit quaternion q (Eigen's toRotationMatrix; inline, as it runs per item in loops).
inline Eigen::Matrix3d quat_to_matrix(const Eigen::Quaterniond& q) { return q.toRotationMatrix(); }

// The unit quaternion of a rotation matrix R, canonical (quat_canonical: w >= 0). Markley's
// method (F. L. Markley, "Unit Quaternion from Rotation Matrix", J. Guidance, Control, and Dynamics
// 31(2), 2008), with SciPy's choice of branch: the largest of R_00, R_11, R_22 and tr R picks the
// component computed from the diagonal, so it is accurate at every angle, including pi.
// R is assumed orthonormal (see checked_rotation_matrix, projected_rotation_matrix in
// nearest_rotation.hpp); the result is normalised.
Eigen::Quaterniond matrix_to_quat(const Eigen::Matrix3d& R);

}  // namespace rigiddyn
