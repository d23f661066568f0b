// Arguments that several layers' bindings take in the same form: the frame a vector is expressed
// in, gravity, and the length of a run (steps or duration). Converted here once so that every binding names and checks them alike.
#pragma once
#include <pybind11/pybind11.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <sstream>

#include "numpy_io.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/simulate/simulate.hpp"  // standard_gravity
#include "rigiddyn/so3/integrate.hpp"      // Frame

namespace rigiddyn::bindings {

// A quaternion's order as the rotation functions take it: scalar_first=True for (w, x, y, z), else (x, y, z, w);
// TypeError unless a bool.
inline bool as_scalar_first(pybind11::handle scalar_first) { return py_io::as_bool(scalar_first, "scalar_first"); }
// That parameter's entry in a docstring's Parameters
inline const char* const scalar_first_param =
    "scalar_first : bool, default False\n"
    "    Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.\n";

// 'world' or 'body' (the frame a vector is expressed in), else TypeError / ValueError naming `name`.
inline Frame as_frame(pybind11::handle frame, const std::string& name = "frame") {
  return py_io::as_choice<Frame>(frame, name, {{"world", Frame::world}, {"body", Frame::body}});
}

// None or False: no gravity; True: standard gravity (0, 0, -9.81) [m/s²]; else a 3-vector [m/s²] in W.
inline Eigen::Vector3d as_gravity(pybind11::handle obj) {
  if (obj.is_none()) return Eigen::Vector3d::Zero();
  if (pybind11::isinstance<pybind11::bool_>(obj))
    return obj.cast<bool>() ? standard_gravity() : Eigen::Vector3d::Zero();
  return py_io::as_vector3(py_io::in_si(obj, "m/s^2", "gravity"), "gravity");  // a float array [m/s²] or a pint quantity
}

// The steps of a run at dt [s], from exactly one of `steps` (an integer >= 0) and `duration` [s] (a float or
// a pint quantity >= 0), else ValueError naming both. A duration must be a whole number of steps: duration /
// dt within 1e-9 of an integer k relative to k (the round-off of e.g. 10 s / 0.01 s = 999.9999999999999),
// else ValueError naming duration and dt with the two nearest durations that are.
inline std::int64_t as_steps(pybind11::handle steps, pybind11::handle duration, double dt) {
  if (steps.is_none() == duration.is_none()) {
    py_io::throw_value_error("steps, duration", "exactly one of them (a step count, or a time span [s])",
                             steps.is_none() ? "neither" : "both");
  }
  if (!steps.is_none()) return py_io::as_int(steps, "steps", 0);
  require_positive(dt, "dt");
  const double span = py_io::as_scalar(py_io::in_si(duration, "s", "duration"), "duration");
  if (span < 0.0) py_io::throw_value_error("duration", "a time span >= 0 [s]", format_value(span));
  const double ratio = span / dt;
  constexpr double max_steps = 9007199254740992.0;  // 2^53: every count below it is exact in a double
  if (!(ratio <= max_steps)) {  // also inf (1e300 / 1e-300)
    py_io::throw_value_error("duration", "a run of at most 2**53 steps of dt = " + format_value(dt) + " s",
                             format_value(span) + " s (duration / dt = " + format_value(ratio) + ")");
  }
  const double whole = std::round(ratio);
  if (std::abs(ratio - whole) > 1e-9 * std::max(1.0, whole)) {
    auto shown = [](double x) {  // 12 digits: the nearest whole-step durations without their round-off
      std::ostringstream out;
      out.precision(12);
      out << x;
      return out.str();
    };
    py_io::throw_value_error("duration", "a whole number of steps of dt = " + format_value(dt) + " s (e.g. " +
                                             shown(std::floor(ratio) * dt) + " s or " + shown(std::ceil(ratio) * dt) +
                                             " s)",
                             format_value(span) + " s (" + shown(ratio) + " steps)");
  }
  return static_cast<std::int64_t>(whole);
}

}  // namespace rigiddyn::bindings
