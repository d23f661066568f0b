#include "rigiddyn/simulate/tolerance.hpp"

#include "numbers.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/closest_name.hpp"
#include "rigiddyn/simulate/run_loop.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace rigiddyn {

namespace {

using detail::nan;


// The values per record of `measure` in e: nb for the state quantities, 1 for energy and |L|.
std::size_t width_of(const GlobalErrorEstimate& e, ErrorMeasure measure) {
  const bool one_value = measure == ErrorMeasure::energy || measure == ErrorMeasure::angular_momentum;
  return one_value ? 1 : static_cast<std::size_t>(e.bodies);
}

// Whether the verdict of some record of `verdicts` satisfies `says` (each distinct text read once).
template <class Predicate>
bool any_record_says(const Verdicts& verdicts, Predicate says) {
  std::vector<char> said;
  for (const std::string& text : verdicts.texts()) said.push_back(says(text));
  for (std::size_t i = 0; i < verdicts.size(); ++i) {
    if (said[verdicts.text_index(i)]) return true;
  }
  return false;
}

// What the certificate makes of a verdict: accepted, accepted where its estimate is negligible (an order outside the
// window), or refused
enum class Acceptance : char { accepted, accepted_if_negligible, refused };

// The acceptance of each distinct verdict text of e (Verdicts::texts' order; each text read once)
std::vector<Acceptance> acceptance_of_texts(const GlobalErrorEstimate& e) {
  const std::string_view between = "interpolated between the reliable records";  // both neighbours checked
  std::vector<Acceptance> kind;
  for (const std::string& v : e.verdict.texts()) {
    const bool accepted = is_reliable(v) || v.compare(0, between.size(), between) == 0 || above_the_window(v);
    kind.push_back(accepted ? Acceptance::accepted
                   : v.compare(0, 15, "not asymptotic:") == 0 ? Acceptance::accepted_if_negligible
                                                              : Acceptance::refused);
  }
  return kind;
}

// x in (0, 1] as a / b in lowest terms with b <= max_denominator and |x − a / b| <= 1e-12 x (the convergents of its
// continued fraction, the best approximations with bounded denominators: Hardy & Wright, "An Introduction to the
// Theory of Numbers", ch. 10); none where no convergent is that close. (A looser match would find a fraction for any
// x: every real is within 1 / b² of a convergent a / b, ibid.)
std::optional<std::pair<std::int64_t, std::int64_t>> fraction_of(double x, std::int64_t max_denominator) {
  std::int64_t a0 = 0, b0 = 1, a1 = 1, b1 = 0;  // the convergents before the current one
  double rest = x;
  for (int k = 0; k < 64; ++k) {
    const double whole = std::floor(rest);
    if (whole > 1e12) break;
    const auto q = static_cast<std::int64_t>(whole);
    const std::int64_t a = q * a1 + a0, b = q * b1 + b0;
    if (b > max_denominator) break;
    if (std::abs(x - static_cast<double>(a) / static_cast<double>(b)) <= 1e-12 * x) return std::pair(a, b);
    a0 = a1, b0 = b1, a1 = a, b1 = b;
    if (rest == whole) break;
    rest = 1.0 / (rest - whole);
  }
  return std::nullopt;
}

}  // namespace

std::string refinements_text(int refinements) {
  return refinements == 1 ? "the refinement" : std::to_string(refinements) + " refinements";
}

bool says_runs_unstable(const std::string& verdict) {
  return verdict.find("stability limit") != std::string::npos || verdict.find("diverged") != std::string::npos;
}

bool runs_unstable(const GlobalErrorEstimate& e) { return any_record_says(e.verdict, says_runs_unstable); }

void keep_stability_verdicts(const GlobalErrorEstimate& all, GlobalErrorEstimate& measure) {
  std::vector<char> unstable;  // per distinct text of all's verdicts: each read once
  for (const std::string& text : all.verdict.texts()) unstable.push_back(says_runs_unstable(text));
  for (std::size_t i = 0; i < all.verdict.size() && i < measure.verdict.size(); ++i) {
    if (!unstable[all.verdict.text_index(i)]) continue;
    measure.verdict.set(i, all.verdict[i]);
    if (i < measure.reliable_quantities.size()) measure.reliable_quantities[i] = 0;
  }
}

