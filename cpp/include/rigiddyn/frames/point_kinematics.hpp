// Velocity and acceleration of a point Q that moves in a moving frame F, seen from a frame A, term
// by term (Craig "Relative Acceleration"; Rigid-body notes (4.38), (4.39)), and the transport theorem.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigiddyn/frames/frame_kinematics.hpp"

namespace rigiddyn {

// v_AQ = v_AF + w_AF x r + v_rel   (Rigid-body notes (4.38)), r = p_FQ. All terms expressed in one frame
// (the frame A of the query unless rotated) [m/s].
struct PointVelocity {
  Eigen::Vector3d origin;      // v_AF: velocity of F's origin seen from A
  Eigen::Vector3d rotational;  // w_AF x r
  Eigen::Vector3d relative;    // v_rel: velocity of Q seen from F
  Eigen::Vector3d total() const { return origin + rotational + relative; }
  // The same terms expressed in E, given R_EA (A coordinates to E coordinates).
  PointVelocity rotated(const Eigen::Matrix3d& R_EA) const;
};

// a_AQ = a_AF + alpha_AF x r + w_AF x (w_AF x r) + a_rel + 2 w_AF x v_rel   (Rigid-body notes (4.39);
// Craig: origin, tangential, centripetal, relative, Coriolis). All terms expressed in one frame
// [m/s^2].
struct PointAcceleration {
  Eigen::Vector3d origin;       // a_AF: acceleration of F's origin seen from A
  Eigen::Vector3d tangential;   // alpha_AF x r
  Eigen::Vector3d centripetal;  // w_AF x (w_AF x r)
  Eigen::Vector3d relative;     // a_rel: acceleration of Q seen from F
  Eigen::Vector3d coriolis;     // 2 w_AF x v_rel
  Eigen::Vector3d total() const { return origin + tangential + centripetal + relative + coriolis; }
  // The same terms expressed in E, given R_EA (A coordinates to E coordinates).
  PointAcceleration rotated(const Eigen::Matrix3d& R_EA) const;
};

// Velocity of Q seen from A, expressed in A. K_AF: F relative to A; p_FQ_F: Q's position relative
// to F's origin [m], v_FQ_F: Q's velocity seen from F [m/s], both expressed in F.
PointVelocity point_velocity(const FrameKinematics& K_AF, const Eigen::Vector3d& p_FQ_F,
                             const Eigen::Vector3d& v_FQ_F);

// Acceleration of Q seen from A, expressed in A; a_FQ_F: Q's acceleration seen from F [m/s^2],
// expressed in F; the other arguments as point_velocity.
PointAcceleration point_acceleration(const FrameKinematics& K_AF, const Eigen::Vector3d& p_FQ_F,
                                     const Eigen::Vector3d& v_FQ_F, const Eigen::Vector3d& a_FQ_F);

// Transport theorem (Craig): the time derivative of a vector u seen from A, from its derivative
// seen from B: d^A u/dt = d^B u/dt + w_AB x u. All three vectors expressed in one frame.
inline Eigen::Vector3d transport_derivative(const Eigen::Vector3d& w_AB, const Eigen::Vector3d& u,
                                 const Eigen::Vector3d& du_dt_in_B) {
  return du_dt_in_B + w_AB.cross(u);
}

}  // namespace rigiddyn
