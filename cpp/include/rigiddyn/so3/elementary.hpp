// Elementary rotations about the coordinate axes (active: they rotate vectors by +angle, right-hand
// rule), as matrices and as quaternions.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigiddyn {

// angle [rad]. rot_x = [[1, 0, 0], [0, c, -s], [0, s, c]] with c = cos(angle), s = sin(angle);
// rot_y = [[c, 0, s], [0, 1, 0], [-s, 0, c]]; rot_z = [[c, -s, 0], [s, c, 0], [0, 0, 1]].
Eigen::Matrix3d rot_x(double angle);
Eigen::Matrix3d rot_y(double angle);
Eigen::Matrix3d rot_z(double angle);

// The rotation by `angle` [rad] about coordinate axis `axis` (0 = x, 1 = y, 2 = z) as a quaternion
// (sin(angle/2) e_axis, cos(angle/2)).
Eigen::Quaterniond elementary_quat(int axis, double angle);

}  // namespace rigiddyn
