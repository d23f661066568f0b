// Python bindings of the simulation layer: applied loads, one `step` of any method, `simulate`, and
// the method registry `methods()` (the bodies, their states and dynamics are in bind_bodies.cpp).
// Every argument is taken as a handle and converted by name (numpy_io.hpp), so a wrong one raises
// TypeError/ValueError naming it, never pybind11's overload list.
#include <pybind11/stl.h>
#include <pybind11/typing.h>

#include "bindings.hpp"
#include "common_args.hpp"
#include "numpy_io.hpp"
#include "pivoted.hpp"
#include "python_run.hpp"
#include "scene_run.hpp"
#include "repr.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/compile.hpp"  // scene_features
#include "rigiddyn/simulate/simulate.hpp"

#include <chrono>
#include <optional>
#include <string>
#include <utility>

namespace rigiddyn::bindings {

namespace py = pybind11;
using py_io::Array;

namespace {

// The options shared by simulate and step, each argument converted by name (TypeError/ValueError
// naming it); the core checks the values (dt > 0, finite gravity, ...).
SimulationOptions as_options(py::handle dt, py::handle method, py::handle loads, py::handle gravity) {
  SimulationOptions o;
  o.dt = py_io::as_scalar(py_io::in_si(dt, "s", "dt"), "dt");
  o.method = method.is_none() ? Method::rk4 : method_from_name(py_io::as_string(method, "method"), "method");
  o.loads = as_loads(loads);
  o.gravity_W = as_gravity(gravity);
  return o;
}

// Calls f(body, state) with the model `model` is and its state `state` (argument `state_name`);
// TypeError naming model for anything else, naming the state for another model's state.
template <class F>
auto with_model(py::handle model, py::handle state, const char* state_name, F&& f)
    -> decltype(f(std::declval<const RigidBody&>(), std::declval<RigidBodyState&>())) {
  if (py::isinstance<RigidBody>(model)) {
    return f(model.cast<const RigidBody&>(),
             py_io::as_instance<RigidBodyState>(state, state_name, "a RigidBodyState (the state of a RigidBody)"));
  }
  if (py::isinstance<PlanarBody>(model)) {
    return f(model.cast<const PlanarBody&>(),
             py_io::as_instance<PlanarBodyState>(state, state_name, "a PlanarBodyState (the state of a PlanarBody)"));
  }
  if (py::isinstance<Particle>(model)) {
    return f(model.cast<const Particle&>(),
             py_io::as_instance<ParticleState>(state, state_name, "a ParticleState (the state of a Particle)"));
  }
  py_io::throw_type_error("model", "a RigidBody, PlanarBody, Particle, PivotedBody, PivotedPlanarBody, Gyrostat, "
                          "Scene or CompiledScene", model);
}

// simulate's result: numpy arrays, one row per record.
struct SimulationResult {
  Array t, p_W, q_WB, v_W, w_B, kinetic_energy, total_energy, angular_momentum_norm, quaternion_norm_error, work;
  bool diverged;
  std::int64_t unconverged_steps;
  double elapsed_seconds;
  bool scalar_first = false;  // q_WB rows as (w, x, y, z)
};

SimulationResult to_result(Trajectory&& tr, bool scalar_first) {
  const auto n = static_cast<py::ssize_t>(tr.size());
  if (scalar_first) to_scalar_first(tr.q_WB);
  return SimulationResult{adopt(std::move(tr.t), {n}),
                          adopt(std::move(tr.p_W), {n, 3}),
                          adopt(std::move(tr.q_WB), {n, 4}),
                          adopt(std::move(tr.v_W), {n, 3}),
                          adopt(std::move(tr.w_B), {n, 3}),
                          adopt(std::move(tr.kinetic_energy), {n}),
                          adopt(std::move(tr.total_energy), {n}),
                          adopt(std::move(tr.angular_momentum_norm), {n}),
                          adopt(std::move(tr.quaternion_norm_error), {n}),
                          adopt(std::move(tr.work), {n}),
                          tr.diverged,
                          tr.unconverged_steps,
                          tr.elapsed_seconds,
                          scalar_first};
}

template <class Body, class State>
SimulationResult simulate_one(const Body& body, const State& initial, const SimulationOptions& o,
                              const std::string& method, py::handle progress, bool scalar_first) {
  SimulationOptions options = o;
  PythonMonitor monitor(progress);
  if (monitor.needed()) options.monitor = [&monitor](std::int64_t steps_done) { return monitor(steps_done); };
  Trajectory tr;
  {
    py::gil_scoped_release release;
    tr = simulate(body, initial, options);
  }
  if (tr.interrupted) monitor.raise();  // the records so far are dropped with tr
  warn_after_run(tr, o, method);
  return to_result(std::move(tr), scalar_first);
}

// simulate: every argument converted by name before the run (see simulate_doc); a scene's run is
// bind_scene.cpp's.
py::typing::Union<SimulationResult, SceneResult> simulate_py(py::handle model, py::handle initial, py::handle dt,
                                                             py::handle steps, py::handle method,
                                                             py::handle record_every, py::handle loads,
                                                             py::handle gravity, py::handle t0,
                                                             py::handle scalar_first, py::handle progress,
                                                             py::handle duration) {
  if (is_scene(model)) {
    return py::cast(simulate_scene_py(model, initial, dt, steps, method, record_every, loads, gravity, t0, scalar_first,
                                      progress, duration));
  }
  if (is_pivoted(model) || is_gyrostat(model)) {  // the one-body scene of the body, its gravity and loads
    const py::object scene = is_gyrostat(model) ? gyrostat_scene(model, loads, gravity) : pivoted_scene(model, loads, gravity);
    return py::cast(simulate_scene_py(scene, py::make_tuple(initial), dt, steps, method, record_every, py::none(),
                                      py::none(), t0, scalar_first, progress, duration));
  }
  return py::cast(with_model(model, initial, "initial", [&](const auto& body, const auto& state) {
    SimulationOptions o = as_options(dt, method, loads, gravity);
    o.steps = as_steps(steps, duration, o.dt);
    o.record_every = py_io::as_int(record_every, "record_every", 1);
    o.t0 = py_io::as_scalar(py_io::in_si(t0, "s", "t0"), "t0");
    const bool first = py_io::as_bool(scalar_first, "scalar_first");
    return simulate_one(body, state, o, method_info(o.method).name, progress, first);
  }));
}

// The arrays of a SimulationResult in order (pickle state, field by field).
constexpr const char* result_arrays[] = {"t", "p_W", "q_WB", "v_W", "w_B", "kinetic_energy", "total_energy",
                                         "angular_momentum_norm", "quaternion_norm_error", "work"};

py::tuple result_state(const SimulationResult& r) {
  return py::make_tuple(r.t, r.p_W, r.q_WB, r.v_W, r.w_B, r.kinetic_energy, r.total_energy, r.angular_momentum_norm,
                        r.quaternion_norm_error, r.work, r.diverged, r.unconverged_steps, r.elapsed_seconds,
                        r.scalar_first);
}

// A pickled array as a read-only float64 copy of the shape it must have ((n,) or (n, k), n records).
Array unpickled_array(py::handle obj, const char* name, py::ssize_t n, py::ssize_t k) {
  Array a = Array::ensure(py::module_::import("numpy").attr("array")(obj, "float64"));  // a copy
  const bool ok = a && (k == 0 ? a.ndim() == 1 && a.shape(0) == n : a.ndim() == 2 && a.shape(0) == n && a.shape(1) == k);
  if (!ok) {
    py_io::throw_value_error(std::string("SimulationResult pickle ") + name,
                             k == 0 ? "shape (n,)" : "shape (n, " + std::to_string(k) + ")", py_io::describe(obj));
  }
  a.attr("flags").attr("writeable") = false;
  return a;
}

// 13 items: a state without scalar_first (q_WB as (x, y, z, w)), as simulate_batch's samples and earlier pickles
SimulationResult result_from_state(const py::tuple& t) {
  if (t.size() != 13 && t.size() != 14) {
    py_io::throw_value_error("SimulationResult pickle", "a tuple of 13 or 14 items", std::to_string(t.size()) + " items");
  }
  const py::ssize_t n = py::len(t[0]);
  auto column = [&](int i, py::ssize_t k) { return unpickled_array(t[i], result_arrays[i], n, k); };
  return SimulationResult{column(0, 0), column(1, 3), column(2, 4), column(3, 3), column(4, 3), column(5, 0),
                          column(6, 0), column(7, 0), column(8, 0), column(9, 0), t[10].cast<bool>(),
                          t[11].cast<std::int64_t>(), t[12].cast<double>(), t.size() == 14 && t[13].cast<bool>()};
}

// "SimulationResult(records=n, t=[t0, t_end], diverged=..., unconverged_steps=..., elapsed_seconds=...)".
std::string result_repr(const SimulationResult& r) {
  const py::ssize_t n = r.t.shape(0);
  const py::object span = n == 0 ? py::object(py::list()) : py::object(py::make_tuple(r.t.at(0), r.t.at(n - 1)));
  return repr_call("SimulationResult", {{"records", py::int_(n)},
                                        {"t", span},
                                        {"diverged", py::bool_(r.diverged)},
                                        {"unconverged_steps", py::int_(r.unconverged_steps)},
                                        {"elapsed_seconds", py::float_(r.elapsed_seconds)}});
}

bool all_finite(const RigidBodyState& s) {
  return s.p_W.allFinite() && s.q_WB.coeffs().allFinite() && s.v_W.allFinite() && s.w_B.allFinite();
}
bool all_finite(const ParticleState& s) { return s.p_W.allFinite() && s.v_W.allFinite(); }
bool all_finite(const PlanarBodyState& s) {
  return s.p_W.allFinite() && std::isfinite(s.theta) && s.v_W.allFinite() && std::isfinite(s.omega);
}

// step: t = None: the new state, refused for a schedule with a time window (its step depends on t);
// t given: (new state, t + dt). Warns when the new state is not finite.
py::object step_py(py::handle model, py::handle state, py::handle dt, py::handle method, py::handle loads,
                   py::handle gravity, py::handle t) {
  if (is_scene(model)) return step_scene_py(model, state, dt, method, loads, gravity, t);
  if (is_pivoted(model) || is_gyrostat(model)) {  // the one-body scene's step, its one state out of the list
    const py::object scene = is_gyrostat(model) ? gyrostat_scene(model, loads, gravity) : pivoted_scene(model, loads, gravity);
    const py::object next = step_scene_py(scene, py::make_tuple(state), dt, method, py::none(), py::none(), t);
    if (t.is_none()) return next[py::int_(0)];
    return py::make_tuple(next[py::int_(0)][py::int_(0)], next[py::int_(1)]);
  }
  return with_model(model, state, "state", [&](const auto& body, const auto& current) -> py::object {
    SimulationOptions o = as_options(dt, method, loads, gravity);
    if (!t.is_none()) {
      o.t0 = py_io::as_scalar(py_io::in_si(t, "s", "t"), "t");
    } else if (has_time_window(o.loads)) {
      py_io::throw_value_error("t", "the time [s] of `state` (a load acts on a time window: t_start or t_end "
                               "finite; pass t=... and use the time returned)", "None");
    }
    const auto next = step(body, current, o);
    if (!all_finite(next)) {
      const std::string msg = "step: the state became non-finite in the step of dt = " + format_value(o.dt) +
                              (t.is_none() ? std::string() : " from t = " + format_value(o.t0)) + " (method '" +
                              method_info(o.method).name + "')";
      if (PyErr_WarnEx(PyExc_RuntimeWarning, msg.c_str(), 1) != 0) throw py::error_already_set();
    }
    if (t.is_none()) return py::cast(next);
    return py::make_tuple(next, o.t0 + o.dt);
  });
}

const char* const simulate_doc = R"doc(
Integrate `model` from `initial` over `steps` fixed steps of `dt` [s] with `method` (see methods()),
in C++ with the GIL released, and record every `record_every`-th step (plus the first and the last).
The run's length: steps= (an int >= 0) or, by keyword, duration= [s] (a float or a pint quantity), exactly one;
a duration must be a whole number of steps of dt (to 1e-9 relative: 10 s at dt = 0.01 s is 1000 steps),
else ValueError naming duration and dt with the nearest durations that are.
dt, t0 and duration: each a float [s] or a pint quantity (converted to s; ValueError naming it for another
dimension).

model/initial: Particle/ParticleState, PlanarBody/PlanarBodyState or RigidBody/RigidBodyState; or a Scene
  or CompiledScene and a list of the states of its bodies (returns a SceneResult: see Scene); or a PivotedBody/
  PivotedBodyState, PivotedPlanarBody/PivotedPlanarBodyState or Gyrostat/GyrostatState: the one-body scene of
  the body, UniformGravity (gravity) and ScheduledLoads (loads) (returns a SceneResult; a PivotedPlanarBody takes
  an in-plane gravity (2,) or (3,)).
method: a name of methods(); None (the default): 'rk4', or the method a CompiledScene was compiled for.
loads: an AppliedLoad or a sequence of them, a piecewise-constant schedule: a step that crosses a
  switch time (a t_start or t_end) is split there into sub-steps of the same method, so every method
  keeps its order; records stay at t0 + i dt. gravity: None/False (the default: none), True
  ((0, 0, -9.81) m/s^2 in W) or a 3-vector [m/s^2] in W. t0: initial time [s]. scalar_first: quaternions
  as (w, x, y, z).
progress: None or a callable(steps_done), called with the GIL after the first step and then about every
  0.05 s of a long run, however long a step takes; an exception it raises stops the run and propagates.

Returns a SimulationResult, arrays with one row per record (n records): t (n,) [s]; p_W (n, 3) [m];
q_WB (n, 4) (x, y, z, w); v_W (n, 3) [m/s]; w_B (n, 3) [rad/s]; kinetic_energy (n,) [J];
total_energy (n,) kinetic + gravity potential [J]; angular_momentum_norm (n,) |H_G| [kg m^2/s];
quaternion_norm_error (n,) |q| - 1; work (n,) work of loads and gravity since t0 [J], integrated by the
same method (kinetic_energy - kinetic_energy[0] ~ work); diverged; unconverged_steps (implicit solves that
hit their iteration cap); elapsed_seconds (C++ loop wall time).
A particle records q = identity, w = 0; a planar body p = (x, y, 0), q = Rz(theta), w = (0, 0, omega).
Warns RuntimeWarning and stops if the state becomes non-finite; warns RuntimeWarning naming the quantities
and their first times if a recorded quantity is not finite although the state is (an overflow, e.g. the
kinetic energy of |v_W| > 1e154 m/s); warns RuntimeWarning (naming dt and the count) if an implicit solve
did not converge. Ctrl-C stops the run within about 0.05 s however long a step takes (a step under way is
finished first) with KeyboardInterrupt (no result is kept). ValueError names a bad argument, also a
recording larger than the memory available (record_every, with both figures).
)doc";

const char* const step_doc = R"doc(
One step of `method` (see methods()) of length dt [s] from `state` at time t [s] to t + dt under `loads`
(AppliedLoad or sequence) and `gravity` (None/False, the default: none; True for (0, 0, -9.81) m/s^2, or a
3-vector [m/s^2] in W). A step across a switch time of the loads is split there, as in simulate.
dt and t: each a float [s] or a pint quantity (converted to s; ValueError naming it for another dimension).

t=None (default): returns the new state (same type as `state`); ValueError (naming t) if a load acts on a
  time window (finite t_start or t_end), since the step then depends on the time.
t given: returns (new state, t + dt), e.g. `state, t = step(body, state, dt, loads=loads, t=t)` in a loop.
Warns RuntimeWarning if the new state is not finite, as simulate does. ValueError names a bad argument.
method: a name of methods(); None (the default): 'rk4', or the method a CompiledScene was compiled for.
model may also be a Scene or CompiledScene with `state` a list of the states of its bodies: returns the
list of new states (or (list, t + dt)); ValueError naming model for a scene with a MassFlow (a state does
not carry the mass: use simulate); or a PivotedBody / PivotedPlanarBody / Gyrostat with its state (the step of its
one-body scene, as simulate): returns the new state (or (state, t + dt)).
)doc";

}  // namespace

