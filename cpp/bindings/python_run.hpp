// What the Python runs of one body (bind_dynamics.cpp) and of a scene (bind_scene.cpp) share: the loads
// argument, read-only numpy arrays that adopt the C++ records, the monitor that gives Python its
// progress callback and Ctrl-C during a run without the GIL, and the warnings after a run.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "numpy_io.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/models/loads.hpp"

namespace rigiddyn::bindings {

// None, an AppliedLoad or an iterable of them (argument `name`).
inline std::vector<AppliedLoad> as_loads(pybind11::handle obj, const std::string& name = "loads") {
  namespace py = pybind11;
  constexpr const char* expected = "None, an AppliedLoad or a sequence of AppliedLoad";
  std::vector<AppliedLoad> loads;
  if (obj.is_none()) return loads;
  if (py::isinstance<AppliedLoad>(obj)) return {obj.cast<AppliedLoad>()};
  if (py::isinstance<py::str>(obj) || py::isinstance<py::bytes>(obj) || !py::isinstance<py::iterable>(obj)) {
    py_io::throw_type_error(name, expected, obj);
  }
  for (py::handle item : obj) {
    if (!py::isinstance<AppliedLoad>(item)) py_io::throw_type_error(name, std::string(expected) + " (items)", item);
    loads.push_back(item.cast<AppliedLoad>());
  }
  return loads;
}

// A read-only numpy array taking ownership of a std::vector (no copy): `result.w_B[0, 0] = 1` raises.
inline py_io::Array adopt(std::vector<double>&& data, std::vector<pybind11::ssize_t> shape) {
  namespace py = pybind11;
  auto* owner = new std::vector<double>(std::move(data));
  py::capsule free_owner(owner, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  py_io::Array out(shape, owner->data(), free_owner);
  out.attr("flags").attr("writeable") = false;
  return out;
}

// Reorders n quaternions (x, y, z, w) in place to (w, x, y, z).
inline void to_scalar_first(std::vector<double>& q_xyzw) {
  for (std::size_t i = 0; i + 4 <= q_xyzw.size(); i += 4) {
    double* q = q_xyzw.data() + i;
    const double w = q[3];
    q[3] = q[2], q[2] = q[1], q[1] = q[0], q[0] = w;
  }
}

// simulate's monitor from Python (SimulationOptions::monitor): at most every 50 ms of the run it takes
// the GIL, lets Python handle signals (Ctrl-C raises KeyboardInterrupt; only the main thread gets
// them, so other threads skip this unless they report progress) and calls progress(steps_done). An
// exception from either stops the run and is kept for the binding to raise once the GIL is back.
class PythonMonitor {
 public:
  explicit PythonMonitor(pybind11::handle progress)
      : progress_(progress.is_none() ? pybind11::object()
                                     : py_io::as_callable(progress, "progress", "a callable(steps_done) or None")),
        main_thread_(PyThread_get_thread_ident() == pybind11::module_::import("threading")
                                                        .attr("main_thread")()
                                                        .attr("ident")
                                                        .cast<unsigned long>()) {}

  // Whether the run needs the monitor at all.
  bool needed() const { return main_thread_ || progress_; }

  bool operator()(std::int64_t steps_done) {
    const auto now = std::chrono::steady_clock::now();
    if (now < next_call_) return false;
    next_call_ = now + std::chrono::milliseconds(50);
    pybind11::gil_scoped_acquire gil;
    try {
      if (main_thread_ && PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
      if (progress_) progress_(steps_done);
    } catch (pybind11::error_already_set& e) {
      error_ = std::move(e);
      return true;
    }
    return false;
  }

  // The exception that stopped the run (call with the GIL held, after an interrupted run).
  [[noreturn]] void raise() {
    if (error_) throw *error_;
    throw std::logic_error("simulate: interrupted without an exception");
  }

 private:
  pybind11::object progress_;
  bool main_thread_;
  std::chrono::steady_clock::time_point next_call_ = std::chrono::steady_clock::now();
  std::optional<pybind11::error_already_set> error_;
};

// The RuntimeWarnings after a run (GIL held): the state became non-finite by t_end, or `unconverged` of
// `steps` implicit solves hit their iteration cap.
inline void warn_after_run(bool diverged, double t_end, std::int64_t unconverged, std::int64_t steps,
                           const std::string& method, double dt) {
  if (diverged) {
    const std::string msg = "simulate: the state became non-finite by t = " + format_value(t_end) + " (method '" +
                            method + "', dt = " + format_value(dt) + "); the run stopped there";
    if (PyErr_WarnEx(PyExc_RuntimeWarning, msg.c_str(), 1) != 0) throw pybind11::error_already_set();
  }
  if (unconverged > 0) {
    const std::string msg = "simulate: the implicit solve of method '" + method + "' did not converge in " +
                            std::to_string(unconverged) + " of " + std::to_string(steps) +
                            " steps at dt = " + format_value(dt) +
                            " (its conservation is lost there); reduce dt (see methods() stability_limit)";
    if (PyErr_WarnEx(PyExc_RuntimeWarning, msg.c_str(), 1) != 0) throw pybind11::error_already_set();
  }
}

}  // namespace rigiddyn::bindings
