// simulate(..., tolerance=): the checks of its arguments, the methods it tries, the class ToleranceChoice
// (result.choice) and the exception ToleranceError. The runs are in bind_dynamics.cpp and bind_scene.cpp, the
// planner in simulate/tolerance.hpp.
#include "tolerance_run.hpp"

#include <pybind11/stl.h>

#include <cmath>
#include <string>

#include "numpy_io.hpp"
#include "repr.hpp"
#include "rigiddyn/check.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;

namespace {

PyObject* tolerance_error = nullptr;  // rigiddyn.ToleranceError, set by bind_tolerance

// The SI unit of each measure, as in_si takes it.
const char* pint_unit(ErrorMeasure measure) {
  constexpr const char* units[] = {"rad", "rad/s", "m", "m/s", "J", "kg*m^2/s"};
  return units[static_cast<int>(measure)];
}

py::dict pilot_dict(const PilotRun& p) {
  py::dict d;
  d["method"] = method_info(p.method).name;
  d["order"] = p.order;
  d["dt"] = p.dt;
  d["horizon"] = p.horizon;
  d["steps"] = p.steps;
  d["error"] = p.error;
  d["constant"] = p.constant;
  d["seconds_per_step"] = p.seconds_per_step;
  d["planned_steps"] = p.planned_steps;
  d["planned_seconds"] = p.planned_seconds;
  d["verdict"] = p.verdict;
  return d;
}

PilotRun pilot_from_dict(py::handle obj) {
  const py::dict d = py::reinterpret_borrow<py::dict>(obj);
  PilotRun p;
  p.method = method_from_name(d["method"].cast<std::string>(), "ToleranceChoice pickle pilots");
  p.order = d["order"].cast<int>();
  p.dt = d["dt"].cast<double>(), p.horizon = d["horizon"].cast<double>();
  p.steps = d["steps"].cast<std::int64_t>();
  p.error = d["error"].cast<double>(), p.constant = d["constant"].cast<double>();
  p.seconds_per_step = d["seconds_per_step"].cast<double>();
  p.planned_steps = d["planned_steps"].cast<std::int64_t>();
  p.planned_seconds = d["planned_seconds"].cast<double>();
  p.verdict = d["verdict"].cast<std::string>();
  return p;
}

py::tuple pilots_tuple(const ToleranceChoice& c) {
  py::tuple out(c.pilots.size());
  for (std::size_t i = 0; i < c.pilots.size(); ++i) out[i] = pilot_dict(c.pilots[i]);
  return out;
}

// The pickle state: every field, the pilots as dicts.
py::tuple choice_state(const ToleranceChoice& c) {
  return py::make_tuple(method_info(c.method).name, c.order, c.dt, c.steps, c.tolerance, error_measure_name(c.measure),
                        c.predicted_error, c.certified_error, c.met, c.refinements, c.reason, pilots_tuple(c),
                        c.pilot_seconds, c.run_seconds);
}

ToleranceChoice choice_from_state(const py::tuple& t) {
  if (t.size() != 14) {
    py_io::throw_value_error("ToleranceChoice pickle", "a tuple of 14 items", std::to_string(t.size()) + " items");
  }
  ToleranceChoice c;
  c.method = method_from_name(t[0].cast<std::string>(), "ToleranceChoice pickle method");
  c.order = t[1].cast<int>(), c.dt = t[2].cast<double>(), c.steps = t[3].cast<std::int64_t>();
  c.tolerance = t[4].cast<double>();
  c.measure = error_measure_from_name(t[5].cast<std::string>(), "ToleranceChoice pickle measure");
  c.predicted_error = t[6].cast<double>(), c.certified_error = t[7].cast<double>();
  c.met = t[8].cast<bool>(), c.refinements = t[9].cast<int>(), c.reason = t[10].cast<std::string>();
  for (py::handle p : py::tuple(t[11])) c.pilots.push_back(pilot_from_dict(p));
  c.pilot_seconds = t[12].cast<double>(), c.run_seconds = t[13].cast<double>();
  return c;
}

std::string choice_repr(const ToleranceChoice& c) {
  return repr_call("ToleranceChoice", {{"method", py::str(method_info(c.method).name)},
                                       {"dt", py::float_(c.dt)},
                                       {"steps", py::int_(c.steps)},
                                       {"measure", py::str(error_measure_name(c.measure))},
                                       {"tolerance", py::float_(c.tolerance)},
                                       {"predicted_error", py::float_(c.predicted_error)},
                                       {"certified_error", py::float_(c.certified_error)},
                                       {"met", py::bool_(c.met)},
                                       {"refinements", py::int_(c.refinements)}});
}

const char* const choice_doc = R"doc(What simulate(..., tolerance=) chose, and why: result.choice.

The planner pilots each candidate method on a short run (16 steps over a quarter of the horizon, shortened and
refined until its own global error estimate passes its order check), fits the error model
eps(t) ~ C dt^p (t - t0) (p the order the model has under the method, linear growth in t), and runs the cheapest
(method, dt) predicted to meet half the tolerance, cost = steps x the seconds per step its pilot measured (so that
two calls on machines of different speeds, or on one machine under different loads, may choose differently; a run of
a given method and dt is the same to the bit whatever the machine's pace). When its
run has 64 steps or more, the chosen method then runs over the whole horizon at a quarter of those steps and its
largest error, scaled by dt^p, sets the steps (an error that jumps after the short pilot's span is seen). The run's
global error estimate (GlobalError) is the certificate: when it is not accepted (see met), or above the tolerance,
the run is refined, dt' = dt (tolerance / 2 / error)^(1/p) (at most dt / 2 when not accepted), and refined again the
same way while the certificate fails, at most three times (a step that the short pilots called asymptotic may not
be over the whole horizon: a cluster's close encounters come later).

Parameters
----------
None
    Made by simulate; it has no public constructor. Pickles; == compares every field.

Attributes
----------
method : str
    The method of the final run.
order : int
    Its order on this model (0: 'exact', the closed form, whose error is its round-off bound).
dt : float
    Its step [s]; steps : int, its step count (duration / dt, a multiple of lcm(record_every, 4)).
measure : str
    The quantity the tolerance bounds ('attitude', 'angular_velocity', 'position', 'velocity', 'energy' or
    'angular_momentum'); tolerance : float, the bound, in the measure's unit.
predicted_error : float
    The error the pilot's fit predicted for the first final run, in the measure's unit (where the run at the
    fewest steps, tried first, met the tolerance: its own estimate).
certified_error : float
    The largest global error estimate of the measure over the records (and bodies) of the final run; where the
    largest error's own order is not asymptotic, a record accepted only as negligible (an observed order below the
    window) counts its difference d(y_h, y_2h) unextrapolated, as nothing in the run vouches for the power of h that
    Richardson's division presumes (NaN where a record has none).
met : bool
    The certificate holds: certified_error <= tolerance, and the measure's own estimate (its observed order
    checked alone: result.error's record-wide verdict also checks the other quantities) is accepted on every
    record: reliable, between two reliable records, an observed order above the window (an over-estimate), or an
    estimate <= tolerance / 16 (a zero crossing of an oscillating error, the round-off of the first records).
refinements : int
    0 to 3: the runs after the first.
reason : str
    The choice and its outcome, in words.
pilots : tuple of dict
    One per candidate: method, order, dt, horizon, steps, error, constant (C), seconds_per_step, planned_steps,
    planned_seconds and verdict ('used', or why not: pruned by order, not piloted because another method is exact
    on the scene, because it takes the same steps as another candidate (rkmk4 as rk4 and exact_flow_kick as
    splitting_dlm where no body turns in 3D) or because the first candidate's run over the whole horizon at the
    fewest steps (16) met the tolerance or set at most 64 steps, not asymptotic, ...); the figures a pilot did not
    reach are NaN (a candidate pruned or not piloted has no error, constant or seconds_per_step). A method the model
    does not take is left out, where the planner asked (a candidate not piloted may be one).
pilot_seconds, run_seconds : float
    Wall time of the pilots, and of the final run(s) with their estimates [s].

See Also
--------
simulate, GlobalError, ToleranceError

Examples
--------
>>> body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
>>> r = rd.simulate(body, rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), duration=10.0, tolerance=1e-6)
>>> c = r.choice
>>> c.met, c.measure, bool(c.certified_error <= 1e-6), c.steps * c.dt
(True, 'attitude', True, 10.0)
)doc";

const char* const error_doc = R"doc(simulate(..., tolerance=) could not meet the tolerance: a ValueError with the figures.

Raised when the cost cap (max_steps) would be exceeded, when the certificate of the refined run still fails, when no
method reached its asymptotic regime in its pilots, or before any run for a model whose forces the certificate
cannot check (a PythonForce). The message gives the figures (the steps needed, the measured or predicted error).

Parameters
----------
message : str
    The reason, with its figures (raised by simulate; not made by hand).

Attributes
----------
choice : ToleranceChoice or None
    What was chosen and what happened (None for a refusal before any run).
error : float
    The certified error of the best run, else the predicted error at max_steps, in the measure's unit (NaN for a
    refusal before any run).
