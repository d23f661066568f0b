// OneBodySceneModel<Slot, elements>: the scene model (scene_model.hpp) compiled for a scene of one body of the kind
// Slot (scene/kinds/, at FirstPlace) under the elements `elements` says (OneBodyElements: none; one UniformGravity;
// at most one UniformGravity and one ScheduledLoads), with fixed-size coordinates.
//
// Coordinates y: the body's block (its kind's layout), t [s], then, with loads, the work of the gravity and of the
// loads [J] (a slot each, zero for the element the scene does not declare) and, for a free body, the impulses J_W (3)
// [N s] and K_W (3) [N m s]; ξ in the same order. A body held by a pivot or a plane integrates no impulse: the
// constraint's reaction is an external force whose impulse no model integrates, so its momentum balance is not
// applicable (and its records carry none).
// Under uniform gravity alone nothing is integrated but the motion: the work and the impulses are exact from the
// records (Craig, work of a constant force; impulse–momentum): W = V(t0) − V(t) (the pivot or the plane does no
// work), J_W = m g (t − t0) and, about W's origin, K_W = p × m v − p0 × m v0 (d(p × m v)/dt = p × m g for one body,
// and gravity has no moment about its centre of mass), so that the records carry the same balances at the cost of
// the motion alone.
// Every member runs the generic model's code in the generic model's order: the same kind slot and the same terms
// (their one-body form, add_wrench, which their add_wrenches applies to each body). A run on this layout moves the
// body bitwise as the generic model's run of the same scene does (a test holds it to that, but for the implicit
// midpoint's convergence test, which takes the norm of a shorter vector), while the fold over kinds, the visits over
// elements and the body's place in y are resolved at compile time and the kinematics and wrench of an evaluation are
// locals: the integrator's stages stay in registers.
#pragma once
#include "rigiddyn/always_inline.hpp"
#include "rigiddyn/scene/elements/scheduled_loads.hpp"
#include "rigiddyn/scene/elements/uniform_gravity.hpp"
#include "rigiddyn/scene/kinds/kind_list.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <vector>

namespace rigiddyn {

namespace detail {

// The kinds a OneBodySceneModel carries, at the first place (body_slot.hpp FirstPlace)
using FirstSlots =
    std::tuple<std::vector<ParticleSlot<FirstPlace>>, std::vector<PlanarSlot<FirstPlace>>,
               std::vector<RigidSlot<SphericalEuler, FirstPlace>>, std::vector<RigidSlot<PrincipalEuler, FirstPlace>>,
               std::vector<RigidSlot<FullEuler, FirstPlace>>, std::vector<PivotedSlot<SphericalEuler, FirstPlace>>,
               std::vector<PivotedSlot<PrincipalEuler, FirstPlace>>, std::vector<PivotedSlot<FullEuler, FirstPlace>>,
               std::vector<PivotedPlanarSlot<FirstPlace>>>;

// f(the slot of `body` at the first place): its kind's add_slot, of the slot type its inertia chooses
template <class Kind, class F>
void with_first_slot(const Kind& body, F&& f) {
  FirstSlots slots;
  Eigen::Index y = 0, xi = 0;
  add_slot(slots, 0, body, y, xi);
  const auto call = [&](const auto& group) {
    if constexpr (std::is_same_v<typename std::decay_t<decltype(group)>::value_type::kind, Kind>) {
      if (!group.empty()) f(group.front());
    }
  };
  std::apply([&](const auto&... group) { (call(group), ...); }, slots);
}

}  // namespace detail

// The elements of a one-body scene its layout carries
enum class OneBodyElements {
  none,               // no element
  gravity,            // one UniformGravity: its work and impulses exact from the records
  gravity_and_loads,  // at most one UniformGravity and one ScheduledLoads: their works and impulses integrated
};

template <class Slot, OneBodyElements elements>
class OneBodySceneModel {
  static constexpr bool free_body = !detail::is_constrained<Slot>::value;
  static constexpr bool loaded = elements != OneBodyElements::none;
  static constexpr bool exact_gravity = elements == OneBodyElements::gravity;
  static constexpr int t_y = static_cast<int>(Slot::y_size), t_xi = static_cast<int>(Slot::xi_size);
  static constexpr bool integrated = elements == OneBodyElements::gravity_and_loads;  // works and impulses in y
  static constexpr int work_size = integrated ? 2 : 0;  // the gravity's, then the loads'
  static constexpr int impulse_size = integrated && free_body ? 6 : 0;
  static constexpr int impulse_y = t_y + 1 + work_size, impulse_xi = t_xi + 1 + work_size;

