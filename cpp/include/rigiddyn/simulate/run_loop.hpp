// The stepping loop shared by every simulate and step of a scene (scene/simulate_scene.hpp; a body runs as its
// one-body scene), in rigiddyn::detail: compiled per (integrator, model), the runs of plain steps as tight as a
// hand-written loop, steps that contain a switch time of a piecewise-constant schedule split there
// (models/loads.hpp "Time discretisation").
//
// What differs between the models is a `Pieces` policy (scene/simulate_scene.hpp: ScenePieces, FixedScenePieces):
//   const std::vector<AppliedLoad>& schedule   every load whose t_start/t_end are switch times
//   void set_piece(Model&, double t) const     sets the model's loads of the piece that contains t
//   void at_time(Coordinates& y, double t) const
//                                              after a (sub-)step that ends at t [s]: sets y's t to t (no
//                                              accumulated rounding)
//   static constexpr bool t_place_fixed        (optional) true where at_time stores at a place known at
//                                              compile time
// and the result type, filled by the overload append_state found for it (by ADL).
#pragma once
#include "rigiddyn/always_inline.hpp"
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/models/loads.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#if defined(__GNUC__) || defined(__clang__)
#define RIGIDDYN_NOINLINE __attribute__((noinline))
#else
#define RIGIDDYN_NOINLINE
#endif

namespace rigiddyn::detail {

// The switch times of the run's schedule on its step grid t_i = t0 + i dt (grid_time): switch k at
// time[k] falls in step step[k], the step from t_{j-1} to t_j with t_{j-1} <= time[k] < t_j; a switch
// within on_grid_tolerance of a grid time is taken at that time (it then starts a step). Switches
// at or after the last grid time change nothing and are left out.
struct SwitchGrid {
  std::vector<double> time;        // [s], ascending
  std::vector<std::int64_t> step;  // in [1, steps]
};

inline double grid_time(const SimulationOptions& o, std::int64_t i) { return o.t0 + static_cast<double>(i) * o.dt; }

// A few ulps of the grid time t_i (or of dt near t = 0): the rounding of t_i itself, far below any
// method's error, so that a switch meant to lie on the grid makes no sub-step of round-off length.
inline double on_grid_tolerance(double t, double dt) {
  return 64.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(t), dt);
}

inline SwitchGrid switch_grid(const SimulationOptions& o, const std::vector<AppliedLoad>& schedule) {
  SwitchGrid grid;
  for (const double s : switch_times(schedule, o.t0, grid_time(o, o.steps))) {
    // the nearest grid index m ((s - t0) / dt <= steps up to rounding)
    const double x = std::clamp(std::round((s - o.t0) / o.dt), 0.0, static_cast<double>(o.steps));
    const auto m = static_cast<std::int64_t>(x);
    const double t_m = grid_time(o, m);
    const std::int64_t j = (s > t_m || std::abs(s - t_m) <= on_grid_tolerance(t_m, o.dt)) ? m + 1 : m;
    if (j > o.steps) continue;  // at the last grid time: acts after the run
    grid.time.push_back(s);
    grid.step.push_back(j);
  }
  return grid;
}

// One step of Integrator over h [s] with the workspace w; 1 if its implicit solve stopped at the iteration
// cap, else 0.
template <class Integrator, class Model>
RIGIDDYN_ALWAYS_INLINE int step_with(const Model& model, typename Model::Coordinates& y, double h,
                                     Workspace<Integrator, Model>& w) {
  if constexpr (std::is_same_v<decltype(Integrator::step(model, y, h, w)), bool>) {
    return Integrator::step(model, y, h, w) ? 0 : 1;
  } else {
    Integrator::step(model, y, h, w);
    return 0;
  }
}

// One step of the run: a dynamic-size model's stages in the run's workspace w (no step allocates); a
// fixed-size model's in a workspace of the step's own, which the compiler keeps in registers once the step
// is inlined (the run's workspace is reached from split_step too, so its stages would be stored and loaded
// again at every stage: +14 % instructions per RK4 step of a rigid body, +26 % of a particle).
template <class Integrator, class Model>
RIGIDDYN_ALWAYS_INLINE int advance(const Model& model, typename Model::Coordinates& y, double h,
                                   Workspace<Integrator, Model>& w) {
  if constexpr (has_fixed_size<Model>) {
    Workspace<Integrator, Model> local(model, y);
    return step_with<Integrator>(model, y, h, local);
  } else {
    return step_with<Integrator>(model, y, h, w);
  }
}

