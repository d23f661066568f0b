// Python bindings of the frames layer: FrameKinematics, FrameMotion, FrameTree, PointVelocity,
// PointAcceleration and the formula-level functions. Arrays: vectors (3,), matrices (3, 3), float64.
// Every argument is converted by numpy_io (TypeError/ValueError naming it); every result that can
// overflow is checked (RuntimeWarning naming it).
#include <pybind11/stl.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "numpy_io.hpp"
#include "repr.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/frames/frame_kinematics.hpp"
#include "rigiddyn/frames/frame_motion.hpp"
#include "rigiddyn/frames/frame_tree.hpp"
#include "rigiddyn/frames/point_kinematics.hpp"
#include "value_type.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using py_io::as_matrix3;
using py_io::as_matrix3_or_identity;
using py_io::as_scalar;
using py_io::as_string;
using py_io::as_vector3;
using py_io::as_vector3_or_zero;
using py_io::finite_result;
using py_io::to_array;

namespace {

// A Python callable kept alive by C++ copies of a FrameMotion; the GIL is taken to call it and to
// release it, so the motion may be copied and destroyed without the GIL.
std::shared_ptr<py::object> hold(py::object f) {
  return std::shared_ptr<py::object>(new py::object(std::move(f)), [](py::object* p) {
    py::gil_scoped_acquire gil;
    delete p;
  });
}

// The value returned by a user motion: a FrameKinematics or a 6-sequence
// (R_PF, w_PF_P, alpha_PF_P, p_PF_P, v_PF_P, a_PF_P).
FrameKinematics kinematics_from_python(py::handle value) {
  if (is_instance<FrameKinematics>(value)) return value.cast<FrameKinematics>();
  if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) || py::len(value) != 6) {
    py_io::throw_type_error("kinematics_at(t)",
                            "a FrameKinematics or a 6-tuple (R_PF, w_PF_P, alpha_PF_P, p_PF_P, v_PF_P, a_PF_P)", value);
  }
  const py::sequence s = value.cast<py::sequence>();
  FrameKinematics K;
  K.R_PF = as_matrix3(s[0], "kinematics_at(t)[0] (R_PF)");
  K.w_PF_P = as_vector3(s[1], "kinematics_at(t)[1] (w_PF_P)");
  K.alpha_PF_P = as_vector3(s[2], "kinematics_at(t)[2] (alpha_PF_P)");
  K.p_PF_P = as_vector3(s[3], "kinematics_at(t)[3] (p_PF_P)");
  K.v_PF_P = as_vector3(s[4], "kinematics_at(t)[4] (v_PF_P)");
  K.a_PF_P = as_vector3(s[5], "kinematics_at(t)[5] (a_PF_P)");
  return K;
}

// The function of a FrameMotion given by a Python callable (named, so that repr and pickle find the
// callable again through FrameMotion::function().target<PythonKinematics>()).
struct PythonKinematics {
  std::shared_ptr<py::object> f;
  FrameKinematics operator()(double t) const {
    py::gil_scoped_acquire gil;
    const py::object value = (*f)(t);
    try {
      return kinematics_from_python(value);
    } catch (const py::value_error& e) {  // as std::invalid_argument, so the tree names the frame
      throw std::invalid_argument(e.what());
    }
  }
};

FrameMotion motion_from_python(py::handle kinematics_at) {
  return FrameMotion(PythonKinematics{hold(py_io::as_callable(
      kinematics_at, "kinematics_at", "a callable t -> FrameKinematics or 6-tuple (R_PF, w_PF_P, ..., a_PF_P)"))});
}

// Bound arguments of the classes of this layer.
const FrameKinematics& as_kinematics(py::handle obj, const std::string& name) {
  return py_io::as_instance<FrameKinematics>(obj, name, "a FrameKinematics");
}
const FrameMotion& as_motion(py::handle obj) {
  return py_io::as_instance<FrameMotion>(obj, "motion", "a FrameMotion");
}

// The results: every member finite, else a RuntimeWarning naming the quantity.
bool all_finite(const FrameKinematics& K) {
  return K.R_PF.allFinite() && K.w_PF_P.allFinite() && K.alpha_PF_P.allFinite() && K.p_PF_P.allFinite() &&
         K.v_PF_P.allFinite() && K.a_PF_P.allFinite();
}
FrameKinematics checked(const FrameKinematics& K, const char* quantity) {
  py_io::warn_unless_finite(all_finite(K), quantity, "a FrameKinematics with non-finite members");
  return K;
}
PointVelocity checked(const PointVelocity& v, const char* quantity) {
  py_io::warn_unless_finite(v.origin.allFinite() && v.rotational.allFinite() && v.relative.allFinite() &&
                                v.total().allFinite(),
                            quantity, "a PointVelocity with non-finite terms");
  return v;
}
PointAcceleration checked(const PointAcceleration& a, const char* quantity) {
  py_io::warn_unless_finite(a.origin.allFinite() && a.tangential.allFinite() && a.centripetal.allFinite() &&
                                a.relative.allFinite() && a.coriolis.allFinite() && a.total().allFinite(),
                            quantity, "a PointAcceleration with non-finite terms");
  return a;
}

// FrameKinematics: its six fields are its state (pickle, ==, repr).
py::tuple kinematics_state(const FrameKinematics& K) {
  return py::make_tuple(to_array(K.R_PF), to_array(K.w_PF_P), to_array(K.alpha_PF_P), to_array(K.p_PF_P),
                        to_array(K.v_PF_P), to_array(K.a_PF_P));
}
FrameKinematics kinematics_from_state(const py::tuple& state) {
  const py::tuple s = pickled_state(state, 6, "FrameKinematics");
  FrameKinematics K;
  K.R_PF = as_matrix3(s[0], "R_PF");
  K.w_PF_P = as_vector3(s[1], "w_PF_P");
  K.alpha_PF_P = as_vector3(s[2], "alpha_PF_P");
  K.p_PF_P = as_vector3(s[3], "p_PF_P");
  K.v_PF_P = as_vector3(s[4], "v_PF_P");
  K.a_PF_P = as_vector3(s[5], "a_PF_P");
  check_frame_kinematics(K);
  return K;
}
bool same_kinematics(const FrameKinematics& a, const FrameKinematics& b) {
  return same(a.R_PF, b.R_PF) && same(a.w_PF_P, b.w_PF_P) && same(a.alpha_PF_P, b.alpha_PF_P) &&
         same(a.p_PF_P, b.p_PF_P) && same(a.v_PF_P, b.v_PF_P) && same(a.a_PF_P, b.a_PF_P);
}
std::string kinematics_repr(const FrameKinematics& K) {
  return repr_call("FrameKinematics", {{"R_PF", to_array(K.R_PF)},
                                       {"w_PF_P", to_array(K.w_PF_P)},
                                       {"alpha_PF_P", to_array(K.alpha_PF_P)},
                                       {"p_PF_P", to_array(K.p_PF_P)},
                                       {"v_PF_P", to_array(K.v_PF_P)},
                                       {"a_PF_P", to_array(K.a_PF_P)}});
}

// A FrameMotion's parameters, by how it was built: ("fixed", R_PF, p_PF_P), ("constant_rotation",
// axis_P, rate, R_PF0, p_PF_P) or ("function", kinematics_at); TypeError for a C++ function.
py::tuple motion_state(const FrameMotion& motion) {
  const FrameMotion::Function& f = motion.function();
  if (const auto* fixed = f.target<FixedPlacement>()) {
    return py::make_tuple("fixed", to_array(fixed->R_PF), to_array(fixed->p_PF_P));
  }
  if (const auto* rotation = f.target<ConstantRotation>()) {
    return py::make_tuple("constant_rotation", to_array(rotation->axis_P), rotation->rate, to_array(rotation->R_PF0),
                          to_array(rotation->p_PF_P));
  }
  if (const auto* user = f.target<PythonKinematics>()) return py::make_tuple("function", *user->f);
  throw py::type_error("FrameMotion: expected a motion built by FrameMotion(...), FrameMotion.fixed or "
                       "FrameMotion.constant_rotation, got one built in C++ from a function");
}