tolerance : float
    The tolerance asked (NaN for a refusal).
measure : str or None
    The quantity it bounds.
result : SceneResult or None
    The best run (None when none ran).

See Also
--------
simulate, ToleranceChoice

Examples
--------
>>> couple = rd.AppliedLoad(torque=[0.0, 0.0, 0.1], frame="body")
>>> try:
...     rd.simulate(rd.RigidBody(1.0, [1.0, 2.0, 3.0]), rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), duration=20.0,
...                 loads=couple, tolerance=1e-10, max_steps=8)
... except rd.ToleranceError as e:
...     print(e.measure, e.tolerance, e.result, "max_steps = 8" in str(e))
attitude 1e-10 None True
)doc";

}  // namespace

std::optional<ToleranceArgs> as_tolerance_args(py::handle tolerance, py::handle measure, py::handle max_steps,
                                               py::handle dt, py::handle steps, py::handle duration,
                                               py::handle error, ErrorMeasure default_measure) {
  if (tolerance.is_none()) {
    if (!measure.is_none()) py_io::throw_value_error("measure", "None without tolerance", py_io::describe(measure));
    if (!max_steps.is_none()) py_io::throw_value_error("max_steps", "None without tolerance", py_io::describe(max_steps));
    if (dt.is_none()) {
      py_io::throw_value_error("dt", "a time step [s] > 0, or tolerance=... to have the step chosen", "None");
    }
    return std::nullopt;
  }
  ToleranceArgs a;  // the tolerance itself first: a bad one is named before the other arguments
  a.measure = measure.is_none() ? default_measure : error_measure_from_name(py_io::as_string(measure, "measure"));
  a.tolerance = py_io::as_scalar(py_io::in_si(tolerance, pint_unit(a.measure), "tolerance"), "tolerance");
  if (!(std::isfinite(a.tolerance) && a.tolerance > 0.0)) {
    py_io::throw_value_error("tolerance", "a finite number > 0 [" + error_measure_unit(a.measure) + "]",
                             format_value(a.tolerance));
  }
  a.max_steps = max_steps.is_none() ? default_max_steps : py_io::as_int(max_steps, "max_steps", 4);
  if (!dt.is_none()) {
    py_io::throw_value_error("dt", "None when tolerance is given (exactly one of dt and tolerance: the step is chosen)",
                             py_io::describe(dt));
  }
  if (!steps.is_none()) {
    py_io::throw_value_error("steps", "None when tolerance is given (the step count follows from the chosen dt): "
                             "give the horizon as duration=", py_io::describe(steps));
  }
  if (duration.is_none()) {
    py_io::throw_value_error("duration", "the time span [s] of the run when tolerance is given", "None");
  }
  if (!py_io::as_bool(error, "error")) {
    py_io::throw_value_error("error", "True when tolerance is given (the global error estimate is the certificate)",
                             "False");
  }
  a.horizon = py_io::as_scalar(py_io::in_si(duration, "s", "duration"), "duration");
  if (!(std::isfinite(a.horizon) && a.horizon > 0.0)) {
    py_io::throw_value_error("duration", "a finite time span > 0 [s]", format_value(a.horizon));
  }
  return a;
}

