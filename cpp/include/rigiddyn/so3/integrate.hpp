// Exact attitude update for a constant angular velocity over one step.
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

}  // namespace rigiddyn
