// VariableMassParticleModel: the fast model of ONE particle whose mass changes at a constant rate ṁ
// (scene/mass_flow.hpp), pushed by one Thrust along a fixed direction of the inertial frame W
// (scene/elements/thrust.hpp) and, optionally, uniform gravity (the fast path compile chooses
// for such a scene). Fixed-size coordinates, no allocation, no visit; the same members as SceneModel
// (scene/scene_model.hpp), so the run loop and every integrator take it unchanged.
//
// Coordinates y (11,): (p_W 3, v_W 3, m, t, work of gravity, work of the thrust, mass-flow energy) [m, m/s, kg,
// s, J, J, J]. Tangent ξ (11,): the rates of the same (a vector space: ξ = ẏ).
//
// Equations ("Rigid body kinematics and dynamics" notes, eq. (4.36), f = d(m v)/dt for the particle and the
// mass it exchanges: d(m v)/dt = m g + ṁ (v + u_rel)):
//   ṗ = v,   m v̇ = m g + ṁ u_rel  (v̇ = g + (ṁ/m) u_rel),   ṁ = const,   ṫ = 1,
//   dW_gravity/dt = m g·v,   dW_thrust/dt = ṁ u_rel·v,   dE/dt = ½ ṁ |v|²,
// E the mass-flow energy: with T = ½ m |v|², dT/dt = dW_gravity/dt + dW_thrust/dt + ½ ṁ |v|² (scene_model.hpp).
// The mass is a position-like coordinate: it moves with t in the free part of the splitting methods
// (free_flow, drift: m += h ṁ, exact for a constant rate, E += ½ h ṁ |v|² with it, exact at fixed v) and is
// frozen in the kicks, which use the mass at the kick's time (kick: v += h (g + ṁ u_rel / m); loads_kick: the
// same, the exact flow of the loads part at that frozen mass, v linear in time). Strang's kick · free · kick is
// then a splitting of the whole system into two exactly solved parts (order 2). Yoshida's triple jump takes the
// three-part form (mass_part, free_flow_at_fixed_mass: integrators/yoshida4.hpp), order 4, which keeps every
// mass it meets between those at the ends of its step.
//
// Mass running out: the mass changes only where a (sub-)step ends (project, the last call of explicit
// Euler, RK4, RKMK4 and the implicit midpoint rule; drift and free_flow, the parts of the kick/drift and
// splitting methods that move m), and each checks m > 0 there, else throws std::invalid_argument
// (out_of_mass_error): "mass_flows[0]: expected a positive mass, got m = <m> kg at t = <t> s (the body
// '<name>' runs out of mass in the step from t = <t0> s)". With a constant rate the stage masses of the
// Runge–Kutta methods lie between those at the step's ends, so no evaluation inside a step sees m <= 0
// without its step raising at its end (a stage at m = 0 gives inf, replaced by the raise); the evaluations
// themselves do not check (no per-stage branch). drift and free_flow know their step's start (t of y before
// them); the methods that end with project have theirs from the previous project (or set_time/coordinates
// at the start of a run), kept in the model (a run copies its model). Yoshida4's mass parts keep the masses
// between those of the step's ends (their t is that of the sub-step, which may lie outside the step).
// Why it stays beside the one engine: a body with a mass flow has no one-body layout, and the generic model takes
// 7.8× its time per RK4 step (110 against 14 ns; `bench/bench_variable_mass.cpp`, variable_mass_particle_rk4 and
// variable_mass_particle_scene_rk4, each over the same hand-written loop; docs/perf/scenes.md §4.1).
#pragma once
#include "rigiddyn/always_inline.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/models/particle.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/elements/thrust.hpp"
#include "rigiddyn/scene/mass_flow.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigiddyn {

class VariableMassParticleModel {
 public:
  using Coordinates = Eigen::Matrix<double, 11, 1>;
  using Tangent = Eigen::Matrix<double, 11, 1>;

