// A rigid body in space with a MassFlow in the scene model (scene/kinds/body_slot.hpp has the members every kind
// has; mass_coordinate.hpp the mass it adds; scene/mass_flow.hpp the equations): m v̇ = f and Euler's equations
// I(m) ω̇ + ω × I(m) ω = τ.
//   y (p_W 3, q_WB 4, v_W 3, w_B 3, m), ξ (v_W, w_B, a_W, alpha_B, ṁ).
// Two slot types: MassRigidSlot<Euler> under InertiaRule::scaled (Euler's equations of I_C0 in its form, the
// torque scaled by m0/m) and FunctionRigidSlot under InertiaRule::function (I_C(m) from the user's function at each
// evaluation, Euler's equations in full form; the splitting methods are refused for it by compile). They share
// MassRigidKind, which asks the slot for euler_at(m), torque_scale_at(m), the energy terms and the free rotation.
#pragma once
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/kinds/mass_coordinate.hpp"
#include "rigiddyn/scene/kinds/rigid_slot.hpp"

#include <stdexcept>

namespace rigiddyn::detail {

template <class Slot>
struct MassRigidKind : SlotPlace, SpatialLayout {
  static constexpr bool has_mass_flow = true;
  static constexpr Eigen::Index y_size = 14, xi_size = 13;
  MassCoordinate mass;