// The pickled state: motion_state, with a TypeError saying what to do when the callable of a
// general motion cannot be pickled (a lambda or a closure).
py::tuple motion_pickled_state(const FrameMotion& motion) {
  py::tuple state = motion_state(motion);
  if (state[0].cast<std::string>() != "function") return state;
  try {
    py::module_::import("pickle").attr("dumps")(state[1]);
  } catch (py::error_already_set& e) {
    if (py_io::is_interrupt(e)) throw;
    throw py::type_error("FrameMotion: cannot pickle its kinematics_at " + std::string(py::repr(state[1])) + " (" +
                         e.what() + "); pickle saves functions defined at module level (not lambdas or closures), "
                         "or use FrameMotion.fixed / FrameMotion.constant_rotation");
  }
  return state;
}

FrameMotion motion_from_state(const py::tuple& state) {
  if (py::len(state) == 0) throw py::value_error("FrameMotion state: expected a non-empty tuple, got ()");
  const std::string kind = py::str(state[0]);
  if (kind == "fixed") {
    const py::tuple s = pickled_state(state, 3, "FrameMotion.fixed");
    return FrameMotion::fixed(as_matrix3(s[1], "R_PF"), as_vector3(s[2], "p_PF_P"));
  }
  if (kind == "constant_rotation") {
    const py::tuple s = pickled_state(state, 5, "FrameMotion.constant_rotation");
    return FrameMotion::constant_rotation(as_vector3(s[1], "axis_P"), as_scalar(s[2], "rate"),
                                          as_matrix3(s[3], "R_PF0"), as_vector3(s[4], "p_PF_P"));
  }
  if (kind == "function") return motion_from_python(pickled_state(state, 2, "FrameMotion")[1]);
  throw py::value_error("FrameMotion state: expected 'fixed', 'constant_rotation' or 'function' first, got " +
                        std::string(py::repr(state[0])));
}

// Equal when built the same way from exactly equal parameters (a general motion: from equal callables).
bool same_motion(const FrameMotion& a, const FrameMotion& b) {
  const py::tuple x = motion_state(a), y = motion_state(b);
  if (py::len(x) != py::len(y) || !x[0].equal(y[0])) return false;
  const py::module_ np = py::module_::import("numpy");
  for (size_t i = 1; i < py::len(x); ++i) {
    if (!(x[0].cast<std::string>() == "function" ? x[i].equal(y[i]) : np.attr("array_equal")(x[i], y[i]).cast<bool>())) {
      return false;
    }
  }
  return true;
}

std::string motion_repr(const FrameMotion& motion) {
  const py::tuple s = motion_state(motion);
  const std::string kind = s[0].cast<std::string>();
  if (kind == "fixed") return repr_call("FrameMotion.fixed", {{"R_PF", s[1]}, {"p_PF_P", s[2]}});
  if (kind == "constant_rotation") {
    return repr_call("FrameMotion.constant_rotation",
                     {{"axis_P", s[1]}, {"rate", s[2]}, {"R_PF0", s[3]}, {"p_PF_P", s[4]}});
  }
  return repr_call("FrameMotion", {{"kinematics_at", s[1]}});
}

// A FrameTree as (name, parent, motion) triples of its frames but 'world', in the order added.
py::list tree_frames(const FrameTree& tree) {
  py::list frames;
  for (const std::string& name : tree.frame_names()) {
    if (name != FrameTree::world) frames.append(py::make_tuple(name, tree.parent(name), tree.motion(name)));
  }
  return frames;
}

// The tree of such triples: every frame is added under 'world', then moved under its parent, so that
// a parent may come after its child (as after set_parent); the order of the names is kept.
FrameTree tree_from_frames(py::handle frames) {
  FrameTree tree;
  if (frames.is_none()) return tree;
  const char* expected = "a list of (name, parent, FrameMotion) triples";
  if (!py::isinstance<py::sequence>(frames) || py::isinstance<py::str>(frames)) {
    py_io::throw_type_error("frames", expected, frames);
  }
  const py::sequence items = py::reinterpret_borrow<py::sequence>(frames);
  for (size_t i = 0; i < py::len(items); ++i) {
    const py::object item = items[i];
    const std::string name = "frames[" + std::to_string(i) + "]";
    if (!py::isinstance<py::tuple>(item) || py::len(item) != 3) py_io::throw_type_error(name, expected, item);
    tree.add_frame(as_string(item[py::int_(0)], name + "[0]"), FrameTree::world,
                   py_io::as_instance<FrameMotion>(item[py::int_(2)], name + "[2]", "a FrameMotion"));
  }
  for (size_t i = 0; i < py::len(items); ++i) {
    const py::object item = items[i];
    const std::string name = "frames[" + std::to_string(i) + "]";
    const std::string parent = as_string(item[py::int_(1)], name + "[1]");
    if (parent != FrameTree::world) {
      tree.set_parent(as_string(item[py::int_(0)], name + "[0]"), parent, item[py::int_(2)].cast<const FrameMotion&>());
    }
  }
  return tree;
}

bool same_tree(const FrameTree& a, const FrameTree& b) {
  if (a.frame_names() != b.frame_names()) return false;
  for (const std::string& name : a.frame_names()) {
    if (a.parent(name) != b.parent(name) || !same_motion(a.motion(name), b.motion(name))) return false;
  }
  return true;
}

