// A planar body pinned at a fixed point O in the scene model (scene/kinds/body_slot.hpp has the members every kind
// has; models/pivoted_planar_body.hpp the plane kinetics about O).
//   y (θ, ω), ξ (ω, α); the centre of mass follows the angle: p = (O + c_W, 0), v = ω ẑ × c_W, q = Rz(θ).
#pragma once
#include "rigiddyn/models/pivoted_planar_body.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/kinds/body_slot.hpp"

#include <cmath>
#include <limits>

namespace rigiddyn::detail {

template <class Place = SlotPlace>
struct PivotedPlanarSlot : Place {
  using kind = PivotedPlanarBody;  // the body it carries
  using place = Place;
  using Place::body, Place::at_y, Place::at_xi;
  static constexpr bool has_mass_flow = false;
  static constexpr Eigen::Index y_size = 2, xi_size = 2;
  static constexpr bool constrained = true;  // its pivot's reaction
  static constexpr bool reads_kinematics = false;
  static constexpr int theta = 0, w = 1;  // in y
  double inertia_O_zz;
  Eigen::Vector2d c_B, p_WO;  // p_OC_B [m] in B's xy plane, O [m] in W's xy plane
  // the last angle [rad] and its c_W = R(θ) c_B [m]: an evaluation's kinematics and angular acceleration share one
  // sine and cosine (the same numbers as computing them twice; a run copies its model, so its slot)
  mutable double cached_angle = std::numeric_limits<double>::quiet_NaN();
  mutable Eigen::Vector2d cached_c_W = Eigen::Vector2d::Zero();

  const Eigen::Vector2d& c_W_at(double angle) const {
    if (!(angle == cached_angle)) cached_angle = angle, cached_c_W = pivoted_planar_c_W(c_B, angle);
    return cached_c_W;
  }

  // α [rad/s²] at y under the wrench (plane kinetics about O)
  double alpha(const double* y, const BodyWrench& wrench) const {
    return pivoted_planar_angular_acceleration(inertia_O_zz, c_W_at(y[at_y + theta]), wrench);
  }
  RIGIDDYN_ALWAYS_INLINE void kinematics(const double* y, const StepClock& clock, BodyKinematics& k) const {
    motion_kinematics(y, clock, k);
    const double angle = y[at_y + theta];
    k.q_WB = Eigen::Quaterniond(std::cos(0.5 * angle), 0.0, 0.0, std::sin(0.5 * angle));
  }
  RIGIDDYN_ALWAYS_INLINE void motion_kinematics(const double* y, const StepClock&, BodyKinematics& k) const {
    const double angle = y[at_y + theta], omega = y[at_y + w];
    const Eigen::Vector2d c_W = c_W_at(angle);
    k.p_W = Eigen::Vector3d(p_WO.x() + c_W.x(), p_WO.y() + c_W.y(), 0.0);
    k.v_W = Eigen::Vector3d(-omega * c_W.y(), omega * c_W.x(), 0.0);
    k.w_B = Eigen::Vector3d(0.0, 0.0, omega);
  }
  RIGIDDYN_ALWAYS_INLINE void rate(const double* y, const StepClock&, const BodyKinematics&, const BodyWrench& wrench, double* dy) const {
    dy[at_y + theta] = y[at_y + w], dy[at_y + w] = alpha(y, wrench);
  }
  RIGIDDYN_ALWAYS_INLINE void velocity(const double* y, const StepClock&, const BodyKinematics&, const BodyWrench& wrench, double* xi) const {
    xi[at_xi] = y[at_y + w], xi[at_xi + 1] = alpha(y, wrench);
  }
  RIGIDDYN_ALWAYS_INLINE void retract(const double* y, const double* theta_, double* out) const {
    for (int i = 0; i < 2; ++i) out[at_y + i] = y[at_y + i] + theta_[at_xi + i];
  }
  RIGIDDYN_ALWAYS_INLINE void dexp_inv(const double*, double*) const {}
  RIGIDDYN_ALWAYS_INLINE void project(double*) const {}
  template <class GyroscopicKick>
  RIGIDDYN_ALWAYS_INLINE void kick(double* y, const BodyKinematics&, const BodyWrench& wrench, double h, const GyroscopicKick&) const {
    y[at_y + w] += h * alpha(y, wrench);
  }
  RIGIDDYN_ALWAYS_INLINE void translate(double*, double) const {}
  RIGIDDYN_ALWAYS_INLINE void turn(double* y, double h) const { y[at_y + theta] += h * y[at_y + w]; }
  template <class Rotation>
  RIGIDDYN_ALWAYS_INLINE void free_rotation(double* y, double h) const {
    turn(y, h);
  }
  // (no Coriolis torque about O: in the plane f ∥ c_W, and τ_z = 0)
  template <class Kicks>
  RIGIDDYN_ALWAYS_INLINE double loads_kick(double* y, BodyKinematics& k, const BodyWrench& wrench, double h, const Kicks&) const {
    const Eigen::Vector2d c_W = c_W_at(y[at_y + theta]);
    const double d = h * pivoted_planar_angular_acceleration(inertia_O_zz, c_W, wrench);
    k.w_B[2] += 0.5 * d;
    k.v_W = Eigen::Vector3d(-k.w_B[2] * c_W.y(), k.w_B[2] * c_W.x(), 0.0);
    y[at_y + w] += d;
    return 0.0;
  }
  // T = ½ I_O ω², H_O = (0, 0, I_O ω), H about W's origin = O × m v_C + H_O, the pivot's reaction
  void record(const double* y, const BodyKinematics& k, const BodyWrench& wrench, RecordSums& sums,
              Eigen::Vector3d& momentum_O_W, Eigen::Vector3d& reaction_W) const {
    const double omega = k.w_B[2];
    sums.T += 0.5 * inertia_O_zz * omega * omega;
    sums.L_W += k.m * k.v_W;
    momentum_O_W = Eigen::Vector3d(0.0, 0.0, inertia_O_zz * omega);
    sums.H_W += Eigen::Vector3d(p_WO.x(), p_WO.y(), 0.0).cross(k.m * k.v_W) + momentum_O_W;
    const Eigen::Vector2d c_W = c_W_at(y[at_y + theta]);
    reaction_W = pivoted_planar_reaction_W(k.m, c_W, omega, alpha(y, wrench), wrench.f_W);
  }
  void coordinates(const BodyState& state, double* y) const {
    const auto& s = std::get<PivotedPlanarBodyState>(state);
    y[at_y + theta] = s.theta, y[at_y + w] = s.omega;
  }
  BodyState state(const double* y) const { return PivotedPlanarBodyState{y[at_y + theta], y[at_y + w]}; }
  Eigen::Index attitude_y() const { return -1; }
};

template <class Groups>
void add_slot(Groups& groups, int b, const PivotedPlanarBody& body, Eigen::Index& y, Eigen::Index& xi) {
  std::get<std::vector<PivotedPlanarSlot<place_of<Groups>>>>(groups).push_back({{b, y, xi}, body.inertia_O_zz(), body.p_OC_B(), body.p_WO()});
  y += PivotedPlanarSlot<>::y_size, xi += PivotedPlanarSlot<>::xi_size;
}

}  // namespace rigiddyn::detail
