// The spatial rigid body (6 DOF): mass properties, state (docs/conventions.md "Body state") and the
// integrator model RigidBodyModel<Euler> (see model_interface.hpp), templated on the form of
// Euler's equations (euler_equations.hpp) so that a sphere pays nothing for the gyroscopic term.
//
// Equations of motion (Craig, "Rigid Body Dynamics" slides, Newton–Euler about the centre of mass G):
//   ṗ_W = v_W,  q̇_WB = ½ q_WB ⊗ (ω_B, 0),  m v̇_W = f_W + m g_W,  I ω̇_B + ω_B × I ω_B = tau_B.
#pragma once
#include "rigiddyn/check.hpp"  // format_value
#include "rigiddyn/inertia/spatial_inertia.hpp"
#include "rigiddyn/inertia/validity.hpp"
#include "rigiddyn/integrators/exact_flow_kick.hpp"    // exact_free_rotation, FreeRotationFlow
#include "rigiddyn/integrators/implicit_midpoint.hpp"  // midpoint_rotation, implicit_midpoint_solver
#include "rigiddyn/integrators/splitting_dlm.hpp"      // dlm_free_rotation
#include "rigiddyn/models/euler_equations.hpp"
#include "rigiddyn/models/loads.hpp"
#include "rigiddyn/models/model_interface.hpp"
#include "rigiddyn/so3/dexp_inv.hpp"
#include "rigiddyn/so3/exp_log.hpp"
#include "rigiddyn/so3/quaternion_kernels.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace rigiddyn {

// Which form of Euler's equations an inertia needs.
enum class EulerForm { spherical, principal, full };

// Mass [kg] and rotational inertia about the centre of mass [kg m²], expressed in the body frame B
// (origin at the centre of mass).
class RigidBody {
 public:
  // Throws std::invalid_argument (the inertia layer's checked_inertia, so the messages are those of
  // every other constructor of mass properties) for mass <= 0 or non-finite, for an inertia_com that is
  // not symmetric positive semi-definite or, under InertiaCheck::physical (the default), whose
  // principal moments violate I_a + I_b >= I_c (no real body has them; pass
  // InertiaCheck::allow_unrealizable to accept e.g. the Hairer–Lubich–Wanner test body
  // I = (2, 1, 2/3) on purpose); and for a singular inertia (Euler's equations need I⁻¹).
  RigidBody(double mass, const Eigen::Matrix3d& inertia_com, InertiaCheck check = InertiaCheck::physical);
  // The same from any Eigen expression: a 3×3 one is inertia_com; a 3-vector holds the principal
  // moments (I1, I2, I3) [kg m²] about the centre of mass, B's axes principal: inertia_com =
  // diag(I1, I2, I3). (One template for both, so that `RigidBody(m, Eigen::Matrix3d::Identity())` and
  // `RigidBody(m, Eigen::Vector3d(1, 2, 2.5))` are never ambiguous.)
  template <class Derived>
  RigidBody(double mass, const Eigen::MatrixBase<Derived>& inertia, InertiaCheck check = InertiaCheck::physical)
      : RigidBody(mass, as_inertia_com(inertia), check) {}
  // From mass properties: uses mass() and inertia_com() (B's axes, origin moved to the centre of mass).
  explicit RigidBody(const SpatialInertia& inertia, InertiaCheck check = InertiaCheck::physical);

  double mass() const { return mass_; }
  const Eigen::Matrix3d& inertia_com() const { return inertia_com_; }
  // spherical if I = s 1, principal if I is diagonal, full otherwise (relative tolerance 1e-12,
  // so dropping the terms changes the motion far below any integrator's error).
  EulerForm euler_form() const { return form_; }

 private:
  template <class Derived>
  static Eigen::Matrix3d as_inertia_com(const Eigen::MatrixBase<Derived>& inertia) {
    if constexpr (Derived::ColsAtCompileTime == 1) {
      static_assert(Derived::RowsAtCompileTime == 3, "RigidBody: principal moments are a 3-vector");
      return Eigen::Vector3d(inertia).asDiagonal();
    } else {
      static_assert(Derived::RowsAtCompileTime == 3 && Derived::ColsAtCompileTime == 3, "RigidBody: inertia_com is 3x3");
      return inertia;
    }
  }