  const Slot& self() const { return static_cast<const Slot&>(*this); }
  // a_W = f/m, α_B from Euler's equations at the mass m of k
  void newton_euler(const BodyKinematics& k, const Eigen::Vector3d& w_B, const BodyWrench& wrench, Eigen::Vector3d& a_W,
                    Eigen::Vector3d& alpha_B) const {
    const double m = k.m;
    a_W = wrench.f_W / m;
    alpha_B = self().euler_at(m).angular_acceleration(w_B, self().torque_scale_at(m) * wrench.tau_B);
  }
  void kinematics(const double* y, const StepClock& clock, BodyKinematics& k) const {
    SpatialLayout::kinematics(y + at_y, k);
    k.m = mass.checked_mass(y, clock);
  }
  void rate(const double* y, const StepClock& clock, const BodyKinematics& k, const BodyWrench& wrench, double* dy) const {
    const double* x = y + at_y;
    double* dx = dy + at_y;
    const Eigen::Vector3d w_B = three(x + w);
    Eigen::Vector3d a, alpha;
    newton_euler(k, w_B, wrench, a, alpha);
    for (int i = 0; i < 3; ++i) dx[p + i] = x[v + i], dx[v + i] = a[i], dx[w + i] = alpha[i];
    quat_rate_body(x + q, w_B, dx + q);
    dy[mass.m_y] = mass.rate_at(clock);
    dy[mass.energy_y] = self().mass_flow_power(y, dy[mass.m_y]);
  }
  void velocity(const double* y, const StepClock& clock, const BodyKinematics& k, const BodyWrench& wrench, double* xi) const {
    const double* x = y + at_y;
    double* u = xi + at_xi;
    const Eigen::Vector3d w_B = three(x + w);
    Eigen::Vector3d a, alpha;
    newton_euler(k, w_B, wrench, a, alpha);
    for (int i = 0; i < 3; ++i) u[xi_v + i] = x[v + i], u[xi_w + i] = w_B[i], u[xi_a + i] = a[i], u[xi_a + 3 + i] = alpha[i];
    xi[mass.m_xi] = mass.rate_at(clock);
    xi[mass.energy_xi] = self().mass_flow_power(y, xi[mass.m_xi]);
  }
  void retract(const double* y, const double* theta, double* out) const {
    for (int i = 0; i < 3; ++i) out[at_y + p + i] = y[at_y + p + i] + theta[at_xi + xi_v + i];
    times_exp(y + at_y + q, three(theta + at_xi + xi_w), out + at_y + q);
    for (int i = 0; i < 7; ++i) out[at_y + v + i] = y[at_y + v + i] + theta[at_xi + xi_a + i];  // v, ω, m
  }
  void dexp_inv(const double* theta, double* xi) const { dexp_inv_body(theta + at_xi + xi_w, xi + at_xi + xi_w); }
  void project(double* y) const { normalise_quaternion(y + at_y + q); }
  // Euler's equations of the form at m with the torque scaled (m0/m for I_C0)
  template <class GyroscopicKick>
  void kick(double* y, const BodyKinematics& k, const BodyWrench& wrench, double h, const GyroscopicKick& gyroscopic_kick) const {
    double* x = y + at_y;
    const double m = k.m;
    const Eigen::Vector3d w_B =
        gyroscopic_kick(self().euler_at(m), three(x + w), self().torque_scale_at(m) * wrench.tau_B, h);
    for (int i = 0; i < 3; ++i) x[v + i] += (h / m) * wrench.f_W[i], x[w + i] = w_B[i];
  }
  void translate(double* y, double h) const {
    for (int i = 0; i < 3; ++i) y[at_y + p + i] += h * y[at_y + v + i];
  }
  void turn(double* y, double h) const { SpatialLayout::turn(y + at_y, h); }
  template <class Kicks>
  double loads_kick(double* y, BodyKinematics& k, const BodyWrench& wrench, double h, const Kicks& kicks) const {
    Eigen::Vector3d a, alpha, dv, mean_v, dw, mean_w;
    newton_euler(k, Eigen::Vector3d::Zero(), wrench, a, alpha);  // ω = 0: the scaled torque alone
    kicks.translation(h * a, dv, mean_v);
    self().rotation_kick(kicks, k, h * alpha, dw, mean_w);
    k.v_W += mean_v;
    k.w_B += mean_w;
    for (int i = 0; i < 3; ++i) y[at_y + v + i] += dv[i], y[at_y + w + i] += dw[i];
    return dw.norm();
  }
  // I_C(m) ω = (I_C0 m/m0) ω under the scaled rule
  void record(const double*, const BodyKinematics& k, const BodyWrench&, RecordSums& sums, Eigen::Vector3d& momentum_O_W,
              Eigen::Vector3d&) const {
    sums.add_translation(k);
    const Eigen::Vector3d h_B = self().euler_at(k.m).momentum(k.w_B) / self().torque_scale_at(k.m);
    sums.T += 0.5 * k.w_B.dot(h_B);
    momentum_O_W = k.q_WB * h_B;
    sums.H_W += momentum_O_W;
  }
  void coordinates(const BodyState& state, double* y) const {
    SpatialLayout::coordinates(std::get<RigidBodyState>(state), y + at_y);
    y[mass.m_y] = mass.m0;
  }
  BodyState state(const double* y) const { return SpatialLayout::state(y + at_y); }
  Eigen::Index attitude_y() const { return at_y + q; }
};

template <class Euler>
struct MassRigidSlot : MassRigidKind<MassRigidSlot<Euler>> {
  Euler euler;            // of I_C0
  FreeRotationFlow flow;  // the exact free rotation of I_C0 (that of I_C0 m/m0 too)

  const Euler& euler_at(double /*m*/) const { return euler; }
  double torque_scale_at(double m) const { return torque_scale(this->mass.m0, m); }
  // scaled: M = I_C0⁻¹ [s]× with s of I_C0 (both scale by m/m0)
  template <class Kicks>
  void rotation_kick(const Kicks& kicks, const BodyKinematics& k, const Eigen::Vector3d& h_a0, Eigen::Vector3d& dw,
                     Eigen::Vector3d& mean) const {
    kicks.rotation(this->body, k.q_WB, h_a0, dw, mean);
  }
  // the free rotation of I_C0 (ω × I ω = 0 is unchanged by the factor m/m0)
  template <class Rotation>
  void free_rotation(double* y, double h) const {
    free_rotation_by(Rotation{}, euler, flow, y + this->at_y + SpatialLayout::q, y + this->at_y + SpatialLayout::w, h);
  }
  // ½ (m_new − m) (|v|² + ω·I_C0 ω / m0)
  double kinetic_energy_change(const double* y, double m, double m_new) const {
    const double* x = y + this->at_y;
    const Eigen::Vector3d w_B = three(x + SpatialLayout::w);
    return 0.5 * (m_new - m) * (three(x + SpatialLayout::v).squaredNorm() + w_B.dot(euler.momentum(w_B)) / this->mass.m0);
  }
  // ½ ṁ (|v|² + ω·I_C0 ω / m0)
  double mass_flow_power(const double* y, double rate) const {
    const double* x = y + this->at_y;
    const Eigen::Vector3d w_B = three(x + SpatialLayout::w);
    return 0.5 * rate * (three(x + SpatialLayout::v).squaredNorm() + w_B.dot(euler.momentum(w_B)) / this->mass.m0);
  }
};

struct FunctionRigidSlot : MassRigidKind<FunctionRigidSlot> {
  Eigen::Matrix3d inertia_com0;  // I_C0 [kg m²] in B

