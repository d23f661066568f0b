// Python bindings of batch runs (batch/simulate_batch.hpp, batch/simd_rigid_body.hpp): rigiddyn.simulate_batch
// and its result BatchSceneResult (of scenes; a batch of bodies runs their one-body scenes), read-only numpy arrays
// with a leading sample axis adopting the C++ records. Every argument is converted by name (numpy_io.hpp) before the run;
// the run itself holds no GIL (python_run.hpp's PythonMonitor gives progress and Ctrl-C from the calling
// thread only).
#include <pybind11/stl.h>
#include <pybind11/typing.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <optional>
#include <type_traits>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "body_records.hpp"
#include "common_args.hpp"
#include "numpy_io.hpp"
#include "python_run.hpp"
#include "repr.hpp"
#include "scene_run.hpp"
#include "rigiddyn/batch/parallel_for.hpp"
#include "rigiddyn/batch/simd_rigid_body.hpp"
#include "rigiddyn/vector_instructions.hpp"
#include "rigiddyn/batch/simulate_batch.hpp"
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/one_body_scene.hpp"
#include "rigiddyn/scene/scene_order.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using py_io::Array;

namespace {

// ------------------------------------------------------------ numpy views of the stacked records

// A read-only numpy array adopting a std::vector of any element type (no copy).
template <class T>
py::array adopt_vector(std::vector<T>&& data, std::vector<py::ssize_t> shape) {
  auto* owner = new std::vector<T>(std::move(data));
  py::capsule free_owner(owner, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  py::array_t<T> out(shape, owner->data(), free_owner);
  py_io::set_read_only(out);
  return std::move(out);
}

// diverged as a read-only numpy bool array (N,).
py::array bool_array(const std::vector<std::uint8_t>& flags) {
  py::array_t<bool> out(static_cast<py::ssize_t>(flags.size()));
  bool* p = out.mutable_data();
  for (std::size_t i = 0; i < flags.size(); ++i) p[i] = flags[i] != 0;
  py_io::set_read_only(out);
  return std::move(out);
}

// A read-only float64 copy of `obj` with exactly `shape` (a pickle's array), else ValueError naming it.
py::array checked_copy(py::handle obj, const std::string& name, const std::vector<py::ssize_t>& shape,
                       const char* dtype = "float64") {
  py::array a = py::module_::import("numpy").attr("array")(obj, dtype);  // a copy
  bool ok = a.ndim() == static_cast<py::ssize_t>(shape.size());
  for (std::size_t d = 0; ok && d < shape.size(); ++d) ok = a.shape(d) == shape[d];
  if (!ok) {
    std::string expected = "shape (";
    for (std::size_t d = 0; d < shape.size(); ++d) expected += (d ? ", " : "") + std::to_string(shape[d]);
    py_io::throw_value_error(name, expected + ")", py_io::describe(obj));
  }
  py_io::set_read_only(a);
  return a;
}

// Rows [0, rows) of sample i of a stacked array (N, n, ...) as a new read-only float64 array (rows, ...).
Array sample_rows(const py::array& stacked, py::ssize_t i, py::ssize_t rows) {
  const py::object row = stacked[py::int_(i)];
  const py::object cut = row[py::slice(0, rows, 1)];
  Array out = Array::ensure(py::module_::import("numpy").attr("array")(cut, "float64"));  // a copy
  py_io::set_read_only(out);
  return out;
}

// The index `key` of a sequence of n (negative counts from the end), else IndexError.
py::ssize_t sample_index(py::handle key, py::ssize_t n, const char* cls) {
  const std::int64_t i = py_io::as_int(key, "index");
  const std::int64_t j = i < 0 ? i + n : i;
  if (j < 0 || j >= n) {
    throw py::index_error(std::string(cls) + " index: expected an integer in [-" + std::to_string(n) + ", " +
                          std::to_string(n) + "), got " + std::to_string(i));
  }
  return static_cast<py::ssize_t>(j);
}

// The error item of a pickle state: a GlobalError or None (`what` names it in the message).
py::object error_from_state(py::handle item, const std::string& what) {
  if (!item.is_none() && !is_instance<GlobalError>(item)) py_io::throw_type_error(what, "a GlobalError or None", item);
  return py::reinterpret_borrow<py::object>(item);
}

std::int64_t count_true(const py::array& flags) { return py::int_(flags.attr("sum")()).cast<std::int64_t>(); }

// ------------------------------------------------------------ BatchSceneResult

// The arrays of a scene batch, with their shapes after (N, n) (-1: bodies, -2: work columns), and the member
// of SceneResult each sample's rows go to.
struct SceneColumn {
  const char* name;
  std::vector<double> BatchSceneSimulation::*data;
  LazyArray SceneResult::*member;
  std::vector<py::ssize_t> tail;
};
const SceneColumn scene_columns[] = {
    {"t", &BatchSceneSimulation::t, &SceneResult::t, {}},
    {"p_W", &BatchSceneSimulation::p_W, &SceneResult::p_W, {-1, 3}},
    {"q_WB", &BatchSceneSimulation::q_WB, &SceneResult::q_WB, {-1, 4}},
    {"v_W", &BatchSceneSimulation::v_W, &SceneResult::v_W, {-1, 3}},
    {"w_B", &BatchSceneSimulation::w_B, &SceneResult::w_B, {-1, 3}},
    {"kinetic_energy", &BatchSceneSimulation::kinetic_energy, &SceneResult::kinetic_energy, {}},
    {"potential_energy", &BatchSceneSimulation::potential_energy, &SceneResult::potential_energy, {}},
    {"total_energy", &BatchSceneSimulation::total_energy, &SceneResult::total_energy, {}},
    {"linear_momentum_W", &BatchSceneSimulation::linear_momentum_W, &SceneResult::linear_momentum_W, {3}},
    {"angular_momentum_W", &BatchSceneSimulation::angular_momentum_W, &SceneResult::angular_momentum_W, {3}},
    {"pivot_reaction_W", &BatchSceneSimulation::pivot_reaction_W, &SceneResult::pivot_reaction_W, {-1, 3}},
    {"angular_momentum_O_W", &BatchSceneSimulation::angular_momentum_O_W, &SceneResult::angular_momentum_O_W, {-1, 3}},
    {"mass", &BatchSceneSimulation::mass, &SceneResult::mass, {-1}},
    {"work", &BatchSceneSimulation::work, &SceneResult::work, {-2}},
    {"power", &BatchSceneSimulation::power, &SceneResult::power, {-2}},
    {"mass_flow_energy", &BatchSceneSimulation::mass_flow_energy, &SceneResult::mass_flow_energy, {-1}},
};
constexpr std::size_t scene_column_count = sizeof(scene_columns) / sizeof(scene_columns[0]);

struct BatchSceneResult {
  py::array arrays[scene_column_count];  // scene_columns, each (N, n, ...)
  py::tuple body_names, elements;
  py::array wheel_speed;   // (N, n, nw) each gyrostat wheel's speed relative to its body [rad/s]
  py::array motor_work;    // (N, n, nw) each wheel's motor work since t0 [J]
  py::tuple wheel_bodies;  // (nw,) the body index of each wheel
  py::array joint_q;       // (N, n, nq) the trees' configurations q
  py::array joint_v;       // (N, n, nv) their velocities v
  py::array diverged, filled, unconverged_steps;  // (N,) bool, int64, int64
  double elapsed_seconds = 0.0;
  bool scalar_first = false;  // q_WB rows as (w, x, y, z)
  LazyBatchError error;  // a GlobalError with a leading sample axis (simulate_batch(..., error=True)) or None

  py::ssize_t samples() const { return filled.shape(0); }
  py::ssize_t records() const { return arrays[0].shape(1); }
};

std::vector<py::ssize_t> scene_shape(py::ssize_t N, py::ssize_t n, const std::vector<py::ssize_t>& tail, py::ssize_t nb,
                                     py::ssize_t ne) {
  std::vector<py::ssize_t> shape{N, n};
  for (py::ssize_t d : tail) shape.push_back(d == -1 ? nb : d == -2 ? ne : d);
  return shape;
}

BatchSceneResult to_batch_scene_result(BatchSceneSimulation&& b, py::tuple body_names, py::tuple elements,
                                       py::tuple wheel_bodies, bool scalar_first) {
  const auto N = static_cast<py::ssize_t>(b.samples), n = static_cast<py::ssize_t>(b.records);
  if (scalar_first) to_scalar_first(b.q_WB);
  BatchSceneResult r;
  for (std::size_t k = 0; k < scene_column_count; ++k) {
    r.arrays[k] = adopt_vector(std::move(b.*(scene_columns[k].data)),
                               scene_shape(N, n, scene_columns[k].tail, b.body_count, b.element_count));
  }
  r.body_names = std::move(body_names);
  r.elements = std::move(elements);
  r.wheel_speed = adopt_vector(std::move(b.wheel_speed), {N, n, static_cast<py::ssize_t>(b.wheel_count)});
  r.motor_work = adopt_vector(std::move(b.motor_work), {N, n, static_cast<py::ssize_t>(b.wheel_count)});
  r.wheel_bodies = std::move(wheel_bodies);
  r.joint_q = adopt_vector(std::move(b.joint_q), {N, n, static_cast<py::ssize_t>(b.joint_q_count)});
  r.joint_v = adopt_vector(std::move(b.joint_v), {N, n, static_cast<py::ssize_t>(b.joint_v_count)});
  r.diverged = bool_array(b.diverged);
  r.filled = adopt_vector(std::move(b.filled), {N});
  r.unconverged_steps = adopt_vector(std::move(b.unconverged_steps), {N});
  r.elapsed_seconds = b.elapsed_seconds;
  r.scalar_first = scalar_first;
  return r;
}

// The array of the column `name` of r (scene_columns).
const py::array& batch_column(const BatchSceneResult& r, const char* name) {
  for (std::size_t k = 0; k < scene_column_count; ++k) {
    if (std::strcmp(scene_columns[k].name, name) == 0) return r.arrays[k];
  }
  throw std::logic_error(std::string("no batch column ") + name);
}

[[noreturn]] void raise_sample_failure(const SampleFailure& failure);

// result.error of r (LazyBatchError): a deferred estimate reads the answer's columns from r's own arrays (GIL held);
// a sample's exception in its coarse runs is raised as the batch raises it ("sample <i>: ...").
py::object batch_result_error(const BatchSceneResult& r) {
  try {
    return r.error.get([&r] {
      const auto data = [&r](const char* name) { return static_cast<const double*>(batch_column(r, name).data()); };
      BatchColumns c;
      c.samples = static_cast<std::size_t>(r.samples()), c.records = static_cast<std::size_t>(r.records());
      c.bodies = static_cast<std::int64_t>(batch_column(r, "q_WB").shape(2));
      c.filled = static_cast<const std::int64_t*>(r.filled.data());
      c.t = data("t"), c.q_WB = data("q_WB"), c.w_B = data("w_B"), c.p_W = data("p_W"), c.v_W = data("v_W");
      c.scalar_first = r.scalar_first;
      c.total_energy = data("total_energy"), c.kinetic_energy = data("kinetic_energy");
      c.angular_momentum_W = data("angular_momentum_W");
      c.mass = data("mass"), c.angular_momentum_O_W = data("angular_momentum_O_W"), c.work = data("work");
      c.elements = static_cast<std::int64_t>(batch_column(r, "work").shape(2));
      c.mass_flow_energy = data("mass_flow_energy");
      c.motor_work = static_cast<const double*>(r.motor_work.data());
      c.wheels = static_cast<std::int64_t>(r.motor_work.shape(2));
      return c;
    });
  } catch (const SampleFailure& failure) {
    raise_sample_failure(failure);
  }
}

py::tuple batch_scene_state(const BatchSceneResult& r) {
  py::tuple out(scene_column_count + 13);
  for (std::size_t k = 0; k < scene_column_count; ++k) out[k] = r.arrays[k];
  out[scene_column_count] = r.body_names;
  out[scene_column_count + 1] = r.elements;
  out[scene_column_count + 2] = r.diverged;
  out[scene_column_count + 3] = r.filled;
  out[scene_column_count + 4] = r.unconverged_steps;
  out[scene_column_count + 5] = py::float_(r.elapsed_seconds);
  out[scene_column_count + 6] = py::bool_(r.scalar_first);
  out[scene_column_count + 7] = r.wheel_speed;
  out[scene_column_count + 8] = r.motor_work;
  out[scene_column_count + 9] = r.wheel_bodies;
  out[scene_column_count + 10] = batch_result_error(r);
  out[scene_column_count + 11] = r.joint_q;
  out[scene_column_count + 12] = r.joint_v;
  return out;
}

// scene_column_count + 6 or + 7 items: a state without scalar_first (q_WB as (x, y, z, w)) or without the wheels,
// + 10 without the error estimate, + 11 without the joint columns, as earlier pickles
BatchSceneResult batch_scene_from_state(const py::tuple& t) {
  const std::size_t size = t.size();
  const std::size_t wheels = scene_column_count + 10;  // the size of a state with the wheels
  if (size != scene_column_count + 6 && size != scene_column_count + 7 && size != wheels && size != wheels + 1 &&
      size != wheels + 3) {
    py_io::throw_value_error("BatchSceneResult pickle",
                             "a tuple of " + std::to_string(scene_column_count + 6) + ", " +
                                 std::to_string(scene_column_count + 7) + ", " + std::to_string(wheels) + ", " +
                                 std::to_string(wheels + 1) + " or " + std::to_string(wheels + 3) + " items",
                             std::to_string(size) + " items");
  }
  BatchSceneResult r;
  r.body_names = py::tuple(t[scene_column_count]);
  r.elements = py::tuple(t[scene_column_count + 1]);
  const py::array t0 = py::module_::import("numpy").attr("asarray")(t[0]);
  if (t0.ndim() != 2) py_io::throw_value_error("BatchSceneResult pickle t", "shape (N, n)", py_io::describe(t[0]));
  const py::ssize_t N = t0.shape(0), n = t0.shape(1);
  const auto nb = static_cast<py::ssize_t>(r.body_names.size()), ne = static_cast<py::ssize_t>(r.elements.size());
  for (std::size_t k = 0; k < scene_column_count; ++k) {
    r.arrays[k] = checked_copy(t[k], std::string("BatchSceneResult pickle ") + scene_columns[k].name,
                               scene_shape(N, n, scene_columns[k].tail, nb, ne));
  }
  r.diverged = checked_copy(t[scene_column_count + 2], "BatchSceneResult pickle diverged", {N}, "bool");
  r.filled = checked_copy(t[scene_column_count + 3], "BatchSceneResult pickle filled", {N}, "int64");
  r.unconverged_steps = checked_copy(t[scene_column_count + 4], "BatchSceneResult pickle unconverged_steps", {N}, "int64");
  r.elapsed_seconds = t[scene_column_count + 5].cast<double>();
  r.scalar_first = size >= scene_column_count + 7 && t[scene_column_count + 6].cast<bool>();
  r.wheel_bodies = size >= wheels ? py::tuple(t[scene_column_count + 9]) : py::tuple();
  if (size >= wheels + 1) r.error = error_from_state(t[wheels], "BatchSceneResult pickle error");
  const auto nw = static_cast<py::ssize_t>(r.wheel_bodies.size());
  // each wheel column, (N, n, nw) (empty in an earlier pickle)
  const auto wheel_column = [&](std::size_t at, const std::string& name) -> py::array {
    if (size < wheels) return py::array_t<double>(std::vector<py::ssize_t>{N, n, 0});
    return checked_copy(t[at], "BatchSceneResult pickle " + name, {N, n, nw});
  };
  r.wheel_speed = wheel_column(scene_column_count + 7, "wheel_speed");
  r.motor_work = wheel_column(scene_column_count + 8, "motor_work");
  // each joint column, (N, n, k) (empty in an earlier pickle)
  const auto joint_column = [&](std::size_t at, const std::string& name) -> py::array {
    if (size < wheels + 3) return py::array_t<double>(std::vector<py::ssize_t>{N, n, 0});
    const py::array a = py::module_::import("numpy").attr("asarray")(t[at]);
    return checked_copy(t[at], "BatchSceneResult pickle " + name, {N, n, a.ndim() == 3 ? a.shape(2) : 0});
  };
  r.joint_q = joint_column(wheels + 1, "joint_q");
  r.joint_v = joint_column(wheels + 2, "joint_v");
  return r;
}

// result[i]: sample i's records (its filled rows) as a rigiddyn.SceneResult; elapsed_seconds is the batch's.
SceneResult batch_scene_sample(const BatchSceneResult& r, py::handle key) {
  const py::ssize_t i = sample_index(key, r.samples(), "BatchSceneResult");
  const py::ssize_t rows = r.filled.attr("__getitem__")(i).cast<py::ssize_t>();
  SceneResult out;
  for (std::size_t k = 0; k < scene_column_count; ++k) {
    out.*(scene_columns[k].member) = LazyArray(sample_rows(r.arrays[k], i, rows));
  }
  out.body_names = r.body_names;
  out.elements = r.elements;
  out.wheel_speed = LazyArray(sample_rows(r.wheel_speed, i, rows));
  out.motor_work = LazyArray(sample_rows(r.motor_work, i, rows));
  out.wheel_bodies = r.wheel_bodies;
  out.joint_q = LazyArray(sample_rows(r.joint_q, i, rows));
  out.joint_v = LazyArray(sample_rows(r.joint_v, i, rows));
  out.diverged = r.diverged.attr("__getitem__")(i).cast<bool>();
  out.unconverged_steps = r.unconverged_steps.attr("__getitem__")(i).cast<std::int64_t>();
  out.elapsed_seconds = r.elapsed_seconds;
  out.scalar_first = r.scalar_first;
  if (r.error.pending()) {  // made with its batch's, on the first read of either (r's Python object kept alive)
    const py::object batch = py::cast(&r, py::return_value_policy::reference);
    out.error = LazyError(std::function<py::object()>([batch, i, rows] {
      return sample_error(batch_result_error(batch.cast<const BatchSceneResult&>()), i, rows);
    }));
  } else {
    out.error = sample_error(batch_result_error(r), i, rows);
  }
  return out;
}

// result.body(key): one body's columns, (N, n, ...) arrays (BodyRecords)
py::object batch_body(const BatchSceneResult& r, py::handle key) {
  BodyColumnsSource source;
  source.body_names = r.body_names;
  source.wheel_bodies = r.wheel_bodies;
  const auto column = [&r](const char* name) -> py::object { return batch_column(r, name); };
  source.t = column("t");
  source.p_W = column("p_W");
  source.q_WB = column("q_WB");
  source.v_W = column("v_W");
  source.w_B = column("w_B");
  source.mass = column("mass");
  source.pivot_reaction_W = column("pivot_reaction_W");
  source.angular_momentum_O_W = column("angular_momentum_O_W");
  source.mass_flow_energy = column("mass_flow_energy");
  source.wheel_speed = r.wheel_speed;
  source.motor_work = r.motor_work;
  source.scalar_first = r.scalar_first;
  return body_records(source, key);
}

const std::string batch_body_doc = body_method_doc(
    "The records of one body of every sample.",
    "The body's columns of this result's arrays with their sample axis: t (N, n), p_W, v_W, w_B (N, n, 3), q_WB\n"
    "    (N, n, 4), mass (N, n), ...",
    R"doc(Two spheres spun up by 1 and 2 N m for 1 s (I = 0.5 kg m^2) turn at 2 and 4 rad/s:

>>> sphere = rd.RigidBody(1.0, [0.5, 0.5, 0.5])
>>> torques = [[rd.AppliedLoad(torque=(0.0, 0.0, tau))] for tau in (1.0, 2.0)]
>>> res = rd.simulate_batch(sphere, [rd.RigidBodyState()] * 2, dt=0.01, duration=1.0, loads=torques)
>>> spin = res.body(0)
>>> spin.w_B.shape, spin.w_B[:, -1, 2].round(12)
((2, 101, 3), array([2., 4.]))
)doc");

std::string batch_scene_repr(const BatchSceneResult& r) {
  return repr_call("BatchSceneResult", {{"samples", py::int_(r.samples())},
                                        {"records", py::int_(r.records())},
                                        {"body_names", r.body_names},
                                        {"elements", r.elements},
                                        {"diverged", py::int_(count_true(r.diverged))},
                                        {"elapsed_seconds", py::float_(r.elapsed_seconds)}});
}

// ------------------------------------------------------------ arguments

bool is_sequence(py::handle obj) { return py::isinstance<py::list>(obj) || py::isinstance<py::tuple>(obj); }

// threads: None -> every hardware thread; else an int >= 1.
int as_threads(py::handle obj) {
  if (obj.is_none()) return default_thread_count();
  const std::int64_t threads = py_io::as_int(obj, "threads");
  if (threads < 1) py_io::throw_value_error("threads", "None (all cores) or an integer >= 1", std::to_string(threads));
  return static_cast<int>(std::min<std::int64_t>(threads, INT_MAX));
}

// ValueError "<name>: expected <what> (N = <n>, as initial), got <count>".
void require_count(py::ssize_t count, py::ssize_t N, const std::string& name, const std::string& what) {
  if (count != N) {
    py_io::throw_value_error(name, what + " (N = " + std::to_string(N) + ", as initial)", std::to_string(count));
  }
}

// dt: a float [s] (or a pint quantity) for every sample, or an (N,) array of them (empty result: common).
std::vector<double> as_dt(py::handle obj, double& common, py::ssize_t N) {
  const py::object si = py_io::in_si(obj, "s", "dt");
  if (!py::isinstance<py::array>(si) && !is_sequence(si)) {
    common = py_io::as_scalar(si, "dt");
    return {};
  }
  const Array a = py_io::as_array(si, "dt");
  if (a.ndim() == 0) {
    common = py_io::as_scalar(si, "dt");
    return {};
  }
  if (a.ndim() != 1) py_io::throw_value_error("dt", "a float [s] or an array of shape (N,)", py_io::describe(si));
  require_count(a.shape(0), N, "dt", "one step [s] per sample");
  common = a.data()[0];  // unused by the runs (each sample has its own); a valid value for checks of the common one
  return std::vector<double>(a.data(), a.data() + a.shape(0));
}

// steps of every sample: `steps`, or `duration` [s] in whole steps of the samples' dt (a float, or an (N,) array whose
// every entry gives the same count: the samples' records share their times' count), as simulate's as_steps.
std::int64_t batch_steps(py::handle steps, py::handle duration, py::handle dt) {
  if (steps.is_none() == duration.is_none() || !steps.is_none()) return as_steps(steps, duration, 1.0);
  const py::object si = py_io::in_si(dt, "s", "dt");
  py::ssize_t n = 1;  // the samples' count as dt gives it (as_dt checks its shape)
  if (is_sequence(si)) n = py::len(si);
  if (py::isinstance<py::array>(si) && py::array(si).ndim() > 0) n = py::array(si).shape(0);
  double common = 0.0;
  const std::vector<double> per_sample = as_dt(si, common, n);
  const std::int64_t count = as_steps(steps, duration, per_sample.empty() ? common : per_sample[0]);
  for (std::size_t i = 1; i < per_sample.size(); ++i) {
    if (as_steps(steps, duration, per_sample[i]) != count) {
      py_io::throw_value_error("duration", "the same number of steps for every sample's dt (or steps= instead)",
                               std::to_string(count) + " steps of dt[0] = " + format_value(per_sample[0]) + " s and " +
                                   std::to_string(as_steps(steps, duration, per_sample[i])) + " of dt[" +
                                   std::to_string(i) + "] = " + format_value(per_sample[i]) + " s");
    }
  }
  return count;
}

// gravity: as simulate's (None/False, True, a 3-vector [m/s²] in W) for every sample, or an (N, 3) array.
std::vector<Eigen::Vector3d> as_batch_gravity(py::handle obj, Eigen::Vector3d& common, py::ssize_t N) {
  if (obj.is_none() || py::isinstance<py::bool_>(obj)) {
    common = as_gravity(obj);
    return {};
  }
  const py::object si = py_io::in_si(obj, "m/s^2", "gravity");
  const Array a = py_io::as_array(si, "gravity");
  if (a.ndim() != 2) {
    common = as_gravity(si);
    return {};
  }
  if (a.shape(1) != 3) py_io::throw_value_error("gravity", "a 3-vector [m/s^2] or an array of shape (N, 3)", py_io::describe(si));
  require_count(a.shape(0), N, "gravity", "one gravity vector per sample");
  std::vector<Eigen::Vector3d> out;
  for (py::ssize_t i = 0; i < N; ++i) out.emplace_back(a.data() + 3 * i);
  return out;
}

// loads: as simulate's (None, an AppliedLoad or a sequence of them) for every sample, or a sequence of N
// schedules (each a sequence of AppliedLoad).
std::vector<std::vector<AppliedLoad>> as_batch_loads(py::handle obj, std::vector<AppliedLoad>& common, py::ssize_t N) {
  const bool per_sample = is_sequence(obj) && py::len(obj) > 0 && is_sequence(obj[py::int_(0)]);
  if (!per_sample) {
    common = as_loads(obj);
    return {};
  }
  require_count(static_cast<py::ssize_t>(py::len(obj)), N, "loads", "one load schedule per sample");
  std::vector<std::vector<AppliedLoad>> out;
  for (py::ssize_t i = 0; i < N; ++i) {
    const py::object item = obj[py::int_(i)];
    const std::string name = "loads[" + std::to_string(i) + "]";
    if (!is_sequence(item)) py_io::throw_type_error(name, "a list of AppliedLoad (one schedule per sample)", item);
    out.push_back(as_loads(item, name));
  }
  return out;
}

// The models: one (shared) or a sequence of N of the kind of the first ("model[i]").
template <class Model>
std::vector<Model> as_models(py::handle model, const char* kind, py::ssize_t N) {
  if (!is_sequence(model)) return {model.cast<const Model&>()};
  require_count(static_cast<py::ssize_t>(py::len(model)), N, "model", std::string("one ") + kind + " per sample");
  std::vector<Model> out;
  for (py::ssize_t i = 0; i < N; ++i) {
    out.push_back(py_io::as_instance<Model>(model[py::int_(i)], "model[" + std::to_string(i) + "]",
                                            std::string("a ") + kind + " (as model[0])"));
  }
  return out;
}

// The dict form of `initial`: exactly `keys`, each (N, width) (width 0: (N,)); returns N.
py::ssize_t check_state_dict(const py::dict& d, std::initializer_list<std::pair<const char*, py::ssize_t>> keys,
                             std::vector<Array>& arrays) {
  std::string listed;
  for (const auto& [key, width] : keys) listed += (listed.empty() ? "'" : ", '") + std::string(key) + "'";
  bool same = d.size() == keys.size();
  for (const auto& [key, width] : keys) same = same && d.contains(key);
  if (!same) {
    std::string given;
    for (const auto& item : d) given += (given.empty() ? "'" : ", '") + py::str(item.first).cast<std::string>() + "'";
    py_io::throw_value_error("initial", "a dict with the keys " + listed, "keys " + given);
  }
  py::ssize_t N = -1;
  for (const auto& [key, width] : keys) {
    const std::string name = std::string("initial['") + key + "']";
    Array a = py_io::as_array(d[key], name);
    const std::string shape = width == 0 ? "(N,)" : "(N, " + std::to_string(width) + ")";
    const bool ok = width == 0 ? a.ndim() == 1 : a.ndim() == 2 && a.shape(1) == width;
    if (!ok) py_io::throw_value_error(name, "an array of shape " + shape, py_io::describe(d[key]));
    if (N < 0) {
      N = a.shape(0);
    } else if (a.shape(0) != N) {
      py_io::throw_value_error(name, "an array of shape " + shape + " with N = " + std::to_string(N) + " (as initial['" +
                                         keys.begin()->first + "'])",
                               py_io::describe(d[key]));
    }
    arrays.push_back(std::move(a));
  }
  return N;
}

std::vector<RigidBodyState> states_from_dict(const py::dict& d, bool scalar_first) {
  std::vector<Array> a;
  const py::ssize_t N = check_state_dict(d, {{"p_W", 3}, {"q_WB", 4}, {"v_W", 3}, {"w_B", 3}}, a);
  std::vector<RigidBodyState> out(static_cast<std::size_t>(N));
  for (py::ssize_t i = 0; i < N; ++i) {
    RigidBodyState& s = out[static_cast<std::size_t>(i)];
    s.p_W = Eigen::Vector3d(a[0].data() + 3 * i);
    s.q_WB = py_io::read_quaternion(a[1].data() + 4 * i, scalar_first);
    s.v_W = Eigen::Vector3d(a[2].data() + 3 * i);
    s.w_B = Eigen::Vector3d(a[3].data() + 3 * i);
  }
  return out;
}

std::vector<ParticleState> particle_states_from_dict(const py::dict& d, bool) {
  std::vector<Array> a;
  const py::ssize_t N = check_state_dict(d, {{"p_W", 3}, {"v_W", 3}}, a);
  std::vector<ParticleState> out(static_cast<std::size_t>(N));
  for (py::ssize_t i = 0; i < N; ++i) {
    out[static_cast<std::size_t>(i)].p_W = Eigen::Vector3d(a[0].data() + 3 * i);
    out[static_cast<std::size_t>(i)].v_W = Eigen::Vector3d(a[1].data() + 3 * i);
  }
  return out;
}

std::vector<PlanarBodyState> planar_states_from_dict(const py::dict& d, bool) {
  std::vector<Array> a;
  const py::ssize_t N = check_state_dict(d, {{"p_W", 2}, {"theta", 0}, {"v_W", 2}, {"omega", 0}}, a);
  std::vector<PlanarBodyState> out(static_cast<std::size_t>(N));
  for (py::ssize_t i = 0; i < N; ++i) {
    PlanarBodyState& s = out[static_cast<std::size_t>(i)];
    s.p_W = Eigen::Vector2d(a[0].data() + 2 * i);
    s.theta = a[1].data()[i];
    s.v_W = Eigen::Vector2d(a[2].data() + 2 * i);
    s.omega = a[3].data()[i];
  }
  return out;
}

// initial for bodies: a sequence of N states of the model's kind, or the dict of stacked arrays.
template <class State, class FromDict>
std::vector<State> as_states(py::handle initial, const char* state_kind, FromDict from_dict, bool scalar_first) {
  const std::string expected = std::string("a sequence of ") + state_kind + " (one per sample) or a dict of stacked arrays";
  if (py::isinstance<py::dict>(initial)) return from_dict(py::reinterpret_borrow<py::dict>(initial), scalar_first);
  if (!is_sequence(initial)) py_io::throw_type_error("initial", expected, initial);
  std::vector<State> out;
  for (py::ssize_t i = 0; i < static_cast<py::ssize_t>(py::len(initial)); ++i) {
    out.push_back(py_io::as_instance<State>(initial[py::int_(i)], "initial[" + std::to_string(i) + "]",
                                            std::string("a ") + state_kind));
  }
  return out;
}

// The number of samples: at least one.
py::ssize_t require_samples(std::size_t n) {
  if (n == 0) py_io::throw_value_error("initial", "at least one sample", "0");
  return static_cast<py::ssize_t>(n);
}

// "sample 0: kinetic_energy from t = 0, ...; sample 3: ..." for the samples (the first five, then their count) whose
// recorded quantities became non-finite while their state stayed finite (overflowed_quantities); "" for none.
template <class Batch>
std::string overflowed_samples(const Batch& b) {
  const auto columns = record_columns(b);
  std::string found;
  std::size_t count = 0;
  for (std::size_t i = 0; i < b.samples; ++i) {
    if (b.diverged[i]) continue;  // its state is not finite: the diverged warning names it
    const std::string quantities =
        non_finite_quantities(columns, b.t, b.samples, b.records, i, static_cast<std::size_t>(b.filled[i]));
    if (quantities.empty()) continue;
    if (++count <= 5) found += (found.empty() ? "" : "; ") + ("sample " + std::to_string(i) + ": ") + quantities;
  }
  if (count > 5) found += "; ...";
  return count == 0 ? found : std::to_string(count) + " of " + std::to_string(b.samples) + " samples: " + found;
}

// The one RuntimeWarning naming the diverged samples (the first five), one naming the samples whose records
// overflowed (`overflowed`: overflowed_samples, "" for none), and one for unconverged solves.
void warn_after_batch(const py::array& diverged, const py::array& unconverged, const std::string& method,
                      const std::string& overflowed) {
  const auto* d = static_cast<const bool*>(diverged.data());
  const py::ssize_t N = diverged.shape(0);
  std::vector<py::ssize_t> bad;
  for (py::ssize_t i = 0; i < N; ++i) {
    if (d[i]) bad.push_back(i);
  }
  if (!bad.empty()) {
    std::string list;
    for (std::size_t k = 0; k < std::min<std::size_t>(bad.size(), 5); ++k) list += (k ? ", " : "") + std::to_string(bad[k]);
    if (bad.size() > 5) list += ", ...";
    const std::string msg = "simulate_batch: " + std::to_string(bad.size()) + " of " + std::to_string(N) +
                            " samples became non-finite (samples " + list + "); their runs stopped there";
    if (PyErr_WarnEx(PyExc_RuntimeWarning, msg.c_str(), 1) != 0) throw py::error_already_set();
  }
  if (!overflowed.empty()) {
    const std::string msg = "simulate_batch: recorded quantities became non-finite while the state stayed finite "
                            "(an overflow) in " + overflowed;
    if (PyErr_WarnEx(PyExc_RuntimeWarning, msg.c_str(), 1) != 0) throw py::error_already_set();
  }
  const auto* u = static_cast<const std::int64_t*>(unconverged.data());
  std::int64_t samples = 0, steps = 0;
  for (py::ssize_t i = 0; i < N; ++i) samples += u[i] > 0, steps += u[i];
  if (samples > 0) {
    const std::string msg = "simulate_batch: the implicit solve of method '" + method + "' did not converge in " +
                            std::to_string(steps) + " steps of " + std::to_string(samples) +
                            " samples (see unconverged_steps; their conservation is lost there); reduce dt";
    if (PyErr_WarnEx(PyExc_RuntimeWarning, msg.c_str(), 1) != 0) throw py::error_already_set();
  }
}

// The options every sample shares.
struct CommonArgs {
  SimulationOptions options;
  bool scalar_first;
  int threads;
  bool simd;
};

CommonArgs as_common(std::int64_t steps, py::handle record_every, py::handle t0, py::handle threads, py::handle simd,
                     py::handle scalar_first) {
  CommonArgs c;
  c.options.steps = steps;
  c.options.record_every = py_io::as_int(record_every, "record_every", 1);
  c.options.t0 = py_io::as_scalar(py_io::in_si(t0, "s", "t0"), "t0");
  c.threads = as_threads(threads);
  c.simd = py_io::as_bool(simd, "simd");
  c.scalar_first = py_io::as_bool(scalar_first, "scalar_first");
  return c;
}

// The values per record of a batch run with options `o` and its error estimate (`error`), for `doubles_per_record`
// values of its own: its two coarse batches, at most as many values a record (they hold the kinematics alone) and
// at most floor(steps / m0) + 1 records each (m0 = lcm(record_every, 4): coarse_options; counted so, as the scene's
// values below, though a long run's are fewer: CommonRecords), and the estimate's own, at most 16
// float64s' worth per record (7 values and a verdict: a 32-byte std::string, then a reference and a bool in Python; a
// scene's 4 more per extra body are within what its coarse batches are counted for: 20 values per body, in at least a
// quarter of the records each).
double with_error_doubles(double doubles_per_record, bool error, const SimulationOptions& o) {
  if (!error) return doubles_per_record;
  const double coarse_records = static_cast<double>(o.steps / common_record_steps(o.record_every) + 1);
  const double records = static_cast<double>(batch_record_count(o.steps, o.record_every));
  return doubles_per_record * (1.0 + 2.0 * coarse_records / records) + 16.0;
}

// ValueError naming record_every when the stacked records of N samples (`doubles_per_record` values each) do not
// fit in the memory available (as simulate refuses a recording larger than it).
void require_batch_memory(py::ssize_t N, const SimulationOptions& o, double doubles_per_record) {
  const double records = static_cast<double>(batch_record_count(o.steps, o.record_every));
  const double bytes = static_cast<double>(N) * records * doubles_per_record * sizeof(double);
  const auto available = static_cast<double>(py_io::available_memory_bytes());
  if (bytes > available) {
    py_io::throw_value_error("record_every",
                             "a batch recording that fits in the available memory (" + format_value(available) + " bytes)",
                             std::to_string(o.record_every) + " (" + std::to_string(N) + " samples of " +
                                 format_value(records) + " records: " + format_value(bytes) +
                                 " bytes; record less often)");
  }
}

// Prefixes the message of the Python exception `error` with "sample <i>: " (its args[0] when a str, else its
// args become that and its class name); a KeyboardInterrupt or SystemExit (not an Exception) stays as raised.
void prefix_sample(py::error_already_set& error, std::size_t i) {
  if (!error.matches(PyExc_Exception)) return;
  const std::string prefix = "sample " + std::to_string(i) + ": ";
  try {
    const py::object value = error.value();
    py::list args(value.attr("args"));
    if (args.empty()) {
      args.append(py::str(prefix + Py_TYPE(value.ptr())->tp_name));
    } else if (py::isinstance<py::str>(args[0])) {
      args[0] = py::str(prefix) + args[0];
    } else {
      args.insert(0, py::str(prefix.substr(0, prefix.size() - 2)));
    }
    value.attr("args") = py::tuple(args);
  } catch (py::error_already_set& e) {  // an exception whose args cannot be set: raised unprefixed
    if (!e.matches(PyExc_Exception)) throw;  // never swallow a KeyboardInterrupt met here
  }
}

// The Python exception of a SampleFailure (a sample's exception that stopped the batch): a Python exception
// (from a PythonForce) or a pybind11 one (its ValueError/TypeError naming a bad return), prefixed with
// "sample <i>: "; any other C++ exception as pybind11 translates it.
[[noreturn]] void raise_sample_failure(const SampleFailure& failure) {
  try {
    std::rethrow_exception(failure.cause());
  } catch (py::error_already_set& e) {
    prefix_sample(e, failure.sample());
    throw;
  } catch (const py::builtin_exception& e) {
    e.set_error();  // the Python exception it stands for, fetched next
    py::error_already_set python;
    prefix_sample(python, failure.sample());
    throw python;
  }
}

// Runs `batch(options)` without the GIL, the calling thread's PythonMonitor reporting progress(samples done)
// and Ctrl-C; raises the monitor's exception if it stopped the batch, also when the batch failed meanwhile
// (a Ctrl-C is never lost to a sample's error), else the batch's exception (a SampleFailure as the Python
// exception of its sample).
template <class Run>
auto run_without_gil(SimulationOptions& o, py::handle progress, Run&& batch) {
  PythonMonitor monitor(progress);
  if (monitor.needed()) o.monitor = [&monitor](std::int64_t samples_done) { return monitor(samples_done); };
  decltype(batch(o)) out;
  try {
    py::gil_scoped_release release;
    out = batch(o);
  } catch (const SampleFailure& failure) {
    if (monitor.failed()) monitor.raise();
    raise_sample_failure(failure);
  } catch (...) {
    if (monitor.failed()) monitor.raise();
    throw;
  }
  if (monitor.failed() || out.interrupted) monitor.raise();  // the records so far are dropped with out
  return out;
}

// ------------------------------------------------------------ the runs

// Each sample's model as its estimate needs it: its scene's order for the method (scene_order.hpp; the loads are
// split at their switches) and the force the estimate cannot see into.
std::vector<SampleModel> sample_models(const std::vector<CompiledScene>& scenes) {
  std::vector<SampleModel> models;
  for (const CompiledScene& scene : scenes) models.push_back({scene_order(scene), opaque_force(scene)});
  return models;
}

// The runs of a batch's samples under options o with the samples' dt: the answer's, and its estimate's at 2h and 4h.
using BatchRun = std::function<BatchSceneSimulation(const SimulationOptions& o, const std::vector<double>& dt)>;

// result.error of the batch `r` that `run` made under o with the samples' dt, of models `models` on `threads` threads:
// made on its first read (LazyBatchError), when the two batches at 2h and 4h (none for models of order 0) run, Ctrl-C
// stopping them (no progress report: progress counted the answer's samples), then each sample's estimate. A batch
// result has no balance check, so its estimate decides no warning; it is made at once only where a sample's scene has
// a force the library cannot see into (a PythonForce, whose calls a later run may not repeat), or where a run at 4h
// refuses its step (4 dt beyond the largest double: the call raises, as the run's own check of dt would). `run` holds
// what it runs, so the estimate made later is the one made at once, bit for bit.
void put_batch_error(BatchSceneResult& r, BatchRun run, SimulationOptions o, std::vector<double> dt,
                     std::vector<SampleModel> models, int threads) {
  o.monitor = nullptr;  // the answer's monitor ended with its run
  const bool opaque =
      std::any_of(models.begin(), models.end(), [](const SampleModel& model) { return !model.opaque.empty(); });
  const auto beyond = [](double sample_dt) { return !std::isfinite(4.0 * sample_dt); };
  const bool at_once = opaque || beyond(o.dt) || std::any_of(dt.begin(), dt.end(), beyond);
  auto d = std::make_shared<DeferredBatchEstimate>();
  d->make = [run = std::move(run), o, dt = std::move(dt), models = std::move(models), threads](
                const BatchColumns& answer, PythonMonitor& monitor) -> std::optional<BatchErrorEstimate> {
    const bool coarse_runs =
        std::any_of(models.begin(), models.end(), [](const SampleModel& model) { return model.order > 0; });
    BatchSceneSimulation coarse[2];  // at 2h and 4h
    for (int k = 0; k < 2 && coarse_runs; ++k) {
      const int factor = 2 << k;
      SimulationOptions options = coarse_options(o, factor);
      options.estimate_records = true;  // what the estimate reads of it
      options.monitor = coarse_monitor(monitor);
      coarse[k] = run(options, coarse_dt(dt, factor));
      if (coarse[k].interrupted) return std::nullopt;
    }
    return batch_error_estimate(answer, batch_columns(coarse[0]), batch_columns(coarse[1]), o, models, threads);
  };
  r.error = LazyBatchError(std::move(d));
  if (at_once) batch_result_error(r);
}

// The elements every sample's one-body scene declares, the same for every sample so that their records have the same
// columns: gravity and loads given per sample declare a UniformGravity (g = 0 included) and a ScheduledLoads (an empty
// schedule included) in every sample's scene; given for all, each only when it acts (as one_body_scene declares them).
// The columns so depend on the arguments' form alone, never on their values, and so do not change when a batch is
// split into chunks (rigiddyn.distributed).
struct OneBodyElementSet {
  bool gravity = false, loads = false;

  std::int64_t count() const { return static_cast<std::int64_t>(gravity) + static_cast<std::int64_t>(loads); }
};

OneBodyElementSet batch_elements(const SimulationOptions& o, const BatchParameters& p) {
  OneBodyElementSet e;
  e.gravity = !p.gravity_W.empty() || !o.gravity_W.isZero(0.0);
  e.loads = !p.loads.empty() || !o.loads.empty();
  return e;
}

// The one-body scenes of a batch of bodies, compiled for o.method: one shared when the body, gravity and loads are
// (sample i is then simulate(body, initial[i], ..., loads, gravity) bitwise), else sample i's own, compiled on
// `threads` threads without the GIL (a scene of bodies and these elements holds no Python object; the error of the
// lowest failing sample is raised, named "sample <i>: ..."); the first sample's alone for the SIMD path (`first_only`:
// it runs the bodies, and the scene gives the records' columns and the method's order).
template <class Model>
std::vector<CompiledScene> one_body_scenes(const std::vector<Model>& bodies, const SimulationOptions& o,
                                           const BatchParameters& p, std::size_t N, OneBodyElementSet elements,
                                           bool first_only, int threads) {
  const bool shared = bodies.size() == 1 && p.gravity_W.empty() && p.loads.empty();
  const std::size_t count = shared || first_only ? 1 : N;
  const auto compile_sample = [&](std::size_t i) {
    try {
      return compile_scene(rigiddyn::one_body_scene(bodies[bodies.size() == 1 ? 0 : i],
                                                    p.gravity_W.empty() ? o.gravity_W : p.gravity_W[i],
                                                    p.loads.empty() ? o.loads : p.loads[i], elements.gravity,
                                                    elements.loads),
                           o.method);
    } catch (const std::invalid_argument& e) {
      if (shared) throw;
      throw std::invalid_argument("sample " + std::to_string(i) + ": " + e.what());
    }
  };
  if (count == 1) return {compile_sample(0)};
  std::vector<std::optional<CompiledScene>> compiled(count);
  const std::size_t chunk = 64;  // samples per task: a compile is microseconds
  {
    py::gil_scoped_release release;
    parallel_for((count + chunk - 1) / chunk, threads, [&](std::size_t k, int) {
      for (std::size_t i = k * chunk; i < std::min(count, (k + 1) * chunk); ++i) compiled[i] = compile_sample(i);
    });
  }
  std::vector<CompiledScene> scenes;
  scenes.reserve(count);
  for (std::optional<CompiledScene>& scene : compiled) scenes.push_back(std::move(*scene));
  return scenes;
}

// The SceneCompatibilityWarnings of the scenes' compiles, each text once (as simulate gives a body's).
void warn_compatibility(const std::vector<CompiledScene>& scenes) {
  const py::object warning = py::module_::import("rigiddyn._core").attr("SceneCompatibilityWarning");
  std::vector<std::string> given;
  for (const CompiledScene& scene : scenes) {
    for (const std::string& w : scene.warnings()) {
      if (std::find(given.begin(), given.end(), w) != given.end()) continue;
      given.push_back(w);
      if (PyErr_WarnEx(warning.ptr(), w.c_str(), 2) != 0) throw py::error_already_set();
    }
  }
}

// The records of one-body rigid scenes (one_body_scene's, declaring `elements`) from the SIMD path's records `b` of RK4
// on the bodies themselves (batch/simd_rigid_body.hpp), equal to the scene path's up to round-off: the state columns
// and T as recorded; the rest from each record as a one-body scene records them (scene/one_body_scene_model.hpp):
// V = −m g_W·p_W (Craig, "Rigid Body Dynamics" slides: work of a constant force), the momenta m v_W,
// p_W × m v_W + R_WB I ω_B and R_WB I ω_B (Newton–Euler about the centre of mass), gravity's work V(t0) − V(t) (RK4
// integrates ṗ = v and gravity's power m g·v with the same weights, so its integrated work is this to round-off), the
// loads' work the rest of the recorded work (Ẇ = (f_W + m g_W)·v_W + τ_B·ω_B), the powers m g_W·v_W and
// f_W·v_W + τ_B·ω_B (the loads constant: the SIMD path refuses time windows).
BatchSceneSimulation simd_scene_records(BatchTrajectory&& b, const std::vector<RigidBody>& bodies,
                                        const SimulationOptions& o, const BatchParameters& p,
                                        OneBodyElementSet elements) {
  const std::int64_t ne = elements.count();
  BatchSceneSimulation out = empty_scene_batch(b.samples, b.records, 1, ne);
  for (std::size_t i = 0; i < b.samples; ++i) {
    const RigidBody& body = bodies[bodies.size() == 1 ? 0 : i];
    const double m = body.mass();
    const Eigen::Vector3d g_W = p.gravity_W.empty() ? o.gravity_W : p.gravity_W[i];
    const ComLoads loads = loads_at(p.loads.empty() ? o.loads : p.loads[i], o.t0);
    double V0 = 0.0;
    for (std::size_t row = 0; row < static_cast<std::size_t>(b.filled[i]); ++row) {
      const std::size_t r = i * b.records + row;
      const Eigen::Vector3d p_W(&b.p_W[3 * r]), v_W(&b.v_W[3 * r]), w_B(&b.w_B[3 * r]);
      Eigen::Quaterniond q_WB;
      q_WB.coeffs() = Eigen::Vector4d(&b.q_WB[4 * r]);
      const double V = -m * g_W.dot(p_W);
      if (row == 0) V0 = V;
      const Eigen::Vector3d L_W = m * v_W, H_C_W = q_WB.normalized() * (body.inertia_com() * w_B);
      const Eigen::Vector3d H_W = p_W.cross(L_W) + H_C_W;
      out.potential_energy[r] = V;
      out.total_energy[r] = b.total_energy[r];
      for (int k = 0; k < 3; ++k) {
        out.linear_momentum_W[3 * r + k] = L_W[k], out.angular_momentum_W[3 * r + k] = H_W[k];
        out.angular_momentum_O_W[3 * r + k] = H_C_W[k], out.pivot_reaction_W[3 * r + k] = 0.0;
      }
      out.mass[r] = m;
      out.mass_flow_energy[r] = 0.0;
      std::size_t column = 0;
      if (elements.gravity) {
        out.work[ne * r + column] = V0 - V;
        out.power[ne * r + column++] = m * g_W.dot(v_W);
      }
      if (elements.loads) {
        out.work[ne * r + column] = b.work[r] - (elements.gravity ? V0 - V : 0.0);
        out.power[ne * r + column] = loads.f_W.dot(v_W) + loads.tau_B.dot(w_B);
      }
    }
  }
  out.t = std::move(b.t);
  out.p_W = std::move(b.p_W);
  out.q_WB = std::move(b.q_WB);
  out.v_W = std::move(b.v_W);
  out.w_B = std::move(b.w_B);
  out.kinetic_energy = std::move(b.kinetic_energy);
  out.filled = std::move(b.filled);
  out.diverged = std::move(b.diverged);
  out.unconverged_steps = std::move(b.unconverged_steps);
  out.elapsed_seconds = b.elapsed_seconds;
  out.interrupted = b.interrupted;
  return out;
}

// The samples of a batch of bodies as its runs read them (the answer's, and later its estimate's): sample i's one-body
// scene (one_body_scenes) from its state, or with `simd` the SIMD path on the rigid bodies under RK4, its records made
// a scene's (simd_scene_records).
template <class Body, class State>
struct BodySamples {
  std::vector<Body> bodies;
  std::vector<State> states;
  BatchParameters parameters;  // the samples' gravity and loads (their dt: run's)
  OneBodyElementSet elements;
  std::vector<CompiledScene> scenes;
  std::vector<std::vector<BodyState>> scene_states;
  bool simd = false;
  int threads = 1;

  // The samples run under o with the samples' dt.
  BatchSceneSimulation run(const SimulationOptions& o, const std::vector<double>& dt) const {
    if constexpr (std::is_same_v<Body, RigidBody>) {
      // the SIMD path (batch/simd_rigid_body.hpp); its own checks name loads (a time window, a torque in W or a
      // force in B)
      if (simd) {
        BatchParameters params = parameters;
        params.dt = dt;
        return simd_scene_records(simulate_batch_simd(bodies, states, o, params, threads), bodies, o, params,
                                  elements);
      }
    }
    SimulationOptions scene_options = o;  // the scenes declare the gravity and the loads
    scene_options.gravity_W.setZero();
    scene_options.loads.clear();
    return simulate_batch(scenes, scene_states, scene_options, dt, threads);
  }
};

// simulate_batch of bodies (BodySamples).
template <class Body, class State, class FromDict>
BatchSceneResult body_batch(py::handle model, py::handle initial, py::handle dt, py::handle method, py::handle loads,
                            py::handle gravity, CommonArgs c, py::handle progress, bool error, const char* kind,
                            const char* state_kind, FromDict from_dict) {
  std::vector<State> states = as_states<State>(initial, state_kind, from_dict, c.scalar_first);
  const py::ssize_t N = require_samples(states.size());
  std::vector<Body> bodies = as_models<Body>(model, kind, N);
  SimulationOptions& o = c.options;
  o.method = method.is_none() ? Method::rk4 : method_from_name(py_io::as_string(method, "method"), "method");
  BatchParameters p;
  p.dt = as_dt(dt, o.dt, N);
  p.gravity_W = as_batch_gravity(gravity, o.gravity_W, N);
  p.loads = as_batch_loads(loads, o.loads, N);
  const bool simd_path = c.simd;
  if (simd_path && !std::is_same_v<Body, RigidBody>) {
    py_io::throw_value_error("simd", std::string("False for a ") + kind + " (the SIMD path runs RigidBody batches)", "True");
  }
  if (simd_path && o.method != Method::rk4) {
    py_io::throw_value_error("simd", "False for method '" + method_info(o.method).name + "' (the SIMD path runs rk4)",
                             "True");
  }
  const OneBodyElementSet elements = batch_elements(o, p);
  // a one-body scene's record: 10 + 20 per body + 2 per element doubles (scene_batch's count)
  require_batch_memory(N, o, with_error_doubles(30.0 + 2.0 * static_cast<double>(elements.count()), error, o));
  std::vector<CompiledScene> scenes =
      one_body_scenes(bodies, o, p, static_cast<std::size_t>(N), elements, simd_path, c.threads);
  warn_compatibility(scenes);
  std::vector<std::vector<BodyState>> scene_states;
  scene_states.reserve(states.size());
  for (const State& state : states) scene_states.push_back({BodyState(state)});
  const auto samples = std::make_shared<const BodySamples<Body, State>>(
      BodySamples<Body, State>{std::move(bodies), std::move(states), p, elements, std::move(scenes),
                               std::move(scene_states), simd_path, c.threads});
  const BatchRun run = [samples](const SimulationOptions& opt, const std::vector<double>& sample_dt) {
    return samples->run(opt, sample_dt);
  };
  BatchSceneSimulation b = run_without_gil(o, progress, [&](const SimulationOptions& opt) { return run(opt, p.dt); });
  const std::string overflowed = overflowed_samples(b);
  const Scene& first = samples->scenes[0].scene();
  BatchSceneResult r = to_batch_scene_result(std::move(b), py::tuple(py::cast(detail::body_names_of(first))),
                                             py::tuple(py::cast(samples->scenes[0].element_types())),
                                             wheel_bodies_of(first), c.scalar_first);
  if (error) put_batch_error(r, run, o, p.dt, sample_models(samples->scenes), c.threads);
  warn_after_batch(r.diverged, r.unconverged_steps, method_info(o.method).name, overflowed);
  return r;
}

// A scene given from Python (Scene or CompiledScene) compiled for `method` (None: a CompiledScene's own, a
// Scene's rk4), as rigiddyn.simulate compiles it (a Scene's SceneCompatibilityWarnings raised here).
CompiledScene compiled_scene(py::handle obj, py::handle method, const std::string& name) {
  if (is_instance<Scene>(obj)) {
    const Method m = method.is_none() ? Method::rk4 : method_from_name(py_io::as_string(method, "method"), "method");
    CompiledScene compiled = compile_scene(obj.cast<const Scene&>(), m);
    const py::object warning = py::module_::import("rigiddyn._core").attr("SceneCompatibilityWarning");
    for (const std::string& w : compiled.warnings()) {
      if (PyErr_WarnEx(warning.ptr(), w.c_str(), 2) != 0) throw py::error_already_set();
    }
    return compiled;
  }
  if (!is_scene(obj)) py_io::throw_type_error(name, "a Scene or CompiledScene (as model[0])", obj);
  const std::string own = obj.attr("method").cast<std::string>();
  if (!method.is_none() && py_io::as_string(method, "method") != own) {
    py_io::throw_value_error("method", "None or '" + own + "' (the method `" + name + "` was compiled for)",
                             "'" + py::str(method).cast<std::string>() + "'");
  }
  // a CompiledScene's C++ model is private to bind_scene.cpp: its scene is compiled again for its method (the
  // same model: compile_scene is a function of the scene and the method; its warnings were given at its compile)
  return compile_scene(obj.attr("scene").cast<Scene>(), method_from_name(own, "method"));
}

// A body state of body `body`'s kind (the alternative of BodyState at its index), else TypeError naming it.
template <std::size_t... K>
BodyState state_of_kind(py::handle obj, std::size_t kind, const std::string& name, std::index_sequence<K...>) {
  std::optional<BodyState> out;
  ((kind == K && is_instance<std::variant_alternative_t<K, BodyState>>(obj)
        ? (void)(out = obj.cast<const std::variant_alternative_t<K, BodyState>&>())
        : void()),
   ...);
  if (!out) py_io::throw_type_error(name, std::string("a ") + state_type_name(kind) + " (the state of its body)", obj);
  return *out;
}

// initial for scenes: N lists of one state per body of the sample's scene.
std::vector<std::vector<BodyState>> as_scene_batch_states(py::handle initial, const std::vector<CompiledScene>& scenes) {
  if (!is_sequence(initial)) {
    py_io::throw_type_error("initial", "a sequence of N lists of body states (one list per sample)", initial);
  }
  std::vector<std::vector<BodyState>> out;
  for (py::ssize_t i = 0; i < static_cast<py::ssize_t>(py::len(initial)); ++i) {
    const std::string name = "initial[" + std::to_string(i) + "]";
    const py::object item = initial[py::int_(i)];
    const Scene& scene = scenes[scenes.size() == 1 ? 0 : static_cast<std::size_t>(i)].scene();
    const std::size_t nb = scene.bodies.size();
    const std::string expected = "a list of " + std::to_string(nb) + " body states (one per body of the scene)";
    if (!is_sequence(item)) py_io::throw_type_error(name, expected, item);
    if (py::len(item) != nb) py_io::throw_value_error(name, expected, std::to_string(py::len(item)) + " states");
    std::vector<BodyState> states;
    for (std::size_t b = 0; b < nb; ++b) {
      states.push_back(state_of_kind(item[py::int_(b)], scene.bodies[b].index(), name + "[" + std::to_string(b) + "]",
                                     std::make_index_sequence<std::variant_size_v<BodyState>>()));
    }
    out.push_back(std::move(states));
  }
  return out;
}

// The samples of a batch of scenes as its runs read them (the answer's, and later its estimate's): sample i's scene
// (or the one shared) from its states.
struct SceneSamples {
  std::vector<CompiledScene> scenes;
  std::vector<std::vector<BodyState>> states;
};

BatchSceneResult scene_batch(py::handle model, py::handle initial, py::handle dt, py::handle method, py::handle loads,
                             py::handle gravity, CommonArgs c, py::handle progress, bool error) {
  if (!loads.is_none()) {
    py_io::throw_value_error("loads", "None for a scene (declare a ScheduledLoads element)", py_io::describe(loads));
  }
  if (!gravity.is_none() && !(py::isinstance<py::bool_>(gravity) && !gravity.cast<bool>())) {
    py_io::throw_value_error("gravity", "None for a scene (declare a UniformGravity element)", py_io::describe(gravity));
  }
  if (c.simd) py_io::throw_value_error("simd", "False for a scene (the SIMD path runs RigidBody batches)", "True");
  if (!is_sequence(initial)) {
    py_io::throw_type_error("initial", "a sequence of N lists of body states (one list per sample)", initial);
  }
  const py::ssize_t N = require_samples(py::len(initial));
  std::vector<CompiledScene> scenes;
  if (is_sequence(model)) {
    require_count(static_cast<py::ssize_t>(py::len(model)), N, "model", "one Scene or CompiledScene per sample");
    for (py::ssize_t i = 0; i < N; ++i) {
      scenes.push_back(compiled_scene(model[py::int_(i)], method, "model[" + std::to_string(i) + "]"));
      if (scenes.back().method() != scenes[0].method()) {
        py_io::throw_value_error("model[" + std::to_string(i) + "]",
                                 "a scene compiled for '" + method_info(scenes[0].method()).name + "' (as model[0])",
                                 "'" + method_info(scenes.back().method()).name + "'");
      }
    }
  } else {
    scenes.push_back(compiled_scene(model, method, "model"));
  }
  std::vector<std::vector<BodyState>> states = as_scene_batch_states(initial, scenes);
  SimulationOptions& o = c.options;
  o.method = scenes[0].method();
  const std::vector<double> dts = as_dt(dt, o.dt, N);
  const Scene& first = scenes[0].scene();
  const double nb = static_cast<double>(first.bodies.size()), ne = static_cast<double>(scenes[0].element_types().size());
  require_batch_memory(N, o, with_error_doubles(10.0 + 20.0 * nb + 2.0 * ne, error, o));
  py::tuple body_names = py::tuple(py::cast(detail::body_names_of(first)));
  py::tuple elements = py::tuple(py::cast(scenes[0].element_types()));
  py::tuple wheel_bodies = wheel_bodies_of(first);
  const auto samples = std::make_shared<const SceneSamples>(SceneSamples{std::move(scenes), std::move(states)});
  const BatchRun run = [samples, threads = c.threads](const SimulationOptions& opt, const std::vector<double>& dt) {
    return simulate_batch(samples->scenes, samples->states, opt, dt, threads);
  };
  BatchSceneSimulation b = run_without_gil(o, progress, [&](const SimulationOptions& opt) { return run(opt, dts); });
  const std::string overflowed = overflowed_samples(b);
  BatchSceneResult r = to_batch_scene_result(std::move(b), std::move(body_names), std::move(elements),
                                             std::move(wheel_bodies), c.scalar_first);
  if (error) put_batch_error(r, run, o, dts, sample_models(samples->scenes), c.threads);
  warn_after_batch(r.diverged, r.unconverged_steps, method_info(o.method).name, overflowed);
  return r;
}

bool is_scene_model(py::handle model) {
  return is_scene(model) || (is_sequence(model) && py::len(model) > 0 && is_scene(model[py::int_(0)]));
}

// The kind of the model (the first item of a sequence); TypeError naming model otherwise.
py::object model_kind(py::handle model) {
  const py::handle first = is_sequence(model) && py::len(model) > 0 ? py::handle(model[py::int_(0)]) : model;
  for (const char* cls : {"RigidBody", "PlanarBody", "Particle"}) {
    if (py::isinstance(first, py::module_::import("rigiddyn._core").attr(cls))) return py::str(cls);
  }
  py_io::throw_type_error(is_sequence(model) ? "model[0]" : "model",
                          "a RigidBody, PlanarBody, Particle, Scene or CompiledScene, or a list of N of one kind", first);
}

BatchSceneResult simulate_batch_py(py::handle model, py::handle initial, py::handle dt, py::handle steps,
                                   py::handle method, py::handle record_every, py::handle loads, py::handle gravity,
                                   py::handle t0, py::handle threads, py::handle simd, py::handle scalar_first,
                                   py::handle progress, py::handle duration, py::handle error) {
  const CommonArgs c = as_common(batch_steps(steps, duration, dt), record_every, t0, threads, simd, scalar_first);
  const bool estimate = py_io::as_bool(error, "error");
  if (is_scene_model(model)) return scene_batch(model, initial, dt, method, loads, gravity, c, progress, estimate);
  const std::string kind = model_kind(model).cast<std::string>();
  if (kind == "RigidBody") {
    return body_batch<RigidBody, RigidBodyState>(model, initial, dt, method, loads, gravity, c, progress, estimate,
                                                 "RigidBody", "RigidBodyState", &states_from_dict);
  }
  if (kind == "PlanarBody") {
    return body_batch<PlanarBody, PlanarBodyState>(model, initial, dt, method, loads, gravity, c, progress, estimate,
                                                   "PlanarBody", "PlanarBodyState", &planar_states_from_dict);
  }
  return body_batch<Particle, ParticleState>(model, initial, dt, method, loads, gravity, c, progress, estimate, "Particle",
                                             "ParticleState", &particle_states_from_dict);
}

const char* const simulate_batch_doc = "N independent runs of a body or a scene, one per initial state, in parallel.\n"
    R"doc(
Integrated in C++ on `threads` threads with the GIL released. Sample i is exactly
``rigiddyn.simulate(model_i, initial[i], dt_i, steps, method, record_every, loads_i, gravity_i, t0)``: the
records equal N serial simulate calls bitwise, whatever the thread count (the SIMD path: up to round-off).
steps (or duration), record_every, t0, method and scalar_first are shared by every sample, so every sample has
the same record count n. A body runs as its one-body scene, as simulate runs it; gravity or loads given per
sample are declared in every sample's scene (a UniformGravity of g = 0, a ScheduledLoads without a load
included), so that the samples' records have the same columns.

Parameters
----------
model : Particle, PlanarBody, RigidBody, Scene, CompiledScene, sequence of Particle, sequence of PlanarBody, sequence of RigidBody, sequence of Scene or sequence of CompiledScene
    One model shared by every sample, or a list of N of one kind (per-sample mass [kg] and inertia about the
    centre of mass in B [kg m^2]; scenes of the same structure: bodies and elements). A scene with a
    PythonForce runs, slowly: each call takes the GIL, so its samples run one at a time.
initial : list of states, or dict of arrays
    A list of N states of the body's kind (ParticleState, PlanarBodyState, RigidBodyState), or a dict of
    stacked arrays: RigidBody {'p_W': (N, 3) [m] in W, 'q_WB': (N, 4) (x, y, z, w), or (w, x, y, z) with
    scalar_first, 'v_W': (N, 3) [m/s] in W, 'w_B': (N, 3) [rad/s] in B}; Particle {'p_W', 'v_W'}; PlanarBody
    {'p_W': (N, 2) [m], 'theta': (N,) [rad], 'v_W': (N, 2) [m/s], 'omega': (N,) [rad/s]}. A scene: a list of N
    lists of the states of its bodies.
dt : float, array_like, shape (N,), or pint.Quantity
    Step [s] of every sample, or of each.
steps : int, optional
    Number of steps (>= 0) of every sample. Exactly one of steps and duration.
method : str, optional
    A name of methods(); None (the default): 'rk4', or the method the CompiledScenes were compiled for (the same
    for every sample).
record_every : int, default 1
    Record every record_every-th step (>= 1), plus the first and the last.
loads : AppliedLoad, sequence of AppliedLoad, or list of N lists of AppliedLoad, optional
    Bodies: one schedule for every sample, as simulate, or one per sample. A scene takes None (it declares its
    loads as elements).
gravity : None, bool, array_like, shape (3,) or (N, 3), default None
    Bodies: g_W [m/s^2] in W for every sample (None or False: none; True: (0, 0, -9.81)), or one per sample. A
    scene takes None.
t0 : float or pint.Quantity, default 0.0
    Initial time [s] of every sample.
threads : int, optional
    Number of threads, >= 1 (None, the default: every hardware thread, default_thread_count()).
simd : bool, default False
    Run the SIMD path across samples (RigidBody, method 'rk4', constant loads: a force in W and a torque in B
    without time window), eight samples per 512-bit instruction where the CPU has AVX-512F, else four (AVX2) or
    two (SSE2): equal to the scalar path up to round-off, not bitwise.
scalar_first : bool, default False
    Quaternions, read from a dict and recorded, as (w, x, y, z).
progress : callable, optional
    progress(samples_done), called with the GIL from the calling thread once before the samples start and then
    about every 0.05 s; an exception it raises stops every sample and propagates.
duration : float or pint.Quantity, keyword-only, optional
    Length of the runs [s] instead of steps: it must give the same whole number of steps at every sample's dt.
error : bool, keyword-only, default True
    Estimate the global error of every record of every sample (result.error, a GlobalError with a leading sample
    axis) from two more batches at 2 dt and 4 dt (+0.75x the cost, on the same threads, with the GIL released),
    made on the first read of result.error, result[i].error or a pickle (at once where a scene has a PythonForce); a
    batch that is never asked for it costs what error=False costs. Sample i's estimate is the one simulate gives
    for it (result[i].error). False: no estimate (result.error is None).

Returns
-------
BatchSceneResult
    The arrays of SceneResult with a leading sample axis (N, n, ...), and error; result.body(0) reads one body's
    columns as (N, n, ...) arrays (p_W (N, n, 3), q_WB (N, n, 4), ...). A sample whose state becomes non-finite stops alone: diverged[i]
    is True, filled[i] its rows, the rest of its rows NaN (its error rows too, their verdict saying so).

Raises
------
ValueError
    Input errors, before any sample runs, naming the argument: N = 0, mismatched N between model, initial, dt,
    gravity and loads, a wrong dict key or shape, threads < 1, simd for another kind or method, a duration
    giving different step counts. An error of one sample (a bad state, a body running out of mass), after every
    sample has run: "sample <i>: ..." for the lowest such sample.
TypeError
    A model or state of the wrong kind (the message names it).
Exception
    An exception raised by a PythonForce (or its wrong return value) stops every sample within about 0.05 s and
    is raised, its message prefixed "sample <i>: " (the first sample that raised; a KeyboardInterrupt as it is).
KeyboardInterrupt
    Ctrl-C stops every sample within about 0.05 s however long a step takes (the steps under way are finished
    first); no result is kept.

Warns
-----
RuntimeWarning
    One names how many samples diverged and the first few; another the samples whose recorded quantities
    became non-finite although their state stayed finite (an overflow, e.g. a kinetic energy of |v_W| > 1e154
    m/s), each quantity with its first time; another the implicit solves that did not converge.

See Also
--------
simulate, BatchSceneResult, default_thread_count

Examples
--------
Four spins; each sample equals its serial simulate bitwise:

>>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
>>> states = [rd.RigidBodyState(w_B=[1.0, 0.0, 0.1 * i]) for i in range(4)]
>>> res = rd.simulate_batch(body, states, dt=0.01, steps=100, threads=2)
>>> serial = rd.simulate(body, states[2], dt=0.01, steps=100)
>>> res.w_B.shape, np.array_equal(res.w_B[2], serial.w_B)
((4, 101, 1, 3), True)
>>> res.body(0).w_B.shape
(4, 101, 3)

Every record of every sample has its global error estimate (rk4: order 4):

>>> res.error.attitude.shape, res.error.order, np.array_equal(res.error.attitude[2], serial.error.attitude)
((4, 101, 1), 4, True)

Three particles dropped for 1 s under their own gravity fall g t^2 / 2:

>>> zeros = np.zeros((3, 3))
>>> drop = rd.simulate_batch(rd.Particle(1.0), {"p_W": zeros, "v_W": zeros}, dt=0.01, duration=1.0,
...                          gravity=[[0, 0, -1.0], [0, 0, -2.0], [0, 0, -3.0]], record_every=100)
>>> drop.t[0], drop.body(0).p_W[:, -1, 2].round(12)
(array([0., 1.]), array([-0.5, -1. , -1.5]))
)doc";

