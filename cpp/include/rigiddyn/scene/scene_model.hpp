// SceneModel: the integrator model (models/model_interface.hpp) of a compiled scene — any number of
// bodies of any kind and the force elements declared, nothing else.
//
// Coordinates y (Eigen::VectorXd), per body in the scene's order:
//   particle  (p_W 3, v_W 3)                        no attitude: a particle pays nothing for one
//   planar    (x, y, θ, v_x, v_y, ω)
//   rigid     (p_W 3, q_WB xyzw 4, v_W 3, w_B 3)
//   pivoted   (q_WB xyzw 4, w_B 3)                   pinned at O: the centre of mass follows the attitude
//   pivoted planar (θ, ω)
//   gyrostat  (p_W 3, q_WB xyzw 4, v_W 3, w_B 3, its N wheel speeds, its N motor works [J])
//   tree      (q nq, v nv) of the whole tree, at its first link's place (its links are consecutive bodies)
// and, right after its own, the mass m [kg] of a particle or rigid body with a MassFlow (scene/mass_flow.hpp;
// tangent ṁ); then t [s] (so that every method evaluates time-dependent forces at its own stage times), then one
// work slot per element [J] (its work since t0, integrated with the motion: dW_e/dt = P_e), then one mass-flow
// energy slot per body with a MassFlow, in the scene's order [J] (dE_b/dt = the mass-flow power below), then the
// impulses of all the elements since t0: linear J_W (3) [N s] and angular about W's origin K_W (3) [N m s], with
//   dJ_W/dt = Σ_b f_b,   dK_W/dt = Σ_b (p_b × f_b + R_WB,b τ_B,b)
// (the impulse–momentum principle: m v − m v0 = ∫ f dt, H_W − H_W0 = ∫ M_W dt for bodies free of constraints;
// Rigid-body notes §4.11, f = dp/dt (4.36); Craig, impulse–momentum). They are integrated with the motion
// exactly as the works are (the same stages, kicks and drifts), so that the momentum balances of the records
// close to the method's error. Internal elements (mutual gravity, a spring between two bodies) add equal and
// opposite wrenches: their net impulse is zero, and a scene of such elements alone (ElementTraits zero_net_wrench)
// keeps its impulses at 0, exactly, without summing them.
// Tangent ξ: per body (particle v_W, a_W; planar the 6 rates; rigid v_W, w_B, a_W, alpha_B; pivoted
// w_B, alpha_B; pivoted planar ω, α; gyrostat v_W, w_B, a_W, alpha_B, the wheels' accelerations, the motors'
// powers), then dt/dt = 1, then each element's power [W], then each mass-flow power [W], then the resultant force
// Σ f [N] and moment about W's origin [N m].
//
// The work–energy balance with a mass flow. T = ½ m |v|² + ½ ω·I ω changes with the mass as well as with the work:
// m v̇ = f and I ω̇ + ω × I ω = τ (mass_flow.hpp) give
//   dT/dt = Σ_e P_e + ½ ṁ |v|² + ½ ω·(dI/dt) ω,     dI/dt = ṁ dI/dm (I_C0 ṁ/m0 under InertiaRule::scaled),
// the last two terms the mass-flow power of the body: the kinetic energy, at the body's own velocity, of the
// mass that leaves (ṁ < 0) or joins it. Its integral, the mass-flow energy E_b, is integrated with the motion as
// the works are, so that T − T(0) = Σ_e W_e + Σ_b E_b holds to the method's error on every run. Where a method
// moves the masses alone (drift, free_flow, mass_part: v and ω fixed), E_b takes the exact change of T there,
// ½ Δm |v|² + ½ ω·(I(m + Δm) − I(m)) ω; the kicks keep the masses (no E_b), and the splittings then close the
// balance to round-off but for the free rotation's own energy error (none with ExactRotation).
// "W" is the scene frame: in a moving frame F the states are relative to F and the model is the same
// (the compiled fictitious terms, scene/elements/fictitious_forces.hpp, add the frame's forces).
//
// One evaluation: every body's kinematics (body_kinematics.hpp) from y, wrenches zeroed, each element
// adds its wrenches once (one std::visit per element: an element that is not declared does not exist),
// then Newton–Euler per body by its kind (a tree applies a UniformGravity on all its links itself, as its base's
// acceleration: leave_gravity_to). Each body kind is one file in scene/kinds/ (its layout, kinematics,
// Newton–Euler, retraction, kicks, free flow and record; body_slot.hpp lists the members); the model folds over
// the list of kinds (kinds/kind_list.hpp), the rigid and pivoted bodies grouped by Euler form (a sphere pays
// nothing for the gyroscopic term); the fold visits only the kinds present (for_each_slot). Scratch buffers are
// sized when the model is built: an evaluation allocates nothing (so a model is not shared between threads:
// each run copies its own).
#pragma once
#include "rigiddyn/integrators/free_flow_tags.hpp"
#include "rigiddyn/integrators/implicit_midpoint.hpp"
#include "rigiddyn/scene/elements/fictitious_forces.hpp"
#include "rigiddyn/scene/kinds/kind_list.hpp"
#include "rigiddyn/scene/mass_flow.hpp"
#include "rigiddyn/scene/scene.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace rigiddyn {

template <class F>
class CustomForceTerm;  // scene/custom_force.hpp

