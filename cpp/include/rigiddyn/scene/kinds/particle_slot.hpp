// A particle in the scene model (scene/kinds/body_slot.hpp has the members every kind has): no attitude, so a
// particle pays nothing for one.
//   y (p_W 3, v_W 3), ξ (v_W 3, a_W 3); Newton: m a_W = f_W (a point takes no torque).
#pragma once
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/kinds/body_slot.hpp"

namespace rigiddyn::detail {

template <class Place = SlotPlace>
struct ParticleSlot : Place {
  using kind = Particle;  // the body it carries
  using place = Place;
  using Place::body, Place::at_y, Place::at_xi;
  static constexpr bool has_mass_flow = false;
  static constexpr Eigen::Index y_size = 6, xi_size = 6;
  static constexpr bool reads_kinematics = false;
  static constexpr int p = 0, v = 3;  // in y
  double inverse_mass;

  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d acceleration(const BodyWrench& w) const {
    return Eigen::Vector3d(inverse_mass * w.f_W[0], inverse_mass * w.f_W[1], inverse_mass * w.f_W[2]);
  }
  RIGIDDYN_ALWAYS_INLINE void kinematics(const double* y, const StepClock&, BodyKinematics& k) const {
    const double* x = y + at_y;
    k.p_W = three(x + p);
    k.v_W = three(x + v);
  }
  RIGIDDYN_ALWAYS_INLINE void rate(const double* y, const StepClock&, const BodyKinematics&, const BodyWrench& w, double* dy) const {
    const double* x = y + at_y;
    const Eigen::Vector3d a = acceleration(w);
    for (int i = 0; i < 3; ++i) dy[at_y + p + i] = x[v + i], dy[at_y + v + i] = a[i];
  }
  RIGIDDYN_ALWAYS_INLINE void velocity(const double* y, const StepClock&, const BodyKinematics&, const BodyWrench& w, double* xi) const {
    const double* x = y + at_y;
    const Eigen::Vector3d a = acceleration(w);
    for (int i = 0; i < 3; ++i) xi[at_xi + i] = x[v + i], xi[at_xi + 3 + i] = a[i];
  }
  RIGIDDYN_ALWAYS_INLINE void retract(const double* y, const double* theta, double* out) const {
    for (int i = 0; i < 6; ++i) out[at_y + i] = y[at_y + i] + theta[at_xi + i];
  }
  RIGIDDYN_ALWAYS_INLINE void dexp_inv(const double*, double*) const {}
  RIGIDDYN_ALWAYS_INLINE void project(double*) const {}
  template <class GyroscopicKick>
  RIGIDDYN_ALWAYS_INLINE void kick(double* y, const BodyKinematics&, const BodyWrench& w, double h, const GyroscopicKick&) const {
    const Eigen::Vector3d a = acceleration(w);
    for (int i = 0; i < 3; ++i) y[at_y + v + i] += h * a[i];
  }
  RIGIDDYN_ALWAYS_INLINE void translate(double* y, double h) const {
    for (int i = 0; i < 3; ++i) y[at_y + p + i] += h * y[at_y + v + i];
  }
  RIGIDDYN_ALWAYS_INLINE void turn(double*, double) const {}
  template <class Rotation>
  RIGIDDYN_ALWAYS_INLINE void free_rotation(double*, double) const {}
  template <class Kicks>
  RIGIDDYN_ALWAYS_INLINE double loads_kick(double* y, BodyKinematics& k, const BodyWrench& w, double h, const Kicks& kicks) const {
    Eigen::Vector3d dv, mean_v;
    kicks.translation(h * acceleration(w), dv, mean_v);
    k.v_W += mean_v;
    for (int i = 0; i < 3; ++i) y[at_y + v + i] += dv[i];
    return 0.0;
  }
  void record(const double*, const BodyKinematics& k, const BodyWrench&, RecordSums& sums, Eigen::Vector3d&,
              Eigen::Vector3d&) const {
    sums.add_translation(k);
  }
  void coordinates(const BodyState& state, double* y) const {
    const auto& s = std::get<ParticleState>(state);
    for (int i = 0; i < 3; ++i) y[at_y + p + i] = s.p_W[i], y[at_y + v + i] = s.v_W[i];
  }
  BodyState state(const double* y) const {
    const double* x = y + at_y;
    return ParticleState{three(x + p), three(x + v)};
  }
  Eigen::Index attitude_y() const { return -1; }
};

template <class Groups>
void add_slot(Groups& groups, int b, const Particle& particle, Eigen::Index& y, Eigen::Index& xi) {
  std::get<std::vector<ParticleSlot<place_of<Groups>>>>(groups).push_back({{b, y, xi}, 1.0 / particle.mass()});
  y += ParticleSlot<>::y_size, xi += ParticleSlot<>::xi_size;
}

}  // namespace rigiddyn::detail
