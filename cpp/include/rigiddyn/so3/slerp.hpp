// Spherical linear interpolation (slerp) of unit quaternions: between two rotations, and along a
// sequence of key rotations at key times (SciPy's scipy.spatial.transform.Slerp).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

#include "rigiddyn/so3/exp_log.hpp"

namespace rigiddyn {

// The rotation a fraction t of the way from q0 to q1 along the shortest great arc, at constant
// angular rate: q(t) = q0 ⊗ exp(t log(q0^-1 ⊗ q1)), with the log taken at angle in [0, pi]
// (K. Shoemake, "Animating rotation with quaternion curves", SIGGRAPH 1985; SciPy's Slerp
// computes the same product). q(0) = q0, q(1) = ±q1; any real t extrapolates along the same arc.
// q0, q1 unit quaternions.
inline Eigen::Quaterniond slerp(const Eigen::Quaterniond& q0, const Eigen::Quaterniond& q1, double t) {
  return q0 * rotvec_to_quat(t * quat_to_rotvec(q0.conjugate() * q1));
}

// Slerp along key rotations q[k] at strictly increasing key times times[k] (k = 0 .. n-1, n >= 2):
// at t in [times[k], times[k+1]], slerp(q[k], q[k+1], (t - times[k]) / (times[k+1] - times[k])).
// At an interior key time the segment ending there is used, as SciPy's Slerp does.
class KeyedSlerp {
 public:
  // Throws std::invalid_argument naming "times" (fewer than 2, not finite, not strictly
  // increasing) or "q" (count differs from the times'). q must be unit quaternions.
  KeyedSlerp(std::vector<double> times, std::vector<Eigen::Quaterniond> q);
  // The interpolated rotation at time t; throws std::invalid_argument naming `name` unless
  // times.front() <= t <= times.back().
  Eigen::Quaterniond operator()(double t, const char* name = "t") const;

 private:
  std::vector<double> times_;
  std::vector<Eigen::Quaterniond> q_;
  std::vector<Eigen::Vector3d> rotvec_;  // log(q[k]^-1 ⊗ q[k+1]) [rad], angle in [0, pi]
};

}  // namespace rigiddyn
