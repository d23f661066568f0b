// The global error estimate of a run: global Richardson extrapolation with an observed-order check
// (Hairer, Nørsett & Wanner, "Solving Ordinary Differential Equations I", global error estimation by
// Richardson extrapolation of whole runs).
//
// The answer is the run at step h. Two more runs of the same method at 2h and 4h over the same records
// (cost +½ +¼ of the answer) give, at a record where all three have a state, for a method of order p
//     ε ≈ d(y_h, y_2h) / (2^p − 1)                   (the leading term of the error of y_h),
//     r  = d(y_2h, y_4h) / d(y_h, y_2h) ≈ 2^p       (the observed order is log2 r).
// The estimate is trusted ("reliable") only where r lies in [2^p / 1.5, 2^p · 1.5] for every state quantity (the
// bodies of a kind together), and in [2^p / 1.5, 2^(p+1) · 1.5] for the invariants energy and |L| (whose error may
// fall an order faster; above 2^p · 1.5 their estimate is d1 / (r − 1), the observed order's). Outside it the error
// is not in its asymptotic regime (a step too coarse, a force that is not smooth inside a step) and the verdict
// names the reason instead: "not asymptotic: ...", "step beyond the stability limit: ..." (a coarse run diverged
// or its energy departed by more than |T| + |V|), "past the Lyapunov time of this scene: ..." (estimates growing
// exponentially, more than 1000 (t / t_k)^4 from an earlier record). Where d(y_h, y_2h) is below the round-off bound
// of the run the estimate is that bound (and the verdict "reliable"); the method 'exact' reports the round-off bound
// alone.
//
// Distances: the attitude's is the geodesic angle of q_2h⁻¹ q_h (so3/angular_distance.hpp, valid to leading
// order), the other quantities' the norm of their difference.
//
// Which records: the 2h and 4h runs have a state only at steps that are multiples of m0 = lcm(record_every, 4), and
// record at most max_common_records of them after t0 (CommonRecords: every m0 steps in all but long runs recorded
// densely, and the last). At those "common" records the estimate is computed and checked; at the records
// between two of them it is interpolated linearly in t, and after the last of them (steps not a multiple of m0)
// extrapolated as ε(t) = ε(t_c) (t − t0) / (t_c − t0) (linear growth). Neither is checked, so neither is called
// reliable: their verdict says "interpolated ..." or "extrapolated ..." between reliable records, else the
// reason of the record that is not. With record_every a multiple of 4 every record is common, up to
// max_common_records of them.
//
// A force the core cannot see into (a PythonForce, which may switch inside a step) is refused the verdict
// "reliable": the nested grids h, 2h, 4h can put a switch in the same step of all three runs, whose error then
// cancels in every difference while the order check passes (measured: implicit_midpoint under-estimated 20×).
#pragma once
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/simulate/simulate.hpp"
#include "rigiddyn/simulate/verdicts.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rigiddyn {

// The records of one run the estimate reads: n records of nb bodies, row-major (as Trajectory and
// SceneSimulation hold them).
struct ErrorRecords {
  std::size_t n = 0;
  std::int64_t bodies = 1;
  const double* t = nullptr;             // (n,) [s]
  const double* q_WB = nullptr;          // (n, nb, 4) attitudes (x, y, z, w), any norm
  bool scalar_first = false;             // q_WB as (w, x, y, z) (the records of a result that gives them so)
  const double* w_B = nullptr;           // (n, nb, 3) [rad/s]
  const double* p_W = nullptr;           // (n, nb, 3) [m]
  const double* v_W = nullptr;           // (n, nb, 3) [m/s]
  const double* energy = nullptr;        // (n,) total energy [J]
  const double* energy_scale = nullptr;  // (n,) the kinetic energy T (the round-off scales with |T| + |V|) [J]
  // momentum, momentum_scale and balance: NaN between the records error_records made them at (its `every`, `also`)
  std::vector<double> momentum;          // (n,) |L| of the run [kg m²/s]
  // (n,) the size the round-off of |L| scales with [kg m²/s]: Σ over the bodies of |p_W| m |v_W| + |H| (a scene's
  // L may cancel to 0 while its terms do not); empty: |L| itself
  std::vector<double> momentum_scale;
  // (n,) the energy balance T − W [J]: the kinetic energy less the work done on the bodies since t0 (of every load
  // and element, and a scene's mass flows and wheel motors), T(t0) at every t for the exact motion, so that its
  // error is known; empty: not checked
  std::vector<double> balance;
};

