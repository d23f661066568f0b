#include "rigiddyn/simulate/simulate.hpp"

#include "append_record.hpp"
#include "run_rigid_body.hpp"


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

}  // namespace

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

double recording_bytes(std::int64_t steps, std::int64_t record_every) {
  return (std::floor(static_cast<double>(steps) / static_cast<double>(record_every)) + 2.0) * doubles_per_record *
         sizeof(double);
}

void check_recording_fits(double bytes, std::int64_t steps, std::int64_t record_every) {
  if (bytes > unchecked_recording_bytes) {
    const double available = available_memory_bytes();
    if (available >= 0.0 && bytes > available) {
      throw std::invalid_argument("record_every: expected a recording that fits in the memory available (" +
                                  format_bytes(available) + "), got record_every=" + std::to_string(record_every) +
                                  " for steps=" + std::to_string(steps) + ", which would need " + format_bytes(bytes) +
                                  "; record less often (a larger record_every)");
    }
  }
}

void reserve_records(Trajectory& out, std::int64_t steps, std::int64_t record_every) {
  const double bytes = recording_bytes(steps, record_every);
  check_recording_fits(bytes, steps, record_every);
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
  return with_euler_form(body, [&](const auto& euler) { return run_rigid_body(body.mass(), euler, y, o); });
}

// the runs of the spherical and principal forms here, the full form's in simulate_rigid_full.cpp (built
// in parallel: the three forms' 90 runs in one translation unit were its longest build)
template Trajectory run_rigid_body(double, const SphericalEuler&, const RigidBodyCoordinates&, const SimulationOptions&);
template Trajectory run_rigid_body(double, const PrincipalEuler&, const RigidBodyCoordinates&, const SimulationOptions&);

}  // namespace rigiddyn
