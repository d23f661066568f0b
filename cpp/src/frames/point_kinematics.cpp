#include "rigiddyn/frames/point_kinematics.hpp"

namespace rigiddyn {

PointVelocity PointVelocity::rotated(const Eigen::Matrix3d& R_EA) const {
  return {R_EA * origin, R_EA * rotational, R_EA * relative};
}

PointAcceleration PointAcceleration::rotated(const Eigen::Matrix3d& R_EA) const {
  return {R_EA * origin, R_EA * tangential, R_EA * centripetal, R_EA * relative, R_EA * coriolis};
}

PointVelocity point_velocity(const FrameKinematics& K_AF, const Eigen::Vector3d& p_FQ_F,
                             const Eigen::Vector3d& v_FQ_F) {
  const Eigen::Vector3d r = K_AF.R_PF * p_FQ_F;
  return {K_AF.v_PF_P, K_AF.w_PF_P.cross(r), K_AF.R_PF * v_FQ_F};
}

PointAcceleration point_acceleration(const FrameKinematics& K_AF, const Eigen::Vector3d& p_FQ_F,
                                     const Eigen::Vector3d& v_FQ_F, const Eigen::Vector3d& a_FQ_F) {
  const Eigen::Vector3d& w = K_AF.w_PF_P;
  const Eigen::Vector3d r = K_AF.R_PF * p_FQ_F;
  const Eigen::Vector3d v_rel = K_AF.R_PF * v_FQ_F;
  return {K_AF.a_PF_P, K_AF.alpha_PF_P.cross(r), w.cross(w.cross(r)), K_AF.R_PF * a_FQ_F,
          2.0 * w.cross(v_rel)};
}

}  // namespace rigiddyn
