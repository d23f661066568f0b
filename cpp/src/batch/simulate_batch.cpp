#include "rigiddyn/batch/simulate_batch.hpp"

#include "rigiddyn/batch/parallel_for.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <utility>

namespace rigiddyn {

std::size_t batch_record_count(std::int64_t steps, std::int64_t record_every) {
  if (steps < 0) throw_invalid("steps", "an integer >= 0", steps);
  if (record_every < 1) throw_invalid("record_every", "an integer >= 1", record_every);
  // step 0, steps k·record_every for k = 1 .. floor(steps / record_every), and the last step if not among them
  return static_cast<std::size_t>(1 + steps / record_every + (steps % record_every != 0 ? 1 : 0));
}

namespace {

// "sample <i>: " and the message of `cause` (std::exception's what(), else its lack of one).
std::string sample_failure_message(std::size_t sample, const std::exception_ptr& cause) {
  std::string what = "an exception not derived from std::exception";
  try {
    std::rethrow_exception(cause);
  } catch (const std::exception& e) {
    what = e.what();
  } catch (...) {
  }
  return "sample " + std::to_string(sample) + ": " + what;
}

}  // namespace

SampleFailure::SampleFailure(std::size_t sample, std::exception_ptr cause)
    : std::runtime_error(sample_failure_message(sample, cause)), sample_(sample), cause_(std::move(cause)) {}

namespace {

using StepMonitor = std::function<bool(std::int64_t)>;

// `count` items of a per-sample argument: none (the common value) or one per sample.
void check_per_sample(std::size_t count, std::size_t samples, const char* name, const char* what) {
  if (count != 0 && count != samples) {
    throw std::invalid_argument(std::string(name) + ": expected one " + what + " per sample (N = " +
                                std::to_string(samples) + ") or a common one, got " + std::to_string(count));
  }
}

// The checks done before any thread starts (simulate.hpp "Checked before any thread starts").
void check_batch(std::size_t samples, std::size_t models, const char* model_name, const std::vector<double>& dt,
                 int threads) {
  if (samples == 0) throw std::invalid_argument("initial: expected at least one sample, got 0");
  if (models != 1 && models != samples) {
    throw std::invalid_argument(std::string(model_name) + ": expected 1 (shared) or N = " + std::to_string(samples) +
                                " (one per sample), got " + std::to_string(models));
  }
  check_per_sample(dt.size(), samples, "dt", "step");
  if (threads < 1) throw_invalid("threads", "an integer >= 1", threads);
}

// True for a sample's own error (simulate_batch.hpp): exactly std::invalid_argument, std::domain_error or
// std::runtime_error, the types the core throws for a bad sample.
bool is_sample_error(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::exception& e) {
    const std::type_info& type = typeid(e);
    return type == typeid(std::invalid_argument) || type == typeid(std::domain_error) ||
           type == typeid(std::runtime_error);
  } catch (...) {
    return false;
  }
}

// A sample's own error rethrown with its message prefixed "sample <i>: ", its type kept.
[[noreturn]] void rethrow_for_sample(std::size_t i, const std::exception_ptr& error) {
  const std::string prefix = "sample " + std::to_string(i) + ": ";
  try {
    std::rethrow_exception(error);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(prefix + e.what());
  } catch (const std::domain_error& e) {
    throw std::domain_error(prefix + e.what());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(prefix + e.what());
  }
}

// The first failure (in time) that stops the batch, and its sample; any thread may report one.
class FirstStop {
 public:
  // Keeps (i, error) if it is the first; returns whether it was.
  bool keep(std::size_t i, std::exception_ptr error) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (error_) return false;
    error_ = std::move(error), sample_ = i;
    return true;
  }
  void rethrow() const {
    if (error_) throw SampleFailure(sample_, error_);
  }

 private:
  std::mutex mutex_;
  std::exception_ptr error_;
  std::size_t sample_ = 0;
};

