#include "rigiddyn/so3/euler.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/elementary.hpp"
#include "rigiddyn/so3/matrix.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace rigiddyn {

namespace {

constexpr double pi = 3.14159265358979323846;

// |cos| between consecutive Davenport axes above which they are not orthogonal (SciPy's tolerance)
constexpr double orthogonal_tolerance = 1e-7;

const char* const valid_sequences =
    "one of the 12 axis sequences xyz, xzy, yxz, yzx, zxy, zyx, xyx, xzx, yxy, yzy, zxz, zyz, "
    "lowercase (extrinsic) or uppercase (intrinsic)";

// +1 if (i, j, k) is an even permutation of (0, 1, 2), -1 if odd.
int permutation_sign(int i, int j, int k) { return (i - j) * (j - k) * (k - i) / 2; }

// x in [-pi, pi] for x in [-2 pi, 2 pi] (each angle here is a sum, difference or double of atan2 values):
// std::remainder(x, 2 pi) to the bit, zero's sign included, without its division. x - 2 pi for x > pi is
// exact (Sterbenz: pi <= x <= 2 (2 pi)), and so is -(-x - 2 pi) for x < -pi (-0 at x = -2 pi, as remainder).
double wrap_angle(double x) {
  constexpr double two_pi = 2.0 * pi;
  return x > pi ? x - two_pi : x < -pi ? -(-x - two_pi) : x;
}

// The angles of a proper sequence about orthonormal n1, n2: q = q_n1(θ3) ⊗ q_n2(φ) ⊗ q_n1(θ1).
struct ProperAngles {
  double theta1, phi, theta3;  // phi in [0, pi]
  GimbalLock lock;
};

// From q's coordinates in the frame (n1, n2, n1 × n2): a = w, b = v . n1, c = v . n2,
// d = v . (n1 × n2), up to a common positive factor. Bernardes & Viollet (2022), Algorithm 2:
// φ = 2 atan2(|(c, d)|, |(a, b)|), (θ1 + θ3)/2 = atan2(b, a), (θ3 - θ1)/2 = atan2(d, c), only
// atan2, so accurate everywhere. At gimbal lock θ1 (zero_first) or θ3 is set to 0. |(c, d)| and |(a, b)| as
// square roots, without std::hypot's scaling (which took a third of the time): a, b, c, d are at most 2 (sums of
// two coordinates of a unit quaternion), so c² + d² cannot overflow, and where it underflows (|(c, d)| < 1e-154,
// then |(a, b)| >= 1/2) φ moves by less than 1e-153 rad; elsewhere each norm is within a relative 1.5 u of the
// exact one (u = 2^-53), which moves φ by at most 3 u rad.
ProperAngles proper_angles(double a, double b, double c, double d, bool zero_first) {
  const double phi = 2.0 * std::atan2(std::sqrt(c * c + d * d), std::sqrt(a * a + b * b));
  const double half_sum = std::atan2(b, a);
  const double half_diff = std::atan2(d, c);
  const double distance = std::min(phi, pi - phi);
  const GimbalLock lock = distance <= at_gimbal_lock     ? GimbalLock::at
                          : distance <= near_gimbal_lock ? GimbalLock::near
                                                         : GimbalLock::none;
  if (lock != GimbalLock::at) return {half_sum - half_diff, phi, half_sum + half_diff, lock};
  // only half_sum (φ = 0) or half_diff (φ = pi) is defined
  const bool lock_at_0 = phi < 0.5 * pi;
  if (zero_first) return {0.0, phi, lock_at_0 ? 2.0 * half_sum : 2.0 * half_diff, lock};
  return {lock_at_0 ? 2.0 * half_sum : -2.0 * half_diff, phi, 0.0, lock};
}

// Extrinsic angles (θ1, θ2, θ3) with q = q_k(θ3) ⊗ q_j(θ2) ⊗ q_i(θ1), axes = (i, j, k).
Eigen::Vector3d extrinsic_angles(const std::array<int, 3>& axes, const Eigen::Quaterniond& q, bool zero_first,
                                 GimbalLock* lock) {
  const int i = axes[0], j = axes[1];
  const bool proper = axes[0] == axes[2];
  const int k = proper ? 3 - i - j : axes[2];  // proper Euler: k is the axis not in the sequence
  const double epsilon = permutation_sign(i, j, k);
  const Eigen::Vector3d v = q.vec();
  // (a, b, c, d): q in the coordinates where the sequence is a proper Euler sequence (i, j, i);
  // a Tait-Bryan sequence is first rotated by -pi/2 about j (the factor 1/√2 cancels in atan2)
  const ProperAngles p = proper ? proper_angles(q.w(), v[i], v[j], epsilon * v[k], zero_first)
                                : proper_angles(q.w() - v[j], v[i] + epsilon * v[k], v[j] + q.w(),
                                                epsilon * v[k] - v[i], zero_first);
  if (lock) *lock = p.lock;
  if (proper) return {wrap_angle(p.theta1), p.phi, wrap_angle(p.theta3)};
  return {wrap_angle(p.theta1), p.phi - 0.5 * pi, wrap_angle(epsilon * p.theta3)};  // θ2 in [-pi/2, pi/2]
}

// The rotation by `angle` [rad] about the unit vector n: (sin(angle/2) n, cos(angle/2)).
Eigen::Quaterniond axis_quat(const Eigen::Vector3d& n, double angle) {
  const double half = 0.5 * angle;
  const Eigen::Vector3d v = std::sin(half) * n;
  return Eigen::Quaterniond(std::cos(half), v.x(), v.y(), v.z());
}

// Extrinsic Davenport angles, q = q_n3(θ3) ⊗ q_n2(θ2) ⊗ q_n1(θ1), for unit n1 ⊥ n2 ⊥ n3.
// With λ = atan2(n3 . (n1 × n2), n3 . n1), n3 = cos λ n1 + sin λ n1 × n2 = R_n2(-λ) n1, so
// q_n3(θ3) = q_n2(-λ) ⊗ q_n1(θ3) ⊗ q_n2(λ) and q_n2(λ) ⊗ q = q_n1(θ3) ⊗ q_n2(θ2 + λ) ⊗ q_n1(θ1):
// a proper sequence about (n1, n2) with φ = θ2 + λ. For λ < 0 the same holds about -n2 with
// θ2 negated, which keeps λ in [0, pi] and θ2 in [-λ, pi - λ] (as SciPy's as_davenport).
Eigen::Vector3d extrinsic_davenport(const Eigen::Vector3d& n1, Eigen::Vector3d n2, const Eigen::Vector3d& n3,
                                    const Eigen::Quaterniond& q, bool zero_first, GimbalLock* lock) {
  Eigen::Vector3d n12 = n1.cross(n2);
  double lambda = std::atan2(n3.dot(n12), n3.dot(n1));
  const double flip = lambda < 0.0 ? -1.0 : 1.0;
  n2 *= flip;
  n12 *= flip;
  lambda *= flip;
  const Eigen::Quaterniond t = axis_quat(n2, lambda) * q;
  const ProperAngles p = proper_angles(t.w(), t.vec().dot(n1), t.vec().dot(n2), t.vec().dot(n12), zero_first);
  if (lock) *lock = p.lock;
  return {wrap_angle(p.theta1), flip * (p.phi - lambda), wrap_angle(p.theta3)};
}

Eigen::Vector3d unit_axis(const Eigen::Matrix3d& axes, int row, const std::string& name) {
  const Eigen::Vector3d n = axes.row(row).transpose();
  if (!(n.allFinite() && n.stableNorm() > 0.0)) {
    throw_invalid(name + "[" + std::to_string(row) + "]", "a finite non-zero axis", n.transpose().eval());
  }
  return n.stableNormalized();
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

Eigen::Vector3d quat_to_euler(const EulerSequence& seq, const Eigen::Quaterniond& q, GimbalLock* lock) {
  if (!seq.intrinsic) return extrinsic_angles(seq.axes, q, false, lock);
  // R_A(θ1) R_B(θ2) R_C(θ3) is the extrinsic sequence (C, B, A) with angles (θ3, θ2, θ1)
  const Eigen::Vector3d reversed = extrinsic_angles({seq.axes[2], seq.axes[1], seq.axes[0]}, q, true, lock);
  return reversed.reverse();
}

Eigen::Vector3d matrix_to_euler(const EulerSequence& seq, const Eigen::Matrix3d& R, GimbalLock* lock) {
  return quat_to_euler(seq, matrix_to_quat(R), lock);
}

DavenportAxes::DavenportAxes(const Eigen::Matrix3d& axes, bool intrinsic_order, const std::string& name)
    : n1(unit_axis(axes, 0, name)), n2(unit_axis(axes, 1, name)), n3(unit_axis(axes, 2, name)), intrinsic(intrinsic_order) {
  if (!(std::abs(n1.dot(n2)) <= orthogonal_tolerance && std::abs(n2.dot(n3)) <= orthogonal_tolerance)) {
    throw_invalid(name, "3 axes (rows) with the second orthogonal to the first and to the third (|cos| <= 1e-7)",
                  axes);
  }
}

Eigen::Quaterniond davenport_to_quat(const DavenportAxes& axes, const Eigen::Vector3d& angles) {
  const Eigen::Quaterniond q1 = axis_quat(axes.n1, angles[0]);
  const Eigen::Quaterniond q2 = axis_quat(axes.n2, angles[1]);
  const Eigen::Quaterniond q3 = axis_quat(axes.n3, angles[2]);
  return axes.intrinsic ? q1 * q2 * q3 : q3 * q2 * q1;
}

Eigen::Vector3d quat_to_davenport(const DavenportAxes& axes, const Eigen::Quaterniond& q, GimbalLock* lock) {
  if (!axes.intrinsic) return extrinsic_davenport(axes.n1, axes.n2, axes.n3, q, false, lock);
  // R_n1(θ1) R_n2(θ2) R_n3(θ3) is the extrinsic sequence (n3, n2, n1) with angles (θ3, θ2, θ1)
  return extrinsic_davenport(axes.n3, axes.n2, axes.n1, q, true, lock).reverse();
}

}  // namespace rigiddyn
