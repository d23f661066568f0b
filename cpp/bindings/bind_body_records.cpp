// Python bindings of one body's records in a run (rigiddyn.BodyRecords) and SceneResult.body(key), which gives them:
// the body's columns of the result's (n, nb, ...) arrays as (n, ...) arrays (of a batch's (N, n, nb, ...) arrays as
// (N, n, ...): BatchSceneResult.body, bind_batch.cpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include "bindings.hpp"
#include "body_records.hpp"
#include "numpy_io.hpp"
#include "repr.hpp"
#include "scene_run.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

// One body's records: views of a SceneResult's or BatchSceneResult's arrays (read-only, sharing its memory), or
// copies once unpickled.
struct BodyRecords {
  std::string name;
  py::ssize_t index = 0;
  py::object t, p_W, q_WB, v_W, w_B, mass, pivot_reaction_W, angular_momentum_O_W, mass_flow_energy, wheel_speed,
      motor_work;
  bool scalar_first = false;
};

// The members in pickle order after (name, index), with their number of dimensions
struct RecordsColumn {
  const char* name;
  py::object BodyRecords::*member;
  int ndim;
};
constexpr RecordsColumn records_columns[] = {
    {"t", &BodyRecords::t, 1},
    {"p_W", &BodyRecords::p_W, 2},
    {"q_WB", &BodyRecords::q_WB, 2},
    {"v_W", &BodyRecords::v_W, 2},
    {"w_B", &BodyRecords::w_B, 2},
    {"mass", &BodyRecords::mass, 1},
    {"pivot_reaction_W", &BodyRecords::pivot_reaction_W, 2},
    {"angular_momentum_O_W", &BodyRecords::angular_momentum_O_W, 2},
    {"mass_flow_energy", &BodyRecords::mass_flow_energy, 1},
    {"wheel_speed", &BodyRecords::wheel_speed, 2},
    {"motor_work", &BodyRecords::motor_work, 2},
};
constexpr std::size_t records_column_count = sizeof(records_columns) / sizeof(records_columns[0]);

// The index in [0, nb) of `key`: an int in [-nb, nb) (from the end when negative) or one of the names
py::ssize_t body_index(const py::tuple& names, py::handle key) {
  const auto nb = static_cast<py::ssize_t>(names.size());
  std::string choices;
  for (py::ssize_t b = 0; b < nb; ++b) choices += (b == 0 ? "" : ", ") + py::repr(names[b]).cast<std::string>();
  const std::string expected = "an index in [" + std::to_string(-nb) + ", " + std::to_string(nb) + ") or a name of " +
                               "the result's body_names (" + choices + ")";
  if (py::isinstance<py::str>(key)) {
    for (py::ssize_t b = 0; b < nb; ++b) {
      if (py::object(names[b]).equal(key)) return b;
    }
    py_io::throw_value_error("key", expected, py::repr(key).cast<std::string>());
  }
  if (PyBool_Check(key.ptr()) || !PyIndex_Check(key.ptr())) py_io::throw_type_error("key", expected, key);
  const std::int64_t i = py_io::as_int(key, "key", -nb, nb - 1);  // a Python or numpy integer
  return static_cast<py::ssize_t>(i < 0 ? i + nb : i);
}

// a[:, b] (a[:, :, b] for a batch's, `time_axes` 2): the body's columns of an (n, nb, ...) array, as a view
py::object body_column(py::handle a, py::ssize_t b, int time_axes) {
  const py::object all = py::slice(py::none(), py::none(), py::none());
  return a[time_axes == 1 ? py::tuple(py::make_tuple(all, b)) : py::tuple(py::make_tuple(all, all, b))];
}

// The columns of body b's wheels (wheel_bodies[k] == b) of an (n, nw) or (N, n, nw) array, as a new array (..., nw_b)
py::object wheel_columns(py::handle a, const py::tuple& wheel_bodies, py::ssize_t b) {
  py::list columns;
  for (py::ssize_t k = 0; k < static_cast<py::ssize_t>(wheel_bodies.size()); ++k) {
    if (wheel_bodies[k].cast<py::ssize_t>() == b) columns.append(k);
  }
  const py::array out = py::reinterpret_borrow<py::array>(py::object(a[py::make_tuple(py::ellipsis(), columns)]));
  py_io::set_read_only(out);
  return out;
}

