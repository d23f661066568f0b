#include "rigiddyn/so3/integrate.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/exp_log.hpp"

namespace rigiddyn {

Eigen::Quaterniond quat_integrate(const Eigen::Quaterniond& q, const Eigen::Vector3d& w, double dt, Frame frame) {
  require_finite(w, "w");
  require_finite(dt, "dt");
  // exp(w dt / 2) as a quaternion is the rotation by the rotation vector w dt
  const Eigen::Quaterniond step = rotvec_to_quat(w * dt);
  const Eigen::Quaterniond next = (frame == Frame::body) ? q * step : step * q;
  return next.normalized();
}

Eigen::Quaterniond quat_rate(const Eigen::Quaterniond& q, const Eigen::Vector3d& w, Frame frame) {
  require_finite(w, "w");
  const Eigen::Quaterniond half_w(0.0, 0.5 * w.x(), 0.5 * w.y(), 0.5 * w.z());  // (w/2, 0)
  return frame == Frame::body ? q * half_w : half_w * q;
}

Eigen::Vector3d angular_velocity_from_quat_rate(const Eigen::Quaterniond& q, const Eigen::Quaterniond& dq_dt, Frame frame) {
  require_finite(dq_dt.coeffs(), "dq_dt");
  // q* ⊗ q' = (w_B/2, q . q') and q' ⊗ q* = (w_W/2, q . q') for |q| = 1
  const Eigen::Quaterniond product = frame == Frame::body ? q.conjugate() * dq_dt : dq_dt * q.conjugate();
  return 2.0 * product.vec();
}

}  // namespace rigiddyn