const char* const batch_scene_result_doc = R"doc(The records of simulate_batch: N samples of n records each.

The arrays of SceneResult with a leading sample axis (nb bodies, ne work columns, nw wheels), read-only: t (N, n)
[s]; p_W, v_W, w_B, pivot_reaction_W, angular_momentum_O_W (N, n, nb, 3); q_WB (N, n, nb, 4); kinetic_energy,
potential_energy, total_energy (N, n) [J]; linear_momentum_W, angular_momentum_W (N, n, 3); mass,
mass_flow_energy (N, n, nb) [kg], [J]; work, power (N, n, ne) [J], [W]; wheel_speed, motor_work (N, n, nw).
body_names and elements label the axes (the first scene's). Frames and units as SceneResult. A diverged
sample's rows after filled[i] are NaN. len(result) is N; result[i] is sample i as a SceneResult (its filled
rows, copies, the same scalar_first); result.body(key) is one body's columns (BodyRecords, arrays (N, n, ...));
pickles.

Parameters
----------
None
    Made by simulate_batch; it has no public constructor.

See Also
--------
simulate_batch, SceneResult, BodyRecords

Examples
--------
Three balls thrown up at 0, 1 and 2 m/s, after 1 s: z = v t - g t^2 / 2:

>>> scene = rd.Scene()
>>> ball = scene.add_body(rd.Particle(1.0), name="ball")
>>> gravity = scene.add(rd.UniformGravity())
>>> res = rd.simulate_batch(scene, [[rd.ParticleState(v_W=[0, 0, v])] for v in (0.0, 1.0, 2.0)], dt=0.01,
...                         steps=100, record_every=100)
>>> res.p_W.shape, res.body_names, res.elements
((3, 2, 1, 3), ('ball',), ('UniformGravity',))
>>> res.p_W[:, -1, 0, 2].round(12)
array([-4.905, -3.905, -2.905])
)doc";

