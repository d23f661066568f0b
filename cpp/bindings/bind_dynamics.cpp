// Python bindings of the simulation layer: applied loads, one `step` of any method, `simulate`, and
// the method registry `methods()` (the bodies, their states and dynamics are in bind_bodies.cpp).
// Every argument is taken as a handle and converted by name (numpy_io.hpp), so a wrong one raises
// TypeError/ValueError naming it, never pybind11's overload list.
#include <pybind11/stl.h>
#include <pybind11/typing.h>

#include "bindings.hpp"
#include "common_args.hpp"
#include "fast_call.hpp"
#include "numpy_io.hpp"
#include "pivoted.hpp"
#include "python_run.hpp"
#include "scene_run.hpp"
#include "repr.hpp"
#include "tolerance_run.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/compile.hpp"  // scene_features
#include "rigiddyn/simulate/simulate.hpp"
#include "rigiddyn/simulate/tolerance.hpp"  // error_measure_from_name

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

namespace rigiddyn::bindings {

namespace py = pybind11;
using py_io::Array;

namespace {

// The options shared by simulate and step but the step, each argument converted by name (TypeError/ValueError
// naming it); the core checks the values (finite gravity, ...).
SimulationOptions as_run_options(py::handle method, py::handle loads, py::handle gravity) {
  SimulationOptions o;
  o.method = method.is_none() ? Method::rk4 : method_from_name(py_io::as_string(method, "method"), "method");
  o.loads = as_loads(loads);
  o.gravity_W = as_gravity(gravity);
  return o;
}

// as_run_options with the step dt [s] (the core checks dt > 0).
SimulationOptions as_options(py::handle dt, py::handle method, py::handle loads, py::handle gravity) {
  SimulationOptions o = as_run_options(method, loads, gravity);
  o.dt = py_io::as_scalar(py_io::in_si(dt, "s", "dt"), "dt");
  return o;
}

// Whether `model` is a RigidBody, a PlanarBody or a Particle (the models with_model takes).
bool is_one_body(py::handle model) {
  return is_instance<RigidBody>(model) || is_instance<PlanarBody>(model) || is_instance<Particle>(model);
}

// Calls f(body, state) with the model `model` is and its state `state` (argument `state_name`);
// TypeError naming model for anything else, naming the state for another model's state.
template <class F>
auto with_model(py::handle model, py::handle state, const char* state_name, F&& f)
    -> decltype(f(std::declval<const RigidBody&>(), std::declval<RigidBodyState&>())) {
  if (is_instance<RigidBody>(model)) {
    return f(model.cast<const RigidBody&>(),
             py_io::as_instance<RigidBodyState>(state, state_name, "a RigidBodyState (the state of a RigidBody)"));
  }
  if (is_instance<PlanarBody>(model)) {
    return f(model.cast<const PlanarBody&>(),
             py_io::as_instance<PlanarBodyState>(state, state_name, "a PlanarBodyState (the state of a PlanarBody)"));
  }
  if (is_instance<Particle>(model)) {
    return f(model.cast<const Particle&>(),
             py_io::as_instance<ParticleState>(state, state_name, "a ParticleState (the state of a Particle)"));
  }
  py_io::throw_type_error("model", "a RigidBody, PlanarBody, Particle, PivotedBody, PivotedPlanarBody, Gyrostat, "
                          "Scene or CompiledScene", model);
}

// A Scene's Python object, named so in the signature
using SceneObject = py::typing::Union<Scene>;

// Scene.of_body: the one-body scene of `body` (any kind simulate takes alone), without a state
py::object one_body_scene_of(py::handle body, py::handle gravity, py::handle loads) {
  if (is_gyrostat(body)) return gyrostat_scene(body, loads, gravity);
  if (is_pivoted(body)) return pivoted_scene(body, loads, gravity);
  if (is_instance<RigidBody>(body)) return one_body_scene(body.cast<const RigidBody&>(), as_gravity(gravity), loads);
  if (is_instance<PlanarBody>(body)) return one_body_scene(body.cast<const PlanarBody&>(), as_gravity(gravity), loads);
  if (is_instance<Particle>(body)) return one_body_scene(body.cast<const Particle&>(), as_gravity(gravity), loads);
  py_io::throw_type_error("body", "a Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody or Gyrostat", body);
}

SceneObject scene_of_body(py::handle body, py::handle gravity, py::handle loads) {
  return py::reinterpret_borrow<SceneObject>(one_body_scene_of(body, gravity, loads));
}

constexpr const char* scene_of_body_doc = R"doc(The Scene that simulate(body, ..., gravity=, loads=) and step run for one body.

The body alone in W (index 0), with UniformGravity(gravity) when gravity is not zero and ScheduledLoads(body=0,
loads) when there are loads: each element declared only where it acts. A run of this scene gives the records of
simulate(body, ...) bitwise. Use it to add elements to a body's run, or to compile it once for many runs.

Parameters
----------
body : Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody or Gyrostat
    The body.
gravity : None, bool, array_like, shape (3,), or pint.Quantity, optional
    Uniform gravity g_W [m/s^2] in W: None or False none, True standard gravity (0, 0, -9.81); on a planar body
    it must lie in the xy plane.
loads : None, AppliedLoad or sequence of AppliedLoad, optional
    The piecewise-constant schedule of applied loads (simulate's `loads`).

Returns
-------
Scene
    One body; its elements: UniformGravity, then ScheduledLoads, those that act.

Raises
------
TypeError
    `body` of another type, `loads` not AppliedLoads.
ValueError
    Naming `gravity` (not finite; out of a planar body's plane) or `loads[i]` (not finite; a load the body's kind
    cannot take, e.g. a torque on a particle).

Examples
--------
>>> scene = rd.Scene.of_body(rd.RigidBody(2.0, [1.0, 2.0, 3.0]), gravity=True)
>>> [type(e).__name__ for e in scene.elements]
['UniformGravity']
>>> result = rd.simulate(scene, [rd.RigidBodyState(v_W=(1.0, 0.0, 0.0))], 0.01, steps=100, method="rk4")
>>> result.p_W[-1, 0].round(6)  # x = v t, z = -g t² / 2
array([ 1.   ,  0.   , -4.905])
)doc";

// A SceneResult's Python object, named so in the signature
using SceneResultObject = py::typing::Union<SceneResult>;

// simulate: a scene's run (bind_scene.cpp's), a body's as its one-body scene; every argument converted by name
// before the run (see simulate_doc).
SceneResultObject simulate_py(py::handle model, py::handle initial, py::handle dt, py::handle steps,
                              py::handle method, py::handle record_every, py::handle loads, py::handle gravity,
                              py::handle t0, py::handle scalar_first, py::handle progress, py::handle duration,
                              py::handle error, py::handle accuracy_level, py::handle tolerance, py::handle measure,
                              py::handle max_steps, py::handle controller) {
  const ToleranceHandles to{tolerance, measure, max_steps};
  if (is_scene(model)) {
    return py::reinterpret_borrow<SceneResultObject>(simulate_scene_py(model, initial, dt, steps, method, record_every,
                                                                       loads, gravity, t0, scalar_first, progress,
                                                                       duration, error, accuracy_level, to, controller));
  }
  if (is_gyrostat(model) || is_pivoted(model)) {
    return py::reinterpret_borrow<SceneResultObject>(simulate_scene_py(one_body_scene_of(model, gravity, loads),
                                                                       py::make_tuple(initial), dt, steps, method,
                                                                       record_every, py::none(), py::none(), t0,
                                                                       scalar_first, progress, duration, error,
                                                                       accuracy_level, to, controller));
  }
  // a particle, a planar or a rigid body: its scene compiled once for a loop of runs (simulate_scene_py)
  const OneBodyInputs body = with_model(model, initial, "initial", [&](const auto& b, const auto&) {
    return OneBodyInputs{Body(b), as_gravity(gravity), as_loads(loads)};
  });
  return py::reinterpret_borrow<SceneResultObject>(simulate_scene_py(model, py::make_tuple(initial), dt, steps, method,
                                                                     record_every, py::none(), py::none(), t0,
                                                                     scalar_first, progress, duration, error,
                                                                     accuracy_level, to, controller, &body));
}

// The quantities of a GlobalError with their units, in the order of max() and summary().
struct ErrorQuantity {
  const char* name;
  LazyArray GlobalError::*values;
  const char* unit;
};
constexpr ErrorQuantity error_quantities[] = {
    {"attitude", &GlobalError::attitude, "rad"},         {"angular_velocity", &GlobalError::angular_velocity, "rad/s"},
    {"position", &GlobalError::position, "m"},           {"velocity", &GlobalError::velocity, "m/s"},
    {"energy", &GlobalError::energy, "J"},               {"angular_momentum", &GlobalError::angular_momentum, "kg m^2/s"}};

// The largest finite value of `a` (any shape); NaN when it has none.
double finite_max(const Array& a) {
  double largest = std::numeric_limits<double>::quiet_NaN();
  for (py::ssize_t i = 0; i < a.size(); ++i) {
    const double v = a.data()[i];
    if (std::isfinite(v) && !(v <= largest)) largest = v;
  }
  return largest;
}

// {"attitude": largest estimate [rad], ...} over every record (and body).
py::dict error_max(const GlobalError& e) {
  py::dict out;
  for (const ErrorQuantity& q : error_quantities) out[q.name] = finite_max((e.*q.values).get());
  return out;
}

// The bits of e.reliable_quantities (measure_bit), C-contiguous.
py::array_t<std::uint8_t, py::array::c_style> quantity_bits(const GlobalError& e) {
  return py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(e.reliable_quantities.get());
}

// result.error.reliable_for(quantity): where the estimate of `quantity` (an error_measure_names name) is reliable,
// bool of the shape of `reliable`.
py::array_t<bool> reliable_for(const GlobalError& e, const std::string& quantity) {
  const std::uint8_t bit = measure_bit(error_measure_from_name(quantity, "quantity"));
  const auto bits = quantity_bits(e);
  py::array_t<bool> out(std::vector<py::ssize_t>(bits.shape(), bits.shape() + bits.ndim()));
  bool* into = out.mutable_data();
  for (py::ssize_t i = 0; i < bits.size(); ++i) into[i] = (bits.data()[i] & bit) != 0;
  py_io::set_read_only(out);
  return out;
}

// ", by quantity: attitude 1001, ..., energy 32" where a quantity is reliable at other records than the whole
// record's `reliable` count (a record is reliable where every quantity is); "" where each quantity's count is it.
std::string reliable_by_quantity(const GlobalError& e, std::size_t reliable) {
  const auto bits = quantity_bits(e);
  std::size_t counts[std::size(error_quantities)] = {};
  for (std::size_t k = 0; k < std::size(counts); ++k) {
    const std::uint8_t bit = measure_bit(error_measure_from_name(error_quantities[k].name));
    for (py::ssize_t i = 0; i < bits.size(); ++i) counts[k] += (bits.data()[i] & bit) != 0;
  }
  if (std::all_of(std::begin(counts), std::end(counts), [&](std::size_t c) { return c == reliable; })) return "";
  std::string text = ", by quantity:";
  const char* separator = " ";
  for (std::size_t k = 0; k < std::size(counts); ++k) {
    text += separator + std::string(error_quantities[k].name) + " " + std::to_string(counts[k]);
    separator = ", ";
  }
  return text;
}

// "order 4: 11 of 11 records reliable; largest estimates: attitude 3.1e-06 rad, ..." (and the first verdict that
// is not reliable, with its record; "sample i, record k" for a batch's, whose verdict holds a tuple per sample).
std::string error_summary(const GlobalError& e) {
  std::size_t records = 0, reliable = 0;
  std::string first_other;
  const auto count = [&](py::handle verdict, const std::string& where) {
    const std::string v = verdict.cast<std::string>();
    ++records;
    if (v == "reliable") {
      ++reliable;
    } else if (first_other.empty()) {
      first_other = where + ": " + v;
    }
  };
  const py::tuple verdict = e.verdicts.verdict();
  for (std::size_t i = 0; i < verdict.size(); ++i) {
    const py::handle item = verdict[i];
    if (!py::isinstance<py::tuple>(item)) {
      count(item, "record " + std::to_string(i));
      continue;
    }
    const py::tuple sample = py::reinterpret_borrow<py::tuple>(item);
    for (std::size_t k = 0; k < sample.size(); ++k) {
      count(sample[k], "sample " + std::to_string(i) + ", record " + std::to_string(k));
    }
  }
  std::string text = (e.order == 0 ? std::string("exact method (round-off bound)") : "order " + std::to_string(e.order)) +
                     ": " + std::to_string(reliable) + " of " + std::to_string(records) + " records reliable" +
                     reliable_by_quantity(e, reliable) + "; largest estimates:";
  const char* separator = " ";
  for (const ErrorQuantity& q : error_quantities) {
    char value[32];
    std::snprintf(value, sizeof value, "%.2g", finite_max((e.*q.values).get()));
    text += separator + std::string(q.name) + " " + value + " " + q.unit;
    separator = ", ";
  }
  if (!first_other.empty()) text += "; " + first_other;
  return text;
}

// A GlobalError's pickle state: order, the seven arrays of error_arrays, verdict, reliable, reliable_quantities.
constexpr LazyArray GlobalError::*error_arrays[] = {&GlobalError::attitude, &GlobalError::angular_velocity,
                                                    &GlobalError::position, &GlobalError::velocity,
                                                    &GlobalError::energy,   &GlobalError::angular_momentum,
                                                    &GlobalError::observed_order};

py::tuple global_error_state(const GlobalError& e) {
  py::tuple out(11);
  out[0] = py::int_(e.order);
  for (std::size_t k = 0; k < 7; ++k) out[k + 1] = (e.*error_arrays[k]).get();
  out[8] = e.verdicts.verdict();
  out[9] = e.verdicts.reliable();
  out[10] = e.reliable_quantities.get();
  return out;
}

// A state of 10 items (a pickle of a GlobalError without reliable_quantities) takes every quantity as reliable where
// its record is.
GlobalError global_error_from_state(const py::tuple& t) {
  if (t.size() != 10 && t.size() != 11) {
    py_io::throw_value_error("GlobalError pickle", "a tuple of 11 items (10 from an older pickle)",
                             std::to_string(t.size()) + " items");
  }
  const py::object numpy = py::module_::import("numpy");
  GlobalError e;
  e.order = t[0].cast<int>();
  for (std::size_t k = 0; k < 7; ++k) {
    Array a = Array::ensure(numpy.attr("array")(t[k + 1], "float64"));  // a copy
    py_io::set_read_only(a);
    e.*error_arrays[k] = LazyArray(a);
  }
  py::array_t<bool> reliable = py::array_t<bool>::ensure(numpy.attr("array")(t[9], "bool"));
  py_io::set_read_only(reliable);
  e.verdicts = LazyVerdicts(py::tuple(t[8]), reliable);
  auto quantities = py::array_t<std::uint8_t>::ensure(
      t.size() == 11 ? numpy.attr("array")(t[10], "uint8")
                     : numpy.attr("where")(reliable, py::int_(every_measure), 0).attr("astype")("uint8"));
  if (!quantities.attr("shape").equal(reliable.attr("shape"))) {
    py_io::throw_value_error("GlobalError pickle", "reliable_quantities of the shape of reliable",
                             py::str(quantities.attr("shape")).cast<std::string>());
  }
  py_io::set_read_only(quantities);
  e.reliable_quantities = LazyQuantityBits(quantities);
  return e;
}

// Every field the same (arrays bitwise, NaN equal to NaN).
bool same_error(const GlobalError& a, const GlobalError& b) {
  const py::object array_equal = py::module_::import("numpy").attr("array_equal");
  if (a.order != b.order || !a.verdicts.verdict().equal(b.verdicts.verdict()) ||
      !array_equal(a.verdicts.reliable(), b.verdicts.reliable()).cast<bool>() ||
      !array_equal(a.reliable_quantities.get(), b.reliable_quantities.get()).cast<bool>()) {
    return false;
  }
  for (const auto member : error_arrays) {
    if (!array_equal((a.*member).get(), (b.*member).get(), py::arg("equal_nan") = true).cast<bool>()) return false;
  }
  return true;
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
  const bool one_body = is_one_body(model);  // a RigidBody, PlanarBody or Particle: none of the kinds below
  if (!one_body && is_scene(model)) return step_scene_py(model, state, dt, method, loads, gravity, t);
  if (!one_body && (is_pivoted(model) || is_gyrostat(model))) {  // the one-body scene's step, its one state out of the list
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

const char* const simulate_doc = R"doc(Integrate a body or a scene over fixed steps and record its motion.

Runs `steps` fixed steps of `dt` with `method` (see methods()) from `initial` at time t0, in C++ with the GIL
released (a run of fewer than 512 steps times bodies keeps it, unless a controller drives it: taking it back would
cost more than such a run, and could wait for another thread), and records every `record_every`-th step plus the
first and the last (records at t0 + i dt). The loads are a piecewise-constant schedule: a step that crosses a
switch time (a t_start or t_end) is split there into sub-steps of the same method, so every method keeps its order.

Parameters
----------
model : Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody, Gyrostat, Scene or CompiledScene
    What to integrate. A body runs as its one-body scene with a UniformGravity (`gravity`) and a
    ScheduledLoads (`loads`).
initial : ParticleState, PlanarBodyState, RigidBodyState, PivotedBodyState, ..., or list
    The state of `model`'s kind at t0 (also PivotedPlanarBodyState or GyrostatState); for a Scene or
    CompiledScene, a list of the states of its bodies.
dt : float or pint.Quantity, optional
    Step [s], finite and > 0 (a quantity is converted to s). Exactly one of dt and tolerance.
steps : int, optional
    Number of steps, >= 0. Exactly one of steps and duration (with tolerance: duration).
method : str, optional
    A name of methods(): 'explicit_euler', 'semi_implicit_euler', 'semi_implicit_euler_implicit_gyroscopic',
    'rk4', 'rkmk4', 'implicit_midpoint', 'splitting_dlm', 'splitting_dlm_yoshida4', 'exact_flow_kick' or 'exact'.
    None (the default): 'rk4', or the method a CompiledScene was compiled for.
record_every : int, default 1
    Record every record_every-th step (>= 1), plus the first and the last.
loads : AppliedLoad or sequence of AppliedLoad, optional
    The applied loads (None: none). A Scene or CompiledScene takes None (it declares its loads as elements).
gravity : None, bool or array_like, shape (3,), default None
    Uniform gravity g_W [m/s^2] in W: None or False (none), True ((0, 0, -9.81)) or a vector. A PivotedPlanarBody
    takes None or an in-plane vector, shape (2,) or (3,); a Scene or CompiledScene takes None (declare a
    UniformGravity element).
t0 : float or pint.Quantity, default 0.0
    Initial time [s].
scalar_first : bool, default False
    Record quaternions as (w, x, y, z) instead of (x, y, z, w).
progress : callable, optional
    progress(steps_done), called with the GIL after the first step and then about every 0.05 s of a long run,
    however long a step takes; an exception it raises stops the run and propagates.
duration : float or pint.Quantity, keyword-only, optional
    Length of the run [s] instead of steps: a whole number of steps of dt (to 1e-9 relative: 10 s at
    dt = 0.01 s is 1000 steps).
error : bool, keyword-only, default True
    Estimate the global error of every record (result.error, a GlobalError) by two more runs of the method at 2 dt
    and 4 dt (+0.75x the cost; global Richardson extrapolation with an observed-order check, see GlobalError).
    A run without a PythonForce, a control law in Python or a progress callback, whose balances close whatever the
    estimate says, makes it on the first read of result.error, from the records the result keeps (the same values,
    the GIL released meanwhile), so that a run whose state alone is read pays for the run alone.
    False: no estimate (result.error is None), the cost of the run alone. True with tolerance.
accuracy_level : float or None, keyword-only, default 1e-3
    The relative residual of an energy or momentum balance (result.balance) beyond which a run without a reliable
    global error estimate warns with an AccuracyWarning (where the estimate is reliable, a residual beyond 10 times
    its bound warns instead); finite and > 0. None: no AccuracyWarning (the balance is still made). Runs that are
    coarse on purpose (work-precision studies) pass None.
tolerance : float or pint.Quantity, keyword-only, optional
    Instead of dt: the largest error of `measure` the run may have, absolute, in the measure's unit (a quantity
    is converted to it), finite and > 0. The method (unless given) and dt are chosen: each candidate method is
    piloted on a short run, its error fitted as C dt^p (t - t0), and the cheapest (method, dt) predicted to meet
    half the tolerance is run with its global error estimate as the certificate, refined while that fails (at
    most three times; see ToleranceChoice). The horizon is `duration` (steps depend on dt: steps is refused);
    record_every counts steps of the chosen dt; steps is a multiple of lcm(record_every, 4), so every record is
    checked (up to 1024 after t0, see GlobalError). Where the loads switch inside the horizon, every run's 4 dt
    ends at the switch times when a grid of at most 256 steps holds them; elsewhere a switch splits a step of the
    estimate's coarse runs, and the certificate takes no record whose order check failed.
    result.choice says what was chosen and why. A scene with a PythonForce is refused (ToleranceError): its
    estimate is never reliable.
measure : str, keyword-only, optional
    The quantity the tolerance bounds, its largest estimate over the records (and bodies): 'attitude' [rad],
    'angular_velocity' [rad/s], 'position' [m], 'velocity' [m/s], 'energy' [J] or 'angular_momentum'
    [kg m^2/s]. None (the default): 'position' for a Particle and a scene of particles, else 'attitude'
    (which, like 'angular_velocity', a scene of particles refuses: ValueError).
max_steps : int, keyword-only, optional
    The cost cap of a run to a tolerance: no run (the final run and its refinement) of more steps, >= 4.
    None (the default): 10_000_000.
controller : Controller, keyword-only, optional
    A digital controller (rigiddyn.Controller) of a body or a scene: its law is
    called with the GIL at t0 + k controller.period, k = 0, 1, ... before the end of the run, with the state of every
    body there, and its actuator commands (gyrostat wheel torques, MagneticDipole dipoles, ScheduledLoads thrusts)
    are held until the next sample; the steps are split at the samples, as at switch times, so every method keeps
    its order. The estimate's runs at 2 dt and 4 dt each go under a copy of the controller as it was before the
    run: a shipped law's, or a law in Python declared Controller(..., repeatable=True) (copy.deepcopy); an
    undeclared law in Python is sampled by the run alone, and result.error has no values, its verdict saying
    why. With tolerance, every run of the choice (pilots, the run, its estimate's runs) goes under a copy of the
    controller as it was before the call, which the law given never sees, and steps on a divisor of period / 4
    (so that no sample splits a step of the runs at 2 dt and 4 dt alone); the duration must then be a whole
    number of period / 4, and a law in Python must be declared repeatable. None (the default): no controller.

Returns
-------
SceneResult
    One row per record, n records, of every kind of model: per body (n, nb, ...) arrays (p_W, q_WB, v_W, w_B,
    mass, ...), the scene's (n,) energies and (n, ne) work of each element (a body's one-body scene: its
    UniformGravity first, then its ScheduledLoads); diverged, unconverged_steps, elapsed_seconds; error; balance;
    choice. result.body(0) (a BodyRecords) reads one body's records as (n, ...) arrays: q_WB (n, 4), ... The
    records are those of the run at dt whether or not error is True; elapsed_seconds
    is its loop's. result.balance (a Balance, on every run) holds the residuals of the work-energy and
    impulse-momentum balances per record, zero for the exact dynamics. With tolerance, result.choice is a
    ToleranceChoice (else None).

Raises
------
ValueError
    A bad argument, named: dt not > 0, steps < 0, both or neither of steps and duration, a duration that is not a
    whole number of steps of dt (the message gives the nearest durations that are), an unknown method (with the
    nearest name), record_every < 1, a recording larger than the memory available (record_every, with both
    figures), a quantity of another dimension, loads or gravity for a scene, accuracy_level not finite and > 0;
    with tolerance: tolerance not finite and > 0, dt or steps given too, no duration, error False, an unknown
    measure (with the nearest name), max_steps < 4; with a controller: a body outside a scene, a bad command
    (named by the controller), and with tolerance a law in Python not declared repeatable or a duration that is not
    a whole number of period / 4.
ToleranceError
    A ValueError: the tolerance cannot be met within max_steps, the last refined run's certificate still fails, or the
    scene has a PythonForce; it carries the measured error, the choice and the best result (see ToleranceError).
TypeError
    model not one of the kinds listed, or initial not of its kind (the message names it).
KeyboardInterrupt
    Ctrl-C stops the run within about 0.05 s however long a step takes (a step under way is finished first); no
    result is kept.

Warns
-----
RuntimeWarning
    The state became non-finite (the run stops there and diverged is True); a recorded quantity is not finite
    although the state is (an overflow, e.g. the kinetic energy of |v_W| > 1e154 m/s; the message names the
    quantities and their first times); an implicit solve did not converge (naming dt and the count).
AccuracyWarning
    An energy or momentum balance does not close: its residual exceeds 10 times the reliable global error
    estimate's bound (plus round-off), or, without a reliable estimate, accuracy_level of its scale (see Balance);
    the message gives the figure and suggests a smaller dt or another method.

See Also
--------
step, simulate_batch, methods, SceneResult, BodyRecords, AppliedLoad, Scene, GlobalError, Balance,
AccuracyWarning, ToleranceChoice

Notes
-----
A Particle records q = identity and w = 0; a PlanarBody records p = (x, y, 0), q = Rz(theta), w = (0, 0, omega).
work is integrated by the same method as the motion, so kinetic_energy - kinetic_energy[0] ~ work.sum(axis=1).

Examples
--------
A dropped particle follows z = -1/2 g t^2; rk4 integrates a quadratic motion exactly (round-off only):

>>> r = rd.simulate(rd.Particle(1.0), rd.ParticleState(), dt=0.01, duration=2.0, gravity=True, record_every=50)
>>> r.t
array([0. , 0.5, 1. , 1.5, 2. ])
>>> np.allclose(r.body(0).p_W[:, 2], -0.5 * 9.81 * r.t**2, rtol=0, atol=1e-12)
True

A torque-free body keeps its kinetic energy and |H_G|; implicit_midpoint holds both to its Newton tolerance
(1e-14 per step):

>>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
>>> r = rd.simulate(body, rd.RigidBodyState(w_B=[1.0, 0.1, 0.2]), dt=0.01, steps=1000, method="implicit_midpoint")
>>> body_records = r.body(0)
>>> body_records.q_WB.shape, bool(np.ptp(r.kinetic_energy) < 1e-10), bool(np.ptp(body_records.angular_momentum_norm) < 1e-10)
((1001, 4), True, True)

A force of 2 N on 1 kg for the first second (the step across t = 1 s is split there):

>>> push = rd.AppliedLoad(force=[2.0, 0.0, 0.0], t_end=1.0)
>>> rd.simulate(rd.Particle(1.0), rd.ParticleState(), dt=0.3, steps=5, loads=push).body(0).v_W[-1].round(12)
array([2., 0., 0.])

How accurate a run is: rk4 on a tumbling body, its attitude's error at the last record [rad]:

>>> r = rd.simulate(body, rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), dt=0.01, steps=1000)
>>> r.error.verdict[-1], bool(r.error.attitude[-1] < 1e-8)
('reliable', True)

Its balances close: the energy residual T - T0 - work and |H_G - H_G0| stay far below their scale:

>>> r.balance.verdict["energy"], r.balance.verdict["angular_momentum"], bool(abs(r.balance.energy[-1]) < 1e-9)
('closed', 'closed', True)

Or ask for the accuracy and let the method and dt be chosen: the attitude within 1e-7 rad over 10 s:

>>> r = rd.simulate(body, rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), duration=10.0, tolerance=1e-7)
>>> r.choice.met, bool(r.error.attitude.max() <= 1e-7), float(r.t[-1])
(True, True, 10.0)
)doc";