void keep_low_orders_refused(const GlobalErrorEstimate& all, ErrorMeasure quantity, GlobalErrorEstimate& measure) {
  const std::uint8_t bit = measure_bit(quantity);
  const double lowest = measure.order - std::log2(quantity_window);  // 2^p / quantity_window
  for (std::size_t i = 0; i < measure.verdict.size() && i < all.reliable_quantities.size(); ++i) {
    const double q = measure.observed_order[i];
    if ((all.reliable_quantities[i] & bit) != 0 || !(q < lowest) || !is_reliable(measure.verdict[i])) continue;
    char order[32];
    std::snprintf(order, sizeof order, "%.2g", q);
    measure.verdict.set(i, "not asymptotic: observed order " + std::string(order) + " where " +
                               std::to_string(measure.order) + " is expected (" + error_measure_name(quantity) +
                               ", below 2^p / " + tolerance_detail::format_number(quantity_window) +
                               " where another quantity of its record fails its check)");
    measure.reliable_quantities[i] = 0;
  }
}

const std::vector<std::string>& error_measure_names() {
  static const std::vector<std::string> names = {"attitude", "angular_velocity", "position",
                                                 "velocity", "energy",           "angular_momentum"};
  return names;
}

std::string error_measure_name(ErrorMeasure measure) {
  return error_measure_names().at(static_cast<std::size_t>(measure));
}

std::string error_measure_unit(ErrorMeasure measure) {
  static const std::vector<std::string> units = {"rad", "rad/s", "m", "m/s", "J", "kg m^2/s"};
  return units.at(static_cast<std::size_t>(measure));
}

ErrorMeasure error_measure_from_name(const std::string& name, const std::string& argument) {
  const auto& names = error_measure_names();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<ErrorMeasure>(i);
  }
  std::string listed;
  for (const std::string& n : names) listed += (listed.empty() ? "'" : ", '") + n + "'";
  throw_invalid(argument, "one of " + listed + did_you_mean(name, names), "'" + name + "'");
}

double largest_error(const GlobalErrorEstimate& e, ErrorMeasure measure) {
  double largest = 0.0;
  for (const double v : values_of(e, measure)) {
    if (std::isnan(v)) return nan;
    largest = std::max(largest, v);
  }
  return largest;
}

// A ratio r = d(y_2h, y_4h) / d(y_h, y_2h) above 1.5 · 2^p: an error falling faster than h^p (q > p), whose
// estimate d(y_h, y_2h) / (2^p − 1) = C h^q (2^q − 1) / (2^p − 1) exceeds the error C h^q: conservative. (The other
// cause, an error all three runs share, is a force switching inside a step: refused before any run.)
bool above_the_window(const std::string& verdict) {
  // "not asymptotic: observed order <q> where <p> is expected ...", read with std::from_chars (sscanf cost ~1 000
  // instructions a text, and a call reads hundreds)
  constexpr std::string_view head = "not asymptotic: observed order ", middle = " where ", tail = " is expected";
  const std::string_view v = verdict;
  if (v.substr(0, head.size()) != head) return false;
  const char* end = v.data() + v.size();
  double observed = 0.0;
  int expected = 0;
  auto read = std::from_chars(v.data() + head.size(), end, observed);
  if (read.ec != std::errc() || std::string_view(read.ptr, end - read.ptr).substr(0, middle.size()) != middle) {
    return false;
  }
  read = std::from_chars(read.ptr + middle.size(), end, expected);
  if (read.ec != std::errc() || std::string_view(read.ptr, end - read.ptr).substr(0, tail.size()) != tail) return false;
  return observed > expected + std::log2(1.5);
}

