#include "rigiddyn/frames/frame_kinematics.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/frames/point_kinematics.hpp"
#include "rigiddyn/so3/matrix.hpp"

namespace rigiddyn {

FrameKinematics compose_kinematics(const FrameKinematics& K_AP, const FrameKinematics& K_PF) {
  const Eigen::Matrix3d& R_AP = K_AP.R_PF;
  const Eigen::Vector3d& w_AP = K_AP.w_PF_P;
  const Eigen::Vector3d w_PF_A = R_AP * K_PF.w_PF_P;
  // F's origin is a point moving in P: its motion seen from A, Rigid-body notes (4.38), (4.39).
  const PointVelocity v = point_velocity(K_AP, K_PF.p_PF_P, K_PF.v_PF_P);
  const PointAcceleration a = point_acceleration(K_AP, K_PF.p_PF_P, K_PF.v_PF_P, K_PF.a_PF_P);
  FrameKinematics K_AF;
  K_AF.R_PF = R_AP * K_PF.R_PF;
  // addition theorem (Craig): w_AF = w_AP + w_PF
  K_AF.w_PF_P = w_AP + w_PF_A;
  // d^A/dt (w_AP + w_PF) = alpha_AP + d^P/dt w_PF + w_AP x w_PF (transport theorem, Craig)
  K_AF.alpha_PF_P = K_AP.alpha_PF_P + R_AP * K_PF.alpha_PF_P + w_AP.cross(w_PF_A);
  K_AF.p_PF_P = K_AP.p_PF_P + R_AP * K_PF.p_PF_P;
  K_AF.v_PF_P = v.total();
  K_AF.a_PF_P = a.total();
  return K_AF;
}

FrameKinematics relative_kinematics(const FrameKinematics& K_WA, const FrameKinematics& K_WF) {
  // Solve compose_kinematics(K_WA, K_AF) = K_WF for K_AF, first with vectors in W, then rotate them into A.
  const Eigen::Matrix3d R_AW = K_WA.R_PF.transpose();
  const Eigen::Vector3d& w_WA = K_WA.w_PF_P;
  const Eigen::Vector3d w_AF = K_WF.w_PF_P - w_WA;
  // d^A/dt w_AF = d^W/dt w_AF - w_WA x w_AF
  const Eigen::Vector3d alpha_AF = K_WF.alpha_PF_P - K_WA.alpha_PF_P - w_WA.cross(w_AF);
  const Eigen::Vector3d r = K_WF.p_PF_P - K_WA.p_PF_P;
  // d^A/dt r = d^W/dt r - w_WA x r
  const Eigen::Vector3d v_AF = K_WF.v_PF_P - K_WA.v_PF_P - w_WA.cross(r);
  // Rigid-body notes (4.39) solved for the relative term
  const Eigen::Vector3d a_AF = K_WF.a_PF_P - K_WA.a_PF_P - K_WA.alpha_PF_P.cross(r) -
                               w_WA.cross(w_WA.cross(r)) - 2.0 * w_WA.cross(v_AF);
  FrameKinematics K_AF;
  K_AF.R_PF = R_AW * K_WF.R_PF;
  K_AF.w_PF_P = R_AW * w_AF;
  K_AF.alpha_PF_P = R_AW * alpha_AF;
  K_AF.p_PF_P = R_AW * r;
  K_AF.v_PF_P = R_AW * v_AF;
  K_AF.a_PF_P = R_AW * a_AF;
  return K_AF;
}

void check_frame_kinematics(const FrameKinematics& K) {
  checked_rotation_matrix(K.R_PF, "R_PF");
  require_finite(K.w_PF_P, "w_PF_P");
  require_finite(K.alpha_PF_P, "alpha_PF_P");
  require_finite(K.p_PF_P, "p_PF_P");
  require_finite(K.v_PF_P, "v_PF_P");
  require_finite(K.a_PF_P, "a_PF_P");
}

}  // namespace rigiddyn
