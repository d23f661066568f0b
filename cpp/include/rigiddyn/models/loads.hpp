// Applied loads of a single body: forces through the centre of mass and torques (pure couples), each given in the
// world frame W or in the body frame B, each active on a time interval [t_start, t_end), so that a
// list of them is a piecewise-constant schedule. Uniform gravity is separate (models add m g).
//
// Time discretisation: the schedule is constant between its switch times (the finite t_start and
// t_end), and `simulate` and `step` integrate each piece with that piece's loads. A step that
// crosses a switch time is split there into sub-steps, each taken by the same method with the loads
// of its piece, so every method keeps its order however the switch times fall on the step grid
// (records stay on the grid t0 + i dt). A switch within a few ulps of a grid time is taken at that
// time (simulate/simulate.hpp), which moves it by no more than the rounding of t itself.
#pragma once
#include "rigiddyn/so3/integrate.hpp"  // Frame

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace rigiddyn {

// One load: force [N] through the centre of mass and torque [N m], both expressed in `frame`,
// active for t in [t_start, t_end) [s].
struct AppliedLoad {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  Frame frame = Frame::world;
  double t_start = -std::numeric_limits<double>::infinity();
  double t_end = std::numeric_limits<double>::infinity();

  bool active_at(double t) const { return t_start <= t && t < t_end; }
};

// The sum of the loads active at one instant, split by frame of expression (the body-frame parts
// turn with the body, so a model rotates them at each derivative evaluation).
struct ComLoads {
  Eigen::Vector3d f_W = Eigen::Vector3d::Zero();  // force in W [N] (gravity m g is added by the model)
  Eigen::Vector3d f_B = Eigen::Vector3d::Zero();  // force in B [N]
  Eigen::Vector3d tau_W = Eigen::Vector3d::Zero();  // torque in W [N m]
  Eigen::Vector3d tau_B = Eigen::Vector3d::Zero();  // torque in B [N m]
};

// The sum of the loads of `schedule` active at time t [s].
ComLoads loads_at(const std::vector<AppliedLoad>& schedule, double t);

// True when every load of `schedule` is active for all t >= t0 (a constant schedule from t0 on).
bool is_constant_from(const std::vector<AppliedLoad>& schedule, double t0);

// The times strictly inside (t_begin, t_end) [s] at which the sum of `schedule` may change (every
// finite t_start and t_end there), ascending, without repeats; empty for a constant schedule.
std::vector<double> switch_times(const std::vector<AppliedLoad>& schedule, double t_begin, double t_end);

// True when some load of `schedule` acts only on a bounded part of time (a finite t_start or t_end),
// so that its effect depends on the time at which a state is taken.
bool has_time_window(const std::vector<AppliedLoad>& schedule);

// Throws std::invalid_argument naming "loads[i]..." for a non-finite force or torque or an
// interval with t_start >= t_end or a NaN bound.
void check_loads(const std::vector<AppliedLoad>& schedule);

}  // namespace rigiddyn
