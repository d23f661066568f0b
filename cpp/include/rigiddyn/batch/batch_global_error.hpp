// The global error estimate of every sample of a batch (batch/simulate_batch.hpp): the estimate of
// simulate/global_error.hpp (global Richardson at h, 2h, 4h with an observed-order check) for each sample,
// from two more batches of the same samples at 2h and 4h (each sample's dt times 2 and 4), so that the
// coarse runs share the batch's threads (and its SIMD lanes). Sample i's estimate is exactly the one
// simulate gives for that sample's run alone.
#pragma once
#include "rigiddyn/batch/batch_result.hpp"
#include "rigiddyn/simulate/global_error.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rigiddyn {

// The estimates of N samples of n records each (nb bodies), row-major, sample-major: each field of
// GlobalErrorEstimate with a leading sample axis. The rows a sample did not fill (its run at h stopped early)
// are NaN, their verdict "no record: the run at h diverged".
struct BatchErrorEstimate {
  std::size_t samples = 0;                  // N
  std::size_t records = 0;                  // n
  std::int64_t bodies = 1;                  // nb
  int order = 0;                            // the order p of sample 0 (0: the method 'exact')
  std::vector<double> attitude;             // (N, n, nb) [rad]
  std::vector<double> angular_velocity;     // (N, n, nb) [rad/s]
  std::vector<double> position;             // (N, n, nb) [m]
  std::vector<double> velocity;             // (N, n, nb) [m/s]
  std::vector<double> energy;               // (N, n) [J]
  std::vector<double> angular_momentum;     // (N, n) [kg m²/s]
  std::vector<double> observed_order;       // (N, n)
  std::vector<std::uint8_t> reliable_quantities;  // (N, n) (GlobalErrorEstimate's)
  std::vector<Verdicts> verdict;            // (N,) sample i's n verdicts
};

// The columns of a batch the estimate reads, as views (a BatchSceneSimulation's, or the same arrays after they became
// a Python result's): row-major, sample-major, N samples of n records of nb bodies, ne work columns, nw wheels.
struct BatchColumns {
  std::size_t samples = 0, records = 0;                // N, n
  std::int64_t bodies = 1, elements = 0, wheels = 0;   // nb, ne, nw
  const std::int64_t* filled = nullptr;                // (N,) the rows each sample filled
  const double *t = nullptr, *q_WB = nullptr, *w_B = nullptr, *p_W = nullptr, *v_W = nullptr;  // (N, n[, nb, 4|3])
  bool scalar_first = false;                           // q_WB as (w, x, y, z)
  const double *total_energy = nullptr, *kinetic_energy = nullptr;  // (N, n) [J]
  const double* angular_momentum_W = nullptr;                        // (N, n, 3) [kg m²/s]
  const double *mass = nullptr, *angular_momentum_O_W = nullptr;     // (N, n, nb) [kg], (N, n, nb, 3) [kg m²/s]
  const double *work = nullptr, *mass_flow_energy = nullptr, *motor_work = nullptr;  // (N, n, ne|nb|nw) [J]
};
BatchColumns batch_columns(const BatchSceneSimulation& batch);

// The columns of sample i (its filled rows) as those of its run alone.
SceneColumns sample_columns(const BatchColumns& batch, std::size_t i);

// What the estimate of one sample needs besides its records: the order of its model for the method (0: the
// method 'exact', the round-off bound alone) and the force it cannot see into ("" for none), as
// estimate_global_error takes them.
struct SampleModel {
  int order = 0;
  std::string opaque;
};

// The estimates of the batch `h` run with `answer` (the options every sample shares; the samples' own dt does
// not enter the estimate), from the batches h2 and h4 of the same samples made with coarse_options(answer, 2)
// and coarse_options(answer, 4) (empty when every model's order is 0). models: one per sample, or one shared.
// The samples are estimated on `threads` threads (batch/parallel_for.hpp).
BatchErrorEstimate batch_error_estimate(const BatchColumns& h, const BatchColumns& h2, const BatchColumns& h4,
                                        const SimulationOptions& answer, const std::vector<SampleModel>& models,
                                        int threads);

// The per-sample dt of the batch at factor·h: each of `dt` times factor (empty stays empty: the common dt of
// coarse_options).
std::vector<double> coarse_dt(const std::vector<double>& dt, int factor);

}  // namespace rigiddyn
