// The particle (point mass, 3 DOF; "Rigid body kinematics and dynamics" notes, §4.11): m p̈_W = f_W + m g_W.
// A particle has no attitude: loads given in the "body" frame are taken as world-frame forces, and
// torques are rejected by simulate (they would do nothing).
#pragma once
#include "rigiddyn/models/loads.hpp"
#include "rigiddyn/models/model_interface.hpp"

#include <Eigen/Core>

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

// Coordinates y = (p_W:3, v_W:3, work:1) (7,); tangent = the same (a vector space).
using ParticleCoordinates = Eigen::Matrix<double, 7, 1>;
ParticleCoordinates to_coordinates(const ParticleState& state, double work = 0.0);
ParticleState to_particle_state(const ParticleCoordinates& y);

// The model simulate(particle, ...) runs. Why it stays beside the one engine: the scene model's one-body layout of a
// particle (what simulate(scene, ...) runs) takes 1.24–1.26× its time in the implicit midpoint rule and 1.30× in
// splitting_dlm under gravity, and is within 1.1× or faster in the other methods (bench/bench_one_body_layout.cpp,
// docs/perf/scenes.md §4.1).
class ParticleModel {
 public:
  using Coordinates = ParticleCoordinates;
  using Tangent = ParticleCoordinates;

  ParticleModel(const Particle& particle, const Eigen::Vector3d& g_W = Eigen::Vector3d::Zero())
      : mass_(particle.mass()), inverse_mass_(1.0 / particle.mass()), g_W_(g_W), f_W_(particle.mass() * g_W) {}

  // world- and "body"-frame forces add (no attitude); torques are ignored here (simulate rejects them)
  void set_loads(const ComLoads& loads) { f_W_ = loads.f_W + loads.f_B + mass_ * g_W_; }

  RIGIDDYN_ALWAYS_INLINE void rate(const Coordinates& y, Coordinates& dy) const {
    // element by element (scalar stores; see rk4.hpp's axpy on store forwarding)
    for (int i = 0; i < 3; ++i) dy[i] = y[3 + i], dy[3 + i] = inverse_mass_ * f_W_[i];
    dy[6] = f_W_[0] * y[3] + f_W_[1] * y[4] + f_W_[2] * y[5];
  }
  static void project(Coordinates& /*y*/) {}
  RIGIDDYN_ALWAYS_INLINE void velocity(const Coordinates& y, Tangent& xi) const { rate(y, xi); }
  static void retract(const Coordinates& y, const Tangent& theta, Coordinates& out) { out = y + theta; }
  RIGIDDYN_ALWAYS_INLINE void velocity_at(const Coordinates& y, const Tangent& theta, Tangent& xi) const {
    Coordinates stage;
    retract(y, theta, stage);
    velocity(stage, xi);
  }
  static void dexp_inv(const Tangent& /*theta*/, Tangent& /*xi*/) {}
  RIGIDDYN_ALWAYS_INLINE void kick(Coordinates& y, double h) const { y.segment<3>(3) += (h * inverse_mass_) * f_W_; }
  void kick_implicit_gyroscopic(Coordinates& y, double h) const { kick(y, h); }
  RIGIDDYN_ALWAYS_INLINE void drift(Coordinates& y, double h) const {
    y(6) += h * f_W_.dot(y.segment<3>(3));
    y.segment<3>(0) += h * y.segment<3>(3);
  }
  // the force does not depend on the velocity: two kicks are one (simulate/run_loop.hpp, merged_steps)
  static constexpr bool kicks_merge() { return true; }
  // the loads part: the force is constant over a step, so kick is its exact flow (v += h f/m); no
  // attitude, so no angular velocity changes (returns 0)
  RIGIDDYN_ALWAYS_INLINE double loads_kick(Coordinates& y, double h) const {
    kick(y, h);
    return 0.0;
  }
  // the free part p += h v (no attitude: the rotation flow is not used); with the work of the force
  // over the drift (drift), so that a kick–free–kick step is velocity Verlet
  template <class Rotation>
  RIGIDDYN_ALWAYS_INLINE void free_flow(Coordinates& y, double h) const {
    drift(y, h);
  }

  RecordedState record(const Coordinates& y) const {
    RecordedState r;
    r.p_W = y.segment<3>(0);
    r.q_WB = Eigen::Quaterniond::Identity();
    r.v_W = y.segment<3>(3);
    r.w_B.setZero();
    r.kinetic_energy = 0.5 * mass_ * r.v_W.squaredNorm();
    r.potential_energy = -mass_ * g_W_.dot(r.p_W);
    r.angular_momentum_norm = 0.0;
    r.work = y(6);
    return r;
  }

 private:
  double mass_;
  double inverse_mass_;
  Eigen::Vector3d g_W_;
  Eigen::Vector3d f_W_;  // total force in W during the step, gravity included [N]
};

}  // namespace rigiddyn
