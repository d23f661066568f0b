#include "rigiddyn/batch/batch_global_error.hpp"

#include "rigiddyn/batch/parallel_for.hpp"

#include <algorithm>
#include <limits>

namespace rigiddyn {

namespace {

// Moves the estimate `e` of sample i (e.verdict.size() <= n records) into its rows of `out`; the rows after them
// say that the run at h stopped there.
void put_estimate(BatchErrorEstimate& out, std::size_t i, GlobalErrorEstimate&& e) {
  const std::size_t n = out.records, nb = static_cast<std::size_t>(out.bodies);
  std::copy(e.attitude.begin(), e.attitude.end(), out.attitude.begin() + i * n * nb);
  std::copy(e.angular_velocity.begin(), e.angular_velocity.end(), out.angular_velocity.begin() + i * n * nb);
  std::copy(e.position.begin(), e.position.end(), out.position.begin() + i * n * nb);
  std::copy(e.velocity.begin(), e.velocity.end(), out.velocity.begin() + i * n * nb);
  std::copy(e.energy.begin(), e.energy.end(), out.energy.begin() + i * n);
  std::copy(e.angular_momentum.begin(), e.angular_momentum.end(), out.angular_momentum.begin() + i * n);
  std::copy(e.observed_order.begin(), e.observed_order.end(), out.observed_order.begin() + i * n);
  std::copy(e.reliable_quantities.begin(), e.reliable_quantities.end(), out.reliable_quantities.begin() + i * n);
  Verdicts& verdict = out.verdict[i] = std::move(e.verdict);
  while (verdict.size() < n) verdict.push_back("no record: the run at h diverged");
}

}  // namespace

BatchColumns batch_columns(const BatchSceneSimulation& batch) {
  BatchColumns c;
  c.samples = batch.samples, c.records = batch.records;
  c.bodies = batch.body_count, c.elements = batch.element_count, c.wheels = batch.wheel_count;
  c.filled = batch.filled.data();
  c.t = batch.t.data(), c.q_WB = batch.q_WB.data(), c.w_B = batch.w_B.data(), c.p_W = batch.p_W.data();
  c.v_W = batch.v_W.data();
  c.total_energy = batch.total_energy.data(), c.kinetic_energy = batch.kinetic_energy.data();
  c.angular_momentum_W = batch.angular_momentum_W.data();
  // the columns an estimate_records batch has not, and those of no value (no element, no wheel): none
  const auto column = [](const std::vector<double>& values) { return values.empty() ? nullptr : values.data(); };
  c.mass = column(batch.mass), c.angular_momentum_O_W = column(batch.angular_momentum_O_W);
  c.work = column(batch.work), c.mass_flow_energy = column(batch.mass_flow_energy);
  c.motor_work = column(batch.motor_work);
  return c;
}

SceneColumns sample_columns(const BatchColumns& batch, std::size_t i) {
  const std::size_t row = i * batch.records, nb = static_cast<std::size_t>(batch.bodies);
  const std::size_t ne = static_cast<std::size_t>(batch.elements), nw = static_cast<std::size_t>(batch.wheels);
  SceneColumns c;
  c.n = static_cast<std::size_t>(batch.filled[i]);
  c.bodies = batch.bodies;
  c.t = batch.t + row;
  c.q_WB = batch.q_WB + row * nb * 4, c.scalar_first = batch.scalar_first;
  c.w_B = batch.w_B + row * nb * 3, c.p_W = batch.p_W + row * nb * 3, c.v_W = batch.v_W + row * nb * 3;
  c.total_energy = batch.total_energy + row, c.angular_momentum_W = batch.angular_momentum_W + row * 3;
  c.kinetic_energy = batch.kinetic_energy + row, c.kinetic_energy_size = c.n;
  // the sample's rows of a column of `width` values a record, and their count (none where the batch has no column)
  const auto rows_of = [&](const double* column, std::size_t width, const double*& rows, std::size_t& size) {
    rows = column == nullptr ? nullptr : column + row * width;
    size = column == nullptr ? 0 : c.n * width;
  };
  rows_of(batch.mass, nb, c.mass, c.mass_size);
  rows_of(batch.angular_momentum_O_W, nb * 3, c.angular_momentum_O_W, c.angular_momentum_O_W_size);
  rows_of(batch.work, ne, c.work, c.work_size);
  rows_of(batch.mass_flow_energy, nb, c.mass_flow_energy, c.mass_flow_energy_size);
  rows_of(batch.motor_work, nw, c.motor_work, c.motor_work_size);
  return c;
}

BatchErrorEstimate batch_error_estimate(const BatchColumns& h, const BatchColumns& h2, const BatchColumns& h4,
                                        const SimulationOptions& answer, const std::vector<SampleModel>& models,
                                        int threads) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  BatchErrorEstimate out;
  out.samples = h.samples, out.records = h.records, out.bodies = h.bodies;
  out.order = models.empty() ? 0 : models[0].order;
  const std::size_t rows = h.samples * h.records, nb = static_cast<std::size_t>(out.bodies);
  for (auto* per_body : {&out.attitude, &out.angular_velocity, &out.position, &out.velocity}) per_body->assign(rows * nb, nan);
  for (auto* per_record : {&out.energy, &out.angular_momentum, &out.observed_order}) per_record->assign(rows, nan);
  out.reliable_quantities.assign(rows, 0);  // the rows after a sample's diverged run: none reliable
  out.verdict.resize(h.samples);  // each sample's filled by put_estimate
  // each sample writes only its own rows
  parallel_for(h.samples, threads, [&](std::size_t i, int) {
    const SampleModel& model = models[models.size() == 1 ? 0 : i];
    // as simulate reads its run's records (global_error.hpp: the coarse runs' without the answer's round-off size)
    const ErrorRecords records = error_records(sample_columns(h, i));
    put_estimate(out, i,
                 model.order == 0 ? round_off_estimate(records, answer)
                                  : estimate_global_error(records, error_records(sample_columns(h2, i), false),
                                                          error_records(sample_columns(h4, i), false), answer,
                                                          model.order, model.opaque));
  });
  return out;
}

std::vector<double> coarse_dt(const std::vector<double>& dt, int factor) {
  std::vector<double> out = dt;
  for (double& d : out) d *= factor;
  return out;
}

}  // namespace rigiddyn
