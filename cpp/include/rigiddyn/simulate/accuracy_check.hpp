// The accuracy check at the end of a run: does each balance (balance.hpp) close within what the run's error allows?
//
// The rule, per quantity q and record i where q applies: |r_q,i| must not exceed
//     max(estimate_factor · (the estimate's bound of r_q,i), estimate_floor · level · scale_q,i) + round_off_q,i
// where the global error estimate is reliable at i (a larger residual contradicts the estimate), else
//     level · scale_q,i + round_off_q,i.
// The estimate's bound of a residual is first order in the state errors (global_error.hpp):
//   energy            the estimate of the total energy's error;
//   linear momentum   Σ_b m_b δv_b;
//   angular momentum  Σ_b (m_b (|v_b| δp_b + |p_b| δv_b) + |H_C,b| δθ_b + λ_b δω_b) for a scene (H about W's origin,
//                     λ_b = |H_C,b| / |ω_b|, exact for a sphere), |H_C| δθ + λ δω for one body (H about its centre of
//                     mass, λ a bound of its largest principal moment).
// A residual beyond its allowance sets the quantity's verdict to "open: <the figure>"; the message of the
// AccuracyWarning names the quantity furthest beyond its allowance first.
#pragma once
#include "rigiddyn/simulate/balance.hpp"
#include "rigiddyn/simulate/global_error.hpp"

#include <array>
#include <string>
#include <vector>

namespace rigiddyn {

// The relative residual (of the quantity's scale) beyond which a run without a reliable global error estimate
// warns. A well-resolved run closes its balances to 1e-6 of the scale or better (rk4 at dt |w| = 0.05 on a tumbling
// body: 2e-9); 1e-3 is three orders above and far below the failures worth a warning (whole percents).
inline constexpr double default_accuracy_level = 1e-3;

// The factor on the global error estimate's bound of a residual where the estimate is reliable: a reliable estimate
// was within 0.5-2x the true error (docs/guide, global error), and a residual combines the error of the state with
// that of the integrated works or impulses (of the same size): 10 leaves margin for both.
inline constexpr double estimate_factor = 10.0;

// The least allowance of a residual where the estimate is reliable, as a fraction of the level (1e-4 of the scale by
// default): the estimate of the total energy's error does not cover the integrated works' and mass-flow energies'
// own error, which can exceed it by orders (measured: implicit_midpoint on a body losing mass, a residual of 1.1e-5
// of the scale against an estimate 1000x smaller; rk4 on a rocket near t0, 8e-11 against 100x smaller). A reliable
// estimate thus lowers the level by at most 10x and raises it where the estimate itself reports a larger error.
inline constexpr double estimate_floor = 0.1;

// The estimate's bound of each residual per record, (n,) each, indexed by BalanceQuantity.
using BalanceBounds = std::array<std::vector<double>, balance_quantity_count>;

// The bounds for a scene's run `r` from its estimate `e` ((n, nb) state quantities).
BalanceBounds scene_estimate_bounds(const GlobalErrorEstimate& e, const SceneSimulation& r);

// What a run's accuracy check needs besides its balance: its estimate (null: none), the estimate's bounds of the
// residuals (bounds_of above; ignored without an estimate), the relative level, the record times t (n,) [s], the
// method's name and the step dt [s] (for the message).
struct AccuracyCheck {
  const GlobalErrorEstimate* estimate = nullptr;
  const BalanceBounds* bounds = nullptr;
  double level = default_accuracy_level;
  const std::vector<double>* t = nullptr;
  std::string method;
  double dt = 0.0;
};

// Applies the rule to `balance`: sets the verdict of every quantity that applies ("closed" or "open: ...") and
// returns the AccuracyWarning's message, "" when every balance closes. E.g. "simulate: the energy balance is off by
// 0.35 J (0.34 of its scale 1.02 J) at t = 238 s, beyond the level 0.001 of its scale (no reliable global error
// estimate there); also ... . The records of this run (method 'rk4', dt = 1.98) are not accurate: use a smaller dt
// or another method (see methods()), or pass accuracy_level=None to silence this check".
std::string check_accuracy(RunBalance& balance, const AccuracyCheck& check);

// Whether `balance` closes at relative `level` whatever the run's global error estimate says: every residual that
// applies within estimate_floor · level · scale + round-off, the least allowance the rule above gives a record (with
// a reliable estimate at least that, without one level · scale + round-off). check_accuracy then sets the same
// verdicts with or without an estimate, so a run may make its estimate later (or never).
bool closes_under_any_estimate(const RunBalance& balance, double level);

}  // namespace rigiddyn