  // One evaluation's kinematics, wrench and powers [W] (the gravity's, the loads'); its construction inlined, so that
  // the fields the evaluation never reads are never written (an out-of-line constructor writes all 30 of them)
  struct Evaluation {
    RIGIDDYN_ALWAYS_INLINE Evaluation() {}
    BodyKinematics k;
    BodyWrench wrench;
    double power[2] = {0.0, 0.0};
  };

 public:
  using Coordinates = Eigen::Matrix<double, impulse_y + impulse_size, 1>;
  using Tangent = Eigen::Matrix<double, impulse_xi + impulse_size, 1>;

  // The body's slot (detail::with_first_slot) and mass m [kg]; the compiled gravity and loads on it (those `elements`
  // allows) and their indices among the scene's elements (element_count() of them: those present).
  OneBodySceneModel(const Slot& slot, double mass, std::optional<UniformGravityTerm> gravity, int gravity_element,
                    std::optional<ScheduledLoadsTerm> loads, int loads_element)
      : slot_(slot), mass_(mass), gravity_(std::move(gravity)), loads_(std::move(loads)) {
    static_assert(!Slot::has_mass_flow, "a body with a mass flow runs on the generic model");
    if ((exact_gravity && (!gravity_ || loads_)) || (!loaded && (gravity_ || loads_))) {
      throw std::logic_error("a one-body layout given other elements than its own");
    }
    if (gravity_) column_[gravity_element] = 0;
    if (loads_) {
      column_[loads_element] = 1;
      turns_vectors_ = loads_->piece_turns_vectors();
    }
    element_count_ = (gravity_ ? 1 : 0) + (loads_ ? 1 : 0);
  }

  static constexpr Eigen::Index coordinate_count() { return Coordinates::RowsAtCompileTime; }
  static constexpr Eigen::Index tangent_count() { return Tangent::RowsAtCompileTime; }
  static constexpr Eigen::Index time_index() { return t_y; }
  static constexpr bool has_mass_flow() { return false; }
  // without scheduled loads nothing switches: the runs compile no split step (run_loop.hpp switches_never)
  static constexpr bool switches_never() { return !integrated; }
  static constexpr std::size_t body_count() { return 1; }
  std::size_t element_count() const { return element_count_; }

  // As SceneModel::set_time: the loads of the piece at t [s], and whether its evaluations need R_WB
  void set_time(double t) {
    if (loads_) {
      loads_->set_time(t);
      turns_vectors_ = loads_->piece_turns_vectors();
    }
  }

  // ẏ (SceneModel::rate)
  RIGIDDYN_ALWAYS_INLINE void rate(const Coordinates& y, Coordinates& dy) const {
    Evaluation e;
    evaluate(y, e);
    slot_.rate(y.data(), clock_at(y), e.k, e.wrench, dy.data());
    extra_rates(e, dy.data() + t_y);
  }

  // the attitude q ← q / |q|
  RIGIDDYN_ALWAYS_INLINE void project(Coordinates& y) const { slot_.project(y.data()); }

  // As SceneModel::midpoint_newton: the body's ω̄ by a Newton step and its q̄ exactly in the implicit midpoint's fixed
  // point (a kind without an attitude and Euler's gyroscopic term: nothing)
  RIGIDDYN_ALWAYS_INLINE void midpoint_newton(const Coordinates& y0, const Coordinates& mid, Coordinates& next,
                                              double h) const {
    if constexpr (detail::has_midpoint_newton<Slot>::value) slot_.midpoint_newton(y0.data(), mid.data(), next.data(), h);
  }

