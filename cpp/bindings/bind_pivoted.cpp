// Python bindings of the bodies about a fixed point (models/pivoted_body.hpp, pivoted_planar_body.hpp):
// PivotedBody (the heavy top, the gyroscope), PivotedPlanarBody (the compound pendulum),
// their states, and their forward and inverse dynamics (dynamics/pivoted_body_dynamics.hpp) with the result
// classes. forward_dynamics / inverse_dynamics (bind_bodies.cpp) and simulate / step (bind_dynamics.cpp)
// route a pivoted body here (pivoted.hpp). "W" is the scene frame: W itself (inertial) for these functions.
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "common_args.hpp"
#include "numpy_io.hpp"
#include "pivoted.hpp"
#include "python_run.hpp"
#include "repr.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/dynamics/pivoted_body_dynamics.hpp"
#include "rigiddyn/dynamics/planar_body_dynamics.hpp"
#include "rigiddyn/scene/scene.hpp"
#include "rigiddyn/so3/quaternion.hpp"
#include "scene_run.hpp"
#include "state_args.hpp"
#include "value_type.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using py_io::Array;

namespace {

// ------------------------------------------------------------ conversions

py::object list_of(const Eigen::Vector2d& v) { return py_io::to_array(v); }
py::object list_of(const Eigen::Vector3d& v) { return py_io::to_array(v); }

Array read_only_quaternion(const Eigen::Quaterniond& q, bool scalar_first) {
  Array out = py_io::to_array(q, scalar_first);
  py_io::set_read_only(out);
  return out;
}

const char* euler_form_name(EulerForm form) {
  switch (form) {
    case EulerForm::spherical: return "spherical";
    case EulerForm::principal: return "principal";
    case EulerForm::full: return "full";
  }
  return "full";
}

// A pivoted planar body's gravity: None (none) or an in-plane vector (2,) or (3,) [m/s^2] in W (its z part
// is taken by the plane). True is refused: standard gravity (0, 0, -9.81) is normal to the plane.
Eigen::Vector3d as_in_plane_gravity(py::handle obj) {
  if (obj.is_none()) return Eigen::Vector3d::Zero();
  constexpr const char* expected = "None or an in-plane vector (2,) or (3,) [m/s^2] in W for a PivotedPlanarBody "
                                   "(True's (0, 0, -9.81) is normal to its plane)";
  if (py::isinstance<py::bool_>(obj)) py_io::throw_value_error("gravity", expected, py_io::describe(obj));
  const Array g = py_io::as_array(py_io::in_si(obj, "m/s^2", "gravity"), "gravity");
  if (g.ndim() == 1 && g.shape(0) == 2) {
    const Eigen::Vector2d g2 = py_io::as_vector2(g, "gravity");
    return Eigen::Vector3d(g2.x(), g2.y(), 0.0);
  }
  if (g.ndim() == 1 && g.shape(0) == 3) return py_io::as_vector3(g, "gravity");
  py_io::throw_value_error("gravity", expected, py_io::describe(obj));
}

// A state of the kind `State`, checked (finite, unit quaternion: ValueError naming state.<member>), else
// TypeError naming `state`.
template <class State>
State checked_state_of(py::handle state, const char* model) {
  constexpr const char* type = std::is_same_v<State, PivotedBodyState> ? "PivotedBodyState" : "PivotedPlanarBodyState";
  const State& s = py_io::as_instance<State>(state, "state", std::string("a ") + type + " (the state of a " + model + ")");
  return checked_state(s, "state");
}

// ------------------------------------------------------------ the bodies

std::string pivoted_body_repr(const PivotedBody& b) {
  return repr_call("PivotedBody", {{"body", py::cast(b.body())}, {"p_OC_B", list_of(b.p_OC_B())}, {"p_WO", list_of(b.p_WO())}});
}

PivotedBody make_pivoted_body(py::handle body, py::handle p_OC_B, py::handle p_WO) {
  const RigidBody& b = py_io::as_instance<RigidBody>(body, "body", "a RigidBody (mass and inertia about the centre of mass)");
  return PivotedBody(b, py_io::as_vector3(py_io::in_si(p_OC_B, "m", "p_OC_B"), "p_OC_B"),
                     py_io::as_vector3_or_zero(py_io::in_si(p_WO, "m", "p_WO"), "p_WO"));
}

void bind_pivoted_body(py::module_& m) {
  py::class_<PivotedBody> cls(
      m, "PivotedBody",
          "A rigid body pinned at a point O fixed in the scene frame W (3 DOF): the heavy top, the gyroscope.\n"
          R"doc(
B is the body frame at the centre of mass C, as for RigidBody; C is at p_WO + R_WB p_OC_B. Euler's law is
written about O (K. Craig, "Rigid Body Dynamics" slides: M_O = dH_O/dt) with
inertia_O = I_C + m (|c|^2 1 - c c^T), c = p_OC_B, the parallel-axis theorem with the products of inertia.
digits_lost tells how many decimal digits of I_C the rounding of inertia_O loses (the compile of a scene warns
above 6). Its state is a PivotedBodyState. Immutable; pickles; == compares body, p_OC_B and p_WO.

Parameters
----------
body : RigidBody
    Mass [kg] and inertia_com [kg m^2] about the centre of mass C, in B.
p_OC_B : array_like, shape (3,), or pint.Quantity
    C relative to O, in B [m] (zero allowed: the free rotation about C).
p_WO : array_like, shape (3,), or pint.Quantity, optional
    O in W [m] (None: the origin).

Raises
------
TypeError
    body not a RigidBody.
ValueError
    p_OC_B beyond 15 digits lost (m |c|^2 > 1e15 times the smallest moment of I_C: inertia_O's moment about the
    axis through O and C, I_C's about it, is then rounding noise), or inertia_O no longer positive definite in
    double precision (the message names p_OC_B); a field of another shape or dimension.

See Also
--------
PivotedBodyState, PivotedAcceleration, PivotedTorque, PivotedPlanarBody, forward_dynamics, simulate

Examples
--------
A top of 1 kg, its centre of mass 0.5 m up its axis: the parallel-axis theorem adds m |c|^2 = 0.25 kg m^2 to
the transverse moments:

>>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.1, 0.1, 0.2]), p_OC_B=[0.0, 0.0, 0.5])
>>> top.inertia_O.diagonal()
array([0.35, 0.35, 0.2 ])
>>> rd.forward_dynamics(top, rd.PivotedBodyState(), gravity=True).reaction_W  # upright at rest: the pivot holds m g
array([0.  , 0.  , 9.81])
)doc");
  cls.def(py::init(&make_pivoted_body), py::arg("body"), py::arg("p_OC_B"), py::arg("p_WO") = py::none())
      .def_property_readonly("body", [](const PivotedBody& b) { return b.body(); },
                             "The RigidBody: mass [kg] and inertia about C in B [kg m^2] (a copy).")
      .def_property_readonly("mass", &PivotedBody::mass, "Mass m [kg].")
      .def_property_readonly("inertia_com", [](const PivotedBody& b) { return py_io::read_only(b.inertia_com()); },
                             "Inertia I_C about the centre of mass C, in B, shape (3, 3) [kg m^2].")
      .def_property_readonly("p_OC_B", [](const PivotedBody& b) { return py_io::read_only(b.p_OC_B()); },
                             "The centre of mass C relative to the pivot O, in B, shape (3,) [m].")
      .def_property_readonly("p_WO", [](const PivotedBody& b) { return py_io::read_only(b.p_WO()); },
                             "The pivot O in the scene frame W, shape (3,) [m].")
      .def_property_readonly("inertia_O", [](const PivotedBody& b) { return py_io::read_only(b.inertia_O()); },
                             "Inertia about O in B, I_C + m (|c|^2 1 - c c^T), shape (3, 3) [kg m^2].")
      .def_property_readonly("digits_lost", &PivotedBody::digits_lost,
                             "Decimal digits of I_C lost in inertia_O, max(0, log10(m |c|^2 / smallest moment "
                             "of I_C)), at most 15 (a float).")
      .def_property_readonly("euler_form", [](const PivotedBody& b) { return euler_form_name(b.euler_form()); },
                             "Form of Euler's equations of inertia_O: 'spherical', 'principal' or 'full'.")
      .def("__repr__", &pivoted_body_repr)
      .def(py::pickle([](const PivotedBody& b) { return py::make_tuple(b.body(), list_of(b.p_OC_B()), list_of(b.p_WO())); },
                      [](const py::tuple& t) {
                        pickled_state(t, 3, "PivotedBody");
                        return PivotedBody(py_io::as_instance<RigidBody>(t[0], "PivotedBody pickle body", "a RigidBody"),
                                           unpickled<3>(t[1], "PivotedBody pickle p_OC_B"),
                                           unpickled<3>(t[2], "PivotedBody pickle p_WO"));
                      }));
  def_equality(cls, [](const PivotedBody& a, const PivotedBody& b) {
    return a.mass() == b.mass() && a.inertia_com() == b.inertia_com() && a.p_OC_B() == b.p_OC_B() && a.p_WO() == b.p_WO();
  });

  py::class_<PivotedPlanarBody> planar(
      m, "PivotedPlanarBody",
          "The compound pendulum: a planar body pinned at a point O fixed in the scene frame W (1 DOF).\n"
          R"doc(
It turns about W's z axis, R_WB = Rz(theta). Plane kinetics about O (K. Craig, "Rigid Body Dynamics" slides):
inertia_O_zz alpha = tau_O, inertia_O_zz = inertia_zz + m |c|^2, c = p_OC_B. Its state is a
PivotedPlanarBodyState; its gravity an in-plane vector. Immutable; pickles; == compares every field.

Parameters
----------
mass : float or pint.Quantity
    Mass m [kg], > 0.
inertia_zz : float or pint.Quantity
    Moment of inertia about the z axis through the centre of mass C [kg m^2], > 0.
p_OC_B : array_like, shape (2,), or pint.Quantity
    C relative to O in B's xy plane [m] (zero allowed).
p_WO : array_like, shape (2,), or pint.Quantity, optional
    O in W's xy plane [m] (None: the origin).

Raises
------
ValueError
    mass or inertia_zz not a finite number > 0; inertia_O_zz beyond the double range (the message names
    p_OC_B); a field of another shape or dimension.

See Also
--------
PivotedPlanarBodyState, PivotedPlanarAcceleration, PivotedPlanarTorque, PivotedBody, simulate

Examples
--------
A uniform rod of 2 m and 3 kg pinned at one end: inertia_O_zz = m L^2 / 3 = 4 kg m^2.

>>> rod = rd.PivotedPlanarBody(3.0, 3.0 * 2.0**2 / 12, p_OC_B=[1.0, 0.0])
>>> rod.inertia_O_zz
4.0
)doc");
  planar
      .def(py::init([](py::handle mass, py::handle inertia_zz, py::handle p_OC_B, py::handle p_WO) {
             return PivotedPlanarBody(py_io::as_scalar(py_io::in_si(mass, "kg", "mass"), "mass"),
                                      py_io::as_scalar(py_io::in_si(inertia_zz, "kg*m^2", "inertia_zz"), "inertia_zz"),
                                      py_io::as_vector2(py_io::in_si(p_OC_B, "m", "p_OC_B"), "p_OC_B"),
                                      py_io::as_vector2_or_zero(py_io::in_si(p_WO, "m", "p_WO"), "p_WO"));
           }),
           py::arg("mass"), py::arg("inertia_zz"), py::arg("p_OC_B"), py::arg("p_WO") = py::none())
      .def_property_readonly("mass", &PivotedPlanarBody::mass, "Mass m [kg].")
      .def_property_readonly("inertia_zz", &PivotedPlanarBody::inertia_zz,
                             "Moment of inertia about the z axis through C [kg m^2].")
      .def_property_readonly("inertia_O_zz", &PivotedPlanarBody::inertia_O_zz,
                             "Moment of inertia about the z axis through O, inertia_zz + m |c|^2 [kg m^2].")
      .def_property_readonly("p_OC_B", [](const PivotedPlanarBody& b) { return py_io::read_only(b.p_OC_B()); },
                             "C relative to O in B's xy plane, shape (2,) [m].")
      .def_property_readonly("p_WO", [](const PivotedPlanarBody& b) { return py_io::read_only(b.p_WO()); },
                             "The pivot O in W's xy plane, shape (2,) [m].")
      .def("__repr__",
           [](const PivotedPlanarBody& b) {
             return repr_call("PivotedPlanarBody", {{"mass", py::float_(b.mass())},
                                                    {"inertia_zz", py::float_(b.inertia_zz())},
                                                    {"p_OC_B", list_of(b.p_OC_B())},
                                                    {"p_WO", list_of(b.p_WO())}});
           })
      .def(py::pickle(
          [](const PivotedPlanarBody& b) {
            return py::make_tuple(b.mass(), b.inertia_zz(), list_of(b.p_OC_B()), list_of(b.p_WO()));
          },
          [](const py::tuple& t) {
            pickled_state(t, 4, "PivotedPlanarBody");
            return PivotedPlanarBody(t[0].cast<double>(), t[1].cast<double>(), unpickled<2>(t[2], "PivotedPlanarBody pickle p_OC_B"),
                                     unpickled<2>(t[3], "PivotedPlanarBody pickle p_WO"));
          }));
  def_equality(planar, [](const PivotedPlanarBody& a, const PivotedPlanarBody& b) {
    return a.mass() == b.mass() && a.inertia_zz() == b.inertia_zz() && a.p_OC_B() == b.p_OC_B() && a.p_WO() == b.p_WO();
  });
}

