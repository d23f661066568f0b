// A particle with a MassFlow in the scene model (scene/kinds/body_slot.hpp has the members every kind has;
// mass_coordinate.hpp the mass it adds): m v̇ = f (thrust included, scene/mass_flow.hpp).
//   y (p_W 3, v_W 3, m), ξ (v_W 3, a_W 3, ṁ).
#pragma once
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/kinds/mass_coordinate.hpp"

namespace rigiddyn::detail {

struct MassParticleSlot : SlotPlace {
  static constexpr bool has_mass_flow = true;
  static constexpr Eigen::Index y_size = 7, xi_size = 7;
  static constexpr int p = 0, v = 3;  // in y (then m)
  MassCoordinate mass;

  void kinematics(const double* y, const StepClock& clock, BodyKinematics& k) const {
    k.p_W = three(y + at_y + p);
    k.v_W = three(y + at_y + v);
    k.m = mass.checked_mass(y, clock);
  }
  void rate(const double* y, const StepClock& clock, const BodyKinematics& k, const BodyWrench& wrench, double* dy) const {
    const Eigen::Vector3d a = wrench.f_W / k.m;  // m v̇ = f (thrust included)
    for (int i = 0; i < 3; ++i) dy[at_y + p + i] = y[at_y + v + i], dy[at_y + v + i] = a[i];
    dy[mass.m_y] = mass.rate_at(clock);
    dy[mass.energy_y] = mass_flow_power(y, dy[mass.m_y]);
  }
  void velocity(const double* y, const StepClock& clock, const BodyKinematics& k, const BodyWrench& wrench, double* xi) const {
    const Eigen::Vector3d a = wrench.f_W / k.m;
    for (int i = 0; i < 3; ++i) xi[at_xi + i] = y[at_y + v + i], xi[at_xi + 3 + i] = a[i];
    xi[mass.m_xi] = mass.rate_at(clock);
    xi[mass.energy_xi] = mass_flow_power(y, xi[mass.m_xi]);
  }
  void retract(const double* y, const double* theta, double* out) const {
    for (int i = 0; i < 7; ++i) out[at_y + i] = y[at_y + i] + theta[at_xi + i];
  }
  void dexp_inv(const double*, double*) const {}
  void project(double*) const {}
  // the mass frozen at its value now
  template <class GyroscopicKick>
  void kick(double* y, const BodyKinematics& k, const BodyWrench& wrench, double h, const GyroscopicKick&) const {
    const Eigen::Vector3d dv = (h / k.m) * wrench.f_W;
    for (int i = 0; i < 3; ++i) y[at_y + v + i] += dv[i];
  }
  void translate(double* y, double h) const {
    for (int i = 0; i < 3; ++i) y[at_y + p + i] += h * y[at_y + v + i];
  }
  void turn(double*, double) const {}
  template <class Rotation>
  void free_rotation(double*, double) const {}
  template <class Kicks>
  double loads_kick(double* y, BodyKinematics& k, const BodyWrench& wrench, double h, const Kicks& kicks) const {
    Eigen::Vector3d dv, mean_v;
    kicks.translation((h / k.m) * wrench.f_W, dv, mean_v);
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
    y[mass.m_y] = mass.m0;
  }
  BodyState state(const double* y) const { return ParticleState{three(y + at_y + p), three(y + at_y + v)}; }
  Eigen::Index attitude_y() const { return -1; }

  // The change of T [J] when the mass goes from m to m_new [kg] at the velocity of y: ½ (m_new − m) |v|²
  double kinetic_energy_change(const double* y, double m, double m_new) const {
    return 0.5 * (m_new - m) * three(y + at_y + v).squaredNorm();
  }
  // The mass-flow power [W] at y with the mass rate ṁ [kg/s]: ½ ṁ |v|²
  double mass_flow_power(const double* y, double rate) const { return 0.5 * rate * three(y + at_y + v).squaredNorm(); }
};

template <class Groups>
void add_mass_slot(Groups& groups, int b, const Particle& particle, const MassCoordinate& given, Eigen::Index& y,
                   Eigen::Index& xi) {
  MassCoordinate mass = given;
  mass.m_y = y + 6, mass.m_xi = xi + 6, mass.m0 = particle.mass();
  std::get<std::vector<MassParticleSlot>>(groups).push_back({{b, y, xi}, std::move(mass)});
  y += MassParticleSlot::y_size, xi += MassParticleSlot::xi_size;
}

}  // namespace rigiddyn::detail