// The columns of a scene's run that its ErrorRecords are made of (SceneSimulation's, or those of a result that keeps
// them): n records of nb bodies, row-major, as SceneSimulation holds them; a null column with its size 0 where the run
// has none.
struct SceneColumns {
  std::size_t n = 0;
  std::int64_t bodies = 1;
  const double *t = nullptr, *q_WB = nullptr, *w_B = nullptr, *p_W = nullptr, *v_W = nullptr;
  bool scalar_first = false;  // q_WB as (w, x, y, z)
  const double *total_energy = nullptr, *angular_momentum_W = nullptr;
  const double* kinetic_energy = nullptr;
  std::size_t kinetic_energy_size = 0;
  const double *mass = nullptr, *angular_momentum_O_W = nullptr;  // (n, nb), (n, nb, 3)
  std::size_t mass_size = 0, angular_momentum_O_W_size = 0;
  const double *work = nullptr, *mass_flow_energy = nullptr, *motor_work = nullptr;  // (n, ne), (n, nb), (n, nw)
  std::size_t work_size = 0, mass_flow_energy_size = 0, motor_work_size = 0;
};
SceneColumns scene_columns(const SceneSimulation& r);

// The records of a body's run (|L| = angular_momentum_norm) and of a scene's (|L| = |angular_momentum_W|); a scene's
// with the size of |L|'s round-off (momentum_scale) unless `scaled` is false (the runs at 2h and 4h, whose own
// round-off the estimate does not read), and its columns made of several (momentum, momentum_scale, balance) at every
// `every`-th record and the record `also` alone (NaN between; the records an estimate compares: answer_records).
ErrorRecords error_records(const Trajectory& r);
ErrorRecords error_records(const SceneColumns& r, bool scaled = true, std::size_t every = 1,
                           std::size_t also = static_cast<std::size_t>(-1));
inline ErrorRecords error_records(const SceneSimulation& r, bool scaled = true, std::size_t every = 1,
                                  std::size_t also = static_cast<std::size_t>(-1)) {
  return error_records(scene_columns(r), scaled, every, also);
}

// The quantities an estimate gives (the fields of GlobalErrorEstimate, in their order); a tolerance bounds one of
// them (simulate/tolerance.hpp).
enum class ErrorMeasure { attitude, angular_velocity, position, velocity, energy, angular_momentum };

// The estimate at every record of the answer run (n records, nb bodies), row-major.
struct GlobalErrorEstimate {
  int order = 0;                            // the order p the estimate assumed (0: the method 'exact')
  std::int64_t bodies = 1;
  std::vector<double> attitude;             // (n, nb) [rad]
  std::vector<double> angular_velocity;     // (n, nb) [rad/s]
  std::vector<double> position;             // (n, nb) [m]
  std::vector<double> velocity;             // (n, nb) [m/s]
  std::vector<double> energy;               // (n,) total energy [J]
  std::vector<double> angular_momentum;     // (n,) |L| [kg m²/s]
  std::vector<double> observed_order;       // (n,) log2 r of the quantity furthest from p (NaN: none measured)
  Verdicts verdict;                         // (n,) "reliable" or the reason the estimate is not
  // (n,) the quantities whose estimate is reliable at the record, one bit each (measure_bit): checked at a common
  // record, its own observed order inside its window (or its differences at round-off), and the record not
  // disqualified as a whole (a run beyond the stability limit, the energy balance, a force the core cannot see into).
  // A record is reliable where every quantity estimated there is; a quantity may be reliable where another is not
  // (a damped chain's positions, whose error falls as dt^p, beside its energy, whose error mixes two orders).
  std::vector<std::uint8_t> reliable_quantities;
};