template <class Result>
void def_common(py::class_<Result>& cls, py::object (*sample)(const Result&, py::handle)) {
  cls.def_readonly("diverged", &Result::diverged,
                   "Per sample, True if its state became non-finite and its run stopped there, shape (N,) (bool).")
      .def_readonly("filled", &Result::filled,
                    "Rows filled per sample, shape (N,) (int64): n unless it diverged (its later rows are NaN).")
      .def_readonly("unconverged_steps", &Result::unconverged_steps,
                    "Per sample, steps whose implicit solve stopped at its iteration cap, shape (N,) (int64; 0 for "
                    "explicit methods).")
      .def_readonly("elapsed_seconds", &Result::elapsed_seconds, "Wall time of the whole batch [s].")
      .def_property_readonly(
          "error", [](const Result& r) -> py::typing::Optional<GlobalError> { return batch_result_error(r); },
          "The global error estimate of every record of every sample (GlobalError, arrays (N, n, ...)); None with "
          "simulate_batch(..., error=False). Made on this first read (or a sample's, or a pickle's): two more batches "
          "at 2 dt and 4 dt, +0.75x the batch's cost.")
      .def_readonly("scalar_first", &Result::scalar_first,
                    "True if q_WB's rows are (w, x, y, z): the result of simulate_batch(..., scalar_first=True).")
      .def("__len__", [](const Result& r) { return r.samples(); }, "N, the number of samples")
      .def("__getitem__", sample, py::arg("i"), "sample i's records (negative i counts from the end)");
}

