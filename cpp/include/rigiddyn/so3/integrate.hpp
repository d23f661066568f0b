// The attitude kinematics q' = ½ q ⊗ (w_B, 0) = ½ (w_W, 0) ⊗ q of a unit quaternion q = q_WB, w the
// angular velocity of B in W expressed in B or in W (Solà, "Quaternion kinematics for the
// error-state Kalman filter": local and global angular velocity): the quaternion rate of an
// angular velocity and back, and the exact attitude update for a constant one over a step.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigiddyn {

// The frame in which an angular velocity is expressed: `body` (w_B, in the moving frame B) or
// `world` (w_W, in the fixed frame W).
enum class Frame { body, world };

// q_WB(t + dt) for q = q_WB(t) and an angular velocity w [rad/s] constant over dt [s]:
//   Frame::body:  q ⊗ exp(w dt / 2)    (w = w_B, expressed in B)
//   Frame::world: exp(w dt / 2) ⊗ q    (w = w_W, expressed in W)
// where exp of a pure vector u is (sin|u| u/|u|, cos|u|) = rotvec_to_quat(2u). This is the exact
// solution of q' = q ⊗ (w_B/2, 0) = (w_W/2, 0) ⊗ q. q must be a unit quaternion; the result is
// normalised. Throws std::invalid_argument for non-finite w or dt.
Eigen::Quaterniond quat_integrate(const Eigen::Quaterniond& q, const Eigen::Vector3d& w, double dt, Frame frame);

// dq/dt [1/s] of q = q_WB (unit) turning with angular velocity w [rad/s]:
//   Frame::body:  ½ q ⊗ (w_B, 0)    Frame::world: ½ (w_W, 0) ⊗ q
// (a quaternion orthogonal to q, not of unit norm: |dq/dt| = |w|/2). Throws std::invalid_argument
// for a non-finite w.
Eigen::Quaterniond quat_rate(const Eigen::Quaterniond& q, const Eigen::Vector3d& w, Frame frame);

// The angular velocity [rad/s] of q = q_WB (unit) changing at dq_dt [1/s], the inverse of quat_rate:
//   Frame::body:  w_B = 2 vec(q* ⊗ dq/dt)    Frame::world: w_W = 2 vec(dq/dt ⊗ q*)
// The scalar part q . dq/dt (zero for the rate of a unit quaternion, non-zero for a rate that would
// change |q|) is dropped: w is the least-squares fit of dq/dt by rotations. Throws
// std::invalid_argument for a non-finite dq_dt.
Eigen::Vector3d angular_velocity_from_quat_rate(const Eigen::Quaterniond& q, const Eigen::Quaterniond& dq_dt, Frame frame);

}  // namespace rigiddyn
