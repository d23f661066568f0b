// The planar rigid body (3 DOF: x, y, θ in the xy plane of W; Craig, "Rigid Body Dynamics" slides, "plane kinetics"):
//   m a_G = Σ f (in the plane),  I_zz α = Σ τ_z (torques about the centre of mass G).
// There is no gyroscopic term in plane motion. Body frame B turns about z by θ: R_WB = Rz(θ).
#pragma once
#include "rigiddyn/models/loads.hpp"
#include "rigiddyn/models/model_interface.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

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

// Coordinates y = (x, y, θ, v_x, v_y, ω, work) (7,); tangent = the same (a vector space).
using PlanarBodyCoordinates = Eigen::Matrix<double, 7, 1>;
PlanarBodyCoordinates to_coordinates(const PlanarBodyState& state, double work = 0.0);
PlanarBodyState to_planar_state(const PlanarBodyCoordinates& y);

// The model simulate(planar body, ...) runs. Why it stays beside the one engine: under body-frame loads the scene
// model's one-body layout of a planar body (what simulate(scene, ...) runs) takes 1.04–2.24× its time (its
// semi-implicit steps evaluate the loads twice, for the works' powers), while without loads the layout takes
// 0.35–1.05× its time (bench/bench_one_body_layout.cpp, docs/perf/scenes.md §4.1).
class PlanarBodyModel {
 public:
  using Coordinates = PlanarBodyCoordinates;
  using Tangent = PlanarBodyCoordinates;

  // g_W: gravity [m/s²] in the plane (its z component is ignored; simulate rejects a non-zero one).
  PlanarBodyModel(const PlanarBody& body, const Eigen::Vector3d& g_W = Eigen::Vector3d::Zero())
      : mass_(body.mass()), inertia_zz_(body.inertia_zz()), g_W_(g_W.head<2>()) {
    set_loads(ComLoads{});
  }

  // in-plane parts: f = f_W.xy + Rz(θ) f_B.xy + m g, τ = tau_W.z + tau_B.z (out-of-plane parts ignored)
  void set_loads(const ComLoads& loads) {
    f_fixed_W_ = loads.f_W.head<2>() + mass_ * g_W_;
    f_B_ = loads.f_B.head<2>();
    tau_ = loads.tau_W.z() + loads.tau_B.z();
    turning_force_ = !f_B_.isZero(0.0);
  }

  RIGIDDYN_ALWAYS_INLINE void rate(const Coordinates& y, Coordinates& dy) const {
    const Eigen::Vector2d f = force_W(y(2));
    dy << y.segment<3>(3), f / mass_, tau_ / inertia_zz_, f.dot(y.segment<2>(3)) + tau_ * y(5);
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
  RIGIDDYN_ALWAYS_INLINE void kick(Coordinates& y, double h) const {
    y.segment<2>(3) += (h / mass_) * force_W(y(2));
    y(5) += h * tau_ / inertia_zz_;
  }
  void kick_implicit_gyroscopic(Coordinates& y, double h) const { kick(y, h); }
  RIGIDDYN_ALWAYS_INLINE void drift(Coordinates& y, double h) const {
    y(6) += h * (force_W(y(2)).dot(y.segment<2>(3)) + tau_ * y(5));
    y.segment<3>(0) += h * y.segment<3>(3);
  }
  // the loads do not depend on the velocities: two kicks are one (simulate/run_loop.hpp, merged_steps)
  static constexpr bool kicks_merge() { return true; }
  // the loads part: kick, the exact flow at the frozen angle θ (v += h f/m, ω += h τ/I_zz). Returns 0:
  // plane motion turns about a fixed axis and has no gyroscopic term, so the kick–free–kick step is
  // exact under a constant torque too and the 'exact' method takes it (ExactFreeFlow refuses only
  // kicks of a spatial body's ω)
  RIGIDDYN_ALWAYS_INLINE double loads_kick(Coordinates& y, double h) const {
    kick(y, h);
    return 0.0;
  }
  // the free part (x, y, θ) += h (v_x, v_y, ω), the same under every rotation flow (a turn about a
  // fixed axis is exact), with the work of the loads over the drift (drift): kick–free–kick is
  // velocity Verlet
  template <class Rotation>
  RIGIDDYN_ALWAYS_INLINE void free_flow(Coordinates& y, double h) const {
    drift(y, h);
  }

  RecordedState record(const Coordinates& y) const {
    RecordedState r;
    r.p_W << y(0), y(1), 0.0;
    r.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(y(2), Eigen::Vector3d::UnitZ()));
    r.v_W << y(3), y(4), 0.0;
    r.w_B << 0.0, 0.0, y(5);
    r.kinetic_energy = 0.5 * mass_ * y.segment<2>(3).squaredNorm() + 0.5 * inertia_zz_ * y(5) * y(5);
    r.potential_energy = -mass_ * g_W_.dot(y.head<2>());
    r.angular_momentum_norm = inertia_zz_ * std::abs(y(5));
    r.work = y(6);
    return r;
  }

 private:
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector2d force_W(double theta) const {
    if (!turning_force_) return f_fixed_W_;
    return f_fixed_W_ + Eigen::Rotation2Dd(theta) * f_B_;
  }

  double mass_;
  double inertia_zz_;
  Eigen::Vector2d g_W_;
  Eigen::Vector2d f_fixed_W_;  // f_W + m g [N]
  Eigen::Vector2d f_B_;        // body-frame force [N]
  double tau_;                 // torque about z [N m]
  bool turning_force_;
};

}  // namespace rigiddyn