  double mass_;
  Eigen::Matrix3d inertia_com_;
  EulerForm form_;
};

// Calls f(euler) with the Euler-equation form the body needs: SphericalEuler, PrincipalEuler or
// FullEuler. The single runtime switch; everything below it is compiled per form.
template <class F>
decltype(auto) with_euler_form(const RigidBody& body, F&& f) {
  const Eigen::Matrix3d& I = body.inertia_com();
  switch (body.euler_form()) {
    case EulerForm::spherical: return f(SphericalEuler(I.trace() / 3.0));
    case EulerForm::principal: return f(PrincipalEuler(I.diagonal()));
    case EulerForm::full: return f(FullEuler(I));
  }
  throw std::logic_error("with_euler_form: unknown EulerForm");
}

// State (docs/conventions.md): p_W of the centre of mass [m], unit q_WB, v_W of the centre of mass
// [m/s] in W, angular velocity w_B [rad/s] in B.
struct RigidBodyState {
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_WB = Eigen::Quaterniond::Identity();
  Eigen::Vector3d v_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_B = Eigen::Vector3d::Zero();
};

// The state with its quaternion normalised; throws std::invalid_argument naming `name`.p_W etc.
// for a non-finite entry or a quaternion farther than 1e-6 from unit norm.
RigidBodyState checked_state(const RigidBodyState& state, const std::string& name = "state");

// Coordinates layout (rot/lin as MuJoCo): y = (p_W:3, q_WB xyzw:4, v_W:3, w_B:3, work:1) (14,);
// tangent xi = (v_W:3, w_B:3, a_W:3, alpha_B:3, power:1) (13,).
using RigidBodyCoordinates = Eigen::Matrix<double, 14, 1>;
using RigidBodyTangent = Eigen::Matrix<double, 13, 1>;
RigidBodyCoordinates to_coordinates(const RigidBodyState& state, double work = 0.0);
RigidBodyState to_rigid_body_state(const RigidBodyCoordinates& y);

// The applied loads a RigidBodyModel evaluates, fixed at compile time so that a step pays only
// for the loads a scene has ("model only what a scene requires"; simulate chooses once per run):
//   none     no applied load and no gravity: the free body, which does no work;
//   fixed    gravity, world-fixed forces f_W and body-fixed torques tau_B: constant during a step and
//            independent of the attitude;
//   turning  any loads, also body-fixed forces f_B and world-fixed torques tau_W, which turn with the
//            body (the wrench then depends on the attitude at every derivative evaluation).
enum class LoadKind { none, fixed, turning };

// The least LoadKind that covers every load of `schedule` (at any time) under gravity g_W [m/s²].
LoadKind load_kind_of(const std::vector<AppliedLoad>& schedule, const Eigen::Vector3d& g_W);

// Calls f(std::integral_constant<LoadKind, kind>{}) with kind = load_kind_of(schedule, g_W): the
// single runtime switch, everything below it compiled per kind.
template <class F>
decltype(auto) with_load_kind(const std::vector<AppliedLoad>& schedule, const Eigen::Vector3d& g_W, F&& f) {
  switch (load_kind_of(schedule, g_W)) {
    case LoadKind::none: return f(std::integral_constant<LoadKind, LoadKind::none>{});
    case LoadKind::fixed: return f(std::integral_constant<LoadKind, LoadKind::fixed>{});
    case LoadKind::turning: return f(std::integral_constant<LoadKind, LoadKind::turning>{});
  }
  throw std::logic_error("with_load_kind: unknown LoadKind");
}