// ------------------------------------------------------------ the states

void bind_pivoted_states(py::module_& m) {
  py::class_<PivotedBodyState> state(
      m, "PivotedBodyState", R"doc(State of a PivotedBody: its attitude and angular velocity.

Fields are assigned whole (``s.w_B = [...]``, converted and checked as the constructor does); the arrays read are
read-only copies. Pickles; == compares every field.

Parameters
----------
q_WB : array_like, shape (4,), optional
    Unit quaternion B to the scene frame W, (x, y, z, w), or (w, x, y, z) with `scalar_first` (None:
    identity); normalised.
w_B : array_like, shape (3,), or pint.Quantity, optional
    Angular velocity of B relative to W, in B [rad/s] (None: zero).
scalar_first : bool, default False
    Read q_WB as (w, x, y, z).

Raises
------
ValueError
    q_WB farther than 1e-6 from unit norm (| |q| - 1 | > 1e-6), a field of another shape, or a quantity of
    another dimension (the message names it).

See Also
--------
PivotedBody, simulate, step

Examples
--------
A top spinning at 10 rad/s about its upright axis stays upright; one step of 0.01 s turns it 0.1 rad:

>>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.1, 0.1, 0.2]), p_OC_B=[0.0, 0.0, 0.5])
>>> s = rd.step(top, rd.PivotedBodyState(w_B=[0.0, 0.0, 10.0]), 0.01, gravity=True)
>>> rd.quat_to_rotvec(s.q_WB).round(6), s.w_B
(array([0. , 0. , 0.1]), array([ 0.,  0., 10.]))
)doc");
  state
      .def(py::init([](py::handle q_WB, py::handle w_B, py::handle scalar_first) {
             const bool wxyz = py_io::as_bool(scalar_first, "scalar_first");
             return PivotedBodyState{q_WB.is_none() ? Eigen::Quaterniond::Identity() : as_unit_quaternion(q_WB, "q_WB", wxyz),
                                     py_io::as_vector3_or_zero(py_io::in_si(w_B, "rad/s", "w_B"), "w_B")};
           }),
           py::arg("q_WB") = py::none(), py::arg("w_B") = py::none(), py::arg("scalar_first") = false)
      .def_property(
          "q_WB", [](const PivotedBodyState& s) { return read_only_quaternion(s.q_WB, false); },
          [](PivotedBodyState& s, py::handle v) { s.q_WB = as_unit_quaternion(v, "q_WB", false); },
          "Attitude q_WB (B to W), shape (4,), (x, y, z, w); set from (x, y, z, w), normalised (ValueError beyond "
          "1e-6 of unit norm).")
      .def(
          "quaternion",
          [](const PivotedBodyState& s, py::handle scalar_first) {
            return read_only_quaternion(s.q_WB, py_io::as_bool(scalar_first, "scalar_first"));
          },
          py::arg("scalar_first") = false, R"doc(The attitude q_WB (B to W) in the order asked.

Parameters
----------
scalar_first : bool, default False
    Return (w, x, y, z) instead of (x, y, z, w).

Returns
-------
ndarray, shape (4,)
    q_WB, read-only.

Examples
--------
>>> rd.PivotedBodyState().quaternion(scalar_first=True)
array([1., 0., 0., 0.])
)doc")
      .def_property(
          "w_B", [](const PivotedBodyState& s) { return py_io::read_only(s.w_B); },
          [](PivotedBodyState& s, py::handle v) { s.w_B = py_io::as_vector3(py_io::in_si(v, "rad/s", "w_B"), "w_B"); },
          "Angular velocity w_B of B relative to W, expressed in B, shape (3,) [rad/s].")
      .def("__repr__",
           [](const PivotedBodyState& s) {
             return repr_call("PivotedBodyState",
                              {{"q_WB", py::object(py_io::to_array(s.q_WB, false))}, {"w_B", list_of(s.w_B)}});
           })
      .def(py::pickle(
          [](const PivotedBodyState& s) { return py::make_tuple(py_io::to_array(s.q_WB, false), list_of(s.w_B)); },
          [](const py::tuple& t) {
            pickled_state(t, 2, "PivotedBodyState");
            const Eigen::Vector4d q = unpickled<4>(t[0], "PivotedBodyState pickle q_WB");
            return PivotedBodyState{py_io::read_quaternion(q.data(), false), unpickled<3>(t[1], "PivotedBodyState pickle w_B")};
          }));
  def_equality(state, [](const PivotedBodyState& a, const PivotedBodyState& b) {
    return a.q_WB.coeffs() == b.q_WB.coeffs() && a.w_B == b.w_B;
  });

  py::class_<PivotedPlanarBodyState> planar(
      m, "PivotedPlanarBodyState", R"doc(State of a PivotedPlanarBody: its angle and angular velocity about z.

Fields are assignable (converted and checked as the constructor does). Pickles; == compares every field.

Parameters
----------
theta : float or pint.Quantity, default 0
    Angle of B about z [rad] (R_WB = Rz(theta)).
omega : float or pint.Quantity, default 0
    d theta/dt [rad/s].

Raises
------
ValueError
    A value that is not a number, or a quantity of another dimension (the message names it).

See Also
--------
PivotedPlanarBody, simulate, step

Examples
--------
A pendulum released horizontal keeps its energy (rk4's drift is O(dt^4): below 1e-9 J here at dt = 1 ms):

>>> rod = rd.PivotedPlanarBody(3.0, 1.0, p_OC_B=[1.0, 0.0])
>>> r = rd.simulate(rod, rd.PivotedPlanarBodyState(theta=0.0), 0.001, steps=1000, gravity=[0.0, -9.81])
>>> bool(abs(r.total_energy - r.total_energy[0]).max() < 1e-9)
True
)doc");
  planar
      .def(py::init([](py::handle theta, py::handle omega) {
             return PivotedPlanarBodyState{py_io::as_scalar(py_io::in_si(theta, "rad", "theta"), "theta"),
                                           py_io::as_scalar(py_io::in_si(omega, "rad/s", "omega"), "omega")};
           }),
           py::arg("theta") = 0.0, py::arg("omega") = 0.0)
      .def_property(
          "theta", [](const PivotedPlanarBodyState& s) { return s.theta; },
          [](PivotedPlanarBodyState& s, py::handle v) { s.theta = py_io::as_scalar(py_io::in_si(v, "rad", "theta"), "theta"); },
          "Angle theta of B about z [rad], R_WB = Rz(theta).")
      .def_property(
          "omega", [](const PivotedPlanarBodyState& s) { return s.omega; },
          [](PivotedPlanarBodyState& s, py::handle v) { s.omega = py_io::as_scalar(py_io::in_si(v, "rad/s", "omega"), "omega"); },
          "Angular velocity omega = d theta/dt about z [rad/s].")
      .def("__repr__",
           [](const PivotedPlanarBodyState& s) {
             return repr_call("PivotedPlanarBodyState", {{"theta", py::float_(s.theta)}, {"omega", py::float_(s.omega)}});
           })
      .def(py::pickle([](const PivotedPlanarBodyState& s) { return py::make_tuple(s.theta, s.omega); },
                      [](const py::tuple& t) {
                        pickled_state(t, 2, "PivotedPlanarBodyState");
                        return PivotedPlanarBodyState{t[0].cast<double>(), t[1].cast<double>()};
                      }));
  def_equality(planar, [](const PivotedPlanarBodyState& a, const PivotedPlanarBodyState& b) {
    return a.theta == b.theta && a.omega == b.omega;
  });
}

