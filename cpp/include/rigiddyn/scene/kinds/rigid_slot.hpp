// A rigid body in space in the scene model (scene/kinds/body_slot.hpp has the members every kind has), one slot
// type per Euler form (models/euler_equations.hpp: a sphere pays nothing for the gyroscopic term).
//   y (p_W 3, q_WB xyzw 4, v_W 3, w_B 3), ξ (v_W 3, w_B 3, a_W 3, alpha_B 3); Newton–Euler about the centre of
//   mass: m a_W = f_W, I α_B + ω_B × I ω_B = τ_B; q̇ = ½ q ⊗ (ω_B, 0).
#pragma once
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/kinds/body_slot.hpp"
#include "rigiddyn/so3/dexp_inv.hpp"
#include "rigiddyn/so3/quaternion_kernels.hpp"

namespace rigiddyn::detail {

// The attitude block of a body in space, y (p_W 3, q_WB 4, v_W 3, w_B 3, …): shared by the rigid kinds with and
// without a mass flow
struct SpatialLayout {
  static constexpr int p = 0, q = 3, v = 7, w = 10;     // in y
  static constexpr int xi_v = 0, xi_w = 3, xi_a = 6;    // in ξ (then alpha_B at 9)

  // p_W, the unit q_WB (the attitude as integrated, normalised), v_W, w_B
  RIGIDDYN_ALWAYS_INLINE static void kinematics(const double* x, BodyKinematics& k) {
    motion_kinematics(x, k);
    k.q_WB = unit_quaternion(x + q);
  }
  // p_W, v_W, w_B (the attitude left as it was)
  RIGIDDYN_ALWAYS_INLINE static void motion_kinematics(const double* x, BodyKinematics& k) {
    k.p_W = three(x + p);
    k.v_W = three(x + v);
    k.w_B = three(x + w);
  }
  // q ← q ⊗ exp(h ω_B) (exact for constant ω)
  RIGIDDYN_ALWAYS_INLINE static void turn(double* x, double h) {
    const double q0[4] = {x[q], x[q + 1], x[q + 2], x[q + 3]};
    times_exp(q0, Eigen::Vector3d(h * x[w], h * x[w + 1], h * x[w + 2]), x + q);
  }
  static void coordinates(const RigidBodyState& s, double* x) {
    for (int i = 0; i < 3; ++i) x[p + i] = s.p_W[i], x[v + i] = s.v_W[i], x[w + i] = s.w_B[i];
    for (int i = 0; i < 4; ++i) x[q + i] = s.q_WB.coeffs()[i];
  }
  static RigidBodyState state(const double* x) {
    RigidBodyState s;
    s.p_W = three(x + p);
    s.q_WB.coeffs() = Eigen::Vector4d(x[q], x[q + 1], x[q + 2], x[q + 3]);
    s.v_W = three(x + v);
    s.w_B = three(x + w);
    return s;
  }
};

template <class Euler, class Place = SlotPlace>
struct RigidSlot : Place, SpatialLayout {
  using kind = RigidBody;  // the body it carries
  using place = Place;
  using Place::body, Place::at_y, Place::at_xi;
  static constexpr bool has_mass_flow = false;
  static constexpr Eigen::Index y_size = 13, xi_size = 12;
  static constexpr bool reads_kinematics = false;
  double inverse_mass;
  Euler euler;
  FreeRotationFlow flow;  // the exact Euler–Poinsot flow of this body's inertia (free_flow<ExactRotation>)

