// Running to a tolerance: the library chooses the method and the step, runs, and certifies the result with the
// global error estimate (global_error.hpp).
//
// The error model of a method of order p over a run from t0 (Hairer, Nørsett & Wanner, "Solving Ordinary
// Differential Equations I", the global error of a one-step method grows at most like its local error summed):
//     ε(t) ≈ C dt^p (t − t0)                                   (linear growth in t),
// C fitted on a short pilot run whose own Richardson estimate passed its order check (so that the pilot is in
// the asymptotic regime and the extrapolation in dt is sound). For a horizon T and a tolerance τ the largest
// step is then dt = (s τ / (C T))^(1/p), s the safety factor; the run's cost is its steps times the cost per step
// the pilot measured (plans within plan_tie of the cheapest a tie: cheapest_plan). The cheapest candidate is run
// with its estimate; a certificate that fails (not reliable, or above τ) is followed by a refinement
// dt' = dt (s τ / ε)^(1/p) (at most dt / 2 when the estimate was not reliable), at most max_refinements times: a
// step that the short pilots called asymptotic may not be over the whole horizon (a cluster's close encounters come
// later), and a halving is then a guess that the next certificate checks.
// A reliable certificate f times its prediction shows a growth g(t) of the error model C dt^p g(t) that the short
// pilots did not see, which every method shares. Each used candidate of a higher order is then planned again with its
// prediction scaled by f, and the refinement takes the cheapest of those plans and its own. Measured on a controller's
// grid, where every candidate's step was capped alike: a second-order splitting 493x its prediction over 4 orbits
// would have needed 7x its steps, where rk4 met the tolerance at the same steps. Two limits keep it from guessing: a
// plan's step is at most the refined run's (whose estimate saw the whole horizon at that step and coarser, and no
// other: on the cluster, rk4 at a coarser step met close encounters unseen), and a method of the same order gains
// nothing from the growth (on the cluster, a splitting and exact_flow_kick, alike there, took turns at the same steps).
// A certificate that is the round-off bound at every record (at_round_off) is not refined: that bound grows with the
// steps, so the tolerance is below what the run can certify in double precision.
//
// The fewest steps first: before any pilot, the first candidate (one that may be exact on the scene, else the first
// of the highest order) runs over the whole horizon at the fewest steps a run takes (16, fewest_run_steps) with its
// estimate. Where that certificate holds within s τ, the call is that run; where it holds above s τ and its error,
// scaled by dt^q as the whole-horizon pilot's below, asks for at most 64 steps (direct_plan_steps), those steps are
// the plan and no method is piloted: a pilot's first attempt (1.75 runs of 16 steps) would cost more than a better
// method could save on so short a run. Otherwise the pilots follow, at the price of that first run (28 steps of
// 16). The caller compiles a model for a candidate's method only where the planner runs it (`admit`), where each was
// compiled and probed before planning began. Instructions of a call of `simulate(..., tolerance=)` (callgrind),
// before → after: the shipped rocket to 0.4 m 850 000 → 205 000 (met at 16 steps) and to 4 mm 812 000 → 381 000
// (planned at 28), the solar array to 1e-3 rad 9.98M → 3.11M (met at 24: a grid of 12 steps), a torque-free body
// to 1e-5 rad 466 000 → 297 000 (exact_flow_kick, met at 16 after a pilot before); the three-body scene to 1 mm
// 5.12M → 5.25M (its first run not certified) and the pendulum to 1e-5 rad 15.60M → 15.65M.
//
// Pilots: 16 steps over T/4 first; while the pilot's estimate is not reliable its horizon is halved (down to T/32, the
// step with it) and then its steps doubled (up to 512). Its cost is that of ~28 steps whatever the horizon, a small
// part of any run long enough to need a choice. A later candidate's pilot starts one attempt before the coarsest an
// earlier pilot was used at, not at T/4: the attempts coarser than that found the scene's motion unresolved for the
// earlier methods, and one of them is still tried for a method that resolves it at a coarser step (the shipped
// pendulum at 1e-3 rad made 17 attempts for its five pilots, each 3 runs and an estimate; now 13, with the same
// pilots used). A run's step is at most its pilot's (see below), except for a method
// exact on the scene: one whose flow is exact without torques (exact_torque_free) and whose pilot's estimate is its
// round-off bound at every record (a torque-free body) has no truncation error and no stability limit, and runs at the
// fewest steps the planner gives a run (fewest_run_steps); such a method is piloted first, and where it is exact
// no other is piloted (none takes fewer steps). Candidates are pruned by order before their pilot: an
// order-p method needs ~(τ/scale)^(−1/p) steps per unit of the problem's time scale, times its evaluations per step;
// one whose figure is above 8x the best candidate's is not piloted (unless it is exact on a torque-free body: its error
// may be round-off). Nor is a candidate that takes another candidate's steps on the model (ToleranceCandidate::same_as:
// a Lie-group method where no body turns in 3D, scene/method_twins.hpp), whose pilot would cost more for the same
// error (measured with callgrind, `simulate(..., tolerance=)` a call: the shipped Kepler orbit at 8 km 14.36M → 13.74M
// instructions, the three-body scene at 1e-5 m 3.84M → 3.19M, the pendulum at 1e-5 rad 16.32M → 15.61M).
//
// The short pilots rank the candidates; the chosen one (when its run has 64 steps or more) then runs over the whole
// horizon at a quarter of its steps, and the largest error of that run, scaled by dt^q (extrapolation_order: the order
// q that error showed, in [p, p + 1]), sets the steps without a growth model: the error can jump after the short
// pilot's span (a flip near a separatrix: measured 10x above the linear growth from the first quarter). It records at
// the final run's common records, so that when the final run takes exactly 4x its steps it is that run's 4h run: the
// final run and its estimate then cost 1.5x the run instead of 1.75x, and the whole-horizon pilot (0.44x the final run
// with its 8h and 16h runs) costs a net 0.19x, less than the refinement it spares (1.75x the run and more). The final
// run takes 4x its steps where the steps it needs are between 6/7 of that and that (a cheaper run then with its own
// estimate would cost more). It is not run where its step, 4 dt, is at or above a step at which the chosen method's
// pilot found its runs beyond the stability limit (PilotRun::unstable_step): its runs at 4 dt, 8 dt and 16 dt, each
// at least as coarse as that pilot's at dt', 2 dt' and 4 dt', would be too. A plan capped at its pilot's step by
// stability comes there: the shipped satellite boom (a stiff spring) to 1e-3 rad ran it at 2 048 steps, unstable,
// before its 8 192-step run (callgrind, a call: 189.3M → 167.1M instructions).
//
// On a grid (ToleranceRequest::grid_steps: a run under a controller sampled every P, 4T/P blocks of P/4; a scene whose
// loads switch at fractions a/b of the horizon, grid_steps_through) every step the planner takes divides a block: a
// pilot's step is the largest divisor of T / grid_steps within its span / n, and every run over the horizon takes a
// multiple of the grid's steps. Each run of an estimate, at dt, 2 dt and 4 dt, then steps onto every sample and
// switch, as the premise of Richardson extrapolation needs (one inside a step of the coarse runs alone changes their
// error by more than a power of dt: the shipped solar array's certificate was 4.2x below its true error). The
// whole-horizon pilot runs only where the grid leaves it at most half the final run's steps.
//
// The method 'exact' (order 0, a closed form) has no truncation error: its error is the round-off bound of the
// run, and its cost is per record, not per step. It runs at the step of the cheapest stepping candidate (so
// that its records are the same) when that is cheaper.
#pragma once
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/simulate/global_error.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rigiddyn {

// "attitude", ... in ErrorMeasure's order; the unit of each ("rad", "rad/s", "m", "m/s", "J", "kg m^2/s").
const std::vector<std::string>& error_measure_names();
std::string error_measure_name(ErrorMeasure measure);
std::string error_measure_unit(ErrorMeasure measure);
// The measure named `name`; std::invalid_argument naming `argument` (with the nearest name) for another.
ErrorMeasure error_measure_from_name(const std::string& name, const std::string& argument = "measure");

// The largest estimate of `measure` over every record (and body) of `e`; NaN if a record has none.
double largest_error(const GlobalErrorEstimate& e, ErrorMeasure measure);

// The first record the certificate does not accept: a verdict other than "reliable", "interpolated between the
// reliable records ..." (a record between two checked ones, when record_every is not a multiple of 4), an
// observed order above the window (the estimate over-estimates there: see above_the_window), and an order outside
// it where the estimate of `measure` is at most tolerance / 16 (a zero crossing of an oscillating error, or the
// round-off of the first records, where the ratio is noise: an estimate 16x too small would still meet the
// tolerance); e.verdict.size() when none.
std::size_t first_unreliable(const GlobalErrorEstimate& e, ErrorMeasure measure, double tolerance);
// The observed order of the largest error over the records: log2(max_i d(y_2h, y_4h) / max_i d(y_h, y_2h)) of
// `measure`, from the checked records (NaN: none). The tolerance bounds that largest error, and its ratio is
// smooth in h where a record's ratio is noise (a record near a zero crossing of an oscillating error, e.g. a
// pendulum's angle error at a turning point, where a higher-order term dominates).
double observed_order_of_largest(const GlobalErrorEstimate& e, ErrorMeasure measure);
// Whether that order lies at or above the window's lower end (2^p / 1.5): the largest error falls as a power of h.
bool asymptotic_largest(const GlobalErrorEstimate& e, ErrorMeasure measure);

// The certificate: first_unreliable, or, where a record fails, e.verdict.size() all the same when no run diverged
// or went beyond the stability limit (says_runs_unstable), every record has an estimate, the largest error's
// observed order is at or above the window's lower end (2^p / 1.5) and no load switches inside a step of the
// estimate's runs (`switch_inside_steps`: switch_inside_coarse_step); else the first record not accepted. A switch
// inside a step makes the runs at h, 2h and 4h split their steps at different places, whose errors are then no common
// power of h: measured on the shipped solar array with its motor's switch moved off the grid (10.0123457 s of 30 s),
// the largest error's order was in the window while the certificate was 4x below the true error (7.7x for 9.87654321
// s), and the failing records said so.
std::size_t first_uncertified(const GlobalErrorEstimate& e, ErrorMeasure measure, double tolerance,
                              bool switch_inside_steps = false);

// The figure a certificate of `measure` states for e: its largest estimate over the records (and bodies), except where
// the largest error's order is not asymptotic (asymptotic_largest): a record the certificate accepts only because its
// estimate is negligible (an observed order below the window: first_unreliable) then counts its difference
// d(y_h, y_2h) = (2^p − 1) ε unextrapolated. Richardson's division by 2^p − 1 presumes the error a power of h, which
// neither that record's order nor the largest error's vouches for; of two runs whose results differ by d, one is at
// least d / 2 off. (Where the largest error is asymptotic, such records are noise about it, an oscillating error's
// zero crossings: the three-body scene's have differences 13x its largest estimate, which is within 1.5x of its true
// error.) Measured on the shipped satellite boom (rk4 at 8 192 steps to 1e-7 rad: the rounding of positions 7 000 km
// from W's origin, through the boom's stiff spring, turns its attitude by ~1e-9 rad at any step, and the largest
// error's order is 2.1): the largest estimate 2.9e-11 rad, its largest difference 4.3e-10 rad, against attitudes
// 3.0e-10 to 7.1e-10 rad from rk4 runs at 2x, 4x and 8x its steps. NaN if a record has no estimate.
double certified_error(const GlobalErrorEstimate& e, ErrorMeasure measure);

// Whether a load switches inside a step of the estimate's coarsest run of the run `o` (at 4 o.dt): a time of
// `switch_times` inside (t0, t0 + o.steps o.dt) more than a few ulps (run_loop.hpp's on_grid_tolerance) from
// t0 + k 4 o.dt.
bool switch_inside_coarse_step(const std::vector<double>& switch_times, const SimulationOptions& o);

// A verdict "not asymptotic: observed order q where p is expected" with q above the window (q > p + log2 1.5).
bool above_the_window(const std::string& verdict);

// The size of `measure` in the records (the largest norm over records and bodies; 1 rad for the attitude): the
// scale that makes a tolerance relative for pruning candidates by order.
double measure_scale(const ErrorRecords& r, ErrorMeasure measure);

// C of ε(t) ≈ C dt^p (t − t0) fitted on a pilot of step dt: the largest ε(t_k) / (dt^p (t_k − t0)) over the
// records after t0 (the pilot's records r, its estimate e of order p >= 1). Conservative where the error grows
// slower than linearly.
double error_constant(const GlobalErrorEstimate& e, const ErrorRecords& r, double dt, ErrorMeasure measure);

// C dt^p T: the predicted error of a run of step dt over a horizon T [s].
double predicted_error(double constant, int order, double dt, double horizon);

// The largest step whose predicted error over `horizon` is `target` (+inf when C is 0).
double step_for_error(double constant, int order, double horizon, double target);

// The fewest steps, a multiple of `multiple`, whose step horizon / steps is at most dt_max.
std::int64_t steps_for(double horizon, double dt_max, std::int64_t multiple);

// The multiple of a run's steps on a grid of grid_steps steps over the horizon: lcm(multiple, grid_steps), so that the
// run's step divides horizon / grid_steps (ToleranceRequest::grid_steps; `multiple` where grid_steps is 0).
std::int64_t on_grid(std::int64_t multiple, std::int64_t grid_steps);

// The fewest steps over [t0, t0 + horizon] whose blocks of four steps end at every time of `times` (each inside the
// horizon): for each time, (t − t0) / horizon as a fraction a / b in lowest terms (b at most 1e4, within 1e-12
// relative: times given in decimals), and the steps a multiple of 4b / gcd(a, 4b); their lcm over the times. 0 (no
// grid) where a time is no such fraction or the lcm exceeds `limit`. A load that switches at such a time then switches
// on a step's end in every run of an estimate, at dt, 2 dt and 4 dt alike (ToleranceRequest::grid_steps).
std::int64_t grid_steps_through(const std::vector<double>& times, double t0, double horizon, std::int64_t limit);

// The most steps of a grid through the loads' switch times (grid_steps_through's limit when running to a tolerance):
// a finer grid costs more than certifying without it, where the certificate takes no record that fails
// (first_uncertified). Measured on the shipped solar array with its motor switching at 7.31 s and 17.77 s of 30 s:
// the grid (12 000 steps) made every run 12 000 steps long, where rk4 without it was certified at 16 to 132 steps
// (tolerances 1e-3 to 1e-9 rad, each within 1.2x of its true error); with switches at 3.3 s and 21.7 s (400 steps),
// 16 to 256.
inline constexpr std::int64_t switch_grid_limit = 256;

// The largest step at most dt_max that divides horizon / grid_steps: (horizon / grid_steps) / k for the least whole k
// (dt_max itself where grid_steps is 0).
double step_on_grid(double dt_max, double horizon, std::int64_t grid_steps);

// The step of a refinement: dt (target / measured)^(1/p), at most dt / 2^(1/p) (a refinement refines).
double refined_step(double dt, int order, double measured, double target);

// The refinements of a run to a tolerance after its first run, at most (each within the cost cap max_steps).
inline constexpr int max_refinements = 3;

// The order at which the error of a run of estimate e (order p) is extrapolated to a smaller step: its largest
// error's observed order q (observed_order_of_largest) where that lies in [p, p + 1] (an error that fell faster
// than dt^p from the estimate's run at 4h to the one at h, its leading term small at these steps), p + 1 above
// it, and p below p or where none was measured (the error model C dt^q of Hairer, Nørsett & Wanner above, q measured
// as global_error.hpp's observed order). The certificate then checks the run the extrapolation chose.
double extrapolation_order(const GlobalErrorEstimate& e, ErrorMeasure measure);

// A pilot's attempts, coarsest first: 16 steps over T/4, T/8, T/16 and T/32, then 32, 64, ... 512 steps over T/32
// (each attempt's step half the one before)
inline constexpr int pilot_attempts = 9;
struct PilotSpan {
  double span;         // [s]
  std::int64_t steps;
};
inline PilotSpan pilot_span(double horizon, int attempt) {
  return attempt < 4 ? PilotSpan{horizon / 4.0 / std::ldexp(1.0, attempt), 16}
                     : PilotSpan{horizon / 32.0, std::int64_t{16} << (attempt - 3)};
}

// The fewest steps the planner gives a run over the whole horizon: the records of a method exact on the scene, and
// of the closed form when no stepping plan sets them.
inline constexpr std::int64_t fewest_run_steps = 16;

// Whether an estimate is its round-off bound at every record: no record's order was measured (each difference of
// the runs at h, 2h and 4h at or below the round-off of the run at h).
bool at_round_off(const GlobalErrorEstimate& e);

// "the refinement" (1), "2 refinements", ...
std::string refinements_text(int refinements);

// What a candidate needs, per unit of the problem's time scale, at relative tolerance `relative`:
// relative^(−1/p) steps times `evaluations` per step (the order pruning's figure).
double order_cost_figure(int order, int evaluations, double relative);

// The estimates of a run: every quantity's (result.error) and the measure's alone (its certificate:
// estimate_global_error with `only`, the other quantities neither estimated nor checked), so that the certificate's
// verdicts check the observed order of the measure only. (A record-wide verdict also checks the other quantities:
// rk4's energy error on a free body falls faster than dt^4 at a coarse step, which says nothing of the attitude's
// estimate.) Both from one pass over the common records (estimate_global_error_and_alone).
struct MeasuredEstimate {
  GlobalErrorEstimate all, measure;
};

// Whether a verdict says that a run of the estimate went beyond the stability limit or diverged ("step beyond the
// stability limit: ...", "... diverged").
bool says_runs_unstable(const std::string& verdict);
// Whether some record of e says so.
bool runs_unstable(const GlobalErrorEstimate& e);

// Copies to `measure` (the same records) every verdict of `all` that says_runs_unstable: those are facts of the
// runs, which no single measure's order shows (the measure's estimate does not see the energy that a coarse run
// gains beyond the stability limit, while its attitude error stays bounded).
void keep_stability_verdicts(const GlobalErrorEstimate& all, GlobalErrorEstimate& measure);

// Refuses the records of `measure` (the estimate of `quantity` alone) whose verdict is reliable where `all` (the same
// runs' estimate of every quantity) says another quantity of the record fails its check and `quantity`'s observed
// order lies below 2^p / quantity_window: the window reliable_for judges a quantity by at such a record
// (global_error.hpp), whose low side is where a higher-order term makes the estimate too small (measured: 2.05x
// below the true error at 2^4 / 1.29). Its high side over-estimates, which the certificate accepts (above_the_window).
// The record's verdict then names the order as a failed check does ("not asymptotic: observed order ...").
void keep_low_orders_refused(const GlobalErrorEstimate& all, ErrorMeasure quantity, GlobalErrorEstimate& measure);

// global_error's runs, estimated both ways (order 0, 'exact': the round-off bound alone, both ways).
template <class Records, class Run>
MeasuredEstimate measured_global_error(const Records& answer, const SimulationOptions& options, int order, Run&& run,
                                       ErrorMeasure measure) {
  if (order == 0) {
    GlobalErrorEstimate e = round_off_estimate(error_records(answer), options);
    return {e, e};
  }
  const Records twice = run(coarse_options(options, 2));
  const Records four_times = run(coarse_options(options, 4));
  const ErrorRecords h = answer_records(answer, options, order), h2 = coarse_records(twice),
                     h4 = coarse_records(four_times);
  auto [all, alone] = estimate_global_error_and_alone(h, h2, h4, options, order, measure);
  MeasuredEstimate out{std::move(all), std::move(alone)};
  keep_stability_verdicts(out.all, out.measure);
  keep_low_orders_refused(out.all, measure, out.measure);
  return out;
}

// A method the run may use, with the order the model has under it (scene_order; 0 for 'exact'), and the method it
// takes the same steps as on the model, if any (scene/method_twins.hpp plain_twin): where that one is a candidate
// too, this one is not piloted (its pilot would find the same error at more cost per step).
struct ToleranceCandidate {
  Method method;
  int order;
  std::optional<Method> same_as = std::nullopt;
};

// What run_to_tolerance is asked.
struct ToleranceRequest {
  double tolerance;      // τ, absolute, in the measure's unit
  ErrorMeasure measure;  // the quantity τ bounds (largest over records and bodies)
  double horizon;        // T = the run's duration [s]
  std::int64_t max_steps;  // the cost cap: no run of more steps (the final run and its refinement)
  double safety = 0.5;   // s: the run aims at s τ
  // every run's steps a multiple of this, so that every step divides T / grid_steps (0: any steps): 4T/P under a
  // controller sampled every P, and grid_steps_through the loads' switch times, so that each run of an estimate, at
  // dt, 2 dt and 4 dt, steps onto every sample and switch (one inside a step of the coarse runs alone breaks the
  // premise of Richardson extrapolation)
  std::int64_t grid_steps = 0;
  // the loads' switch times inside the horizon [s]: where one falls inside a step of a run's coarsest estimate run,
  // the certificate takes no record that fails (first_uncertified)
  std::vector<double> switch_times{};
};

// One pilot of a candidate (or why it has none).
struct PilotRun {
  Method method;
  int order = 0;
  double dt = 0.0, horizon = 0.0;         // its step and span [s]
  std::int64_t steps = 0;
  double error = std::numeric_limits<double>::quiet_NaN();     // its estimate at its end, in the measure's unit
  double constant = std::numeric_limits<double>::quiet_NaN();  // C of the fit
  double seconds_per_step = std::numeric_limits<double>::quiet_NaN();  // measured (per record for 'exact')
  std::int64_t planned_steps = 0;         // the run it predicts for τ
  double planned_seconds = std::numeric_limits<double>::quiet_NaN();
  std::string verdict;                    // "used", or why not (pruned, not asymptotic ...)
  bool exact_on_scene = false;            // its estimate the round-off bound at every record (fewest_run_steps)
  // the finest step of its attempts whose runs at dt, 2 dt and 4 dt went beyond the stability limit (runs_unstable)
  // or diverged [s]: the steps at and above which a run's estimate is never certified (+inf: none)
  double unstable_step = std::numeric_limits<double>::infinity();
};

// The choice and its outcome.
struct ToleranceChoice {
  Method method = Method::rk4;
  int order = 0;
  double dt = 0.0;
  std::int64_t steps = 0;
  double tolerance = 0.0;
  ErrorMeasure measure = ErrorMeasure::attitude;
  double predicted_error = std::numeric_limits<double>::quiet_NaN();
  double certified_error = std::numeric_limits<double>::quiet_NaN();  // the final run's certified_error()
  bool met = false;       // certified reliable and <= τ
  int refinements = 0;
  std::string reason;     // why this choice, and what happened
  std::vector<PilotRun> pilots;
  double pilot_seconds = 0.0, run_seconds = 0.0;  // wall time of the pilots, of the runs with their estimates [s]
};

template <class Records>
struct ToleranceRun {
  Records records;  // the final run (the best one when the tolerance was not met); empty if none ran
  GlobalErrorEstimate estimate;  // its estimate of every quantity (the certificate is the measure's alone)
  ToleranceChoice choice;
  bool ran = false;          // a final run exists
  bool interrupted = false;  // the monitor stopped a run
};

namespace tolerance_detail {

// The verdict of a pilot that is usable, and the text of the choice.
inline const std::string used = "used";

// A plan of another candidate: its pilot and its steps over the horizon.
struct Replan {
  const PilotRun* pilot = nullptr;
  std::int64_t steps = 0;
};

// After a reliable certificate f times the prediction of a run of `chosen` at step dt_run (f > 1: a growth g(t) of the
// error model C dt^p g(t) that the short pilots did not see, which the methods share), the used stepping candidate of
// a higher order than `chosen`'s whose plan with its prediction scaled by f, at a step of at most dt_run (and its
// pilot's), costs least, where that is less than `chosen`'s refinement of `steps` steps; no pilot where none is (or f
// is not > 1). (A low order whose step was capped with the others', e.g. at a controller's grid, may need many times
// their steps once its error is seen.)
Replan cheaper_with_growth(const std::vector<PilotRun>& pilots, const PilotRun& chosen, std::int64_t steps, double f,
                           double dt_run, const ToleranceRequest& request, std::int64_t multiple);
std::string describe_choice(const ToleranceChoice& c, const PilotRun& chosen, std::size_t piloted);
std::string format_number(double value);
double seconds_since(std::chrono::steady_clock::time_point start);

template <class Records>
double elapsed_of(const Records& r) {
  return r.elapsed_seconds;
}

// run(c, x) for the runs of one pilot (a run and its estimate's): their wall time added to `seconds`, a monitor's stop
// to out.interrupted
template <class Records, class Run>
auto timed_runs(Run& run, const ToleranceCandidate& c, double& seconds, ToleranceRun<Records>& out) {
  return [&run, &c, &seconds, &out](const SimulationOptions& x) {
    Records r = run(c, x);
    seconds += elapsed_of(r);
    out.interrupted = out.interrupted || r.interrupted;
    return r;
  };
}

// Plans whose planned seconds lie within this factor of the fastest's are a tie (cheapest_plan): the seconds per
// step a pilot of 16 steps measures repeat within ~10 % (the median of 12 calls over their fastest: 1.01-1.09 for
// every pilot of the shipped heavy top, pendulum, gravity gradient and three bodies while another job ran; single
// calls up to 1.7x), so that the fastest of two such plans is chance: in two sweeps of bench_tolerance.py, 11 of its
// 54 cases chose rk4 in one and rkmk4 in the other, 9 of them at the same steps; 4 with the tie. A wider tie would
// hold more (rkmk4's step costs 1.07-1.29x rk4's on the shipped scenes: at the same steps the two straddle 1.15), and
// would take plans with fewer evaluations that are slower by as much.
inline constexpr double plan_tie = 1.15;

// The plan a run to a tolerance takes among `pilots` (those used, within max_steps): the fastest by planned_seconds,
// where the plans within plan_tie of it are a tie, taken by the fewest planned evaluations (planned_steps x the
// method's evaluations per step; 'exact' none), then in the pilots' order (the candidates': rk4 first). Null when
// no pilot has a plan.
const PilotRun* cheapest_plan(const std::vector<PilotRun>& pilots, std::int64_t max_steps);

// The candidate a run to a tolerance tries first at the fewest steps (fewest_steps_run): the first that may be exact
// on the scene (exact_torque_free), else the first (of the highest order: the candidates' order); never 'exact' (the
// closed form, which has no steps to take), and only one that `usable(i)` (asked in that order, until one is: the
// model takes its method, and it takes no other candidate's steps). candidates.size() when none is.
template <class Usable>
std::size_t first_to_run(const std::vector<ToleranceCandidate>& candidates, Usable&& usable) {
  for (const bool exact_torque_free : {true, false}) {
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const ToleranceCandidate& c = candidates[i];
      if (c.order == 0 || method_info(c.method).exact_torque_free != exact_torque_free) continue;
      if (usable(i)) return i;
    }
  }
  return candidates.size();
}

// The most steps a plan from the run at the fewest steps takes without a pilot (fewest_steps_run): a pilot's first
// attempt alone costs 1.75 runs of 16 steps, as much as a third of such a run with its estimate.
inline constexpr std::int64_t direct_plan_steps = 4 * fewest_run_steps;

// What the run at the fewest steps found (fewest_steps_run): its figures as a pilot's, its verdict `used` where its
// certificate holds (the error then measured over the whole horizon), the order q its error is extrapolated at
// (extrapolation_order) and the size of the measure in its records (measure_scale).
struct FewestStepsRun {
  PilotRun run;
  double order = 0.0;
  double scale = std::numeric_limits<double>::quiet_NaN();
};

// The run no plan can make cheaper, tried before any pilot: candidates[first] over the whole horizon at the fewest
// steps a run takes (fewest_run_steps, rounded up to a multiple of `multiple`), with its estimate, where those steps
// are at most direct_plan_steps and within max_steps (none otherwise, or where a run was interrupted). Where its
// certificate holds within s τ (the error a planned run aims at), it is the final run: `out` holds it and its choice
// (met), and every other candidate is listed as not piloted (none could take fewer steps, and a pilot would cost as
// much as this run). (A short problem's pilots cost several times its run: on the shipped rocket to 0.4 m, three
// pilots and a whole-horizon pilot of 16 steps each came before a final run of 16 steps.)
template <class Records, class Run>
std::optional<FewestStepsRun> fewest_steps_run(const std::vector<ToleranceCandidate>& candidates, std::size_t first,
                                               const SimulationOptions& base, const ToleranceRequest& request,
                                               std::int64_t multiple, Run& run, ToleranceRun<Records>& out) {
  const double T = request.horizon;
  const std::int64_t steps = steps_for(T, T / static_cast<double>(fewest_run_steps), multiple);
  if (steps > direct_plan_steps || steps > request.max_steps) return std::nullopt;
  const ToleranceCandidate& c = candidates[first];
  SimulationOptions o = base;
  o.method = c.method, o.steps = steps, o.dt = T / static_cast<double>(steps);  // as the final run's step
  const auto start = std::chrono::steady_clock::now();
  double seconds = 0.0;
  const auto timed = timed_runs(run, c, seconds, out);
  Records h = timed(o);
  if (out.interrupted) return std::nullopt;
  MeasuredEstimate estimates = measured_global_error(h, o, c.order, timed, request.measure);
  if (out.interrupted) return std::nullopt;
  const GlobalErrorEstimate& e = estimates.measure;
  const ErrorRecords records = error_records(h);
  FewestStepsRun found;
  PilotRun& p = found.run;
  p.method = c.method, p.order = c.order, p.dt = o.dt, p.horizon = T, p.steps = steps;
  p.error = largest_error(e, request.measure);
  p.seconds_per_step = seconds / (1.75 * static_cast<double>(steps));
  p.planned_steps = steps, p.planned_seconds = static_cast<double>(steps) * p.seconds_per_step;
  found.scale = std::max(measure_scale(records, request.measure), 1e-300);
  const std::size_t bad =
      first_uncertified(e, request.measure, request.tolerance, switch_inside_coarse_step(request.switch_times, o));
  if (bad != e.verdict.size() || h.diverged || !(p.error <= found.scale)) {
    p.verdict = "not asymptotic at dt = " + format_number(o.dt) + " s over the whole horizon: " +
                (bad < e.verdict.size() ? e.verdict[bad] : h.diverged ? "diverged" : "its error exceeds the quantity");
    return found;
  }
  p.verdict = used;
  p.constant = error_constant(e, records, o.dt, request.measure);
  p.exact_on_scene = method_info(c.method).exact_torque_free && at_round_off(e);
  found.order = extrapolation_order(e, request.measure);
  const double certified = certified_error(e, request.measure);
  if (!(certified <= request.safety * request.tolerance)) return found;

  ToleranceChoice& choice = out.choice;
  const std::string name = method_info(c.method).name, unit = error_measure_unit(request.measure);
  const std::string why = p.exact_on_scene ? " is exact on this scene" : " met the tolerance at the fewest steps";
  const std::string not_piloted = "not piloted: " + name + why;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    PilotRun skipped;
    skipped.method = candidates[i].method, skipped.order = candidates[i].order, skipped.verdict = not_piloted;
    choice.pilots.push_back(i == first ? p : skipped);
  }
  choice.method = c.method, choice.order = c.order, choice.dt = o.dt, choice.steps = steps;
  choice.predicted_error = p.error, choice.certified_error = certified, choice.met = true;
  const std::string exact =
      p.exact_on_scene ? "exact on this scene (its estimate is the round-off bound at every record), " : "";
  choice.reason = name + " at " + std::to_string(steps) + " steps of dt = " + format_number(o.dt) +
                  " s, the fewest a run takes, tried first over the whole horizon: " + exact + "certified " +
                  format_number(certified) + " " + unit + ", within " + format_number(request.safety) +
                  "x the tolerance (no other method piloted: none takes fewer steps)";
  choice.run_seconds = seconds_since(start);
  out.records = std::move(h), out.estimate = std::move(estimates.all), out.ran = true;
  return found;
}

}  // namespace tolerance_detail