// ------------------------------------------------------------ the dynamics results

// A member of a result: a 3-vector or a number, with its unit for pint quantities.
Eigen::Vector3d as_member(py::handle obj, const char* unit, const char* name, Eigen::Vector3d*) {
  return py_io::as_vector3_or_zero(py_io::in_si(obj, unit, name), name);
}
double as_member(py::handle obj, const char* unit, const char* name, double*) {
  return py_io::as_scalar(py_io::in_si(obj, unit, name), name);
}
py::object member_object(const Eigen::Vector3d& v) { return py_io::read_only(v); }
py::object member_object(double x) { return py::float_(x); }
py::object member_state(const Eigen::Vector3d& v) { return py_io::to_array(v); }
py::object member_state(double x) { return py::float_(x); }
Eigen::Vector3d unpickled_member(py::handle obj, const std::string& what, Eigen::Vector3d*) { return unpickled<3>(obj, what); }
double unpickled_member(py::handle obj, const std::string&, double*) { return obj.cast<double>(); }
bool finite_member(const Eigen::Vector3d& v) { return v.allFinite(); }
bool finite_member(double x) { return std::isfinite(x); }

struct Member {
  const char* name;
  const char* unit;
  const char* doc;
};

// An immutable result of two named members (a, b) that unpacks as the pair it is: keyword constructor
// (None or 0: zero), read-only attributes, repr, pickle, ==, len/iter/[i].
template <class T, class A, class B>
void bind_result_pair(py::module_& m, const char* name, const char* doc, A T::*a, Member ma, B T::*b, Member mb) {
  py::class_<T> cls(m, name, doc);
  const auto zero_a = std::is_same_v<A, double> ? py::object(py::float_(0.0)) : py::object(py::none());
  const auto zero_b = std::is_same_v<B, double> ? py::object(py::float_(0.0)) : py::object(py::none());
  cls.def(py::init([=](py::handle x, py::handle y) {
            T out;
            out.*a = as_member(x, ma.unit, ma.name, static_cast<A*>(nullptr));
            out.*b = as_member(y, mb.unit, mb.name, static_cast<B*>(nullptr));
            return out;
          }),
          py::arg(ma.name) = zero_a, py::arg(mb.name) = zero_b)
      .def_property_readonly(ma.name, [a](const T& r) { return member_object(r.*a); }, ma.doc)
      .def_property_readonly(mb.name, [b](const T& r) { return member_object(r.*b); }, mb.doc)
      .def("__repr__",
           [=](const T& r) { return repr_call(name, {{ma.name, member_state(r.*a)}, {mb.name, member_state(r.*b)}}); })
      .def(py::pickle([=](const T& r) { return py::make_tuple(member_state(r.*a), member_state(r.*b)); },
                      [=](const py::tuple& t) {
                        pickled_state(t, 2, name);
                        T out;
                        out.*a = unpickled_member(t[0], std::string(name) + " pickle " + ma.name, static_cast<A*>(nullptr));
                        out.*b = unpickled_member(t[1], std::string(name) + " pickle " + mb.name, static_cast<B*>(nullptr));
                        return out;
                      }))
      .def("__len__", [](const T&) { return 2; })
      .def("__iter__", [=](const T& r) { return py::iter(py::make_tuple(member_object(r.*a), member_object(r.*b))); })
      .def(
          "__getitem__",
          [=](const T& r, py::handle i) {
            return py::make_tuple(member_object(r.*a), member_object(r.*b)).attr("__getitem__")(i);
          },
          py::arg("index"));
  def_equality(cls, [a, b](const T& x, const T& y) { return x.*a == y.*a && x.*b == y.*b; });
}