std::vector<Method> tolerance_methods() {
  return {Method::rk4,          Method::rkmk4,           Method::splitting_dlm_yoshida4,
          Method::splitting_dlm, Method::exact_flow_kick, Method::semi_implicit_euler_implicit_gyroscopic,
          Method::exact};
}

void raise_tolerance_error(const ToleranceChoice& choice, py::object result) {
  const std::string message = "tolerance: " + format_value(choice.tolerance) + " " + error_measure_unit(choice.measure) +
                              " (" + error_measure_name(choice.measure) + ") not met: " + choice.reason;
  py::object exc = py::reinterpret_borrow<py::object>(tolerance_error)(message);
  exc.attr("choice") = py::cast(choice);
  exc.attr("error") = std::isnan(choice.certified_error) ? choice.predicted_error : choice.certified_error;
  exc.attr("tolerance") = choice.tolerance;
  exc.attr("measure") = error_measure_name(choice.measure);
  exc.attr("result") = std::move(result);
  PyErr_SetObject(tolerance_error, exc.ptr());
  throw py::error_already_set();
}

void refuse_tolerance(const std::string& what, const std::string& why) {
  py::object exc = py::reinterpret_borrow<py::object>(tolerance_error)("tolerance: refused for " + what + ": " + why);
  exc.attr("choice") = py::none();
  exc.attr("error") = std::nan("");
  exc.attr("tolerance") = std::nan("");
  exc.attr("measure") = py::none();
  exc.attr("result") = py::none();
  PyErr_SetObject(tolerance_error, exc.ptr());
  throw py::error_already_set();
}