BodyRecords records_of(const SceneResult& r, py::handle key) {
  BodyColumnsSource source;
  source.body_names = r.body_names;
  source.wheel_bodies = r.wheel_bodies;
  source.t = r.t.get();
  source.p_W = r.p_W.get();
  source.q_WB = r.q_WB.get();
  source.v_W = r.v_W.get();
  source.w_B = r.w_B.get();
  source.mass = r.mass.get();
  source.pivot_reaction_W = r.pivot_reaction_W.get();
  source.angular_momentum_O_W = r.angular_momentum_O_W.get();
  source.mass_flow_energy = r.mass_flow_energy.get();
  source.wheel_speed = r.wheel_speed.get();
  source.motor_work = r.motor_work.get();
  source.scalar_first = r.scalar_first;
  return body_records(source, key).cast<BodyRecords>();
}

py::tuple records_state(const BodyRecords& r) {
  py::list state;
  state.append(r.name);
  state.append(r.index);
  for (const RecordsColumn& c : records_columns) state.append(r.*c.member);
  state.append(r.scalar_first);
  return py::tuple(state);
}

BodyRecords records_from_state(const py::tuple& t) {
  if (t.size() != records_column_count + 3) {
    py_io::throw_value_error("BodyRecords pickle", "a tuple of " + std::to_string(records_column_count + 3) + " items",
                             std::to_string(t.size()) + " items");
  }
  BodyRecords r;
  r.name = py_io::as_string(t[0], "BodyRecords pickle name");
  r.index = static_cast<py::ssize_t>(py_io::as_int(t[1], "BodyRecords pickle index", 0));
  const py_io::Array time = py_io::as_array(t[2], "BodyRecords pickle t");
  const int time_axes = time.ndim() == 2 ? 2 : 1;  // a batch's records: (N, n)
  for (std::size_t k = 0; k < records_column_count; ++k) {
    const RecordsColumn& c = records_columns[k];
    py_io::Array a = py_io::as_array(t[2 + k], (std::string("BodyRecords pickle ") + c.name).c_str());
    const int ndim = c.ndim + time_axes - 1;
    if (a.ndim() != ndim || a.shape(0) != time.shape(0) || (time_axes == 2 && a.shape(1) != time.shape(1))) {
      py_io::throw_value_error(std::string("BodyRecords pickle ") + c.name,
                               std::to_string(ndim) + "-D with the shape " + py_io::describe(t[2]) + " of t first",
                               py_io::describe(t[2 + k]));
    }
    py_io::set_read_only(a);
    r.*c.member = a;
  }
  r.scalar_first = py_io::as_bool(t[records_column_count + 2], "BodyRecords pickle scalar_first");
  return r;
}

// |x| of each row of an (n, k) or (N, n, k) array, as a read-only (n,) or (N, n) array minus `offset`; a row beyond
// 1e154 (a diverged run's) gives inf quietly, as the run's own records do
py::object row_norms(py::handle a, double offset) {
  const py::module_ np = py::module_::import("numpy");
  const py::object quiet = np.attr("errstate")("over"_a = "ignore", "invalid"_a = "ignore");
  quiet.attr("__enter__")();
  py::array out;
  try {
    out = np.attr("subtract")(np.attr("linalg").attr("norm")(a, "axis"_a = -1), offset);
  } catch (...) {
    quiet.attr("__exit__")(py::none(), py::none(), py::none());
    throw;
  }
  quiet.attr("__exit__")(py::none(), py::none(), py::none());
  py_io::set_read_only(out);
  return out;
}

// |H_O| = |angular_momentum_O_W| of each record [kg m^2/s]
py::object angular_momentum_norm(const BodyRecords& r) { return row_norms(r.angular_momentum_O_W, 0.0); }

// |q_WB| - 1 of each record: the drift of the integrated quaternion from the unit sphere
py::object quaternion_norm_error(const BodyRecords& r) { return row_norms(r.q_WB, 1.0); }