// Runs run_sample(i, monitor) for every sample i in [0, samples) on `threads` threads, in chunks of
// consecutive samples; run_sample returns true when its run was interrupted by the monitor it was given,
// which every sample gets: it stops the run once the batch is stopped (by `monitor`, or by a failure that is
// not a sample's own error), checked at simulate's monitor pace. `monitor` (the batch's: samples done ->
// stop; may be empty) is called from the calling thread only. Rethrows, after every thread joined, the
// first failure that stopped the batch (SampleFailure), else the own error of the lowest failing sample
// (prefixed); returns whether the monitor stopped the batch.
bool run_samples(std::size_t samples, int threads, const StepMonitor& monitor,
                 const std::function<bool(std::size_t i, const StepMonitor& sample_monitor)>& run_sample) {
  // about 8 chunks per thread: balance between threads, and few chunk boundaries (each one a place where
  // two threads write neighbouring rows)
  const std::size_t chunk = std::max<std::size_t>(1, samples / (8 * static_cast<std::size_t>(threads)));
  const std::size_t chunks = (samples + chunk - 1) / chunk;
  std::atomic<bool> stop{false}, monitor_stopped{false};
  std::atomic<std::int64_t> done{0};
  auto ask_monitor = [&] {  // calling thread only
    if (monitor && !stop.load(std::memory_order_relaxed) && monitor(done.load(std::memory_order_relaxed))) {
      monitor_stopped.store(true, std::memory_order_relaxed);
      stop.store(true, std::memory_order_relaxed);
    }
  };
  const StepMonitor follow_stop = [&](std::int64_t) { return stop.load(std::memory_order_relaxed); };
  const StepMonitor main_monitor = [&](std::int64_t) {
    ask_monitor();
    return stop.load(std::memory_order_relaxed);
  };
  // the first own error of each chunk (its lowest sample): chunk-owned, no lock
  std::vector<std::exception_ptr> failure(chunks);
  std::vector<std::size_t> failed_sample(chunks, 0);
  FirstStop first_stop;
  ask_monitor();  // once before any sample starts (whichever thread then takes the samples)
  parallel_for(
      chunks, threads,
      [&](std::size_t c, int worker) {
        const StepMonitor& sample_monitor = monitor && worker == 0 ? main_monitor : follow_stop;
        for (std::size_t i = c * chunk; i < std::min(samples, (c + 1) * chunk); ++i) {
          if (stop.load(std::memory_order_relaxed)) return;
          try {
            if (run_sample(i, sample_monitor)) return;
          } catch (...) {
            std::exception_ptr error = std::current_exception();
            if (!is_sample_error(error)) {  // e.g. a Python force's exception: every sample stops
              first_stop.keep(i, std::move(error));
              stop.store(true, std::memory_order_relaxed);
              return;
            }
            if (!failure[c]) failure[c] = std::move(error), failed_sample[c] = i;
          }
          done.fetch_add(1, std::memory_order_relaxed);
          if (worker == 0) ask_monitor();
        }
      },
      monitor ? std::function<void()>(ask_monitor) : std::function<void()>());
  first_stop.rethrow();
  for (std::size_t c = 0; c < chunks; ++c) {
    if (failure[c]) rethrow_for_sample(failed_sample[c], failure[c]);
  }
  return monitor_stopped.load();
}

// Sample i's options: common with its dt, gravity and loads.
SimulationOptions sample_options(const SimulationOptions& common, const BatchParameters& p, std::size_t i,
                                 const StepMonitor& monitor) {
  SimulationOptions o = common;
  if (!p.dt.empty()) o.dt = p.dt[i];
  if (!p.gravity_W.empty()) o.gravity_W = p.gravity_W[i];
  if (!p.loads.empty()) o.loads = p.loads[i];
  o.monitor = monitor;
  return o;
}