  // ξ (SceneModel::velocity)
  RIGIDDYN_ALWAYS_INLINE void velocity(const Coordinates& y, Tangent& xi) const {
    Evaluation e;
    evaluate(y, e);
    slot_.velocity(y.data(), clock_at(y), e.k, e.wrench, xi.data());
    extra_rates(e, xi.data() + t_xi);
  }

  // y ⊕ Θ
  RIGIDDYN_ALWAYS_INLINE void retract(const Coordinates& y, const Tangent& theta, Coordinates& out) const {
    slot_.retract(y.data(), theta.data(), out.data());
    for (int i = 0; i < 1 + work_size + impulse_size; ++i) out[t_y + i] = y[t_y + i] + theta[t_xi + i];
  }

  // ξ(y ⊕ Θ); the stage's attitude is skipped where neither the kind's velocity nor a term reads it (as the
  // one-body models do: ξ is the same): a kind that reads its kinematics reads the attitude only through a force,
  // and there is none without an element
  RIGIDDYN_ALWAYS_INLINE void velocity_at(const Coordinates& y, const Tangent& theta, Tangent& xi) const {
    Coordinates stage;
    if constexpr (detail::has_retract_motion<Slot>::value && (!detail::reads_kinematics<Slot>::value || !loaded)) {
      if (!turns_vectors_) {
        slot_.retract_motion(y.data(), theta.data(), stage.data());
        for (int i = 0; i < 1 + work_size + impulse_size; ++i) stage[t_y + i] = y[t_y + i] + theta[t_xi + i];
        return velocity(stage, xi);
      }
    }
    retract(y, theta, stage);
    velocity(stage, xi);
  }

  // ω ← dexp⁻¹_{−Θ} ω of the attitude part
  RIGIDDYN_ALWAYS_INLINE void dexp_inv(const Tangent& theta, Tangent& xi) const { slot_.dexp_inv(theta.data(), xi.data()); }

  // velocities += h × accelerations at y, with the explicit or the implicit gyroscopic term (SceneModel::kick)
  RIGIDDYN_ALWAYS_INLINE void kick(Coordinates& y, double h) const {
    kick_with(y, h, [](const auto& euler, const auto& w, const auto& tau, double k) {
      return euler.explicit_gyroscopic_kick(w, tau, k);
    });
  }
  RIGIDDYN_ALWAYS_INLINE void kick_implicit_gyroscopic(Coordinates& y, double h) const {
    kick_with(y, h, [](const auto& euler, const auto& w, const auto& tau, double k) {
      return euler.implicit_gyroscopic_kick(w, tau, k);
    });
  }

  // works and impulses at y, then the position and attitude over h, t += h (SceneModel::drift)
  RIGIDDYN_ALWAYS_INLINE void drift(Coordinates& y, double h) const {
    Evaluation e;
    evaluate(y, e);
    for (int i = 0; i < work_size; ++i) y[t_y + 1 + i] += h * e.power[i];
    if constexpr (impulse_size > 0) add_impulses(e, y.data() + impulse_y, h);
    slot_.translate(y.data(), h);
    slot_.turn(y.data(), h);
    project(y);
    y[t_y] += h;
  }

  // the exact flow of the loads part over h [s] (SceneModel::loads_kick); returns |Δω_B| [rad/s]
  RIGIDDYN_ALWAYS_INLINE double loads_kick(Coordinates& y, double h) const {
    Evaluation e;
    fill_kinematics(y, e.k);
    BodyWrench parts[2];  // the gravity's and the loads'
    if constexpr (exact_gravity) {
      e.wrench.f_W += gravity_->force(mass_);
    } else if constexpr (loaded) {
      if (gravity_) gravity_->add_wrench(e.k, parts[0]);
      if (loads_) loads_->add_wrench(e.k, parts[1]);
      for (const BodyWrench& part : parts) e.wrench.f_W += part.f_W, e.wrench.tau_B += part.tau_B;
    }
    if constexpr (impulse_size > 0) add_impulses(e, y.data() + impulse_y, h);
    const detail::VelocityKicks<false> kicks(h, Eigen::Vector3d::Zero(), nullptr);
    const double kicked = slot_.loads_kick(y.data(), e.k, e.wrench, h, kicks);  // e.k then holds the mean velocities
    for (int i = 0; i < work_size; ++i) {
      const double work = parts[i].f_W.dot(e.k.v_W) + parts[i].tau_B.dot(e.k.w_B);
      y[t_y + 1 + i] += h * work;
    }
    return kicked;
  }