// The window of a record's order check: the ratio r of every quantity in [2^p / 1.5, 2^p · 1.5] (2^(p+1) · 1.5 for
// an invariant, above).
inline constexpr double record_window = 1.5;
// The window of one quantity's own check at a record that another quantity fails (reliable_quantities): a failure
// says the record is near the edge of the asymptotic regime, and a ratio inside the record's window may then come
// from a higher-order term that the estimate misses. Measured on the shipped spring chain (rk4 at 4 ms, every 4th
// step recorded, against rk4 at 0.25 ms), where the energy (no invariant of a damped chain) fails at most records:
// the velocity's estimate at 1.504 s was 2.05x below its true error with r = 12.4 (2^4 / 1.29), while every record
// inside [2^4 / 1.25, 2^4 · 1.25] of the chain's and the box on springs' positions and velocities at 8, 4 and 2 ms
// lay within 0.80 and 1.22 of it. (For an error A h^p + B h^(p+1), the 1.5 window bounds the effectivity to
// [0.85, 1.35] at p = 4, the 1.25 window to [0.91, 1.15]: what lies beyond comes from further terms.)
inline constexpr double quantity_window = 1.25;

// The bit of `measure` in GlobalErrorEstimate::reliable_quantities; every_measure: all six.
constexpr std::uint8_t measure_bit(ErrorMeasure measure) {
  return static_cast<std::uint8_t>(1u << static_cast<unsigned>(measure));
}
inline constexpr std::uint8_t every_measure = 0x3F;

// The steps of the answer between two records that the answer, 2h and 4h runs can all have: lcm(record_every, 4).
std::int64_t common_record_steps(std::int64_t record_every);

// The most common records an estimate compares after t0: where the run has more multiples of
// common_record_steps, its common records are spaced further apart (CommonRecords). Each common record costs the
// coarse runs two records and the estimate a comparison, together ~3.5 rk4 steps of a free body (a coarse record
// ~390 instructions, a comparison ~940, a step ~490: callgrind, docs/perf/scenes.md §4.16), where the coarse runs take
// 0.75 m0 steps between two of them (3 for m0 = 4); the records between are interpolated, as are those of a run
// recording every step, where the error varies smoothly. Beyond 1024, a longer run adds steps to the coarse runs and
// no comparison.
inline constexpr std::int64_t max_common_records = 1024;

// The records where the answer run and its runs at 2h and 4h all have a state ("common" records), where the estimate
// is computed and checked: t0, every `steps_between` steps (m0 k, m0 = common_record_steps(record_every), k the
// fewest that leave at most max_common_records after t0: 1 in all but long runs recorded densely), and the last
// multiple of m0 within the run (when k does not divide the run's multiples of m0). The answer's common record j is
// its record answer_record(j).
struct CommonRecords {
  std::int64_t steps_between = 4;
  std::size_t stride = 1;  // the answer's records between two common records: steps_between / record_every
  std::size_t last = 0;    // the answer's record at the last common record: its step floor(steps / m0) m0
  std::size_t count = 1;   // the common records, t0's included
  std::size_t answer_record(std::size_t j) const { return std::min(j * stride, last); }
};
CommonRecords common_records(const SimulationOptions& answer);

// The records of the answer run as an estimate of order `order` reads them: a scene's made of several columns at its
// common records alone (error_records' `every`), where the estimate compares the runs; every record for the round-off
// bound of order 0, which reads them all.
inline ErrorRecords answer_records(const Trajectory& r, const SimulationOptions&, int) { return error_records(r); }
template <class Columns>  // SceneSimulation or SceneColumns
ErrorRecords answer_records(const Columns& r, const SimulationOptions& answer, int order) {
  if (order == 0) return error_records(r);
  const CommonRecords common = common_records(answer);
  return error_records(r, true, common.stride, common.last);
}