// The model of one rigid body (model_interface.hpp) with the Euler-equation form Euler and the
// applied loads of `kind` (LoadKind::turning, the default, takes any loads): the model simulate(body, ...) runs.
// Why it stays beside the one engine: the scene model's one-body layout of a rigid body (what simulate(scene, ...)
// runs) takes 1.10–1.11× its time in RKMK4 and 1.01–1.73× under loads (a work per element and the six impulses the
// momentum balance reads: 23 coordinates against 14), and is within 1.1× in the other cases
// (bench/bench_one_body_layout.cpp, docs/perf/scenes.md §4.1).
template <class Euler, LoadKind kind = LoadKind::turning>
class RigidBodyModel {
 public:
  using Coordinates = RigidBodyCoordinates;
  using Tangent = RigidBodyTangent;

  // g_W: uniform gravity [m/s²] in W (zero for none). Throws std::invalid_argument for gravity
  // under LoadKind::none.
  RigidBodyModel(double mass, const Euler& euler, const Eigen::Vector3d& g_W = Eigen::Vector3d::Zero())
      : mass_(mass), inverse_mass_(1.0 / mass), euler_(euler), g_W_(g_W) {
    set_loads(ComLoads{});
  }

  // Loads held constant until the next call (see loads.hpp for the time discretisation). Throws
  // std::invalid_argument for loads that `kind` does not cover (see LoadKind).
  void set_loads(const ComLoads& loads) {
    if constexpr (kind != LoadKind::turning) {
      if (!(loads.f_B.isZero(0.0) && loads.tau_W.isZero(0.0))) {
        throw std::invalid_argument("loads: expected no body-fixed force and no world-fixed torque (LoadKind::none or fixed), got f_B = " +
                                    format_value(loads.f_B.transpose()) + ", tau_W = " + format_value(loads.tau_W.transpose()));
      }
    }
    if constexpr (kind == LoadKind::none) {
      if (!(loads.f_W.isZero(0.0) && loads.tau_B.isZero(0.0) && g_W_.isZero(0.0))) {
        throw std::invalid_argument("loads: expected no loads and no gravity (LoadKind::none), got f_W = " +
                                    format_value(loads.f_W.transpose()) + ", tau_B = " + format_value(loads.tau_B.transpose()) +
                                    ", g_W = " + format_value(g_W_.transpose()));
      }
    }
    loads_ = loads;
    f_fixed_W_ = loads.f_W + mass_ * g_W_;
    turning_loads_ = !(loads.f_B.isZero(0.0) && loads.tau_W.isZero(0.0));
  }
  const Euler& euler() const { return euler_; }
  double mass() const { return mass_; }

  // The members below read and write y element by element (three_at, scalar stores): Eigen's packet
  // copies of segments would reload, as one 2-wide load, values just stored one by one by the
  // previous stage (a store-forwarding stall on the critical path; see euler_equations.hpp).
  RIGIDDYN_ALWAYS_INLINE void rate(const Coordinates& y, Coordinates& dy) const {
    const Eigen::Vector3d v = three_at(y, 7), w = three_at(y, 10);
    Eigen::Vector3d f_W, tau_B;
    wrench(y, f_W, tau_B);
    const Eigen::Vector3d alpha_B = euler_.angular_acceleration(w, tau_B);
    for (int i = 0; i < 3; ++i) dy[i] = v[i], dy[7 + i] = inverse_mass_ * f_W[i], dy[10 + i] = alpha_B[i];
    quat_rate_body(y.data() + 3, w, dy.data() + 3);  // q̇ = ½ q ⊗ (ω_B, 0)
    dy(13) = power(f_W, tau_B, v, w);
  }

  // q ← q / |q| (written out, so3/quaternion_kernels.hpp: Eigen's normalize() is not always inlined)
  RIGIDDYN_ALWAYS_INLINE static void project(Coordinates& y) { normalise_quaternion(y.data() + 3); }

  RIGIDDYN_ALWAYS_INLINE void velocity(const Coordinates& y, Tangent& xi) const {
    const Eigen::Vector3d v = three_at(y, 7), w = three_at(y, 10);
    Eigen::Vector3d f_W, tau_B;
    wrench(y, f_W, tau_B);
    const Eigen::Vector3d alpha_B = euler_.angular_acceleration(w, tau_B);
    for (int i = 0; i < 3; ++i) xi[i] = v[i], xi[3 + i] = w[i], xi[6 + i] = inverse_mass_ * f_W[i], xi[9 + i] = alpha_B[i];
    xi[12] = power(f_W, tau_B, v, w);
  }