py::object batch_scene_sample_object(const BatchSceneResult& r, py::handle key) {
  return py::cast(batch_scene_sample(r, key));
}

}  // namespace

void bind_batch(py::module_& m) {
  py::class_<BatchSceneResult> scene(m, "BatchSceneResult", batch_scene_result_doc);
  for (std::size_t k = 0; k < scene_column_count; ++k) {
    static const char* const docs[scene_column_count] = {
"Time of each record, shape (N, n) [s].",
        "Each body's centre of mass position in W, shape (N, n, nb, 3) [m].",
        "Each body's attitude q_WB (B to W), shape (N, n, nb, 4), (x, y, z, w) unless scalar_first.",
        "Each body's centre of mass velocity in W, shape (N, n, nb, 3) [m/s].",
        "Each body's angular velocity, in its body frame B, shape (N, n, nb, 3) [rad/s].",
        "Kinetic energy, the sum over the bodies, shape (N, n) [J].",
        "Potential energy, the sum of the elements' potentials, shape (N, n) [J].",
        "Kinetic + potential energy, shape (N, n) [J].",
        "Linear momentum, the sum of m v_W, in W, shape (N, n, 3) [kg m/s].",
        "Angular momentum about W's origin, in W, shape (N, n, 3) [kg m^2/s].",
        "The pivot's force on each body, in W, shape (N, n, nb, 3) [N].",
        "Each body's angular momentum about its pivot (its centre of mass unpinned), in W, shape (N, n, nb, 3) "
        "[kg m^2/s].",
        "Each body's mass, shape (N, n, nb) [kg].",
        "Each element's work since t0, shape (N, n, ne) [J].",
        "Each element's power at the record, shape (N, n, ne) [W].",
        "Each body's mass-flow energy since t0, shape (N, n, nb) [J] (0 for a constant mass)."};
    scene.def_property_readonly(scene_columns[k].name, [k](const BatchSceneResult& r) { return r.arrays[k]; }, docs[k]);
  }
  scene.def_readonly("body_names", &BatchSceneResult::body_names, "The bodies' names, a tuple of nb str.")
      .def_readonly("elements", &BatchSceneResult::elements, "The work columns' class names, a tuple of ne str.")
      .def_readonly("wheel_speed", &BatchSceneResult::wheel_speed,
                    "Each gyrostat wheel's speed relative to its body, shape (N, n, nw) [rad/s] (nw = 0 without a "
                    "gyrostat).")
      .def_readonly("motor_work", &BatchSceneResult::motor_work,
                    "Each wheel's motor work since t0, shape (N, n, nw) [J].")
      .def_readonly("wheel_bodies", &BatchSceneResult::wheel_bodies,
                    "The body index of each wheel, a tuple of nw int.")
      .def_readonly("joint_q", &BatchSceneResult::joint_q,
                    "The trees' configurations q (Scene.add_tree), shape (N, n, nq); nq = 0 without a tree.")
      .def_readonly("joint_v", &BatchSceneResult::joint_v, "The trees' velocities v, shape (N, n, nv).");
  def_common(scene, &batch_scene_sample_object);
  scene.def("body", &batch_body, py::arg("key"), batch_body_doc.c_str());
  scene.def("__repr__", &batch_scene_repr).def(py::pickle(&batch_scene_state, &batch_scene_from_state));

  m.def("simulate_batch", &simulate_batch_py, py::arg("model"), py::arg("initial"), py::arg("dt"),
        py::arg("steps") = py::none(),
        py::arg("method") = py::none(), py::arg("record_every") = 1, py::arg("loads") = py::none(),
        py::arg("gravity") = py::none(), py::arg("t0") = 0.0, py::arg("threads") = py::none(),
        py::arg("simd") = false, py::arg("scalar_first") = false, py::arg("progress") = py::none(), py::kw_only(),
        py::arg("duration") = py::none(), py::arg("error") = true, simulate_batch_doc);
  m.def("default_thread_count", &default_thread_count, R"doc(The number of hardware threads, at least 1.

simulate_batch runs on this many threads when threads=None.

Parameters
----------
None

Returns
-------
int
    The hardware thread count (1 where it is unknown).

See Also
--------
simulate_batch

Examples
--------
>>> rd.default_thread_count() >= 1
True
)doc");
  m.def("vector_instructions", [] { return std::string(vector_instructions_name(vector_instructions())); },
        R"doc(The vector instructions this process's hot kernels run on: 'avx512', 'avx2_fma' or 'portable'.

The N-body pair sum of MutualGravity runs eight pairs per instruction where the CPU and the operating system have
AVX-512F ('avx512'), four with AVX2 and fused multiply-adds where the CPU has those ('avx2_fma'), and two per
instruction otherwise ('portable', the x86-64 baseline the library is built for); the rotation array functions run
their AVX2 blocks on 'avx512' and 'avx2_fma', with the same bits as 'portable'. The paths agree to round-off (the
pair sum per body and component within (n + 24) 2**-53 times the sum of the pair forces' magnitudes of the exact
sum, n the body count); only 'portable' gives the same bits on every machine. The choice is made once per process:
set the environment variable RIGIDDYN_PORTABLE=1 before the first run to force 'portable'. The SIMD batch lanes
(simulate_batch(..., simd=True)) choose their own instructions when the library is loaded.

Parameters
----------
None

Returns
-------
str
    'avx512', 'avx2_fma' or 'portable'.

See Also
--------
MutualGravity, simulate_batch

Examples
--------
>>> rd.vector_instructions() in ("avx512", "avx2_fma", "portable")
True
)doc");
}

}  // namespace rigiddyn::bindings