  FullEuler euler_at(double m) const {
    return FullEuler(inertia_at_mass(mass.flow, inertia_com0, mass.m0, m, mass.flow_name));
  }
  double torque_scale_at(double /*m*/) const { return 1.0; }
  // (I(m) of a function: the splitting methods are refused for it, so no exact Coriolis kick)
  template <class Kicks>
  void rotation_kick(const Kicks&, const BodyKinematics&, const Eigen::Vector3d& h_a0, Eigen::Vector3d& dw,
                     Eigen::Vector3d& mean) const {
    dw = h_a0, mean = 0.5 * dw;
  }
  template <class Rotation>
  void free_rotation(double*, double) const {
    throw std::logic_error("free_flow: a rigid body with InertiaRule::function has no free rotation (compile refuses "
                           "the splitting methods for it)");
  }
  // ½ (m_new − m) |v|² + ½ ω·(I(m_new) − I(m)) ω
  double kinetic_energy_change(const double* y, double m, double m_new) const {
    const double* x = y + at_y;
    const Eigen::Vector3d w_B = three(x + w);
    const Eigen::Matrix3d dI = inertia_at_mass(mass.flow, inertia_com0, mass.m0, m_new, mass.flow_name) -
                               inertia_at_mass(mass.flow, inertia_com0, mass.m0, m, mass.flow_name);
    return 0.5 * (m_new - m) * three(x + v).squaredNorm() + 0.5 * w_B.dot(dI * w_B);
  }
  // ½ ṁ (|v|² + ω·(dI/dm) ω)
  double mass_flow_power(const double* y, double rate) const {
    if (rate == 0.0) return 0.0;
    const double* x = y + at_y;
    const Eigen::Vector3d w_B = three(x + w);
    const Eigen::Matrix3d dI_dm = inertia_mass_derivative(mass.flow, inertia_com0, mass.m0, y[mass.m_y], rate, mass.flow_name);
    return 0.5 * rate * (three(x + v).squaredNorm() + w_B.dot(dI_dm * w_B));
  }
};

template <class Groups>
void add_mass_slot(Groups& groups, int b, const RigidBody& body, const MassCoordinate& given, Eigen::Index& y,
                   Eigen::Index& xi) {
  MassCoordinate mass = given;
  mass.m_y = y + 13, mass.m_xi = xi + 12, mass.m0 = body.mass();
  if (mass.flow.inertia_rule == InertiaRule::function) {
    std::get<std::vector<FunctionRigidSlot>>(groups).push_back({{{b, y, xi}, {}, std::move(mass)}, body.inertia_com()});
  } else {
    with_euler_form(body, [&](const auto& euler) {
      using Euler = std::decay_t<decltype(euler)>;
      std::get<std::vector<MassRigidSlot<Euler>>>(groups).push_back(
          {{{b, y, xi}, {}, mass}, euler, FreeRotationFlow(body.inertia_com())});
    });
  }
  y += FunctionRigidSlot::y_size, xi += FunctionRigidSlot::xi_size;
}

}  // namespace rigiddyn::detail