void bind_frame_kinematics(py::module_& m) {
  py::class_<FrameKinematics>(
      m, "FrameKinematics",
      "Frame F relative to frame P at one instant: orientation, angular velocity and acceleration, and the\n"
      "position, velocity and acceleration of F's origin.\n\n"
      "P is the parent of a FrameMotion, or the `relative_to` frame of a FrameTree query. Every vector is\n"
      "expressed in P; SI units. The caller keeps the fields consistent (w, alpha the derivatives of R; v, a\n"
      "those of p): only R_PF being a rotation and finiteness are checked.\n\n"
      "Parameters\n----------\n"
      "R_PF : array_like, shape (3, 3), optional\n"
      "    Orientation of F in P, F coordinates to P coordinates (None: identity).\n"
      "w_PF_P : array_like, shape (3,), optional\n    Angular velocity of F relative to P [rad/s], in P (None: zero).\n"
      "alpha_PF_P : array_like, shape (3,), optional\n"
      "    Angular acceleration of F relative to P [rad/s^2], in P (None: zero).\n"
      "p_PF_P : array_like, shape (3,), optional\n    Position of F's origin relative to P's [m], in P (None: zero).\n"
      "v_PF_P : array_like, shape (3,), optional\n    Velocity of F's origin seen from P [m/s], in P (None: zero).\n"
      "a_PF_P : array_like, shape (3,), optional\n"
      "    Acceleration of F's origin seen from P [m/s^2], in P (None: zero).\n\n"
      "Raises\n------\nValueError\n    A non-rotation R_PF, NaN/Inf or a bad shape (the message names the argument).\n"
      "\n"
      "See Also\n--------\nFrameMotion, FrameTree.kinematics, compose_kinematics, point_velocity\n\n"
      "Examples\n--------\n"
      "F spins at 2 rad/s about its z axis, its origin fixed 1 m along P's x; a point fixed in F 1 m further out\n"
      "moves at w x r_FQ = 2 m/s:\n\n"
      ">>> K_PF = rd.FrameKinematics(w_PF_P=[0.0, 0.0, 2.0], p_PF_P=[1.0, 0.0, 0.0])\n"
      ">>> rd.point_velocity(K_PF, [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]).total\narray([0., 2., 0.])\n\n"
      "Immutable; pickles; == compares every field exactly.")
      .def(py::init([](py::handle R_PF, py::handle w_PF_P, py::handle alpha_PF_P, py::handle p_PF_P,
                       py::handle v_PF_P, py::handle a_PF_P) {
             FrameKinematics K;
             K.R_PF = as_matrix3_or_identity(R_PF, "R_PF");
             K.w_PF_P = as_vector3_or_zero(w_PF_P, "w_PF_P");
             K.alpha_PF_P = as_vector3_or_zero(alpha_PF_P, "alpha_PF_P");
             K.p_PF_P = as_vector3_or_zero(p_PF_P, "p_PF_P");
             K.v_PF_P = as_vector3_or_zero(v_PF_P, "v_PF_P");
             K.a_PF_P = as_vector3_or_zero(a_PF_P, "a_PF_P");
             check_frame_kinematics(K);
             return K;
           }),
           py::arg("R_PF") = py::none(), py::arg("w_PF_P") = py::none(), py::arg("alpha_PF_P") = py::none(),
           py::arg("p_PF_P") = py::none(), py::arg("v_PF_P") = py::none(), py::arg("a_PF_P") = py::none(),
           "Arguments as the attributes (None: identity / zero); see the class. ValueError on a non-rotation R_PF or\n"
           "NaN/Inf.")
      .def_property_readonly("R_PF", [](const FrameKinematics& K) { return to_array(K.R_PF); },
                             "(3, 3) orientation of F in P: maps F coordinates to P coordinates.")
      .def_property_readonly("w_PF_P", [](const FrameKinematics& K) { return to_array(K.w_PF_P); },
                             "(3,) angular velocity of F relative to P [rad/s], expressed in P.")
      .def_property_readonly("alpha_PF_P", [](const FrameKinematics& K) { return to_array(K.alpha_PF_P); },
                             "(3,) angular acceleration of F relative to P (d/dt of w_PF) [rad/s^2], expressed in P.")
      .def_property_readonly("p_PF_P", [](const FrameKinematics& K) { return to_array(K.p_PF_P); },
                             "(3,) position of F's origin relative to P's origin [m], expressed in P.")
      .def_property_readonly("v_PF_P", [](const FrameKinematics& K) { return to_array(K.v_PF_P); },
                             "(3,) velocity of F's origin seen from P [m/s], expressed in P.")
      .def_property_readonly("a_PF_P", [](const FrameKinematics& K) { return to_array(K.a_PF_P); },
                             "(3,) acceleration of F's origin seen from P [m/s^2], expressed in P.")
      .def(
          "__eq__",
          [](const FrameKinematics& a, py::handle b) { return equal_or_not_implemented(a, b, &same_kinematics); },
          py::is_operator(), "Exact equality of every field.")
      .def("__repr__", &kinematics_repr)
      .def(py::pickle(&kinematics_state, &kinematics_from_state));

  m.def(
      "compose_kinematics",
      [](py::handle K_AP, py::handle K_PF) {
        return checked(compose_kinematics(as_kinematics(K_AP, "K_AP"), as_kinematics(K_PF, "K_PF")),
                       "compose_kinematics");
      },
      py::arg("K_AP"), py::arg("K_PF"),
      "Kinematics of F relative to A from those of P relative to A and of F relative to P.\n\n"
      "R_AF = R_AP R_PF; the addition theorem w_AF = w_AP + w_PF; alpha_AF = alpha_AP + alpha_PF + w_AP x w_PF;\n"
      "F's origin by the point formulas of the \"Rigid body kinematics and dynamics\" notes, (4.38), (4.39).\n\n"
      "Parameters\n----------\n"
      "K_AP : FrameKinematics\n    P relative to A, expressed in A.\n"
      "K_PF : FrameKinematics\n    F relative to P, expressed in P.\n\n"
      "Returns\n-------\nFrameKinematics\n    F relative to A, expressed in A.\n\n"
      "Raises\n------\nTypeError\n    An argument not a FrameKinematics (naming it).\n\n"
      "See Also\n--------\nrelative_kinematics, FrameTree.kinematics\n\n"
      "Examples\n--------\n"
      "P spins at 1 rad/s about z; F, 2 m along P's x, spins at 1 rad/s about P's x:\n\n"
      ">>> K_AP = rd.FrameKinematics(w_PF_P=[0.0, 0.0, 1.0])\n"
      ">>> K_PF = rd.FrameKinematics(w_PF_P=[1.0, 0.0, 0.0], p_PF_P=[2.0, 0.0, 0.0])\n"
      ">>> K_AF = rd.compose_kinematics(K_AP, K_PF)\n"
      ">>> K_AF.w_PF_P, K_AF.alpha_PF_P, K_AF.v_PF_P, K_AF.a_PF_P\n"
      "(array([1., 0., 1.]), array([0., 1., 0.]), array([0., 2., 0.]), array([-2.,  0.,  0.]))\n");
  m.def(
      "relative_kinematics",
      [](py::handle K_WA, py::handle K_WF) {
        return checked(relative_kinematics(as_kinematics(K_WA, "K_WA"), as_kinematics(K_WF, "K_WF")),
                       "relative_kinematics");
      },
      py::arg("K_WA"), py::arg("K_WF"),
      "Kinematics of F relative to A from those of A and of F relative to a common frame W.\n\n"
      "The inverse of compose_kinematics: compose_kinematics(K_WA, relative_kinematics(K_WA, K_WF)) is K_WF.\n\n"
      "Parameters\n----------\n"
      "K_WA : FrameKinematics\n    A relative to W, expressed in W.\n"
      "K_WF : FrameKinematics\n    F relative to W, expressed in W.\n\n"
      "Returns\n-------\nFrameKinematics\n    F relative to A, expressed in A.\n\n"
      "Raises\n------\nTypeError\n    An argument not a FrameKinematics (naming it).\n\n"
      "See Also\n--------\ncompose_kinematics, FrameTree.kinematics\n\n"
      "Examples\n--------\n"
      ">>> K_WA = rd.FrameKinematics(w_PF_P=[0.0, 0.0, 1.0])\n"
      ">>> K_AF = rd.FrameKinematics(w_PF_P=[1.0, 0.0, 0.0], p_PF_P=[2.0, 0.0, 0.0])\n"
      ">>> K = rd.relative_kinematics(K_WA, rd.compose_kinematics(K_WA, K_AF))\n"
      ">>> bool(np.allclose(K.w_PF_P, K_AF.w_PF_P) and np.allclose(K.a_PF_P, K_AF.a_PF_P))\nTrue\n");
}

