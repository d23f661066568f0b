#include "rigiddyn/batch/batch_result.hpp"

#include "numbers.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace rigiddyn {

namespace {

using detail::nan;

// The first `rows` rows of `width` values of `run` into the block of sample i (N blocks of `records` rows).
void copy_rows(std::vector<double>& batch, std::size_t i, std::size_t records, std::size_t width,
               const std::vector<double>& run, std::size_t rows) {
  if (batch.empty()) return;  // a column the batch does not hold (estimate_records)
  std::copy_n(run.begin(), rows * width, batch.begin() + static_cast<std::ptrdiff_t>(i * records * width));
}

std::vector<double> nans(std::size_t samples, std::size_t records, std::size_t width) {
  return std::vector<double>(samples * records * width, nan);
}

void check_sample(std::size_t i, std::size_t samples) {
  if (i >= samples) {
    throw std::invalid_argument("i: expected a sample index in [0, " + std::to_string(samples) + "), got " +
                                std::to_string(i));
  }
}

}  // namespace

BatchTrajectory empty_batch(std::size_t samples, std::size_t records) {
  BatchTrajectory b;
  b.samples = samples, b.records = records;
  b.t = nans(samples, records, 1), b.p_W = nans(samples, records, 3), b.q_WB = nans(samples, records, 4);
  b.v_W = nans(samples, records, 3), b.w_B = nans(samples, records, 3);
  b.kinetic_energy = b.total_energy = b.angular_momentum_norm = b.quaternion_norm_error = b.work = b.t;
  b.filled.assign(samples, 0);
  b.diverged.assign(samples, 0);
  b.unconverged_steps.assign(samples, 0);
  return b;
}

void put_sample(BatchTrajectory& batch, std::size_t i, const Trajectory& run) {
  check_sample(i, batch.samples);
  const std::size_t n = batch.records, rows = std::min(run.size(), n);
  copy_rows(batch.t, i, n, 1, run.t, rows);
  copy_rows(batch.p_W, i, n, 3, run.p_W, rows);
  copy_rows(batch.q_WB, i, n, 4, run.q_WB, rows);
  copy_rows(batch.v_W, i, n, 3, run.v_W, rows);
  copy_rows(batch.w_B, i, n, 3, run.w_B, rows);
  copy_rows(batch.kinetic_energy, i, n, 1, run.kinetic_energy, rows);
  copy_rows(batch.total_energy, i, n, 1, run.total_energy, rows);
  copy_rows(batch.angular_momentum_norm, i, n, 1, run.angular_momentum_norm, rows);
  copy_rows(batch.quaternion_norm_error, i, n, 1, run.quaternion_norm_error, rows);
  copy_rows(batch.work, i, n, 1, run.work, rows);
  batch.filled[i] = static_cast<std::int64_t>(rows);
  batch.diverged[i] = run.diverged ? 1 : 0;
  batch.unconverged_steps[i] = run.unconverged_steps;
}

BatchSceneSimulation empty_scene_batch(std::size_t samples, std::size_t records, std::int64_t body_count,
                                       std::int64_t element_count, std::int64_t wheel_count,
                                       std::int64_t joint_q_count, std::int64_t joint_v_count, bool estimate_records) {
  const auto nb = static_cast<std::size_t>(body_count), ne = static_cast<std::size_t>(element_count);
  BatchSceneSimulation b;
  b.samples = samples, b.records = records, b.body_count = body_count, b.element_count = element_count;
  b.wheel_count = wheel_count, b.joint_q_count = joint_q_count, b.joint_v_count = joint_v_count;
  b.t = nans(samples, records, 1);
  b.p_W = nans(samples, records, nb * 3);
  b.q_WB = nans(samples, records, nb * 4);
  b.v_W = b.w_B = b.p_W;
  b.kinetic_energy = b.total_energy = b.t;
  b.angular_momentum_W = nans(samples, records, 3);
  b.mass_flow_energy = nans(samples, records, nb);
  b.work = nans(samples, records, ne);
  b.estimate_records = estimate_records;
  if (!estimate_records) {
    b.pivot_reaction_W = b.angular_momentum_O_W = b.p_W;
    b.potential_energy = b.t;
    b.linear_momentum_W = b.angular_momentum_W;
    b.mass = b.mass_flow_energy;
    b.power = b.work;
  }
  b.wheel_speed = b.motor_work = nans(samples, records, static_cast<std::size_t>(wheel_count));
  b.joint_q = nans(samples, records, static_cast<std::size_t>(joint_q_count));
  b.joint_v = nans(samples, records, static_cast<std::size_t>(joint_v_count));
  b.filled.assign(samples, 0);
  b.diverged.assign(samples, 0);
  b.unconverged_steps.assign(samples, 0);
  return b;
}