std::string records_repr(const BodyRecords& r) {
  const py::tuple shape = r.t.attr("shape");
  if (shape.size() == 2) {  // a batch's: the samples' times differ with their dt
    return repr_call("BodyRecords", {{"name", py::str(r.name)}, {"index", py::int_(r.index)}, {"samples", shape[0]},
                                     {"records", shape[1]}});
  }
  const py::ssize_t n = shape[0].cast<py::ssize_t>();
  const py::object span = n == 0 ? py::object(py::list()) : py::object(py::make_tuple(py::float_(r.t[py::int_(0)].cast<double>()), py::float_(r.t[py::int_(-1)].cast<double>())));
  return repr_call("BodyRecords", {{"name", py::str(r.name)}, {"index", py::int_(r.index)}, {"records", py::int_(n)},
                                   {"t", span}});
}

const char* const body_records_doc = R"doc(One body's records of a run: its columns of a SceneResult as (n, ...) arrays.

SceneResult.body(key) gives them (a run of one body: result.body(0)); every array is read-only and shares the
result's memory (the wheels' columns are copies). "W" is the result's scene frame. BatchSceneResult.body(key) gives
a batch's: every array with the batch's leading sample axis, t (N, n), p_W (N, n, 3), mass (N, n), ...

Attributes
----------
name : str
    The body's name (an entry of SceneResult.body_names).
index : int
    Its index among the result's bodies, in [0, nb).
t : ndarray, shape (n,)
    Record times [s].
p_W, v_W : ndarray, shape (n, 3)
    Centre of mass position [m] and velocity [m/s] in W.
q_WB : ndarray, shape (n, 4)
    Attitude, (x, y, z, w) unless scalar_first (a particle: the identity; a planar body: Rz(theta)).
w_B : ndarray, shape (n, 3)
    Angular velocity in B [rad/s] (a planar body: (0, 0, omega)).
mass : ndarray, shape (n,)
    Mass [kg].
pivot_reaction_W : ndarray, shape (n, 3)
    The pivot's force on the body in W [N] (0 unpinned).
angular_momentum_O_W : ndarray, shape (n, 3)
    Angular momentum about the pivot (about the centre of mass unpinned), in W [kg m^2/s].
angular_momentum_norm : ndarray, shape (n,)
    |angular_momentum_O_W| [kg m^2/s] (conserved by a free body, a torque-free body about its pivot).
quaternion_norm_error : ndarray, shape (n,)
    |q_WB| - 1: how far the integrated attitude has drifted off the unit sphere (0 for a method that keeps it).
mass_flow_energy : ndarray, shape (n,)
    The body's mass-flow energy since t0 [J] (0 for a constant mass).
wheel_speed, motor_work : ndarray, shape (n, nw)
    Each of the body's gyrostat wheels' speed relative to it [rad/s] and motor work since t0 [J] (nw = 0 for a
    body without wheels).
scalar_first : bool
    True if q_WB's rows are (w, x, y, z).

See Also
--------
SceneResult.body, BatchSceneResult.body, simulate

Examples
--------
A free rigid body turning about its first axis:

)doc"
                                       R"doc(>>> body = rd.RigidBody(mass=2.0, inertia_com=np.diag([1.0, 2.0, 3.0]))
>>> result = rd.simulate(rd.Scene([body]), [rd.RigidBodyState(w_B=(0.5, 0.0, 0.0))], 0.01, steps=100)
>>> records = result.body(0)
>>> records.name, records.q_WB.shape, records.w_B.shape
('body0', (101, 4), (101, 3))
>>> bool(np.allclose(records.q_WB[-1], rd.rotvec_to_quat([0.5, 0.0, 0.0])))
True
)doc";

const std::string body_doc = body_method_doc(
    "The records of one body of the run.",
    "The body's columns of this result's arrays: t (n,), p_W, v_W, w_B (n, 3), q_WB (n, 4), mass (n,), ...",
    R"doc(>>> scene = rd.Scene([rd.Particle(2.0), rd.Particle(1.0)], body_names=["a", "b"])
>>> result = rd.simulate(scene, [rd.ParticleState(), rd.ParticleState(v_W=(1.0, 0.0, 0.0))], 0.1, steps=10)
>>> result.body("b").p_W[-1]
array([1., 0., 0.])
>>> result.body(-1).name
'b'
)doc");

}  // namespace

