#include "rigiddyn/models/loads.hpp"

#include "rigiddyn/check.hpp"

#include <cmath>
#include <string>

namespace rigiddyn {

ComLoads loads_at(const std::vector<AppliedLoad>& schedule, double t) {
  ComLoads sum;
  for (const AppliedLoad& load : schedule) {
    if (!load.active_at(t)) continue;
    if (load.frame == Frame::world) {
      sum.f_W += load.force;
      sum.n_W += load.torque;
    } else {
      sum.f_B += load.force;
      sum.n_B += load.torque;
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
