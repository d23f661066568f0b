// Euler angles in all 12 axis sequences (6 Tait-Bryan such as "xyz", 6 proper Euler such as
// "zxz"), extrinsic or intrinsic, with SciPy's spelling and angle ranges:
//   lowercase "abc" = extrinsic (fixed axes): R = R_c(θ3) R_b(θ2) R_a(θ1), θ1 applied first;
//   uppercase "ABC" = intrinsic (moving axes): R = R_A(θ1) R_B(θ2) R_C(θ3).
// The inverse maps return θ1, θ3 in [-pi, pi] and θ2 in [0, pi] (proper) or [-pi/2, pi/2]
// (Tait-Bryan). At gimbal lock (θ2 at an end of its range) only θ1 ± θ3 is defined: the third angle
// (θ3, in the order given) is set to 0, as SciPy does.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <string>

namespace rigiddyn {

// A parsed axis sequence. Constructed from its 3-letter name ("xyz", "ZXZ", ...); throws
// std::invalid_argument naming `name` for anything else (mixed case, repeated consecutive axes,
// letters other than x, y, z, wrong length).
struct EulerSequence {
  EulerSequence(const std::string& seq, const std::string& name = "seq");
  EulerSequence(const char* seq) : EulerSequence(std::string(seq)) {}

  std::array<int, 3> axes;  // 0 = x, 1 = y, 2 = z, in the order of the name
  bool intrinsic;           // uppercase name
};

// The rotation of the Euler angles `angles` = (θ1, θ2, θ3) [rad] in sequence `seq`.
Eigen::Quaterniond euler_to_quat(const EulerSequence& seq, const Eigen::Vector3d& angles);
Eigen::Matrix3d euler_to_matrix(const EulerSequence& seq, const Eigen::Vector3d& angles);

// The Euler angles (θ1, θ2, θ3) [rad] of a unit quaternion / rotation matrix in sequence `seq`
// (ranges and gimbal lock: see the top of this file). Method: Bernardes & Viollet (2022), "Quaternion
// to Euler angles conversion: a direct, general and computationally efficient method", PLoS ONE
// 17(11): e0276302, which uses only atan2 and so is accurate everywhere.
Eigen::Vector3d quat_to_euler(const EulerSequence& seq, const Eigen::Quaterniond& q);
Eigen::Vector3d matrix_to_euler(const EulerSequence& seq, const Eigen::Matrix3d& R);

}  // namespace rigiddyn
