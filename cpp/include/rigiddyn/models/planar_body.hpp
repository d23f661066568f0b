// The planar rigid body (3 DOF: x, y, θ in the xy plane of W; Craig, "Rigid Body Dynamics" slides, "plane kinetics"):
//   m a_G = Σ f (in the plane),  I_zz α = Σ τ_z (torques about the centre of mass G).
// There is no gyroscopic term in plane motion. Body frame B turns about z by θ: R_WB = Rz(θ).
#pragma once
#include <Eigen/Core>

#include <string>

namespace rigiddyn {

// mass [kg] and moment of inertia about the z axis through the centre of mass [kg m²]; throws
// std::invalid_argument unless both are finite and > 0.
class PlanarBody {
 public:
  PlanarBody(double mass, double inertia_zz);
  double mass() const { return mass_; }
  double inertia_zz() const { return inertia_zz_; }

 private:
  double mass_;
  double inertia_zz_;
};

// Centre of mass position p_W = (x, y) [m], angle θ [rad] of B about z, velocity v_W [m/s],
// angular velocity ω = θ̇ [rad/s].
struct PlanarBodyState {
  Eigen::Vector2d p_W = Eigen::Vector2d::Zero();
  double theta = 0.0;
  Eigen::Vector2d v_W = Eigen::Vector2d::Zero();
  double omega = 0.0;
};

// Throws std::invalid_argument naming `name`.p_W etc. for non-finite entries.
PlanarBodyState checked_state(const PlanarBodyState& state, const std::string& name = "state");

}  // namespace rigiddyn