  // particle: its mass() is the mass at the start of a run [kg]; flow: its MassFlow (a constant rate; no
  // rate_of_t); thrust: the Thrust element on it (body 0, u_rel [m/s] in W: Frame::world, r_B = 0), at index
  // thrust_element among the scene's element_count elements; g_W [m/s²]: uniform gravity of the element
  // gravity_element (or -1 and g_W = 0); body_name: the body's name in messages.
  // Throws std::invalid_argument naming the argument: "mass_flows[0]..." (check_mass_flow; a rate_of_t),
  // "elements[<thrust_element>]..." (detail::check_thrust), an element index out of range or repeated, a
  // non-finite g_W, gravity without a gravity element.
  VariableMassParticleModel(const Particle& particle, const MassFlow& flow, const Thrust& thrust, int thrust_element,
                            const Eigen::Vector3d& g_W, int gravity_element, std::size_t element_count,
                            const std::string& body_name = "body0")
      : m0_(particle.mass()),
        rate_(flow.rate),
        thrust_W_(flow.rate * thrust.u_rel),
        u_rel_W_(thrust.u_rel),
        g_W_(g_W),
        thrust_element_(thrust_element),
        gravity_element_(gravity_element),
        element_count_(element_count),
        body_name_(body_name) {
    const int n = static_cast<int>(element_count);
    if (thrust_element < 0 || thrust_element >= n) throw_invalid("thrust_element", "an index in [0, " + std::to_string(n) + ")", thrust_element);
    if (gravity_element < -1 || gravity_element >= n) {
      throw_invalid("gravity_element", "-1 or an index in [0, " + std::to_string(n) + ")", gravity_element);
    }
    if (gravity_element == thrust_element) throw_invalid("gravity_element", "another element than thrust_element", gravity_element);
    check_mass_flow(flow, flow_name_);
    if (!has_constant_rate(flow)) {
      throw std::invalid_argument(flow_name_ + ".rate_of_t: expected none (this fast model takes a constant rate; the "
                                               "scene model runs a rate of t), got a function");
    }
    detail::check_thrust(thrust, {Body(particle)}, {flow}, "elements[" + std::to_string(thrust_element) + "]");
    require_finite(g_W, "g_W");
    if (gravity_element < 0 && !g_W.isZero(0.0)) {
      throw_invalid("g_W", "zero without a gravity element (gravity_element = -1)", g_W.transpose().eval());
    }
  }

  Eigen::Index coordinate_count() const { return 11; }
  Eigen::Index tangent_count() const { return 11; }
  Eigen::Index mass_index() const { return 6; }  // where m [kg] is in y
  static constexpr Eigen::Index time_index() { return 7; }  // where t [s] is in y
  Eigen::Index mass_flow_energy_index() const { return 10; }  // where E [J] is in y
  bool has_mass_flow() const { return true; }  // (the model has a mass part: mass_part)
  // where element e's work is in y (gravity's or the thrust's slot; -1 for any other element, which a scene
  // on this fast path does not have)
  Eigen::Index work_index(std::size_t element) const {
    const int e = static_cast<int>(element);
    return e == gravity_element_ ? 8 : e == thrust_element_ ? 9 : -1;
  }
  std::size_t body_count() const { return 1; }
  std::size_t element_count() const { return element_count_; }
  double initial_mass() const { return m0_; }       // [kg]
  double mass_rate() const { return rate_; }        // ṁ [kg/s]
  const Eigen::Vector3d& u_rel_W() const { return u_rel_W_; }  // [m/s]
  const Eigen::Vector3d& g_W() const { return g_W_; }          // [m/s²]

  // Nothing is piecewise constant here; the run loop calls it at t0 [s]: the start of the first step (for
  // the out-of-mass message).
  void set_time(double t) { step_start_ = t; }

  // ẏ = (v, g + ṁ u_rel/m, ṁ, 1, m g·v, ṁ u_rel·v, ½ ṁ |v|²)
  RIGIDDYN_ALWAYS_INLINE void rate(const Coordinates& y, Coordinates& dy) const {
    const double m = y[6];
    const double inverse_mass = 1.0 / m;
    for (int i = 0; i < 3; ++i) dy[i] = y[3 + i], dy[3 + i] = g_W_[i] + inverse_mass * thrust_W_[i];
    dy[6] = rate_;
    dy[7] = 1.0;
    dy[8] = m * (g_W_[0] * y[3] + g_W_[1] * y[4] + g_W_[2] * y[5]);
    dy[9] = thrust_W_[0] * y[3] + thrust_W_[1] * y[4] + thrust_W_[2] * y[5];
    dy[10] = 0.5 * rate_ * (y[3] * y[3] + y[4] * y[4] + y[5] * y[5]);
  }

  // No attitude: checks the mass at the end of the step (out_of_mass_error at t of y, in the step from the
  // previous project) and keeps t as the next step's start.
  RIGIDDYN_ALWAYS_INLINE void project(Coordinates& y) const {
    checked_mass(y);
    step_start_ = y[7];
  }

  // ξ = ẏ (a vector space)
  RIGIDDYN_ALWAYS_INLINE void velocity(const Coordinates& y, Tangent& xi) const { rate(y, xi); }

  // y + Θ
  RIGIDDYN_ALWAYS_INLINE static void retract(const Coordinates& y, const Tangent& theta, Coordinates& out) {
    for (int i = 0; i < 11; ++i) out[i] = y[i] + theta[i];
  }