std::string body_method_doc(const std::string& summary, const std::string& returns, const std::string& examples) {
  return summary + R"doc(

Parameters
----------
key : int or str
    The body's index among the result's bodies, in [-nb, nb) (from the end when negative), or its name (an entry of
    body_names).

Returns
-------
BodyRecords
    )doc" + returns + R"doc(

Raises
------
TypeError
    `key` neither an int nor a str.
ValueError
    An index out of range or a name not in body_names (the message lists the names).

Examples
--------
)doc" + examples;
}

py::object body_records(const BodyColumnsSource& source, py::handle key) {
  BodyRecords out;
  out.index = body_index(source.body_names, key);
  const py::ssize_t b = out.index;
  const int time_axes = py::len(source.t.attr("shape")) == 2 ? 2 : 1;
  out.name = source.body_names[b].cast<std::string>();
  out.t = source.t;
  out.p_W = body_column(source.p_W, b, time_axes);
  out.q_WB = body_column(source.q_WB, b, time_axes);
  out.v_W = body_column(source.v_W, b, time_axes);
  out.w_B = body_column(source.w_B, b, time_axes);
  out.mass = body_column(source.mass, b, time_axes);
  out.pivot_reaction_W = body_column(source.pivot_reaction_W, b, time_axes);
  out.angular_momentum_O_W = body_column(source.angular_momentum_O_W, b, time_axes);
  out.mass_flow_energy = body_column(source.mass_flow_energy, b, time_axes);
  out.wheel_speed = wheel_columns(source.wheel_speed, source.wheel_bodies, b);
  out.motor_work = wheel_columns(source.motor_work, source.wheel_bodies, b);
  out.scalar_first = source.scalar_first;
  return py::cast(std::move(out));
}

void bind_body_records(py::module_& m) {
  py::class_<BodyRecords>(m, "BodyRecords", body_records_doc)
      .def_readonly("name", &BodyRecords::name, "The body's name (an entry of SceneResult.body_names)")
      .def_readonly("index", &BodyRecords::index, "Its index among the result's bodies")
      .def_readonly("t", &BodyRecords::t, "(n,) time [s]")
      .def_readonly("p_W", &BodyRecords::p_W, "(n, 3) centre of mass position in W [m]")
      .def_readonly("q_WB", &BodyRecords::q_WB, "(n, 4) attitude, (x, y, z, w) unless scalar_first")
      .def_readonly("v_W", &BodyRecords::v_W, "(n, 3) centre of mass velocity in W [m/s]")
      .def_readonly("w_B", &BodyRecords::w_B, "(n, 3) angular velocity in B [rad/s]")
      .def_readonly("mass", &BodyRecords::mass, "(n,) mass [kg]")
      .def_readonly("pivot_reaction_W", &BodyRecords::pivot_reaction_W,
                    "(n, 3) the pivot's force on the body, in W [N] (0 unpinned)")
      .def_readonly("angular_momentum_O_W", &BodyRecords::angular_momentum_O_W,
                    "(n, 3) angular momentum about the pivot (about the centre of mass unpinned), in W [kg m^2/s]")
      .def_property_readonly("angular_momentum_norm", &angular_momentum_norm,
                             "(n,) |angular_momentum_O_W| [kg m^2/s] (a new read-only array)")
      .def_property_readonly("quaternion_norm_error", &quaternion_norm_error,
                             "(n,) |q_WB| - 1, the integrated attitude's drift off the unit sphere (a new read-only array)")
      .def_readonly("mass_flow_energy", &BodyRecords::mass_flow_energy, "(n,) mass-flow energy since t0 [J]")
      .def_readonly("wheel_speed", &BodyRecords::wheel_speed,
                    "(n, nw) the speed of each of the body's wheels relative to it [rad/s]")
      .def_readonly("motor_work", &BodyRecords::motor_work, "(n, nw) each of its wheels' motor work since t0 [J]")
      .def_readonly("scalar_first", &BodyRecords::scalar_first, "True if q_WB's rows are (w, x, y, z)")
      .def("__repr__", &records_repr)
      .def(py::pickle(&records_state, &records_from_state));

  py::class_<SceneResult> result = py::reinterpret_borrow<py::class_<SceneResult>>(m.attr("SceneResult"));
  result.def("body", &records_of, "key"_a, body_doc.c_str());
}

}  // namespace rigiddyn::bindings