template <class Body, class State>
BatchTrajectory batch_of_bodies(const std::vector<Body>& bodies, const std::vector<State>& initial,
                                const SimulationOptions& common, const BatchParameters& p, int threads) {
  const auto start = std::chrono::steady_clock::now();
  const std::size_t samples = initial.size();
  check_batch(samples, bodies.size(), "bodies", p.dt, threads);
  check_per_sample(p.gravity_W.size(), samples, "gravity", "gravity vector");
  check_per_sample(p.loads.size(), samples, "loads", "load schedule");
  BatchTrajectory out = empty_batch(samples, batch_record_count(common.steps, common.record_every));
  out.interrupted = run_samples(samples, threads, common.monitor, [&](std::size_t i, const StepMonitor& monitor) {
    const Trajectory run = simulate(bodies[bodies.size() == 1 ? 0 : i], initial[i], sample_options(common, p, i, monitor));
    put_sample(out, i, run);
    return run.interrupted;
  });
  out.elapsed_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace

BatchTrajectory simulate_batch(const std::vector<RigidBody>& bodies, const std::vector<RigidBodyState>& initial,
                               const SimulationOptions& common, const BatchParameters& per_sample, int threads) {
  return batch_of_bodies(bodies, initial, common, per_sample, threads);
}

BatchTrajectory simulate_batch(const std::vector<Particle>& particles, const std::vector<ParticleState>& initial,
                               const SimulationOptions& common, const BatchParameters& per_sample, int threads) {
  return batch_of_bodies(particles, initial, common, per_sample, threads);
}

BatchTrajectory simulate_batch(const std::vector<PlanarBody>& bodies, const std::vector<PlanarBodyState>& initial,
                               const SimulationOptions& common, const BatchParameters& per_sample, int threads) {
  return batch_of_bodies(bodies, initial, common, per_sample, threads);
}

BatchSceneSimulation simulate_batch(const std::vector<CompiledScene>& scenes,
                                    const std::vector<std::vector<BodyState>>& initial,
                                    const SimulationOptions& common, const std::vector<double>& dt, int threads) {
  const auto start = std::chrono::steady_clock::now();
  const std::size_t samples = initial.size();
  check_batch(samples, scenes.size(), "scenes", dt, threads);
  const std::size_t nb = scenes[0].scene().bodies.size(), ne = scenes[0].element_types().size();
  const std::size_t nw = wheel_count(scenes[0].scene().bodies);
  const JointCounts joints = joint_counts(scenes[0].scene().bodies);  // each sample's run checks its own (put_sample)
  for (std::size_t s = 1; s < scenes.size(); ++s) {
    const std::size_t nb_s = scenes[s].scene().bodies.size(), ne_s = scenes[s].element_types().size();
    const std::size_t nw_s = wheel_count(scenes[s].scene().bodies);
    if (nb_s != nb || ne_s != ne || nw_s != nw) {
      throw std::invalid_argument("scenes[" + std::to_string(s) + "]: expected a scene of " + std::to_string(nb) +
                                  " bodies, " + std::to_string(ne) + " work columns and " + std::to_string(nw) +
                                  " gyrostat wheels (as scenes[0]), got " + std::to_string(nb_s) + " bodies, " +
                                  std::to_string(ne_s) + " work columns and " + std::to_string(nw_s) + " wheels");
    }
  }
  BatchSceneSimulation out = empty_scene_batch(samples, batch_record_count(common.steps, common.record_every),
                                               static_cast<std::int64_t>(nb), static_cast<std::int64_t>(ne),
                                               static_cast<std::int64_t>(nw), static_cast<std::int64_t>(joints.q),
                                               static_cast<std::int64_t>(joints.v), common.estimate_records);
  const BatchParameters p{dt, {}, {}};
  out.interrupted = run_samples(samples, threads, common.monitor, [&](std::size_t i, const StepMonitor& monitor) {
    const SceneSimulation run =
        simulate(scenes[scenes.size() == 1 ? 0 : i], initial[i], sample_options(common, p, i, monitor));
    put_sample(out, i, run);
    return run.interrupted;
  });
  out.elapsed_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace rigiddyn
