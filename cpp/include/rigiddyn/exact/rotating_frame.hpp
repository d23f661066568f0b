// The exact motion of a free particle seen from a frame F that turns at a constant rate about a fixed
// axis through its origin (the scene frame of SceneFrame::rotating), as a function of time.
//
// In the inertial frame W (here: F's inertial twin, the frame F is at t = 0) the particle moves on a straight line, p_W(t) = p_W0 + v_W0 t. F coincides with
// W at t = 0 and turns about the unit axis n (the same in F and W: it is fixed in both) at the rate Ω, so
// R_WF(t) = exp(Ω t n̂) and ω = Ω n. The observer in F sees ("Rigid body kinematics and dynamics" notes,
// §4.11.1, the velocity of a point in a moving frame, v_W = v_F + ω × p):
//   p_F(t) = R_FW(t) p_W(t),   v_F(t) = R_FW(t) (v_W0 − ω × p_W(t)),
// with p_W0 = p_F0 and v_W0 = v_F0 + ω × p_F0 from the state in F at t = 0. This is the solution of the
// particle's equation in F with only the centrifugal and Coriolis forces (eq. (4.40)):
//   a_F = −ω × (ω × p_F) − 2 ω × v_F,
// whose Jacobi integral ½|v_F|² − ½|ω × p_F|² is constant (jacobi_integral()).
#pragma once
#include "rigiddyn/scene/scene_frame.hpp"

#include <Eigen/Core>

namespace rigiddyn {

// Position [m] and velocity relative to F [m/s] of the particle, expressed in F.
struct RotatingFrameParticleState {
  Eigen::Vector3d p_F;
  Eigen::Vector3d v_F;
};

class RotatingFrameFreeParticle {
 public:
  // axis_F: the axis of F's rotation (any non-zero length; in F, equal to W at t = 0); rate: Ω [rad/s]
  // about it (right-handed); p0_F [m], v0_F [m/s]: the particle's position and velocity relative to F,
  // in F, at t = 0. Throws std::invalid_argument naming the argument for a non-finite value or a zero axis
  // (a zero axis is accepted with rate 0: F does not turn).
  RotatingFrameFreeParticle(const Eigen::Vector3d& axis_F, double rate, const Eigen::Vector3d& p0_F,
                            const Eigen::Vector3d& v0_F);

  // The same in a scene's frame: frame.constant_rotation must hold (SceneFrame::rotating, ::earth, or a
  // moving() frame recognised as a constant rotation), else std::invalid_argument naming frame; ω_F is
  // its angular velocity in F (frame_terms at t = 0). F's placement in W at t = 0 does not enter: the
  // motion relative to F is the same for any (the straight line in F's inertial twin at t = 0).
  RotatingFrameFreeParticle(const SceneFrame& frame, const Eigen::Vector3d& p0_F, const Eigen::Vector3d& v0_F);

  // The state in F at time t [s] (finite; throws std::invalid_argument naming t otherwise).
  RotatingFrameParticleState at(double t) const;
  // The straight line in W: p_W(t) [m] and the constant v_W [m/s].
  Eigen::Vector3d p_W_at(double t) const { return p_W0_ + v_W_ * t; }
  const Eigen::Vector3d& v_W() const { return v_W_; }
  // ω = Ω n [rad/s], in F (= in W).
  const Eigen::Vector3d& w_F() const { return w_; }
  // The Jacobi integral per unit mass ½|v_F|² − ½|ω × p_F|² [J/kg], constant along the motion.
  double jacobi_integral() const { return jacobi_; }

 private:
  Eigen::Vector3d axis_;  // unit
  double rate_;
  Eigen::Vector3d w_, p_W0_, v_W_;
  double jacobi_;
};

}  // namespace rigiddyn