namespace detail {

// Whether a term or a body's slot is piecewise constant in time (it has set_time(t)).
template <class Term, class = void>
struct has_set_time : std::false_type {};
template <class Term>
struct has_set_time<Term, std::void_t<decltype(std::declval<Term&>().set_time(0.0))>> : std::true_type {};

// Whether a term takes a controller's command (command(value): MagneticDipole, ScheduledLoads; scene/controller.hpp).
template <class Term, class = void>
struct has_command : std::false_type {};
template <class Term>
struct has_command<Term, std::void_t<decltype(std::declval<Term&>().command(Eigen::Vector3d()))>> : std::true_type {};

// Whether a term takes a number commanded by a controller (command_scalar: a ReactionWheel's speed, a joint motor's
// force; scene/controller.hpp).
template <class Term, class = void>
struct has_scalar_command : std::false_type {};
template <class Term>
struct has_scalar_command<Term, std::void_t<decltype(std::declval<Term&>().command_scalar(0.0, 0.0, 0.0, 0.0))>>
    : std::true_type {};

// Whether a term hands the bodies' kinematics to a user's function (PythonForce, custom_force), which may read any
// q_WB: the tree slots then fill their links' quaternions at every evaluation (they leave them to the records
// otherwise: every other element reads R_WB).
template <class Term>
struct is_user_force : std::false_type {};
template <>
struct is_user_force<FunctionForceTerm> : std::true_type {};
template <class F>
struct is_user_force<CustomForceTerm<F>> : std::true_type {};

// Whether a term turns vectors between a body's B and W (reads R_WB, or gives a torque that the impulses turn to W):
// it declares reads_attitude or has_torque, or it takes a controller's command (which may turn it at run time).
template <class Term>
bool turns_vectors(const Term& term) {
  const ElementTraits t = term.traits();
  return t.reads_attitude || t.has_torque || has_command<Term>::value || has_scalar_command<Term>::value;
}

// Whether a body's slot records coordinates of its own (record_internal: the gyrostat's wheel speeds).
template <class Slot, class = void>
struct has_internal_record : std::false_type {};
template <class Slot>
struct has_internal_record<Slot, std::void_t<decltype(std::declval<const Slot&>().record_internal(
                                      static_cast<const double*>(nullptr), std::declval<SceneSimulation&>()))>>
    : std::true_type {};

// Whether a body's slot spans several bodies (a tree's links: states(y, first) writes each of their states).
template <class Slot, class = void>
struct spans_bodies : std::false_type {};
template <class Slot>
struct spans_bodies<Slot, std::void_t<decltype(std::declval<const Slot&>().states(static_cast<const double*>(nullptr),
                                                                                   static_cast<BodyState*>(nullptr)))>>
    : std::true_type {};

}  // namespace detail

// The model of a scene whose elements compile to the terms UniformGravityTerm … FunctionForceTerm and
// the user's Extra terms (CustomForceTerm<F>, scene/custom_force.hpp). SceneModel = BasicSceneModel<>.
template <class... Extra>
class BasicSceneModel {
 public:
  using Coordinates = Eigen::VectorXd;
  using Tangent = Eigen::VectorXd;
  using Term = typename TermsOf<Element, FrameOriginTerm, EulerForceTerm, CentrifugalTerm, CoriolisTerm, Extra...>::type;

  // The bodies (checked when they were built) and the compiled terms, in the scene's order.
  BasicSceneModel(const std::vector<Body>& bodies, std::vector<Term> terms)
      : BasicSceneModel(bodies, std::move(terms), {}, {}) {}

