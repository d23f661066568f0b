// A planar body in the scene model (scene/kinds/body_slot.hpp has the members every kind has): it moves in W's
// xy plane and turns about z.
//   y (x, y, θ, v_x, v_y, ω), ξ the six rates; plane kinetics (Craig, "Rigid Body Dynamics" slides): m a = f_xy,
//   I_zz α = τ_z. f_z and τ_x, τ_y are taken by the plane (the constraint reaction).
#pragma once
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/kinds/body_slot.hpp"

#include <cmath>

namespace rigiddyn::detail {

template <class Place = SlotPlace>
struct PlanarSlot : Place {
  using kind = PlanarBody;  // the body it carries
  using place = Place;
  using Place::body, Place::at_y, Place::at_xi;
  static constexpr bool has_mass_flow = false;
  static constexpr Eigen::Index y_size = 6, xi_size = 6;
  static constexpr bool constrained = true;  // its plane's reaction
  static constexpr bool reads_kinematics = false;
  static constexpr bool sets_rotation_matrices = true;  // kinematics sets R_WB = Rz(θ)
  static constexpr int p = 0, theta = 2, v = 3, w = 5;  // in y
  double inverse_mass, inertia_zz, inverse_inertia_zz;

  // (a_x, a_y, α)
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d acceleration(const BodyWrench& wrench) const {
    return Eigen::Vector3d(inverse_mass * wrench.f_W[0], inverse_mass * wrench.f_W[1], inverse_inertia_zz * wrench.tau_B[2]);
  }
  RIGIDDYN_ALWAYS_INLINE void kinematics(const double* y, const StepClock& clock, BodyKinematics& k) const {
    motion_kinematics(y, clock, k);
    const double half = 0.5 * y[at_y + theta], c = std::cos(half), s = std::sin(half);
    k.q_WB = Eigen::Quaterniond(c, 0.0, 0.0, s);
    // R_WB = Rz(θ) as Eigen's toRotationMatrix forms it from (c, 0, 0, s) (the same bits but for zeros' signs),
    // without the products of the zero components
    const double tzz = (2.0 * s) * s, twz = (2.0 * s) * c;
    k.R_WB << 1.0 - tzz, -twz, 0.0, twz, 1.0 - tzz, 0.0, 0.0, 0.0, 1.0;
  }
  RIGIDDYN_ALWAYS_INLINE void motion_kinematics(const double* y, const StepClock&, BodyKinematics& k) const {
    const double* x = y + at_y;
    k.p_W = Eigen::Vector3d(x[p], x[p + 1], 0.0);
    k.v_W = Eigen::Vector3d(x[v], x[v + 1], 0.0);
    k.w_B = Eigen::Vector3d(0.0, 0.0, x[w]);
  }
  RIGIDDYN_ALWAYS_INLINE void rate(const double* y, const StepClock&, const BodyKinematics&, const BodyWrench& wrench, double* dy) const {
    const Eigen::Vector3d a = acceleration(wrench);
    for (int i = 0; i < 3; ++i) dy[at_y + i] = y[at_y + v + i], dy[at_y + v + i] = a[i];
  }
  RIGIDDYN_ALWAYS_INLINE void velocity(const double* y, const StepClock&, const BodyKinematics&, const BodyWrench& wrench, double* xi) const {
    const Eigen::Vector3d a = acceleration(wrench);
    for (int i = 0; i < 3; ++i) xi[at_xi + i] = y[at_y + v + i], xi[at_xi + 3 + i] = a[i];
  }
  RIGIDDYN_ALWAYS_INLINE void retract(const double* y, const double* theta_, double* out) const {
    for (int i = 0; i < 6; ++i) out[at_y + i] = y[at_y + i] + theta_[at_xi + i];
  }
  RIGIDDYN_ALWAYS_INLINE void dexp_inv(const double*, double*) const {}
  RIGIDDYN_ALWAYS_INLINE void project(double*) const {}
  template <class GyroscopicKick>
  RIGIDDYN_ALWAYS_INLINE void kick(double* y, const BodyKinematics&, const BodyWrench& wrench, double h, const GyroscopicKick&) const {
    const Eigen::Vector3d a = acceleration(wrench);
    for (int i = 0; i < 3; ++i) y[at_y + v + i] += h * a[i];
  }
  RIGIDDYN_ALWAYS_INLINE void translate(double* y, double h) const {
    for (int i = 0; i < 2; ++i) y[at_y + p + i] += h * y[at_y + v + i];
  }
  RIGIDDYN_ALWAYS_INLINE void turn(double* y, double h) const { y[at_y + theta] += h * y[at_y + w]; }
  template <class Rotation>
  RIGIDDYN_ALWAYS_INLINE void free_rotation(double* y, double h) const {
    turn(y, h);
  }
  // (no Coriolis torque about z: ω ẑ and Ω_B give τ_z = 0)
  template <class Kicks>
  RIGIDDYN_ALWAYS_INLINE double loads_kick(double* y, BodyKinematics& k, const BodyWrench& wrench, double h, const Kicks& kicks) const {
    const Eigen::Vector3d d = h * acceleration(wrench);
    Eigen::Vector3d dv, mean_v;
    kicks.translation_in_plane(Eigen::Vector3d(d[0], d[1], 0.0), dv, mean_v);
    k.v_W += mean_v;
    k.w_B[2] += 0.5 * d[2];
    for (int i = 0; i < 2; ++i) y[at_y + v + i] += dv[i];
    y[at_y + w] += d[2];
    return 0.0;
  }
  // T = ½ m |v|² + ½ I_zz ω², H_C = (0, 0, I_zz ω) (R_WB = Rz(θ) leaves the z axis)
  void record(const double*, const BodyKinematics& k, const BodyWrench&, RecordSums& sums, Eigen::Vector3d& momentum_O_W,
              Eigen::Vector3d&) const {
    sums.add_translation(k);
    const double omega = k.w_B[2];
    sums.T += 0.5 * inertia_zz * omega * omega;
    momentum_O_W = Eigen::Vector3d(0.0, 0.0, inertia_zz * omega);
    sums.H_W += momentum_O_W;
  }
  void coordinates(const BodyState& state, double* y) const {
    const auto& s = std::get<PlanarBodyState>(state);
    double* x = y + at_y;
    x[p] = s.p_W.x(), x[p + 1] = s.p_W.y(), x[theta] = s.theta, x[v] = s.v_W.x(), x[v + 1] = s.v_W.y(), x[w] = s.omega;
  }
  BodyState state(const double* y) const {
    const double* x = y + at_y;
    return PlanarBodyState{Eigen::Vector2d(x[p], x[p + 1]), x[theta], Eigen::Vector2d(x[v], x[v + 1]), x[w]};
  }
  Eigen::Index attitude_y() const { return -1; }
};

template <class Groups>
void add_slot(Groups& groups, int b, const PlanarBody& body, Eigen::Index& y, Eigen::Index& xi) {
  std::get<std::vector<PlanarSlot<place_of<Groups>>>>(groups).push_back(
      {{b, y, xi}, 1.0 / body.mass(), body.inertia_zz(), 1.0 / body.inertia_zz()});
  y += PlanarSlot<>::y_size, xi += PlanarSlot<>::xi_size;
}

}  // namespace rigiddyn::detail
