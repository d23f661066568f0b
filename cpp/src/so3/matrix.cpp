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
  // Markley (2008), eqs. (4)-(7): each column of 4 q q^T from R; take the column of the largest
  // diagonal entry 4 q_i^2 (R_ii or tr R decides: 4 x^2 = 1 - tr R + 2 R_00, 4 w^2 = 1 + tr R).
  // The first maximum wins ties, as numpy's argmax in SciPy's from_matrix.
  const double trace = R.trace();
  int choice = 3;
  double largest = trace;
  for (int i = 2; i >= 0; --i) {
    if (R(i, i) >= largest) {
      largest = R(i, i);
      choice = i;
    }
  }
  Eigen::Vector4d xyzw;
  if (choice == 3) {
    xyzw << R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1), 1.0 + trace;
  } else {
    // (i, j, k) a cyclic permutation of (0, 1, 2)
    const int i = choice, j = (i + 1) % 3, k = (i + 2) % 3;
    xyzw[i] = 1.0 - trace + 2.0 * R(i, i);
    xyzw[j] = R(j, i) + R(i, j);
    xyzw[k] = R(k, i) + R(i, k);
    xyzw[3] = R(k, j) - R(j, k);
  }
  return quat_canonical(Eigen::Quaterniond(xyzw / xyzw.norm()));
}

}  // namespace rigiddyn