  // y ⊕ Θ: vector parts added, q ← q ⊗ exp(Θ_rot)
  RIGIDDYN_ALWAYS_INLINE static void retract(const Coordinates& y, const Tangent& theta, Coordinates& out) {
    out = translated(y, theta);
    times_exp(y.data() + 3, three_at(theta, 3), out.data() + 3);
  }

  // ξ(y ⊕ Θ). Without body-fixed forces or world-fixed torques ξ does not read the attitude, so
  // the exponential of the stage attitude is skipped (a torque-free body, gravity, world forces).
  RIGIDDYN_ALWAYS_INLINE void velocity_at(const Coordinates& y, const Tangent& theta, Tangent& xi) const {
    Coordinates stage;
    if constexpr (kind == LoadKind::turning) {
      if (turning_loads_) {
        retract(y, theta, stage);
        return velocity(stage, xi);
      }
    }
    stage = translated(y, theta);
    velocity(stage, xi);
  }

  // ω ← dexp⁻¹_{−Θ} ω for the attitude part (so3/dexp_inv.hpp), identity elsewhere
  RIGIDDYN_ALWAYS_INLINE static void dexp_inv(const Tangent& theta, Tangent& xi) { dexp_inv_body(theta.data() + 3, xi.data() + 3); }

  RIGIDDYN_ALWAYS_INLINE void kick(Coordinates& y, double h) const {
    Eigen::Vector3d f_W, tau_B;
    wrench(y, f_W, tau_B);
    const Eigen::Vector3d w = euler_.explicit_gyroscopic_kick(three_at(y, 10), tau_B, h);
    for (int i = 0; i < 3; ++i) y[7 + i] += (h * inverse_mass_) * f_W[i], y[10 + i] = w[i];
  }

  RIGIDDYN_ALWAYS_INLINE void kick_implicit_gyroscopic(Coordinates& y, double h) const {
    Eigen::Vector3d f_W, tau_B;
    wrench(y, f_W, tau_B);
    const Eigen::Vector3d w = euler_.implicit_gyroscopic_kick(three_at(y, 10), tau_B, h);
    for (int i = 0; i < 3; ++i) y[7 + i] += (h * inverse_mass_) * f_W[i], y[10 + i] = w[i];
  }

  // p += h v, q ← q ⊗ exp(h ω_B) (exact for constant ω), work += h × power at the current velocities
  RIGIDDYN_ALWAYS_INLINE void drift(Coordinates& y, double h) const {
    const Eigen::Vector3d v = three_at(y, 7), w = three_at(y, 10);
    Eigen::Vector3d f_W, tau_B;
    wrench(y, f_W, tau_B);
    y(13) += h * power(f_W, tau_B, v, w);
    for (int i = 0; i < 3; ++i) y[i] += h * v[i];
    const double q[4] = {y[3], y[4], y[5], y[6]};
    times_exp(q, Eigen::Vector3d(h * w[0], h * w[1], h * w[2]), y.data() + 3);
    project(y);
  }

  // the loads do not depend on the velocities: two kicks are one (simulate/run_loop.hpp, merged_steps)
  static constexpr bool kicks_merge() { return true; }
  // The exact flow of the loads part over h [s] at the current attitude (no gyroscopic term):
  // v += h f_W/m, ω += h I⁻¹ n_B, and the work += h (f_W·v̄ + n_B·ω̄) with v̄, ω̄ the mean velocities
  // (exact: v and ω are linear in t in this flow). One derivative evaluation (ξ at ω = 0 is
  // (v, 0, f_W/m, I⁻¹ n_B, ·)); none for LoadKind::none, where the flow is the identity. Returns
  // |Δω_B| = |h I⁻¹ n_B| [rad/s].
  double loads_kick(Coordinates& y, double h) const {
    if constexpr (kind == LoadKind::none) {
      return 0.0;
    } else {
      Coordinates still = y;
      still.template segment<3>(10).setZero();
      Tangent xi;
      velocity(still, xi);
      const Eigen::Vector3d dv = h * xi.template segment<3>(6), dw = h * xi.template segment<3>(9);
      const Eigen::Vector3d v_mean = y.template segment<3>(7) + 0.5 * dv, w_mean = y.template segment<3>(10) + 0.5 * dw;
      y(13) += mass_ * dv.dot(v_mean) + euler_.momentum(dw).dot(w_mean);
      y.template segment<3>(7) += dv;
      y.template segment<3>(10) += dw;
      return dw.norm();
    }
  }

