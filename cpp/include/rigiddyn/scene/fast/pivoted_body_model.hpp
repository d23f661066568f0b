// PivotedBodyModel<Euler>: the fast model of ONE pivoted body (models/pivoted_body.hpp) in the inertial
// frame W under uniform gravity g_W and a piecewise-constant ScheduledLoads schedule (the fast path
// compile chooses for such a scene). Fixed-size coordinates, no allocation, no visit; the same members
// as SceneModel (scene/scene_model.hpp), so the run loop and every integrator take it unchanged.
//
// Coordinates y (10,): (q_WB xyzw 4, w_B 3, t, work of gravity, work of the loads) [-, rad/s, s, J, J].
// Tangent ξ (9,): (w_B 3, α_B 3, 1, power of gravity, power of the loads) [rad/s, rad/s², 1, W, W].
//
// Equations (the per-body kernels of pivoted_body.hpp, the one home of the pivoted Newton–Euler):
//   q̇ = ½ q ⊗ (ω_B, 0),  I_O α_B + ω × I_O ω = τ_O = τ_gravity + τ_loads,
//   τ_gravity = c × R_BW m g_W,  τ_loads = τ_B + R_BW τ_W + (c + r_B) × R_BW (f_W + R_WB f_B)
// (the loads' forces act at the body point C + r_B, point_B of the ScheduledLoads element, zero: at C).
// O does not move, so the reaction does no work and each load's power is τ_O·ω (= f·v_P + τ·ω).
// The free part of the splitting methods is the torque-free rotation about O: Euler–Poinsot with I_O
// (free_flow<DlmRotation/ExactRotation> on the Euler form of I_O).
// Why it stays beside the one engine: the heavy top's one-body layout (OneBodySceneModel of its PivotedSlot) matches
// it within 1.1× under gravity in every method, but takes 1.03–1.44× its time under loads and 1.24× in RKMK4 without
// an element (bench/bench_one_body_layout.cpp, docs/perf/scenes.md §4.1).
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/exact/free_body.hpp"
#include "rigiddyn/integrators/exact_flow_kick.hpp"
#include "rigiddyn/integrators/free_flow_tags.hpp"
#include "rigiddyn/integrators/implicit_midpoint.hpp"
#include "rigiddyn/integrators/splitting_dlm.hpp"
#include "rigiddyn/models/euler_equations.hpp"
#include "rigiddyn/models/loads.hpp"
#include "rigiddyn/models/pivoted_body.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/so3/dexp_inv.hpp"
#include "rigiddyn/so3/quaternion_kernels.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace rigiddyn {

template <class Euler>
class PivotedBodyModel {
 public:
  using Coordinates = Eigen::Matrix<double, 10, 1>;
  using Tangent = Eigen::Matrix<double, 9, 1>;

