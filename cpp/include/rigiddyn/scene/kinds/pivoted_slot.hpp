// A rigid body pinned at a fixed point O in the scene model (scene/kinds/body_slot.hpp has the members every kind
// has), one slot type per Euler form of its inertia about O (models/pivoted_body.hpp: Euler's equations about O,
// the one home of the pivoted Newton–Euler).
//   y (q_WB xyzw 4, w_B 3), ξ (w_B 3, alpha_B 3); the centre of mass follows the attitude: p = O + R c, v = R (ω × c).
#pragma once
#include "rigiddyn/models/pivoted_body.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/kinds/body_slot.hpp"
#include "rigiddyn/so3/dexp_inv.hpp"
#include "rigiddyn/so3/quaternion_kernels.hpp"

namespace rigiddyn::detail {

template <class Euler, class Place = SlotPlace>
struct PivotedSlot : Place {
  using kind = PivotedBody;  // the body it carries
  using place = Place;
  using Place::body, Place::at_y, Place::at_xi;
  static constexpr bool has_mass_flow = false;
  static constexpr Eigen::Index y_size = 7, xi_size = 6;
  static constexpr bool constrained = true;  // its pivot's reaction
  static constexpr int q = 0, w = 4;  // in y
  Eigen::Vector3d c_B, p_WO;          // p_OC_B [m] in B, O [m] in W
  Euler euler_O;                      // the Euler form of I_O
  FreeRotationFlow flow_O;            // the exact free rotation about O (free_flow<ExactRotation>)

  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d angular_acceleration(const BodyKinematics& k, const Eigen::Vector3d& w_B, const BodyWrench& wrench) const {
    return pivoted_angular_acceleration(euler_O, c_B, k.q_WB, w_B, wrench);
  }
  // at the centre of mass: p = O + R c, v = R (ω × c)
  RIGIDDYN_ALWAYS_INLINE void kinematics(const double* y, const StepClock&, BodyKinematics& k) const {
    const double* x = y + at_y;
    k.q_WB = Eigen::Quaterniond(x[q + 3], x[q], x[q + 1], x[q + 2]);
    k.q_WB.coeffs() *= 1.0 / k.q_WB.coeffs().norm();
    k.w_B = three(x + w);
    k.p_W = p_WO + k.q_WB * c_B;
    k.v_W = k.q_WB * cross_3(k.w_B, c_B);
  }
  RIGIDDYN_ALWAYS_INLINE void rate(const double* y, const StepClock&, const BodyKinematics& k, const BodyWrench& wrench, double* dy) const {
    const Eigen::Vector3d alpha = angular_acceleration(k, k.w_B, wrench);
    quat_rate_body(y + at_y + q, k.w_B, dy + at_y + q);  // q̇ = ½ q ⊗ (ω_B, 0)
    for (int i = 0; i < 3; ++i) dy[at_y + w + i] = alpha[i];
  }
  RIGIDDYN_ALWAYS_INLINE void velocity(const double*, const StepClock&, const BodyKinematics& k, const BodyWrench& wrench, double* xi) const {
    const Eigen::Vector3d alpha = angular_acceleration(k, k.w_B, wrench);
    for (int i = 0; i < 3; ++i) xi[at_xi + i] = k.w_B[i], xi[at_xi + 3 + i] = alpha[i];
  }
  RIGIDDYN_ALWAYS_INLINE void retract(const double* y, const double* theta, double* out) const {
    times_exp(y + at_y + q, three(theta + at_xi), out + at_y + q);
    for (int i = 0; i < 3; ++i) out[at_y + w + i] = y[at_y + w + i] + theta[at_xi + 3 + i];
  }
  // retract but the attitude, y's kept: for a stage whose velocity reads the attitude only through a force (the
  // one-body layout without an element)
  RIGIDDYN_ALWAYS_INLINE void retract_motion(const double* y, const double* theta, double* out) const {
    for (int i = 0; i < 4; ++i) out[at_y + q + i] = y[at_y + q + i];
    for (int i = 0; i < 3; ++i) out[at_y + w + i] = y[at_y + w + i] + theta[at_xi + 3 + i];
  }
  RIGIDDYN_ALWAYS_INLINE void dexp_inv(const double* theta, double* xi) const { dexp_inv_body(theta + at_xi, xi + at_xi); }
  RIGIDDYN_ALWAYS_INLINE void project(double* y) const { normalise_quaternion(y + at_y + q); }
  // about O: Euler's gyroscopic term of I_O
  RIGIDDYN_ALWAYS_INLINE void midpoint_newton(const double* y0, const double* mid, double* next, double h) const {
    midpoint_newton_correction(euler_O, mid + at_y + w, next + at_y + w, h);
    midpoint_attitude(y0 + at_y + q, next + at_y + w, h, next + at_y + q);
  }
  // Euler's equations about O with the wrench reduced to O
  template <class GyroscopicKick>
  RIGIDDYN_ALWAYS_INLINE void kick(double* y, const BodyKinematics& k, const BodyWrench& wrench, double h, const GyroscopicKick& gyroscopic_kick) const {
    const Eigen::Vector3d w_B = gyroscopic_kick(euler_O, k.w_B, pivoted_torque_O(c_B, k.q_WB, wrench), h);
    for (int i = 0; i < 3; ++i) y[at_y + w + i] = w_B[i];
  }
  RIGIDDYN_ALWAYS_INLINE void translate(double*, double) const {}
  RIGIDDYN_ALWAYS_INLINE void turn(double* y, double h) const {
    double* x = y + at_y;
    const double q0[4] = {x[q], x[q + 1], x[q + 2], x[q + 3]};
    times_exp(q0, Eigen::Vector3d(h * x[w], h * x[w + 1], h * x[w + 2]), x + q);
  }
  // the free rotation about O: I_O in place of I_C
  template <class Rotation>
  RIGIDDYN_ALWAYS_INLINE void free_rotation(double* y, double h) const {
    free_rotation_by(Rotation{}, euler_O, flow_O, y + at_y + q, y + at_y + w, h);
  }
  // ω += h I_O⁻¹ τ_O (ω = 0 in Euler's equations: the torque alone); the mean v̄ = R (ω̄ × c)
  template <class Kicks>
  RIGIDDYN_ALWAYS_INLINE double loads_kick(double* y, BodyKinematics& k, const BodyWrench& wrench, double h, const Kicks& kicks) const {
    Eigen::Vector3d dw, mean_w;
    kicks.rotation(body, k.q_WB, h * angular_acceleration(k, Eigen::Vector3d::Zero(), wrench), dw, mean_w);
    k.w_B += mean_w;
    k.v_W = k.q_WB * cross_3(k.w_B, c_B);
    for (int i = 0; i < 3; ++i) y[at_y + w + i] += dw[i];
    return dw.norm();
  }
  // T = ½ ω·I_O ω, H_O = R I_O ω, H about W's origin = p_WO × m v_C + H_O (H_O sums (r − O) × v dm), the
  // reaction from Newton's law for the centre of mass (models/pivoted_body.hpp)
  void record(const double*, const BodyKinematics& k, const BodyWrench& wrench, RecordSums& sums,
              Eigen::Vector3d& momentum_O_W, Eigen::Vector3d& reaction_W) const {
    const Eigen::Vector3d h_B = euler_O.momentum(k.w_B);
    sums.T += 0.5 * k.w_B.dot(h_B);
    sums.L_W += k.m * k.v_W;
    momentum_O_W = k.q_WB * h_B;
    sums.H_W += p_WO.cross(k.m * k.v_W) + momentum_O_W;
    const Eigen::Vector3d alpha = angular_acceleration(k, k.w_B, wrench);
    reaction_W = pivot_reaction_W(k.m, c_B, k.q_WB, k.w_B, alpha, wrench.f_W);
  }
  void coordinates(const BodyState& state, double* y) const {
    const auto& s = std::get<PivotedBodyState>(state);
    for (int i = 0; i < 4; ++i) y[at_y + q + i] = s.q_WB.coeffs()[i];
    for (int i = 0; i < 3; ++i) y[at_y + w + i] = s.w_B[i];
  }
  BodyState state(const double* y) const {
    const double* x = y + at_y;
    PivotedBodyState s;
    s.q_WB.coeffs() = Eigen::Vector4d(x[q], x[q + 1], x[q + 2], x[q + 3]);
    s.w_B = three(x + w);
    return s;
  }
  Eigen::Index attitude_y() const { return at_y + q; }
};

template <class Groups>
void add_slot(Groups& groups, int b, const PivotedBody& body, Eigen::Index& y, Eigen::Index& xi) {
  with_euler_form(body, [&](const auto& euler_O) {
    using Euler = std::decay_t<decltype(euler_O)>;
    std::get<std::vector<PivotedSlot<Euler, place_of<Groups>>>>(groups).push_back(
        {{b, y, xi}, body.p_OC_B(), body.p_WO(), euler_O, FreeRotationFlow(body.inertia_O())});
  });
  y += PivotedSlot<SphericalEuler>::y_size, xi += PivotedSlot<SphericalEuler>::xi_size;
}

}  // namespace rigiddyn::detail