void bind_point_terms(py::module_& m) {
  py::class_<PointVelocity>(
      m, "PointVelocity",
      "Velocity of a point Q moving in a frame F, seen from a frame A, term by term.\n\n"
      "v_AQ = v_AF + w_AF x r_FQ + v_FQ (\"Rigid body kinematics and dynamics\" notes (4.38)): total = origin +\n"
      "rotational + relative. Each (3,) [m/s], all expressed in the same frame E (the query's `expressed_in`;\n"
      "A for the free function point_velocity).\n\n"
      "Parameters\n----------\n"
      "origin : array_like, shape (3,)\n    v_AF_E, velocity of F's origin seen from A [m/s].\n"
      "rotational : array_like, shape (3,)\n    w_AF x r_FQ [m/s].\n"
      "relative : array_like, shape (3,)\n    v_FQ_E, velocity of Q seen from F [m/s].\n\n"
      "See Also\n--------\npoint_velocity, FrameTree.point_velocity, PointAcceleration\n\n"
      "Examples\n--------\n"
      ">>> rd.PointVelocity([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]).total\narray([1., 1., 1.])\n\n"
      "Immutable; pickles; == compares every term exactly.")
      .def(py::init([](py::handle origin, py::handle rotational, py::handle relative) {
             return PointVelocity{as_vector3(origin, "origin"), as_vector3(rotational, "rotational"),
                                  as_vector3(relative, "relative")};
           }),
           py::arg("origin"), py::arg("rotational"), py::arg("relative"),
           "From its terms (3,) [m/s], all in one frame; see the class.")
      .def_property_readonly("origin", [](const PointVelocity& v) { return to_array(v.origin); },
                             "v_AF_E: velocity of F's origin seen from A, expressed in E [m/s]")
      .def_property_readonly("rotational", [](const PointVelocity& v) { return to_array(v.rotational); },
                             "w_AF x r_FQ, r_FQ = position of Q relative to F's origin, expressed in E [m/s]")
      .def_property_readonly("relative", [](const PointVelocity& v) { return to_array(v.relative); },
                             "v_FQ_E: velocity of Q seen from F, expressed in E [m/s]")
      .def_property_readonly("total", [](const PointVelocity& v) { return finite_result(v.total(), "PointVelocity.total"); },
                             "v_AQ_E: velocity of Q seen from A (sum of the terms), expressed in E [m/s]")
      .def(
          "__eq__",
          [](const PointVelocity& a, py::handle b) {
            return equal_or_not_implemented(a, b, [](const PointVelocity& x, const PointVelocity& y) {
              return same(x.origin, y.origin) && same(x.rotational, y.rotational) && same(x.relative, y.relative);
            });
          },
          py::is_operator(), "Exact equality of every term.")
      .def("__repr__",
           [](const PointVelocity& v) {
             return repr_call("PointVelocity", {{"origin", to_array(v.origin)},
                                                {"rotational", to_array(v.rotational)},
                                                {"relative", to_array(v.relative)}});
           })
      .def(py::pickle(
          [](const PointVelocity& v) { return py::make_tuple(to_array(v.origin), to_array(v.rotational), to_array(v.relative)); },
          [](const py::tuple& state) {
            const py::tuple s = pickled_state(state, 3, "PointVelocity");
            return PointVelocity{as_vector3(s[0], "origin"), as_vector3(s[1], "rotational"), as_vector3(s[2], "relative")};
          }));

  py::class_<PointAcceleration>(
      m, "PointAcceleration",
      "Acceleration of a point Q moving in a frame F, seen from a frame A, term by term.\n\n"
      "a_AQ = a_AF + alpha_AF x r_FQ + w_AF x (w_AF x r_FQ) + a_FQ + 2 w_AF x v_FQ (\"Rigid body kinematics and\n"
      "dynamics\" notes (4.39); Craig's \"Rigid Body Dynamics\" slides): total = origin + tangential +\n"
      "centripetal + relative + coriolis. Each (3,) [m/s^2], all expressed in one frame E (the query's\n"
      "`expressed_in`; A for the free function point_acceleration).\n\n"
      "Parameters\n----------\n"
      "origin : array_like, shape (3,)\n    a_AF_E, acceleration of F's origin seen from A [m/s^2].\n"
      "tangential : array_like, shape (3,)\n    alpha_AF x r_FQ [m/s^2].\n"
      "centripetal : array_like, shape (3,)\n    w_AF x (w_AF x r_FQ) [m/s^2].\n"
      "relative : array_like, shape (3,)\n    a_FQ_E, acceleration of Q seen from F [m/s^2].\n"
      "coriolis : array_like, shape (3,)\n    2 w_AF x v_FQ [m/s^2].\n\n"
      "See Also\n--------\npoint_acceleration, FrameTree.point_acceleration, PointVelocity\n\n"
      "Examples\n--------\n"
      ">>> a = rd.PointAcceleration([1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0], [1.0, 0, 0], [0, 1.0, 0])\n"
      ">>> a.total\narray([2., 2., 1.])\n\n"
      "Immutable; pickles; == compares every term exactly.")
      .def(py::init([](py::handle origin, py::handle tangential, py::handle centripetal, py::handle relative,
                       py::handle coriolis) {
             return PointAcceleration{as_vector3(origin, "origin"), as_vector3(tangential, "tangential"),
                                      as_vector3(centripetal, "centripetal"), as_vector3(relative, "relative"),
                                      as_vector3(coriolis, "coriolis")};
           }),
           py::arg("origin"), py::arg("tangential"), py::arg("centripetal"), py::arg("relative"), py::arg("coriolis"),
           "From its terms (3,) [m/s^2], all in one frame; see the class.")
      .def_property_readonly("origin", [](const PointAcceleration& a) { return to_array(a.origin); },
                             "a_AF_E: acceleration of F's origin seen from A, expressed in E [m/s^2]")
      .def_property_readonly("tangential", [](const PointAcceleration& a) { return to_array(a.tangential); },
                             "alpha_AF x r_FQ (r_FQ: Q relative to F's origin), expressed in E [m/s^2]")
      .def_property_readonly("centripetal", [](const PointAcceleration& a) { return to_array(a.centripetal); },
                             "w_AF x (w_AF x r_FQ), expressed in E [m/s^2]")
      .def_property_readonly("relative", [](const PointAcceleration& a) { return to_array(a.relative); },
                             "a_FQ_E: acceleration of Q seen from F, expressed in E [m/s^2]")
      .def_property_readonly("coriolis", [](const PointAcceleration& a) { return to_array(a.coriolis); },
                             "2 w_AF x v_FQ (v_FQ: velocity of Q seen from F), expressed in E [m/s^2]")
      .def_property_readonly("total", [](const PointAcceleration& a) { return finite_result(a.total(), "PointAcceleration.total"); },
                             "a_AQ_E: acceleration of Q seen from A (sum of the terms), expressed in E [m/s^2]")
      .def(
          "__eq__",
          [](const PointAcceleration& a, py::handle b) {
            return equal_or_not_implemented(a, b, [](const PointAcceleration& x, const PointAcceleration& y) {
              return same(x.origin, y.origin) && same(x.tangential, y.tangential) &&
                     same(x.centripetal, y.centripetal) && same(x.relative, y.relative) && same(x.coriolis, y.coriolis);
            });
          },
          py::is_operator(), "Exact equality of every term.")
      .def("__repr__",
           [](const PointAcceleration& a) {
             return repr_call("PointAcceleration", {{"origin", to_array(a.origin)},
                                                    {"tangential", to_array(a.tangential)},
                                                    {"centripetal", to_array(a.centripetal)},
                                                    {"relative", to_array(a.relative)},
                                                    {"coriolis", to_array(a.coriolis)}});
           })
      .def(py::pickle(
          [](const PointAcceleration& a) {
            return py::make_tuple(to_array(a.origin), to_array(a.tangential), to_array(a.centripetal),
                                  to_array(a.relative), to_array(a.coriolis));
          },
          [](const py::tuple& state) {
            const py::tuple s = pickled_state(state, 5, "PointAcceleration");
            return PointAcceleration{as_vector3(s[0], "origin"), as_vector3(s[1], "tangential"),
                                     as_vector3(s[2], "centripetal"), as_vector3(s[3], "relative"),
                                     as_vector3(s[4], "coriolis")};
          }));

  m.def(
      "point_velocity",
      [](py::handle K_AF, py::handle p, py::handle v) {
        return checked(point_velocity(as_kinematics(K_AF, "K_AF"), as_vector3(p, "p_FQ_F"), as_vector3(v, "v_FQ_F")),
                       "point_velocity");
      },
      py::arg("K_AF"), py::arg("p_FQ_F"), py::arg("v_FQ_F"),
      "Velocity of a point Q moving in frame F, seen from frame A, term by term.\n\n"
      "v_AQ = v_AF + w_AF x r_FQ + v_FQ (\"Rigid body kinematics and dynamics\" notes (4.38)), every term\n"
      "expressed in A.\n\n"
      "Parameters\n----------\n"
      "K_AF : FrameKinematics\n    F relative to A, expressed in A.\n"
      "p_FQ_F : array_like, shape (3,)\n    Q's position relative to F's origin [m], expressed in F.\n"
      "v_FQ_F : array_like, shape (3,)\n"
      "    Q's velocity seen from F [m/s], expressed in F (zero for a point fixed in F).\n\n"
      "Returns\n-------\nPointVelocity\n    origin, rotational, relative and total [m/s], expressed in A.\n\n"
      "Raises\n------\nTypeError\n    K_AF not a FrameKinematics.\nValueError\n"
      "    A vector of another shape or non-finite (naming it).\n\n"
      "See Also\n--------\npoint_acceleration, FrameTree.point_velocity\n\n"
      "Examples\n--------\n"
      "A point 1 m from the axis of a frame spinning at 2 rad/s moves at 2 m/s:\n\n"
      ">>> K_AF = rd.FrameKinematics(w_PF_P=[0.0, 0.0, 2.0])\n"
      ">>> rd.point_velocity(K_AF, [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]).total\narray([0., 2., 0.])\n");
  m.def(
      "point_acceleration",
      [](py::handle K_AF, py::handle p, py::handle v, py::handle a) {
        return checked(point_acceleration(as_kinematics(K_AF, "K_AF"), as_vector3(p, "p_FQ_F"),
                                          as_vector3(v, "v_FQ_F"), as_vector3(a, "a_FQ_F")),
                       "point_acceleration");
      },
      py::arg("K_AF"), py::arg("p_FQ_F"), py::arg("v_FQ_F"), py::arg("a_FQ_F"),
      "Acceleration of a point Q moving in frame F, seen from frame A, term by term.\n\n"
      "a_AQ = a_AF + alpha_AF x r_FQ + w_AF x (w_AF x r_FQ) + a_FQ + 2 w_AF x v_FQ (\"Rigid body kinematics and\n"
      "dynamics\" notes (4.39)), every term expressed in A.\n\n"
      "Parameters\n----------\n"
      "K_AF : FrameKinematics\n    F relative to A, expressed in A.\n"
      "p_FQ_F : array_like, shape (3,)\n    Q's position relative to F's origin [m], expressed in F.\n"
      "v_FQ_F : array_like, shape (3,)\n    Q's velocity seen from F [m/s], expressed in F.\n"
      "a_FQ_F : array_like, shape (3,)\n    Q's acceleration seen from F [m/s^2], expressed in F.\n\n"
      "Returns\n-------\nPointAcceleration\n"
      "    origin, tangential, centripetal, relative, coriolis and total [m/s^2], expressed in A.\n\n"
      "Raises\n------\nTypeError\n    K_AF not a FrameKinematics.\nValueError\n"
      "    A vector of another shape or non-finite (naming it).\n\n"
      "See Also\n--------\npoint_velocity, FrameTree.point_acceleration\n\n"
      "Examples\n--------\n"
      "In a frame spinning at 2 rad/s about z: the centripetal term of a point 1 m out, and the Coriolis term of\n"
      "a point at the origin moving at 1 m/s along x:\n\n"
      ">>> K_AF = rd.FrameKinematics(w_PF_P=[0.0, 0.0, 2.0])\n"
      ">>> rd.point_acceleration(K_AF, [1.0, 0, 0], [0, 0, 0], [0, 0, 0]).centripetal\narray([-4.,  0.,  0.])\n"
      ">>> rd.point_acceleration(K_AF, [0, 0, 0], [1.0, 0, 0], [0, 0, 0]).coriolis\narray([0., 4., 0.])\n");
  m.def(
      "transport_derivative",
      [](py::handle w, py::handle u, py::handle du) {
        return finite_result(transport_derivative(as_vector3(w, "w_AB"), as_vector3(u, "u"), as_vector3(du, "du_dt_in_B")),
                             "transport_derivative");
      },
      py::arg("w_AB"), py::arg("u"), py::arg("du_dt_in_B"),
      "Transport theorem: the derivative of a vector seen from A, from its derivative seen from B.\n\n"
      "d^A u/dt = d^B u/dt + w_AB x u (Craig's \"Rigid Body Dynamics\" slides).\n\n"
      "Parameters\n----------\n"
      "w_AB : array_like, shape (3,)\n    Angular velocity of B relative to A [rad/s].\n"
      "u : array_like, shape (3,)\n    The vector (any unit).\n"
      "du_dt_in_B : array_like, shape (3,)\n    Its time derivative seen from B [unit of u / s].\n\n"
      "Returns\n-------\nndarray, shape (3,)\n"
      "    d^A u/dt [unit of u / s]. All vectors are expressed in one (any) frame.\n\n"
      "Raises\n------\nValueError\n    A vector of another shape or non-finite (naming it).\n\n"
      "See Also\n--------\nFrameTree.transport_derivative, point_velocity\n\n"
      "Examples\n--------\n"
      "A vector fixed in B (d^B u/dt = 0) turns with B:\n\n"
      ">>> rd.transport_derivative([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0])\narray([0., 1., 0.])\n");
}

