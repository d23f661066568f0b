// Principal moments and principal axes of a rotational inertia (Craig "Principal Axes"): the
// rotation R whose columns are the axes, so that I = R diag(moments) R^T.
#pragma once
#include <Eigen/Core>

namespace rigiddyn {

// Two principal moments are treated as coincident when they differ by less than this fraction of
// the largest moment; the axes spanning their plane are then chosen canonically (see below).
inline constexpr double coincident_moments_tolerance = 1e-9;

struct PrincipalAxes {
  Eigen::Vector3d moments;  // principal moments, ascending [kg m^2]
  Eigen::Matrix3d axes;     // column k = axis of moments(k), in the frame of I; right-handed (det +1)
};

// Principal moments (ascending) and axes of a symmetric 3x3 inertia by Eigen's
// SelfAdjointEigenSolver (iterative tridiagonal QR, accurate to round-off).
// The axes are deterministic and continuous away from coincident moments:
//  - distinct moments: each of axes 0 and 1 has its largest-magnitude component positive,
//    axis 2 = axis 0 x axis 1;
//  - two coincident moments: the distinct axis d as above; in the plane orthogonal to it, the first
//    axis is the projection of the frame basis vector least aligned with d, the second completes a
//    right-handed set;
//  - three coincident moments: the identity.
// Only the lower triangle of `inertia` is read.
PrincipalAxes principal_axes(const Eigen::Matrix3d& inertia);

}  // namespace rigiddyn
