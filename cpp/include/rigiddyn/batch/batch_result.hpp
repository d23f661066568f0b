// The records of N runs of one model stacked sample by sample (batch/simulate_batch.hpp): every array has
// a leading sample axis, the rows of sample i contiguous (sample-major, then record, then component), so
// that each thread of a batch writes one block. A sample that stopped early (its state became non-finite)
// fills fewer rows; the rest of its rows stay NaN.
#pragma once
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rigiddyn {

// N runs of the same record count n (= the record count of one full run), row-major:
struct BatchTrajectory {
  std::size_t samples = 0;                    // N
  std::size_t records = 0;                    // n
  std::vector<double> t;                      // (N, n) time [s]
  std::vector<double> p_W;                    // (N, n, 3) centre of mass position in W [m]
  std::vector<double> q_WB;                   // (N, n, 4) attitude (x, y, z, w)
  std::vector<double> v_W;                    // (N, n, 3) centre of mass velocity in W [m/s]
  std::vector<double> w_B;                    // (N, n, 3) angular velocity in B [rad/s]
  std::vector<double> kinetic_energy;         // (N, n) T [J]
  std::vector<double> total_energy;           // (N, n) T + V of gravity [J]
  std::vector<double> angular_momentum_norm;  // (N, n) |H_G| [kg m²/s]
  std::vector<double> quaternion_norm_error;  // (N, n) |q| − 1
  std::vector<double> work;                   // (N, n) work of loads and gravity since t0 [J]
  std::vector<std::int64_t> filled;           // (N,) rows filled per sample (n unless it stopped early)
  std::vector<std::uint8_t> diverged;         // (N,) 1 where the sample's state became non-finite
  std::vector<std::int64_t> unconverged_steps;  // (N,) implicit solves that hit their iteration cap
  double elapsed_seconds = 0.0;               // wall time of the whole batch [s]
  bool interrupted = false;                   // the monitor stopped the batch: samples not run stay NaN
};

// A batch of `samples` runs of `records` records each, every value NaN, filled 0, diverged 0.
BatchTrajectory empty_batch(std::size_t samples, std::size_t records);

// Copies the run of sample i into its rows (at most `records` of them) and sets filled[i], diverged[i] and
// unconverged_steps[i].
void put_sample(BatchTrajectory& batch, std::size_t i, const Trajectory& run);

// N runs of scenes of the same structure (nb bodies, ne work columns) and the same record count n: each
// array of SceneSimulation with a leading sample axis, row-major, sample-major.
struct BatchSceneSimulation {
  std::size_t samples = 0;                    // N
  std::size_t records = 0;                    // n
  std::int64_t body_count = 0;                // nb
  std::int64_t element_count = 0;             // ne (the scene's elements, then the frame's fictitious terms)
  std::int64_t wheel_count = 0;               // nw (the wheels of the scene's gyrostats)
  std::int64_t joint_q_count = 0;             // nq (the coordinates of the scene's trees)
  std::int64_t joint_v_count = 0;             // nv (their velocities)
  std::vector<double> t;                      // (N, n) time [s]
  std::vector<double> p_W;                    // (N, n, nb, 3) centre of mass positions in W [m]
  std::vector<double> q_WB;                   // (N, n, nb, 4) attitudes (x, y, z, w)
  std::vector<double> v_W;                    // (N, n, nb, 3) centre of mass velocities in W [m/s]
  std::vector<double> w_B;                    // (N, n, nb, 3) angular velocities, each in its body's B [rad/s]
  std::vector<double> kinetic_energy;         // (N, n) [J]
  std::vector<double> potential_energy;       // (N, n) [J]
  std::vector<double> total_energy;           // (N, n) [J]
  std::vector<double> linear_momentum_W;      // (N, n, 3) [kg m/s]
  std::vector<double> angular_momentum_W;     // (N, n, 3) about W's origin [kg m²/s]
  std::vector<double> pivot_reaction_W;       // (N, n, nb, 3) [N]
  std::vector<double> angular_momentum_O_W;   // (N, n, nb, 3) about each body's pivot (else its C), in W [kg m²/s]
  std::vector<double> mass;                   // (N, n, nb) [kg]
  std::vector<double> work;                   // (N, n, ne) each element's work since t0 [J]
  std::vector<double> power;                  // (N, n, ne) each element's power [W]
  std::vector<double> mass_flow_energy;       // (N, n, nb) each body's mass-flow energy since t0 [J]
  std::vector<double> wheel_speed;            // (N, n, nw) each gyrostat wheel's speed relative to its body [rad/s]
  std::vector<double> motor_work;             // (N, n, nw) each wheel's motor work since t0 [J]
  std::vector<double> joint_q;                // (N, n, nq) the trees' configurations q
  std::vector<double> joint_v;                // (N, n, nv) their velocities v
  std::vector<std::int64_t> filled;           // (N,) rows filled per sample (n unless it stopped early)
  std::vector<std::uint8_t> diverged;         // (N,) 1 where the sample's state became non-finite
  std::vector<std::int64_t> unconverged_steps;  // (N,)
  double elapsed_seconds = 0.0;               // wall time of the whole batch [s]
  bool interrupted = false;                   // the monitor stopped the batch: samples not run stay NaN
  // The batch holds what the global error estimate reads of a coarse batch (SimulationOptions' estimate_records):
  // potential_energy, linear_momentum_W, pivot_reaction_W, angular_momentum_O_W, mass and power are empty.
  bool estimate_records = false;
};

// A batch of `samples` scene runs of `records` records, nb bodies, ne work columns, nw gyrostat wheels and the trees'
// nq coordinates and nv velocities, every value NaN; with `estimate_records`, without the columns it names.
BatchSceneSimulation empty_scene_batch(std::size_t samples, std::size_t records, std::int64_t body_count,
                                       std::int64_t element_count, std::int64_t wheel_count = 0,
                                       std::int64_t joint_q_count = 0, std::int64_t joint_v_count = 0,
                                       bool estimate_records = false);

// Copies the scene run of sample i into its rows, as put_sample above, each column the batch has (std::invalid_argument
// if the run's body or element count is not the batch's).
void put_sample(BatchSceneSimulation& batch, std::size_t i, const SceneSimulation& run);

}  // namespace rigiddyn