  // The free part over h [s]: p += h v, then the attitude and ω_B by the free rotation Rotation
  // (integrators/free_flow_tags.hpp): the DLM splitting or the exact Euler–Poinsot flow of this body.
  template <class Rotation>
  void free_flow(Coordinates& y, double h) const {
    y.template segment<3>(0) += h * y.template segment<3>(7);
    free_rotation(Rotation{}, y.data() + 3, y.data() + 10, h);
  }

  // The implicit midpoint rule's hook (integrators/implicit_midpoint.hpp): Newton on the mean angular
  // velocity ω̄ with the Jacobian of Euler's equations (gyroscopic_jacobian, τ = h/2; the residual
  // multiplied by I), v̄ by the fixed point (the force does not depend on v), the attitude by the
  // Cayley map (unit |q| exactly). Returns true if the iteration converged within max_iterations.
  bool implicit_midpoint_step(Coordinates& y, double h) const {
    using namespace implicit_midpoint_solver;
    const Eigen::Matrix3d I = inertia_matrix(euler_);
    const Eigen::Quaterniond q0(Eigen::Vector4d(y.template segment<4>(3)));
    const Eigen::Vector3d v0 = y.template segment<3>(7), w0 = y.template segment<3>(10);
    Eigen::Vector3d w_bar = w0, v_bar = v0;
    Coordinates mid = y;  // ȳ = (y0 + y1)/2
    double power = 0.0;
    bool converged = false;
    for (int k = 0; k < max_iterations && !converged; ++k) {
      const Eigen::Quaterniond q1 = q0 * midpoint_rotation(h * w_bar);
      mid.template segment<4>(3) = 0.5 * (q0.coeffs() + q1.coeffs());
      mid.template segment<3>(7) = v_bar;
      mid.template segment<3>(10) = w_bar;
      Tangent xi;
      velocity(mid, xi);
      power = xi(12);
      const Eigen::Vector3d r_w = w_bar - w0 - 0.5 * h * xi.template segment<3>(9);
      const Eigen::Vector3d r_v = v_bar - v0 - 0.5 * h * xi.template segment<3>(6);
      const Eigen::Vector3d I_r_w = times_3x3(I, r_w);
      const Eigen::Matrix3d J = gyroscopic_jacobian(I, w_bar, times_3x3(I, w_bar), 0.5 * h);
      const Eigen::Vector3d dw = solve_3x3(J.row(0), J.row(1), J.row(2), I_r_w);
      w_bar -= dw;
      v_bar -= r_v;
      const bool w_done = dw.norm() <= tolerance * (w_bar.norm() + h * xi.template segment<3>(9).norm());
      const bool v_done = r_v.norm() <= tolerance * (v_bar.norm() + h * xi.template segment<3>(6).norm());
      converged = w_done && v_done;
    }
    y.template segment<3>(0) += h * v_bar;
    y.template segment<4>(3) = (q0 * midpoint_rotation(h * w_bar)).normalized().coeffs();
    y.template segment<3>(7) = 2.0 * v_bar - v0;
    y.template segment<3>(10) = 2.0 * w_bar - w0;
    y(13) += h * power;
    return converged;
  }

  RecordedState record(const Coordinates& y) const {
    RecordedState r;
    r.p_W = y.segment<3>(0);
    r.q_WB = Eigen::Quaterniond(y.segment<4>(3));
    r.v_W = y.segment<3>(7);
    r.w_B = y.segment<3>(10);
    const Eigen::Vector3d h_B = euler_.momentum(r.w_B);
    r.kinetic_energy = 0.5 * mass_ * r.v_W.squaredNorm() + 0.5 * r.w_B.dot(h_B);
    r.potential_energy = -mass_ * g_W_.dot(r.p_W);
    r.angular_momentum_norm = h_B.norm();
    r.work = y(13);
    return r;
  }

