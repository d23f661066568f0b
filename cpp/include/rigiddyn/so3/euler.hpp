// Euler angles in all 12 axis sequences (6 Tait-Bryan such as "xyz", 6 proper Euler such as
// "zxz"), extrinsic or intrinsic, with SciPy's spelling and angle ranges:
//   lowercase "abc" = extrinsic (fixed axes): R = R_c(θ3) R_b(θ2) R_a(θ1), θ1 applied first;
//   uppercase "ABC" = intrinsic (moving axes): R = R_A(θ1) R_B(θ2) R_C(θ3).
// The inverse maps return θ1, θ3 in [-pi, pi] and θ2 in [0, pi] (proper) or [-pi/2, pi/2]
// (Tait-Bryan). At gimbal lock (θ2 at an end of its range) only θ1 ± θ3 is defined: the third angle
// (θ3, in the order given) is set to 0, as SciPy does.
//
// Davenport angles generalise them to any three unit axes n1, n2, n3 with n2 orthogonal to n1 and
// to n3 (SciPy's Rotation.from_davenport / as_davenport): extrinsic R = R_n3(θ3) R_n2(θ2) R_n1(θ1),
// intrinsic R = R_n1(θ1) R_n2(θ2) R_n3(θ3). Euler angles are the case of coordinate axes.
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

// How near the middle angle is to gimbal lock, measured by φ in [0, pi], the middle angle of the
// equivalent proper sequence (n1, n2, n1) (φ = θ2 for proper Euler angles, θ2 + pi/2 for
// Tait-Bryan ones, θ2 + λ for Davenport angles with n3 = R_n2(-λ) n1): the lock is φ = 0 or pi.
enum class GimbalLock {
  none,  // min(φ, pi - φ) > near_gimbal_lock: the angles are well defined
  near,  // within near_gimbal_lock (SciPy's threshold, where SciPy sets θ3 = 0 and warns): the angles
         // returned are the exact ones, but θ1 and θ3 amplify round-off by 1/sin φ >= 1e7
  at     // within at_gimbal_lock (round-off): only θ1 ± θ3 is defined, θ3 is set to 0
};
// [rad] SciPy's test |φ| <= 1e-7 or |φ - pi| <= 1e-7 (scipy.spatial.transform.Rotation.as_euler).
inline constexpr double near_gimbal_lock = 1e-7;
// [rad] Setting θ3 to 0 at a distance δ from the lock moves the rotation by up to 2δ, so the core
// does so only at round-off level: its angles reproduce the rotation to ~1e-13 everywhere, where
// SciPy's err by up to 2e-7 rad between 1e-13 and 1e-7 from the lock.
inline constexpr double at_gimbal_lock = 1e-13;

// The rotation of the Euler angles `angles` = (θ1, θ2, θ3) [rad] in sequence `seq`.
Eigen::Quaterniond euler_to_quat(const EulerSequence& seq, const Eigen::Vector3d& angles);
Eigen::Matrix3d euler_to_matrix(const EulerSequence& seq, const Eigen::Vector3d& angles);

// The Euler angles (θ1, θ2, θ3) [rad] of a unit quaternion / rotation matrix in sequence `seq`
// (ranges and gimbal lock: see the top of this file). Method: Bernardes & Viollet (2022), "Quaternion
// to Euler angles conversion: a direct, general and computationally efficient method", PLoS ONE
// 17(11): e0276302, which uses only atan2 and so is accurate everywhere.
// When `lock` is given, it receives how near θ2 is to gimbal lock.
Eigen::Vector3d quat_to_euler(const EulerSequence& seq, const Eigen::Quaterniond& q, GimbalLock* lock = nullptr);
Eigen::Vector3d matrix_to_euler(const EulerSequence& seq, const Eigen::Matrix3d& R, GimbalLock* lock = nullptr);

// Three axes for Davenport angles: constructed from the rows of `axes` (any non-zero length, they
// are normalised) with |n1 . n2| <= 1e-7 and |n2 . n3| <= 1e-7 after normalisation (SciPy's
// tolerance); throws std::invalid_argument naming `name` otherwise.
struct DavenportAxes {
  DavenportAxes(const Eigen::Matrix3d& axes, bool intrinsic, const std::string& name = "axes");

  Eigen::Vector3d n1, n2, n3;  // unit axes, in the order given
  bool intrinsic;
};

// The rotation of the Davenport angles (θ1, θ2, θ3) [rad] about `axes` (see the top of this file).
Eigen::Quaterniond davenport_to_quat(const DavenportAxes& axes, const Eigen::Vector3d& angles);

// The Davenport angles (θ1, θ2, θ3) [rad] of a unit quaternion: θ1, θ3 in [-pi, pi], and θ2 in
// [-λ, pi - λ] for λ >= 0, in [-pi - λ, -λ] for λ < 0, where λ = atan2(m3 . (m1 × n2), m3 . m1) in
// [-pi, pi] (m3 = R_n2(-λ) m1) with (m1, m3) = (n1, n3), or (n3, n1) when intrinsic; as SciPy
// (λ = 0: proper Euler, θ2 in [0, pi]; λ = ±pi/2: Tait-Bryan, θ2 in [-pi/2, pi/2]; for n3 = ±n1 the
// sign of λ, so the range, is that of the round-off in n3 . (n1 × n2)).
// Gimbal lock as quat_to_euler. Method: Bernardes & Viollet (2022) for arbitrary axes: since
// n3 = R_n2(-λ) n1, q_n2(λ) ⊗ q is the proper sequence (n1, n2, n1) with middle angle θ2 + λ.
Eigen::Vector3d quat_to_davenport(const DavenportAxes& axes, const Eigen::Quaterniond& q, GimbalLock* lock = nullptr);

}  // namespace rigiddyn