void bind_frame_motion(py::module_& m) {
  py::class_<FrameMotion>(
      m, "FrameMotion",
      "How a frame F moves relative to its parent P: a function of time t [s] giving its FrameKinematics (all\n"
      "vectors expressed in P).\n\n"
      "Built from a Python callable (general motion), or by FrameMotion.fixed or FrameMotion.constant_rotation.\n\n"
      "Parameters\n----------\n"
      "kinematics_at : callable\n"
      "    t -> a FrameKinematics or a 6-tuple (R_PF (3,3), w_PF_P, alpha_PF_P, p_PF_P, v_PF_P, a_PF_P) (each\n"
      "    (3,), expressed in P, SI units). The caller keeps them consistent (w, alpha the derivatives of R; v,\n"
      "    a those of p); the tree checks each value (finite, R_PF a rotation) and raises ValueError naming the\n"
      "    frame.\n\n"
      "Raises\n------\nTypeError\n    kinematics_at not callable.\n\n"
      "See Also\n--------\nFrameTree, FrameKinematics\n\n"
      "Examples\n--------\n"
      "A frame turning at 2 rad/s about P's z axis is a quarter turn on at t = pi/4 s:\n\n"
      ">>> M = rd.FrameMotion.constant_rotation([0.0, 0.0, 1.0], 2.0)\n"
      ">>> bool(np.allclose(M.at(np.pi / 4).R_PF, rd.rot_z(np.pi / 2))), M.at(0.1).w_PF_P\n"
      "(True, array([0., 0., 2.]))\n\n"
      "Immutable; pickles (a general motion when its callable pickles); == compares how it was built.")
      .def(py::init(&motion_from_python), py::arg("kinematics_at"),
           "General motion: kinematics_at(t) returns a FrameKinematics or a 6-tuple\n"
           "(R_PF (3,3), w_PF_P, alpha_PF_P, p_PF_P, v_PF_P, a_PF_P) (each (3,), expressed in P); see the class.")
      .def_static(
          "fixed",
          [](py::handle R_PF, py::handle p_PF_P) {
            return FrameMotion::fixed(as_matrix3_or_identity(R_PF, "R_PF"), as_vector3_or_zero(p_PF_P, "p_PF_P"));
          },
          py::arg("R_PF") = py::none(), py::arg("p_PF_P") = py::none(),
          "F fixed in P: orientation R_PF (3,3) (None: identity), origin at p_PF_P (3,) [m] in P (None: 0).\n\n"
          "Parameters\n----------\nR_PF : array_like, shape (3, 3), optional\n    F coordinates to P coordinates.\n"
          "p_PF_P : array_like, shape (3,), optional\n    F's origin relative to P's [m], in P.\n\n"
          "Returns\n-------\nFrameMotion\n\n"
          "Examples\n--------\n"
          ">>> rd.FrameMotion.fixed(p_PF_P=[1.0, 2.0, 3.0]).at(5.0).p_PF_P\narray([1., 2., 3.])\n")
      .def_static(
          "constant_rotation",
          [](py::handle axis_P, py::handle rate, py::handle R_PF0, py::handle p_PF_P) {
            return FrameMotion::constant_rotation(as_vector3(axis_P, "axis_P"), as_scalar(rate, "rate"),
                                                  as_matrix3_or_identity(R_PF0, "R_PF0"), as_vector3_or_zero(p_PF_P, "p_PF_P"));
          },
          py::arg("axis_P"), py::arg("rate"), py::arg("R_PF0") = py::none(), py::arg("p_PF_P") = py::none(),
          "Simple angular velocity (Craig's \"Rigid Body Dynamics\" slides): F turns at `rate` [rad/s] about\n"
          "axis_P (3,) (expressed in P, any non-zero length) through F's origin, which stays at p_PF_P [m] in P\n"
          "(None: 0). R_PF(t) = exp(hat(rate t axis_P/|axis_P|)) R_PF0 (R_PF0: orientation at t = 0, None:\n"
          "identity).\n\n"
          "Parameters\n----------\naxis_P : array_like, shape (3,)\n    Rotation axis, in P (any non-zero length).\n"
          "rate : float\n    Angular rate [rad/s].\n"
          "R_PF0 : array_like, shape (3, 3), optional\n    R_PF at t = 0 (None: identity).\n"
          "p_PF_P : array_like, shape (3,), optional\n    F's fixed origin relative to P's [m], in P (None: 0).\n\n"
          "Returns\n-------\nFrameMotion\n\n"
          "Examples\n--------\n"
          ">>> M = rd.FrameMotion.constant_rotation([0.0, 0.0, 2.0], 1.0)\n"
          ">>> bool(np.allclose(M.at(np.pi / 2).R_PF, rd.rot_z(np.pi / 2))), M.at(0.0).w_PF_P\n"
          "(True, array([0., 0., 1.]))\n")
      .def(
          "at",
          [](const FrameMotion& motion, py::handle t) {
            const double time = as_scalar(t, "t");
            try {
              return motion.at(time);
            } catch (const std::invalid_argument& e) {  // a user motion's bad value, named as the tree names it
              throw py::value_error(std::string("motion at t=") + format_value(time) + ": " + e.what());
            }
          },
          py::arg("t"),
          "FrameKinematics of F relative to P at time t [s], expressed in P (not checked: the tree checks the values\n"
          "it uses).\n\n"
          "Parameters\n----------\nt : float\n    Time [s].\n\n"
          "Returns\n-------\nFrameKinematics\n    F relative to P, expressed in P.\n\n"
          "Raises\n------\nTypeError\n    A general motion's value neither a FrameKinematics nor a 6-tuple.\n"
          "ValueError\n    A part of that value of another shape (the message names t and the part).\n\n"
          "Examples\n--------\n"
          ">>> rd.FrameMotion.constant_rotation([0.0, 0.0, 1.0], 2.0).at(0.5).w_PF_P\narray([0., 0., 2.])\n")
      .def(
          "__eq__", [](const FrameMotion& a, py::handle b) { return equal_or_not_implemented(a, b, &same_motion); },
          py::is_operator(), "Built the same way from exactly equal parameters (or equal callables).")
      .def("__repr__", &motion_repr)
      .def("__copy__", [](const FrameMotion& motion) { return FrameMotion(motion); })
      .def(
          "__deepcopy__", [](const FrameMotion& motion, py::handle) { return FrameMotion(motion); }, py::arg("memo"),
          "A copy; a general motion's callable is shared, as copy.deepcopy shares functions.")
      .def(py::pickle(&motion_pickled_state, &motion_from_state));
}

