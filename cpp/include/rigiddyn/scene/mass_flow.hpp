// A body whose mass changes (docs/fixed_point_frames_mass.md §3): the mass rate ṁ [kg/s] and the rule its
// rotational inertia follows, given per body when it is added to a scene (Scene::mass_flows), with the helpers
// the scene models call. Its companion is the Thrust element (scene/elements/thrust.hpp): the force ṁ u_rel of
// the mass that leaves (ṁ < 0) or joins (ṁ > 0) the body with the velocity u_rel relative to it.
//
// Translation ("Rigid body kinematics and dynamics" notes, eq. (4.36), f = d(m v)/dt, written for the
// body and the mass it exchanges): d(m v)/dt = f + ṁ (v + u_rel), so m v̇ = f + ṁ u_rel. The external
// forces f act on the body's mass now (uniform gravity: m(t) g).
//
// Rotation. ASSUMPTION: the mass that leaves (or joins) carries its own angular momentum: a piece dm
// leaving from a body point takes the share (dI) ω of I ω it had as part of the body. Euler's law for
// the body and the piece together, d(I ω)/dt|_B + ω × I ω = τ + (dI/dt) ω, then leaves Euler's equations
// with the inertia now,
//   I(m) ω̇ + ω × I(m) ω = τ,
// without a jet-damping term (the moment about C of the exhaust's relative momentum is not modelled: a jet
// off the centre of mass acts only through the Thrust element's torque r_B × f).
// Under InertiaRule::scaled, I(m) = I_C0 m/m0, and dividing by m/m0:
//   α_B = I_C0⁻¹ ((m0/m) τ − ω × I_C0 ω),
// Euler's equations of the constant inertia I_C0 with the torque scaled by m0/m (torque_scale): every
// method applies, in the Euler form of I_C0. Under InertiaRule::function the inertia changes shape with
// m; the scene refuses the splitting methods there (their free rotation needs a fixed inertia).
#pragma once
#include "rigiddyn/check.hpp"

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace rigiddyn {

// How the rotational inertia about the centre of mass follows the mass.
enum class InertiaRule {
  scaled,    // I_C(m) = I_C0 m / m0: the body's shape and its mass distribution are kept
  function,  // I_C(m) = inertia_of_mass(m), given by the user
};

// A body's mass flow:
//   rate             ṁ [kg/s] when rate_of_t is empty (negative: the body loses mass; zero: constant mass);
//   rate_of_t        ṁ(t) [kg/s] as a function of the time t [s], or empty;
//   inertia_rule     InertiaRule::scaled (the default) or InertiaRule::function;
//   inertia_of_mass  for InertiaRule::function: I_C(m) [kg m²] about the centre of mass, in B, as a function
//                    of the mass m [kg] (symmetric positive definite; negated products off the diagonal).
// The mass itself is a coordinate of the body's state, starting at the body's mass() [kg].
struct MassFlow {
  double rate = 0.0;
  std::function<double(double t)> rate_of_t;
  InertiaRule inertia_rule = InertiaRule::scaled;
  std::function<Eigen::Matrix3d(double m)> inertia_of_mass;
};

// Checks a mass flow given as `name` (e.g. "mass_flows[2]"): throws std::invalid_argument
//   "<name>.rate: expected a finite number, got inf"                      for a non-finite rate;
//   "<name>.rate: expected 0 when rate_of_t is given, got ..."           (one rate, not two);
//   "<name>.inertia_of_mass: expected a function of the mass for InertiaRule::function, got none";
//   "<name>.inertia_of_mass: expected none for InertiaRule::scaled, ..."  (a function that would be ignored);
//   "<name>.inertia_rule: expected InertiaRule::scaled or ::function, got <n>".
// A rate_of_t is checked where it is called (mass_rate): its values are known only then.
void check_mass_flow(const MassFlow& flow, const std::string& name);

// True when the rate is the constant `rate` (no rate_of_t).
inline bool has_constant_rate(const MassFlow& flow) { return !flow.rate_of_t; }

namespace detail {
[[noreturn]] void throw_bad_mass_rate(const std::string& name, double t, double rate);
}  // namespace detail

// ṁ(t) [kg/s] at the time t [s]: `rate`, or rate_of_t(t). Throws std::invalid_argument
// "<name>.rate: expected a finite mass rate [kg/s] at t = <t> s, got <value>" for a non-finite value
// (a rate_of_t returning inf or NaN; a constant rate was checked by check_mass_flow, and is re-checked here
// for a flow that was not: one comparison).
inline double mass_rate(const MassFlow& flow, double t, const std::string& name = "mass_flow") {
  const double rate = flow.rate_of_t ? flow.rate_of_t(t) : flow.rate;
  if (!std::isfinite(rate)) detail::throw_bad_mass_rate(name, t, rate);
  return rate;
}

// The rotational inertia about the centre of mass at the mass m [kg], in B [kg m²], for a body whose
// inertia is inertia_com0 at its initial mass m0 [kg]:
//   InertiaRule::scaled    I_C0 m / m0;
//   InertiaRule::function  inertia_of_mass(m), checked: finite, symmetric (to 1e-10 of its trace) and
//                          positive definite (its smallest eigenvalue above 1e-10 of its trace), else
//                          std::invalid_argument "<name>.inertia_of_mass: expected a finite symmetric
//                          positive definite inertia [kg m²] at m = <m> kg, got [...]".
Eigen::Matrix3d inertia_at_mass(const MassFlow& flow, const Eigen::Matrix3d& inertia_com0, double m0, double m,
                                const std::string& name = "mass_flow");

// dI_C/dm [m²] at the mass m [kg], in B, for a body whose mass changes at the rate `rate` [kg/s] (not 0):
//   InertiaRule::scaled    I_C0 / m0 (exact);
//   InertiaRule::function  the one-sided difference of second order toward the masses the body reaches (the sign
//                          of the rate), (−3 I(m) + 4 I(m + δ) − I(m + 2δ)) / (2δ) with δ = ±2⁻¹⁷ m: truncation
//                          δ² |d³I/dm³|/3, round-off about 4 ε |I| / |δ| (~3e-11 |I|/m); every I checked by
//                          inertia_at_mass (its message names `name`).
// With it the mass-flow power ½ ω·(dI/dt) ω = ½ ṁ ω·(dI/dm) ω (scene_model.hpp).
Eigen::Matrix3d inertia_mass_derivative(const MassFlow& flow, const Eigen::Matrix3d& inertia_com0, double m0, double m,
                                        double rate, const std::string& name = "mass_flow");

// The torque scale m0/m of InertiaRule::scaled (see the top of this file): with it, Euler's equations of
// the constant inertia I_C0, α_B = I_C0⁻¹ (torque_scale(m0, m) τ − ω × I_C0 ω), are those of I_C0 m/m0.
inline double torque_scale(double m0, double m) { return m0 / m; }

// The time [s] at which a constant rate brings the mass m [kg] at time t [s] to zero: t + m/(−rate);
// +inf for rate >= 0 (the mass never runs out).
inline double burn_out_time(double m, double rate, double t) {
  return rate < 0.0 ? t + m / -rate : std::numeric_limits<double>::infinity();
}

// The error of a mass that is no longer positive: std::invalid_argument
// "<name>: expected a positive mass, got m = <m> kg at t = <t> s (the body '<body_name>' runs out of mass
// in the step from t = <step_start> s)"; name is the flow's ("mass_flows[i]").
std::invalid_argument out_of_mass_error(const std::string& name, const std::string& body_name, double m, double t,
                                        double step_start);
// Throws out_of_mass_error(...) (out of line: the cold path of the models' checks).
[[noreturn]] void throw_out_of_mass(const std::string& name, const std::string& body_name, double m, double t,
                                    double step_start);

// The round-off of a mass accumulated over a run, per step, relative to the initial mass: every method moves
// the mass by a few increments per step (RK4's stages: one sum h/6 (ṁ + 2ṁ + 2ṁ + ṁ); Yoshida's four mass
// parts), each rounding once relative to the mass and a few times relative to h |ṁ| ≤ m0/steps, so that after
// k steps the mass is within 16 ε k m0 of m0 + ṁ k dt (ε the machine epsilon).
inline constexpr double mass_roundoff_per_step = 16.0 * std::numeric_limits<double>::epsilon();

// The up-front check of a run with a constant rate ṁ < 0: the body of mass m0 [kg] at t0 [s], stepped `steps`
// times by dt [s]. A run is accepted when its end mass stays above the round-off of its accumulation,
//   m0 + ṁ steps dt > mass_roundoff_per_step steps m0,
// so that no method meets a mass m <= 0 at any evaluation of it (every stage and sub-step mass of every
// method lies between the masses at the ends of its step, splitting_dlm_yoshida4's included:
// integrators/yoshida4.hpp). Otherwise throws std::invalid_argument:
//   - when the first step already empties the body (dt longer than the time the mass lasts):
//     "<name>: expected a positive mass, got a body that is empty within the first step: '<body_name>' (m =
//     <m0> kg at t = <t0> s, dm/dt = <ṁ> kg/s) runs out at t = <t_out> s, before the step of dt = <dt> s ends;
//     steps, dt: expected dt < <(1 − 16 ε) m0/(−ṁ)> s (the time the mass lasts, less 16 eps of it), got dt =
//     <dt> s";
//   - else, for the first grid step k whose end mass m = m0 + ṁ k dt fails the test, out_of_mass_error when
//     m <= 0, or "<name>: expected a mass above the round-off of its accumulation (16 eps k m0 = <r> kg), got
//     m = <m> kg at t = ... s (the body ... runs out of mass in the step from t = ... s)" when m is positive
//     but within it, followed by "; steps, dt: expected a run that ends before the mass runs out at t =
//     <t_out> s (at most <k − 1> steps of dt = <dt> s), got <steps> steps".
// Nothing for ṁ >= 0 or a rate_of_t (checked as it runs).
void check_mass_over_run(const MassFlow& flow, double m0, double t0, double dt, std::int64_t steps,
                         const std::string& name, const std::string& body_name);

}  // namespace rigiddyn
