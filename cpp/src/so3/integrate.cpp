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

}  // namespace rigiddyn