void bind_frame_tree(py::module_& m) {
  py::class_<FrameTree>(
      m, "FrameTree",
      "A tree of reference frames rooted at the inertial frame 'world'.\n\n"
      "Each frame is placed relative to its parent by a FrameMotion. Queries relate any frame F (`frame`) to any\n"
      "frame A (`relative_to`) at time t [s], with results expressed in `expressed_in` E. Unknown names,\n"
      "duplicates and cycles raise ValueError. Trees of any depth (every walk is iterative).\n\n"
      "Parameters\n----------\n"
      "frames : list of (str, str, FrameMotion), optional\n"
      "    (name, parent, motion) triples, as repr shows them (None: 'world' only); a parent may come after its\n"
      "    child.\n\n"
      "Raises\n------\nValueError\n    An unknown parent, a duplicate name or a cycle (naming it).\n"
      "TypeError\n    frames not such a list (naming the bad item).\n\n"
      "See Also\n--------\nFrameMotion, FrameKinematics, SceneFrame\n\n"
      "Examples\n--------\n"
      "An arm 2 m out on a table turning at 1 rad/s: its origin moves at 2 m/s, accelerates at 2 m/s^2 inward:\n\n"
      ">>> tree = rd.FrameTree([(\"table\", \"world\", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),\n"
      "...                      (\"arm\", \"table\", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])\n"
      ">>> tree.frame_names()\n['world', 'table', 'arm']\n"
      ">>> tree.point_velocity(\"arm\", [0, 0, 0], [0, 0, 0], \"world\", \"world\", 0.0).total\narray([0., 2., 0.])\n"
      ">>> tree.point_acceleration(\"arm\", [0, 0, 0], [0, 0, 0], [0, 0, 0], \"world\", \"world\", 0.0).total\n"
      "array([-2.,  0.,  0.])\n\n"
      "Mutable (add_frame, set_parent); pickles when its motions do; == compares names, parents and motions.")
      .def(py::init(&tree_from_frames), py::arg("frames") = py::none(),
           "A tree holding 'world' and the frames: a list of (name, parent, FrameMotion) triples (None: none),\n"
           "as repr shows them; a parent may come after its child. See the class.")
      .def(
          "motion", [](const FrameTree& tree, py::handle name) { return tree.motion(as_string(name, "name")); },
          py::arg("name"),
          "The FrameMotion placing frame `name` in its parent ('world': fixed at the identity).\n\n"
          "Parameters\n----------\nname : str\n    A frame of the tree (ValueError otherwise).\n\n"
          "Returns\n-------\nFrameMotion\n\n"
          "Examples\n--------\n"
          ">>> rd.FrameTree().motion(\"world\").at(0.0).p_PF_P\narray([0., 0., 0.])\n")
      .def(
          "__eq__", [](const FrameTree& a, py::handle b) { return equal_or_not_implemented(a, b, &same_tree); },
          py::is_operator(), "Same names in the same order, same parents, equal motions.")
      .def("__repr__", [](const FrameTree& tree) { return repr_call("FrameTree", {{"frames", tree_frames(tree)}}); })
      .def("__copy__", [](const FrameTree& tree) { return FrameTree(tree); })
      .def(
          "__deepcopy__", [](const FrameTree& tree, py::handle) { return FrameTree(tree); }, py::arg("memo"),
          "A copy; the motions' callables are shared, as copy.deepcopy shares functions.")
      .def(py::pickle(
          [](const FrameTree& tree) {
            py::list frames = tree_frames(tree);
            for (const py::handle frame : frames) motion_pickled_state(frame.cast<py::tuple>()[2].cast<const FrameMotion&>());
            return py::make_tuple(frames);
          },
          [](const py::tuple& state) { return tree_from_frames(pickled_state(state, 1, "FrameTree")[0]); }))
      .def_property_readonly_static("world", [](const py::object&) { return FrameTree::world; },
                                    "The root's name, 'world'.")
      .def(
          "add_frame",
          [](FrameTree& tree, py::handle name, py::handle parent, py::handle motion) {
            tree.add_frame(as_string(name, "name"), as_string(parent, "parent"), as_motion(motion));
          },
          py::arg("name"), py::arg("parent"), py::arg("motion"),
          "Adds frame `name` under `parent` (which must exist), placed by `motion`.\n\n"
          "Parameters\n----------\nname : str\n    The new frame's name (not in the tree yet).\n"
          "parent : str\n    An existing frame.\nmotion : FrameMotion\n"
          "    How the new frame moves relative to `parent`.\n\n"
          "Raises\n------\nValueError\n    A duplicate name or an unknown parent (naming it).\n\n"
          "Examples\n--------\n"
          ">>> tree = rd.FrameTree()\n"
          ">>> tree.add_frame(\"table\", \"world\", rd.FrameMotion.fixed(p_PF_P=[0.0, 0.0, 1.0]))\n"
          ">>> tree.frame_names(), tree.parent(\"table\")\n(['world', 'table'], 'world')\n")
      .def(
          "set_parent",
          [](FrameTree& tree, py::handle name, py::handle parent, py::handle motion) {
            tree.set_parent(as_string(name, "name"), as_string(parent, "parent"), as_motion(motion));
          },
          py::arg("name"), py::arg("parent"), py::arg("motion"),
          "Moves frame `name` and its subtree under `parent`, placed by `motion`. ValueError if that would\n"
          "make a cycle (parent is `name` or one of its descendants) or `name` is 'world'.\n\n"
          "Parameters\n----------\nname : str\n    The frame to move.\nparent : str\n    Its new parent.\n"
          "motion : FrameMotion\n    How it moves relative to the new parent.\n\n"
          "Examples\n--------\n"
          ">>> tree = rd.FrameTree([(\"a\", \"world\", rd.FrameMotion.fixed()), (\"b\", \"world\", "
          "rd.FrameMotion.fixed())])\n"
          ">>> tree.set_parent(\"b\", \"a\", rd.FrameMotion.fixed())\n"
          ">>> tree.parent(\"b\")\n'a'\n")
      .def(
          "has_frame", [](const FrameTree& tree, py::handle name) { return tree.has_frame(as_string(name, "name")); },
          py::arg("name"),
          "True if a frame of this name is in the tree.\n\n"
          "Parameters\n----------\nname : str\n\n"
          "Returns\n-------\nbool\n\n"
          "Examples\n--------\n"
          ">>> rd.FrameTree().has_frame(\"world\"), rd.FrameTree().has_frame(\"arm\")\n(True, False)\n")
      .def(
          "parent", [](const FrameTree& tree, py::handle name) { return tree.parent(as_string(name, "name")); },
          py::arg("name"),
          "The parent's name ('' for 'world').\n\n"
          "Parameters\n----------\nname : str\n    A frame of the tree (ValueError otherwise).\n\n"
          "Returns\n-------\nstr\n\n"
          "Examples\n--------\n"
          ">>> rd.FrameTree().parent(\"world\")\n''\n")
      .def("frame_names", &FrameTree::frame_names, "All names: 'world' first, then in the order added.")
      .def(
          "kinematics",
          [](const FrameTree& tree, py::handle frame, py::handle relative_to, py::handle t) {
            return checked(tree.kinematics(as_string(frame, "frame"), as_string(relative_to, "relative_to"),
                                           as_scalar(t, "t")),
                           "FrameTree.kinematics");
          },
          py::arg("frame"), py::arg("relative_to"), py::arg("t"),
          "FrameKinematics of `frame` F relative to `relative_to` A at t, expressed in A.\n\n"
          "Parameters\n----------\n"
          "frame : str\n    F, the frame queried.\n"
          "relative_to : str\n    A, the frame it is seen from.\n"
          "t : float\n    Time [s].\n"
          "\nReturns\n-------\nFrameKinematics\n    F relative to A, every vector expressed in A (SI units).\n"
          "\nRaises\n------\nValueError\n"
          "    An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming\n"
          "    the frame).\n\n"
          "Examples\n--------\n"
          "An arm 2 m out on a table turning at 1 rad/s about z:\n\n"
          ">>> tree = rd.FrameTree([(\"table\", \"world\", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),\n"
          "...                      (\"arm\", \"table\", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])\n"
          ">>> tree.kinematics(\"arm\", \"world\", 0.0).v_PF_P\narray([0., 2., 0.])\n")
      .def(
          "rotation",
          [](const FrameTree& tree, py::handle frame, py::handle relative_to, py::handle t) {
            return finite_result(tree.rotation(as_string(frame, "frame"), as_string(relative_to, "relative_to"),
                                               as_scalar(t, "t")),
                                 "FrameTree.rotation");
          },
          py::arg("frame"), py::arg("relative_to"), py::arg("t"),
          "R_AF (3,3): maps `frame` F coordinates to `relative_to` A coordinates at t.\n\n"
          "Parameters\n----------\n"
          "frame : str\n    F, the frame queried.\n"
          "relative_to : str\n    A, the frame it is seen from.\n"
          "t : float\n    Time [s].\n"
          "\nReturns\n-------\nndarray, shape (3, 3)\n    R_AF.\n"
          "\nRaises\n------\nValueError\n"
          "    An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming\n"
          "    the frame).\n\n"
          "Examples\n--------\n"
          "An arm 2 m out on a table turning at 1 rad/s about z:\n\n"
          ">>> tree = rd.FrameTree([(\"table\", \"world\", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),\n"
          "...                      (\"arm\", \"table\", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])\n"
          ">>> bool(np.allclose(tree.rotation(\"arm\", \"world\", np.pi / 2), rd.rot_z(np.pi / 2)))\nTrue\n")
      .def(
          "angular_velocity",
          [](const FrameTree& tree, py::handle frame, py::handle relative_to, py::handle expressed_in, py::handle t) {
            return finite_result(tree.angular_velocity(as_string(frame, "frame"), as_string(relative_to, "relative_to"),
                                                       as_string(expressed_in, "expressed_in"), as_scalar(t, "t")),
                                 "FrameTree.angular_velocity");
          },
          py::arg("frame"), py::arg("relative_to"), py::arg("expressed_in"), py::arg("t"),
          "w_AF_E (3,) [rad/s]: angular velocity of F relative to A (addition theorem), expressed in E.\n\n"
          "Parameters\n----------\n"
          "frame : str\n    F, the frame queried.\n"
          "relative_to : str\n    A, the frame it is seen from.\n"
          "expressed_in : str\n    E, the frame the result is expressed in.\n"
          "t : float\n    Time [s].\n"
          "\nReturns\n-------\nndarray, shape (3,)\n    w_AF_E [rad/s].\n"
          "\nRaises\n------\nValueError\n"
          "    An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming\n"
          "    the frame).\n\n"
          "Examples\n--------\n"
          "An arm 2 m out on a table turning at 1 rad/s about z:\n\n"
          ">>> tree = rd.FrameTree([(\"table\", \"world\", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),\n"
          "...                      (\"arm\", \"table\", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])\n"
          ">>> tree.angular_velocity(\"arm\", \"world\", \"arm\", 0.0)\narray([0., 0., 1.])\n")
      .def(
          "angular_acceleration",
          [](const FrameTree& tree, py::handle frame, py::handle relative_to, py::handle expressed_in, py::handle t) {
            return finite_result(tree.angular_acceleration(as_string(frame, "frame"),
                                                           as_string(relative_to, "relative_to"),
                                                           as_string(expressed_in, "expressed_in"), as_scalar(t, "t")),
                                 "FrameTree.angular_acceleration");
          },
          py::arg("frame"), py::arg("relative_to"), py::arg("expressed_in"), py::arg("t"),
          "alpha_AF_E (3,) [rad/s^2]: d/dt in A of w_AF, expressed in E (includes the w x w terms; no\n"
          "addition theorem for angular accelerations, Craig's \"Rigid Body Dynamics\" slides).\n\n"
          "Parameters\n----------\n"
          "frame : str\n    F, the frame queried.\n"
          "relative_to : str\n    A, the frame it is seen from.\n"
          "expressed_in : str\n    E, the frame the result is expressed in.\n"
          "t : float\n    Time [s].\n"
          "\nReturns\n-------\nndarray, shape (3,)\n    alpha_AF_E [rad/s^2].\n"
          "\nRaises\n------\nValueError\n"
          "    An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming\n"
          "    the frame).\n\n"
          "Examples\n--------\n"
          "An arm 2 m out on a table turning at 1 rad/s about z:\n\n"
          ">>> tree = rd.FrameTree([(\"table\", \"world\", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),\n"
          "...                      (\"arm\", \"table\", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])\n"
          ">>> tree.angular_acceleration(\"arm\", \"world\", \"world\", 0.0)\narray([0., 0., 0.])\n")
      .def(
          "transport_derivative",
          [](const FrameTree& tree, py::handle u, py::handle du, py::handle from_frame, py::handle to_frame,
             py::handle expressed_in, py::handle t) {
            return finite_result(
                tree.transport_derivative(as_vector3(u, "u_E"), as_vector3(du, "du_B_E"),
                                          as_string(from_frame, "from_frame"), as_string(to_frame, "to_frame"),
                                          as_string(expressed_in, "expressed_in"), as_scalar(t, "t")),
                "FrameTree.transport_derivative");
          },
          py::arg("u_E"), py::arg("du_B_E"), py::arg("from_frame"), py::arg("to_frame"), py::arg("expressed_in"),
          py::arg("t"),
          "Transport theorem (Craig's \"Rigid Body Dynamics\" slides): the derivative of u seen from\n"
          "A = `to_frame`, from its derivative du_B_E seen from B = `from_frame`: du_B_E + w_AB x u_E. u_E,\n"
          "du_B_E and the result (3,) in E.\n\n"
          "Parameters\n----------\n"
          "u_E : array_like, shape (3,)\n    The vector u (any unit), in E.\n"
          "du_B_E : array_like, shape (3,)\n    Its derivative seen from B [unit of u / s], in E.\n"
          "from_frame : str\n    B.\n"
          "to_frame : str\n    A.\n"
          "expressed_in : str\n    E, the frame the result is expressed in.\n"
          "t : float\n    Time [s].\n"
          "\nReturns\n-------\nndarray, shape (3,)\n    The derivative of u seen from A [unit of u / s], in E.\n"
          "\nRaises\n------\nValueError\n"
          "    An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming\n"
          "    the frame).\n\n"
          "Examples\n--------\n"
          "An arm 2 m out on a table turning at 1 rad/s about z:\n\n"
          ">>> tree = rd.FrameTree([(\"table\", \"world\", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),\n"
          "...                      (\"arm\", \"table\", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])\n"
          ">>> tree.transport_derivative([1.0, 0, 0], [0, 0, 0], \"table\", \"world\", \"world\", 0.0)\n"
          "array([0., 1., 0.])\n")
      .def(
          "point_position",
          [](const FrameTree& tree, py::handle frame, py::handle p, py::handle relative_to, py::handle expressed_in,
             py::handle t) {
            return finite_result(tree.point_position(as_string(frame, "frame"), as_vector3(p, "p_FQ_F"),
                                                     as_string(relative_to, "relative_to"),
                                                     as_string(expressed_in, "expressed_in"), as_scalar(t, "t")),
                                 "FrameTree.point_position");
          },
          py::arg("frame"), py::arg("p_FQ_F"), py::arg("relative_to"), py::arg("expressed_in"), py::arg("t"),
          "p_AQ_E (3,) [m]: position of Q relative to A's origin, expressed in E; p_FQ_F (3,): Q relative\n"
          "to F's origin, expressed in F.\n\n"
          "Parameters\n----------\n"
          "frame : str\n    F, the frame queried.\n"
          "p_FQ_F : array_like, shape (3,)\n    Q relative to F's origin [m], in F.\n"
          "relative_to : str\n    A, the frame it is seen from.\n"
          "expressed_in : str\n    E, the frame the result is expressed in.\n"
          "t : float\n    Time [s].\n"
          "\nReturns\n-------\nndarray, shape (3,)\n    p_AQ_E [m].\n"
          "\nRaises\n------\nValueError\n"
          "    An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming\n"
          "    the frame).\n\n"
          "Examples\n--------\n"
          "An arm 2 m out on a table turning at 1 rad/s about z:\n\n"
          ">>> tree = rd.FrameTree([(\"table\", \"world\", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),\n"
          "...                      (\"arm\", \"table\", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])\n"
          ">>> tree.point_position(\"arm\", [1.0, 0, 0], \"world\", \"world\", np.pi / 2).round(12)\n"
          "array([0., 3., 0.])\n")
      .def(
          "point_velocity",
          [](const FrameTree& tree, py::handle frame, py::handle p, py::handle v, py::handle relative_to,
             py::handle expressed_in, py::handle t) {
            return checked(tree.point_velocity(as_string(frame, "frame"), as_vector3(p, "p_FQ_F"),
                                               as_vector3(v, "v_FQ_F"), as_string(relative_to, "relative_to"),
                                               as_string(expressed_in, "expressed_in"), as_scalar(t, "t")),
                           "FrameTree.point_velocity");
          },
          py::arg("frame"), py::arg("p_FQ_F"), py::arg("v_FQ_F"), py::arg("relative_to"), py::arg("expressed_in"),
          py::arg("t"),
          "PointVelocity of Q seen from A, terms expressed in E. Q at p_FQ_F [m] moving with v_FQ_F [m/s] as\n"
          "seen from F (both (3,), expressed in F; zeros for a point fixed in F).\n\n"
          "Parameters\n----------\n"
          "frame : str\n    F, the frame queried.\n"
          "p_FQ_F : array_like, shape (3,)\n    Q relative to F's origin [m], in F.\n"
          "v_FQ_F : array_like, shape (3,)\n    Q's velocity seen from F [m/s], in F.\n"
          "relative_to : str\n    A, the frame it is seen from.\n"
          "expressed_in : str\n    E, the frame the result is expressed in.\n"
          "t : float\n    Time [s].\n"
          "\nReturns\n-------\nPointVelocity\n    origin, rotational, relative and total [m/s], in E.\n"
          "\nRaises\n------\nValueError\n"
          "    An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming\n"
          "    the frame).\n\n"
          "Examples\n--------\n"
          "An arm 2 m out on a table turning at 1 rad/s about z:\n\n"
          ">>> tree = rd.FrameTree([(\"table\", \"world\", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),\n"
          "...                      (\"arm\", \"table\", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])\n"
          ">>> tree.point_velocity(\"arm\", [0, 0, 0], [0, 0, 0], \"world\", \"world\", 0.0).total\n"
          "array([0., 2., 0.])\n")
      .def(
          "point_acceleration",
          [](const FrameTree& tree, py::handle frame, py::handle p, py::handle v, py::handle a, py::handle relative_to,
             py::handle expressed_in, py::handle t) {
            return checked(tree.point_acceleration(as_string(frame, "frame"), as_vector3(p, "p_FQ_F"),
                                                   as_vector3(v, "v_FQ_F"), as_vector3(a, "a_FQ_F"),
                                                   as_string(relative_to, "relative_to"),
                                                   as_string(expressed_in, "expressed_in"), as_scalar(t, "t")),
                           "FrameTree.point_acceleration");
          },
          py::arg("frame"), py::arg("p_FQ_F"), py::arg("v_FQ_F"), py::arg("a_FQ_F"), py::arg("relative_to"),
          py::arg("expressed_in"), py::arg("t"),
          "PointAcceleration of Q seen from A (origin, tangential, centripetal, relative, coriolis, total),\n"
          "terms expressed in E [m/s^2]; a_FQ_F (3,): Q's acceleration seen from F, expressed in F.\n\n"
          "Parameters\n----------\n"
          "frame : str\n    F, the frame queried.\n"
          "p_FQ_F : array_like, shape (3,)\n    Q relative to F's origin [m], in F.\n"
          "v_FQ_F : array_like, shape (3,)\n    Q's velocity seen from F [m/s], in F.\n"
          "a_FQ_F : array_like, shape (3,)\n    Q's acceleration seen from F [m/s^2], in F.\n"
          "relative_to : str\n    A, the frame it is seen from.\n"
          "expressed_in : str\n    E, the frame the result is expressed in.\n"
          "t : float\n    Time [s].\n"
          "\nReturns\n-------\nPointAcceleration\n"
          "    origin, tangential, centripetal, relative, coriolis and total [m/s^2], in E.\n"
          "\nRaises\n------\nValueError\n"
          "    An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming\n"
          "    the frame).\n\n"
          "Examples\n--------\n"
          "An arm 2 m out on a table turning at 1 rad/s about z:\n\n"
          ">>> tree = rd.FrameTree([(\"table\", \"world\", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),\n"
          "...                      (\"arm\", \"table\", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])\n"
          ">>> tree.point_acceleration(\"arm\", [0, 0, 0], [0, 0, 0], [0, 0, 0], \"world\", \"world\", "
          "0.0).origin\n"
          "array([-2.,  0.,  0.])\n");
}

}  // namespace

void bind_frames(py::module_& m) {
  bind_frame_kinematics(m);
  bind_point_terms(m);
  bind_frame_motion(m);
  bind_frame_tree(m);
}

}  // namespace rigiddyn::bindings