// The options of the run at factor·h (factor 2 or 4) that records at the common records of `answer`: dt·factor,
// steps floor(steps / m0)·m0 / factor (its last step the last common record), record_every m / factor
// (m0 = common_record_steps, m = common_records' steps_between).
SimulationOptions coarse_options(const SimulationOptions& answer, int factor);

// The estimate from the three runs (coarse[0] at 2h, coarse[1] at 4h, made with coarse_options) of a method of
// order `order` >= 1, `answer` the options of the run at h.
// `opaque` names a force the core cannot see into ("" for none): then no record is called reliable.
// `only`, where given, restricts the estimate to that quantity: the others are neither estimated (NaN) nor checked,
// as if the three runs agreed on them (the energy balance's check stays: it tests the run, not a quantity).
GlobalErrorEstimate estimate_global_error(const ErrorRecords& h, const ErrorRecords& h2, const ErrorRecords& h4,
                                          const SimulationOptions& answer, int order, const std::string& opaque = {},
                                          std::optional<ErrorMeasure> only = std::nullopt);

// The estimate of every quantity and that of `measure` alone: estimate_global_error's (`only` none) and its estimate
// with `only` = measure, bit for bit, from one pass over the common records, each difference of the runs taken once for
// both (the estimates a run to a tolerance reads: simulate/tolerance.hpp MeasuredEstimate).
std::pair<GlobalErrorEstimate, GlobalErrorEstimate> estimate_global_error_and_alone(
    const ErrorRecords& h, const ErrorRecords& h2, const ErrorRecords& h4, const SimulationOptions& answer, int order,
    ErrorMeasure measure);

// The estimates of `measure` in e: (n, nb) for the state quantities, (n,) for the energy and |L|.
const std::vector<double>& values_of(const GlobalErrorEstimate& e, ErrorMeasure measure);

// The round-off bound alone, for the method 'exact' (order 0).
GlobalErrorEstimate round_off_estimate(const ErrorRecords& h, const SimulationOptions& answer);

// No estimate, for the reason `why`: n records of nb bodies, every value NaN, every verdict `why` (a run whose
// coarse runs cannot be made, e.g. under a control law that may not be sampled again).
GlobalErrorEstimate no_estimate(std::size_t n, std::int64_t bodies, int order, std::string_view why);

// The records of a run at 2h or 4h as the estimate reads them (error_records without what it reads of the answer
// alone).
inline ErrorRecords coarse_records(const Trajectory& r) { return error_records(r); }
inline ErrorRecords coarse_records(const SceneSimulation& r) { return error_records(r, false); }

// The estimate of a run whose records as the estimate reads them are `answer` (error_records), made with `options`,
// for a method of order `order` (0: the round-off bound alone): runs run(coarse_options(options, 2)) and
// run(coarse_options(options, 4)), each returning the records of the same model from the same initial state (a
// Trajectory or a SceneSimulation); `opaque` as in estimate_global_error.
template <class Run>
GlobalErrorEstimate global_error_of(const ErrorRecords& answer, const SimulationOptions& options, int order, Run&& run,
                                    const std::string& opaque = {}) {
  if (order == 0) return round_off_estimate(answer, options);
  const auto twice = run(coarse_options(options, 2));
  const auto four_times = run(coarse_options(options, 4));
  return estimate_global_error(answer, coarse_records(twice), coarse_records(four_times), options, order, opaque);
}

// global_error_of the records of the run `answer` (a Trajectory or a SceneSimulation).
template <class Records, class Run>
GlobalErrorEstimate global_error(const Records& answer, const SimulationOptions& options, int order, Run&& run,
                                 const std::string& opaque = {}) {
  return global_error_of(answer_records(answer, options, order), options, order, std::forward<Run>(run), opaque);
}

}  // namespace rigiddyn