std::size_t first_unreliable(const GlobalErrorEstimate& e, ErrorMeasure measure, double tolerance) {
  const std::vector<double>& values = values_of(e, measure);
  const std::size_t width = width_of(e, measure);
  const auto negligible = [&](std::size_t i) {  // every estimate of record i <= tolerance / 16
    for (std::size_t b = 0; b < width; ++b) {
      if (!(values[i * width + b] <= tolerance / 16.0)) return false;
    }
    return true;
  };
  const std::vector<Acceptance> kind = acceptance_of_texts(e);
  for (std::size_t i = 0; i < e.verdict.size(); ++i) {
    const Acceptance k = kind[e.verdict.text_index(i)];
    if (k == Acceptance::refused || (k == Acceptance::accepted_if_negligible && !negligible(i))) return i;
  }
  return e.verdict.size();
}

double observed_order_of_largest(const GlobalErrorEstimate& e, ErrorMeasure measure) {
  const std::vector<double>& values = values_of(e, measure);
  const std::size_t width = width_of(e, measure);
  const double factor = std::exp2(e.order) - 1.0;  // d1 = ε (2^p − 1)
  double d1 = 0.0, d2 = 0.0;
  for (std::size_t i = 0; i < e.observed_order.size(); ++i) {
    if (!std::isfinite(e.observed_order[i])) continue;  // at round-off, or not checked (interpolated)
    double epsilon = 0.0;
    for (std::size_t b = 0; b < width; ++b) epsilon = std::max(epsilon, values[i * width + b]);
    d1 = std::max(d1, epsilon * factor);
    d2 = std::max(d2, epsilon * factor * std::exp2(e.observed_order[i]));
  }
  return d1 > 0.0 ? std::log2(d2 / d1) : nan;
}

bool asymptotic_largest(const GlobalErrorEstimate& e, ErrorMeasure measure) {
  return observed_order_of_largest(e, measure) >= e.order - std::log2(1.5);
}

double certified_error(const GlobalErrorEstimate& e, ErrorMeasure measure) {
  const double largest = largest_error(e, measure);
  if (std::isnan(largest) || e.order < 1 || asymptotic_largest(e, measure)) return largest;
  const std::vector<double>& values = values_of(e, measure);
  const std::size_t width = width_of(e, measure);
  const std::vector<Acceptance> kind = acceptance_of_texts(e);
  const double factor = std::exp2(e.order) - 1.0;  // ε = d(y_h, y_2h) / (2^p − 1)
  double figure = largest;
  for (std::size_t i = 0; i < e.verdict.size(); ++i) {
    if (kind[e.verdict.text_index(i)] != Acceptance::accepted_if_negligible) continue;
    for (std::size_t b = 0; b < width; ++b) figure = std::max(figure, factor * values[i * width + b]);
  }
  return figure;
}

std::size_t first_uncertified(const GlobalErrorEstimate& e, ErrorMeasure measure, double tolerance,
                              bool switch_inside_steps) {
  const std::size_t bad = first_unreliable(e, measure, tolerance);
  if (bad == e.verdict.size() || switch_inside_steps) return bad;
  // a run that diverged, whose step is beyond the stability limit (a coarse run's energy ran away: its error is no
  // power of h, whatever the order its largest error shows) or has no estimate is never certified
  const bool never = any_record_says(e.verdict, [](const std::string& v) {
    return says_runs_unstable(v) || v.compare(0, 11, "no estimate") == 0;
  });
  if (never) return bad;
  if (std::isnan(largest_error(e, measure))) return bad;
  return asymptotic_largest(e, measure) ? e.verdict.size() : bad;
}

bool switch_inside_coarse_step(const std::vector<double>& switch_times, const SimulationOptions& o) {
  const double coarse = 4.0 * o.dt, t_end = o.t0 + static_cast<double>(o.steps) * o.dt;
  return std::any_of(switch_times.begin(), switch_times.end(), [&](double s) {
    if (!(s > o.t0 && s < t_end)) return false;
    const double grid_time = o.t0 + std::round((s - o.t0) / coarse) * coarse;  // the nearest end of a coarse step
    return std::abs(s - grid_time) > detail::on_grid_tolerance(grid_time, o.dt);
  });
}

