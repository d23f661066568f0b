// The particle (point mass, 3 DOF; "Rigid body kinematics and dynamics" notes, §4.11): m p̈_W = f_W + m g_W.
// A particle has no attitude: loads given in the "body" frame are taken as world-frame forces, and
// torques are rejected by simulate (they would do nothing).
#pragma once
#include <Eigen/Core>

#include <string>

namespace rigiddyn {

// mass [kg]; throws std::invalid_argument unless finite and > 0.
class Particle {
 public:
  explicit Particle(double mass);
  double mass() const { return mass_; }

 private:
  double mass_;
};

// Position [m] and velocity [m/s] in W.
struct ParticleState {
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_W = Eigen::Vector3d::Zero();
};

// Throws std::invalid_argument naming `name`.p_W / `name`.v_W for non-finite entries.
ParticleState checked_state(const ParticleState& state, const std::string& name = "state");

}  // namespace rigiddyn
