#include "rigiddyn/inertia/principal_axes.hpp"

#include "canonical_sign.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace rigiddyn {

namespace {

using detail::canonical_sign;

// A unit vector orthogonal to the unit vector d: the frame basis vector least aligned with d,
// projected onto the plane orthogonal to d.
Eigen::Vector3d canonical_orthogonal(const Eigen::Vector3d& d) {
  Eigen::Index k;
  d.cwiseAbs().minCoeff(&k);
  const Eigen::Vector3d e = Eigen::Vector3d::Unit(k);
  return (e - d.dot(e) * d).normalized();
}

// The solver's axes with canonical signs: right-handed, V diag(moments) Vᵀ = I to round-off.
PrincipalAxes solver_axes(const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& eig) {
  Eigen::Matrix3d axes;
  axes.col(0) = canonical_sign(eig.eigenvectors().col(0));
  axes.col(1) = canonical_sign(eig.eigenvectors().col(1));
  axes.col(2) = axes.col(0).cross(axes.col(1));
  return PrincipalAxes{eig.eigenvalues(), axes};
}

}  // namespace

PrincipalAxes principal_decomposition(const Eigen::Matrix3d& inertia) {
  return solver_axes(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia));
}

PrincipalAxes principal_axes(const Eigen::Matrix3d& inertia) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(inertia);
  const Eigen::Vector3d moments = eig.eigenvalues();  // ascending
  const Eigen::Matrix3d& V = eig.eigenvectors();
  const double tol = coincident_moments_tolerance * moments.cwiseAbs().maxCoeff();
  const bool low_pair = moments(1) - moments(0) <= tol;   // I0 = I1
  const bool high_pair = moments(2) - moments(1) <= tol;  // I1 = I2
  if (!low_pair && !high_pair) return solver_axes(eig);
  Eigen::Matrix3d axes;
  if (low_pair && high_pair) {
    axes.setIdentity();
  } else if (low_pair) {
    const Eigen::Vector3d d = canonical_sign(V.col(2));
    axes.col(0) = canonical_orthogonal(d);
    axes.col(1) = d.cross(axes.col(0));
    axes.col(2) = d;
  } else {
    const Eigen::Vector3d d = canonical_sign(V.col(0));
    axes.col(0) = d;
    axes.col(1) = canonical_orthogonal(d);
    axes.col(2) = d.cross(axes.col(1));
  }
  return PrincipalAxes{moments, axes};
}

}  // namespace rigiddyn
