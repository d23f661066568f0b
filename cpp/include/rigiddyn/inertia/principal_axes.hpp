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
// Only the lower triangle of `inertia` is read. The canonical axes of coincident moments reproduce
// `inertia` only to within the moments' difference (up to coincident_moments_tolerance relative): a
// computation that needs `inertia` back from its moments and axes uses principal_decomposition.
PrincipalAxes principal_axes(const Eigen::Matrix3d& inertia);

// The same decomposition without the canonical choice: moments ascending and axes that reproduce the
// matrix, axes diag(moments) axesᵀ = inertia to a few ε |inertia| (the solver is backward stable), for
// any spacing of the moments, equal and nearly equal ones included. Axes 0 and 1 are the solver's with
// the sign rule above (largest-magnitude component positive), axis 2 = axis 0 × axis 1; where the
// moments are distinct by more than coincident_moments_tolerance this is principal_axes, bit for bit.
// What the closed-form motion of a free body (exact/free_body.hpp) and the splittings that turn about
// the principal axes (integrators/splitting_parts.hpp) are built on: axes within a plane of two moments
// that differ by δ may turn by up to ~ε |inertia| / δ between nearby inputs, but the body they describe
// is `inertia` to round-off. Only the lower triangle of `inertia` is read.
PrincipalAxes principal_decomposition(const Eigen::Matrix3d& inertia);

}  // namespace rigiddyn
