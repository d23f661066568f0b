// The skew-symmetric ("hat") matrix of a 3-vector and its inverse ("vee"):
// hat(v) x = v × x for every x (the cross-product matrix, Craig / any mechanics text).
#pragma once
#include <Eigen/Core>

namespace rigiddyn {

// hat(v) = [[0, -v_z, v_y], [v_z, 0, -v_x], [-v_y, v_x, 0]], so that hat(v) x = v × x.
// v: any 3-vector (units kept: hat of rad/s is a rad/s matrix).
Eigen::Matrix3d hat(const Eigen::Vector3d& v);

// vee(S) = (S(2,1), S(0,2), S(1,0)) of the skew-symmetric part (S - S^T)/2, so vee(hat(v)) = v.
// A symmetric part of S, if any, is ignored (vee is the projection onto so(3) followed by vee).
Eigen::Vector3d vee(const Eigen::Matrix3d& S);

}  // namespace rigiddyn