const char* const step_doc = R"doc(One step of `method` from `state` at time t to t + dt.

The step `simulate` takes, for a loop written in Python. A step across a switch time of the loads (a t_start or
t_end) is split there, as in simulate. Steps from the states they return, at the times t0 + i dt, give the records of
``simulate(model, state, dt, steps, t0=t0)`` bit for bit (by every method but 'exact', whose records are its closed
form from the run's start).

Parameters
----------
model : Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody, Gyrostat, Scene or CompiledScene
    What to step. A PivotedBody, PivotedPlanarBody or Gyrostat steps as its one-body scene, as in simulate.
state : ParticleState, PlanarBodyState, RigidBodyState, PivotedBodyState, ..., or list
    The state of `model`'s kind; for a Scene or CompiledScene, a list of the states of its bodies.
dt : float or pint.Quantity
    Step [s], finite and > 0.
method : str, optional
    A name of methods(); None (the default): 'rk4', or the method a CompiledScene was compiled for.
loads : AppliedLoad or sequence of AppliedLoad, optional
    The applied loads (None: none), as simulate takes them.
gravity : None, bool or array_like, shape (3,), default None
    Uniform gravity g_W [m/s^2] in W: None or False (none), True ((0, 0, -9.81)) or a vector; as simulate.
t : float or pint.Quantity, optional
    The time of `state` [s]. Needed when a load acts on a time window (finite t_start or t_end).

Returns
-------
state or (state, float)
    t None: the new state, of the type of `state` (a list of new states for a scene). t given: (new state,
    t + dt), e.g. ``state, t = step(body, state, dt, loads=loads, t=t)`` in a loop.

Raises
------
ValueError
    A bad argument, named; t None while a load acts on a time window (the step then depends on the time); a
    scene with a MassFlow (a state does not carry the mass: use simulate).
TypeError
    model not one of the kinds listed, or state not of its kind (the message names it).

Warns
-----
RuntimeWarning
    The new state is not finite, as simulate warns.

See Also
--------
simulate, methods

Examples
--------
Ten steps of 0.1 s at 1 rad/s about z turn a body 1 rad (rk4):

>>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
>>> state, t = rd.RigidBodyState(w_B=[0.0, 0.0, 1.0]), 0.0
>>> for _ in range(10):
...     state, t = rd.step(body, state, 0.1, t=t)
>>> print(f"{t:.12f}", rd.quat_to_rotvec(state.q_WB).round(6))
1.000000000000 [0. 0. 1.]

One step of a falling particle (rk4 is exact on it):

>>> rd.step(rd.Particle(1.0), rd.ParticleState(), 0.5, gravity=True).v_W.round(12)
array([ 0.   ,  0.   , -4.905])
)doc";

}  // namespace