  RIGIDDYN_ALWAYS_INLINE void velocity_at(const Coordinates& y, const Tangent& theta, Tangent& xi) const {
    Coordinates stage;
    retract(y, theta, stage);
    velocity(stage, xi);
  }

  // identity (no attitude)
  RIGIDDYN_ALWAYS_INLINE static void dexp_inv(const Tangent& /*theta*/, Tangent& /*xi*/) {}

  // v += h (g + ṁ u_rel / m), m the mass at the kick's time; p, m, t and the works unchanged
  RIGIDDYN_ALWAYS_INLINE void kick(Coordinates& y, double h) const {
    const double inverse_mass = 1.0 / y[6];
    for (int i = 0; i < 3; ++i) y[3 + i] += h * (g_W_[i] + inverse_mass * thrust_W_[i]);
  }
  // no gyroscopic term: the same kick
  RIGIDDYN_ALWAYS_INLINE void kick_implicit_gyroscopic(Coordinates& y, double h) const { kick(y, h); }

  // works += h × powers at y (m g·v, ṁ u_rel·v), then p += h v, m += h ṁ (E with it), t += h
  RIGIDDYN_ALWAYS_INLINE void drift(Coordinates& y, double h) const {
    const double m = y[6];
    y[8] += h * m * (g_W_[0] * y[3] + g_W_[1] * y[4] + g_W_[2] * y[5]);
    y[9] += h * (thrust_W_[0] * y[3] + thrust_W_[1] * y[4] + thrust_W_[2] * y[5]);
    advance_free(y, h);
  }

  // The exact flow of the loads part over h [s] at the frozen p, m, t: v += Δv = h (g + ṁ u_rel / m), each
  // work += h f·v̄ with v̄ = v + Δv/2 (exact: v is linear in t in this flow). Returns 0 (no attitude).
  RIGIDDYN_ALWAYS_INLINE double loads_kick(Coordinates& y, double h) const {
    const double m = y[6];
    const double inverse_mass = 1.0 / m;
    double v_mean[3];
    for (int i = 0; i < 3; ++i) {
      const double dv = h * (g_W_[i] + inverse_mass * thrust_W_[i]);
      v_mean[i] = y[3 + i] + 0.5 * dv;
      y[3 + i] += dv;
    }
    y[8] += h * m * (g_W_[0] * v_mean[0] + g_W_[1] * v_mean[1] + g_W_[2] * v_mean[2]);
    y[9] += h * (thrust_W_[0] * v_mean[0] + thrust_W_[1] * v_mean[1] + thrust_W_[2] * v_mean[2]);
    return 0.0;
  }

  // The free part over h [s] (no attitude: the rotation flow is not used): p += h v, m += h ṁ (exact; E += ½ h ṁ
  // |v|², exact at fixed v), t += h; no work. Throws out_of_mass_error when the mass at the end is not positive.
  template <class Rotation>
  RIGIDDYN_ALWAYS_INLINE void free_flow(Coordinates& y, double h) const {
    advance_free(y, h);
  }

  // The free part at fixed mass: p += h v, t += h (the three-part form of integrators/yoshida4.hpp)
  template <class Rotation>
  RIGIDDYN_ALWAYS_INLINE void free_flow_at_fixed_mass(Coordinates& y, double h) const {
    for (int i = 0; i < 3; ++i) y[i] += h * y[3 + i];
    y[7] += h;
  }

  // The mass part over h [s] at the t of y, which it keeps: m += h ṁ, E += ½ h ṁ |v|² (exact at fixed v); the
  // out-of-mass error (in the step from the last project) when the new mass is not positive.
  RIGIDDYN_ALWAYS_INLINE void mass_part(Coordinates& y, double h) const { change_mass(y, h * rate_, y[7], step_start_); }