// Runs to τ: tries the fewest steps over the whole horizon first (fewest_steps_run), else pilots each candidate
// (highest order first, pruned by order_cost_figure), chooses the cheapest (method, dt) predicted to meet s τ, runs it
// with its estimate and refines once when the certificate fails. `base` gives t0, record_every and the monitor (its
// dt, steps and method are chosen here); run(candidate, options) returns the records of the model from its initial
// state (a Trajectory or a SceneSimulation). admit(candidate) says whether the model takes the candidate's method,
// asked once per candidate, before its first run and only for those the planner runs (so that a caller compiles a
// model for a method only where it runs): a candidate it refuses is left out, as if it had not been given.
// Never throws for an unmet tolerance: choice.met is false and choice.reason says why.
template <class Records, class Run, class Admit>
ToleranceRun<Records> run_to_tolerance(std::vector<ToleranceCandidate> candidates, const SimulationOptions& base,
                                       const ToleranceRequest& request, Run&& run, Admit&& admit) {
  using namespace tolerance_detail;
  const auto start = std::chrono::steady_clock::now();
  ToleranceRun<Records> out;
  ToleranceChoice& choice = out.choice;
  choice.tolerance = request.tolerance, choice.measure = request.measure;
  const double T = request.horizon, target = request.safety * request.tolerance;
  const std::int64_t m = common_record_steps(base.record_every);
  const std::int64_t multiple = on_grid(m, request.grid_steps);  // of a whole-horizon run's steps
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const ToleranceCandidate& a, const ToleranceCandidate& b) { return a.order > b.order; });

  // a candidate's entry in choice.pilots, its verdict `verdict` (its figures NaN until a pilot sets them)
  const auto pilot_entry = [](const ToleranceCandidate& c, std::string verdict) {
    PilotRun p;
    p.method = c.method, p.order = c.order, p.verdict = std::move(verdict);
    return p;
  };
  // one candidate's pilot (see above), the size of its measure (its records' measure_scale) where it is used, and the
  // attempt it was used at (pilot_span's; -1: none)
  struct Piloted {
    PilotRun run;
    double scale = std::numeric_limits<double>::quiet_NaN();
    int attempt = -1;
  };
  const auto pilot_of = [&](const ToleranceCandidate& c, int first_attempt) {
    Piloted out_c{pilot_entry(c, "")};
    PilotRun& p = out_c.run;
    for (int attempt = first_attempt; attempt < pilot_attempts; ++attempt) {
      const PilotSpan at = pilot_span(T, attempt);
      SimulationOptions o = base;
      o.method = c.method, o.dt = step_on_grid(at.span / static_cast<double>(at.steps), T, request.grid_steps);
      o.steps = at.steps, o.record_every = 4;
      double seconds = 0.0;
      const auto timed = timed_runs(run, c, seconds, out);
      const Records h = timed(o);
      if (out.interrupted) return out_c;
      const GlobalErrorEstimate e = measured_global_error(h, o, c.order, timed, request.measure).measure;
      if (out.interrupted) return out_c;
      const ErrorRecords records = error_records(h);
      p.dt = o.dt, p.horizon = o.dt * static_cast<double>(at.steps), p.steps = at.steps;
      p.error = e.verdict.empty() ? p.error : largest_error(e, request.measure);
      p.seconds_per_step = seconds / (1.75 * static_cast<double>(at.steps));
      const std::size_t bad =
          first_uncertified(e, request.measure, request.tolerance, switch_inside_coarse_step(request.switch_times, o));
      if (bad == e.verdict.size() && !h.diverged) {
        p.constant = error_constant(e, records, o.dt, request.measure);
        out_c.scale = std::max(measure_scale(records, request.measure), 1e-300);
        p.exact_on_scene = method_info(c.method).exact_torque_free && at_round_off(e);
        p.verdict = used;
        out_c.attempt = attempt;
        return out_c;
      }
      p.verdict = "not asymptotic at dt = " + format_number(o.dt) +
                  " s: " + (bad < e.verdict.size() ? e.verdict[bad] : "diverged");
      if (h.diverged || runs_unstable(e)) p.unstable_step = std::min(p.unstable_step, o.dt);
    }
    return out_c;
  };
  // the coarsest attempt an earlier pilot was used at (-1: none yet): each later pilot starts one attempt before it
  // (the attempts coarser than that found the motion unresolved for the earlier methods; one of them is still tried)
  int coarsest_used = -1;
  const auto first_attempt = [&] { return std::max(coarsest_used - 1, 0); };
  const auto learn = [&](const Piloted& piloted) {
    if (piloted.attempt >= 0 && (coarsest_used < 0 || piloted.attempt < coarsest_used)) coarsest_used = piloted.attempt;
  };

  // whether the model takes candidate i's method (admit, asked once: -1 not yet, 0 no, 1 yes)
  std::vector<int> admitted(candidates.size(), -1);
  const auto takes = [&](std::size_t i) {
    if (admitted[i] < 0) admitted[i] = admit(candidates[i]) ? 1 : 0;
    return admitted[i] == 1;
  };
  // the pilots: a method that may be exact on the scene first, since where one is no other method can take fewer
  // steps than it (the fewest the planner gives a run), and none is piloted; then the others, highest order first
  // (a candidate that takes the same steps as another candidate, not refused, is not piloted: twin_of)
  const auto twin_of = [&](const ToleranceCandidate& c) -> const ToleranceCandidate* {
    if (!c.same_as) return nullptr;
    const auto twin = std::find_if(candidates.begin(), candidates.end(),
                                   [&](const ToleranceCandidate& d) { return d.method == *c.same_as; });
    if (twin == candidates.end() || admitted[static_cast<std::size_t>(twin - candidates.begin())] == 0) return nullptr;
    return &*twin;
  };
  // the fewest steps over the whole horizon first (fewest_steps_run): where they meet s τ, the call is that run; where
  // they are certified above it and the steps that error asks for (scaled by dt^q, as the whole-horizon pilot's below)
  // are at most direct_plan_steps, those are the plan, which no pilot could make cheaper by what it costs
  const std::size_t first =
      first_to_run(candidates, [&](std::size_t i) { return twin_of(candidates[i]) == nullptr && takes(i); });
  std::optional<FewestStepsRun> fewest;
  if (first < candidates.size()) fewest = fewest_steps_run(candidates, first, base, request, multiple, run, out);
  if (out.interrupted || out.choice.met) return out;
  std::int64_t direct_steps = 0;  // the plan without pilots (0: none)
  if (fewest && fewest->run.verdict == used) {
    const double dt = fewest->run.dt * std::pow(target / fewest->run.error, 1.0 / fewest->order);
    const std::int64_t steps = steps_for(T, std::min(dt, fewest->run.dt), multiple);
    if (steps <= direct_plan_steps && steps <= request.max_steps) direct_steps = steps;
  }
  double scale = std::numeric_limits<double>::quiet_NaN();
  const PilotRun* best = nullptr;

  if (direct_steps > 0) {
    PilotRun p = fewest->run;
    p.planned_steps = direct_steps, p.planned_seconds = static_cast<double>(direct_steps) * p.seconds_per_step;
    const std::string not_piloted = "not piloted: " + method_info(p.method).name +
                                    " over the whole horizon at the fewest steps sets " + std::to_string(direct_steps) +
                                    " steps (a pilot would cost more than it could save)";
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      PilotRun skipped;
      skipped.method = candidates[i].method, skipped.order = candidates[i].order, skipped.verdict = not_piloted;
      choice.pilots.push_back(i == first ? p : skipped);
    }
    best = &choice.pilots[first];
    choice.pilot_seconds = seconds_since(start);
  } else {
    std::vector<std::optional<Piloted>> early(candidates.size());
    std::string exact_on_scene;  // the name of the method exact on the scene, if one is
    for (std::size_t i = 0; i < candidates.size() && exact_on_scene.empty(); ++i) {
      if (candidates[i].order == 0 || !method_info(candidates[i].method).exact_torque_free) continue;
      if (twin_of(candidates[i]) != nullptr || !takes(i)) continue;
      early[i] = pilot_of(candidates[i], first_attempt());
      if (out.interrupted) return out;
      learn(*early[i]);
      if (early[i]->run.exact_on_scene) exact_on_scene = method_info(candidates[i].method).name;
    }
    double best_figure = std::numeric_limits<double>::infinity();
    std::vector<ToleranceCandidate> exact;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const ToleranceCandidate& c = candidates[i];
      const int evaluations = method_info(c.method).evaluations;
      if (c.order == 0) {
        if (takes(i)) exact.push_back(c);
        continue;
      }
      if (const ToleranceCandidate* twin = twin_of(c)) {
        choice.pilots.push_back(pilot_entry(c, "not piloted: it takes the same steps as " +
                                                   method_info(twin->method).name + " on this scene"));
        continue;
      }
      if (!early[i] && !exact_on_scene.empty()) {
        choice.pilots.push_back(pilot_entry(c, "not piloted: " + exact_on_scene + " is exact on this scene"));
        continue;
      }
      if (!early[i] && std::isfinite(scale) && candidates.size() > 1 && !method_info(c.method).exact_torque_free) {
        const double figure = order_cost_figure(c.order, evaluations, request.tolerance / scale);
        if (figure > 8.0 * best_figure) {
          choice.pilots.push_back(pilot_entry(
              c, "pruned: order " + std::to_string(c.order) + " at a relative tolerance of " +
                     format_number(request.tolerance / scale) + " (needs > 8x the steps x evaluations of order " +
                     std::to_string(candidates.front().order) + ")"));
          continue;
        }
      }
      if (!early[i] && !takes(i)) continue;
      const Piloted piloted = early[i] ? *early[i] : pilot_of(c, first_attempt());
      if (out.interrupted) return out;
      if (!early[i]) learn(piloted);
      PilotRun p = piloted.run;
      if (p.verdict == used) {
        if (!std::isfinite(scale)) scale = piloted.scale;
        best_figure = std::min(best_figure, order_cost_figure(c.order, evaluations, request.tolerance / scale));
        // at most the pilot's step: the pilot's own check ran at 2 dt_p and 4 dt_p, which the certificate's coarse
        // runs then do not exceed (beyond them the pilot says nothing of stability); a method exact on the scene has
        // no stability limit, and its error is round-off, which fewer steps make smaller: the fewest steps
        const double dt = p.exact_on_scene ? T / static_cast<double>(fewest_run_steps)
                                           : std::min(step_for_error(p.constant, p.order, T, target), p.dt);
        p.planned_steps = steps_for(T, dt, multiple);
        p.planned_seconds = static_cast<double>(p.planned_steps) * p.seconds_per_step;
      }
      choice.pilots.push_back(p);
    }
    // the cheapest stepping plan within the cap
    best = cheapest_plan(choice.pilots, request.max_steps);
    // 'exact' at the records of the best stepping plan (or of 16 steps when there is none)
    for (const ToleranceCandidate& c : exact) {
      PilotRun p;
      p.method = c.method, p.order = 0;
      const std::int64_t n =
          best != nullptr ? best->planned_steps : steps_for(T, T / static_cast<double>(fewest_run_steps), multiple);
      SimulationOptions o = base;
      o.method = c.method, o.dt = T / 16.0, o.steps = 16, o.record_every = 1;
      const Records h = run(c, o);
      out.interrupted = out.interrupted || h.interrupted;
      if (out.interrupted) return out;
      p.dt = o.dt, p.horizon = T, p.steps = 16;
      p.seconds_per_step = elapsed_of(h) / 17.0;  // per record
      p.error = largest_error(round_off_estimate(error_records(h), o), request.measure);
      p.constant = 0.0;
      p.planned_steps = n;
      p.planned_seconds = static_cast<double>(n / base.record_every + 2) * p.seconds_per_step;
      const double round_off = p.error * static_cast<double>(n) / 16.0;
      p.verdict =
          round_off <= target ? used : "its round-off bound " + format_number(round_off) + " exceeds the tolerance";
      choice.pilots.push_back(p);
    }
    best = cheapest_plan(choice.pilots, request.max_steps);
    choice.pilot_seconds = seconds_since(start);
  }
  if (best == nullptr) {
    const PilotRun* cheapest = nullptr;  // the cap's figures
    for (const PilotRun& p : choice.pilots) {
      if (p.verdict == used && (cheapest == nullptr || p.planned_steps < cheapest->planned_steps)) cheapest = &p;
    }
    if (cheapest != nullptr) {
      choice.method = cheapest->method, choice.order = cheapest->order, choice.steps = cheapest->planned_steps;
      choice.dt = T / static_cast<double>(choice.steps);
      choice.predicted_error =
          predicted_error(cheapest->constant, cheapest->order, T / static_cast<double>(request.max_steps), T);
      choice.reason = "the cost cap: the cheapest run predicted to meet " + format_number(request.tolerance) + " " +
                      error_measure_unit(request.measure) + " is " + method_info(cheapest->method).name + " at " +
                      std::to_string(cheapest->planned_steps) + " steps, above max_steps = " +
                      std::to_string(request.max_steps) + " (at max_steps its predicted error is " +
                      format_number(choice.predicted_error) + " " + error_measure_unit(request.measure) + ")";
      if (request.grid_steps > request.max_steps) {
        choice.reason += "; every run takes a multiple of " + std::to_string(request.grid_steps) +
                         " steps (a controller's samples and the loads' switch times on a step's end at dt, 2 dt and "
                         "4 dt alike)";
      }
    } else {
      choice.reason = "no method reached its asymptotic regime in its pilot runs (each pilot's verdict is in pilots)";
    }
    return out;
  }
  PilotRun chosen = *best;  // (a refinement may take another candidate)
  std::size_t piloted = 0;
  for (const PilotRun& p : choice.pilots) piloted += p.steps > 0 ? 1 : 0;
  choice.method = chosen.method, choice.order = chosen.order, choice.steps = chosen.planned_steps;
  choice.dt = T / static_cast<double>(choice.steps);
  // a closed form's and an exact method's error: the round-off bound, which grows with the steps (records)
  choice.predicted_error = chosen.order == 0 ? chosen.error * static_cast<double>(choice.steps) / 16.0
                           : chosen.exact_on_scene
                               ? chosen.error * static_cast<double>(choice.steps) / static_cast<double>(chosen.steps)
                               : predicted_error(chosen.constant, chosen.order, choice.dt, T);
  choice.reason = describe_choice(choice, chosen, piloted);
  if (direct_steps > 0) {  // the run at the fewest steps's error, scaled by dt^q
    choice.predicted_error = chosen.error * std::pow(choice.dt / chosen.dt, fewest->order);
    choice.reason = method_info(chosen.method).name + " at " + std::to_string(choice.steps) + " steps of dt = " +
                    format_number(choice.dt) + " s: predicted " + format_number(choice.predicted_error) + " " +
                    error_measure_unit(request.measure) + " from its run over the whole horizon at " +
                    std::to_string(chosen.steps) + " steps (certified " + format_number(chosen.error) +
                    ", scaled by dt^" + format_number(fewest->order) + "), no method piloted (at most " +
                    std::to_string(direct_plan_steps) + " steps: a pilot would cost more than it could save)";
  }
  ToleranceCandidate candidate{chosen.method, chosen.order};
  const auto checked = [&](const SimulationOptions& x) {
    Records r = run(candidate, x);
    out.interrupted = out.interrupted || r.interrupted;
    return r;
  };

  // the chosen method over the whole horizon at a quarter of its steps: its largest error, scaled by dt^p, gives
  // the steps without a growth model (an error that jumps after the short pilot's span, e.g. at a flip near a
  // separatrix, is seen); kept only when its estimate is reliable. It records at the final run's common records,
  // so that it is the 4h run of the final run's estimate when that run takes exactly 4x its steps.
  std::optional<Records> quarter;  // that run, while it may serve as the final run's 4h run
  SimulationOptions quarter_options = base;
  const std::int64_t every = m / 4;  // the final run's common records, every m of its steps
  quarter_options.method = chosen.method;
  quarter_options.steps = steps_for(T, 4.0 * choice.dt, on_grid(common_record_steps(every), request.grid_steps));
  {  // at the common records of the final run of 4x its steps (a long run's are further apart than m: CommonRecords)
    SimulationOptions final_run = base;
    final_run.steps = 4 * quarter_options.steps;
    quarter_options.record_every = common_records(final_run).steps_between / 4;
  }
  // (a grid's steps may round it up to the final run's: then it is no cheaper pilot, and none runs; nor where its step,
  // 4 dt, is at or above one whose estimate a pilot found beyond the stability limit: its runs at 4 dt, 8 dt and
  // 16 dt, each at least as coarse as that pilot's, would be too, and the run could not set the steps)
  const bool quarter_stable = 4.0 * choice.dt < chosen.unstable_step;
  if (direct_steps == 0 && chosen.order > 0 && choice.steps / 4 >= 16 && 2 * quarter_options.steps <= choice.steps &&
      quarter_stable) {
    SimulationOptions& o = quarter_options;
    o.dt = T / static_cast<double>(4 * o.steps) * 4.0;  // as coarse_options(final, 4) makes it, bit for bit
    PilotRun p;
    p.method = chosen.method, p.order = chosen.order, p.dt = o.dt, p.horizon = T, p.steps = o.steps;
    double seconds = 0.0;
    const auto timed = [&](const SimulationOptions& x) {
      Records r = checked(x);
      seconds += elapsed_of(r);
      return r;
    };
    Records h = timed(o);
    if (out.interrupted) return out;
    const GlobalErrorEstimate e = measured_global_error(h, o, chosen.order, timed, request.measure).measure;
    if (out.interrupted) return out;
    p.error = largest_error(e, request.measure);
    p.seconds_per_step = seconds / (1.75 * static_cast<double>(o.steps));
    const std::size_t bad =
        first_uncertified(e, request.measure, request.tolerance, switch_inside_coarse_step(request.switch_times, o));
    // an error beyond the size of the quantity (the short pilots' records) is no error of the asymptotic regime,
    // whatever its observed order (a step beyond the stability limit of a linear oscillation grows it as a power)
    const bool sized = p.error <= scale;
    if (bad == e.verdict.size() && !h.diverged && std::isfinite(p.error) && sized) {
      const double order = extrapolation_order(e, request.measure);
      const double dt = p.error > 0.0 ? o.dt * std::pow(target / p.error, 1.0 / order) : choice.dt;
      const std::int64_t needed = steps_for(T, std::min(dt, o.dt), multiple), reusing = 4 * o.steps;
      // 4x its steps reuses it (that run and its 2h run: 1.5x) where that costs less than a run of the steps
      // needed with its own estimate (1.75x)
      const bool reuse = needed <= reusing && 1.5 * static_cast<double>(reusing) <= 1.75 * static_cast<double>(needed);
      choice.steps = reuse ? reusing : needed, choice.dt = T / static_cast<double>(choice.steps);
      if (reuse) quarter = std::move(h);
      choice.predicted_error = p.error * std::pow(choice.dt / o.dt, order);
      p.constant = error_constant(e, error_records(reuse ? *quarter : h), o.dt, request.measure);
      p.planned_steps = choice.steps;
      p.planned_seconds = static_cast<double>(choice.steps) * chosen.seconds_per_step;
      p.verdict = used;
      choice.reason += "; over the whole horizon at " + std::to_string(o.steps) + " steps its error " +
                       format_number(p.error) + " " + error_measure_unit(request.measure) + " sets " +
                       std::to_string(choice.steps) + " steps (predicted " + format_number(choice.predicted_error) +
                       (reuse ? "; that run is its 4h run)" : ")");
    } else {
      const std::string too_large = "its error " + format_number(p.error) + " " +
                                    error_measure_unit(request.measure) + " exceeds the size of the quantity " +
                                    format_number(scale);
      const std::string why = bad < e.verdict.size() ? e.verdict[bad] : !sized ? too_large : "diverged";
      p.verdict = "not asymptotic at dt = " + format_number(o.dt) + " s over the whole horizon: " + why +
                  " (the short pilot's prediction kept)";
    }
    choice.pilots.push_back(p);
    choice.pilot_seconds = seconds_since(start);
    if (choice.steps > request.max_steps) {
      choice.reason += ", above max_steps = " + std::to_string(request.max_steps);
      return out;
    }
  } else if (!quarter_stable) {
    choice.reason += "; no run over the whole horizon at 4x the step: its pilot went beyond the stability limit at "
                     "dt = " + format_number(chosen.unstable_step) + " s";
  }

  // the run and its certificate; one refinement
  const auto run_start = std::chrono::steady_clock::now();
  SimulationOptions o = base;
  o.method = chosen.method, o.dt = choice.dt, o.steps = choice.steps;
  // a coarse run of the estimate: the quarter-step run where it is that run (the first attempt's 4h run)
  const auto coarse = [&](const SimulationOptions& x) {
    if (quarter && x.steps == quarter_options.steps && x.record_every == quarter_options.record_every &&
        x.dt == quarter_options.dt) {
      Records r = std::move(*quarter);
      quarter.reset();
      return r;
    }
    return checked(x);
  };
  double predicted = choice.predicted_error;  // of the run about to be made
  // the first run, then a refinement while the certificate fails, at most max_refinements (each within max_steps)
  for (int attempt = 0; attempt <= max_refinements; ++attempt) {
    Records h = checked(o);
    if (out.interrupted) break;
    MeasuredEstimate estimates = measured_global_error(h, o, chosen.order, coarse, request.measure);
    quarter.reset();  // a refinement's steps are not 4x its steps
    if (out.interrupted) break;
    const GlobalErrorEstimate& e = estimates.measure;
    const double error = certified_error(e, request.measure);
    const std::size_t bad =
        first_uncertified(e, request.measure, request.tolerance, switch_inside_coarse_step(request.switch_times, o));
    const bool reliable = bad == e.verdict.size();
    const bool met = reliable && error <= request.tolerance;
    const std::string why = reliable ? "the certificate " + format_number(error) + " " +
                                           error_measure_unit(request.measure) + " exceeds the tolerance"
                                     : "the certificate is not reliable (record " + std::to_string(bad) + ": " +
                                           e.verdict[bad] + ")";
    // keep the better run: the certified one, else the smaller finite estimate
    if (!out.ran || met || (std::isfinite(error) && !(error >= choice.certified_error))) {
      out.records = std::move(h), out.estimate = std::move(estimates.all), out.ran = true;
      choice.certified_error = error, choice.dt = o.dt, choice.steps = o.steps;
      choice.method = chosen.method, choice.order = chosen.order;
    }
    if (met) {
      choice.met = true;
      choice.reason += (attempt == 0 ? std::string("; certified ")
                                     : "; certified after " + refinements_text(attempt) + " ") +
                       format_number(error) + " " + error_measure_unit(request.measure);
      break;
    }
    if (attempt == max_refinements || chosen.order == 0) {
      choice.reason += "; " + why + (attempt > 0 ? " after " + refinements_text(attempt) : std::string());
      break;
    }
    // every record's difference within its round-off bound (8 eps |y| per step, global_error.hpp): the certificate is
    // that bound, which a smaller step only raises; the tolerance is below what double precision certifies here
    if (reliable && at_round_off(e)) {
      choice.reason += "; " + why + (attempt > 0 ? " after " + refinements_text(attempt) : std::string()) +
                       ", and it is the round-off bound of " + std::to_string(o.steps) +
                       " steps (every record's error at the round-off level), which a smaller step only raises";
      break;
    }
    // an estimate that is not reliable still bounds the step from above where it is finite: at most dt / 2, less
    // where the estimate asks for less
    const double refined = std::isfinite(error) ? refined_step(o.dt, chosen.order, error, target) : o.dt / 2.0;
    std::int64_t steps = steps_for(T, reliable ? refined : std::min(refined, o.dt / 2.0), multiple);
    const double f = error / predicted;
    const PilotRun* other = nullptr;
    if (reliable) {
      const Replan replan = cheaper_with_growth(choice.pilots, chosen, steps, f, o.dt, request, multiple);
      if (replan.pilot != nullptr) other = replan.pilot, steps = replan.steps;
    }
    if (other != nullptr) chosen = *other, candidate = {chosen.method, chosen.order}, o.method = chosen.method;
    if (steps > request.max_steps) {
      choice.reason += "; " + why + ", and its refinement needs " + std::to_string(steps) +
                       " steps, above max_steps = " + std::to_string(request.max_steps);
      break;
    }
    choice.reason += "; " + why +
                     (other == nullptr ? std::string()
                                       : ", " + format_number(f) + "x its prediction (every method's prediction " +
                                             "scaled alike, " + method_info(chosen.method).name + " is the cheapest)") +
                     ": refined to " + std::to_string(steps) + " steps";
    choice.refinements = attempt + 1;
    predicted = other != nullptr ? predicted_error(chosen.constant * f, chosen.order, T / static_cast<double>(steps), T)
                                 : error * std::pow(T / static_cast<double>(steps) / o.dt, chosen.order);
    o.dt = T / static_cast<double>(steps), o.steps = steps;
  }
  choice.run_seconds = seconds_since(run_start);
  return out;
}

// run_to_tolerance where the model takes every candidate's method
template <class Records, class Run>
ToleranceRun<Records> run_to_tolerance(std::vector<ToleranceCandidate> candidates, const SimulationOptions& base,
                                       const ToleranceRequest& request, Run&& run) {
  return run_to_tolerance<Records>(std::move(candidates), base, request, std::forward<Run>(run),
                                   [](const ToleranceCandidate&) { return true; });
}

}  // namespace rigiddyn
