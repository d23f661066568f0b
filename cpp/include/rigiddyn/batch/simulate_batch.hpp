// simulate_batch: N independent runs of one model (a body, or a compiled scene) from per-sample initial
// states with per-sample parameters, on a thread pool (batch/parallel_for.hpp). Each sample is the EXISTING
// single run (simulate/simulate.hpp, scene/simulate_scene.hpp) into a thread-owned record, copied once into
// the sample's rows of the stacked result (batch/batch_result.hpp): the batch equals N serial simulate calls
// bitwise, whatever the thread count. A sample whose state becomes non-finite stops alone (its diverged flag
// set, the rest of its rows NaN); the other samples are untouched.
//
// Samples are handed out in chunks of consecutive indices, so that each thread writes one contiguous block
// of the output (no false sharing between threads writing neighbouring rows).
#pragma once
#include "rigiddyn/batch/batch_result.hpp"
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <stdexcept>
#include <vector>

namespace rigiddyn {

// Per-sample parameters; an empty vector means "the common value (SimulationOptions) for every sample".
struct BatchParameters {
  std::vector<double> dt;                       // (N,) step of each sample [s]; empty: common.dt
  std::vector<Eigen::Vector3d> gravity_W;       // (N,) uniform gravity in W [m/s²]; empty: common.gravity_W
  std::vector<std::vector<AppliedLoad>> loads;  // (N,) load schedules (models/loads.hpp); empty: common.loads
};

// The record count of one full run of `steps` steps recorded every `record_every`-th step: the first,
// every record_every-th and the last (1 + ceil(steps / record_every)). std::invalid_argument naming steps
// (< 0) or record_every (< 1).
std::size_t batch_record_count(std::int64_t steps, std::int64_t record_every);

// The exception simulate_batch throws when a sample fails with anything but its own error (see below), e.g.
// a Python force's exception or std::bad_alloc: the first such failure stops every sample. what() is
// "sample <i>: " and the cause's message; cause() is the exception itself (to rethrow, e.g. as the Python
// exception it carries).
class SampleFailure : public std::runtime_error {
 public:
  SampleFailure(std::size_t sample, std::exception_ptr cause);
  std::size_t sample() const noexcept { return sample_; }
  const std::exception_ptr& cause() const noexcept { return cause_; }

 private:
  std::size_t sample_;
  std::exception_ptr cause_;
};

// N = initial.size() runs: sample i is simulate(bodies[i] (or bodies[0] when one body is shared),
// initial[i], options_i), options_i = common with the sample's dt, gravity_W and loads. threads >= 1 (the
// calling thread is one of them; the Python layer turns None into default_thread_count()).
// common.monitor, if set, is called from the calling thread only, with the number of samples done (once
// before any sample starts, about every 10 ms while it waits, after each of its samples and at each of its
// samples' monitor checks, at simulate's pace: about every monitor_period_seconds); returning true stops
// every sample at its next check
// (every sample checks at that pace), skips those not started, and returns the batch so far with
// interrupted set.
// Checked before any thread starts (std::invalid_argument naming the argument and both sizes): N >= 1
// ("initial"), bodies 1 or N ("bodies"), per_sample's vectors empty or N ("dt", "gravity", "loads"),
// threads >= 1, steps >= 0, record_every >= 1. Every other check is simulate's, per sample. A sample's own
// error (exactly std::invalid_argument, std::domain_error or std::runtime_error: a bad state, a body
// running out of mass) stops that sample alone: the one of the lowest failing sample is rethrown after every
// thread has joined, its type kept and its message prefixed with "sample <i>: ". Any other exception
// (a subclass of those, e.g. a Python force's, or any other type) stops every sample at its next check,
// skips those not started, and is rethrown as SampleFailure (the first one raised) after every thread has
// joined.
BatchTrajectory simulate_batch(const std::vector<RigidBody>& bodies, const std::vector<RigidBodyState>& initial,
                               const SimulationOptions& common, const BatchParameters& per_sample, int threads);
// The same for particles (records: q_WB = identity, w_B = 0) and planar bodies (p_W = (x, y, 0),
// q_WB = Rz(θ), w_B = (0, 0, ω)), as simulate records them.
BatchTrajectory simulate_batch(const std::vector<Particle>& particles, const std::vector<ParticleState>& initial,
                               const SimulationOptions& common, const BatchParameters& per_sample, int threads);
BatchTrajectory simulate_batch(const std::vector<PlanarBody>& bodies, const std::vector<PlanarBodyState>& initial,
                               const SimulationOptions& common, const BatchParameters& per_sample, int threads);

// N = initial.size() runs of simulate(scenes[i] (or scenes[0] when one is shared), initial[i], options_i),
// options_i = common with the sample's dt (dt empty: common.dt). A scene's gravity and loads are its
// elements (common.gravity_W and common.loads must be left empty, as simulate requires). N scenes must have
// the same structure: as many bodies and work columns as scenes[0] ("scenes[i]"). Checks, monitor, threads
// and exceptions as the bodies' simulate_batch above (a sample whose body runs out of mass: "sample <i>:
// mass_flows[..]: ...").
BatchSceneSimulation simulate_batch(const std::vector<CompiledScene>& scenes,
                                    const std::vector<std::vector<BodyState>>& initial,
                                    const SimulationOptions& common, const std::vector<double>& dt, int threads);

}  // namespace rigiddyn
