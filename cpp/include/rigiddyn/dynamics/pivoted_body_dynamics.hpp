// Dynamics of a body about a fixed point O (models/pivoted_body.hpp, pivoted_planar_body.hpp): Euler's law
// about O (Craig, "Rigid Body Dynamics" slides: M_O = dH_O/dt, H_O = I_O ω; plane kinetics I_O α = M_O for
// rotation about a fixed axis) and the pivot's reaction from Newton's law for the centre of mass C:
//   I_O α_B + ω × I_O ω = τ_O = τ_C + c × f_B,   R = m a_C − f_W,  a_C = R_WB (α × c + ω × (ω × c)).
// Frames: "W" is the scene frame (inertial here); f_W, g_W and the reaction in W; ω_B, α_B and the torques
// in B. Gravity g_W [m/s²] acts at C and defaults to zero (docs/conventions.md, "no gravity unless asked").
#pragma once
#include "rigiddyn/dynamics/rigid_body_dynamics.hpp"  // ComWrench
#include "rigiddyn/models/pivoted_body.hpp"
#include "rigiddyn/models/pivoted_planar_body.hpp"

#include <Eigen/Core>

namespace rigiddyn {

// The motion of a pinned body: its angular acceleration α_B [rad/s²] in B and the pivot's reaction on it,
// reaction_W [N] in W.
struct PivotedAcceleration {
  Eigen::Vector3d alpha_B = Eigen::Vector3d::Zero();
  Eigen::Vector3d reaction_W = Eigen::Vector3d::Zero();
};

// What a motion of a pinned body requires: the torque about O, tau_O_B [N m] in B (applied as a couple, in
// addition to gravity), and the pivot's reaction reaction_W [N] in W.
struct PivotedTorque {
  Eigen::Vector3d tau_O_B = Eigen::Vector3d::Zero();
  Eigen::Vector3d reaction_W = Eigen::Vector3d::Zero();
};

// Forward dynamics: the wrench (f_W [N] at C in W, tau_B [N m] about C in B) and gravity m g_W at C reduced to
// O, α_B = I_O⁻¹ (τ_O − ω × I_O ω), and R = m a_C − (f_W + m g_W).
PivotedAcceleration forward_dynamics(const PivotedBody& body, const PivotedBodyState& state, const ComWrench& wrench,
                                     const Eigen::Vector3d& g_W = Eigen::Vector3d::Zero());

// Inverse dynamics: τ_O = I_O α + ω × I_O ω − c × R_BW m g_W, the couple that gives alpha_B [rad/s²] (in B)
// under gravity, and the reaction R = m a_C − m g_W.
PivotedTorque inverse_dynamics(const PivotedBody& body, const PivotedBodyState& state, const Eigen::Vector3d& alpha_B,
                               const Eigen::Vector3d& g_W = Eigen::Vector3d::Zero());

// The compound pendulum's angular acceleration α [rad/s²] about z and the pivot's reaction [N] in W.
struct PivotedPlanarAcceleration {
  double alpha = 0.0;
  Eigen::Vector3d reaction_W = Eigen::Vector3d::Zero();
};

// Its torque about O, tau_O [N m] about z (a couple, in addition to gravity), and the reaction [N] in W.
struct PivotedPlanarTorque {
  double tau_O = 0.0;
  Eigen::Vector3d reaction_W = Eigen::Vector3d::Zero();
};

// Forward dynamics in the plane: α = (τ_z + (c_W × f)_z) / I_O with f = f_W + m g_W (in-plane parts; the z
// parts of the force and the x, y parts of the torque are taken by the pin and the plane), R = m a_C − f.
PivotedPlanarAcceleration forward_dynamics(const PivotedPlanarBody& body, const PivotedPlanarBodyState& state,
                                           const ComWrench& wrench, const Eigen::Vector3d& g_W = Eigen::Vector3d::Zero());

// Inverse dynamics in the plane: τ_O = I_O α − (c_W × m g)_z for the given alpha [rad/s²], R = m a_C − m g_W.
PivotedPlanarTorque inverse_dynamics(const PivotedPlanarBody& body, const PivotedPlanarBodyState& state, double alpha,
                                     const Eigen::Vector3d& g_W = Eigen::Vector3d::Zero());

}  // namespace rigiddyn