double extrapolation_order(const GlobalErrorEstimate& e, ErrorMeasure measure) {
  const double p = e.order, q = observed_order_of_largest(e, measure);
  return std::isfinite(q) ? std::clamp(q, p, p + 1.0) : p;
}

bool at_round_off(const GlobalErrorEstimate& e) {
  return std::none_of(e.observed_order.begin(), e.observed_order.end(), [](double q) { return std::isfinite(q); });
}

double measure_scale(const ErrorRecords& r, ErrorMeasure measure) {
  if (measure == ErrorMeasure::attitude) return 1.0;
  double largest = 0.0;
  for (std::size_t i = 0; i < r.n; ++i) {
    if (measure == ErrorMeasure::energy) {
      largest = std::max(largest, std::abs(r.energy_scale[i]) + std::abs(r.energy[i] - r.energy_scale[i]));
    } else if (measure == ErrorMeasure::angular_momentum) {
      largest = std::max(largest, r.momentum[i]);
    } else {
      const double* rows = measure == ErrorMeasure::angular_velocity ? r.w_B
                           : measure == ErrorMeasure::position       ? r.p_W
                                                                     : r.v_W;
      for (std::int64_t b = 0; b < r.bodies; ++b) {
        largest = std::max(largest, Eigen::Map<const Eigen::Vector3d>(rows + (i * r.bodies + b) * 3).norm());
      }
    }
  }
  return largest;
}

// ε(t_k) / (dt^p (t_k − t0)) at every record after t0 (Hairer, Nørsett & Wanner: ε ≈ C dt^p (t − t0)).
double error_constant(const GlobalErrorEstimate& e, const ErrorRecords& r, double dt, ErrorMeasure measure) {
  const std::vector<double>& values = values_of(e, measure);
  const std::size_t width = width_of(e, measure);
  double constant = 0.0;
  for (std::size_t i = 1; i < r.n && i * width < values.size(); ++i) {
    const double elapsed = r.t[i] - r.t[0];
    if (!(elapsed > 0.0)) continue;
    for (std::size_t b = 0; b < width; ++b) {
      constant = std::max(constant, values[i * width + b] / (std::pow(dt, e.order) * elapsed));
    }
  }
  return constant;
}

double predicted_error(double constant, int order, double dt, double horizon) {
  return constant * std::pow(dt, order) * horizon;
}

double step_for_error(double constant, int order, double horizon, double target) {
  if (!(constant > 0.0)) return std::numeric_limits<double>::infinity();
  return std::pow(target / (constant * horizon), 1.0 / order);
}

std::int64_t steps_for(double horizon, double dt_max, std::int64_t multiple) {
  const double blocks = std::ceil(horizon / (dt_max * static_cast<double>(multiple)) * (1.0 - 1e-12));
  return std::max<std::int64_t>(1, static_cast<std::int64_t>(std::min(blocks, 9e15 / static_cast<double>(multiple)))) *
         multiple;
}

std::int64_t on_grid(std::int64_t multiple, std::int64_t grid_steps) {
  return grid_steps > 0 ? std::lcm(multiple, grid_steps) : multiple;
}