// First same as last: a kick–drift–kick method (edge_kick, between_kicks: splitting_dlm, its Yoshida composition,
// exact_flow_kick) opens and closes each step with loads_kick(edge_kick h). A step's closing kick and the next
// step's opening kick act at the same positions, attitudes and t, so where the model's kicks merge (kicks_merge:
// the loads do not depend on the velocities) they are one kick of 2 edge_kick h, the same flow to round-off: one
// force evaluation saved per step. The run merges them over the plain steps between two records (and switch
// times), where the state is closed again; a monitor call leaves it open (the monitor sees only the steps done), so
// that where the wall clock puts the calls changes no bit of the run.
template <class Integrator, class = void>
struct has_edge_kick : std::false_type {};
template <class Integrator>
struct has_edge_kick<Integrator, std::void_t<decltype(Integrator::edge_kick)>> : std::true_type {};
template <class Model, class = void>
struct has_kicks_merge : std::false_type {};
template <class Model>
struct has_kicks_merge<Model, std::void_t<decltype(std::declval<const Model&>().kicks_merge())>> : std::true_type {};

// True when the run merges the adjacent kicks of Integrator's steps on `model`
template <class Integrator, class Model>
bool merges_kicks(const Model& model) {
  if constexpr (has_edge_kick<Integrator>::value && has_kicks_merge<Model>::value) {
    return model.kicks_merge();
  } else {
    return false;
  }
}

// Whether the kicks merge on every model of type Model (a static constexpr kicks_merge() that is true): the runs of a
// kick–drift–kick method on it (always_merges) then compile the merged loop alone.
template <class Model, class = void>
struct kicks_always_merge : std::false_type {};
template <class Model>
struct kicks_always_merge<Model, std::void_t<decltype(std::bool_constant<Model::kicks_merge()>{})>>
    : std::bool_constant<Model::kicks_merge()> {};
template <class Integrator, class Model>
inline constexpr bool always_merges = has_edge_kick<Integrator>::value && kicks_always_merge<Model>::value;

// Whether a model repeats a kick without evaluating its elements again (loads_kick_repeated: a kick at the positions,
// attitudes, t and loads of its last loads_kick, whose wrenches it kept)
template <class Model, class = void>
struct has_repeated_kick : std::false_type {};
template <class Model>
struct has_repeated_kick<Model, std::void_t<decltype(std::declval<const Model&>().loads_kick_repeated(
                                    std::declval<typename Model::Coordinates&>(), 0.0))>> : std::true_type {};

// Whether a model records a state right after a loads_kick from that kick's wrenches (record_after_kick: the record
// of merged steps closed for it evaluates no force again)
template <class Model, class Result, class = void>
struct has_record_after_kick : std::false_type {};
template <class Model, class Result>
struct has_record_after_kick<Model, Result, std::void_t<decltype(std::declval<const Model&>().record_after_kick(
                                                std::declval<const typename Model::Coordinates&>(), 0.0,
                                                std::declval<Result&>()))>> : std::true_type {};

// Whether a model can leave the impulses out of its evaluations (leave_out_impulses: the generic model), which a
// coarse run of the global error estimate records none of (SimulationOptions::estimate_records)
template <class Model, class = void>
struct leaves_out_impulses : std::false_type {};
template <class Model>
struct leaves_out_impulses<Model, std::void_t<decltype(std::declval<Model&>().leave_out_impulses())>>
    : std::true_type {};

// How merged steps start: from a closed state, from one left open (the last step's closing kick still to give:
// merged with this first step's opening kick), or from one that the merged steps just before closed for a record
// alone (the opening kick at the closing kick's positions, attitudes, t and loads: where the model keeps that kick's
// wrenches, loads_kick_repeated gives it without a force evaluation, the same bits)
enum class MergedStart { closed, open, closed_for_record };

// n >= 1 steps of h [s] with the adjacent kicks merged, from `start`, to a closed state where `close`, else to an open
// one; after_step(k) after the k-th step's drift (the pieces' at_time)
template <class Integrator, class Model, class AfterStep>
void merged_steps(const Model& model, typename Model::Coordinates& y, double h, std::int64_t n, MergedStart start,
                  bool close, AfterStep after_step) {
  const double edge = Integrator::edge_kick * h;
  if (start == MergedStart::open) {
    model.loads_kick(y, 2.0 * edge);
  } else if constexpr (has_repeated_kick<Model>::value) {
    start == MergedStart::closed_for_record ? model.loads_kick_repeated(y, edge) : model.loads_kick(y, edge);
  } else {
    model.loads_kick(y, edge);
  }
  for (std::int64_t k = 1;; ++k) {
    Integrator::between_kicks(model, y, h);
    after_step(k);
    if (k == n) break;
    model.loads_kick(y, 2.0 * edge);
  }
  if (close) model.loads_kick(y, edge);
}