  // Appends the record of y at time t [s] to `out` (scene_simulation.hpp): the particle (q_WB identity,
  // w_B 0), T = ½ m v·v, V = −m g·p (uniform gravity on the mass now), L = m v, H = p × m v (about W's
  // origin), no pivot (reaction 0; H about C: 0), the mass, each element's work and power, the mass-flow energy.
  void record(const Coordinates& y, double t, SceneSimulation& out) const {
    const double m = y[6];
    const Eigen::Vector3d p(y[0], y[1], y[2]), v(y[3], y[4], y[5]);
    out.t.push_back(t);
    out.p_W.insert(out.p_W.end(), p.data(), p.data() + 3);
    const double identity[4] = {0.0, 0.0, 0.0, 1.0}, zero[3] = {0.0, 0.0, 0.0};
    out.q_WB.insert(out.q_WB.end(), identity, identity + 4);
    out.v_W.insert(out.v_W.end(), v.data(), v.data() + 3);
    out.w_B.insert(out.w_B.end(), zero, zero + 3);
    const double T = 0.5 * m * v.squaredNorm();
    const double V = gravity_element_ >= 0 ? -m * g_W_.dot(p) : 0.0;
    out.kinetic_energy.push_back(T);
    out.potential_energy.push_back(V);
    out.total_energy.push_back(T + V);
    const Eigen::Vector3d L_W = m * v, H_W = p.cross(L_W);
    out.linear_momentum_W.insert(out.linear_momentum_W.end(), L_W.data(), L_W.data() + 3);
    out.angular_momentum_W.insert(out.angular_momentum_W.end(), H_W.data(), H_W.data() + 3);
    out.pivot_reaction_W.insert(out.pivot_reaction_W.end(), zero, zero + 3);
    out.angular_momentum_O_W.insert(out.angular_momentum_O_W.end(), zero, zero + 3);
    out.mass.push_back(m);
    const double gravity_power = m * g_W_.dot(v), thrust_power = thrust_W_.dot(v);
    for (std::size_t e = 0; e < element_count_; ++e) {
      const Eigen::Index i = work_index(e);
      out.work.push_back(i < 0 ? 0.0 : y[i]);
      out.power.push_back(i == 8 ? gravity_power : i == 9 ? thrust_power : 0.0);
    }
    out.mass_flow_energy.push_back(y[10]);
  }

  // y of the particle's state at time t [s] with the mass m [kg] (finite > 0, else std::invalid_argument
  // naming "mass"), works and mass-flow energy 0; the start of the first step for the out-of-mass message.
  Coordinates coordinates(const ParticleState& state, double m, double t) const {
    if (!(std::isfinite(m) && m > 0.0)) throw_invalid("mass", "a finite mass > 0 [kg]", m);
    Coordinates y = Coordinates::Zero();
    y.segment<3>(0) = state.p_W;
    y.segment<3>(3) = state.v_W;
    y[6] = m;
    y[7] = t;  // (step_start_ is the run's copy's, set with its first piece)
    return y;
  }
  // the same from the scene's body states (one, a ParticleState) at the particle's initial mass
  Coordinates coordinates(const std::vector<BodyState>& states, double t) const {
    return coordinates(std::get<ParticleState>(states[0]), m0_, t);
  }

  // The particle's state in y (its mass is y[mass_index()])
  static ParticleState state(const Coordinates& y) { return ParticleState{y.segment<3>(0), y.segment<3>(3)}; }
  // the same as the scene's body states
  static std::vector<BodyState> states(const Coordinates& y) { return {BodyState(state(y))}; }

 private:
  // m of y, when positive; else throws out_of_mass_error (at t of y, in the step from step_start_)
  RIGIDDYN_ALWAYS_INLINE double checked_mass(const Coordinates& y) const {
    const double m = y[6];
    if (!(m > 0.0)) throw_out_of_mass(flow_name_, body_name_, m, y[7], step_start_);
    return m;
  }

  // p += h v, m += h ṁ (exact for a constant rate; E with it), t += h; out_of_mass_error when the new mass is not
  // positive (in the step from t of y)
  RIGIDDYN_ALWAYS_INLINE void advance_free(Coordinates& y, double h) const {
    for (int i = 0; i < 3; ++i) y[i] += h * y[3 + i];
    const double t0 = y[7];
    y[7] = t0 + h;
    change_mass(y, h * rate_, y[7], t0);
  }

  // m += dm at fixed v and E += ½ dm |v|² (the exact change of T = ½ m |v|²); out_of_mass_error (at t, in the step
  // from step_start) when the new mass is not positive
  RIGIDDYN_ALWAYS_INLINE void change_mass(Coordinates& y, double dm, double t, double step_start) const {
    const double m = y[6] + dm;
    if (!(m > 0.0)) throw_out_of_mass(flow_name_, body_name_, m, t, step_start);
    y[10] += 0.5 * dm * (y[3] * y[3] + y[4] * y[4] + y[5] * y[5]);
    y[6] = m;
  }

  double m0_;                  // mass at the start of a run [kg]
  double rate_;                // ṁ [kg/s]
  Eigen::Vector3d thrust_W_;   // ṁ u_rel [N] in W
  Eigen::Vector3d u_rel_W_;    // [m/s] in W
  Eigen::Vector3d g_W_;        // [m/s²]
  int thrust_element_, gravity_element_;
  std::size_t element_count_;
  std::string body_name_;
  std::string flow_name_ = "mass_flows[0]";
  // The start [s] of the step being taken, for the out-of-mass message of the methods that end with project
  // (a run copies its model and steps it on one thread).
  mutable double step_start_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace rigiddyn
