#include "rigiddyn/frames/frame_motion.hpp"

#include <stdexcept>

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/exp_log.hpp"
#include "rigiddyn/so3/matrix.hpp"

namespace rigiddyn {

FrameMotion::FrameMotion(Function kinematics_at) : kinematics_at_(std::move(kinematics_at)) {
  if (!kinematics_at_) throw std::invalid_argument("kinematics_at: expected a callable, got an empty function");
}

FrameMotion FrameMotion::fixed(const Eigen::Matrix3d& R_PF, const Eigen::Vector3d& p_PF_P) {
  FrameKinematics K;
  K.R_PF = checked_rotation_matrix(R_PF, "R_PF");
  require_finite(p_PF_P, "p_PF_P");
  K.p_PF_P = p_PF_P;
  return FrameMotion([K](double) { return K; });
}

FrameMotion FrameMotion::constant_rotation(const Eigen::Vector3d& axis_P, double rate,
                                           const Eigen::Matrix3d& R_PF0, const Eigen::Vector3d& p_PF_P) {
  require_finite(axis_P, "axis_P");
  if (axis_P.norm() == 0.0) throw_invalid("axis_P", "a non-zero vector", axis_P);
  require_finite(rate, "rate");
  checked_rotation_matrix(R_PF0, "R_PF0");
  require_finite(p_PF_P, "p_PF_P");
  const Eigen::Vector3d w_PF_P = rate * axis_P.normalized();
  return FrameMotion([w_PF_P, R_PF0, p_PF_P](double t) {
    FrameKinematics K;
    K.R_PF = rotvec_to_matrix(w_PF_P * t) * R_PF0;
    K.w_PF_P = w_PF_P;
    K.p_PF_P = p_PF_P;
    return K;
  });
}

}  // namespace rigiddyn
