#include "rigiddyn/so3/align_vectors.hpp"

#include "numbers.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/matrix.hpp"
#include "rigiddyn/so3/quaternion.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace rigiddyn {

namespace {

using detail::nan;

// sqrt(sum_i w_i |a_i - R b_i|^2), with w_skip's term left out (skip = -1: none). Scaled by the
// largest residual entry and the largest weight, so that it overflows only when the result does.
double root_sum_squared_distance(const Eigen::Ref<const Vectors3>& a, const Eigen::Ref<const Vectors3>& b,
                                 const Eigen::Ref<const Eigen::VectorXd>& w, const Eigen::Matrix3d& R,
                                 Eigen::Index skip) {
  Vectors3 d = a - b * R.transpose();  // rows a_i - R b_i
  double d_max = 0.0, w_max = 0.0;
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    if (i == skip) continue;
    d_max = std::max(d_max, d.row(i).cwiseAbs().maxCoeff());
    w_max = std::max(w_max, w[i]);
  }
  if (d_max == 0.0 || w_max == 0.0) return 0.0;
  if (!std::isfinite(d_max)) return d_max;  // the residual itself overflowed
  double ssd = 0.0;  // sum (w_i / w_max) |d_i / d_max|^2
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    if (i != skip) ssd += (w[i] / w_max) * (d.row(i) / d_max).squaredNorm();
  }
  return d_max * std::sqrt(w_max) * std::sqrt(ssd);
}

// The unit vector of a primary vector (of any magnitude: stableNormalized never squares it into
// overflow or underflow); throws naming `name` when it is zero.
Eigen::Vector3d primary_direction(const Eigen::Vector3d& v, const char* name) {
  if (v.isZero(0.0)) throw_invalid(name, "a non-zero primary vector (the one with infinite weight, or the only one)", v.transpose().eval());
  return v.stableNormalized();
}

// Smallest rotation taking the unit vector b to the unit vector a: angle atan2(|b x a|, a.b) about
// b x a. Near antiparallel vectors b x a is mostly round-off and its direction arbitrary; any axis
// perpendicular to a then still takes b onto a, so the axis is b x a with its component along a
// removed (SciPy keeps b x a as computed and may miss a by ~1e-2 there). Exactly antiparallel
// (b x a = 0): a half turn about e_i x a, i the index of the smallest |a_i| (SciPy's axis).
Eigen::Quaterniond shortest_arc(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d cross = b.cross(a);
  const double angle = std::atan2(cross.norm(), a.dot(b));
  Eigen::Vector3d axis = cross - cross.dot(a) * a;
  if (axis.isZero(0.0)) {
    Eigen::Index i;
    a.cwiseAbs().minCoeff(&i);
    axis = Eigen::Vector3d::Unit(i).cross(a);
  }
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
}

// One pair aligned exactly (index k), the others by the best turn phi about a_k:
// phi = atan2(sum w (c x a).a_k, sum w (c.a - (c.a_k)(a.a_k))), c = R_pri b.
VectorAlignment align_with_primary(const Eigen::Ref<const Vectors3>& a, const Eigen::Ref<const Vectors3>& b,
                                   const Eigen::Ref<const Eigen::VectorXd>& w, Eigen::Index k) {
  const Eigen::Vector3d a_k = primary_direction(a.row(k).transpose(), "a");
  const Eigen::Vector3d b_k = primary_direction(b.row(k).transpose(), "b");
  const Eigen::Quaterniond q_primary = shortest_arc(a_k, b_k);
  // the sums scaled by 1 / (a_max b_max w_max) over the other pairs (atan2 does not change; no
  // overflow at any magnitude)
  double a_max = std::numeric_limits<double>::min(), b_max = a_max, w_max = a_max;
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    if (i == k) continue;
    a_max = std::max(a_max, a.row(i).cwiseAbs().maxCoeff());
    b_max = std::max(b_max, b.row(i).cwiseAbs().maxCoeff());
    w_max = std::max(w_max, w[i]);
  }
  double sin_sum = 0.0, cos_sum = 0.0;
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    if (i == k) continue;
    const Eigen::Vector3d c = q_primary * Eigen::Vector3d(b.row(i).transpose() / b_max);
    const Eigen::Vector3d a_i = a.row(i).transpose() / a_max;
    sin_sum += (w[i] / w_max) * c.cross(a_i).dot(a_k);
    cos_sum += (w[i] / w_max) * (c.dot(a_i) - c.dot(a_k) * a_i.dot(a_k));
  }
  const double phi = std::atan2(sin_sum, cos_sum);
  const Eigen::Quaterniond q = quat_canonical(Eigen::Quaterniond(Eigen::AngleAxisd(phi, a_k)) * q_primary);
  // a single pair keeps its finite weight in the rssd (SciPy); an infinite one is aligned exactly
  const Eigen::Index skip = std::isinf(w[k]) ? k : -1;
  const double rssd = root_sum_squared_distance(a, b, w, q.toRotationMatrix(), skip);
  return {q, rssd, Eigen::Matrix3d::Constant(nan), true};
}

