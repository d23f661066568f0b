// simulate of a particle, a planar body and a rigid body (simulate/simulate.hpp): the run of the body's one-body
// scene (scene/one_body_scene.hpp) read as a Trajectory; the checks of the options and of a recording's size that
// the runs of scenes share.
#include "rigiddyn/simulate/simulate.hpp"

#include "check_options.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/one_body_scene.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace rigiddyn {

namespace {

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

// |H_G| = |I ω_B| [kg m²/s] about the centre of mass, I ω by the form of Euler's equations the body takes (0 for a
// particle)
double angular_momentum_norm(const Body& body, const Eigen::Vector3d& w_B) {
  if (const auto* rigid = std::get_if<RigidBody>(&body)) {
    return with_euler_form(*rigid, [&](const auto& euler) { return euler.momentum(w_B).norm(); });
  }
  if (const auto* planar = std::get_if<PlanarBody>(&body)) return std::abs(planar->inertia_zz() * w_B.z());
  return 0.0;
}

// A body's records in the one-body layout of Trajectory: the scene run's, each element's work summed
Trajectory trajectory_of(const Body& body, SceneSimulation&& run) {
  Trajectory out;
  const std::size_t n = run.size(), ne = static_cast<std::size_t>(run.element_count);
  out.t = std::move(run.t), out.p_W = std::move(run.p_W), out.q_WB = std::move(run.q_WB);
  out.v_W = std::move(run.v_W), out.w_B = std::move(run.w_B);
  out.kinetic_energy = std::move(run.kinetic_energy), out.total_energy = std::move(run.total_energy);
  out.angular_momentum_norm.resize(n), out.quaternion_norm_error.resize(n), out.work.assign(n, 0.0);
  for (std::size_t r = 0; r < n; ++r) {
    out.angular_momentum_norm[r] = angular_momentum_norm(body, Eigen::Vector3d(&out.w_B[3 * r]));
    out.quaternion_norm_error[r] = Eigen::Vector4d(&out.q_WB[4 * r]).norm() - 1.0;
    for (std::size_t e = 0; e < ne; ++e) out.work[r] += run.work[ne * r + e];
  }
  out.diverged = run.diverged, out.interrupted = run.interrupted, out.unconverged_steps = run.unconverged_steps;
  out.elapsed_seconds = run.elapsed_seconds;
  return out;
}

// simulate of the body's one-body scene (its gravity and loads declared as elements where they act)
Trajectory simulate_one_body(const Body& body, const BodyState& initial, const SimulationOptions& o) {
  check_options(o, true);
  const Scene scene = one_body_scene(body, o.gravity_W, o.loads);
  SimulationOptions scene_options = o;
  scene_options.gravity_W.setZero();
  scene_options.loads.clear();
  return trajectory_of(body, simulate(compile_scene(scene, o.method), {initial}, scene_options));
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

Trajectory simulate(const RigidBody& body, const RigidBodyState& initial, const SimulationOptions& o) {
  return simulate_one_body(body, checked_state(initial, "initial"), o);
}

Trajectory simulate(const Particle& particle, const ParticleState& initial, const SimulationOptions& o) {
  return simulate_one_body(particle, checked_state(initial, "initial"), o);
}

Trajectory simulate(const PlanarBody& body, const PlanarBodyState& initial, const SimulationOptions& o) {
  return simulate_one_body(body, checked_state(initial, "initial"), o);
}

}  // namespace rigiddyn
