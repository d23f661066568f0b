#include "rigiddyn/so3/euler.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/elementary.hpp"
#include "rigiddyn/so3/matrix.hpp"

#include <cctype>
#include <cmath>

namespace rigiddyn {

namespace {

constexpr double pi = 3.14159265358979323846;

// |θ2 - end of its range| [rad] below which a rotation is treated as gimbal lock (θ1 or θ3 set to
// 0). Setting an angle to 0 at a distance δ from the lock moves the rotation by O(δ), so this is
// kept at round-off level: angles always reproduce the rotation to ~1e-13. (SciPy snaps within
// 1e-7, at a cost of up to ~1e-7 in the rotation; between 1e-13 and 1e-7 from the lock our angles
// differ from SciPy's but reproduce the rotation, SciPy's only approximately.)
constexpr double gimbal_lock_tolerance = 1e-13;

const char* const valid_sequences =
    "one of the 12 axis sequences xyz, xzy, yxz, yzx, zxy, zyx, xyx, xzx, yxy, yzy, zxz, zyz, "
    "lowercase (extrinsic) or uppercase (intrinsic)";

// +1 if (i, j, k) is an even permutation of (0, 1, 2), -1 if odd.
int permutation_sign(int i, int j, int k) { return (i - j) * (j - k) * (k - i) / 2; }

// x in [-pi, pi]
double wrap_angle(double x) { return std::remainder(x, 2.0 * pi); }

// Extrinsic angles (θ1, θ2, θ3) with q = q_k(θ3) ⊗ q_j(θ2) ⊗ q_i(θ1), axes = (i, j, k).
// Bernardes & Viollet (2022), Algorithm 2. At gimbal lock θ1 (zero_first) or θ3 is set to 0.
Eigen::Vector3d extrinsic_angles(const std::array<int, 3>& axes, const Eigen::Quaterniond& q, bool zero_first) {
  const int i = axes[0], j = axes[1];
  const bool proper = axes[0] == axes[2];
  const int k = proper ? 3 - i - j : axes[2];  // proper Euler: k is the axis not in the sequence
  const double epsilon = permutation_sign(i, j, k);
  const Eigen::Vector3d v = q.vec();
  // (a, b, c, d): q in the coordinates where the sequence is a proper Euler sequence (i, j, i);
  // a Tait-Bryan sequence is first rotated by -pi/2 about j (the factor 1/√2 cancels in atan2)
  double a, b, c, d;
  if (proper) {
    a = q.w(); b = v[i]; c = v[j]; d = epsilon * v[k];
  } else {
    a = q.w() - v[j]; b = v[i] + epsilon * v[k]; c = v[j] + q.w(); d = epsilon * v[k] - v[i];
  }
  double theta2 = 2.0 * std::atan2(std::hypot(c, d), std::hypot(a, b));  // in [0, pi]
  const double half_sum = std::atan2(b, a);                                // (θ1 + θ3)/2
  const double half_diff = std::atan2(d, c);                               // (θ3 - θ1)/2
  double theta1, theta3;
  const bool lock_at_0 = theta2 <= gimbal_lock_tolerance;
  const bool lock_at_pi = theta2 >= pi - gimbal_lock_tolerance;
  if (lock_at_0 || lock_at_pi) {
    // only half_sum (at 0) or half_diff (at pi) is defined
    if (zero_first) {
      theta1 = 0.0;
      theta3 = lock_at_0 ? 2.0 * half_sum : 2.0 * half_diff;
    } else {
      theta3 = 0.0;
      theta1 = lock_at_0 ? 2.0 * half_sum : -2.0 * half_diff;
    }
  } else {
    theta1 = half_sum - half_diff;
    theta3 = half_sum + half_diff;
  }
  if (!proper) {
    theta2 -= 0.5 * pi;  // in [-pi/2, pi/2]
    theta3 *= epsilon;
  }
  return {wrap_angle(theta1), theta2, wrap_angle(theta3)};
}

}  // namespace

EulerSequence::EulerSequence(const std::string& seq, const std::string& name) : axes{}, intrinsic(false) {
  bool ok = seq.size() == 3;
  int uppercase = 0;
  for (std::size_t n = 0; ok && n < 3; ++n) {
    const char letter = seq[n];
    const char lower = static_cast<char>(std::tolower(static_cast<unsigned char>(letter)));
    ok = lower == 'x' || lower == 'y' || lower == 'z';
    axes[n] = lower - 'x';
    uppercase += (letter != lower);
  }
  ok = ok && (uppercase == 0 || uppercase == 3) && axes[0] != axes[1] && axes[1] != axes[2];
  if (!ok) throw_invalid(name, valid_sequences, "'" + seq + "'");
  intrinsic = uppercase == 3;
}

Eigen::Quaterniond euler_to_quat(const EulerSequence& seq, const Eigen::Vector3d& angles) {
  const Eigen::Quaterniond q1 = elementary_quat(seq.axes[0], angles[0]);
  const Eigen::Quaterniond q2 = elementary_quat(seq.axes[1], angles[1]);
  const Eigen::Quaterniond q3 = elementary_quat(seq.axes[2], angles[2]);
  // extrinsic: first rotation rightmost; intrinsic: first rotation leftmost
  return seq.intrinsic ? q1 * q2 * q3 : q3 * q2 * q1;
}

Eigen::Matrix3d euler_to_matrix(const EulerSequence& seq, const Eigen::Vector3d& angles) {
  return quat_to_matrix(euler_to_quat(seq, angles));
}

Eigen::Vector3d quat_to_euler(const EulerSequence& seq, const Eigen::Quaterniond& q) {
  if (!seq.intrinsic) return extrinsic_angles(seq.axes, q, false);
  // R_A(θ1) R_B(θ2) R_C(θ3) is the extrinsic sequence (C, B, A) with angles (θ3, θ2, θ1)
  const Eigen::Vector3d reversed = extrinsic_angles({seq.axes[2], seq.axes[1], seq.axes[0]}, q, true);
  return reversed.reverse();
}

Eigen::Vector3d matrix_to_euler(const EulerSequence& seq, const Eigen::Matrix3d& R) {
  return quat_to_euler(seq, matrix_to_quat(R));
}

}  // namespace rigiddyn