  // body: the pivoted body (Euler must be the form of its inertia_O, with_euler_form(PivotedBody));
  // g_W [m/s²]: uniform gravity (zero unless gravity_element >= 0); gravity_element: the index of the
  // UniformGravity element among the scene's element_count elements, or -1; loads: the schedule of the
  // ScheduledLoads element loads_element (or -1, loads empty), its forces at point_B [m] (in B, from C).
  // Throws std::invalid_argument naming the argument for an element index out of [-1, element_count) or
  // repeated, non-finite g_W, point_B or loads (check_loads), gravity without a gravity element, loads
  // without a loads element.
  PivotedBodyModel(const PivotedBody& body, const Eigen::Vector3d& g_W, int gravity_element,
                   const std::vector<AppliedLoad>& loads, int loads_element, std::size_t element_count,
                   const Eigen::Vector3d& point_B = Eigen::Vector3d::Zero())
      : mass_(body.mass()),
        c_(body.p_OC_B()),
        arm_(body.p_OC_B() + point_B),
        p_WO_(body.p_WO()),
        inertia_com_(body.inertia_com()),
        inertia_O_(body.inertia_O()),
        euler_(make_euler<Euler>(body.inertia_O())),
        weight_W_(body.mass() * g_W),
        gravity_element_(gravity_element),
        loads_element_(loads_element),
        element_count_(element_count),
        schedule_(loads) {
    const int n = static_cast<int>(element_count);
    const std::string indices = "-1 or an index in [0, " + std::to_string(n) + ")";
    if (gravity_element < -1 || gravity_element >= n) throw_invalid("gravity_element", indices, gravity_element);
    if (loads_element < -1 || loads_element >= n) throw_invalid("loads_element", indices, loads_element);
    if (loads_element >= 0 && loads_element == gravity_element) {
      throw_invalid("loads_element", "another element than gravity_element", loads_element);
    }
    require_finite(g_W, "g_W");
    require_finite(point_B, "point_B");
    check_loads(loads);
    if (gravity_element < 0 && !g_W.isZero(0.0)) {
      throw_invalid("g_W", "zero without a gravity element (gravity_element = -1)", g_W.transpose().eval());
    }
    if (loads_element < 0 && !loads.empty()) {
      throw std::invalid_argument("loads: expected none without a loads element (loads_element = -1), got " +
                                  std::to_string(loads.size()) + " loads");
    }
    has_gravity_ = !weight_W_.isZero(0.0) && !c_.isZero(0.0);  // gravity at O itself exerts no torque
    set_time(0.0);
  }

  Eigen::Index coordinate_count() const { return 10; }
  Eigen::Index tangent_count() const { return 9; }
  static constexpr Eigen::Index time_index() { return 7; }  // where t [s] is in y
  // where element e's work is in y (the gravity slot or the loads slot; -1 for any other element, which a
  // scene on this fast path does not have)
  Eigen::Index work_index(std::size_t element) const {
    const int e = static_cast<int>(element);
    return e == gravity_element_ ? 8 : e == loads_element_ ? 9 : -1;
  }
  std::size_t body_count() const { return 1; }
  std::size_t element_count() const { return element_count_; }
  const Euler& euler() const { return euler_; }

  // The loads of the schedule's piece that contains t [s] (the run loop calls it at t0 and at each switch).
  void set_time(double t) {
    loads_ = loads_at(schedule_, t);
    force_B_ = !loads_.f_B.isZero(0.0);
    torque_W_ = !loads_.tau_W.isZero(0.0);
    has_loads_ = force_B_ || torque_W_ || !loads_.f_W.isZero(0.0) || !loads_.tau_B.isZero(0.0);
  }

  // ẏ = (½ q ⊗ (ω, 0), α_B, 1, τ_gravity·ω, τ_loads·ω)
  RIGIDDYN_ALWAYS_INLINE void rate(const Coordinates& y, Coordinates& dy) const {
    const Eigen::Vector3d w = three_at(y, 4);
    Eigen::Vector3d tau_O;
    double P_gravity, P_loads;
    torque_and_powers(y, w, tau_O, P_gravity, P_loads);
    const Eigen::Vector3d alpha = euler_.angular_acceleration(w, tau_O);
    quat_rate_body(y.data(), w, dy.data());
    for (int i = 0; i < 3; ++i) dy[4 + i] = alpha[i];
    dy[7] = 1.0;
    dy[8] = P_gravity;
    dy[9] = P_loads;
  }

  // q ← q / |q| (so3/quaternion_kernels.hpp)
  RIGIDDYN_ALWAYS_INLINE static void project(Coordinates& y) { normalise_quaternion(y.data()); }

  // In the implicit midpoint's fixed point (integrators/implicit_midpoint.hpp): ω̄ by the Newton step of the
  // gyroscopic term of I_O, q̄ exactly for that ω̄
  RIGIDDYN_ALWAYS_INLINE void midpoint_newton(const Coordinates& y0, const Coordinates& mid, Coordinates& next,
                                              double h) const {
    midpoint_newton_correction(euler_, mid.data() + 4, next.data() + 4, h);
    midpoint_attitude(y0.data(), next.data() + 4, h, next.data());
  }