// A result checked finite (RuntimeWarning naming the quantity otherwise), then as a Python object.
template <class T, class A, class B>
py::object checked_pair(const T& r, A T::*a, B T::*b, const char* quantity) {
  py_io::warn_unless_finite(finite_member(r.*a) && finite_member(r.*b), quantity,
                            py::repr(py::cast(r)).template cast<std::string>());
  return py::cast(r);
}

void bind_pivoted_results(py::module_& m) {
  bind_result_pair(m, "PivotedAcceleration", R"doc(forward_dynamics' result for a PivotedBody.

The angular acceleration in B and the pivot's force on the body in W; unpacks as
``alpha_B, reaction_W = ...``. Immutable; pickles.

Parameters
----------
alpha_B : array_like, shape (3,), or pint.Quantity, optional
    Angular acceleration of B, in B [rad/s^2] (None: zero).
reaction_W : array_like, shape (3,), or pint.Quantity, optional
    The pivot's force on the body, in W [N] (None: zero).

See Also
--------
forward_dynamics, PivotedBody, PivotedTorque

Examples
--------
A top of 1 kg held horizontal, its centre of mass 0.5 m from the pivot: alpha = m g |c| / I_O = 14.01 rad/s^2:

>>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.1, 0.1, 0.2]), p_OC_B=[0.0, 0.0, 0.5])
>>> level = rd.PivotedBodyState(q_WB=rd.rotvec_to_quat([0.0, np.pi / 2, 0.0]))
>>> alpha_B, reaction_W = rd.forward_dynamics(top, level, gravity=True)
>>> alpha_B.round(6)
array([ 0.      , 14.014286,  0.      ])
)doc",
                   &PivotedAcceleration::alpha_B,
                   Member{"alpha_B", "rad/s^2", "Angular acceleration alpha_B of B, in B, shape (3,) [rad/s^2]."},
                   &PivotedAcceleration::reaction_W,
                   Member{"reaction_W", "N", "The pivot's force on the body, in W, shape (3,) [N]."});
  bind_result_pair(m, "PivotedTorque", R"doc(inverse_dynamics' result for a PivotedBody.

The torque about the pivot O the motion needs besides gravity, in B, and the pivot's force on the body in W;
unpacks as ``tau_O_B, reaction_W = ...``. Immutable; pickles.

Parameters
----------
tau_O_B : array_like, shape (3,), or pint.Quantity, optional
    Torque about O, in B [N m] (None: zero).
reaction_W : array_like, shape (3,), or pint.Quantity, optional
    The pivot's force on the body, in W [N] (None: zero).

See Also
--------
inverse_dynamics, PivotedBody, PivotedAcceleration

Examples
--------
At rest upright, the pivot alone holds the top's weight:

>>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.1, 0.1, 0.2]), p_OC_B=[0.0, 0.0, 0.5])
>>> rd.inverse_dynamics(top, rd.PivotedBodyState(), alpha_B=[0, 0, 0], gravity=True)
PivotedTorque(tau_O_B=[0.0, 0.0, 0.0], reaction_W=[0.0, 0.0, 9.81])
)doc",
                   &PivotedTorque::tau_O_B,
                   Member{"tau_O_B", "N*m", "Torque tau_O_B about the pivot O, in B, shape (3,) [N m]."},
                   &PivotedTorque::reaction_W,
                   Member{"reaction_W", "N", "The pivot's force on the body, in W, shape (3,) [N]."});
  bind_result_pair(m, "PivotedPlanarAcceleration", R"doc(forward_dynamics' result for a PivotedPlanarBody.

The angular acceleration about z and the pivot's force on the body in W (its z part is what the pin and the
plane hold); unpacks as ``alpha, reaction_W = ...``. Immutable; pickles.

