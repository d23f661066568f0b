// Written-out quaternion kernels on raw (x, y, z, w) storage, for the integrator models, which keep
// attitudes inside flat coordinate vectors and read and write them element by element (scalar stores:
// Eigen's packet copies would reload values just stored one by one, a store-forwarding stall; see
// models/euler_equations.hpp).
#pragma once
#include "rigiddyn/always_inline.hpp"
#include "rigiddyn/so3/exp_log.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <Eigen/Geometry>

namespace rigiddyn {

// out = q ⊗ exp(θ) [θ in rad, a body-frame rotation vector], q and out stored (x, y, z, w): the Hamilton
// product written out (q and out may not overlap).
RIGIDDYN_ALWAYS_INLINE void times_exp(const double* q, const Eigen::Vector3d& theta, double* out) {
  const double x = q[0], y = q[1], z = q[2], s = q[3];
  const Eigen::Quaterniond e = rotvec_to_quat(theta);
  out[0] = s * e.x() + x * e.w() + y * e.z() - z * e.y();
  out[1] = s * e.y() - x * e.z() + y * e.w() + z * e.x();
  out[2] = s * e.z() + x * e.y() - y * e.x() + z * e.w();
  out[3] = s * e.w() - x * e.x() - y * e.y() - z * e.z();
}

// dq = q̇ = ½ q ⊗ (ω_B, 0) [1/s] for the body-frame angular velocity w_B [rad/s] ("Rigid body kinematics
// and dynamics" notes; Solà (2017), the local form), q and dq stored (x, y, z, w).
RIGIDDYN_ALWAYS_INLINE void quat_rate_body(const double* q, const Eigen::Vector3d& w_B, double* dq) {
  const double x = q[0], y = q[1], z = q[2], s = q[3];
  dq[0] = 0.5 * (s * w_B.x() + y * w_B.z() - z * w_B.y());
  dq[1] = 0.5 * (s * w_B.y() + z * w_B.x() - x * w_B.z());
  dq[2] = 0.5 * (s * w_B.z() + x * w_B.y() - y * w_B.x());
  dq[3] = -0.5 * (x * w_B.x() + y * w_B.y() + z * w_B.z());
}

// q ← q / |q| in place, q stored (x, y, z, w): the projection of the methods that leave the unit sphere
// (RK4, explicit Euler, RKMK4) after each step.
RIGIDDYN_ALWAYS_INLINE void normalise_quaternion(double* q) {
  const double inverse_norm = 1.0 / std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (int i = 0; i < 4; ++i) q[i] *= inverse_norm;
}

// q / |q| of q stored (x, y, z, w), formed in registers (a quaternion written coefficient by coefficient and then
// normalised through Eigen reloads them as packets: a store-forwarding stall per attitude); |q|² summed as Eigen's
// norm of the coefficients sums it on SSE2, (x² + z²) + (y² + w²), so the result is bitwise Eigen's.
RIGIDDYN_ALWAYS_INLINE Eigen::Quaterniond unit_quaternion(const double* q) {
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  const double inverse_norm = 1.0 / std::sqrt((x * x + z * z) + (y * y + w * w));
  return Eigen::Quaterniond(w * inverse_norm, x * inverse_norm, y * inverse_norm, z * inverse_norm);
}

}  // namespace rigiddyn