  // ξ = (ω, α, 1, powers)
  RIGIDDYN_ALWAYS_INLINE void velocity(const Coordinates& y, Tangent& xi) const {
    const Eigen::Vector3d w = three_at(y, 4);
    Eigen::Vector3d tau_O;
    double P_gravity, P_loads;
    torque_and_powers(y, w, tau_O, P_gravity, P_loads);
    const Eigen::Vector3d alpha = euler_.angular_acceleration(w, tau_O);
    for (int i = 0; i < 3; ++i) xi[i] = w[i], xi[3 + i] = alpha[i];
    xi[6] = 1.0;
    xi[7] = P_gravity;
    xi[8] = P_loads;
  }

  // y ⊕ Θ: q ← q ⊗ exp(Θ_rot), the rest added
  RIGIDDYN_ALWAYS_INLINE static void retract(const Coordinates& y, const Tangent& theta, Coordinates& out) {
    out = translated(y, theta);
    times_exp(y.data(), three_at(theta, 0), out.data());
  }

  // ξ(y ⊕ Θ); a torque-free body's ξ does not read the attitude, so its exponential is skipped
  RIGIDDYN_ALWAYS_INLINE void velocity_at(const Coordinates& y, const Tangent& theta, Tangent& xi) const {
    Coordinates stage;
    if (has_gravity_ || has_loads_) {
      retract(y, theta, stage);
    } else {
      stage = translated(y, theta);
    }
    velocity(stage, xi);
  }

  // ω ← dexp⁻¹_{−Θ} ω for the attitude part (so3/dexp_inv.hpp), identity elsewhere
  RIGIDDYN_ALWAYS_INLINE static void dexp_inv(const Tangent& theta, Tangent& xi) { dexp_inv_body(theta.data(), xi.data()); }

  // ω += h α at y (explicit gyroscopic term); attitude, t and work unchanged
  RIGIDDYN_ALWAYS_INLINE void kick(Coordinates& y, double h) const {
    const Eigen::Vector3d w = euler_.explicit_gyroscopic_kick(three_at(y, 4), torque_O(y), h);
    for (int i = 0; i < 3; ++i) y[4 + i] = w[i];
  }

  // the same with the implicit gyroscopic term (one Newton step, euler_equations.hpp)
  RIGIDDYN_ALWAYS_INLINE void kick_implicit_gyroscopic(Coordinates& y, double h) const {
    const Eigen::Vector3d w = euler_.implicit_gyroscopic_kick(three_at(y, 4), torque_O(y), h);
    for (int i = 0; i < 3; ++i) y[4 + i] = w[i];
  }

  // works += h × powers at y, then q ← q ⊗ exp(h ω) (exact for constant ω), t += h
  RIGIDDYN_ALWAYS_INLINE void drift(Coordinates& y, double h) const {
    const Eigen::Vector3d w = three_at(y, 4);
    Eigen::Vector3d tau_gravity, tau_loads;
    torques_O(unit_attitude(y), tau_gravity, tau_loads);
    y[8] += h * dot(tau_gravity, w);
    y[9] += h * dot(tau_loads, w);
    const double q[4] = {y[0], y[1], y[2], y[3]};
    times_exp(q, Eigen::Vector3d(h * w[0], h * w[1], h * w[2]), y.data());
    project(y);
    y[7] += h;
  }

  // gravity and the loads do not depend on ω: two kicks are one (simulate/run_loop.hpp, merged_steps)
  static constexpr bool kicks_merge() { return true; }
  // The exact flow of the loads part over h [s] at the frozen attitude: ω += h I_O⁻¹ τ_O (no gyroscopic
  // term), each work += h τ·ω̄ with ω̄ = ω + Δω/2 (exact: ω is linear in t in this flow). Returns |Δω| [rad/s].
  double loads_kick(Coordinates& y, double h) const {
    if (!(has_gravity_ || has_loads_)) return 0.0;
    Eigen::Vector3d tau_gravity, tau_loads;
    torques_O(unit_attitude(y), tau_gravity, tau_loads);
    const Eigen::Vector3d dw = h * euler_.angular_acceleration(Eigen::Vector3d::Zero(), sum(tau_gravity, tau_loads));
    const Eigen::Vector3d w_mean = three_at(y, 4) + 0.5 * dw;
    y[8] += h * dot(tau_gravity, w_mean);
    y[9] += h * dot(tau_loads, w_mean);
    for (int i = 0; i < 3; ++i) y[4 + i] += dw[i];
    return dw.norm();
  }