  // The same with the bodies' mass flows (empty, or one per body: nullopt for a constant mass; a flow on a
  // particle or a rigid body only, checked by compile) and their names (for the out-of-mass message).
  BasicSceneModel(const std::vector<Body>& bodies, std::vector<Term> terms,
                  const std::vector<std::optional<MassFlow>>& mass_flows, const std::vector<std::string>& body_names)
      : terms_(std::move(terms)) {
    Eigen::Index y = 0, xi = 0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const int b = static_cast<int>(i);
      if (i < mass_flows.size() && mass_flows[i]) {
        const detail::MassCoordinate mass{0, 0, *mass_flows[i], 0.0, "mass_flows[" + std::to_string(b) + "]",
                                          i < body_names.size() ? body_names[i] : "body" + std::to_string(i),
                                          static_cast<Eigen::Index>(energy_body_.size())};
        energy_body_.push_back(b);
        detail::add_body_mass_slot(slots_, b, bodies[i], mass, y, xi);
      } else {
        detail::add_body_slot(slots_, b, bodies[i], y, xi);
      }
    }
    t_y_ = y, t_xi_ = xi;
    find_present_groups(std::make_index_sequence<group_count>());
    const auto extra = static_cast<Eigen::Index>(terms_.size());
    std::apply([&](auto&... group) { (place_energies(group, extra), ...); }, slots_);
    kinematics_.resize(bodies.size());
    wrenches_.resize(bodies.size());
    power_.resize(terms_.size());
    find_term_runs();
    element_wrenches_.assign(terms_.size(), std::vector<BodyWrench>(bodies.size()));
    q_y_.assign(bodies.size(), -1);
    for_each_slot([&](const auto& s) { q_y_[s.body] = s.attitude_y(); });
    for (std::size_t b = 0; b < bodies.size(); ++b) kinematics_[b].m = mass_of(bodies[b]);  // constant masses: set once
    reaction_W_.assign(bodies.size(), Eigen::Vector3d::Zero());
    momentum_O_W_.assign(bodies.size(), Eigen::Vector3d::Zero());
    find_coriolis_terms(bodies);
    wheel_count_ = rigiddyn::wheel_count(bodies);
    stage_.resize(coordinate_count());
    mid_.resize(coordinate_count()), next_.resize(coordinate_count()), rate_.resize(coordinate_count());
    if (!std::get<std::vector<detail::TreeSlot>>(slots_).empty()) {
      for (Coordinates* v : {&residual_, &last_residual_, &last_g_}) v->resize(coordinate_count());
      delta_f_.resize(coordinate_count(), anderson_depth), delta_g_.resize(coordinate_count(), anderson_depth);
    }
    kicks_merge_ = !has_mass_flow() && std::none_of(terms_.begin(), terms_.end(), [](const Term& term) {
      return std::visit([](const auto& e) { return e.traits().velocity_dependent; }, term);
    });
    turns_vectors_ = std::any_of(terms_.begin(), terms_.end(), [](const Term& term) {
      return std::visit([](const auto& e) { return detail::turns_vectors(e); }, term);
    });
    integrates_impulses_ = std::any_of(terms_.begin(), terms_.end(), [](const Term& term) {
      return std::visit([](const auto& e) { return !e.traits().zero_net_wrench; }, term);
    });
    const bool user_force = std::any_of(terms_.begin(), terms_.end(), [](const Term& term) {
      return std::visit([](const auto& e) { return detail::is_user_force<std::decay_t<decltype(e)>>::value; }, term);
    });
    for (detail::TreeSlot& tree : std::get<std::vector<detail::TreeSlot>>(slots_)) {
      tree.fill_quaternions = user_force;
      leave_gravity_to(tree);
    }
  }

  Eigen::Index coordinate_count() const { return t_y_ + 1 + extra_count(); }
  Eigen::Index tangent_count() const { return t_xi_ + 1 + extra_count(); }
  Eigen::Index time_index() const { return t_y_; }  // where t [s] is in y
  Eigen::Index work_index(std::size_t element) const { return t_y_ + 1 + static_cast<Eigen::Index>(element); }
  // True when a body's mass changes (a MassFlow): then the model has a mass part (mass_part) for the splittings'
  // three-part form (integrators/yoshida4.hpp)
  bool has_mass_flow() const { return !energy_body_.empty(); }
  std::size_t body_count() const { return kinematics_.size(); }
  std::size_t wheel_count() const { return wheel_count_; }  // the gyrostats' wheels (SceneSimulation::wheel_speed)
  std::size_t element_count() const { return terms_.size(); }
  const std::vector<Term>& terms() const { return terms_; }

  // Sets every piecewise-constant element (a term with set_time: ScheduledLoads, ReactionWheel) and body input (a
  // gyrostat's motor torques) to its piece at time t [s]: called by the run loop at t0 and at each switch time,
  // never per evaluation.
  void set_time(double t) {
    step_start_ = t;
    std::apply([t](auto&... group) { (set_slots_time(group, t), ...); }, slots_);
    for (Term& term : terms_) {
      std::visit(
          [t](auto& e) {
            if constexpr (detail::has_set_time<std::decay_t<decltype(e)>>::value) e.set_time(t);
          },
          term);
    }
  }

  // A controller's commands (scene/controller.hpp), held until the next set_time: the motor torques u [N m] of
  // every gyrostat wheel, in the scene's order (wheel_count() of them); element e's input (command_element:
  // MagneticDipole's m_B [A m²], ScheduledLoads' force f_B [N] in B), when it takes one (takes_command).
  void command_wheel_torques(const std::vector<double>& u) {
    std::size_t i = 0;
    for (auto& s : std::get<std::vector<detail::GyrostatSlot>>(slots_)) {
      for (double& u_k : s.u) u_k = u[i++];
    }
  }
  bool takes_command(std::size_t e) const {
    return std::visit([](const auto& term) { return detail::has_command<std::decay_t<decltype(term)>>::value; }, terms_[e]);
  }
  void command_element(std::size_t e, const Eigen::Vector3d& value) {
    std::visit(
        [&](auto& term) {
          if constexpr (detail::has_command<std::decay_t<decltype(term)>>::value) term.command(value);
        },
        terms_[e]);
  }
  // A number commanded at the sample t_k [s] to element e (takes_scalar), the next sample at t_next [s]: a
  // ReactionWheel's speed, reached at t_next at a constant rate (reaction_wheel.hpp); a joint motor's force, held
  // (joint_motor.hpp); the piece that starts at t [s] set.
  bool takes_scalar(std::size_t e) const {
    return std::visit([](const auto& term) { return detail::has_scalar_command<std::decay_t<decltype(term)>>::value; },
                      terms_[e]);
  }
  void command_scalar(std::size_t e, double value, double t_k, double t_next, double t) {
    std::visit(
        [&](auto& term) {
          if constexpr (detail::has_scalar_command<std::decay_t<decltype(term)>>::value) {
            term.command_scalar(value, t_k, t_next, t);
          }
        },
        terms_[e]);
  }

  // ẏ: (v, a) per body, q̇ = ½ q ⊗ (ω_B, 0) for attitudes, dt/dt = 1, dW_e/dt = P_e, dE_b/dt = the mass-flow
  // power of body b.
  void rate(const Coordinates& y, Coordinates& dy) const {
    evaluate(y);
    const detail::StepClock clock = clock_at(y);
    for_each_slot([&](const auto& s) { s.rate(y.data(), clock, kinematics_[s.body], wrenches_[s.body], dy.data()); });
    dy[t_y_] = 1.0;
    for (std::size_t e = 0; e < terms_.size(); ++e) dy[t_y_ + 1 + e] = power_[e];
    dy.segment<6>(t_y_ + impulse_offset()).setZero();
    add_impulses(dy.data() + t_y_ + impulse_offset(), 1.0);
  }

  // Evaluations that sum no impulse (they stay as they are in y), for a run that records none: a coarse run of the
  // global error estimate (SimulationOptions::estimate_records, simulate/run_loop.hpp). Nothing else reads them, so
  // the bodies, the works and every other record are the same bits, at the cost of the motion and the works alone.
  void leave_out_impulses() { integrates_impulses_ = false; }

  // every attitude q ← q / |q|
  void project(Coordinates& y) const {
    for_each_slot([&](const auto& s) { s.project(y.data()); });
    step_start_ = y[t_y_];  // the methods that end with project: the next step starts here
  }

  // The implicit midpoint step (integrators/implicit_midpoint.hpp's hook): the fixed point ȳ = y0 + (h/2) ẏ(ȳ) of every
  // coordinate, with the tolerance and cap of that file (a body with an attitude and Euler's gyroscopic term takes its
  // ω̄ by a Newton step and its q̄ exactly: midpoint_newton), then y1 = 2ȳ − y0 and project; except a tree's q and v,
  // which take the variational midpoint method instead (kinds/tree_slot.hpp): symplectic, it keeps the momentum of
  // every symmetry of the scene (a floating tree's momenta, a hinge about the axis of gravity) and bounds the energy
  // error over long runs. With a tree, the iterates are mixed by Anderson's method (anderson_mix): the variational
  // fixed point contracts slowly where a light link turns fast (its rate ~ h × joint rate × the inertias' ratio).
  // Returns whether the fixed point converged.
  bool implicit_midpoint_step(Coordinates& y, double h) const {
    using namespace implicit_midpoint_solver;
    auto& trees = std::get<std::vector<detail::TreeSlot>>(slots_);
    mid_ = y;
    for (const detail::TreeSlot& tree : trees) tree.start_variational_midpoint(y.data(), 0.5 * h, mid_.data());
    bool converged = false;
    for (int k = 0; k < max_iterations && !converged; ++k) {
      rate(mid_, rate_);
      next_ = y + (0.5 * h) * rate_;
      for (const detail::TreeSlot& tree : trees) tree.variational_midpoint_iterate(mid_.data(), 0.5 * h, next_.data());
      midpoint_newton(y, mid_, next_, h);
      converged = midpoint_converged(*this, mid_, next_);
      if (converged || trees.empty()) {
        mid_.swap(next_);
      } else {
        anderson_mix(k);
        for (const detail::TreeSlot& tree : trees) tree.recenter_variational_midpoint(0.5 * h, mid_.data());
      }
    }
    y = 2.0 * mid_ - y;
    for (const detail::TreeSlot& tree : trees) tree.finish_variational_midpoint(h, y.data());
    project(y);
    return converged;
  }

  // In the implicit midpoint's fixed point, next = y0 + (h/2) ẏ(mid) of the map corrected for every body with an
  // attitude and Euler's gyroscopic term: its ω̄ by a Newton step, its q̄ exactly for that ω̄
  // (midpoint_newton_correction, midpoint_attitude)
  void midpoint_newton(const Coordinates& y0, const Coordinates& mid, Coordinates& next, double h) const {
    for_each_slot([&](const auto& s) {
      if constexpr (detail::has_midpoint_newton<std::decay_t<decltype(s)>>::value) {
        s.midpoint_newton(y0.data(), mid.data(), next.data(), h);
      }
    });
  }

  // ξ = (velocities, accelerations per body; 1; element powers; mass-flow powers)
  void velocity(const Coordinates& y, Tangent& xi) const {
    evaluate(y);
    const detail::StepClock clock = clock_at(y);
    for_each_slot([&](const auto& s) { s.velocity(y.data(), clock, kinematics_[s.body], wrenches_[s.body], xi.data()); });
    xi[t_xi_] = 1.0;
    for (std::size_t e = 0; e < terms_.size(); ++e) xi[t_xi_ + 1 + e] = power_[e];
    xi.segment<6>(t_xi_ + impulse_offset()).setZero();
    add_impulses(xi.data() + t_xi_ + impulse_offset(), 1.0);
  }

  // y ⊕ Θ: vector parts added, q ← q ⊗ exp(Θ_rot) for each attitude
  void retract(const Coordinates& y, const Tangent& theta, Coordinates& out) const {
    for_each_slot([&](const auto& s) { s.retract(y.data(), theta.data(), out.data()); });
    for (Eigen::Index i = 0; i <= extra_count(); ++i) out[t_y_ + i] = y[t_y_ + i] + theta[t_xi_ + i];
  }

  // ξ(y ⊕ Θ) (elements may read any attitude: the stage attitude is always built)
  void velocity_at(const Coordinates& y, const Tangent& theta, Tangent& xi) const {
    retract(y, theta, stage_);
    velocity(stage_, xi);
  }

  // ω ← dexp⁻¹_{−Θ} ω for each attitude part (so3/dexp_inv.hpp), identity elsewhere
  void dexp_inv(const Tangent& theta, Tangent& xi) const {
    for_each_slot([&](const auto& s) { s.dexp_inv(theta.data(), xi.data()); });
  }

  // velocities += h × accelerations at y (the explicit gyroscopic term); positions, work, t unchanged
  void kick(Coordinates& y, double h) const { kick_with(y, h, [](const auto& euler, const auto& w, const auto& tau, double k) {
    return euler.explicit_gyroscopic_kick(w, tau, k);
  }); }
  // the same with the implicit gyroscopic term (one Newton step, euler_equations.hpp)
  void kick_implicit_gyroscopic(Coordinates& y, double h) const {
    kick_with(y, h, [](const auto& euler, const auto& w, const auto& tau, double k) { return euler.implicit_gyroscopic_kick(w, tau, k); });
  }

  // work_e += h P_e and the impulses += h (Σ f, Σ M) at y; then p += h v, q ← q ⊗ exp(h ω_B) (exact for constant ω), θ += h ω, m += h ṁ (and
  // E_b with it: advance_masses), t += h
  void drift(Coordinates& y, double h) const {
    evaluate(y);
    for (std::size_t e = 0; e < terms_.size(); ++e) y[t_y_ + 1 + e] += h * power_[e];
    add_impulses(y.data() + t_y_ + impulse_offset(), h);
    for_each_slot([&](const auto& s) {
      s.translate(y.data(), h);
      s.turn(y.data(), h);
    });
    advance_masses(y, h);
    project(y);
    y[t_y_] += h;
    step_start_ = y[t_y_];
  }

  // The exact flow of the loads part over h [s] (model_interface.hpp): the wrenches at y (positions,
  // attitudes, velocities and t as they are), v += h f/m, ω += h I⁻¹ τ (no gyroscopic term) and each
  // element's work += h Σ_b (f_eb·v̄_b + τ_eb·ω̄_b) with the mean velocities v̄ = v + Δv/2 (exact: the
  // velocities are linear in time in this flow), the impulses += h (Σ f, Σ M) (exact: the wrenches are fixed). In a turning frame (a CoriolisTerm) the Coriolis force and
  // torque are linear in the velocities, so each velocity follows u̇ = a0 + M (u − u0) (a0 at the start, M u
  // the Coriolis part: M v = −2 Ω × v for a centre of mass, M ω = I⁻¹ (s × ω) for an attitude): its exact
  // flow is taken (so3/coriolis_flow.hpp, kinds/body_slot.hpp VelocityKicks), so the kick stays a flow and the
  // kick–free–kick compositions keep their orders; v̄ is then the mean velocity of that flow, and the Coriolis
  // work over the kick is zero (its power is zero at every instant). Returns Σ |Δω_B| over the bodies with a
  // 3-D attitude [rad/s].
  double loads_kick(Coordinates& y, double h) const {
    return coriolis_terms_.empty() ? loads_kick_with<false>(y, h) : loads_kick_with<true>(y, h);
  }

  // loads_kick at the positions, attitudes, t and loads of the last loads_kick, from which a record alone separates
  // it (simulate/run_loop.hpp, merged_steps: a step's closing kick before a record, then the next step's opening
  // kick), where kicks_merge(): the elements' wrenches of that kick, which do not depend on the velocities, kept and
  // not evaluated again (a record evaluates into other buffers). The same bits as loads_kick.
  double loads_kick_repeated(Coordinates& y, double h) const {
    return coriolis_terms_.empty() ? loads_kick_with<false, false>(y, h) : loads_kick_with<true, false>(y, h);
  }

  // True when two loads_kick at the same positions, attitudes and t are one (simulate/run_loop.hpp, merged_steps):
  // no element reads the velocities (its traits) and no mass flows (the splittings then move masses between kicks)
  bool kicks_merge() const { return kicks_merge_; }

  // The free part over h [s]: p += h v for every body, θ += h ω for a planar body, each attitude and its ω_B by
  // the flow Rotation (DlmRotation<normalise>: dlm_free_rotation; ExactRotation: the body's own
  // FreeRotationFlow), t += h; no work (no load acts in this part).
  template <class Rotation>
  void free_flow(Coordinates& y, double h) const {
    free_motion<Rotation>(y, h);
    advance_masses(y, h);
    y[t_y_] += h;
    step_start_ = y[t_y_];
  }

  // The free part at fixed masses (free_flow without advance_masses): p, attitudes and ω_B, t += h. With mass_part,
  // the three parts of the splittings' form that keeps the masses inside each step (integrators/yoshida4.hpp,
  // which ends its step with project).
  template <class Rotation>
  void free_flow_at_fixed_mass(Coordinates& y, double h) const {
    free_motion<Rotation>(y, h);
    y[t_y_] += h;
  }

  // The masses' part over h [s] at the time t of y, which it keeps: m += h ṁ(t) for each body with a MassFlow (the
  // exact flow of ṁ at a frozen t), E_b with it (advance_masses' exact change of T); positions, velocities,
  // attitudes and works unchanged. The out-of-mass error (mass_flow.hpp) when a mass is no longer positive, in
  // the step from the last project (or the run's start).
  void mass_part(Coordinates& y, double h) const {
    const double t = y[t_y_];
    for_each_mass_slot([&](const auto& s) {
      const double rate = has_constant_rate(s.mass.flow) ? s.mass.flow.rate : mass_rate(s.mass.flow, t, s.mass.flow_name);
      detail::change_mass(s, y.data(), h * rate, t, step_start_);
    });
  }

  // p += h v, θ += h ω, each attitude and its ω_B by the flow Rotation (free_flow); masses and t unchanged
  template <class Rotation>
  void free_motion(Coordinates& y, double h) const {
    for_each_slot([&](const auto& s) { s.translate(y.data(), h); });
    for_each_slot([&](const auto& s) { s.template free_rotation<Rotation>(y.data(), h); });
  }

  // Appends the record of y at time t [s] to `out` (scene_simulation.hpp): the bodies, energies,
  // momenta, each element's work and power, and (when a body has a MassFlow) each body's mass-flow energy.
  void record(const Coordinates& y, double t, SceneSimulation& out) const {
    // a coarse run of the estimate records no power and no pivot reaction: the kinematics alone, no element's wrench
    if (out.estimate_records) {
      fill_kinematics(y, true);
    } else {
      evaluate(y, true);
    }
    append_record(y, t, out);
  }

  // record() right after a loads_kick at y's positions, attitudes, t and loads (simulate/run_loop.hpp: the closing kick
  // of merged steps, where kicks_merge(), before a record): the elements' wrenches that kick kept, not evaluated
  // again, and each element's power Σ_b f_W·v_W + τ_B·ω_B [W] of its wrenches at the record's velocities (the
  // products its own add_wrenches sums, in body order: the same power to round-off, bit for bit where the element
  // sums them so, as MutualGravity, UniformGravity and ScheduledLoads do)
  void record_after_kick(const Coordinates& y, double t, SceneSimulation& out) const {
    if (out.estimate_records) return record(y, t, out);
    fill_kinematics(y, true);
    sum_element_wrenches();
    for (std::size_t e = 0; e < terms_.size(); ++e) power_[e] = element_power(e);
    append_record(y, t, out);
  }

  // The rest of a record (record): the bodies, energies, momenta, works, powers and mass-flow energies of y at t [s],
  // from kinematics_, wrenches_ and power_ at y
  void append_record(const Coordinates& y, double t, SceneSimulation& out) const {
    out.t.push_back(t);
    detail::RecordSums sums;
    for_each_slot([&](const auto& s) {
      s.record(y.data(), kinematics_[s.body], wrenches_[s.body], sums, momentum_O_W_[s.body], reaction_W_[s.body]);
    });
    for (std::size_t b = 0; b < kinematics_.size(); ++b) {
      const double* q_y = q_y_[b] >= 0 ? y.data() + q_y_[b] : nullptr;  // as integrated
      detail::append_body_record(kinematics_[b], q_y, momentum_O_W_[b], reaction_W_[b], out);
    }
    double V = 0.0;
    for (const Term& term : terms_) V += std::visit([&](const auto& e) { return e.potential(kinematics_); }, term);
    detail::append_record_sums(sums, V, out);
    for (std::size_t e = 0; e < terms_.size(); ++e) out.work.push_back(y[t_y_ + 1 + e]);
    if (!out.estimate_records) {
      const double* impulses = y.data() + t_y_ + impulse_offset();
      append_values<3>(out.impulse_W, impulses);
      append_values<3>(out.angular_impulse_W, impulses + 3);
      out.power.insert(out.power.end(), power_.begin(), power_.end());
    }
    for_each_slot([&](const auto& s) {
      if constexpr (detail::has_internal_record<std::decay_t<decltype(s)>>::value) s.record_internal(y.data(), out);
    });
    if (has_mass_flow()) {
      const std::size_t first = out.mass_flow_energy.size();
      out.mass_flow_energy.resize(first + kinematics_.size(), 0.0);
      for (std::size_t k = 0; k < energy_body_.size(); ++k) out.mass_flow_energy[first + energy_body_[k]] = y[energy_y(k)];
    }
  }

  // y of the bodies' states (each of its body's kind, checked by the caller) at time t [s], works and mass-flow
  // energies 0
  Coordinates coordinates(const std::vector<BodyState>& states, double t) const {
    Coordinates y = Coordinates::Zero(coordinate_count());
    for_each_slot([&](const auto& s) { s.coordinates(states[s.body], y.data()); });
    y[t_y_] = t;
    return y;
  }

  // The bodies' states in y (attitudes as integrated)
  std::vector<BodyState> states(const Coordinates& y) const {
    std::vector<BodyState> out(body_count());
    for_each_slot([&](const auto& s) {
      if constexpr (detail::spans_bodies<std::decay_t<decltype(s)>>::value) {
        s.states(y.data(), &out[s.body]);
      } else {
        out[s.body] = s.state(y.data());
      }
    });
    return out;
  }

  // Each body's mass in y [kg] (its constant mass, or its mass coordinate)
  std::vector<double> masses(const Coordinates& y) const {
    std::vector<double> out(body_count());
    for (std::size_t b = 0; b < out.size(); ++b) out[b] = kinematics_[b].m;
    for_each_mass_slot([&](const auto& s) { out[s.body] = y[s.mass.m_y]; });
    return out;
  }

 private:
  // f(slot) for every body, kind by kind (kinds/kind_list.hpp): one indirect call per kind present in the scene,
  // through a table of one loop per slot type (a kind that is not present costs nothing)
  template <class F>
  void for_each_slot(F&& f) const {
    using Visit = void (*)(const detail::SlotGroups&, std::decay_t<F>&);
    static constexpr auto visits = group_visits<std::decay_t<F>, Visit>(std::make_index_sequence<group_count>());
    for (std::size_t k = 0; k < present_count_; ++k) visits[present_[k]](slots_, f);
  }
  template <class F, class Visit, std::size_t... I>
  static constexpr std::array<Visit, sizeof...(I)> group_visits(std::index_sequence<I...>) {
    return {&visit_group<I, F>...};
  }
  template <std::size_t I, class F>
  static void visit_group(const detail::SlotGroups& groups, F& f) {
    for (const auto& s : std::get<I>(groups)) f(s);
  }
  // present_: the groups of slots_ that hold a body, in order
  template <std::size_t... I>
  void find_present_groups(std::index_sequence<I...>) {
    ((std::get<I>(slots_).empty() ? void() : void(present_[present_count_++] = static_cast<std::uint8_t>(I))), ...);
  }
  // f(slot) for every body with a MassFlow
  template <class F>
  void for_each_mass_slot(F&& f) const {
    for_each_slot([&](const auto& s) {
      if constexpr (std::decay_t<decltype(s)>::has_mass_flow) f(s);
    });
  }
  template <class Group>
  static void set_slots_time(Group& group, double t) {
    if constexpr (detail::has_set_time<typename Group::value_type>::value) {
      for (auto& s : group) s.set_time(t);
    }
  }
  // where the mass-flow energies of a group's slots are in y and ξ (after t and the extra works)
  template <class Group>
  void place_energies(Group& group, Eigen::Index works) {
    if constexpr (Group::value_type::has_mass_flow) {
      for (auto& s : group) s.mass.energy_y = t_y_ + 1 + works + s.mass.energy, s.mass.energy_xi = t_xi_ + 1 + works + s.mass.energy;
    }
  }

  // t of y and the start of the step being taken (the out-of-mass message)
  detail::StepClock clock_at(const Coordinates& y) const { return {y[t_y_], step_start_}; }

  // loads_kick without (turning = false) or with the exact Coriolis kick; the elements' wrenches evaluated, or kept
  // from the last kick (loads_kick_repeated)
  template <bool turning, bool evaluated = true>
  double loads_kick_with(Coordinates& y, double h) const {
    fill_kinematics(y);
    const double t = y[t_y_];
    if constexpr (evaluated) {
      for (std::size_t e = 0; e < terms_.size(); ++e) {
        std::vector<BodyWrench>& w = element_wrenches_[e];
        for (BodyWrench& b : w) b.f_W.setZero(), b.tau_B.setZero();
        std::visit([&](const auto& term) { term.add_wrenches(t, kinematics_, w); }, terms_[e]);
      }
    }
    sum_element_wrenches();
    add_impulses(y.data() + t_y_ + impulse_offset(), h);  // at the positions and attitudes the kick keeps
    Eigen::Vector3d w_F = Eigen::Vector3d::Zero();  // the frame's Ω [rad/s] in F
    if constexpr (turning) w_F = coriolis_frame_rate(t);
    const detail::VelocityKicks<turning> kicks(h, w_F, &coriolis_inertia_);
    // the velocity increments; kinematics_ then holds the mean velocities
    double kicked = 0.0;
    for_each_slot([&](const auto& s) { kicked += s.loads_kick(y.data(), kinematics_[s.body], wrenches_[s.body], h, kicks); });
    for (std::size_t e = 0; e < terms_.size(); ++e) {
      if constexpr (turning) {
        if (std::holds_alternative<CoriolisTerm>(terms_[e])) continue;  // its work over the exact kick: 0
      }
      y[t_y_ + 1 + e] += h * element_power(e);
    }
    return kicked;
  }

  // wrenches_ = Σ of the elements' wrenches element_wrenches_ (loads_kick); a single element's copied (the sum 0 + w
  // is w, but that a −0 becomes +0, which every later use of the wrench adds to or multiplies alike)
  void sum_element_wrenches() const {
    if (element_wrenches_.size() == 1) {
      std::copy(element_wrenches_.front().begin(), element_wrenches_.front().end(), wrenches_.begin());
    } else {
      for (BodyWrench& b : wrenches_) b.f_W.setZero(), b.tau_B.setZero();
      for (const auto& w : element_wrenches_) {
        for (std::size_t b = 0; b < w.size(); ++b) wrenches_[b].f_W += w[b].f_W, wrenches_[b].tau_B += w[b].tau_B;
      }
    }
    note_tree_wrenches();
  }

  // Σ_b f_W·v_W + τ_B·ω_B [W] of element e's wrenches in element_wrenches_ at the velocities of kinematics_
  double element_power(std::size_t e) const {
    double power = 0.0;
    const std::vector<BodyWrench>& w = element_wrenches_[e];
    for (std::size_t b = 0; b < w.size(); ++b) {
      power += w[b].f_W.dot(kinematics_[b].v_W) + w[b].tau_B.dot(kinematics_[b].w_B);
    }
    return power;
  }

  // The Coriolis terms among terms_ (their frames' Ω when constant) and, when there is one, the inertia each body
  // with a 3-D attitude turns with in the exact Coriolis kick (loads_kick): I_C of a rigid body (I_C0 under a
  // MassFlow), I_O of a pivoted one
  void find_coriolis_terms(const std::vector<Body>& bodies) {
    for (std::size_t e = 0; e < terms_.size(); ++e) {
      if (const auto* term = std::get_if<CoriolisTerm>(&terms_[e])) {
        const bool constant = term->frame().constant_rotation;
        coriolis_terms_.push_back({e, constant, constant ? frame_terms(term->frame(), 0.0).w_F : Eigen::Vector3d::Zero()});
      }
    }
    if (coriolis_terms_.empty()) return;
    coriolis_inertia_.resize(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (const auto* r = std::get_if<RigidBody>(&bodies[b])) coriolis_inertia_[b] = coriolis_inertia(r->inertia_com());
      if (const auto* o = std::get_if<PivotedBody>(&bodies[b])) coriolis_inertia_[b] = coriolis_inertia(o->inertia_O());
    }
  }

  // Ω_F [rad/s] of the Coriolis terms at t [s] (their sum: compile adds one)
  Eigen::Vector3d coriolis_frame_rate(double t) const {
    Eigen::Vector3d w = Eigen::Vector3d::Zero();
    for (const CoriolisFrame& c : coriolis_terms_) {
      w += c.constant ? c.w_F : frame_terms(std::get<CoriolisTerm>(terms_[c.element]).frame(), t).w_F;
    }
    return w;
  }

  // The masses over the free part of a splitting (t → t + h, t of y): m += h ṁ, exact for a constant rate,
  // the midpoint rule h ṁ(t + h/2) for a rate of t (second order, as the compositions), E_b with them
  // (detail::change_mass); the out-of-mass error when a mass is no longer positive
  void advance_masses(Coordinates& y, double h) const {
    const double t = y[t_y_];
    for_each_mass_slot([&](const auto& s) {
      const MassFlow& flow = s.mass.flow;
      const double rate = has_constant_rate(flow) ? flow.rate : mass_rate(flow, t + 0.5 * h, s.mass.flow_name);
      detail::change_mass(s, y.data(), h * rate, t + h, t);
    });
  }

  // How many slots follow t in y (and ξ): the works, the mass-flow energies, then the impulses J_W, K_W
  Eigen::Index extra_count() const { return impulse_offset() - 1 + 6; }
  // where the impulses J_W (3) then K_W (3) are in y after t (and in ξ after its dt/dt)
  Eigen::Index impulse_offset() const { return 1 + static_cast<Eigen::Index>(terms_.size() + energy_body_.size()); }

  // out[0..2] += h Σ_b f_b [N], out[3..5] += h Σ_b (p_b × f_b + R_WB,b τ_B,b) [N m] (the moment about W's origin)
  // of wrenches_ at kinematics_ (τ_B = 0 when no term turns vectors: none gives a torque) and of the gravity the trees
  // apply to their links; nothing where every term's wrenches sum to zero (integrates_impulses_), whose impulses then
  // stay 0, their exact value, at no cost per evaluation (an N-body cluster, bodies linked by springs alone), nor in a
  // run that records none (leave_out_impulses)
  void add_impulses(double* out, double h) const {
    if (!integrates_impulses_) return;
    std::size_t b = 0;
    for (const detail::TreeSlot& tree : std::get<std::vector<detail::TreeSlot>>(slots_)) {
      if (!tree.unloaded) continue;  // its links' wrenches are zero: skipped
      add_wrench_impulses(out, h, b, static_cast<std::size_t>(tree.body));
      b = static_cast<std::size_t>(tree.body + tree.links);
    }
    add_wrench_impulses(out, h, b, wrenches_.size());
    for (const TreeGravity& g : tree_gravity_) {  // the gravity a tree applies to its links (leave_gravity_to):
      Eigen::Vector3d mp = Eigen::Vector3d::Zero();  // Σ f = (Σ m) g, Σ p × m g = (Σ m p) × g
      for (int b = g.first; b < g.first + g.count; ++b) mp += kinematics_[b].m * kinematics_[b].p_W;
      const Eigen::Vector3d M_W = mp.cross(g.g_W);
      for (int i = 0; i < 3; ++i) out[i] += h * g.f_W[i], out[3 + i] += h * M_W[i];
    }
  }
  // Anderson's mixing of the fixed point x = g(x) (Walker & Ni 2011, "Anderson acceleration for fixed-point
  // iterations"), after iterate k (x_k in mid_, g(x_k) in next_): with the residuals f = g(x) − x and the differences
  // ΔF, ΔG of the last m iterates' f and g, x_k+1 = g(x_k) − ΔG γ, γ = argmin |f_k − ΔF γ| (the normal equations of
  // at most m unknowns); the plain iterate g(x_k) where γ is not finite, and a restart from it (the differences
  // dropped) where a mixed iterate's residual grew tenfold. The step still ends only on |g(x) − x|. A tree then takes
  // the configuration of the mixed velocities (recenter_variational_midpoint: the pair consistent).
  void anderson_mix(int k) const {
    residual_ = next_ - mid_;
    if (k == 0 || !(residual_.norm() <= 10.0 * last_residual_.norm())) anderson_start_ = k;  // (re)start: plain
    const int kept = k - anderson_start_;  // the differences since the (re)start
    const int columns = std::min(kept, anderson_depth);
    if (kept > 0) {
      const int c = (kept - 1) % anderson_depth;
      delta_f_.col(c) = residual_ - last_residual_;
      delta_g_.col(c) = next_ - last_g_;
    }
    last_residual_ = residual_, last_g_ = next_;
    mid_ = next_;
    if (columns == 0) return;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, anderson_depth, anderson_depth> A(columns, columns);
    Eigen::Matrix<double, Eigen::Dynamic, 1, 0, anderson_depth, 1> b(columns);
    for (int i = 0; i < columns; ++i) {
      b[i] = delta_f_.col(i).dot(residual_);
      for (int j = 0; j <= i; ++j) A(i, j) = A(j, i) = delta_f_.col(i).dot(delta_f_.col(j));
    }
    const auto gamma = A.ldlt().solve(b).eval();
    if (!gamma.allFinite()) return;
    for (int i = 0; i < columns; ++i) mid_ -= gamma[i] * delta_g_.col(i);
  }

  // A UniformGravity on every link of a tree becomes the tree's own: its base's acceleration in the articulated-body
  // algorithm (kinds/tree_slot.hpp apply_gravity), the same motion at no cost per link; the term keeps its power and
  // potential, and add_impulses adds its force on the links (the first such element; another loads them as usual)
  void leave_gravity_to(detail::TreeSlot& tree) {
    for (Term& term : terms_) {
      auto* gravity = std::get_if<UniformGravityTerm>(&term);
      if (!gravity || !gravity->leave_to_tree(tree.body, tree.links)) continue;
      tree.apply_gravity(gravity->g_W());
      double m = 0.0;  // the tree's mass (its links' are constant)
      for (int b = tree.body; b < tree.body + tree.links; ++b) m += kinematics_[b].m;
      tree_gravity_.push_back({tree.body, tree.links, gravity->g_W(), m * gravity->g_W()});
      return;
    }
  }

  // add_impulses of bodies first … last − 1
  void add_wrench_impulses(double* out, double h, std::size_t first, std::size_t last) const {
    for (std::size_t b = first; b < last; ++b) {
      detail::add_wrench_impulses(kinematics_[b], wrenches_[b], turns_vectors_, h, out);
    }
  }

  // where the k-th mass-flow energy is in y
  Eigen::Index energy_y(std::size_t k) const { return t_y_ + 1 + static_cast<Eigen::Index>(terms_.size() + k); }

  template <class GyroscopicKick>
  void kick_with(Coordinates& y, double h, GyroscopicKick&& gyroscopic_kick) const {
    evaluate(y);
    for_each_slot([&](const auto& s) { s.kick(y.data(), kinematics_[s.body], wrenches_[s.body], h, gyroscopic_kick); });
  }

  // kinematics_ from y as elements see them (body_kinematics.hpp; attitudes normalised), with each attitude's
  // R_WB when a term needs it (turns_vectors_); without the attitudes (motion_kinematics) where no term and no exact
  // Coriolis kick reads one, all of them for a record (`all`)
  void fill_kinematics(const Coordinates& y, bool all = false) const {
    const detail::StepClock clock = clock_at(y);
    const bool attitudes = all || turns_vectors_ || !coriolis_terms_.empty();
    for_each_slot([&](const auto& s) {
      BodyKinematics& k = kinematics_[s.body];
      if constexpr (detail::has_motion_kinematics<std::decay_t<decltype(s)>>::value) {
        if (!attitudes) return s.motion_kinematics(y.data(), clock, k);
      }
      s.kinematics(y.data(), clock, k);
      if constexpr (!detail::sets_rotation_matrices<std::decay_t<decltype(s)>>::value) {
        if (turns_vectors_) k.R_WB = k.q_WB.toRotationMatrix();
      }
    });
  }

  // kinematics_ at y, wrenches_ = Σ of every element's wrenches, power_[e] = element e's power (`all`: every
  // attitude in the kinematics, for a record)
  void evaluate(const Coordinates& y, bool all = false) const {
    fill_kinematics(y, all);
    for (BodyWrench& w : wrenches_) w.f_W.setZero(), w.tau_B.setZero();
    const double t = y[t_y_];
    for (const TermRun& run : term_runs_) {  // one dispatch per run, its terms' add_wrenches inlined in its loop
      std::visit(
          [&](const auto& first) {
            using T = std::decay_t<decltype(first)>;
            for (std::size_t e = run.first; e < run.last; ++e) {
              power_[e] = std::get_if<T>(&terms_[e])->add_wrenches(t, kinematics_, wrenches_);  // a run is one kind
            }
          },
          terms_[run.first]);
    }
    note_tree_wrenches();
  }
  // term_runs_ of terms_
  void find_term_runs() {
    for (std::size_t e = 0; e < terms_.size(); ++e) {
      if (term_runs_.empty() || terms_[e].index() != terms_[term_runs_.back().first].index()) {
        term_runs_.push_back({e, e + 1});
      } else {
        term_runs_.back().last = e + 1;
      }
    }
  }
  // each tree notes whether its links have a wrench (kinds/tree_slot.hpp note_wrenches), after wrenches_ are summed
  void note_tree_wrenches() const {
    for (const detail::TreeSlot& tree : std::get<std::vector<detail::TreeSlot>>(slots_)) tree.note_wrenches(wrenches_[tree.body]);
  }

  static constexpr std::size_t group_count = std::tuple_size_v<detail::SlotGroups>;
  std::vector<Term> terms_;
  // the terms in runs of one kind, first … last − 1 (a scene's many springs one run: evaluate dispatches per run)
  struct TermRun {
    std::size_t first, last;
  };
  std::vector<TermRun> term_runs_;
  detail::SlotGroups slots_;       // the bodies, kind by kind
  std::array<std::uint8_t, group_count> present_{};  // the indices of the groups that hold a body, in order
  std::size_t present_count_ = 0;
  Eigen::Index t_y_ = 0, t_xi_ = 0;  // offsets of t in y and ξ
  // the start [s] of the step being taken, for the out-of-mass message (set_time, project, drift, free_flow: a run
  // copies its model, sets its first piece and steps it on one thread; coordinates leaves it, so that threads that
  // start runs of one shared model write nothing of it)
  mutable double step_start_ = std::numeric_limits<double>::quiet_NaN();
  std::vector<Eigen::Index> q_y_;  // offset of each body's q_WB in y, −1 without one (for the recorder only)
  std::vector<int> energy_body_;   // the bodies with a MassFlow, in the scene's order (their mass-flow energies')
  std::size_t wheel_count_ = 0;
  bool kicks_merge_ = false;       // kicks_merge()
  bool turns_vectors_ = false;     // some term reads an attitude or gives a torque: kinematics_ carry R_WB
  // some term's wrenches have a net force or moment (ElementTraits zero_net_wrench), and the run records the impulses
  bool integrates_impulses_ = true;
  // scratch, sized here (an evaluation allocates nothing)
  mutable std::vector<BodyKinematics> kinematics_;
  mutable std::vector<BodyWrench> wrenches_;
  mutable std::vector<double> power_;
  mutable std::vector<std::vector<BodyWrench>> element_wrenches_;  // per element (loads_kick's exact work)
  mutable std::vector<Eigen::Vector3d> reaction_W_, momentum_O_W_;  // per body, for the recorder only
  mutable Coordinates stage_;  // y ⊕ Θ of velocity_at
  mutable Coordinates mid_, next_, rate_;  // implicit_midpoint_step's iterates and rate
  // anderson_mix's last residual and g, and the differences of the last anderson_depth ones (sized with a tree)
  static constexpr int anderson_depth = 4;
  mutable Coordinates residual_, last_residual_, last_g_;
  mutable int anderson_start_ = 0;  // the iterate of the last (re)start
  mutable Eigen::MatrixXd delta_f_, delta_g_;
  // the Coriolis terms (loads_kick's exact kick; empty without a turning frame) and the bodies' inertias for it
  struct CoriolisFrame {
    std::size_t element;
    bool constant;          // the frame's rotation is constant: Ω_F below
    Eigen::Vector3d w_F;    // [rad/s] in F
  };
  std::vector<CoriolisFrame> coriolis_terms_;
  std::vector<CoriolisInertia> coriolis_inertia_;  // per body (set for rigid and pivoted bodies)
  // the links first … first + count − 1 of a tree that applies a UniformGravity g_W [m/s²] itself (leave_gravity_to)
  struct TreeGravity {
    int first, count;
    Eigen::Vector3d g_W, f_W;  // f_W = (Σ m) g_W [N], the force on the whole tree
  };
  std::vector<TreeGravity> tree_gravity_;
};

using SceneModel = BasicSceneModel<>;

}  // namespace rigiddyn
