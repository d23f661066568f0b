// The compound pendulum: a planar body pinned at a point O fixed in the scene frame,
// turning about the scene frame's z axis (1 DOF, the angle θ of B about z, R_WB = Rz(θ)). "W" below is the
// scene frame. Plane kinetics about the fixed point O (Craig, "Rigid Body Dynamics" slides, "plane kinetics",
// rotation about a fixed axis, with the parallel-axis theorem):
//   I_O α = τ_z + (c_W × f)_z,  I_O = I_zz + m |c|²,  c_W = Rz(θ) p_OC_B,
// and the pivot's reaction from Newton's law for C: R = m a_C − f, a_C = α ẑ × c_W − ω² c_W.
#pragma once
#include "rigiddyn/models/planar_body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"  // BodyKinematics, BodyWrench

#include <Eigen/Core>

#include <cmath>
#include <string>

namespace rigiddyn {

// A planar body pinned at O. Throws std::invalid_argument naming mass / inertia_zz (each a finite number
// > 0), p_OC_B / p_WO (finite), and p_OC_B when the inertia about O, inertia_zz + m |c|², overflows.
class PivotedPlanarBody {
 public:
  // mass [kg], inertia_zz [kg m²] about the z axis through C, p_OC_B: C relative to O in B's xy plane [m]
  // (zero allowed), p_WO: O in the scene frame's xy plane [m].
  PivotedPlanarBody(double mass, double inertia_zz, const Eigen::Vector2d& p_OC_B,
                    const Eigen::Vector2d& p_WO = Eigen::Vector2d::Zero());

  double mass() const { return body_.mass(); }
  double inertia_zz() const { return body_.inertia_zz(); }  // about C [kg m²]
  double inertia_O_zz() const { return inertia_O_zz_; }     // I_zz + m |c|² [kg m²] about O
  const Eigen::Vector2d& p_OC_B() const { return p_OC_B_; }
  const Eigen::Vector2d& p_WO() const { return p_WO_; }
  const PlanarBody& body() const { return body_; }

 private:
  PlanarBody body_;
  Eigen::Vector2d p_OC_B_;
  Eigen::Vector2d p_WO_;
  double inertia_O_zz_;
};

// θ [rad]: the angle of B about z (R_WB = Rz(θ)); ω = θ̇ [rad/s].
struct PivotedPlanarBodyState {
  double theta = 0.0;
  double omega = 0.0;
};

// Throws std::invalid_argument naming `name`.theta / `name`.omega for non-finite values.
PivotedPlanarBodyState checked_state(const PivotedPlanarBodyState& state, const std::string& name = "state");

// c_W = Rz(θ) p_OC_B [m]: C relative to O in the scene frame's xy plane.
inline Eigen::Vector2d pivoted_planar_c_W(const Eigen::Vector2d& p_OC_B, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return Eigen::Vector2d(c * p_OC_B.x() - s * p_OC_B.y(), s * p_OC_B.x() + c * p_OC_B.y());
}

// The torque about O [N m] of the wrench (f_W at C, tau_B about C; their in-plane parts): τ_z + (c_W × f)_z.
inline double pivoted_planar_torque_O(const Eigen::Vector2d& c_W, const BodyWrench& wrench) {
  return wrench.tau_B.z() + c_W.x() * wrench.f_W.y() - c_W.y() * wrench.f_W.x();
}

// Plane kinetics about O: α = (τ_z + (c_W × f)_z) / I_O [rad/s²] (inertia_O_zz [kg m²], c_W [m]).
inline double pivoted_planar_angular_acceleration(double inertia_O_zz, const Eigen::Vector2d& c_W, const BodyWrench& wrench) {
  return pivoted_planar_torque_O(c_W, wrench) / inertia_O_zz;
}

// The pivot's reaction on the body [N] in the scene frame: R = m a_C − f_W with a_C = α ẑ × c_W − ω² c_W
// (in the plane) and f_W the resultant of the applied forces (gravity included); its z part −f_z is what
// the pin and the plane hold.
inline Eigen::Vector3d pivoted_planar_reaction_W(double mass, const Eigen::Vector2d& c_W, double omega, double alpha,
                                                 const Eigen::Vector3d& f_W) {
  const Eigen::Vector2d a_C(-alpha * c_W.y() - omega * omega * c_W.x(), alpha * c_W.x() - omega * omega * c_W.y());
  return Eigen::Vector3d(mass * a_C.x() - f_W.x(), mass * a_C.y() - f_W.y(), -f_W.z());
}

// The kinematics elements see (body_kinematics.hpp): p_W = (p_WO + c_W, 0), v_W = ω ẑ × c_W, q_WB = Rz(θ),
// w_B = (0, 0, ω), and the mass.
BodyKinematics kinematics_of(const PivotedPlanarBody& body, const PivotedPlanarBodyState& state);

}  // namespace rigiddyn