  // The free part over h [s]: the torque-free rotation about O (Euler–Poinsot with I_O) by the flow Rotation
  // (DlmRotation<normalise>: dlm_free_rotation; ExactRotation: the closed form of I_O), t += h; no work.
  template <class Rotation>
  void free_flow(Coordinates& y, double h) const {
    free_rotation(Rotation{}, y.data(), y.data() + 4, h);
    y[7] += h;
  }

  // Appends the record of y at time t [s] to `out` (scene_simulation.hpp): the body at its centre of mass
  // (p_W = p_WO + R c, v_W = R (ω × c)), T = ½ ω·I_O ω, V = −m g·p_W, the momenta (about W's origin: p_W × m
  // v_W + R I_C ω), the pivot's reaction, H_O = R I_O ω, the mass, each element's work and power.
  void record(const Coordinates& y, double t, SceneSimulation& out) const {
    const Eigen::Quaterniond q = unit_attitude(y);
    const Eigen::Vector3d w = three_at(y, 4);
    Eigen::Vector3d tau_gravity, tau_loads;
    torques_O(q, tau_gravity, tau_loads);
    const Eigen::Vector3d p_W = p_WO_ + q * c_, v_W = q * w.cross(c_);
    out.t.push_back(t);
    out.p_W.insert(out.p_W.end(), p_W.data(), p_W.data() + 3);
    out.q_WB.insert(out.q_WB.end(), y.data(), y.data() + 4);  // as integrated
    out.v_W.insert(out.v_W.end(), v_W.data(), v_W.data() + 3);
    out.w_B.insert(out.w_B.end(), w.data(), w.data() + 3);
    const double T = 0.5 * w.dot(euler_.momentum(w));
    const double V = gravity_element_ >= 0 ? -weight_W_.dot(p_W) : 0.0;
    out.kinetic_energy.push_back(T);
    out.potential_energy.push_back(V);
    out.total_energy.push_back(T + V);
    const Eigen::Vector3d L_W = mass_ * v_W, H_W = p_W.cross(L_W) + q * (inertia_com_ * w);
    out.linear_momentum_W.insert(out.linear_momentum_W.end(), L_W.data(), L_W.data() + 3);
    out.angular_momentum_W.insert(out.angular_momentum_W.end(), H_W.data(), H_W.data() + 3);
    const Eigen::Vector3d alpha = euler_.angular_acceleration(w, sum(tau_gravity, tau_loads));
    const Eigen::Vector3d R_W = pivot_reaction_W(mass_, c_, q, w, alpha, weight_W_ + loads_force_W(q));
    const Eigen::Vector3d H_O_W = q * euler_.momentum(w);
    out.pivot_reaction_W.insert(out.pivot_reaction_W.end(), R_W.data(), R_W.data() + 3);
    out.angular_momentum_O_W.insert(out.angular_momentum_O_W.end(), H_O_W.data(), H_O_W.data() + 3);
    out.mass.push_back(mass_);
    for (std::size_t e = 0; e < element_count_; ++e) {
      const Eigen::Index i = work_index(e);
      out.work.push_back(i < 0 ? 0.0 : y[i]);
      out.power.push_back(i == 8 ? dot(tau_gravity, w) : i == 9 ? dot(tau_loads, w) : 0.0);
    }
  }

