#include "rigiddyn/simulate/simulate.hpp"

#include "append_record.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/simulate/simulate_exact.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace rigiddyn {

namespace {

// Doubles per record: t, p_W (3), q_WB (4), v_W (3), w_B (3), kinetic and total energy, |H_G|,
// |q| - 1, work (append_record).
constexpr double doubles_per_record = 19.0;

// A recording smaller than this is reserved without asking how much memory is available (reading
// it costs more than such a run); a failed reservation still throws std::bad_alloc.
constexpr double unchecked_recording_bytes = 256.0 * 1024.0 * 1024.0;

// The first number in `path` after `key` (e.g. "MemAvailable:" in /proc/meminfo), or -1.
double number_after(const char* path, const std::string& key) {
  std::ifstream in(path);
  std::string word;
  while (in >> word) {
    if (word == key) {
      double value = -1.0;
      return (in >> value) ? value : -1.0;
    }
  }
  return -1.0;
}

// Bytes of memory this process can still take [B]: Linux's MemAvailable, capped by a cgroup v2
// limit (memory.max - memory.current) when one is set; -1 when unknown (no check then).
double available_memory_bytes() {
  double available = number_after("/proc/meminfo", "MemAvailable:");
  if (available < 0.0) return -1.0;
  available *= 1024.0;  // kB
  std::ifstream max_file("/sys/fs/cgroup/memory.max");
  double limit = 0.0;
  if (max_file >> limit) {  // "max" (no limit) does not parse
    std::ifstream current_file("/sys/fs/cgroup/memory.current");
    double current = 0.0;
    if (current_file >> current) available = std::min(available, std::max(0.0, limit - current));
  }
  return available;
}

// "14.5 GB" (decimal units, 3 significant digits).
std::string format_bytes(double bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000.0 && u < 6) bytes /= 1000.0, ++u;
  char text[32];
  std::snprintf(text, sizeof text, "%.3g %s", bytes, units[u]);
  return text;
}

void check_options(const SimulationOptions& o, bool stepping) {
  require_positive(o.dt, "dt");
  require_finite(o.t0, "t0");
  require_finite(o.gravity_W, "gravity");
  if (stepping) {
    if (o.steps < 0) throw_invalid("steps", "an integer >= 0", o.steps);
    if (o.record_every < 1) throw_invalid("record_every", "an integer >= 1", o.record_every);
  }
  check_loads(o.loads);
}

void check_particle_loads(const SimulationOptions& o) {
  for (std::size_t i = 0; i < o.loads.size(); ++i) {
    if (!o.loads[i].torque.isZero(0.0)) {
      throw_invalid("loads[" + std::to_string(i) + "].torque", "zero (a particle takes no torque)", o.loads[i].torque);
    }
  }
}

void check_planar_loads(const SimulationOptions& o) {
  for (std::size_t i = 0; i < o.loads.size(); ++i) {
    const std::string name = "loads[" + std::to_string(i) + "]";
    if (o.loads[i].force.z() != 0.0) throw_invalid(name + ".force", "a force in the xy plane (z = 0)", o.loads[i].force);
    if (!o.loads[i].torque.head<2>().isZero(0.0)) {
      throw_invalid(name + ".torque", "a torque about z only (x = y = 0)", o.loads[i].torque);
    }
  }
  if (o.gravity_W.z() != 0.0) throw_invalid("gravity", "gravity in the xy plane (z = 0)", o.gravity_W);
}

// The switch times of the run's schedule on its step grid t_i = t0 + i dt (grid_time): switch k at
// time[k] falls in step step[k], the step from t_{j-1} to t_j with t_{j-1} <= time[k] < t_j; a switch
// within on_grid_tolerance of a grid time is taken at that time (it then starts a step). Switches
// at or after the last grid time change nothing and are left out.
struct SwitchGrid {
  std::vector<double> time;        // [s], ascending
  std::vector<std::int64_t> step;  // in [1, steps]
};

double grid_time(const SimulationOptions& o, std::int64_t i) { return o.t0 + static_cast<double>(i) * o.dt; }

// A few ulps of the grid time t_i (or of dt near t = 0): the rounding of t_i itself, far below any
// method's error, so that a switch meant to lie on the grid makes no sub-step of round-off length.
double on_grid_tolerance(double t, double dt) {
  return 64.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(t), dt);
}