void bind_dynamics(py::module_& m) {
  py::class_<AppliedLoad> load(m, "AppliedLoad",
                               "A load: force (3,) [N] through the centre of mass and torque (3,) [N m] (a pure "
                               "couple), both expressed in frame 'world' (W) or 'body' (B), active for t_start <= t < "
                               "t_end [s]. Immutable. Each of force, torque, t_start, t_end: float(s) [unit] or a pint quantity (converted; "
                               "ValueError naming it for another dimension).");
  load.def(py::init([](py::handle force, py::handle torque, py::handle frame, py::handle t_start, py::handle t_end) {
             AppliedLoad l{py_io::as_vector3_or_zero(py_io::in_si(force, "N", "force"), "force"),
                           py_io::as_vector3_or_zero(py_io::in_si(torque, "N*m", "torque"), "torque"), as_frame(frame),
                           py_io::as_extended_real(py_io::in_si(t_start, "s", "t_start"), "t_start"),
                           py_io::as_extended_real(py_io::in_si(t_end, "s", "t_end"), "t_end")};
             check_loads({l});
             return l;
           }),
           py::arg("force") = py::none(), py::arg("torque") = py::none(),
           py::arg("frame") = "world", py::arg("t_start") = -std::numeric_limits<double>::infinity(),
           py::arg("t_end") = std::numeric_limits<double>::infinity())
      .def_property_readonly("force", [](const AppliedLoad& l) { return py_io::read_only(l.force); }, "(3,) [N] in frame")
      .def_property_readonly("torque", [](const AppliedLoad& l) { return py_io::read_only(l.torque); },
                             "(3,) [N m] in frame")
      .def_property_readonly(
          "frame", [](const AppliedLoad& l) { return l.frame == Frame::world ? "world" : "body"; }, "'world' or 'body'")
      .def_readonly("t_start", &AppliedLoad::t_start, "[s]")
      .def_readonly("t_end", &AppliedLoad::t_end, "[s]")
      .def("__repr__",
           [](const AppliedLoad& l) {
             // the infinite ends are the defaults and left out, so that the text evaluates
             std::string text = repr_call("AppliedLoad", {{"force", py::object(py_io::to_array(l.force))},
                                                          {"torque", py::object(py_io::to_array(l.torque))},
                                                          {"frame", py::str(l.frame == Frame::world ? "world" : "body")}});
             text.pop_back();
             if (std::isfinite(l.t_start)) text += ", t_start=" + py::repr(py::float_(l.t_start)).cast<std::string>();
             if (std::isfinite(l.t_end)) text += ", t_end=" + py::repr(py::float_(l.t_end)).cast<std::string>();
             return text + ")";
           })
      .def(py::pickle(
          [](const AppliedLoad& l) {
            return py::make_tuple(py_io::to_array(l.force), py_io::to_array(l.torque),
                                  l.frame == Frame::world ? "world" : "body", l.t_start, l.t_end);
          },
          [](const py::tuple& t) {
            if (t.size() != 5) py_io::throw_value_error("AppliedLoad pickle", "a tuple of 5 items", std::to_string(t.size()) + " items");
            AppliedLoad l{py_io::as_vector3(t[0], "force"), py_io::as_vector3(t[1], "torque"), as_frame(t[2]),
                          t[3].cast<double>(), t[4].cast<double>()};
            check_loads({l});
            return l;
          }))
      .def(
          "__eq__",
          [](const AppliedLoad& a, py::handle other) -> py::object {
            if (!py::isinstance<AppliedLoad>(other)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
            const AppliedLoad& b = other.cast<const AppliedLoad&>();
            return py::bool_(a.force == b.force && a.torque == b.torque && a.frame == b.frame &&
                             a.t_start == b.t_start && a.t_end == b.t_end);
          },
          py::arg("other"));
  load.attr("__hash__") = py::none();

  py::class_<SimulationResult>(m, "SimulationResult",
                               "simulate's records (see simulate), one row per record; the arrays are read-only.")
      .def_readonly("t", &SimulationResult::t, "(n,) time [s]")
      .def_readonly("p_W", &SimulationResult::p_W, "(n, 3) centre of mass position in W [m]")
      .def_readonly("q_WB", &SimulationResult::q_WB, "(n, 4) attitude, (x, y, z, w) unless scalar_first")
      .def_readonly("v_W", &SimulationResult::v_W, "(n, 3) centre of mass velocity in W [m/s]")
      .def_readonly("w_B", &SimulationResult::w_B, "(n, 3) angular velocity in B [rad/s]")
      .def_readonly("kinetic_energy", &SimulationResult::kinetic_energy, "(n,) [J]")
      .def_readonly("total_energy", &SimulationResult::total_energy, "(n,) kinetic + gravity potential [J]")
      .def_readonly("angular_momentum_norm", &SimulationResult::angular_momentum_norm,
                    "(n,) |H_G| about the centre of mass [kg m^2/s]")
      .def_readonly("quaternion_norm_error", &SimulationResult::quaternion_norm_error, "(n,) |q| - 1")
      .def_readonly("work", &SimulationResult::work, "(n,) work of loads and gravity since t0 [J]")
      .def_readonly("diverged", &SimulationResult::diverged, "True if the run stopped on a non-finite state")
      .def_readonly("unconverged_steps", &SimulationResult::unconverged_steps,
                    "number of steps whose implicit solve stopped at its iteration cap (implicit_midpoint; "
                    "0 for explicit methods); simulate warns RuntimeWarning when > 0")
      .def_readonly("elapsed_seconds", &SimulationResult::elapsed_seconds, "wall time of the C++ stepping loop [s]")
      .def_readonly("scalar_first", &SimulationResult::scalar_first,
                    "True if q_WB's rows are (w, x, y, z): the result of simulate(..., scalar_first=True)")
      .def("__repr__", &result_repr)
      .def(py::pickle(&result_state, &result_from_state))
      // the table lives in Python (rigiddyn/trajectory.py): one definition of the columns for CSV, npz,
      // Parquet and pandas
      .def(
          "to_dataframe",
          [](py::object self, py::handle scalar_first) {
            return py::module_::import("rigiddyn.trajectory").attr("to_dataframe")(self, scalar_first);
          },
          py::arg("scalar_first") = py::none(),
          "A pandas.DataFrame of the records (needs pandas: pip install 'rigiddyn[dataframe]'): one row per "
          "record, one column per scalar with its unit, as the CSV of `python -m rigiddyn simulate`: 't [s]' "
          "(a column, not the index), 'p_W_x [m]' .. 'q_WB_x' .. 'q_WB_w', 'v_W_x [m/s]' .., 'w_B_x [rad/s]' "
          ".., 'kinetic_energy [J]', 'total_energy [J]', 'angular_momentum_norm [kg m^2/s]', "
          "'quaternion_norm_error', 'work [J]'; q_WB's columns in the result's order ('q_WB_w' first when "
          "its scalar_first is True). scalar_first: None (the default) for the order the result records; "
          "True or False declares the order of its q_WB rows instead.");

#define RIGIDDYN_SIMULATE_ARGS                                                                              \
  py::arg("model"), py::arg("initial"), py::arg("dt"), py::arg("steps") = py::none(),                        \
      py::arg("method") = py::none(), py::arg("record_every") = 1, py::arg("loads") = py::none(),          \
      py::arg("gravity") = py::none(), py::arg("t0") = 0.0, py::arg("scalar_first") = false,               \
      py::arg("progress") = py::none(), py::kw_only(), py::arg("duration") = py::none()
#define RIGIDDYN_STEP_ARGS                                                                                  \
  py::arg("model"), py::arg("state"), py::arg("dt"), py::arg("method") = py::none(), py::arg("loads") = py::none(), \
      py::arg("gravity") = py::none(), py::arg("t") = py::none()
  m.def("simulate", &simulate_py, RIGIDDYN_SIMULATE_ARGS, simulate_doc);
  m.def("step", &step_py, RIGIDDYN_STEP_ARGS, step_doc);
  m.def(
      "_steps_of",
      [](py::handle steps, py::handle duration, py::handle dt) {
        return as_steps(steps, duration, py_io::as_scalar(py_io::in_si(dt, "s", "dt"), "dt"));
      },
      py::arg("steps"), py::arg("duration"), py::arg("dt"),
      "The step count of a run of simulate(..., steps=, duration=) at one dt [s] (the package's Python front ends "
      "check it before their own work); ValueError as simulate's.");
#undef RIGIDDYN_SIMULATE_ARGS
#undef RIGIDDYN_STEP_ARGS


  m.def(
      "methods",
      []() {
        py::list out;
        for (const MethodInfo& info : method_table()) {
          py::dict d;
          d["name"] = info.name;
          d["order"] = info.order;
          d["evaluations"] = info.evaluations;
          d["conserves"] = info.conserves;
          d["notes"] = info.notes;
          d["stability_limit"] = info.stability_limit;
          d["exact_torque_free"] = info.exact_torque_free;
          d["scene_features"] = scene_features(info.method);
          out.append(d);
        }
        return out;
      },
      "The fixed-step methods: a list of dicts with name, order (global), evaluations (derivative "
      "evaluations per step), conserves (what is kept exactly on a free rigid body), notes, stability_limit "
      "(largest dt*|w| [rad], |w| the largest body rate on the torque-free orbit, at which the method is "
      "documented stable on a free spin: inf if unconditionally, 0 if never), exact_torque_free (True if "
      "torque-free motion is reproduced to round-off at any dt: no observed order applies) and scene_features "
      "(what of a Scene the method runs: bodies, elements, and its compatibility notes).");
}

}  // namespace rigiddyn::bindings
