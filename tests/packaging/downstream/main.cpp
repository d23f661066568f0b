// A downstream program linking the installed rigiddyn through find_package(rigiddyn): the C++
// example of the README. A 0.1 x 0.2 x 0.4 m box of 2 kg tumbles near its intermediate axis
// (Dzhanibekov effect); the DLM splitting integrates it and the exact solution checks it.
#include <rigiddyn/exact/free_body.hpp>
#include <rigiddyn/inertia/primitives.hpp>
#include <rigiddyn/models/rigid_body.hpp>
#include <rigiddyn/simulate/simulate.hpp>
#include <rigiddyn/so3/exp_log.hpp>

#include <cmath>
#include <cstdio>

int main() {
  using namespace rigiddyn;
  const SpatialInertia box = solid_box(Eigen::Vector3d(0.1, 0.2, 0.4), Mass{2.0});
  const RigidBody body(box);

  RigidBodyState initial;
  initial.w_B = Eigen::Vector3d(0.02, 5.0, 0.01);  // rad/s, close to the intermediate axis

  SimulationOptions options;
  options.method = Method::splitting_dlm;
  options.dt = 1e-3;
  options.steps = 10000;
  options.record_every = 10000;
  const Trajectory run = simulate(body, initial, options);

  const TorqueFreeSolution exact(box.inertia_com(), initial.q_WB, initial.w_B);
  const TorqueFreeState truth = exact.state_at(run.t.back());
  const Eigen::Quaterniond q_end(run.q_WB[7], run.q_WB[4], run.q_WB[5], run.q_WB[6]);  // (x, y, z, w) row 1
  const double attitude_error = quat_to_rotvec(truth.q_WB.conjugate() * q_end).norm();
  const double energy_drift = run.kinetic_energy.back() / run.kinetic_energy.front() - 1.0;

  std::printf("t = %.1f s, flip period %.3f s, attitude error %.2e rad, energy drift %.2e\n",
              run.t.back(), exact.period() / 2.0, attitude_error, energy_drift);
  return (attitude_error < 1e-4 && std::abs(energy_drift) < 1e-6) ? 0 : 1;
}