// B = U S V^T, singular values in decreasing order
Eigen::JacobiSVD<Eigen::Matrix3d> full_svd(const Eigen::Matrix3d& B) {
  return Eigen::JacobiSVD<Eigen::Matrix3d>(B, Eigen::ComputeFullU | Eigen::ComputeFullV);
}

VectorAlignment align_by_svd(const Eigen::Ref<const Vectors3>& a, const Eigen::Ref<const Vectors3>& b,
                             const Eigen::Ref<const Eigen::VectorXd>& w) {
  // The optimal rotation does not change when a, b or w are scaled: B is formed from a / a_max,
  // b / b_max and w / w_max (no overflow at any magnitude) and B_true = c B with c = a_max b_max w_max.
  const double a_max = std::max(a.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
  const double b_max = std::max(b.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
  const double w_max = std::max(w.maxCoeff(), std::numeric_limits<double>::min());
  // attitude profile matrix B = sum_i w_i a_i b_i^T (Markley 1988), scaled
  const Eigen::Matrix3d B = (a / a_max).transpose() * (w / w_max).asDiagonal() * (b / b_max);
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd = full_svd(B);
  Eigen::Matrix3d U = svd.matrixU();
  const Eigen::Matrix3d& V = svd.matrixV();
  Eigen::Vector3d s = svd.singularValues();
  // proper rotation: flip the smallest singular direction when det(U V^T) = -1
  if ((U * V.transpose()).determinant() < 0.0) {
    U.col(2) *= -1.0;
    s[2] *= -1.0;
  }
  const Eigen::Matrix3d R = U * V.transpose();
  // Markley 1988: covariance of the error rotation vector, times the mean weight as SciPy:
  // mean(w) / zeta (kappa I + B B^T) is homogeneous of degree -1 in B, so divide by c at the end
  const double zeta = (s[0] + s[1]) * (s[1] + s[2]) * (s[2] + s[0]);
  const double kappa = s[0] * s[1] + s[1] * s[2] + s[2] * s[0];
  const Eigen::Matrix3d sensitivity =
      (w / w_max).mean() / zeta * (kappa * Eigen::Matrix3d::Identity() + B * B.transpose()) / a_max / b_max;
  const bool unique = s[1] + s[2] > 1e-16 * s[0];
  return {matrix_to_quat(R), root_sum_squared_distance(a, b, w, R, -1), sensitivity, unique};
}

}  // namespace

VectorAlignment align_vectors(const Eigen::Ref<const Vectors3>& a, const Eigen::Ref<const Vectors3>& b,
                              const Eigen::Ref<const Eigen::VectorXd>& weights) {
  const Eigen::Index n = a.rows();
  if (n == 0) throw_invalid("a", "at least one vector", "none");
  if (b.rows() != n) throw_invalid("b", std::to_string(n) + " vectors (as a)", b.rows());
  if (weights.size() != n) throw_invalid("weights", std::to_string(n) + " weights (one per vector)", weights.size());
  require_finite(a, "a");
  require_finite(b, "b");
  Eigen::Index infinite = -1;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!(weights[i] >= 0.0)) throw_invalid("weights", "weights >= 0 (+inf for at most one primary vector)", weights.transpose().eval());
    if (std::isinf(weights[i])) {
      if (infinite >= 0) throw_invalid("weights", "at most one infinite weight", weights.transpose().eval());
      infinite = i;
    }
  }
  if (n == 1) return align_with_primary(a, b, weights, 0);
  if (infinite >= 0) return align_with_primary(a, b, weights, infinite);
  return align_by_svd(a, b, weights);
}

}  // namespace rigiddyn
