// Mass flows (scene/mass_flow.hpp): the checks, the inertia at a mass and the out-of-mass errors.
#include "rigiddyn/scene/mass_flow.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/inertia/validity.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <string>

namespace rigiddyn {

void check_mass_flow(const MassFlow& flow, const std::string& name) {
  require_finite(flow.rate, name + ".rate");
  if (flow.rate_of_t && flow.rate != 0.0) {
    throw_invalid(name + ".rate", "0 when rate_of_t is given (one rate, not two)", flow.rate);
  }
  switch (flow.inertia_rule) {
    case InertiaRule::scaled:
      if (flow.inertia_of_mass) {
        throw std::invalid_argument(name + ".inertia_of_mass: expected none for InertiaRule::scaled (the inertia is "
                                           "I_C0 m/m0), got a function");
      }
      return;
    case InertiaRule::function:
      if (!flow.inertia_of_mass) {
        throw std::invalid_argument(name + ".inertia_of_mass: expected a function of the mass for InertiaRule::function, got none");
      }
      return;
  }
  throw_invalid(name + ".inertia_rule", "InertiaRule::scaled or InertiaRule::function", static_cast<int>(flow.inertia_rule));
}

namespace detail {

void throw_bad_mass_rate(const std::string& name, double t, double rate) {
  throw_invalid(name + ".rate", "a finite mass rate [kg/s] at t = " + format_value(t) + " s", rate);
}

}  // namespace detail

Eigen::Matrix3d inertia_at_mass(const MassFlow& flow, const Eigen::Matrix3d& inertia_com0, double m0, double m,
                                const std::string& name) {
  if (flow.inertia_rule == InertiaRule::scaled) return (m / m0) * inertia_com0;
  const Eigen::Matrix3d I = flow.inertia_of_mass(m);
  const std::string expected = "a finite symmetric positive definite inertia [kg m²] at m = " + format_value(m) + " kg";
  if (!I.allFinite()) throw_invalid(name + ".inertia_of_mass", expected, I);
  const double tolerance = inertia_relative_tolerance * std::abs(I.trace());
  if (!((I - I.transpose()).cwiseAbs().maxCoeff() <= tolerance)) throw_invalid(name + ".inertia_of_mass", expected, I);
  const Eigen::Matrix3d symmetric = 0.5 * (I + I.transpose());
  const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(symmetric, Eigen::EigenvaluesOnly).eigenvalues()(0);
  if (!(smallest > tolerance)) throw_invalid(name + ".inertia_of_mass", expected, I);
  return symmetric;
}

Eigen::Matrix3d inertia_mass_derivative(const MassFlow& flow, const Eigen::Matrix3d& inertia_com0, double m0, double m,
                                        double rate, const std::string& name) {
  if (flow.inertia_rule == InertiaRule::scaled) return inertia_com0 / m0;
  const double delta = std::ldexp(rate > 0.0 ? m : -m, -17);  // toward the masses the body reaches
  const auto I = [&](double mass) { return inertia_at_mass(flow, inertia_com0, m0, mass, name); };
  return (-3.0 * I(m) + 4.0 * I(m + delta) - I(m + 2.0 * delta)) / (2.0 * delta);
}

std::invalid_argument out_of_mass_error(const std::string& name, const std::string& body_name, double m, double t,
                                        double step_start) {
  return std::invalid_argument(name + ": expected a positive mass, got m = " + format_value(m) + " kg at t = " +
                               format_value(t) + " s (the body '" + body_name + "' runs out of mass in the step from t = " +
                               format_value(step_start) + " s)");
}

void throw_out_of_mass(const std::string& name, const std::string& body_name, double m, double t, double step_start) {
  throw out_of_mass_error(name, body_name, m, t, step_start);
}

namespace {

// The error of a run whose first step already empties the body (check_mass_over_run)
[[noreturn]] void throw_empty_in_first_step(const MassFlow& flow, double m0, double t0, double dt, const std::string& name,
                                            const std::string& body_name) {
  // the first step passes when m0 + ṁ dt > r m0 (check_mass_over_run): dt < (1 − r) m0 / (−ṁ)
  const double longest = (1.0 - mass_roundoff_per_step) * m0 / -flow.rate;  // [s]
  throw std::invalid_argument(name + ": expected a positive mass, got a body that is empty within the first step: '" +
                              body_name + "' (m = " + format_value(m0) + " kg at t = " + format_value(t0) +
                              " s, dm/dt = " + format_value(flow.rate) + " kg/s) runs out at t = " +
                              format_value(burn_out_time(m0, flow.rate, t0)) + " s, before the step of dt = " +
                              format_value(dt) + " s ends; steps, dt: expected dt < " + format_value(longest) +
                              " s (the time the mass lasts, less 16 eps of it), got dt = " + format_value(dt) + " s");
}

}  // namespace

void check_mass_over_run(const MassFlow& flow, double m0, double t0, double dt, std::int64_t steps,
                         const std::string& name, const std::string& body_name) {
  if (!has_constant_rate(flow) || !(flow.rate < 0.0)) return;
  // the end mass of step k passes when m0 − k (−ṁ dt) > r k m0 (r = mass_roundoff_per_step), i.e. when
  // k < m0 / (−ṁ dt + r m0); −ṁ dt may overflow to inf (then no step passes)
  const double burnt_per_step = -flow.rate * dt;  // [kg]
  const double limit = m0 / (burnt_per_step + mass_roundoff_per_step * m0);
  const double k_max = std::ceil(limit) - 1.0;  // the largest integer k below the limit
  if (static_cast<double>(steps) <= k_max) return;
  if (k_max < 1.0) throw_empty_in_first_step(flow, m0, t0, dt, name, body_name);
  const double k = k_max + 1.0;  // the first step whose end mass fails
  // the grid times as the run loop computes them (t0 + i dt)
  const double t_start = t0 + k_max * dt, t_end = t0 + k * dt;
  const double m_end = m0 + flow.rate * (k * dt);
  std::string base = out_of_mass_error(name, body_name, m_end, t_end, t_start).what();
  if (m_end > 0.0) {  // positive, but within the round-off of its accumulation
    base = name + ": expected a mass above the round-off of its accumulation (16 eps k m0 = " +
           format_value(mass_roundoff_per_step * k * m0) + " kg), got m = " + format_value(m_end) + " kg at t = " +
           format_value(t_end) + " s (the body '" + body_name + "' runs out of mass in the step from t = " +
           format_value(t_start) + " s)";
  }
  throw std::invalid_argument(base + "; steps, dt: expected a run that ends before the mass runs out at t = " +
                              format_value(burn_out_time(m0, flow.rate, t0)) + " s (at most " +
                              format_value(static_cast<std::int64_t>(k_max)) + " steps of dt = " + format_value(dt) +
                              " s), got " + format_value(steps) + " steps");
}

}  // namespace rigiddyn