Parameters
----------
alpha : float or pint.Quantity, default 0
    Angular acceleration about z [rad/s^2].
reaction_W : array_like, shape (3,), or pint.Quantity, optional
    The pivot's force on the body, in W [N] (None: zero).

See Also
--------
forward_dynamics, PivotedPlanarBody, PivotedPlanarTorque

Examples
--------
A rod of L = 2 m and 3 kg pinned at one end, released horizontal: alpha = -3 g / (2 L), and the pin carries
m g / 4 (the centre of mass accelerates down at 3 g / 4):

>>> rod = rd.PivotedPlanarBody(3.0, 3.0 * 2.0**2 / 12, p_OC_B=[1.0, 0.0])
>>> alpha, reaction_W = rd.forward_dynamics(rod, rd.PivotedPlanarBodyState(), gravity=[0.0, -9.81])
>>> print(f"{alpha:.6f} {reaction_W[1]:.6f} {3.0 * 9.81 / 4:.6f}")
-7.357500 7.357500 7.357500
)doc",
                   &PivotedPlanarAcceleration::alpha,
                   Member{"alpha", "rad/s^2", "Angular acceleration alpha about z [rad/s^2]."},
                   &PivotedPlanarAcceleration::reaction_W,
                   Member{"reaction_W", "N", "The pivot's force on the body, in W, shape (3,) [N]."});
  bind_result_pair(m, "PivotedPlanarTorque", R"doc(inverse_dynamics' result for a PivotedPlanarBody.

The torque about the z axis through the pivot O the motion needs besides gravity, and the pivot's force on the
body in W; unpacks as ``tau_O, reaction_W = ...``. Immutable; pickles.

Parameters
----------
tau_O : float or pint.Quantity, default 0
    Torque about the z axis through O [N m].
reaction_W : array_like, shape (3,), or pint.Quantity, optional
    The pivot's force on the body, in W [N] (None: zero).

See Also
--------
inverse_dynamics, PivotedPlanarBody, PivotedPlanarAcceleration

Examples
--------
Holding the rod horizontal takes the torque m g L / 2 about the pin:

>>> rod = rd.PivotedPlanarBody(3.0, 3.0 * 2.0**2 / 12, p_OC_B=[1.0, 0.0])
>>> tau_O, reaction_W = rd.inverse_dynamics(rod, rd.PivotedPlanarBodyState(), alpha_B=0.0, gravity=[0.0, -9.81])
>>> print(f"{tau_O:.6f} {3.0 * 9.81 * 1.0:.6f}")
29.430000 29.430000
)doc",
                   &PivotedPlanarTorque::tau_O,
                   Member{"tau_O", "N*m", "Torque tau_O about the z axis through O [N m]."},
                   &PivotedPlanarTorque::reaction_W,
                   Member{"reaction_W", "N", "The pivot's force on the body, in W, shape (3,) [N]."});
}
}  // namespace

