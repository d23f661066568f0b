// The kinematic state, at one instant, of a frame F relative to a reference frame P: the placement
// of F in P and its first and second time derivatives as seen from P (Craig "Kinematics of a
// Rigid Body"; Rigid-body notes Sect. 4.11.1).
#pragma once
#include <Eigen/Core>

namespace rigiddyn {

// Frame F relative to frame P (P = the parent in a FrameMotion, or the `relative_to` frame of a
// FrameTree query). Every vector is expressed in P; units m, s, rad.
struct FrameKinematics {
  // R_PF: orientation of F in P (maps F coordinates to P coordinates), orthonormal, det +1.
  Eigen::Matrix3d R_PF = Eigen::Matrix3d::Identity();
  // w_PF_P: angular velocity of F relative to P [rad/s], expressed in P.
  Eigen::Vector3d w_PF_P = Eigen::Vector3d::Zero();
  // alpha_PF_P: angular acceleration of F relative to P [rad/s^2], the time derivative of w_PF
  // (the same seen from P or from F, since w_PF x w_PF = 0), expressed in P.
  Eigen::Vector3d alpha_PF_P = Eigen::Vector3d::Zero();
  // p_PF_P: position of F's origin relative to P's origin [m], expressed in P.
  Eigen::Vector3d p_PF_P = Eigen::Vector3d::Zero();
  // v_PF_P: velocity of F's origin as seen from P (d/dt in P of p_PF) [m/s], expressed in P.
  Eigen::Vector3d v_PF_P = Eigen::Vector3d::Zero();
  // a_PF_P: acceleration of F's origin as seen from P (d^2/dt^2 in P of p_PF) [m/s^2], expressed in P.
  Eigen::Vector3d a_PF_P = Eigen::Vector3d::Zero();
};

// Frame F relative to A from P relative to A (K_AP) and F relative to P (K_PF). Angular velocity by
// the addition theorem (Craig), angular acceleration with its cross term
// alpha_AF = alpha_AP + alpha_PF + w_AP x w_PF (Craig: no addition theorem for angular
// accelerations), origin motion by the point formulas (Rigid-body notes (4.38), (4.39)). Result expressed in A.
FrameKinematics compose_kinematics(const FrameKinematics& K_AP, const FrameKinematics& K_PF);

// Frame F relative to frame A, from both relative to a common frame W (K_WA, K_WF); expressed in A.
// The inverse of compose: compose_kinematics(K_WA, relative_kinematics(K_WA, K_WF)) == K_WF.
FrameKinematics relative_kinematics(const FrameKinematics& K_WA, const FrameKinematics& K_WF);

// Throws std::invalid_argument naming the field ("R_PF: expected ...") unless every entry of K is
// finite and K.R_PF is a rotation matrix (orthonormal, det +1).
void check_frame_kinematics(const FrameKinematics& K);

}  // namespace rigiddyn
