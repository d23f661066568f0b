#include "rigiddyn/orbit/orbit_frame.hpp"

#include "rigiddyn/check.hpp"

namespace rigiddyn {

namespace {
// r̂ and ĥ of a state, computed from the unit vectors so that no product overflows.
struct RadialNormal {
  Eigen::Vector3d r_hat, h_hat;
};
RadialNormal radial_and_normal(const Eigen::Vector3d& r_W, const Eigen::Vector3d& v_W) {
  require_finite(r_W, "r_W");
  require_finite(v_W, "v_W");
  const Eigen::Vector3d r_hat = r_W.stableNormalized(), v_hat = v_W.stableNormalized();
  const Eigen::Vector3d normal = r_hat.cross(v_hat);
  if (!(normal.norm() > 0.0)) {
    throw_invalid("r_W, v_W", "a position and velocity that span a plane (r x v != 0)", normal.transpose().eval());
  }
  return {r_hat, normal.normalized()};
}
}  // namespace

Eigen::Matrix3d orbit_frame_rotation(const Eigen::Vector3d& r_W, const Eigen::Vector3d& v_W, OrbitFrame frame) {
  const RadialNormal rn = radial_and_normal(r_W, v_W);
  const Eigen::Vector3d along = rn.h_hat.cross(rn.r_hat);  // S = ĥ × r̂, the local horizontal
  Eigen::Matrix3d R_WO;
  if (frame == OrbitFrame::lvlh) {
    R_WO << along, -rn.h_hat, -rn.r_hat;  // x = y × z = (−ĥ) × (−r̂), y = −ĥ, z = −r̂ (nadir)
  } else {
    R_WO << rn.r_hat, along, rn.h_hat;  // R, S, W
  }
  return R_WO;
}

Eigen::Vector3d orbit_frame_angular_velocity(const Eigen::Vector3d& r_W, const Eigen::Vector3d& v_W) {
  const RadialNormal rn = radial_and_normal(r_W, v_W);
  // (r × v)/r² = (|v|/|r|) (r̂ × v̂)
  return (v_W.norm() / r_W.norm()) * rn.r_hat.cross(v_W.stableNormalized());
}

Attitude attitude_from_orbit_frame(const Eigen::Vector3d& r_W, const Eigen::Vector3d& v_W,
                                   const Eigen::Quaterniond& q_OB, const Eigen::Vector3d& w_OB_B, OrbitFrame frame) {
  const Eigen::Quaterniond q_WO(orbit_frame_rotation(r_W, v_W, frame));
  const Eigen::Quaterniond q_WB = q_WO * q_OB;
  return {q_WB, w_OB_B + q_WB.conjugate() * orbit_frame_angular_velocity(r_W, v_W)};
}

Attitude attitude_to_orbit_frame(const Eigen::Vector3d& r_W, const Eigen::Vector3d& v_W, const Eigen::Quaterniond& q_WB,
                                 const Eigen::Vector3d& w_B, OrbitFrame frame) {
  const Eigen::Quaterniond q_WO(orbit_frame_rotation(r_W, v_W, frame));
  return {q_WO.conjugate() * q_WB, w_B - q_WB.conjugate() * orbit_frame_angular_velocity(r_W, v_W)};
}

}  // namespace rigiddyn