// ------------------------------------------------------------ the seams (pivoted.hpp)

bool is_pivoted(py::handle body) {
  return is_instance<PivotedBody>(body) || is_instance<PivotedPlanarBody>(body);
}

// The lines of forward_dynamics' and inverse_dynamics' docstrings on the pivoted bodies (bind_bodies.cpp).
const char* const pivoted_forward_dynamics_doc =
    "- PivotedBody: Euler about the pivot O, inertia_O alpha_B + w_B x inertia_O w_B = tau_O (in B), and Newton for\n"
    "  the centre of mass C, reaction_W = m a_C - f_W - m g_W; `point` is p_CP from C.\n"
    "- PivotedPlanarBody: inertia_O_zz alpha = tau_O about the z axis through O, and the reaction as for a\n"
    "  PivotedBody.\n";
const char* const pivoted_inverse_dynamics_doc =
    "- PivotedBody: the torque about O in B the motion needs besides gravity, tau_O_B = inertia_O alpha_B +\n"
    "  w_B x inertia_O w_B - p_OC_B x m g_B (g_B: gravity in B), and the pivot's reaction_W in W.\n"
    "- PivotedPlanarBody: the torque tau_O about the z axis through O besides gravity, and reaction_W.\n";
py::object pivoted_forward_dynamics_py(py::handle body, py::handle state, py::handle force, py::handle torque,
                                       py::handle point, py::handle frame_arg, py::handle gravity) {
  const Frame frame = as_frame(frame_arg);
  if (is_instance<PivotedBody>(body)) {
    const auto& b = body.cast<const PivotedBody&>();
    const PivotedBodyState s = checked_state_of<PivotedBodyState>(state, "PivotedBody");
    const ComWrench w = wrench_at_com(s.q_WB, py_io::as_vector3_or_zero(py_io::in_si(force, "N", "force"), "force"),
                                      py_io::as_vector3_or_zero(py_io::in_si(torque, "N*m", "torque"), "torque"),
                                      py_io::as_vector3_or_zero(py_io::in_si(point, "m", "point"), "point"), frame);
    const PivotedAcceleration r = forward_dynamics(b, s, w, as_gravity(gravity));
    return checked_pair(r, &PivotedAcceleration::alpha_B, &PivotedAcceleration::reaction_W, "forward_dynamics");
  }
  const auto& b = body.cast<const PivotedPlanarBody&>();
  const PivotedPlanarBodyState s = checked_state_of<PivotedPlanarBodyState>(state, "PivotedPlanarBody");
  const double tau = torque.is_none() ? 0.0 : py_io::as_scalar(py_io::in_si(torque, "N*m", "torque"), "torque");
  const PlanarWrench w2 = wrench_at_com(s.theta, py_io::as_vector2_or_zero(py_io::in_si(force, "N", "force"), "force"),
                                        tau, py_io::as_vector2_or_zero(py_io::in_si(point, "m", "point"), "point"), frame);
  const ComWrench w{Eigen::Vector3d(w2.f_W.x(), w2.f_W.y(), 0.0), Eigen::Vector3d(0.0, 0.0, w2.tau)};
  const PivotedPlanarAcceleration r = forward_dynamics(b, s, w, as_in_plane_gravity(gravity));
  return checked_pair(r, &PivotedPlanarAcceleration::alpha, &PivotedPlanarAcceleration::reaction_W, "forward_dynamics");
}

