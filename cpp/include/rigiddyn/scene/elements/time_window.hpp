// The window [t_start, t_end) [s] of an element that acts on a part of time only (a joint motor's torque, a
// ReactionWheel's ramp): its check and the times at which a run splits its steps (the run loop's switch times, as
// for ScheduledLoads).
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/models/loads.hpp"

#include <string>
#include <vector>

namespace rigiddyn::detail {

// Throws std::invalid_argument "<prefix>t_end: expected a time after t_start = ..., got ..." unless t_end > t_start.
inline void check_window(double t_start, double t_end, const std::string& prefix = "") {
  if (!(t_end > t_start)) throw_invalid(prefix + "t_end", "a time after t_start = " + format_value(t_start), t_end);
}

// The times at which a run splits its steps for a window [t_start, t_end): its start and its end.
inline std::vector<AppliedLoad> window_switches(double t_start, double t_end) {
  AppliedLoad window;
  window.t_start = t_start, window.t_end = t_end;
  return {window};
}

}  // namespace rigiddyn::detail
