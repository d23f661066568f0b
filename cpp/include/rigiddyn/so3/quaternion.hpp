// Unit quaternions (docs/conventions.md): Hamilton product, active rotation, q_WB maps B
// coordinates to W coordinates, R(q1 ⊗ q2) = R(q1) R(q2). Eigen::Quaterniond stores (x, y, z, w).
//
// The functions below other than checked_unit_quaternion and quat_normalize assume unit input:
// validate user data once with checked_unit_quaternion (the Python bindings do so for every item).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <string>

namespace rigiddyn {

// Tolerance of checked_unit_quaternion: a quaternion q is accepted as a unit quaternion when
// | |q| - 1 | <= unit_quaternion_tolerance (float32 round-off is ~1e-7; anything farther from 1
// means the caller did not mean a rotation, e.g. passed unnormalised data). Error messages quote
// the value 1e-6: keep them in step.
inline constexpr double unit_quaternion_tolerance = 1e-6;

// Throws the std::invalid_argument of checked_unit_quaternion for q (out of line: the cold path).
[[noreturn]] void throw_not_unit_quaternion(const Eigen::Quaterniond& q, const std::string& name);

// q normalised to unit norm. Throws std::invalid_argument naming `name` when q has a non-finite
// coefficient or | |q| - 1 | > unit_quaternion_tolerance (this includes q = 0).
// Inline: it runs once per item in the array loops.
inline Eigen::Quaterniond checked_unit_quaternion(const Eigen::Quaterniond& q, const std::string& name) {
  const double norm = q.norm();
  // false for NaN and inf as well
  if (!(std::abs(norm - 1.0) <= unit_quaternion_tolerance)) throw_not_unit_quaternion(q, name);
  return Eigen::Quaterniond(q.coeffs() * (1.0 / norm));
}

// checked_unit_quaternion for a body's attitude in a state: q kept bit for bit where it is unit to round-off
// (| |q| - 1 | <= 4 eps), normalised otherwise. Every q / |q| formed in double is within that bound (its coefficients
// within 4.5 u of the exact quotient's, u = eps / 2, and its norm formed within 2.5 u more: 7 u < 4 eps), so that
// normalising a state is idempotent: a run started from a state that a run recorded or a step returned continues that
// run bit for bit.
inline Eigen::Quaterniond checked_attitude(const Eigen::Quaterniond& q, const std::string& name) {
  const Eigen::Quaterniond unit = checked_unit_quaternion(q, name);
  return std::abs(q.norm() - 1.0) <= 4 * std::numeric_limits<double>::epsilon() ? q : unit;
}

// q / |q| for any finite non-zero q; throws std::invalid_argument naming `name` otherwise.
Eigen::Quaterniond quat_normalize(const Eigen::Quaterniond& q, const std::string& name = "q");

// The canonical representative of q's rotation (q and -q are the same rotation): the one with
// w > 0, or where w = 0 the first non-zero of x, y, z positive. SciPy's as_quat(canonical=True)
// ties exactly (-0.0 counts as 0), so that half turns map to one representative too.
inline Eigen::Quaterniond quat_canonical(const Eigen::Quaterniond& q) {
  const bool flip = q.w() < 0.0 ||
                    (q.w() == 0.0 && (q.x() < 0.0 || (q.x() == 0.0 && (q.y() < 0.0 || (q.y() == 0.0 && q.z() < 0.0)))));
  return flip ? Eigen::Quaterniond(-q.coeffs()) : q;
}

// Hamilton product q1 ⊗ q2: the rotation q2 followed by q1, R(q1 ⊗ q2) = R(q1) R(q2).
inline Eigen::Quaterniond quat_multiply(const Eigen::Quaterniond& q1, const Eigen::Quaterniond& q2) { return q1 * q2; }

// Inverse of a unit quaternion: its conjugate (-x, -y, -z, w).
inline Eigen::Quaterniond quat_inverse(const Eigen::Quaterniond& q) { return q.conjugate(); }

// R(q) v: v rotated actively by the unit quaternion q (v_W = R_WB v_B for q = q_WB).
// Eigen evaluates v + 2 w (u × v) + 2 u × (u × v), u = (x, y, z), without forming R(q).
inline Eigen::Vector3d quat_rotate(const Eigen::Quaterniond& q, const Eigen::Vector3d& v) { return q * v; }

}  // namespace rigiddyn