py::object pivoted_inverse_dynamics_py(py::handle body, py::handle state, py::handle a_W, py::handle alpha_B,
                                       py::handle gravity) {
  if (!a_W.is_none()) {
    py_io::throw_value_error("a_W", "None for a pivoted body (the pivot fixes the centre of mass's acceleration)",
                             py_io::describe(a_W));
  }
  if (is_instance<PivotedBody>(body)) {
    const auto& b = body.cast<const PivotedBody&>();
    const PivotedBodyState s = checked_state_of<PivotedBodyState>(state, "PivotedBody");
    const PivotedTorque r = inverse_dynamics(
        b, s, py_io::as_vector3(py_io::in_si(alpha_B, "rad/s^2", "alpha_B"), "alpha_B"), as_gravity(gravity));
    return checked_pair(r, &PivotedTorque::tau_O_B, &PivotedTorque::reaction_W, "inverse_dynamics");
  }
  const auto& b = body.cast<const PivotedPlanarBody&>();
  const PivotedPlanarBodyState s = checked_state_of<PivotedPlanarBodyState>(state, "PivotedPlanarBody");
  const PivotedPlanarTorque r = inverse_dynamics(
      b, s, py_io::as_scalar(py_io::in_si(alpha_B, "rad/s^2", "alpha_B"), "alpha_B"), as_in_plane_gravity(gravity));
  return checked_pair(r, &PivotedPlanarTorque::tau_O, &PivotedPlanarTorque::reaction_W, "inverse_dynamics");
}

py::object pivoted_scene(py::handle model, py::handle loads, py::handle gravity) {
  if (is_instance<PivotedBody>(model)) return one_body_scene(model.cast<const PivotedBody&>(), as_gravity(gravity), loads);
  return one_body_scene(model.cast<const PivotedPlanarBody&>(), as_in_plane_gravity(gravity), loads);
}

void bind_pivoted(py::module_& m) {
  bind_pivoted_body(m);
  bind_pivoted_states(m);
  bind_pivoted_results(m);
}

}  // namespace rigiddyn::bindings