std::int64_t grid_steps_through(const std::vector<double>& times, double t0, double horizon, std::int64_t limit) {
  std::int64_t steps = 1;
  for (const double t : times) {
    const auto fraction = fraction_of((t - t0) / horizon, 10'000);
    if (!fraction) return 0;
    const auto [a, b] = *fraction;
    const std::int64_t needed = 4 * b / std::gcd(a, 4 * b);  // steps · a / (4 b) whole
    if (needed > limit / steps * std::gcd(steps, needed)) return 0;  // the lcm would exceed limit
    steps = std::lcm(steps, needed);
  }
  return steps;
}

double step_on_grid(double dt_max, double horizon, std::int64_t grid_steps) {
  if (grid_steps <= 0) return dt_max;
  const double block = horizon / static_cast<double>(grid_steps);
  return block / static_cast<double>(steps_for(block, dt_max, 1));  // the fewest steps of a block within dt_max
}

double refined_step(double dt, int order, double measured, double target) {
  const double shrink = std::pow(target / measured, 1.0 / order);
  return dt * std::min(std::isfinite(shrink) ? shrink : 0.5, std::exp2(-1.0 / order));
}

double order_cost_figure(int order, int evaluations, double relative) {
  return std::pow(relative, -1.0 / order) * std::max(evaluations, 1);
}

namespace tolerance_detail {

const PilotRun* cheapest_plan(const std::vector<PilotRun>& pilots, std::int64_t max_steps) {
  const auto planned = [&](const PilotRun& p) { return p.verdict == used && p.planned_steps <= max_steps; };
  double fastest = std::numeric_limits<double>::infinity();
  for (const PilotRun& p : pilots) {
    if (planned(p)) fastest = std::min(fastest, p.planned_seconds);
  }
  const auto evaluations = [](const PilotRun& p) {
    return static_cast<double>(p.planned_steps) * method_info(p.method).evaluations;
  };
  const PilotRun* best = nullptr;
  for (const PilotRun& p : pilots) {
    if (!planned(p) || !(p.planned_seconds <= plan_tie * fastest)) continue;
    if (best == nullptr || evaluations(p) < evaluations(*best)) best = &p;
  }
  return best;
}

Replan cheaper_with_growth(const std::vector<PilotRun>& pilots, const PilotRun& chosen, std::int64_t steps, double f,
                           double dt_run, const ToleranceRequest& request, std::int64_t multiple) {
  Replan out;
  if (!(f > 1.0) || !std::isfinite(f)) return out;
  const double T = request.horizon, target = request.safety * request.tolerance;
  double cheapest = static_cast<double>(steps) * chosen.seconds_per_step;
  for (const PilotRun& p : pilots) {
    if (p.verdict != used || p.order <= chosen.order || p.exact_on_scene ||
        !std::isfinite(p.constant) || !std::isfinite(p.seconds_per_step)) {
      continue;
    }
    const double dt = std::min({step_for_error(p.constant * f, p.order, T, target), p.dt, dt_run});
    const std::int64_t n = steps_for(T, dt, multiple);
    const double cost = static_cast<double>(n) * p.seconds_per_step;
    if (n <= request.max_steps && cost < cheapest) cheapest = cost, out = {&p, n};
  }
  return out;
}

std::string format_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string describe_choice(const ToleranceChoice& c, const PilotRun& chosen, std::size_t piloted) {
  const std::string unit = error_measure_unit(c.measure);
  std::string text = method_info(c.method).name + " at " + std::to_string(c.steps) + " steps of dt = " +
                     format_number(c.dt) + " s: ";
  if (c.order == 0) {
    text += "the closed form, its round-off bound " + format_number(c.predicted_error) + " " + unit;
  } else if (chosen.exact_on_scene) {
    text += "exact on this scene (its pilot's estimate is the round-off bound at every record), its round-off bound " +
            format_number(c.predicted_error) + " " + unit;
  } else {
    text += "predicted " + format_number(c.predicted_error) + " " + unit + " (C dt^" + std::to_string(c.order) +
            " t with C = " + format_number(chosen.constant) + " from a pilot of " + std::to_string(chosen.steps) +
            " steps over " + format_number(chosen.horizon) + " s)";
  }
  text += ", the cheapest of " + std::to_string(piloted) + " piloted method" + (piloted == 1 ? "" : "s") +
          " at an estimated " + format_number(chosen.planned_seconds) + " s";
  if (piloted > 1) text += " (plans within " + format_number(100.0 * (plan_tie - 1.0)) + " % a tie, by evaluations)";
  return text;
}

}  // namespace tolerance_detail

}  // namespace rigiddyn
