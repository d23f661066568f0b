#include "rigiddyn/models/loads.hpp"

#include "rigiddyn/check.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace rigiddyn {

ComLoads loads_at(const std::vector<AppliedLoad>& schedule, double t) {
  ComLoads sum;
  for (const AppliedLoad& load : schedule) {
    if (!load.active_at(t)) continue;
    if (load.frame == Frame::world) {
      sum.f_W += load.force;
      sum.tau_W += load.torque;
    } else {
      sum.f_B += load.force;
      sum.tau_B += load.torque;
    }
  }
  return sum;
}

bool is_constant_from(const std::vector<AppliedLoad>& schedule, double t0) {
  for (const AppliedLoad& load : schedule) {
    if (!(load.t_start <= t0 && std::isinf(load.t_end))) return false;
  }
  return true;
}

std::vector<double> switch_times(const std::vector<AppliedLoad>& schedule, double t_begin, double t_end) {
  std::vector<double> times;
  for (const AppliedLoad& load : schedule) {
    for (const double t : {load.t_start, load.t_end}) {
      if (t_begin < t && t < t_end) times.push_back(t);  // false for ±inf outside and for NaN
    }
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

bool has_time_window(const std::vector<AppliedLoad>& schedule) {
  return std::any_of(schedule.begin(), schedule.end(),
                     [](const AppliedLoad& load) { return std::isfinite(load.t_start) || std::isfinite(load.t_end); });
}

void check_loads(const std::vector<AppliedLoad>& schedule) {
  for (std::size_t i = 0; i < schedule.size(); ++i) {
    const std::string name = "loads[" + std::to_string(i) + "]";
    require_finite(schedule[i].force, name + ".force");
    require_finite(schedule[i].torque, name + ".torque");
    if (!(schedule[i].t_start < schedule[i].t_end)) {
      throw_invalid(name + ".t_end", "t_end > t_start = " + format_value(schedule[i].t_start), schedule[i].t_end);
    }
  }
}

}  // namespace rigiddyn