  RIGIDDYN_ALWAYS_INLINE void newton_euler(const Eigen::Vector3d& w_B, const BodyWrench& wrench, Eigen::Vector3d& a_W,
                                           Eigen::Vector3d& alpha_B) const {
    a_W = Eigen::Vector3d(inverse_mass * wrench.f_W[0], inverse_mass * wrench.f_W[1], inverse_mass * wrench.f_W[2]);
    alpha_B = euler.angular_acceleration(w_B, wrench.tau_B);
  }
  RIGIDDYN_ALWAYS_INLINE void kinematics(const double* y, const StepClock&, BodyKinematics& k) const { SpatialLayout::kinematics(y + at_y, k); }
  RIGIDDYN_ALWAYS_INLINE void motion_kinematics(const double* y, const StepClock&, BodyKinematics& k) const {
    SpatialLayout::motion_kinematics(y + at_y, k);
  }
  RIGIDDYN_ALWAYS_INLINE void rate(const double* y, const StepClock&, const BodyKinematics&, const BodyWrench& wrench, double* dy) const {
    const double* x = y + at_y;
    double* dx = dy + at_y;
    const Eigen::Vector3d w_B = three(x + w);
    Eigen::Vector3d a, alpha;
    newton_euler(w_B, wrench, a, alpha);
    for (int i = 0; i < 3; ++i) dx[p + i] = x[v + i], dx[v + i] = a[i], dx[w + i] = alpha[i];
    quat_rate_body(x + q, w_B, dx + q);  // q̇ = ½ q ⊗ (ω_B, 0)
  }
  RIGIDDYN_ALWAYS_INLINE void velocity(const double* y, const StepClock&, const BodyKinematics&, const BodyWrench& wrench, double* xi) const {
    const double* x = y + at_y;
    double* u = xi + at_xi;
    const Eigen::Vector3d w_B = three(x + w);
    Eigen::Vector3d a, alpha;
    newton_euler(w_B, wrench, a, alpha);
    for (int i = 0; i < 3; ++i) u[xi_v + i] = x[v + i], u[xi_w + i] = w_B[i], u[xi_a + i] = a[i], u[xi_a + 3 + i] = alpha[i];
  }
  RIGIDDYN_ALWAYS_INLINE void retract(const double* y, const double* theta, double* out) const {
    retract_motion(y, theta, out);
    times_exp(y + at_y + q, three(theta + at_xi + xi_w), out + at_y + q);
  }
  // retract but the attitude, left as it was in out: for a stage whose rate reads no attitude (RKMK4's)
  RIGIDDYN_ALWAYS_INLINE void retract_motion(const double* y, const double* theta, double* out) const {
    for (int i = 0; i < 3; ++i) out[at_y + p + i] = y[at_y + p + i] + theta[at_xi + xi_v + i];
    for (int i = 0; i < 6; ++i) out[at_y + v + i] = y[at_y + v + i] + theta[at_xi + xi_a + i];
  }
  RIGIDDYN_ALWAYS_INLINE void dexp_inv(const double* theta, double* xi) const { dexp_inv_body(theta + at_xi + xi_w, xi + at_xi + xi_w); }
  RIGIDDYN_ALWAYS_INLINE void project(double* y) const { normalise_quaternion(y + at_y + q); }
  RIGIDDYN_ALWAYS_INLINE void midpoint_newton(const double* y0, const double* mid, double* next, double h) const {
    midpoint_newton_correction(euler, mid + at_y + w, next + at_y + w, h);
    midpoint_attitude(y0 + at_y + q, next + at_y + w, h, next + at_y + q);
  }
  template <class GyroscopicKick>
  RIGIDDYN_ALWAYS_INLINE void kick(double* y, const BodyKinematics&, const BodyWrench& wrench, double h, const GyroscopicKick& gyroscopic_kick) const {
    double* x = y + at_y;
    const Eigen::Vector3d w_B = gyroscopic_kick(euler, three(x + w), wrench.tau_B, h);
    for (int i = 0; i < 3; ++i) x[v + i] += (h * inverse_mass) * wrench.f_W[i], x[w + i] = w_B[i];
  }
  RIGIDDYN_ALWAYS_INLINE void translate(double* y, double h) const {
    for (int i = 0; i < 3; ++i) y[at_y + p + i] += h * y[at_y + v + i];
  }
  RIGIDDYN_ALWAYS_INLINE void turn(double* y, double h) const { SpatialLayout::turn(y + at_y, h); }
  template <class Rotation>
  RIGIDDYN_ALWAYS_INLINE void free_rotation(double* y, double h) const {
    free_rotation_by(Rotation{}, euler, flow, y + at_y + q, y + at_y + w, h);
  }
  template <class Kicks>
  RIGIDDYN_ALWAYS_INLINE double loads_kick(double* y, BodyKinematics& k, const BodyWrench& wrench, double h, const Kicks& kicks) const {
    Eigen::Vector3d a, alpha, dv, mean_v, dw, mean_w;
    newton_euler(Eigen::Vector3d::Zero(), wrench, a, alpha);  // ω = 0: I⁻¹ τ alone
    kicks.translation(h * a, dv, mean_v);
    kicks.rotation(body, k.q_WB, h * alpha, dw, mean_w);
    k.v_W += mean_v;
    k.w_B += mean_w;
    for (int i = 0; i < 3; ++i) y[at_y + v + i] += dv[i], y[at_y + w + i] += dw[i];
    return dw.norm();
  }
  // T = ½ m |v|² + ½ ω·I ω, H_C = R I ω
  void record(const double*, const BodyKinematics& k, const BodyWrench&, RecordSums& sums, Eigen::Vector3d& momentum_O_W,
              Eigen::Vector3d&) const {
    sums.add_translation(k);
    const Eigen::Vector3d h_B = euler.momentum(k.w_B);
    sums.T += 0.5 * k.w_B.dot(h_B);
    momentum_O_W = k.q_WB * h_B;
    sums.H_W += momentum_O_W;
  }
  void coordinates(const BodyState& state, double* y) const {
    SpatialLayout::coordinates(std::get<RigidBodyState>(state), y + at_y);
  }
  BodyState state(const double* y) const { return SpatialLayout::state(y + at_y); }
  Eigen::Index attitude_y() const { return at_y + q; }
};

template <class Groups>
void add_slot(Groups& groups, int b, const RigidBody& body, Eigen::Index& y, Eigen::Index& xi) {
  with_euler_form(body, [&](const auto& euler) {
    using Euler = std::decay_t<decltype(euler)>;
    std::get<std::vector<RigidSlot<Euler, place_of<Groups>>>>(groups).push_back(
        {{b, y, xi}, {}, 1.0 / body.mass(), euler, FreeRotationFlow(body.inertia_com())});
  });
  y += RigidSlot<SphericalEuler>::y_size, xi += RigidSlot<SphericalEuler>::xi_size;
}

}  // namespace rigiddyn::detail
