// The rotation matrix nearest to a 3x3 matrix, and the acceptance of nearly orthonormal matrices
// (entries rounded to a few digits, as typed by users or read from files) as rotations.
#pragma once
#include <Eigen/Core>

#include <string_view>

namespace rigiddyn {

// Largest distance max_i |sigma_i - 1| of the singular values of M from 1 (= |M - R|_2 for the
// nearest rotation R when det M > 0) for which projected_rotation_matrix accepts M. A matrix of a
// rotation rounded to 2 decimals errs by <= 0.005 per entry, so by <= 3 * 0.005 = 0.015 in the
// 2-norm; 0.05 also accepts most 1-decimal roundings and refuses scaled matrices (0.5 R, 2 R, R in
// mm). Error messages quote the value 0.05: keep them in step.
inline constexpr double near_rotation_tolerance = 0.05;

// The rotation matrix R minimising the Frobenius norm |M - R|_F over SO(3), for any finite M: with
// the singular value decomposition M = U S V^T, R = U diag(1, 1, det(U V^T)) V^T (the orthogonal
// Procrustes solution, with the sign of the smallest singular value flipped when det M < 0 as in
// the Kabsch algorithm: W. Kabsch, Acta Cryst. A32, 1976; S. Umeyama, IEEE PAMI 13(4), 1991).
// For det M > 0 it is the orthogonal polar factor of M (N. J. Higham, "Computing the polar
// decomposition - with applications", SIAM J. Sci. Stat. Comput. 7(4), 1986). Unique when M has
// rank >= 2 and, if det M < 0, its two smallest singular values differ. Throws
// std::invalid_argument naming "M" on a non-finite entry.
Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& M);

// True when M M^T equals I to SciPy's test in Rotation.from_matrix (numpy.isclose, entrywise
// |(M M^T)_ij - I_ij| <= 1e-12 + 1e-5 I_ij): SciPy then converts M as it is, without projecting.
// False for non-finite entries.
bool orthonormal_as_scipy(const Eigen::Matrix3d& M);

// The rotation matrix that M stands for, as SciPy's Rotation.from_matrix reads it: M itself when
// orthonormal_as_scipy(M), else nearest_rotation(M). Throws std::invalid_argument naming `name`
// (message "<name>: expected a rotation matrix ...") on a non-finite entry, det M <= 0 (a
// reflection or a singular matrix: SciPy refuses these too) or a matrix far from every rotation
// (max |sigma_i - 1| > near_rotation_tolerance; SciPy would project any matrix with det > 0).
Eigen::Matrix3d projected_rotation_matrix(const Eigen::Matrix3d& M, std::string_view name);

}  // namespace rigiddyn
