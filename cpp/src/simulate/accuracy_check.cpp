#include "rigiddyn/simulate/accuracy_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

namespace rigiddyn {

namespace {

double norm3(const double* v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// A number as Python's format(x, spec) for the specs the message uses ("%.3g", "%.6g", "%g").
std::string formatted(const char* spec, double x) {
  char text[64];
  std::snprintf(text, sizeof text, spec, x);
  return text;
}

// Whether the estimate is reliable at each record (n,); empty (none is) without one.
std::vector<bool> reliable_records(const GlobalErrorEstimate* e, std::size_t n) {
  if (e == nullptr) return {};
  std::vector<bool> reliable(n, false);
  for (std::size_t i = 0; i < n && i < e->verdict.size(); ++i) reliable[i] = is_reliable(e->verdict[i]);
  return reliable;
}

// What residual q may be at record i: max(estimate_factor · bound, estimate_floor · level · scale) + round-off where
// the estimate is reliable (and that allowance finite), else level · scale + round-off.
double allowance_at(const RunBalance& b, std::size_t q, const AccuracyCheck& c, const std::vector<bool>& reliable,
                    std::size_t i) {
  const double fallback = c.level * b.scale(q)[i] + b.round_off(q)[i];
  if (reliable.empty() || !reliable[i] || c.bounds == nullptr || i >= (*c.bounds)[q].size()) return fallback;
  const double estimated = estimate_factor * (*c.bounds)[q][i], floor = estimate_floor * c.level * b.scale(q)[i];
  const double bound = std::max(estimated, floor) + b.round_off(q)[i];
  return std::isfinite(estimated) && std::isfinite(floor) && std::isfinite(bound) ? bound : fallback;
}

// A quantity beyond its allowance: how far (residual / allowance at its worst record) and the message's text.
struct Finding {
  double ratio;
  std::string text;
};

}  // namespace

BalanceBounds scene_estimate_bounds(const GlobalErrorEstimate& e, const SceneSimulation& r) {
  const std::size_t n = e.energy.size();
  const auto nb = static_cast<std::size_t>(r.body_count);
  BalanceBounds out;
  out[static_cast<std::size_t>(BalanceQuantity::energy)] = e.energy;
  auto& linear = out[static_cast<std::size_t>(BalanceQuantity::linear_momentum)];
  auto& angular = out[static_cast<std::size_t>(BalanceQuantity::angular_momentum)];
  linear.assign(n, 0.0), angular.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < nb; ++k) {
      const std::size_t at = i * nb + k;
      const double m = r.mass[at], H_C = norm3(&r.angular_momentum_O_W[3 * at]), w = norm3(&r.w_B[3 * at]);
      const double lambda = w > 0 ? H_C / w : 0.0;  // |H_C| / |w|: I's moment about w, exact for a sphere
      linear[i] += m * e.velocity[at];
      angular[i] += m * (norm3(&r.v_W[3 * at]) * e.position[at] + norm3(&r.p_W[3 * at]) * e.velocity[at]) +
                    H_C * e.attitude[at] + lambda * e.angular_velocity[at];
    }
  }
  return out;
}

std::string check_accuracy(RunBalance& b, const AccuracyCheck& c) {
  const std::size_t n = b.size();
  const std::vector<bool> reliable = reliable_records(c.estimate, n);
  std::vector<Finding> findings;
  for (std::size_t q = 0; q < balance_quantity_count; ++q) {
    if (!b.applies(static_cast<BalanceQuantity>(q))) continue;
    // the record furthest beyond its allowance (a record that overflowed is not: simulate warns of it)
    std::size_t worst = n;
    double worst_ratio = 0.0, worst_allowance = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double r = std::abs(b.residual(q)[i]);
      if (!std::isfinite(r)) continue;
      const double allowance = allowance_at(b, q, c, reliable, i);
      if (!(r > allowance)) continue;
      const double ratio = r / std::max(allowance, std::numeric_limits<double>::min());
      if (worst == n || ratio > worst_ratio) worst = i, worst_ratio = ratio, worst_allowance = allowance;
    }
    if (worst == n) continue;
    const char* unit = balance_quantity_units[q];
    const double r = std::abs(b.residual(q)[worst]), scale = b.scale(q)[worst];
    const std::string relative = scale > 0 ? " (" + formatted("%.3g", r / scale) + " of its scale " +
                                                 formatted("%.3g", scale) + " " + unit + ")"
                                           : std::string();
    const bool reliable_there = !reliable.empty() && reliable[worst];
    const std::string why =
        reliable_there ? "beyond " + formatted("%g", estimate_factor) + " x the reliable global error estimate's bound (" +
                             formatted("%.3g", worst_allowance) + " " + unit +
                             " with round-off): the estimate is contradicted"
                       : "beyond the level " + formatted("%g", c.level) +
                             " of its scale (no reliable global error estimate there)";
    std::string name = balance_quantity_names[q];
    std::replace(name.begin(), name.end(), '_', ' ');
    std::string text = "the " + name + " balance is off by " + formatted("%.3g", r) + " " + unit + relative +
                       " at t = " + formatted("%.6g", (*c.t)[worst]) + " s, " + why;
    b.verdict[q] = "open: " + text;
    findings.push_back({worst_ratio, std::move(text)});
  }
  if (findings.empty()) return {};
  std::stable_sort(findings.begin(), findings.end(), [](const Finding& x, const Finding& y) { return x.ratio > y.ratio; });
  std::string message = "simulate: " + findings[0].text;
  for (std::size_t k = 1; k < findings.size(); ++k) message += "; also " + findings[k].text;
  return message + ". The records of this run (method '" + c.method + "', dt = " + formatted("%g", c.dt) +
         ") are not accurate: use a smaller dt or another method (see methods()), or pass accuracy_level=None to "
         "silence this check";
}

bool closes_under_any_estimate(const RunBalance& b, double level) {
  for (std::size_t q = 0; q < balance_quantity_count; ++q) {
    if (!b.applies(static_cast<BalanceQuantity>(q))) continue;
    for (std::size_t i = 0; i < b.size(); ++i) {
      const double r = std::abs(b.residual(q)[i]);  // (one that overflowed is skipped, as check_accuracy does)
      if (std::isfinite(r) && r > estimate_floor * level * b.scale(q)[i] + b.round_off(q)[i]) return false;
    }
  }
  return true;
}

}  // namespace rigiddyn