  // two loads_kick at the same positions, attitude and t are one (neither element reads the velocities)
  static constexpr bool kicks_merge() { return true; }

  // the free part over h [s] (SceneModel::free_flow)
  template <class Rotation>
  RIGIDDYN_ALWAYS_INLINE void free_flow(Coordinates& y, double h) const {
    slot_.translate(y.data(), h);
    slot_.template free_rotation<Rotation>(y.data(), h);
    y[t_y] += h;
  }

  // Appends the record of y at time t [s] to `out` (SceneModel::record)
  void record(const Coordinates& y, double t, SceneSimulation& out) const {
    Evaluation e;
    // a coarse run of the estimate records no power and no pivot reaction: the kinematics alone, no element's wrench
    if (out.estimate_records) {
      fill_kinematics(y, e.k, true);
    } else {
      evaluate(y, e, true);
    }
    const BodyKinematics& k = e.k;
    out.t.push_back(t);
    detail::RecordSums sums;
    Eigen::Vector3d momentum_O_W = Eigen::Vector3d::Zero(), reaction_W = Eigen::Vector3d::Zero();
    slot_.record(y.data(), k, e.wrench, sums, momentum_O_W, reaction_W);
    const Eigen::Index q_y = slot_.attitude_y();
    detail::append_body_record(k, q_y >= 0 ? y.data() + q_y : nullptr, momentum_O_W, reaction_W, out);  // as integrated
    double V = 0.0;  // the gravity's (the loads have no potential)
    if (gravity_) V += gravity_->potential(k);
    if constexpr (exact_gravity) {
      if (out.t.size() == 1) start_ = {t, k.p_W, k.m * k.v_W, V};  // the run's first record is its start
    }
    detail::append_record_sums(sums, V, out);
    if constexpr (exact_gravity) {
      out.work.push_back(start_.V - V);
    } else {
      for (std::size_t i = 0; i < element_count_; ++i) out.work.push_back(y[t_y + 1 + column_[i]]);
    }
    if (out.estimate_records) return;
    for (std::size_t i = 0; i < element_count_; ++i) out.power.push_back(e.power[column_[i]]);
    if constexpr (free_body) {  // a free body's impulses (zero without an element)
      std::array<double, 6> impulses{};
      if constexpr (impulse_size > 0) std::copy(y.data() + impulse_y, y.data() + impulse_y + 6, impulses.begin());
      if constexpr (exact_gravity) exact_gravity_impulses(t, k, impulses);
      append_values<3>(out.impulse_W, impulses.data());
      append_values<3>(out.angular_impulse_W, impulses.data() + 3);
    }
  }

  // y of the body's state (of its kind, checked by the caller) at time t [s], works and impulses 0
  Coordinates coordinates(const std::vector<BodyState>& states, double t) const {
    Coordinates y = Coordinates::Zero();
    slot_.coordinates(states[0], y.data());
    y[t_y] = t;
    return y;
  }

  // the body's state in y (its attitude as integrated)
  std::vector<BodyState> states(const Coordinates& y) const { return {slot_.state(y.data())}; }

 private:
  // t of y; no step start (it serves a mass flow's out-of-mass message, and none of the layout's kinds has one)
  detail::StepClock clock_at(const Coordinates& y) const { return {y[t_y], std::numeric_limits<double>::quiet_NaN()}; }

