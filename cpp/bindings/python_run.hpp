// What the Python runs of one body (bind_dynamics.cpp) and of a scene (bind_scene.cpp) share: the loads
// argument, read-only numpy arrays that adopt the C++ records, the monitor that gives Python its
// progress callback and Ctrl-C during a run without the GIL, and the warnings after a run (a non-finite state, a
// recorded quantity that overflowed, unconverged implicit solves).
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pthread.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "numpy_io.hpp"
#include "rigiddyn/batch/batch_global_error.hpp"
#include "rigiddyn/batch/batch_result.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/models/loads.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/simulate/accuracy_check.hpp"
#include "rigiddyn/simulate/balance.hpp"
#include "rigiddyn/simulate/global_error.hpp"
#include "rigiddyn/simulate/simulate.hpp"

namespace rigiddyn::bindings {

// None, an AppliedLoad or an iterable of them (argument `name`).
inline std::vector<AppliedLoad> as_loads(pybind11::handle obj, const std::string& name = "loads") {
  namespace py = pybind11;
  constexpr const char* expected = "None, an AppliedLoad or a sequence of AppliedLoad";
  std::vector<AppliedLoad> loads;
  if (obj.is_none()) return loads;
  if (is_instance<AppliedLoad>(obj)) return {obj.cast<AppliedLoad>()};
  if (py::isinstance<py::str>(obj) || py::isinstance<py::bytes>(obj) || !py::isinstance<py::iterable>(obj)) {
    py_io::throw_type_error(name, expected, obj);
  }
  for (py::handle item : obj) {
    if (!is_instance<AppliedLoad>(item)) py_io::throw_type_error(name, std::string(expected) + " (items)", item);
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
  py_io::set_read_only(out);
  return out;
}

// A read-only numpy array made on its first read: the std::vector of its values (and its shape) until then, then the
// array that adopts it (adopt: no copy). A result whose arrays are read in part (a control loop reading the last
// state) pays for the arrays it reads only.
class LazyArray {
 public:
  LazyArray() = default;
  // values of shape (d0), (d0, d1) or (d0, d1, d2)
  LazyArray(std::vector<double>&& values, std::initializer_list<pybind11::ssize_t> shape)
      : LazyArray(std::move(values), shape.begin(), shape.size()) {}
  LazyArray(std::vector<double>&& values, const std::vector<pybind11::ssize_t>& shape)
      : LazyArray(std::move(values), shape.data(), shape.size()) {}
  // an array made already (an unpickled or sliced result)
  explicit LazyArray(py_io::Array made) : array_(std::move(made)) {}
  // zeros of shape (d0), (d0, d1) or (d0, d1, d2), made on the first read (a column a run does not fill)
  static LazyArray zeros(std::initializer_list<pybind11::ssize_t> shape) {
    LazyArray out(std::vector<double>(), shape.begin(), shape.size());
    out.zeros_ = true;
    return out;
  }

  // The values it holds now and their number (GIL held): the array's, or those it will adopt (the same buffer: adopt
  // does not copy); none for zeros not yet made
  std::pair<const double*, std::size_t> values() const {
    if (array_) return {pybind11::reinterpret_borrow<py_io::Array>(array_).data(), size()};
    return {values_.data(), values_.size()};
  }

  // The array (GIL held)
  py_io::Array get() const {
    if (!array_ && ndim_ == 0) throw std::logic_error("LazyArray: read before its values were set");
    if (!array_) {
      if (zeros_) values_.assign(size(), 0.0);
      array_ = adopt(std::move(values_), {shape_.begin(), shape_.begin() + ndim_});
    }
    return pybind11::reinterpret_borrow<py_io::Array>(array_);
  }

 private:
  LazyArray(std::vector<double>&& values, const pybind11::ssize_t* shape, std::size_t ndim)
      : values_(std::move(values)), ndim_(ndim) {
    if (ndim > shape_.size()) throw std::logic_error("LazyArray: at most 3 dimensions");
    std::copy(shape, shape + ndim, shape_.begin());
  }

  // the number of values its shape holds
  std::size_t size() const {
    pybind11::ssize_t size = 1;
    for (std::size_t k = 0; k < ndim_; ++k) size *= shape_[k];
    return static_cast<std::size_t>(size);
  }

  mutable std::vector<double> values_;
  std::array<pybind11::ssize_t, 3> shape_{};  // its first ndim_ entries
  std::size_t ndim_ = 0;
  bool zeros_ = false;              // values_ stands for zeros until made
  mutable pybind11::object array_;  // null until made
};

// The getter of a result's LazyArray member, for def_property_readonly.
template <class Result>
auto array_of(LazyArray Result::*member) {
  return [member](const Result& r) { return (r.*member).get(); };
}

// Reorders n quaternions (x, y, z, w) in place to (w, x, y, z).
inline void to_scalar_first(std::vector<double>& q_xyzw) {
  for (std::size_t i = 0; i + 4 <= q_xyzw.size(); i += 4) {
    double* q = q_xyzw.data() + i;
    const double w = q[3];
    q[3] = q[2], q[2] = q[1], q[1] = q[0], q[0] = w;
  }
}

// One Python str per distinct verdict text (a dict from text to str), shared by every record that reads it.
class VerdictStrings {
 public:
  pybind11::object operator()(const std::string& verdict) {
    const pybind11::str text(verdict);
    if (!all_.contains(text)) all_[text] = text;
    return all_[text];
  }

 private:
  pybind11::dict all_;
};

// Fills verdict[i] and reliable_at[i] for the n records of `verdicts`: each distinct text made a str once.
inline void put_verdicts(const Verdicts& verdicts, VerdictStrings& strings, pybind11::tuple& verdict,
                         bool* reliable_at) {
  std::vector<pybind11::object> text_objects;
  std::vector<char> text_reliable;
  for (const std::string& text : verdicts.texts()) {
    text_objects.push_back(strings(text));
    text_reliable.push_back(is_reliable(text));
  }
  for (std::size_t i = 0; i < verdicts.size(); ++i) {
    const std::uint32_t k = verdicts.text_index(i);
    verdict[i] = text_objects[k];
    reliable_at[i] = text_reliable[k] != 0;
  }
}

// A GlobalError's verdicts as Python reads them, verdict (a tuple of str, equal verdicts sharing one; a batch's a
// tuple of tuples) and reliable (verdict == "reliable", a read-only bool array): one run's made on their first read
// from the core's verdicts, a batch's or an unpickled estimate's given made.
class LazyVerdicts {
 public:
  LazyVerdicts() = default;
  explicit LazyVerdicts(Verdicts&& verdicts) : verdicts_(std::move(verdicts)) {}
  LazyVerdicts(pybind11::tuple verdict, pybind11::array_t<bool> reliable)
      : verdict_(std::move(verdict)), reliable_(std::move(reliable)) {}

  pybind11::tuple verdict() const {
    make();
    return pybind11::reinterpret_borrow<pybind11::tuple>(verdict_);
  }
  pybind11::array_t<bool> reliable() const {
    make();
    return pybind11::reinterpret_borrow<pybind11::array_t<bool>>(reliable_);
  }

 private:
  void make() const {
    namespace py = pybind11;
    if (verdict_) return;
    const auto n = static_cast<py::ssize_t>(verdicts_.size());
    py::array_t<bool> reliable(n);
    py::tuple verdict(n);
    VerdictStrings strings;
    put_verdicts(verdicts_, strings, verdict, reliable.mutable_data());
    py_io::set_read_only(reliable);
    verdict_ = std::move(verdict), reliable_ = std::move(reliable);
    verdicts_ = Verdicts();
  }

  mutable Verdicts verdicts_;
  mutable pybind11::object verdict_, reliable_;  // null until made
};

// The quantities reliable at each record (GlobalErrorEstimate::reliable_quantities, one bit per ErrorMeasure), as a
// read-only uint8 array of shape (n,) or a batch's (N, n), made on its first read.
class LazyQuantityBits {
 public:
  LazyQuantityBits() = default;
  LazyQuantityBits(std::vector<std::uint8_t>&& bits, std::vector<pybind11::ssize_t> shape)
      : bits_(std::move(bits)), shape_(std::move(shape)) {}
  // an array made already (an unpickled or sliced result)
  explicit LazyQuantityBits(pybind11::array_t<std::uint8_t> made) : array_(std::move(made)) {}

  pybind11::array_t<std::uint8_t> get() const {
    if (!array_) {
      pybind11::array_t<std::uint8_t> made(shape_);
      if (static_cast<std::size_t>(made.size()) != bits_.size()) {
        throw std::logic_error("LazyQuantityBits: bits and shape disagree");
      }
      std::copy(bits_.begin(), bits_.end(), made.mutable_data());
      py_io::set_read_only(made);
      array_ = std::move(made);
      bits_ = std::vector<std::uint8_t>();
    }
    return pybind11::reinterpret_borrow<pybind11::array_t<std::uint8_t>>(array_);
  }

 private:
  mutable std::vector<std::uint8_t> bits_;
  std::vector<pybind11::ssize_t> shape_;
  mutable pybind11::object array_;  // null until made
};

// simulate's global error estimate (rigiddyn.GlobalError; its docstring in bind_dynamics.cpp): per record (n), and
// per body (n, nb) for a scene's state quantities; each array made on its first read.
struct GlobalError {
  int order;
  LazyArray attitude, angular_velocity, position, velocity, energy, angular_momentum, observed_order;
  LazyVerdicts verdicts;
  LazyQuantityBits reliable_quantities;
};

// The GlobalError of `e` for n records: the state quantities (n, nb).
inline GlobalError to_global_error(GlobalErrorEstimate&& e) {
  namespace py = pybind11;
  const auto n = static_cast<py::ssize_t>(e.verdict.size());
  const std::vector<py::ssize_t> state_shape{n, static_cast<py::ssize_t>(e.bodies)};
  return GlobalError{e.order,
                     LazyArray(std::move(e.attitude), state_shape),
                     LazyArray(std::move(e.angular_velocity), state_shape),
                     LazyArray(std::move(e.position), state_shape),
                     LazyArray(std::move(e.velocity), state_shape),
                     LazyArray(std::move(e.energy), {n}),
                     LazyArray(std::move(e.angular_momentum), {n}),
                     LazyArray(std::move(e.observed_order), {n}),
                     LazyVerdicts(std::move(e.verdict)),
                     LazyQuantityBits(std::move(e.reliable_quantities), {n})};
}

// The GlobalError of a batch's estimates `e`: each array with a leading sample axis, the state quantities
// (N, n, nb); verdict a tuple of N tuples of n, reliable (N, n). Equal verdicts share one str.
inline GlobalError to_global_error(BatchErrorEstimate&& e) {
  namespace py = pybind11;
  const auto N = static_cast<py::ssize_t>(e.samples), n = static_cast<py::ssize_t>(e.records);
  const std::vector<py::ssize_t> state_shape{N, n, static_cast<py::ssize_t>(e.bodies)};
  py::array_t<bool> reliable({N, n});
  bool* reliable_at = reliable.mutable_data();  // C-contiguous (N, n)
  VerdictStrings texts;
  py::tuple verdict(N);
  for (py::ssize_t i = 0; i < N; ++i) {
    py::tuple row(n);
    put_verdicts(e.verdict[static_cast<std::size_t>(i)], texts, row, reliable_at + i * n);
    verdict[i] = row;
  }
  py_io::set_read_only(reliable);
  return GlobalError{e.order,
                     LazyArray(std::move(e.attitude), state_shape),
                     LazyArray(std::move(e.angular_velocity), state_shape),
                     LazyArray(std::move(e.position), state_shape),
                     LazyArray(std::move(e.velocity), state_shape),
                     LazyArray(std::move(e.energy), {N, n}),
                     LazyArray(std::move(e.angular_momentum), {N, n}),
                     LazyArray(std::move(e.observed_order), {N, n}),
                     LazyVerdicts(verdict, reliable),
                     LazyQuantityBits(std::move(e.reliable_quantities), {N, n})};
}

// Sample i of a batch's GlobalError (its first `rows` records), as simulate gives it for that sample alone; None
// for None.
inline pybind11::object sample_error(pybind11::handle batch_error, pybind11::ssize_t i, pybind11::ssize_t rows) {
  namespace py = pybind11;
  if (batch_error.is_none()) return py::none();
  const GlobalError& e = batch_error.cast<const GlobalError&>();
  const py::slice first(0, rows, 1);
  const auto rows_of = [&](const py::array& a) -> py::array {
    py::array out = py::module_::import("numpy").attr("array")(a[py::make_tuple(i, first)]);  // a copy
    py_io::set_read_only(out);
    return out;
  };
  const auto values = [&](const LazyArray& a) { return LazyArray(py_io::Array::ensure(rows_of(a.get()))); };
  const py::tuple verdict(py::tuple(e.verdicts.verdict()[static_cast<std::size_t>(i)])[first]);
  return py::cast(GlobalError{e.order, values(e.attitude), values(e.angular_velocity), values(e.position),
                              values(e.velocity), values(e.energy), values(e.angular_momentum),
                              values(e.observed_order),
                              LazyVerdicts(verdict, py::array_t<bool>::ensure(rows_of(e.verdicts.reliable()))),
                              LazyQuantityBits(py::array_t<std::uint8_t>::ensure(rows_of(e.reliable_quantities.get())))});
}

// simulate's accuracy_level: None (no AccuracyWarning: nullopt) or a finite relative level > 0 (accuracy_check.hpp).
inline std::optional<double> as_accuracy_level(pybind11::handle level) {
  if (level.is_none()) return std::nullopt;
  return py_io::as_positive(level, "accuracy_level");
}

// The loops shorter than this many items (records, or steps times bodies) run with the GIL held: taking the GIL back
// costs more than a short loop's arithmetic and may wait a switch interval (5 ms) for another thread.
inline constexpr std::size_t gil_release_items = 512;

// Calls f() with the GIL released when a loop over `records` records runs long enough to be worth it, else with the
// GIL held (gil_release_items).
template <class F>
auto with_gil_released_for(std::size_t records, F&& f) {
  if (records < gil_release_items) return f();
  pybind11::gil_scoped_release release;
  return f();
}

// The GIL released for the scope of a run of `steps` steps of `bodies` bodies when the run is long enough to be
// worth it, else held (gil_release_items). A PythonForce, controller or progress callback of the run takes it back
// for each of its calls either way.
class GilReleasedForRun {
 public:
  GilReleasedForRun(std::int64_t steps, std::size_t bodies) {
    if (static_cast<double>(steps) * static_cast<double>(bodies) >= static_cast<double>(gil_release_items)) {
      release_.emplace();
    }
  }

 private:
  std::optional<pybind11::gil_scoped_release> release_;
};

// The end of a run's accuracy check (accuracy_check.hpp): the AccuracyWarning with `message` unless it is "", the
// level is None (the verdicts are still made at the default level) or the run diverged (warn_after_run has warned).
inline void warn_accuracy(const std::string& message, const std::optional<double>& level, bool diverged) {
  if (message.empty() || !level || diverged) return;
  const pybind11::object category = pybind11::module_::import("rigiddyn._balance").attr("AccuracyWarning");
  if (PyErr_WarnEx(category.ptr(), message.c_str(), 1) != 0) throw pybind11::error_already_set();
}

// The AccuracyCheck of a run at `level` (None: the default level) with the records' times t and its estimate.
inline AccuracyCheck accuracy_check_of(const std::optional<double>& level, const std::vector<double>& t,
                                       const GlobalErrorEstimate* estimate, const BalanceBounds* bounds,
                                       const std::string& method, double dt) {
  return AccuracyCheck{estimate, bounds, level.value_or(default_accuracy_level), &t, method, dt};
}

// result.balance of a run: the core's RunBalance until Python first reads it, then the rigiddyn.Balance made of its
// arrays (rigiddyn._balance._made, without a copy); None for a batch result. A run that is never asked for its
// balance pays nothing for the Python object.
class LazyBalance {
 public:
  LazyBalance() = default;
  explicit LazyBalance(RunBalance&& core) : core_(std::make_shared<RunBalance>(std::move(core))) {}
  explicit LazyBalance(pybind11::object balance) : object_(std::move(balance)) {}

  // The rigiddyn.Balance (or None), made on the first call (GIL held).
  pybind11::object get() const {
    if (core_) {
      object_ = balance_object(std::move(*core_));
      core_.reset();
    }
    return object_;
  }

 private:
  static pybind11::object balance_object(RunBalance&& b) {
    namespace py = pybind11;
    const auto n = static_cast<py::ssize_t>(b.size());
    const py::object values = adopt(b.take_values(), {3 * static_cast<py::ssize_t>(balance_quantity_count), n});
    py::tuple arrays(3 * balance_quantity_count);  // its rows: views of the one buffer
    for (std::size_t k = 0; k < 3 * balance_quantity_count; ++k) arrays[k] = values[py::int_(k)];
    py::dict verdict;
    for (std::size_t q = 0; q < balance_quantity_count; ++q) verdict[balance_quantity_names[q]] = b.verdict[q];
    return py::module_::import("rigiddyn._balance").attr("_made")(arrays, verdict, b.about);
  }

  mutable std::shared_ptr<RunBalance> core_;
  mutable pybind11::object object_ = pybind11::none();
};

// A pickled result's balance: a rigiddyn.Balance (TypeError naming `name` otherwise).
inline LazyBalance checked_balance(pybind11::handle obj, const std::string& name) {
  if (!pybind11::isinstance(obj, pybind11::module_::import("rigiddyn._balance").attr("Balance"))) {
    py_io::throw_type_error(name, "a Balance or None", obj);
  }
  return LazyBalance(pybind11::reinterpret_borrow<pybind11::object>(obj));
}

// A coarse run of the estimate (global_error) with the monitor of the answer: its records, and `interrupted` set
// when the monitor stopped it (the binding then raises the monitor's exception).
template <class Simulate>
auto interruptible(Simulate&& simulate, bool& interrupted) {
  return [&simulate, &interrupted](const SimulationOptions& coarse) {
    if (interrupted) return decltype(simulate(coarse)){};  // the run is being stopped: no more coarse runs
    auto records = simulate(coarse);
    interrupted = interrupted || records.interrupted;
    return records;
  };
}

// simulate's monitor from Python (SimulationOptions::monitor): at most every 50 ms of the run it takes
// the GIL, lets Python handle signals (Ctrl-C raises KeyboardInterrupt; only the main thread gets
// them, so other threads skip this unless they report progress) and calls progress(steps_done), first after
// the first step when there is a progress, else after 50 ms (a run shorter than that leaves the signals to
// Python, which handles them as the call returns). An exception from either stops the run and is kept for the
// binding to raise once the GIL is back.
class PythonMonitor {
 public:
  explicit PythonMonitor(pybind11::handle progress)
      : progress_(progress.is_none() ? pybind11::object()
                                     : py_io::as_callable(progress, "progress", "a callable(steps_done) or None")),
        main_thread_(PyThread_get_thread_ident() == main_thread_ident()),
        next_call_(std::chrono::steady_clock::now() + (progress_ ? std::chrono::milliseconds(0) : period)) {}

  // threading.main_thread().ident, looked up once per process: a fork makes its calling thread the child's main
  // thread, so the child forgets the parent's (a handler the fork runs in the child; no thread's ident is 0).
  // Asking the process id at every call instead would cost a system call per run.
  static unsigned long main_thread_ident() {
    static unsigned long ident = 0;
    [[maybe_unused]] static const int forget_in_child = pthread_atfork(nullptr, nullptr, [] { ident = 0; });
    if (ident == 0) {
      ident = pybind11::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
    }
    return ident;
  }

  // Whether the run needs the monitor at all.
  bool needed() const { return main_thread_ || progress_; }

  bool operator()(std::int64_t steps_done) {
    const auto now = std::chrono::steady_clock::now();
    if (now < next_call_) return false;
    next_call_ = now + period;
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

  // Whether a signal handler or progress raised (the run was asked to stop).
  bool failed() const { return error_.has_value(); }

  // The exception that stopped the run (call with the GIL held, after an interrupted run).
  [[noreturn]] void raise() {
    if (error_) throw *error_;
    throw std::logic_error("simulate: interrupted without an exception");
  }

 private:
  static constexpr std::chrono::milliseconds period{50};
  pybind11::object progress_;
  bool main_thread_;
  std::chrono::steady_clock::time_point next_call_;
  std::optional<pybind11::error_already_set> error_;
};

// ------------------------------------------------------------ estimates made on the first read

// An estimate made on the first read of result.error: `make`, the coarse runs and their comparison with the answer's
// records (global_error.hpp, batch_global_error.hpp), pure C++, run without the GIL; the answer's records are the
// result's own columns (Columns: SceneColumns of a run, BatchColumns of a batch; no copy), read when it is made.
// make gives nullopt when the reading thread's monitor (Ctrl-C) stopped a coarse run.
template <class Estimate, class Columns>
struct Deferred {
  std::function<std::optional<Estimate>(const Columns& answer, PythonMonitor& monitor)> make;
  std::mutex mutex;  // one thread makes it, the others wait for it
  std::optional<Estimate> made;
};
using DeferredEstimate = Deferred<GlobalErrorEstimate, SceneColumns>;
using DeferredBatchEstimate = Deferred<BatchErrorEstimate, BatchColumns>;

// result.error of a run or a batch: its GlobalError (or None) as made, or a Deferred that makes it on the first read
// (a deterministic run whose balances close under any estimate defers it, simulate_scene_py; a batch without a
// PythonForce, whose estimate decides no warning, simulate_batch_py). A loop of runs that reads the state alone then
// pays for the runs alone; a reader gets the values the run would have made at once.
template <class Estimate, class Columns>
class Lazy {
 public:
  Lazy() = default;
  Lazy(pybind11::object made) : made_(std::move(made)) {}  // NOLINT: a GlobalError or None converts
  explicit Lazy(std::shared_ptr<Deferred<Estimate, Columns>> deferred) : deferred_(std::move(deferred)) {}
  // made on the first read by `later`, with the GIL held (a batch sample's: its rows of its batch's estimate)
  explicit Lazy(std::function<pybind11::object()> later) : later_(std::move(later)) {}

  // Whether it is still to be made
  bool pending() const { return deferred_ || later_; }

  // The GlobalError (or None); a deferred one made on the first call from `columns` (the answer's, read with the GIL
  // held: the result's arrays) with the GIL released, so that other threads run meanwhile; a second reader waits for
  // the first's and gets the same object. Ctrl-C stops the coarse runs (KeyboardInterrupt); an exception leaves it to
  // be made again.
  pybind11::object get(const std::function<Columns()>& columns) const {
    if (later_) {
      made_ = later_();
      later_ = nullptr;
    }
    if (deferred_) {
      const std::shared_ptr<Deferred<Estimate, Columns>> d = deferred_;
      const Columns c = columns();
      PythonMonitor monitor{pybind11::none()};
      try {
        const pybind11::gil_scoped_release release;
        const std::lock_guard<std::mutex> lock(d->mutex);
        if (!d->made) d->made = d->make(c, monitor);
      } catch (...) {
        if (monitor.failed()) monitor.raise();  // a Ctrl-C is never lost to a coarse run's error
        throw;
      }
      if (!d->made) monitor.raise();
      if (deferred_ == d) {  // the first reader back with the GIL converts it
        made_ = pybind11::cast(to_global_error(std::move(*d->made)));
        deferred_.reset();
      }
    }
    return made_;
  }

 private:
  mutable std::shared_ptr<Deferred<Estimate, Columns>> deferred_;
  mutable std::function<pybind11::object()> later_;
  mutable pybind11::object made_ = pybind11::none();
};
using LazyError = Lazy<GlobalErrorEstimate, SceneColumns>;
using LazyBatchError = Lazy<BatchErrorEstimate, BatchColumns>;

// A coarse run's SimulationOptions::monitor: `monitor` where it is needed (Ctrl-C on the main thread), else none.
inline std::function<bool(std::int64_t)> coarse_monitor(PythonMonitor& monitor) {
  if (!monitor.needed()) return nullptr;
  return [&monitor](std::int64_t done) { return monitor(done); };
}

// ------------------------------------------------------------ non-finite records

// A recorded quantity by name: its values, (N, n, width) row-major for N runs of n records each (N = 1 for
// one run), width the values per record (e.g. 3 * bodies).
struct RecordColumn {
  const char* name;
  const std::vector<double>* values;
};

// The recorded quantities of a batch of bodies on the SIMD path (BatchTrajectory), every one but t.
inline std::array<RecordColumn, 9> record_columns(const BatchTrajectory& r) {
  return {{{"p_W", &r.p_W},
          {"q_WB", &r.q_WB},
          {"v_W", &r.v_W},
          {"w_B", &r.w_B},
          {"kinetic_energy", &r.kinetic_energy},
          {"total_energy", &r.total_energy},
          {"angular_momentum_norm", &r.angular_momentum_norm},
          {"quaternion_norm_error", &r.quaternion_norm_error},
          {"work", &r.work}}};
}

// The recorded quantities of a scene's run (SceneSimulation) or batch (BatchSceneSimulation), every one but t.
template <class Records>
std::array<RecordColumn, 14> scene_record_columns(const Records& r) {
  return {{{"p_W", &r.p_W},
          {"q_WB", &r.q_WB},
          {"v_W", &r.v_W},
          {"w_B", &r.w_B},
          {"kinetic_energy", &r.kinetic_energy},
          {"potential_energy", &r.potential_energy},
          {"total_energy", &r.total_energy},
          {"linear_momentum_W", &r.linear_momentum_W},
          {"angular_momentum_W", &r.angular_momentum_W},
          {"pivot_reaction_W", &r.pivot_reaction_W},
          {"angular_momentum_O_W", &r.angular_momentum_O_W},
          {"mass", &r.mass},
          {"work", &r.work},
          {"power", &r.power}}};
}

inline std::array<RecordColumn, 14> record_columns(const SceneSimulation& r) { return scene_record_columns(r); }
inline std::array<RecordColumn, 14> record_columns(const BatchSceneSimulation& r) { return scene_record_columns(r); }

// "kinetic_energy from t = 0, total_energy from t = 0": each quantity of `columns` with a non-finite value in
// the first `rows` records of run i (of N runs of n records; t (N, n) their times [s]), with the time of the
// first such record; "" when there is none.
template <std::size_t count>
std::string non_finite_quantities(const std::array<RecordColumn, count>& columns, const std::vector<double>& t,
                                  std::size_t N, std::size_t n, std::size_t i, std::size_t rows) {
  std::string found;
  for (const RecordColumn& c : columns) {
    const std::size_t width = N * n == 0 ? 0 : c.values->size() / (N * n);
    const double* run = c.values->data() + i * n * width;
    if (width == 0 || py_io::all_finite(run, static_cast<pybind11::ssize_t>(rows * width))) continue;
    std::size_t r = 0;
    while (py_io::all_finite(run + r * width, static_cast<pybind11::ssize_t>(width))) ++r;
    found += (found.empty() ? "" : ", ") + std::string(c.name) + " from t = " + format_value(t[i * n + r]);
  }
  return found;
}

// The quantities of a run's records that are not finite although its state is (an overflow of a quantity
// computed from a finite state, e.g. the kinetic energy of |v_W| > 1e154 m/s), as non_finite_quantities; ""
// for a run that diverged (its state is not finite at its last record: warn_after_run says so).
template <class Records>
std::string overflowed_quantities(const Records& r) {
  if (r.diverged) return {};
  return non_finite_quantities(record_columns(r), r.t, 1, r.size(), 0, r.size());
}

// The RuntimeWarnings after a run of `options` (GIL held): the state became non-finite by the last record, a
// recorded quantity is not finite although the state is (overflowed_quantities), or some implicit solves hit
// their iteration cap.
template <class Records>
void warn_after_run(const Records& r, const SimulationOptions& options, const std::string& method) {
  const auto dt = [&] { return format_value(options.dt); };  // formatted only for a warning
  if (r.diverged) {
    const std::string msg = "simulate: the state became non-finite by t = " +
                            format_value(r.t.empty() ? options.t0 : r.t.back()) + " (method '" + method +
                            "', dt = " + dt() + "); the run stopped there";
    if (PyErr_WarnEx(PyExc_RuntimeWarning, msg.c_str(), 1) != 0) throw pybind11::error_already_set();
  }
  const std::string overflowed = overflowed_quantities(r);
  if (!overflowed.empty()) {
    const std::string msg = "simulate: recorded quantities became non-finite while the state stayed finite (an "
                            "overflow): " + overflowed;
    if (PyErr_WarnEx(PyExc_RuntimeWarning, msg.c_str(), 1) != 0) throw pybind11::error_already_set();
  }
  if (r.unconverged_steps > 0) {
    const std::string msg = "simulate: the implicit solve of method '" + method + "' did not converge in " +
                            std::to_string(r.unconverged_steps) + " of " + std::to_string(options.steps) +
                            " steps at dt = " + dt() +
                            " (its conservation is lost there); reduce dt (see methods() stability_limit)";
    if (PyErr_WarnEx(PyExc_RuntimeWarning, msg.c_str(), 1) != 0) throw pybind11::error_already_set();
  }
}

}  // namespace rigiddyn::bindings