// One step of Integrator from t_begin to t_end = t_begin + dt across the switch times [first, last)
// (inside it, ascending): a sub-step over each piece between them, the loads of the next piece set
// at each switch; a piece shorter than the on-grid tolerance is skipped (its switch then acts from
// the start). Returns the number of sub-steps whose implicit solve did not converge. Out of line,
// so that the loop of plain steps compiles as it would without switch times.
template <class Integrator, class Model, class Pieces>
RIGIDDYN_NOINLINE int split_step(Model& model, typename Model::Coordinates& y, Workspace<Integrator, Model>& w,
                                 const Pieces& pieces, const double* first, const double* last, double t_begin,
                                 double t_end, double dt) {
  const double tolerance = on_grid_tolerance(t_end, dt);
  double t = t_begin;
  int unconverged = 0;
  // one call of advance, inlined once: the pieces before each switch, then the last piece (to t_end)
  for (const double* s = first;; ++s) {
    const bool last_piece = s == last;
    const double h = last_piece ? (t == t_begin ? dt : t_end - t) : *s - t;
    if (last_piece || h > tolerance) {
      unconverged += advance<Integrator>(model, y, h, w);
      if (last_piece) return unconverged;
      t = *s;
      pieces.at_time(y, t);
    }
    pieces.set_piece(model, *s);
  }
}

// Whether a model's loads never switch (a one-body layout without scheduled loads says so with a static constexpr
// switches_never() that is true): its runs compile no split step, and a schedule given to them is a logic error.
template <class Model, class = void>
struct switches_never : std::false_type {};
template <class Model>
struct switches_never<Model, std::void_t<decltype(Model::switches_never())>> : std::bool_constant<Model::switches_never()> {};

// Whether a Pieces policy stores t at a place known at compile time (a static constexpr t_place_fixed that is true).
template <class Pieces, class = void>
struct t_place_fixed : std::false_type {};
template <class Pieces>
struct t_place_fixed<Pieces, std::void_t<decltype(Pieces::t_place_fixed)>> : std::bool_constant<Pieces::t_place_fixed> {};

// Whether a run compiles its split step: unless the model never switches and t's place is fixed. Where t is stored at
// an index read at run time, the split step's call, which takes y's address, keeps y in memory; without it GCC holds a
// particle's y in registers and goes through the stack for that store at every step (classical RK4 on a particle
// under gravity: 5.9 to 9.7 ns per step, measured).
template <class Model, class Pieces>
inline constexpr bool compiles_split_step = !switches_never<Model>::value || !t_place_fixed<Pieces>::value;

// std::logic_error where `Model` never switches (it compiles no split step) but `what` ("a run", "a step") has switch
// times inside it.
template <class Model>
void refuse_switches(bool switches, const char* what) {
  if (switches_never<Model>::value && switches) {
    throw std::logic_error(std::string(what) + " of a model without scheduled loads given a switch schedule");
  }
}

// The switch grid of a run of `model` (switch_grid); refuse_switches.
template <class Model>
SwitchGrid model_switch_grid(const SimulationOptions& o, const std::vector<AppliedLoad>& schedule) {
  SwitchGrid grid = switch_grid(o, schedule);
  refuse_switches<Model>(!grid.time.empty(), "a run");
  return grid;
}