void bind_tolerance(py::module_& m) {
  tolerance_error = PyErr_NewExceptionWithDoc("rigiddyn._core.ToleranceError", error_doc, PyExc_ValueError, nullptr);
  if (tolerance_error == nullptr) throw py::error_already_set();
  m.attr("ToleranceError") = py::handle(tolerance_error);

  py::class_<ToleranceChoice> choice(m, "ToleranceChoice", choice_doc);
  choice.def_property_readonly("method", [](const ToleranceChoice& c) { return method_info(c.method).name; },
                               "The method of the final run (a str).")
      .def_readonly("order", &ToleranceChoice::order, "Its order on this model (0: 'exact').")
      .def_readonly("dt", &ToleranceChoice::dt, "The step of the final run [s].")
      .def_readonly("steps", &ToleranceChoice::steps, "The steps of the final run.")
      .def_readonly("tolerance", &ToleranceChoice::tolerance, "The tolerance, in the measure's unit.")
      .def_property_readonly("measure", [](const ToleranceChoice& c) { return error_measure_name(c.measure); },
                             "The quantity the tolerance bounds (a str).")
      .def_readonly("predicted_error", &ToleranceChoice::predicted_error,
                    "The error the pilot's fit predicted for the first final run, in the measure's unit (the run at "
                    "the fewest steps that met the tolerance: its own estimate).")
      .def_readonly("certified_error", &ToleranceChoice::certified_error,
                    "The largest estimate of the measure over the final run's records and bodies; where the largest "
                    "error's order is not asymptotic, a record accepted only as negligible counts its difference "
                    "d(y_h, y_2h) (NaN: none).")
      .def_readonly("met", &ToleranceChoice::met, "Every record reliable and certified_error <= tolerance.")
      .def_readonly("refinements", &ToleranceChoice::refinements, "0 to 3: the runs after the first.")
      .def_readonly("reason", &ToleranceChoice::reason, "The choice and its outcome, in words.")
      .def_property_readonly("pilots", &pilots_tuple, "One dict per candidate method (see the class docstring).")
      .def_readonly("pilot_seconds", &ToleranceChoice::pilot_seconds, "Wall time of the pilots [s].")
      .def_readonly("run_seconds", &ToleranceChoice::run_seconds,
                    "Wall time of the final run(s) with their estimates [s].")
      .def("__repr__", &choice_repr)
      .def(py::pickle(&choice_state, &choice_from_state))
      .def(
          "__eq__",
          [](const ToleranceChoice& a, py::handle b) -> py::object {
            if (!is_instance<ToleranceChoice>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
            // the states' reprs: NaN equal to NaN, floats to the last bit
            return py::bool_(py::repr(choice_state(a)).cast<std::string>() ==
                             py::repr(choice_state(b.cast<const ToleranceChoice&>())).cast<std::string>());
          },
          py::arg("other"));
  choice.attr("__hash__") = py::none();
}

}  // namespace rigiddyn::bindings