  // k from y as the elements see the body (SceneModel::fill_kinematics), with R_WB when the loads turn vectors:
  // nothing without an element where the kind's rate reads y alone, the attitude only where the loads or the kind
  // read it; all of it for a record (`all`)
  RIGIDDYN_ALWAYS_INLINE void fill_kinematics(const Coordinates& y, BodyKinematics& k, bool all = false) const {
    k.m = mass_;
    if constexpr ((!loaded || exact_gravity) && !detail::reads_kinematics<Slot>::value) {
      if (!all) return;
    }
    if constexpr (detail::has_motion_kinematics<Slot>::value) {
      if (!all && !turns_vectors_) return slot_.motion_kinematics(y.data(), clock_at(y), k);
    }
    slot_.kinematics(y.data(), clock_at(y), k);
    if constexpr (!detail::sets_rotation_matrices<Slot>::value) {
      if (turns_vectors_) k.R_WB = k.q_WB.toRotationMatrix();
    }
  }

  // e.k at y, e.wrench the sum of the elements' wrenches, e.power their powers (SceneModel::evaluate); exact gravity
  // alone needs neither the kinematics nor the power but in a record (`all`)
  RIGIDDYN_ALWAYS_INLINE void evaluate(const Coordinates& y, Evaluation& e, bool all = false) const {
    fill_kinematics(y, e.k, all);
    if constexpr (exact_gravity) {
      if (!all) {
        e.wrench.f_W += gravity_->force(mass_);
        return;
      }
    }
    if constexpr (loaded) {
      if (gravity_) e.power[0] = 0.0 + gravity_->add_wrench(e.k, e.wrench);  // 0 + P: the sum add_wrenches takes
      if (loads_) e.power[1] = loads_->add_wrench(e.k, e.wrench);
    }
  }

  // J_W = m g (t − t0) [N s] and K_W = p × m v − p0 × m v0 [N m s] of exact gravity alone at the record of time t [s]
  // and kinematics k (the top of this file)
  void exact_gravity_impulses(double t, const BodyKinematics& k, std::array<double, 6>& impulses) const {
    const Eigen::Vector3d J = (t - start_.t) * gravity_->force(mass_);
    const Eigen::Vector3d K = cross_3(k.p_W, k.m * k.v_W) - cross_3(start_.p_W, start_.L_W);
    for (int i = 0; i < 3; ++i) impulses[i] = J[i], impulses[3 + i] = K[i];
  }

  // The rates after the body's block, from out (t's place in ẏ or ξ): dt/dt = 1, the works' powers [W], the
  // impulses' rates (SceneModel::rate)
  RIGIDDYN_ALWAYS_INLINE void extra_rates(const Evaluation& e, double* out) const {
    out[0] = 1.0;
    for (int i = 0; i < work_size; ++i) out[1 + i] = e.power[i];
    if constexpr (impulse_size > 0) {
      for (int i = 0; i < 6; ++i) out[1 + work_size + i] = 0.0;
      add_impulses(e, out + 1 + work_size, 1.0);
    }
  }

  // out[0..2] += h f [N], out[3..5] += h (p × f + R_WB τ_B) [N m] (SceneModel::add_impulses)
  RIGIDDYN_ALWAYS_INLINE void add_impulses(const Evaluation& e, double* out, double h) const {
    detail::add_wrench_impulses(e.k, e.wrench, turns_vectors_, h, out);
  }

  template <class GyroscopicKick>
  RIGIDDYN_ALWAYS_INLINE void kick_with(Coordinates& y, double h, GyroscopicKick&& gyroscopic_kick) const {
    Evaluation e;
    evaluate(y, e);
    slot_.kick(y.data(), e.k, e.wrench, h, gyroscopic_kick);
  }

  Slot slot_;
  double mass_;
  std::optional<UniformGravityTerm> gravity_;
  std::optional<ScheduledLoadsTerm> loads_;
  std::array<int, 2> column_{};     // column_[e]: where element e's work is among the two (0 gravity, 1 loads)
  std::size_t element_count_ = 0;
  bool turns_vectors_ = false;      // the loads' current piece reads the attitude or gives a torque: the kinematics
                                    // carry R_WB (the generic model decides it once per run)
  // the run's start (its first record) under exact gravity: t0 [s], p0 [m], m v0 [kg m/s], V(t0) [J]
  struct Start {
    double t = 0.0;
    Eigen::Vector3d p_W = Eigen::Vector3d::Zero(), L_W = Eigen::Vector3d::Zero();
    double V = 0.0;
  };
  mutable Start start_;
};

}  // namespace rigiddyn
