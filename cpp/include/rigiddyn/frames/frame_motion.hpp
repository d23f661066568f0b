// How a frame F moves relative to its parent frame P: a function of time t [s] giving the
// FrameKinematics of F in P (orientation R_PF, angular velocity and acceleration, origin position,
// velocity and acceleration, all expressed in P).
#pragma once
#include <Eigen/Core>

#include <functional>

#include "rigiddyn/frames/frame_kinematics.hpp"

namespace rigiddyn {

// The function of FrameMotion::fixed: F at the constant orientation R_PF and origin p_PF_P [m] in P.
struct FixedPlacement {
  Eigen::Matrix3d R_PF;
  Eigen::Vector3d p_PF_P;
  FrameKinematics operator()(double t) const;
};

// The function of FrameMotion::constant_rotation (parameters as given there; u_P = axis_P/|axis_P|).
struct ConstantRotation {
  Eigen::Vector3d axis_P;
  double rate;  // [rad/s]
  Eigen::Matrix3d R_PF0;
  Eigen::Vector3d p_PF_P;  // [m]
  Eigen::Vector3d u_P;
  FrameKinematics operator()(double t) const;
};

class FrameMotion {
 public:
  // kinematics_at(t): F relative to P at time t [s]. The caller is responsible for its consistency
  // (w_PF_P, alpha_PF_P the derivatives of R_PF; v_PF_P, a_PF_P those of p_PF_P); the frame tree
  // checks each value it gets (finite entries, R_PF a rotation). Throws on an empty function.
  using Function = std::function<FrameKinematics(double t)>;
  explicit FrameMotion(Function kinematics_at);

  // F fixed in P: constant orientation R_PF (a rotation matrix) and origin position p_PF_P [m]
  // (expressed in P). Throws std::invalid_argument on non-finite input or a non-rotation R_PF.
  static FrameMotion fixed(const Eigen::Matrix3d& R_PF = Eigen::Matrix3d::Identity(),
                           const Eigen::Vector3d& p_PF_P = Eigen::Vector3d::Zero());

  // Simple angular velocity (Craig): F turns at the constant rate `rate` [rad/s] about the axis
  // axis_P (expressed in P, any non-zero length; fixed in both P and F) through F's origin, which
  // stays at p_PF_P [m] in P:
  //   R_PF(t) = exp(hat(rate t axis_P/|axis_P|)) R_PF0,  w_PF_P = rate axis_P/|axis_P|, alpha = 0,
  // so R_PF0 is the orientation at t = 0. Throws std::invalid_argument on non-finite input, a zero
  // axis or a non-rotation R_PF0.
  static FrameMotion constant_rotation(const Eigen::Vector3d& axis_P, double rate,
                                       const Eigen::Matrix3d& R_PF0 = Eigen::Matrix3d::Identity(),
                                       const Eigen::Vector3d& p_PF_P = Eigen::Vector3d::Zero());

  // F relative to P at time t [s] (not checked here; FrameTree checks).
  FrameKinematics at(double t) const { return kinematics_at_(t); }
  // The function itself: function().target<FixedPlacement>() (or ConstantRotation) recovers the
  // parameters of a motion built by fixed() (or constant_rotation()), e.g. to save it.
  const Function& function() const { return kinematics_at_; }

 private:
  Function kinematics_at_;
};

}  // namespace rigiddyn