void bind_dynamics(py::module_& m) {
  py::class_<AppliedLoad> load(m, "AppliedLoad",
      "An applied load: a force through the centre of mass and a couple, on a time window.\n"
      R"doc(
Both are expressed in frame 'world' (W) or 'body' (B) and act for t_start <= t < t_end. simulate and step take a
sequence of them as a piecewise-constant schedule, splitting a step at each t_start and t_end. Immutable;
pickles; == compares every field.

Parameters
----------
force : array_like, shape (3,), or pint.Quantity, optional
    Force through the centre of mass [N], in `frame` (None: zero).
torque : array_like, shape (3,), or pint.Quantity, optional
    Torque, a pure couple [N m], in `frame` (None: zero).
frame : {'world', 'body'}, default 'world'
    Frame of force and torque: W or B.
t_start : float or pint.Quantity, default -inf
    Start of the window [s].
t_end : float or pint.Quantity, default inf
    End of the window [s], excluded.

Raises
------
ValueError
    A field of another shape, a non-finite force or torque, an unknown frame, t_end not after t_start, or a
    quantity of another dimension (the message names it).

See Also
--------
simulate, step, simulate_batch

Examples
--------
2 N on 1 kg for one second, then coasting: v = 2 m/s, and 1 m + 2 m/s x 1 s = 3 m after 2 s:

>>> push = rd.AppliedLoad(force=[2.0, 0.0, 0.0], t_end=1.0)
>>> r = rd.simulate(rd.Particle(1.0), rd.ParticleState(), dt=0.1, steps=20, loads=push).body(0)
>>> r.v_W[-1].round(12), r.p_W[-1].round(12)
(array([2., 0., 0.]), array([3., 0., 0.]))
)doc");
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
      .def_property_readonly("force", [](const AppliedLoad& l) { return py_io::read_only(l.force); },
                             "Force through the centre of mass, in `frame`, shape (3,) [N].")
      .def_property_readonly("torque", [](const AppliedLoad& l) { return py_io::read_only(l.torque); },
                             "Torque (a pure couple), in `frame`, shape (3,) [N m].")
      .def_property_readonly(
          "frame", [](const AppliedLoad& l) { return l.frame == Frame::world ? "world" : "body"; },
          "Frame of force and torque: 'world' (W) or 'body' (B).")
      .def_readonly("t_start", &AppliedLoad::t_start, "Start of the window [s] (-inf: always on before t_end).")
      .def_readonly("t_end", &AppliedLoad::t_end, "End of the window [s], excluded (inf: never ends).")
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
            if (!is_instance<AppliedLoad>(other)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
            const AppliedLoad& b = other.cast<const AppliedLoad&>();
            return py::bool_(a.force == b.force && a.torque == b.torque && a.frame == b.frame &&
                             a.t_start == b.t_start && a.t_end == b.t_end);
          },
          py::arg("other"));
  load.attr("__hash__") = py::none();

  py::class_<GlobalError> error_class(m, "GlobalError",
      "The global error estimate of a run: result.error of simulate(..., error=True).\n"
      R"doc(
At every record, the error of the run at dt is estimated by global Richardson extrapolation: the method also runs at
2 dt and 4 dt, and for a method of order p

    eps ~ d(y_dt, y_2dt) / (2^p - 1),   r = d(y_2dt, y_4dt) / d(y_dt, y_2dt) ~ 2^p.

The distance d is the geodesic angle between attitudes [rad] (angular_distance) and the norm of the difference for
the other quantities. The estimate is called reliable only where the observed ratio r of every state quantity
(attitude, angular velocity, position, velocity: each checked over the bodies together) lies in
[2^p / 1.5, 2^p * 1.5], and that of the energy and |L| in [2^p / 1.5, 2^(p+1) * 1.5] (the error of an invariant may
fall one order faster than dt^p, e.g. rk4's energy on a linear problem: above 2^p * 1.5 its estimate takes the
observed order, d / (r - 1)). Elsewhere the verdict names the reason and the number is only indicative:
"not asymptotic: observed order 1.3 where 4 is expected (attitude)"; "step beyond the stability limit: ..." (a run
at 2 dt or 4 dt diverged, or its energy departed by more than |T| + |V|); "past the Lyapunov time of this scene:
..." (the estimates grew more than 1000 (t / t_k)^4 from an earlier record: nearby trajectories diverge
exponentially, and the differences leave the linear regime). A ratio above the window is flagged too: it is what an
error hidden from all three runs alike looks like. Where d is below the round-off bound of the run (8 eps_machine
per step, relative to the quantity's size; for |L| the size of its terms) the estimate is that bound, with the
verdict "reliable"; the method 'exact' reports the round-off bound alone (order 0). Measured against exact
references (docs/accuracy.md): the reliable estimates lie within a factor 2 of the true error. A verdict covers every
quantity of its record; reliable_for(quantity) gives the records where one quantity's own check passes (a damped
chain's positions, where its energy's error mixes two orders).

