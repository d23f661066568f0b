// The frames that follow a body along its orbit, from its position r_W and velocity v_W in the
// inertial frame W (ĥ = (r × v)/|r × v| the orbit normal, r̂ = r/|r|):
//   - LVLH (local vertical, local horizontal, as the attitude texts write it: Wie, "Space Vehicle
//     Dynamics and Control", sec. 6.4, with roll, pitch and yaw axes x, y, z; the shipped gravity_gradient
//     scene): z_O = −r̂ (nadir), y_O = −ĥ (opposite the orbit normal), x_O = y_O × z_O (along the
//     velocity on a circular orbit: the local horizontal);
//   - RSW (Hill's frame; Vallado, "Fundamentals of Astrodynamics and Applications", ch. 3): x_O = r̂
//     (R, radial, out), z_O = ĥ (W, the orbit normal), y_O = z_O × x_O (S, along-track).
// Both turn with the angular velocity w_WO = (r × v)/r²: about ĥ at the rate dθ/dt = h/r² of the radius
// vector (h = r² dθ/dt, Curtis, "Orbital Mechanics for Engineering Students", ch. 2), which on a circular
// orbit is the orbit rate n = √(μ/r³). Exact for any acceleration along r (a Keplerian orbit); an
// acceleration out of the orbit plane would add a component along r̂, not included here.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigiddyn {

enum class OrbitFrame { lvlh, rsw };

// R_WO: the orbit frame's axes as columns in W. Throws std::invalid_argument naming r_W or v_W
// (non-finite) or "r_W, v_W" (r × v = 0).
Eigen::Matrix3d orbit_frame_rotation(const Eigen::Vector3d& r_W, const Eigen::Vector3d& v_W, OrbitFrame frame);

// w_WO_W = (r × v)/r² [rad/s], the angular velocity of either orbit frame in W, expressed in W.
Eigen::Vector3d orbit_frame_angular_velocity(const Eigen::Vector3d& r_W, const Eigen::Vector3d& v_W);

// An attitude q and angular velocity w of a body B.
struct Attitude {
  Eigen::Quaterniond q;
  Eigen::Vector3d w;
};

// From the attitude relative to the orbit frame (q_OB, w_OB_B: B's angular velocity relative to O,
// expressed in B) to the inertial one (q_WB, w_B = w_WB_B):
//   q_WB = q_WO ⊗ q_OB,   w_B = w_OB_B + R_WBᵀ w_WO_W   (angular velocities add).
Attitude attitude_from_orbit_frame(const Eigen::Vector3d& r_W, const Eigen::Vector3d& v_W,
                                   const Eigen::Quaterniond& q_OB, const Eigen::Vector3d& w_OB_B, OrbitFrame frame);
// The inverse: q_OB = q_WO⁻¹ ⊗ q_WB, w_OB_B = w_B − R_WBᵀ w_WO_W.
Attitude attitude_to_orbit_frame(const Eigen::Vector3d& r_W, const Eigen::Vector3d& v_W, const Eigen::Quaterniond& q_WB,
                                 const Eigen::Vector3d& w_B, OrbitFrame frame);

}  // namespace rigiddyn