 private:
  // total force in W (gravity included) and torque in B at the attitude q of y (unit up to the
  // method's error; q is read only under LoadKind::turning, when loads turn with the body)
  RIGIDDYN_ALWAYS_INLINE void wrench([[maybe_unused]] const Coordinates& y, Eigen::Vector3d& f_W, Eigen::Vector3d& tau_B) const {
    if constexpr (kind == LoadKind::none) {
      for (int i = 0; i < 3; ++i) f_W[i] = 0.0, tau_B[i] = 0.0;
    } else {
      for (int i = 0; i < 3; ++i) f_W[i] = f_fixed_W_[i], tau_B[i] = loads_.tau_B[i];
    }
    if constexpr (kind == LoadKind::turning) {
      if (turning_loads_) {
        Eigen::Quaterniond u(y[6], y[3], y[4], y[5]);
        u.coeffs() *= 1.0 / u.coeffs().norm();
        f_W += u * loads_.f_B;
        tau_B += u.conjugate() * loads_.tau_W;
      }
    }
  }

  // the free rotation of the attitude q (x, y, z, w) and ω_B over h, per rotation flow
  template <bool normalise>
  RIGIDDYN_ALWAYS_INLINE void free_rotation(DlmRotation<normalise>, double* q, double* w, double h) const {
    dlm_free_rotation<normalise>(euler_, q, w, h);
  }
  RIGIDDYN_ALWAYS_INLINE void free_rotation(ExactRotation, double* q, double* w, double h) const {
    if (!free_rotation_) free_rotation_.emplace(inertia_matrix(euler_));
    exact_free_rotation(*free_rotation_, q, w, h);
  }

  // (x[i], x[i + 1], x[i + 2]) by scalar loads
  template <class Vector>
  RIGIDDYN_ALWAYS_INLINE static Eigen::Vector3d three_at(const Vector& x, int i) {
    return Eigen::Vector3d(x[i], x[i + 1], x[i + 2]);
  }

  // y with its vector parts moved by Θ and its attitude left as it is
  RIGIDDYN_ALWAYS_INLINE static Coordinates translated(const Coordinates& y, const Tangent& theta) {
    Coordinates out;
    for (int i = 0; i < 3; ++i) out[i] = y[i] + theta[i];
    for (int i = 3; i < 7; ++i) out[i] = y[i];
    for (int i = 7; i < 14; ++i) out[i] = y[i] + theta[i - 1];
    return out;
  }

  // dW/dt = f_W · v_W + tau_B · ω_B [W] (Craig, "Rigid Body Dynamics" slides, power of a force at G and a torque)
  RIGIDDYN_ALWAYS_INLINE double power(const Eigen::Vector3d& f_W, const Eigen::Vector3d& tau_B, const Eigen::Vector3d& v,
                                      const Eigen::Vector3d& w) const {
    if constexpr (kind == LoadKind::none) return 0.0;  // a free body does no work and pays nothing for it
    return f_W[0] * v[0] + f_W[1] * v[1] + f_W[2] * v[2] + tau_B[0] * w[0] + tau_B[1] * w[1] + tau_B[2] * w[2];
  }

  double mass_;
  double inverse_mass_;
  Euler euler_;
  Eigen::Vector3d g_W_;
  ComLoads loads_;
  Eigen::Vector3d f_fixed_W_;  // f_W + m g_W
  bool turning_loads_;         // f_B or tau_W non-zero (only LoadKind::turning reads it)
  // The closed-form free rotation of this body's inertia, its principal frame computed once per model on
  // the first exact free flow (so that a model for any other method, e.g. step()'s, does not pay the
  // eigen-decomposition). Filled from a const member: a model is stepped by one thread at a time (simulate
  // and step each build their own, as every model carries its step's loads).
  mutable std::optional<FreeRotationFlow> free_rotation_;
};

}  // namespace rigiddyn