p is the order the run has, not always the method's: a scene whose velocity-dependent element (drag, a damper, a
PythonForce) meets a kick-based splitting runs at order 1.

The 2dt and 4dt runs have a state only every m = lcm(record_every, 4) steps: the estimate is computed and checked at
those records; between them it is interpolated linearly in t, and after the last of them (steps not a multiple of
m) grown linearly in t from t0. Those records are not checked, so their verdict says "interpolated ..." or
"extrapolated ..." rather than "reliable": pass a record_every and a steps that are multiples of 4 to have every
record checked. A run of fewer than m steps has no estimate (NaN, with a verdict saying so). At most 1024 records
after t0 are checked: a longer run's checked records are every k m steps (k the fewest that leave 1024) and its last
multiple of m, the records between interpolated (each checked record costs the 2dt and 4dt runs a record each and
the estimate a comparison, ~3.5 rk4 steps of a free body; the error between varies smoothly).

A scene with a PythonForce is never called reliable (verdict "not verified: ..."): a force that switches inside a
step (an `if t > t_s`) costs every method its order there, and the runs at dt, 2dt and 4dt can take the switch in
the same step, so that its error cancels in their differences while the order check passes.

simulate_batch gives one GlobalError for the whole batch (BatchResult.error): every array with a leading sample
axis, the verdict a tuple per sample; sample i's (result[i].error) is the one simulate gives for that sample alone.