void put_sample(BatchSceneSimulation& batch, std::size_t i, const SceneSimulation& run) {
  check_sample(i, batch.samples);
  if (run.body_count != batch.body_count || run.element_count != batch.element_count) {
    throw std::invalid_argument("run: expected a scene run of " + std::to_string(batch.body_count) + " bodies and " +
                                std::to_string(batch.element_count) + " elements (the batch's), got " +
                                std::to_string(run.body_count) + " bodies and " + std::to_string(run.element_count) +
                                " elements");
  }
  const std::size_t n = batch.records, rows = std::min(run.size(), n);
  const auto nb = static_cast<std::size_t>(batch.body_count), ne = static_cast<std::size_t>(batch.element_count);
  copy_rows(batch.t, i, n, 1, run.t, rows);
  copy_rows(batch.p_W, i, n, nb * 3, run.p_W, rows);
  copy_rows(batch.q_WB, i, n, nb * 4, run.q_WB, rows);
  copy_rows(batch.v_W, i, n, nb * 3, run.v_W, rows);
  copy_rows(batch.w_B, i, n, nb * 3, run.w_B, rows);
  copy_rows(batch.kinetic_energy, i, n, 1, run.kinetic_energy, rows);
  copy_rows(batch.potential_energy, i, n, 1, run.potential_energy, rows);
  copy_rows(batch.total_energy, i, n, 1, run.total_energy, rows);
  copy_rows(batch.linear_momentum_W, i, n, 3, run.linear_momentum_W, rows);
  copy_rows(batch.angular_momentum_W, i, n, 3, run.angular_momentum_W, rows);
  copy_rows(batch.pivot_reaction_W, i, n, nb * 3, run.pivot_reaction_W, rows);
  copy_rows(batch.angular_momentum_O_W, i, n, nb * 3, run.angular_momentum_O_W, rows);
  copy_rows(batch.mass, i, n, nb, run.mass, rows);
  copy_rows(batch.work, i, n, ne, run.work, rows);
  copy_rows(batch.power, i, n, ne, run.power, rows);
  if (run.mass_flow_energy.empty()) {  // no body with a mass flow: every value 0 (scene_simulation.hpp)
    std::fill_n(batch.mass_flow_energy.begin() + static_cast<std::ptrdiff_t>(i * n * nb), rows * nb, 0.0);
  } else {
    copy_rows(batch.mass_flow_energy, i, n, nb, run.mass_flow_energy, rows);
  }
  const auto nw = static_cast<std::size_t>(batch.wheel_count);
  if (run.wheel_speed.size() != run.size() * nw || run.motor_work.size() != run.size() * nw) {
    throw std::invalid_argument("run: expected " + std::to_string(nw) + " wheel speeds per record (the batch's), got " +
                                std::to_string(run.wheel_speed.size()) + " values in " + std::to_string(run.size()) +
                                " records");
  }
  if (nw > 0) {
    copy_rows(batch.wheel_speed, i, n, nw, run.wheel_speed, rows);
    copy_rows(batch.motor_work, i, n, nw, run.motor_work, rows);
  }
  const auto nq = static_cast<std::size_t>(batch.joint_q_count), nv = static_cast<std::size_t>(batch.joint_v_count);
  if (run.joint_q.size() != run.size() * nq || run.joint_v.size() != run.size() * nv) {
    throw std::invalid_argument("run: expected " + std::to_string(nq) + " tree coordinates and " + std::to_string(nv) +
                                " velocities per record (the batch's), got " + std::to_string(run.joint_q.size()) +
                                " and " + std::to_string(run.joint_v.size()) + " values in " + std::to_string(run.size()) +
                                " records");
  }
  if (nq > 0) copy_rows(batch.joint_q, i, n, nq, run.joint_q, rows);
  if (nv > 0) copy_rows(batch.joint_v, i, n, nv, run.joint_v, rows);
  batch.filled[i] = static_cast<std::int64_t>(rows);
  batch.diverged[i] = run.diverged ? 1 : 0;
  batch.unconverged_steps[i] = run.unconverged_steps;
}

}  // namespace rigiddyn