// The stepping loop, compiled per (model, integrator): records step 0, every record_every-th step
// and the last one into `out` (reserved by the caller); stops after recording a non-finite state, or
// when options.monitor (called at the pace of MonitorPace, about every monitor_period_seconds) returns
// true. The runs of plain steps between the steps that contain a switch time, or a monitor call, are as
// tight as a hand-written loop. The method's workspace is sized here, once: no step allocates.
template <class Integrator, class Model, class Pieces, class Result>
Result run(Model model, typename Model::Coordinates y, const SimulationOptions& o, const Pieces& pieces, Result out) {
  const SwitchGrid switches = model_switch_grid<Model>(o, pieces.schedule);
  if constexpr (leaves_out_impulses<Model>::value) {
    if (o.estimate_records) model.leave_out_impulses();  // the run's own copy: the bodies move bitwise as before
  }
  pieces.set_piece(model, o.t0);
  append_state(out, o.t0, model, y);
  Workspace<Integrator, Model> workspace(model, y);
  const auto start = std::chrono::steady_clock::now();
  const double dt = o.dt;
  const std::int64_t steps = o.steps, record_every = o.record_every;
  MonitorPace pace;
  [[maybe_unused]] const bool merge = merges_kicks<Integrator>(model);
  // how the next merged steps start: open where merged steps left their closing kick to them (at a monitor call),
  // closed_for_record where merged steps closed for a record and nothing stepped since
  [[maybe_unused]] MergedStart start_of_merged = MergedStart::closed;
  std::int64_t i = 0, until_record = record_every;
  std::int64_t next_monitor = o.monitor ? pace.interval() : std::numeric_limits<std::int64_t>::max();
  std::size_t k = 0;  // the next switch
  bool stop = false;  // the monitor asked to stop
  // after the steps up to i, `taken` of them since the last record: the record when one is due (every record_every-th
  // step, and the last), from the wrenches of the kick that closed them where `after_kick`; whether the run ends there
  // (its state not finite)
  const auto recorded_divergence = [&](std::int64_t taken, bool after_kick = false) RIGIDDYN_ALWAYS_INLINE_LAMBDA {
    until_record -= taken;
    if (until_record != 0 && i != steps) return false;
    until_record = record_every;
    if constexpr (has_record_after_kick<Model, Result>::value) {
      if (after_kick) {
        model.record_after_kick(y, grid_time(o, i), out);
        return out.diverged = !y.allFinite();
      }
    }
    append_state(out, grid_time(o, i), model, y);
    return out.diverged = !y.allFinite();
  };
  while (!stop && i < steps) {
    // plain steps up to the next step that contains a switch time, or the next monitor call
    const std::int64_t split = k < switches.step.size() ? switches.step[k] : steps + 1;
    const std::int64_t plain_end = std::min({split - 1, steps, next_monitor});
    if constexpr (has_edge_kick<Integrator>::value && has_kicks_merge<Model>::value) {
      while (merge && i < plain_end) {  // up to the next record, merged (merged_steps)
        const std::int64_t n = std::min(plain_end - i, until_record), first = i;
        // closed for a record, the last step and a step across switch times; left open at a monitor call alone
        const bool close = n == until_record || i + n == steps || i + n == split - 1;
        merged_steps<Integrator>(model, y, dt, n, start_of_merged, close,
                                 [&](std::int64_t k) { pieces.at_time(y, grid_time(o, first + k)); });
        start_of_merged = close ? MergedStart::closed_for_record : MergedStart::open;
        i += n;
        if (recorded_divergence(n, close)) break;
      }
      if (out.diverged) break;
    }
    if constexpr (!always_merges<Integrator, Model>) {
      while (i < plain_end) {
        out.unconverged_steps += advance<Integrator>(model, y, dt, workspace);
        if constexpr (has_edge_kick<Integrator>::value) start_of_merged = MergedStart::closed;
        ++i;
        pieces.at_time(y, grid_time(o, i));
        if (recorded_divergence(1)) break;
      }
    }
    if (out.diverged) break;
    if constexpr (compiles_split_step<Model, Pieces>) {
      if (split <= steps && i == split - 1) {  // step `split` crosses switch times: sub-steps between them
        const std::size_t first = k;
        while (k < switches.step.size() && switches.step[k] == split) ++k;
        // to t_i + dt, as a step from t_i ends (one_step), not to t_(i+1) (the two may differ by an ulp)
        const double t_i = grid_time(o, i);
        out.unconverged_steps += split_step<Integrator>(model, y, workspace, pieces, switches.time.data() + first,
                                                        switches.time.data() + k, t_i, t_i + dt, dt);
        if constexpr (has_edge_kick<Integrator>::value) start_of_merged = MergedStart::closed;
        ++i;
        pieces.at_time(y, grid_time(o, i));
        if (recorded_divergence(1)) break;
      }
    }
    if (i >= next_monitor) {
      stop = pace.check(o.monitor, i);
      next_monitor = i + std::min(pace.interval(), std::numeric_limits<std::int64_t>::max() - i);
    }
  }
  out.interrupted = stop;
  out.elapsed_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

// One step from t = o.t0 to t + o.dt, split at the switch times inside it (as run does).
template <class Model, class Pieces>
typename Model::Coordinates one_step(Model model, typename Model::Coordinates y, const SimulationOptions& o,
                                     const Pieces& pieces) {
  pieces.set_piece(model, o.t0);
  const double t_end = o.t0 + o.dt;
  std::vector<double> switches = switch_times(pieces.schedule, o.t0, t_end);
  // a switch within the on-grid tolerance of t + dt acts from the next step on (as in run)
  while (!switches.empty() && t_end - switches.back() <= on_grid_tolerance(t_end, o.dt)) switches.pop_back();
  refuse_switches<Model>(!switches.empty(), "a step");
  visit_method(o.method, [&](auto integrator) {
    using Integrator = decltype(integrator);
    Workspace<Integrator, Model> w(model, y);
    if constexpr (switches_never<Model>::value) {
      advance<Integrator>(model, y, o.dt, w);
    } else {
      split_step<Integrator>(model, y, w, pieces, switches.data(), switches.data() + switches.size(), o.t0, t_end, o.dt);
    }
  });
  pieces.at_time(y, t_end);
  return y;
}

}  // namespace rigiddyn::detail