Parameters
----------
None
    Made by simulate and simulate_batch; it has no public constructor.

See Also
--------
simulate, simulate_batch, SceneResult, angular_distance

Examples
--------
rk4 (order 4) on a tumbling body; halving dt divides the estimate by about 2^4 = 16:

>>> body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
>>> state = rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])
>>> coarse = rd.simulate(body, state, dt=0.02, steps=512).error
>>> fine = rd.simulate(body, state, dt=0.01, steps=1024).error
>>> coarse.order, coarse.verdict[-1], fine.verdict[-1]
(4, 'reliable', 'reliable')
>>> bool(12 < coarse.attitude[-1] / fine.attitude[-1] < 20)
True

explicit_euler at a coarse step gains energy at every step (its step is beyond its stability limit), and says so
(its energy balance is off too, which simulate reports with an AccuracyWarning: switched off here to show the
estimate's own verdict):

>>> rough = rd.simulate(body, rd.RigidBodyState(w_B=[0.1, 3.0, 0.1]), dt=0.1, steps=100, method="explicit_euler",
...                     accuracy_level=None)
>>> bool(rough.error.reliable[-1]), rough.error.verdict[-1].startswith("step beyond the stability limit")
(False, True)
>>> rough.balance.verdict["energy"].startswith("open")
True
)doc");
  error_class
      .def_readonly("order", &GlobalError::order,
                    "The order p the estimate assumed: the run's order (0: the method 'exact', round-off bound only).")
      .def_property_readonly("attitude", array_of(&GlobalError::attitude),
                    "Error of q_WB as a rotation angle [rad], shape (n,) ((n, nb) for a scene; a batch's with a leading "
                    "sample axis, (N, n) or (N, n, nb)).")
      .def_property_readonly("angular_velocity", array_of(&GlobalError::angular_velocity),
                    "Error of w_B, the norm [rad/s], shape (n,) ((n, nb) for a scene; a batch's (N, n) or (N, n, nb)).")
      .def_property_readonly("position", array_of(&GlobalError::position),
                             "Error of p_W, the norm [m], shape (n,) ((n, nb) for a scene; a batch's (N, n) or (N, n, nb)).")
      .def_property_readonly("velocity", array_of(&GlobalError::velocity),
                    "Error of v_W, the norm [m/s], shape (n,) ((n, nb) for a scene; a batch's (N, n) or (N, n, nb)).")
      .def_property_readonly("energy", array_of(&GlobalError::energy),
                             "Error of total_energy [J], shape (n,) (a batch's (N, n)).")
      .def_property_readonly("angular_momentum", array_of(&GlobalError::angular_momentum),
                    "Error of |L| (angular_momentum_norm of a body, |angular_momentum_W| of a scene) [kg m^2/s], shape (n,) (a batch's (N, n)).")
      .def_property_readonly("observed_order", array_of(&GlobalError::observed_order),
                    "log2 r of the quantity whose ratio r is furthest from 2^p, shape (n,) (a batch's (N, n)); NaN where every quantity is "
                    "at round-off level or no estimate was computed.")
      .def_property_readonly("verdict", [](const GlobalError& e) { return e.verdicts.verdict(); },
                    "'reliable' or the reason the estimate is not, per record (a tuple of n str; a batch's: a tuple of N "
                    "such tuples, one per sample).")
      .def_property_readonly("reliable", [](const GlobalError& e) { return e.verdicts.reliable(); },
                             "verdict == 'reliable', shape (n,) (bool; a batch's (N, n)).")
      .def("reliable_for", &reliable_for, py::arg("quantity"),
           R"doc(Where the estimate of one quantity is reliable, whatever the others' order checks say.

A record's verdict is 'reliable' only where every quantity passes its order check; one quantity may pass where
another does not. A damped spring chain's positions err as dt^4 while its total energy, no invariant there, errs
as a sum of two orders whose ratios r stray from 2^p: the records fail on the energy, and the positions' estimates
are still within their promise. reliable_for('position') is True at a record checked (a common record, see above)
where the position's own ratio r lies in its window (or its differences are at round-off) and nothing disqualifies
the record as a whole: a run at 2 dt or 4 dt beyond the stability limit, an energy balance that contradicts the
estimate, a PythonForce. Where it is True, the estimate of that quantity keeps the promise of a reliable record
(within a factor 2 of the true error, docs/accuracy.md). reliable implies reliable_for(q) for every q.

Parameters
----------
quantity : str
    'attitude', 'angular_velocity', 'position', 'velocity', 'energy' or 'angular_momentum'.

Returns
-------
numpy.ndarray
    bool, shape (n,) (a batch's (N, n)), read-only.

Raises
------
ValueError
    quantity is not one of the six names (the message names the nearest).

Examples
--------
The shipped spring chain (damped) at 2 ms, every 4th step recorded: most records fail on the energy, none on the
positions:

>>> scene, initial, _ = rd.load_scene("spring_chain")
>>> e = rd.simulate(scene, initial, dt=0.002, steps=1000, record_every=4).error
>>> n = len(e.reliable)
>>> bool(e.reliable.sum() < 0.1 * n and e.reliable_for("position").sum() > 0.9 * n)
True
)doc")
      .def("max", &error_max,
           R"doc(The largest estimate of each quantity over the records (and bodies).

Returns
-------
dict
    {'attitude': rad, 'angular_velocity': rad/s, 'position': m, 'velocity': m/s, 'energy': J,
    'angular_momentum': kg m^2/s}, floats (NaN for a quantity without an estimate).

Examples
--------
>>> r = rd.simulate(rd.RigidBody(1.0, [1.0, 2.0, 3.0]), rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), dt=0.01, steps=400)
>>> sorted(r.error.max()), bool(r.error.max()["attitude"] < 1e-8)
(['angular_momentum', 'angular_velocity', 'attitude', 'energy', 'position', 'velocity'], True)
)doc")
      .def("summary", &error_summary,
           R"doc(One line: the order, how many records are reliable, the largest estimates, the first other verdict.

Returns
-------
str

Examples
--------
>>> r = rd.simulate(rd.RigidBody(1.0, [1.0, 2.0, 3.0]), rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), dt=0.01, steps=400,
...                 record_every=4)
>>> r.error.summary().split(";")[0]
'order 4: 101 of 101 records reliable'
)doc")
      .def("__repr__", [](const GlobalError& e) { return "GlobalError(" + error_summary(e) + ")"; })
      .def(py::pickle(&global_error_state, &global_error_from_state))
      .def(
          "__eq__",
          [](const GlobalError& a, py::handle b) -> py::object {
            if (!is_instance<GlobalError>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
            return py::bool_(same_error(a, b.cast<const GlobalError&>()));
          },
          py::arg("other"));
  error_class.attr("__hash__") = py::none();

#define RIGIDDYN_SIMULATE_ARGS                                                                              \
  py::arg("model"), py::arg("initial"), py::arg("dt") = py::none(), py::arg("steps") = py::none(),      \
      py::arg("method") = py::none(), py::arg("record_every") = 1, py::arg("loads") = py::none(),          \
      py::arg("gravity") = py::none(), py::arg("t0") = 0.0, py::arg("scalar_first") = false,               \
      py::arg("progress") = py::none(), py::kw_only(), py::arg("duration") = py::none(),     \
      py::arg("error") = true, py::arg("accuracy_level") = 1e-3, py::arg("tolerance") = py::none(),         \
      py::arg("measure") = py::none(), py::arg("max_steps") = py::none(), py::arg("controller") = py::none()
#define RIGIDDYN_STEP_ARGS                                                                                  \
  py::arg("model"), py::arg("state"), py::arg("dt"), py::arg("method") = py::none(), py::arg("loads") = py::none(), \
      py::arg("gravity") = py::none(), py::arg("t") = py::none()
  // the accuracy check's rule (accuracy_check.hpp), which rigiddyn._balance documents as DEFAULT_LEVEL,
  // ESTIMATE_FACTOR and ESTIMATE_FLOOR
  m.attr("_accuracy_rule") = py::make_tuple(default_accuracy_level, estimate_factor, estimate_floor);
  m.def("simulate", &simulate_py, RIGIDDYN_SIMULATE_ARGS, simulate_doc);
  m.def("step", &step_py, RIGIDDYN_STEP_ARGS, step_doc);
  FastCall<&simulate_py>::add("simulate");  // called in loops: keywords without pybind11's per-call lookups
  FastCall<&step_py>::add("step");
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
      R"doc(The fixed-step methods simulate, step and simulate_batch take, with their properties.

Parameters
----------
None

Returns
-------
list of dict
    One dict per method, with the keys: name (str, the `method` argument); order (int, global order);
    evaluations (int, derivative evaluations per step); conserves (str, what is kept exactly on a free rigid
    body); notes (str); stability_limit (float, the largest dt*|w| [rad], |w| the largest body rate on the
    torque-free orbit, at which the method is documented stable on a free spin: inf if unconditionally, 0 if
    never); exact_torque_free (bool, True if torque-free motion is reproduced to round-off at any dt: no
    observed order applies); scene_features (str, what of a Scene the method runs: bodies, elements, and its
    compatibility notes).

See Also
--------
simulate, step

Examples
--------
>>> [m["name"] for m in rd.methods()]  # doctest: +NORMALIZE_WHITESPACE
['explicit_euler', 'semi_implicit_euler', 'semi_implicit_euler_implicit_gyroscopic', 'rk4', 'rkmk4',
 'implicit_midpoint', 'splitting_dlm', 'splitting_dlm_yoshida4', 'exact_flow_kick', 'exact']
>>> rk4 = next(m for m in rd.methods() if m["name"] == "rk4")
>>> rk4["order"], rk4["evaluations"], f"{rk4['stability_limit']:.6f}"  # 2 sqrt(2)
(4, 4, '2.828427')
)doc");
  py::reinterpret_borrow<py::class_<Scene>>(m.attr("Scene"))
      .def_static("of_body", &scene_of_body, py::arg("body"), py::arg("gravity") = py::none(),
                  py::arg("loads") = py::none(), scene_of_body_doc);
}

}  // namespace rigiddyn::bindings