SwitchGrid switch_grid(const SimulationOptions& o) {
  SwitchGrid grid;
  for (const double s : switch_times(o.loads, o.t0, grid_time(o, o.steps))) {
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

#if defined(__GNUC__) || defined(__clang__)
#define RIGIDDYN_NOINLINE __attribute__((noinline))
#else
#define RIGIDDYN_NOINLINE
#endif

// One step of Integrator over h [s]; 1 if its implicit solve stopped at the iteration cap, else 0.
template <class Integrator, class Model>
RIGIDDYN_ALWAYS_INLINE int advance(const Model& model, typename Model::Coordinates& y, double h) {
  if constexpr (std::is_same_v<decltype(Integrator::step(model, y, h)), bool>) {
    return Integrator::step(model, y, h) ? 0 : 1;
  } else {
    Integrator::step(model, y, h);
    return 0;
  }
}

// One step of Integrator from t_begin to t_end = t_begin + dt across the switch times [first, last)
// (inside it, ascending): a sub-step over each piece between them, the loads of the next piece set
// at each switch; a piece shorter than the on-grid tolerance is skipped (its switch then acts from
// the start). Returns the number of sub-steps whose implicit solve did not converge. Out of line,
// so that the loop of plain steps compiles as it would without switch times.
template <class Integrator, class Model>
RIGIDDYN_NOINLINE int split_step(Model& model, typename Model::Coordinates& y, const std::vector<AppliedLoad>& schedule,
                                 const double* first, const double* last, double t_begin, double t_end, double dt) {
  const double tolerance = on_grid_tolerance(t_end, dt);
  double t = t_begin;
  int unconverged = 0;
  for (const double* s = first; s != last; ++s) {
    if (*s - t > tolerance) {
      unconverged += advance<Integrator>(model, y, *s - t);
      t = *s;
    }
    model.set_loads(loads_at(schedule, *s));
  }
  return unconverged + advance<Integrator>(model, y, t == t_begin ? dt : t_end - t);
}

// The stepping loop, compiled per (model, integrator): records step 0, every record_every-th step
// and the last one; stops after recording a non-finite state, or when options.monitor (called
// every monitor_interval_steps steps) returns true. The runs of plain steps between the steps that
// contain a switch time are as tight as a hand-written loop.
template <class Integrator, class Model>
Trajectory run(Model model, typename Model::Coordinates y, const SimulationOptions& o) {
  Trajectory out;
  reserve_records(out, o.steps, o.record_every);
  const SwitchGrid switches = switch_grid(o);
  model.set_loads(loads_at(o.loads, o.t0));
  append_record(out, o.t0, model.record(y));
  const auto start = std::chrono::steady_clock::now();
  const double dt = o.dt;
  const std::int64_t steps = o.steps, record_every = o.record_every;
  std::int64_t i = 0, until_record = record_every, next_monitor = monitor_interval_steps;
  std::size_t k = 0;  // the next switch
  bool stop = false;  // the monitor asked to stop
  while (!stop && i < steps) {
    // plain steps up to the next step that contains a switch time, or the next monitor call
    const std::int64_t split = k < switches.step.size() ? switches.step[k] : steps + 1;
    const std::int64_t plain_end = std::min({split - 1, steps, next_monitor});
    while (i < plain_end) {
      out.unconverged_steps += advance<Integrator>(model, y, dt);
      ++i;
      if (--until_record == 0 || i == steps) {
        until_record = record_every;
        append_record(out, grid_time(o, i), model.record(y));
        if ((out.diverged = !y.allFinite())) break;
      }
    }
    if (out.diverged) break;
    if (split <= steps && i == split - 1) {  // step `split` crosses switch times: sub-steps between them
      const std::size_t first = k;
      while (k < switches.step.size() && switches.step[k] == split) ++k;
      out.unconverged_steps += split_step<Integrator>(model, y, o.loads, switches.time.data() + first,
                                                      switches.time.data() + k, grid_time(o, i), grid_time(o, i + 1), dt);
      ++i;
      if (--until_record == 0 || i == steps) {
        until_record = record_every;
        append_record(out, grid_time(o, i), model.record(y));
        if ((out.diverged = !y.allFinite())) break;
      }
    }
    if (i >= next_monitor) {
      stop = o.monitor && o.monitor(i);
      next_monitor = i + monitor_interval_steps;
    }
  }
  out.interrupted = stop;
  out.elapsed_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

// One step from t = o.t0 to t + o.dt, split at the switch times inside it (as run does).
template <class Model>
typename Model::Coordinates one_step(Model model, typename Model::Coordinates y, const SimulationOptions& o) {
  model.set_loads(loads_at(o.loads, o.t0));
  const double t_end = o.t0 + o.dt;
  std::vector<double> switches = switch_times(o.loads, o.t0, t_end);
  // a switch within the on-grid tolerance of t + dt acts from the next step on (as in run)
  while (!switches.empty() && t_end - switches.back() <= on_grid_tolerance(t_end, o.dt)) switches.pop_back();
  visit_method(o.method, [&](auto integrator) {
    split_step<decltype(integrator)>(model, y, o.loads, switches.data(), switches.data() + switches.size(), o.t0,
                                     t_end, o.dt);
  });
  return y;
}

}  // namespace

double recording_bytes(std::int64_t steps, std::int64_t record_every) {
  return (std::floor(static_cast<double>(steps) / static_cast<double>(record_every)) + 2.0) * doubles_per_record *
         sizeof(double);
}

void reserve_records(Trajectory& out, std::int64_t steps, std::int64_t record_every) {
  const double bytes = recording_bytes(steps, record_every);
  if (bytes > unchecked_recording_bytes) {
    const double available = available_memory_bytes();
    if (available >= 0.0 && bytes > available) {
      throw std::invalid_argument("record_every: expected a recording that fits in the memory available (" +
                                  format_bytes(available) + "), got record_every=" + std::to_string(record_every) +
                                  " for steps=" + std::to_string(steps) + ", which would need " + format_bytes(bytes) +
                                  "; record less often (a larger record_every)");
    }
  }
  const auto n = static_cast<std::size_t>(bytes / (doubles_per_record * sizeof(double)));
  for (auto* v : {&out.t, &out.kinetic_energy, &out.total_energy, &out.angular_momentum_norm,
                  &out.quaternion_norm_error, &out.work}) v->reserve(n);
  for (auto* v : {&out.p_W, &out.v_W, &out.w_B}) v->reserve(3 * n);
  out.q_WB.reserve(4 * n);
}

Trajectory simulate(const RigidBody& body, const RigidBodyState& initial, const SimulationOptions& o) {
  check_options(o, true);
  if (o.method == Method::exact) return simulate_exact(body, initial, o);  // closed form, no stepping
  const RigidBodyCoordinates y = to_coordinates(checked_state(initial, "initial"));
  return with_euler_form(body, [&](const auto& euler) {
    using Euler = std::decay_t<decltype(euler)>;
    return visit_method(o.method, [&](auto integrator) {
      // every method runs on a model compiled for the loads of this run (LoadKind)
      return with_load_kind(o.loads, o.gravity_W, [&](auto kind) {
        return run<decltype(integrator)>(RigidBodyModel<Euler, kind.value>(body.mass(), euler, o.gravity_W), y, o);
      });
    });
  });
}

Trajectory simulate(const Particle& particle, const ParticleState& initial, const SimulationOptions& o) {
  check_options(o, true);
  check_particle_loads(o);
  const ParticleModel model(particle, o.gravity_W);
  const ParticleCoordinates y = to_coordinates(checked_state(initial, "initial"));
  return visit_method(o.method, [&](auto integrator) { return run<decltype(integrator)>(model, y, o); });
}

Trajectory simulate(const PlanarBody& body, const PlanarBodyState& initial, const SimulationOptions& o) {
  check_options(o, true);
  check_planar_loads(o);
  const PlanarBodyModel model(body, o.gravity_W);
  const PlanarBodyCoordinates y = to_coordinates(checked_state(initial, "initial"));
  return visit_method(o.method, [&](auto integrator) { return run<decltype(integrator)>(model, y, o); });
}

RigidBodyState step(const RigidBody& body, const RigidBodyState& state, const SimulationOptions& o) {
  check_options(o, false);
  const RigidBodyCoordinates y = to_coordinates(checked_state(state, "state"));
  return with_euler_form(body, [&](const auto& euler) {
    using Euler = std::decay_t<decltype(euler)>;
    return to_rigid_body_state(one_step(RigidBodyModel<Euler>(body.mass(), euler, o.gravity_W), y, o));
  });
}

ParticleState step(const Particle& particle, const ParticleState& state, const SimulationOptions& o) {
  check_options(o, false);
  check_particle_loads(o);
  return to_particle_state(one_step(ParticleModel(particle, o.gravity_W), to_coordinates(checked_state(state)), o));
}

PlanarBodyState step(const PlanarBody& body, const PlanarBodyState& state, const SimulationOptions& o) {
  check_options(o, false);
  check_planar_loads(o);
  return to_planar_state(one_step(PlanarBodyModel(body, o.gravity_W), to_coordinates(checked_state(state)), o));
}

}  // namespace rigiddyn
