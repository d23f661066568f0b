// The frame F a scene's states are expressed in, moving relative to the inertial frame W
// (docs/fixed_point_frames_mass.md §2).
// A scene with a SceneFrame is integrated relative to F: Newton's law seen by an observer moving with F
// gains the fictitious forces of the "Rigid body kinematics and dynamics" notes, eqs. (4.39)–(4.40),
//   m r̈ = f − m a_O − m α × r − m Ω × (Ω × r) − 2 m Ω × ṙ
// (frame origin, Euler, centrifugal, Coriolis), each a compiled force term (elements/fictitious_forces.hpp).
#pragma once
#include "rigiddyn/frames/frame_kinematics.hpp"
#include "rigiddyn/frames/frame_motion.hpp"

#include <Eigen/Core>

#include <string>

namespace rigiddyn {

// The Earth's sidereal rotation rate [rad/s] (SceneFrame::earth).
inline constexpr double earth_rotation_rate = 7.2921159e-5;

// The fictitious terms that act in a frame (those not identically zero; compile adds these alone): the frame
// origin's −m a_O needs a_O ≢ 0, the Euler term α ≢ 0, the centrifugal and Coriolis terms Ω ≢ 0 (both: the one
// acts wherever the other does), and α = dΩ/dt ≢ 0 only where Ω ≢ 0.
struct FictitiousTerms {
  bool origin = false, euler = false, centrifugal = false, coriolis = false;

  bool operator==(const FictitiousTerms& o) const {
    return origin == o.origin && euler == o.euler && centrifugal == o.centrifugal && coriolis == o.coriolis;
  }
  bool operator!=(const FictitiousTerms& o) const { return !(*this == o); }
};
inline constexpr FictitiousTerms every_fictitious_term{true, true, true, true};

// F relative to W: `motion` gives, at time t [s], R_WF, F's angular velocity and acceleration and its
// origin's position, velocity and acceleration, all expressed in W (frames/frame_motion.hpp with P = W).
// constant_rotation: F turns at a constant angular velocity about an axis through its origin, which does
// not move (α = 0, a_O = 0): then only the centrifugal and Coriolis terms act, the centrifugal one has a
// potential, and one particle in such a frame may run on the fast model.
// terms: the fictitious terms that act (compile adds these alone). For a general motion they are declared (every
// term by default) and checked where the motion is evaluated (frame_terms).
struct SceneFrame {
  FrameMotion motion;
  bool constant_rotation = false;
  FictitiousTerms terms;

  // F turning at `rate` [rad/s] about `axis_F` (any non-zero length; the axis is fixed in both F and W,
  // so it reads the same in either) through F's origin, fixed at W's origin; F = W at t = 0.
  // Throws std::invalid_argument naming `axis_F` (non-finite or zero) or `rate` (non-finite).
  static SceneFrame rotating(const Eigen::Vector3d& axis_F, double rate);

  // The local frame at geodetic latitude `latitude` [rad] on the turning Earth: x east, y north, z up,
  // Ω = earth_rotation_rate (0, cos φ, sin φ) [rad/s]. F's origin is taken as fixed: the centripetal
  // acceleration of a point of the Earth's surface is part of the local (effective) gravity, which the
  // scene gives as a UniformGravity element. Throws std::invalid_argument naming `latitude` unless it is
  // finite and in [−π/2, π/2].
  static SceneFrame earth(double latitude);

  // A general motion of F: every fictitious term may act. A motion built by FrameMotion::constant_rotation
  // (origin fixed, ω constant) or FrameMotion::fixed is recognised as a constant rotation (rate 0 for a
  // fixed placement), with its terms: the centrifugal and Coriolis ones (none at rate 0).
  static SceneFrame moving(FrameMotion motion);
  // The same with the terms that act declared, for a general motion whose others are identically zero (a frame
  // turning at a constant rate has no Euler term, one whose origin does not accelerate no origin term): compile
  // adds the declared terms alone, and each evaluation of the motion checks that the others' values are zero
  // (frame_terms). Throws std::invalid_argument naming `terms` for a set that cannot be (the Coriolis term without
  // the centrifugal one or the reverse, the Euler term without them), or, for a motion built by
  // FrameMotion::constant_rotation or ::fixed, another set than its own.
  static SceneFrame moving(FrameMotion motion, const FictitiousTerms& terms);
};

// What F's motion gives at one instant, expressed in F:
//   w_F      Ω, F's angular velocity relative to W [rad/s];
//   alpha_F  α = dΩ/dt, its angular acceleration [rad/s²] (the same seen from W or from F);
//   a_O_F    the acceleration of F's origin relative to W [m/s²].
struct FrameTerms {
  Eigen::Vector3d w_F = Eigen::Vector3d::Zero();
  Eigen::Vector3d alpha_F = Eigen::Vector3d::Zero();
  Eigen::Vector3d a_O_F = Eigen::Vector3d::Zero();
};

// The frame terms at time t [s]: the motion's values at t turned into F by R_FW = R_WFᵀ. Throws
// std::invalid_argument "frame: expected finite values from the motion function at t = <t> s, got ..."
// when any value the motion returns (R_WF included) is not finite, the error of checked_rotation_matrix
// naming "frame" when R_WF is not a rotation (so3/matrix.hpp: orthonormal to 1e-6, det > 0), and
// "frame: expected a_WO = 0 at t = <t> s (SceneFrame.moving's terms leave out the FrameOriginForce), got ..."
// (alpha_W for the EulerForce, w_W for the CentrifugalForce and CoriolisForce) when a value that the frame's
// declared terms take as zero is not.
FrameTerms frame_terms(const SceneFrame& frame, double t);

// "origin, euler, centrifugal, coriolis" (the terms that act, in that order; "none" for none)
std::string fictitious_term_names(const FictitiousTerms& terms);

}  // namespace rigiddyn
