#include "rigiddyn/batch/batch_global_error.hpp"

#include "rigiddyn/batch/parallel_for.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <limits>

namespace rigiddyn {

namespace {

// The records of sample i of a batch of `bodies` bodies per record: its filled rows, pointers into the batch.
template <class Batch>
ErrorRecords sample_records(const Batch& b, std::size_t i, std::int64_t bodies) {
  const std::size_t row = i * b.records, nb = static_cast<std::size_t>(bodies);
  ErrorRecords out;
  out.n = static_cast<std::size_t>(b.filled[i]);
  out.bodies = bodies;
  out.t = b.t.data() + row;
  out.q_WB = b.q_WB.data() + row * nb * 4;
  out.w_B = b.w_B.data() + row * nb * 3;
  out.p_W = b.p_W.data() + row * nb * 3;
  out.v_W = b.v_W.data() + row * nb * 3;
  out.energy = b.total_energy.data() + row;
  out.energy_scale = b.kinetic_energy.data() + row;
  return out;
}

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
  Verdicts& verdict = out.verdict[i] = std::move(e.verdict);
  while (verdict.size() < n) verdict.push_back("no record: the run at h diverged");
}

std::int64_t bodies_of(const BatchTrajectory&) { return 1; }
std::int64_t bodies_of(const BatchSceneSimulation& b) { return b.body_count; }

}  // namespace

ErrorRecords error_records(const BatchTrajectory& batch, std::size_t i) {
  ErrorRecords out = sample_records(batch, i, 1);
  const auto first = batch.angular_momentum_norm.begin() + static_cast<std::ptrdiff_t>(i * batch.records);
  out.momentum.assign(first, first + static_cast<std::ptrdiff_t>(out.n));
  return out;
}

ErrorRecords error_records(const BatchSceneSimulation& batch, std::size_t i) {
  ErrorRecords out = sample_records(batch, i, batch.body_count);
  const double* L_W = batch.angular_momentum_W.data() + i * batch.records * 3;
  for (std::size_t k = 0; k < out.n; ++k) out.momentum.push_back(Eigen::Map<const Eigen::Vector3d>(L_W + 3 * k).norm());
  return out;
}

template <class Batch>
BatchErrorEstimate batch_error_estimate(const Batch& h, const Batch& h2, const Batch& h4,
                                        const SimulationOptions& answer, const std::vector<SampleModel>& models,
                                        int threads) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  BatchErrorEstimate out;
  out.samples = h.samples, out.records = h.records, out.bodies = bodies_of(h);
  out.order = models.empty() ? 0 : models[0].order;
  const std::size_t rows = h.samples * h.records, nb = static_cast<std::size_t>(out.bodies);
  for (auto* per_body : {&out.attitude, &out.angular_velocity, &out.position, &out.velocity}) per_body->assign(rows * nb, nan);
  for (auto* per_record : {&out.energy, &out.angular_momentum, &out.observed_order}) per_record->assign(rows, nan);
  out.verdict.resize(h.samples);  // each sample's filled by put_estimate
  // each sample writes only its own rows
  parallel_for(h.samples, threads, [&](std::size_t i, int) {
    const SampleModel& model = models[models.size() == 1 ? 0 : i];
    const ErrorRecords records = error_records(h, i);
    put_estimate(out, i,
                 model.order == 0 ? round_off_estimate(records, answer)
                                  : estimate_global_error(records, error_records(h2, i), error_records(h4, i), answer,
                                                          model.order, model.opaque));
  });
  return out;
}

template BatchErrorEstimate batch_error_estimate(const BatchTrajectory&, const BatchTrajectory&, const BatchTrajectory&,
                                                 const SimulationOptions&, const std::vector<SampleModel>&, int);
template BatchErrorEstimate batch_error_estimate(const BatchSceneSimulation&, const BatchSceneSimulation&,
                                                 const BatchSceneSimulation&, const SimulationOptions&,
                                                 const std::vector<SampleModel>&, int);

std::vector<double> coarse_dt(const std::vector<double>& dt, int factor) {
  std::vector<double> out = dt;
  for (double& d : out) d *= factor;
  return out;
}

}  // namespace rigiddyn
