// Wahba's problem: the rotation that best maps a set of vectors b onto a set of vectors a.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigiddyn {

// N vectors as rows, (N, 3) row-major (the numpy layout).
using Vectors3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

// The solution of align_vectors.
struct VectorAlignment {
  Eigen::Quaterniond q;         // the optimal rotation, canonical (w >= 0): a_i ≈ R(q) b_i
  double rssd;                  // sqrt(sum_i w_i |a_i - R(q) b_i|^2), infinite weights left out
  Eigen::Matrix3d sensitivity;  // covariance of the rotation-vector error (SciPy's); NaN for the
                                // special cases (one pair, an infinite weight)
  bool unique;                  // false when the optimum is not unique or poorly defined
};

// The rotation R minimising L(R) = 1/2 sum_i w_i |a_i - R b_i|^2 (Wahba's problem; SciPy's
// Rotation.align_vectors(a, b, weights) with the same conventions and special cases):
// - general case (N >= 2, finite weights): R = U diag(1, 1, det(U V^T)) V^T from the SVD
//   B = sum_i w_i a_i b_i^T = U S V^T (F. L. Markley, "Attitude determination using vector
//   observations and the singular value decomposition", J. Astronautical Sciences 36(3), 1988;
//   the det correction of Kabsch). Sensitivity as SciPy: mean(w) / zeta (kappa I + B B^T) with
//   zeta = (s1 + s2)(s2 + s3)(s3 + s1), kappa = s1 s2 + s2 s3 + s3 s1 (Markley 1988). `unique` is
//   false when s2 + s3 <= 1e-16 s1 (all pairs parallel, or B = 0).
// - one pair (N = 1), or one infinite weight (a primary pair): the primary pair is aligned
//   exactly by the smallest rotation taking b_k to the direction of a_k (about b_k x a_k, made
//   exactly perpendicular to a_k so that nearly antiparallel pairs are aligned to round-off too;
//   at exactly antiparallel ones about e_i x a_k, i the smallest |a_k| component, as SciPy), then the
//   rotation about a_k minimising the loss of the other pairs is added (closed form, an atan2).
// Vector lengths act as weights (normalise them for equal weighting). a, b: (N, 3), N >= 1;
// weights (N,) >= 0, at most one +inf. Throws std::invalid_argument naming "weights" (negative,
// NaN, more than one infinite, wrong count) or "a"/"b" (different counts, N = 0, a zero primary
// vector).
VectorAlignment align_vectors(const Eigen::Ref<const Vectors3>& a, const Eigen::Ref<const Vectors3>& b,
                              const Eigen::Ref<const Eigen::VectorXd>& weights);

}  // namespace rigiddyn