  // The pivot's reaction on the body at y [N] in W (Newton for C: m a_C − the applied forces, gravity included).
  Eigen::Vector3d reaction_W(const Coordinates& y) const {
    const Eigen::Quaterniond q = unit_attitude(y);
    const Eigen::Vector3d w = three_at(y, 4);
    Eigen::Vector3d tau_gravity, tau_loads;
    torques_O(q, tau_gravity, tau_loads);
    const Eigen::Vector3d alpha = euler_.angular_acceleration(w, sum(tau_gravity, tau_loads));
    return pivot_reaction_W(mass_, c_, q, w, alpha, weight_W_ + loads_force_W(q));
  }

  // H_O = R_WB I_O ω [kg m²/s]: the angular momentum about O at y, in W.
  Eigen::Vector3d angular_momentum_O_W(const Coordinates& y) const { return unit_attitude(y) * euler_.momentum(three_at(y, 4)); }

  // y of the state (q_WB normalised by the caller's checks) at time t [s], works 0
  static Coordinates coordinates(const PivotedBodyState& state, double t) {
    Coordinates y = Coordinates::Zero();
    y.template segment<4>(0) = state.q_WB.coeffs();
    y.template segment<3>(4) = state.w_B;
    y[7] = t;
    return y;
  }
  // the same from the scene's body states (one, a PivotedBodyState, checked by the caller)
  static Coordinates coordinates(const std::vector<BodyState>& states, double t) {
    return coordinates(std::get<PivotedBodyState>(states[0]), t);
  }

  // The body's state in y (attitude as integrated)
  static PivotedBodyState state(const Coordinates& y) {
    PivotedBodyState s;
    s.q_WB.coeffs() = y.template segment<4>(0);
    s.w_B = y.template segment<3>(4);
    return s;
  }
  // the same as the scene's body states
  static std::vector<BodyState> states(const Coordinates& y) { return {BodyState(state(y))}; }

 private:
  // (x[i], x[i + 1], x[i + 2]) by scalar loads
  template <class Vector>
  RIGIDDYN_ALWAYS_INLINE static Eigen::Vector3d three_at(const Vector& x, int i) {
    return Eigen::Vector3d(x[i], x[i + 1], x[i + 2]);
  }
  RIGIDDYN_ALWAYS_INLINE static Eigen::Vector3d sum(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return Eigen::Vector3d(a[0] + b[0], a[1] + b[1], a[2] + b[2]);
  }
  RIGIDDYN_ALWAYS_INLINE static double dot(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }

  // the attitude of y normalised (as SceneModel's kinematics: the kernels take unit attitudes)
  RIGIDDYN_ALWAYS_INLINE static Eigen::Quaterniond unit_attitude(const Coordinates& y) {
    const double inverse_norm = 1.0 / std::sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2] + y[3] * y[3]);
    return Eigen::Quaterniond(inverse_norm * y[3], inverse_norm * y[0], inverse_norm * y[1], inverse_norm * y[2]);
  }

  // y with its vector parts moved by Θ and its attitude left as it is
  RIGIDDYN_ALWAYS_INLINE static Coordinates translated(const Coordinates& y, const Tangent& theta) {
    Coordinates out;
    for (int i = 0; i < 4; ++i) out[i] = y[i];
    for (int i = 4; i < 10; ++i) out[i] = y[i] + theta[i - 1];
    return out;
  }

  // the loads' resultant force in W at the attitude q: f_W + R f_B [N]
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d loads_force_W(const Eigen::Quaterniond& q) const {
    if (!force_B_) return loads_.f_W;
    return loads_.f_W + q * loads_.f_B;
  }

  // τ_gravity and τ_loads about O in B at the unit attitude q [N m] (pivoted_torque_O: gravity at C, the loads'
  // forces at C + r_B with their couples tau_B + R_BW tau_W)
  RIGIDDYN_ALWAYS_INLINE void torques_O(const Eigen::Quaterniond& q, Eigen::Vector3d& tau_gravity, Eigen::Vector3d& tau_loads) const {
    if (has_gravity_) {
      tau_gravity = pivoted_torque_O(c_, q, BodyWrench{weight_W_, Eigen::Vector3d::Zero()});
    } else {
      tau_gravity.setZero();
    }
    if (has_loads_) {
      tau_loads = loads_torque_O(q);
    } else {
      tau_loads.setZero();
    }
  }

  // τ_loads about O in B at the unit attitude q [N m]: the forces at C + r_B, the couples tau_B + R_BW tau_W
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d loads_torque_O(const Eigen::Quaterniond& q) const {
    const Eigen::Vector3d couple_B = torque_W_ ? Eigen::Vector3d(loads_.tau_B + rotate_to_body(q, loads_.tau_W)) : loads_.tau_B;
    return pivoted_torque_O(arm_, q, BodyWrench{loads_force_W(q), couple_B});
  }

  // τ_O = τ_gravity + τ_loads at y and the powers τ_gravity·ω, τ_loads·ω [W] (each part only if it acts)
  RIGIDDYN_ALWAYS_INLINE void torque_and_powers(const Coordinates& y, const Eigen::Vector3d& w, Eigen::Vector3d& tau_O,
                                                double& P_gravity, double& P_loads) const {
    P_gravity = 0.0, P_loads = 0.0;
    if (!(has_gravity_ || has_loads_)) {
      tau_O.setZero();
      return;
    }
    const Eigen::Quaterniond q = unit_attitude(y);
    if (has_gravity_) {
      tau_O = pivoted_torque_O(c_, q, BodyWrench{weight_W_, Eigen::Vector3d::Zero()});
      P_gravity = dot(tau_O, w);
    } else {
      tau_O.setZero();
    }
    if (has_loads_) {
      const Eigen::Vector3d tau_loads = loads_torque_O(q);
      P_loads = dot(tau_loads, w);
      tau_O = sum(tau_O, tau_loads);
    }
  }

  // τ_O at y
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d torque_O(const Coordinates& y) const {
    Eigen::Vector3d tau_O;
    double P_gravity, P_loads;
    torque_and_powers(y, three_at(y, 4), tau_O, P_gravity, P_loads);
    return tau_O;
  }

  // the torque-free rotation about O of the attitude q (x, y, z, w) and ω_B over h, per rotation flow
  template <bool normalise>
  RIGIDDYN_ALWAYS_INLINE void free_rotation(DlmRotation<normalise>, double* q, double* w, double h) const {
    dlm_free_rotation<normalise>(euler_, q, w, h);
  }
  RIGIDDYN_ALWAYS_INLINE void free_rotation(ExactRotation, double* q, double* w, double h) const {
    if (!free_rotation_) free_rotation_.emplace(inertia_O_);
    exact_free_rotation(*free_rotation_, q, w, h);
  }

  double mass_;
  Eigen::Vector3d c_;            // p_OC_B [m]
  Eigen::Vector3d arm_;          // c + point_B: the loads' point of application from O [m] in B
  Eigen::Vector3d p_WO_;         // [m]
  Eigen::Matrix3d inertia_com_;  // I_C [kg m²] in B (the angular momentum about W's origin)
  Eigen::Matrix3d inertia_O_;    // I_O [kg m²] in B (the exact free rotation)
  Euler euler_;                  // Euler's equations with I_O
  Eigen::Vector3d weight_W_;     // m g_W [N]
  int gravity_element_, loads_element_;
  std::size_t element_count_;
  std::vector<AppliedLoad> schedule_;
  ComLoads loads_;                // the loads of the current piece
  bool has_gravity_ = false;      // gravity exerts a torque about O (g ≠ 0 and c ≠ 0)
  bool has_loads_ = false, force_B_ = false, torque_W_ = false;  // the current piece: any load, f_B ≠ 0, τ_W ≠ 0
  // The closed-form free rotation of I_O, built on the first exact free flow (a model is stepped by one thread at a
  // time).
  mutable std::optional<FreeRotationFlow> free_rotation_;
};

}  // namespace rigiddyn
