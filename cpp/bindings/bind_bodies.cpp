// Python bindings of the bodies and their dynamics: Particle, PlanarBody, RigidBody, their states,
// and the functions on them (forward and inverse dynamics, momentum, energy, power, impulse). Each
// function takes any of the three bodies: one entry point that dispatches on the body's type (so a
// wrong argument gives a TypeError naming it, not pybind11's overload list), checks the state it
// gets (finite, unit quaternion: a state returned by `step` may be neither) and warns when a result
// overflows. simulate/step and AppliedLoad are in bind_dynamics.cpp.
#include <pybind11/stl.h>

#include <cmath>
#include <limits>

#include <string>
#include <type_traits>

#include "bindings.hpp"
#include "common_args.hpp"
#include "numpy_io.hpp"
#include "pivoted.hpp"
#include "repr.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/dynamics/particle_dynamics.hpp"
#include "rigiddyn/dynamics/planar_body_dynamics.hpp"
#include "rigiddyn/dynamics/rigid_body_dynamics.hpp"
#include "rigiddyn/simulate/simulate.hpp"  // standard_gravity
#include "rigiddyn/so3/quaternion.hpp"
#include "state_args.hpp"
#include "value_type.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using py_io::finite_result;

namespace {

// A planar body's in-plane gravity: None (none) or (2,) [m/s²] in W.
Eigen::Vector2d as_planar_gravity(py::handle obj) {
  if (py::isinstance<py::bool_>(obj)) {
    py_io::throw_value_error("gravity", "None or an in-plane vector (2,) [m/s^2] for a PlanarBody", py_io::describe(obj));
  }
  return py_io::as_vector2_or_zero(py_io::in_si(obj, "m/s^2", "gravity"), "gravity");
}

// RigidBody's `check`: None (InertiaCheck.physical) or an InertiaCheck.
InertiaCheck as_inertia_check(py::handle check) {
  if (check.is_none()) return InertiaCheck::physical;
  if (!py::isinstance<InertiaCheck>(check)) {
    py_io::throw_type_error("check", "InertiaCheck.physical or InertiaCheck.allow_unrealizable", check);
  }
  return check.cast<InertiaCheck>();
}

// RigidBody from (mass, principal moments (3,) or inertia_com (3, 3)) or from a SpatialInertia alone.
RigidBody as_rigid_body(py::handle mass, py::handle inertia_com, py::handle check_arg) {
  const InertiaCheck check = as_inertia_check(check_arg);
  if (is_instance<SpatialInertia>(mass)) {
    if (!inertia_com.is_none()) {
      py_io::throw_value_error("inertia_com", "None next to a SpatialInertia (it carries the inertia)",
                               py_io::describe(inertia_com));
    }
    return RigidBody(mass.cast<const SpatialInertia&>(), check);
  }
  const double m = py_io::as_scalar(py_io::in_si(mass, "kg", "mass"), "mass");
  if (inertia_com.is_none()) {
    py_io::throw_type_error("inertia_com", "principal moments (3,) or an inertia matrix (3, 3) [kg m^2] next to a mass "
                            "(or a SpatialInertia alone)", inertia_com);
  }
  const py_io::Array I = py_io::as_array(py_io::in_si(inertia_com, "kg*m^2", "inertia_com"), "inertia_com");
  if (I.ndim() == 1 && I.shape(0) == 3) return RigidBody(m, Eigen::Vector3d(py_io::as_vector3(I, "inertia_com")), check);
  if (I.ndim() == 2 && I.shape(0) == 3 && I.shape(1) == 3) return RigidBody(m, py_io::as_matrix3(I, "inertia_com"), check);
  py_io::throw_value_error("inertia_com", "principal moments (3,) or an inertia matrix (3, 3) [kg m^2]",
                           "shape " + py::repr(I.attr("shape")).cast<std::string>());
}

// A read-only numpy copy of q (x, y, z, w), or (w, x, y, z) with scalar_first.
py_io::Array read_only(const Eigen::Quaterniond& q, bool scalar_first = false) {
  py_io::Array out = py_io::to_array(q, scalar_first);
  py_io::set_read_only(out);
  return out;
}
using py_io::read_only;

// The pickled state tuple of `cls` with `n` items (ValueError otherwise).
py::tuple pickled(const py::tuple& t, std::size_t n, const char* cls) {
  if (t.size() != n) {
    py_io::throw_value_error(std::string(cls) + " pickle", "a tuple of " + std::to_string(n) + " items",
                             std::to_string(t.size()) + " items");
  }
  return t;
}

// A vector or matrix as a numpy array for repr_call (which shows it as nested lists).
template <class V>
py::object as_list(const V& v) {
  return py::object(py_io::to_array(v));
}

// An argument a Particle does not take: None (or the default).
void require_none_for_particle(py::handle obj, const std::string& name, const std::string& why) {
  if (!obj.is_none()) py_io::throw_value_error(name, "None for a Particle (" + why + ")", py_io::describe(obj));
}

// The state of the model `body` names, unchanged once checked (checked_state: finite, the
// quaternion of unit norm within 1e-6; ValueError naming state.<member>). TypeError naming `state`
// for another model's state.
template <class State>
const State& checked_state_of(py::handle state, const char* model) {
  const char* type = std::is_same_v<State, RigidBodyState>   ? "RigidBodyState"
                     : std::is_same_v<State, PlanarBodyState> ? "PlanarBodyState"
                                                              : "ParticleState";
  const State& s = py_io::as_instance<State>(state, "state", std::string("a ") + type + " (the state of a " + model + ")");
  checked_state(s, "state");
  return s;
}

// A result as a Python object (numpy arrays and tuples as they are, C++ values cast).
template <class T>
py::object to_object(T&& value) {
  if constexpr (py::detail::is_pyobject<std::decay_t<T>>::value) {
    return std::forward<T>(value);
  } else {
    return py::cast(std::forward<T>(value));
  }
}

// Calls rigid(body, state), planar(body, state) or particle(body, state) for the model `body` is,
// with its checked state. TypeError naming body for anything else.
template <class Rigid, class Planar, class ParticleF>
py::object dispatch(py::handle body, py::handle state, Rigid rigid, Planar planar, ParticleF particle) {
  if (is_instance<RigidBody>(body)) {
    return to_object(rigid(body.cast<const RigidBody&>(), checked_state_of<RigidBodyState>(state, "RigidBody")));
  }
  if (is_instance<PlanarBody>(body)) {
    return to_object(planar(body.cast<const PlanarBody&>(), checked_state_of<PlanarBodyState>(state, "PlanarBody")));
  }
  if (is_instance<Particle>(body)) {
    return to_object(particle(body.cast<const Particle&>(), checked_state_of<ParticleState>(state, "Particle")));
  }
  py_io::throw_type_error("body", "a RigidBody, PlanarBody or Particle", body);
}

// Results: each value checked (RuntimeWarning naming the quantity when not finite).
KineticEnergy checked(const KineticEnergy& T) {
  py_io::warn_unless_finite(std::isfinite(T.translational) && std::isfinite(T.rotational) && std::isfinite(T.total()),
                            "kinetic_energy",
                            "translational " + format_value(T.translational) + ", rotational " + format_value(T.rotational));
  return T;
}
RigidBodyState checked(const RigidBodyState& s, const char* quantity) {
  py_io::warn_unless_finite(s.v_W.allFinite() && s.w_B.allFinite(), quantity,
                            "v_W " + format_value(s.v_W.transpose()) + ", w_B " + format_value(s.w_B.transpose()));
  return s;
}
PlanarBodyState checked(const PlanarBodyState& s, const char* quantity) {
  py_io::warn_unless_finite(s.v_W.allFinite() && std::isfinite(s.omega), quantity,
                            "v_W " + format_value(s.v_W.transpose()) + ", omega " + format_value(s.omega));
  return s;
}
ParticleState checked(const ParticleState& s, const char* quantity) {
  py_io::warn_unless_finite(s.v_W.allFinite(), quantity, "v_W " + format_value(s.v_W.transpose()));
  return s;
}

void bind_particle_and_planar_body(py::module_& m) {
  py::class_<Particle> particle(m, "Particle", R"doc(A point mass (3 DOF).

Newton's law for a point, m a_W = f_W + m g_W ("Rigid body kinematics and dynamics" notes, section 4.11); its
state is a ParticleState (position and velocity in W). Immutable; pickles; == compares the mass.

Parameters
----------
mass : float or pint.Quantity
    Mass m [kg], finite and > 0 (a quantity is converted to kg).

Raises
------
ValueError
    A mass that is not a finite number > 0, or a quantity of another dimension (the message names mass).

See Also
--------
ParticleState, PlanarBody, RigidBody, simulate, forward_dynamics

Examples
--------
A force of 4 N on 2 kg accelerates it at 2 m/s^2:

>>> p = rd.Particle(2.0)
>>> rd.forward_dynamics(p, rd.ParticleState(), force=[0.0, 0.0, 4.0])
array([0., 0., 2.])
)doc");
  particle.def(py::init([](py::handle mass) { return Particle(py_io::as_scalar(py_io::in_si(mass, "kg", "mass"), "mass")); }), py::arg("mass"))
      .def_property_readonly("mass", &Particle::mass, "Mass m [kg].")
      .def("__repr__", [](const Particle& p) { return repr_call("Particle", {{"mass", py::float_(p.mass())}}); })
      .def(py::pickle([](const Particle& p) { return py::make_tuple(p.mass()); },
                      [](const py::tuple& t) { return Particle(pickled(t, 1, "Particle")[0].cast<double>()); }));
  def_equality(particle, [](const Particle& a, const Particle& b) { return a.mass() == b.mass(); });

  py::class_<PlanarBody> planar(m, "PlanarBody", R"doc(A rigid body moving in the xy plane of W (3 DOF: x, y, theta).

Plane kinetics (K. Craig, "Rigid Body Dynamics" slides): m a_W = f_W + m g_W in W's plane and
I_zz alpha = tau_G about the z axis through the centre of mass G. Its state is a PlanarBodyState.
Immutable; pickles; == compares mass and inertia_zz.

Parameters
----------
mass : float or pint.Quantity
    Mass m [kg], finite and > 0.
inertia_zz : float or pint.Quantity
    Moment of inertia I_zz about the z axis through the centre of mass [kg m^2], finite and > 0.

Raises
------
ValueError
    A value that is not a finite number > 0, or a quantity of another dimension (the message names it).

See Also
--------
PlanarBodyState, PivotedPlanarBody, RigidBody, simulate

Examples
--------
Spinning at 2 rad/s, I_zz = 0.5 kg m^2 holds 1/2 I_zz omega^2 = 1 J:

>>> b = rd.PlanarBody(2.0, 0.5)
>>> rd.kinetic_energy(b, rd.PlanarBodyState(omega=2.0)).rotational
1.0
)doc");
  planar
      .def(py::init([](py::handle mass, py::handle inertia_zz) {
             return PlanarBody(py_io::as_scalar(py_io::in_si(mass, "kg", "mass"), "mass"),
                               py_io::as_scalar(py_io::in_si(inertia_zz, "kg*m^2", "inertia_zz"), "inertia_zz"));
           }),
           py::arg("mass"), py::arg("inertia_zz"))
      .def_property_readonly("mass", &PlanarBody::mass, "Mass m [kg].")
      .def_property_readonly("inertia_zz", &PlanarBody::inertia_zz,
                             "Moment of inertia I_zz about the z axis through the centre of mass G [kg m^2].")
      .def("__repr__",
           [](const PlanarBody& b) {
             return repr_call("PlanarBody", {{"mass", py::float_(b.mass())}, {"inertia_zz", py::float_(b.inertia_zz())}});
           })
      .def(py::pickle([](const PlanarBody& b) { return py::make_tuple(b.mass(), b.inertia_zz()); },
                      [](const py::tuple& t) {
                        pickled(t, 2, "PlanarBody");
                        return PlanarBody(t[0].cast<double>(), t[1].cast<double>());
                      }));
  def_equality(planar, [](const PlanarBody& a, const PlanarBody& b) {
    return a.mass() == b.mass() && a.inertia_zz() == b.inertia_zz();
  });
}

// "RigidBody(mass=..., inertia_com=...)": the principal moments when the inertia is diagonal, and
// check=InertiaCheck.allow_unrealizable when the inertia fails the physical check.
std::string rigid_body_repr(const RigidBody& b) {
  const Eigen::Matrix3d& I = b.inertia_com();
  const bool diagonal = Eigen::Matrix3d(I.diagonal().asDiagonal()) == I;
  std::string text = repr_call("RigidBody", {{"mass", py::float_(b.mass())},
                                             {"inertia_com", diagonal ? as_list(I.diagonal()) : as_list(I)}});
  try {
    checked_inertia(b.mass(), I, InertiaCheck::physical);
  } catch (const std::invalid_argument&) {
    text.insert(text.size() - 1, ", check=InertiaCheck.allow_unrealizable");
  }
  return text;
}

void bind_rigid_body(py::module_& m) {
  py::class_<RigidBody> body(
      m, "RigidBody", R"doc(A spatial rigid body (6 DOF): mass and inertia about its centre of mass.

Newton's law for the centre of mass in W and Euler's equations in the body frame B (origin at the centre
of mass): m a_W = f_W + m g_W, I alpha_B + w_B x I w_B = tau_B. Its state is a RigidBodyState. Three forms:

- ``RigidBody(mass, [I1, I2, I3])``: principal moments, the axes of B principal (inertia_com = diag(I1, I2, I3));
- ``RigidBody(mass, inertia_com)``: a full (3, 3) inertia about the centre of mass in B, moments on the
  diagonal and negated products off it (I_xy = -sum x y dm);
- ``RigidBody(spatial_inertia)``: a SpatialInertia: its mass and inertia about its centre of mass, B placed at
  the centre of mass with the SpatialInertia's axes.

The inertia must be symmetric positive definite and is checked as every inertia of rigiddyn is
(inertia_report). euler_form tells which form of Euler's equations it uses: 'spherical', 'principal' or
'full'. Immutable; pickles (an unrealizable test body stays one); == compares mass and inertia_com.

Parameters
----------
mass : float, pint.Quantity or SpatialInertia
    Mass m [kg], finite and > 0; or a SpatialInertia alone (then inertia_com is None).
inertia_com : array_like, shape (3,) or (3, 3), or pint.Quantity
    Principal moments [kg m^2], or the inertia matrix about the centre of mass in B [kg m^2] (an array
    quantity is converted). Required next to a mass; None next to a SpatialInertia.
check : InertiaCheck or None, default None
    None or InertiaCheck.physical: the principal moments must also satisfy the triangle inequality
    I_a + I_b >= I_c. InertiaCheck.allow_unrealizable accepts test bodies no real body has, e.g.
    I = diag(2, 1, 2/3).

Raises
------
ValueError
    mass not a finite number > 0; inertia_com of another shape, not symmetric positive definite or (under
    the physical check) violating the triangle inequality; inertia_com next to a SpatialInertia; a quantity
    of another dimension. The message names the argument.
TypeError
    inertia_com None next to a mass, or check not an InertiaCheck.

See Also
--------
RigidBodyState, SpatialInertia, inertia_report, nearest_valid_inertia, PivotedBody, Gyrostat, simulate

Examples
--------
>>> b = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
>>> b.inertia_com.diagonal()
array([1., 2., 3.])
>>> b.euler_form, rd.RigidBody(1.0, [0.4, 0.4, 0.4]).euler_form
('principal', 'spherical')

A product of inertia makes Euler's equations 'full':

>>> rd.RigidBody(1.0, [[2.0, -0.1, 0.0], [-0.1, 2.0, 0.0], [0.0, 0.0, 3.0]]).euler_form
'full'
)doc");
  body.def(py::init(&as_rigid_body), py::arg("mass"), py::arg("inertia_com") = py::none(), py::arg("check") = py::none())
      .def_property_readonly("mass", &RigidBody::mass, "Mass m [kg].")
      .def_property_readonly(
          "inertia_com", [](const RigidBody& b) { return read_only(b.inertia_com()); },
          "Inertia I about the centre of mass in B, shape (3, 3) [kg m^2], negated products off the diagonal "
          "(read-only).")
      .def_property_readonly(
          "euler_form",
          [](const RigidBody& b) {
            switch (b.euler_form()) {
              case EulerForm::spherical: return "spherical";
              case EulerForm::principal: return "principal";
              case EulerForm::full: return "full";
            }
            return "full";
          },
          "Form of Euler's equations used: 'spherical' (no gyroscopic term), 'principal' (diagonal inertia) or "
          "'full'.")
      .def("__repr__", &rigid_body_repr)
      .def(py::pickle(
          [](const RigidBody& b) { return py::make_tuple(b.mass(), py_io::to_array(b.inertia_com())); },
          [](const py::tuple& t) {
            pickled(t, 2, "RigidBody");
            // checked when first built; kept as it was (an unrealizable test body stays one)
            return RigidBody(t[0].cast<double>(), py_io::as_matrix3(t[1], "RigidBody pickle inertia_com"),
                             InertiaCheck::allow_unrealizable);
          }));
  def_equality(body, [](const RigidBody& a, const RigidBody& b) {
    return a.mass() == b.mass() && a.inertia_com() == b.inertia_com();
  });
}

// The three states: every field assignable as a whole (`s.w_B = [...]`, converted and checked as the
// constructor does) and read as a read-only array (`s.w_B[0] = 5` raises instead of writing to a copy).
void bind_states(py::module_& m) {
  py::class_<ParticleState> particle(m, "ParticleState", R"doc(State of a Particle: position and velocity in W.

Fields are assigned whole (``s.v_W = [...]``, converted and checked as the constructor does); the arrays read
are read-only copies. Pickles; == compares every field.

Parameters
----------
p_W : array_like, shape (3,), or pint.Quantity, optional
    Position in W [m] (None: zero).
v_W : array_like, shape (3,), or pint.Quantity, optional
    Velocity in W [m/s] (None: zero).

Raises
------
ValueError
    A field of another shape, or a quantity of another dimension (the message names it).

See Also
--------
Particle, simulate, step

Examples
--------
>>> s = rd.ParticleState(p_W=[1.0, 0.0, 0.0], v_W=[0.0, 2.0, 0.0])
>>> rd.linear_momentum(rd.Particle(3.0), s)
array([0., 6., 0.])
>>> rd.angular_momentum(rd.Particle(3.0), s)  # about the origin of W: p_W x m v_W
array([0., 0., 6.])
)doc");
  particle
      .def(py::init([](py::handle p_W, py::handle v_W) {
             return ParticleState{py_io::as_vector3_or_zero(py_io::in_si(p_W, "m", "p_W"), "p_W"),
                                  py_io::as_vector3_or_zero(py_io::in_si(v_W, "m/s", "v_W"), "v_W")};
           }),
           py::arg("p_W") = py::none(), py::arg("v_W") = py::none())
      .def_property(
          "p_W", [](const ParticleState& s) { return read_only(s.p_W); },
          [](ParticleState& s, py::handle v) {
            s.p_W = py_io::as_vector3(py_io::in_si(v, "m", "p_W"), "p_W"); }, "Position p_W in W, shape (3,) [m].")
      .def_property(
          "v_W", [](const ParticleState& s) { return read_only(s.v_W); },
          [](ParticleState& s, py::handle v) {
            s.v_W = py_io::as_vector3(py_io::in_si(v, "m/s", "v_W"), "v_W"); }, "Velocity v_W in W, shape (3,) [m/s].")
      .def("__repr__",
           [](const ParticleState& s) {
             return repr_call("ParticleState", {{"p_W", as_list(s.p_W)}, {"v_W", as_list(s.v_W)}});
           })
      .def(py::pickle([](const ParticleState& s) { return py::make_tuple(py_io::to_array(s.p_W), py_io::to_array(s.v_W)); },
                      [](const py::tuple& t) {
                        pickled(t, 2, "ParticleState");
                        return ParticleState{unpickled<3>(t[0], "ParticleState pickle p_W"),
                                             unpickled<3>(t[1], "ParticleState pickle v_W")};
                      }));
  def_equality(particle, [](const ParticleState& a, const ParticleState& b) { return a.p_W == b.p_W && a.v_W == b.v_W; });

  py::class_<PlanarBodyState> planar(m, "PlanarBodyState", R"doc(State of a PlanarBody in W's xy plane.

Fields are assigned whole (converted and checked as the constructor does); the arrays read are read-only
copies. Pickles; == compares every field.

Parameters
----------
p_W : array_like, shape (2,), or pint.Quantity, optional
    Centre of mass in W's xy plane [m] (None: zero).
theta : float or pint.Quantity, default 0
    Angle of B about z [rad] (R_WB = Rz(theta)).
v_W : array_like, shape (2,), or pint.Quantity, optional
    Centre of mass velocity in W [m/s] (None: zero).
omega : float or pint.Quantity, default 0
    Angular velocity about z [rad/s].

Raises
------
ValueError
    A field of another shape, or a quantity of another dimension (the message names it).

See Also
--------
PlanarBody, simulate, step

Examples
--------
>>> s = rd.PlanarBodyState(p_W=[1.0, 2.0], theta=np.pi / 2, omega=3.0)
>>> s.p_W, s.omega
(array([1., 2.]), 3.0)
)doc");
  planar
      .def(py::init([](py::handle p_W, py::handle theta, py::handle v_W, py::handle omega) {
             return PlanarBodyState{py_io::as_vector2_or_zero(py_io::in_si(p_W, "m", "p_W"), "p_W"),
                                    py_io::as_scalar(py_io::in_si(theta, "rad", "theta"), "theta"),
                                    py_io::as_vector2_or_zero(py_io::in_si(v_W, "m/s", "v_W"), "v_W"),
                                    py_io::as_scalar(py_io::in_si(omega, "rad/s", "omega"), "omega")};
           }),
           py::arg("p_W") = py::none(), py::arg("theta") = 0.0, py::arg("v_W") = py::none(), py::arg("omega") = 0.0)
      .def_property(
          "p_W", [](const PlanarBodyState& s) { return read_only(s.p_W); },
          [](PlanarBodyState& s, py::handle v) {
            s.p_W = py_io::as_vector2(py_io::in_si(v, "m", "p_W"), "p_W"); },
          "Centre of mass p_W in W's xy plane, shape (2,) [m].")
      .def_property(
          "theta", [](const PlanarBodyState& s) { return s.theta; },
          [](PlanarBodyState& s, py::handle v) {
            s.theta = py_io::as_scalar(py_io::in_si(v, "rad", "theta"), "theta"); },
          "Angle theta of B about z [rad], R_WB = Rz(theta).")
      .def_property(
          "v_W", [](const PlanarBodyState& s) { return read_only(s.v_W); },
          [](PlanarBodyState& s, py::handle v) {
            s.v_W = py_io::as_vector2(py_io::in_si(v, "m/s", "v_W"), "v_W"); },
          "Centre of mass velocity v_W in W, shape (2,) [m/s].")
      .def_property(
          "omega", [](const PlanarBodyState& s) { return s.omega; },
          [](PlanarBodyState& s, py::handle v) {
            s.omega = py_io::as_scalar(py_io::in_si(v, "rad/s", "omega"), "omega"); },
          "Angular velocity omega about z [rad/s].")
      .def("__repr__",
           [](const PlanarBodyState& s) {
             return repr_call("PlanarBodyState", {{"p_W", as_list(s.p_W)},
                                                  {"theta", py::float_(s.theta)},
                                                  {"v_W", as_list(s.v_W)},
                                                  {"omega", py::float_(s.omega)}});
           })
      .def(py::pickle(
          [](const PlanarBodyState& s) {
            return py::make_tuple(py_io::to_array(s.p_W), s.theta, py_io::to_array(s.v_W), s.omega);
          },
          [](const py::tuple& t) {
            pickled(t, 4, "PlanarBodyState");
            return PlanarBodyState{unpickled<2>(t[0], "PlanarBodyState pickle p_W"), t[1].cast<double>(),
                                   unpickled<2>(t[2], "PlanarBodyState pickle v_W"), t[3].cast<double>()};
          }));
  def_equality(planar, [](const PlanarBodyState& a, const PlanarBodyState& b) {
    return a.p_W == b.p_W && a.theta == b.theta && a.v_W == b.v_W && a.omega == b.omega;
  });

  py::class_<RigidBodyState> rigid(
      m, "RigidBodyState", R"doc(State of a RigidBody (docs/conventions.md).

Position and velocity of the centre of mass in W, attitude q_WB (B to W) and the angular velocity of B in W,
expressed in B. Fields are assigned whole (``s.w_B = [...]``, ``s.q_WB = [x, y, z, w]``, converted and checked
as the constructor does); the arrays read are read-only copies. Pickles; == compares every field.

Parameters
----------
p_W : array_like, shape (3,), or pint.Quantity, optional
    Centre of mass position in W [m] (None: zero).
q_WB : array_like, shape (4,), optional
    Unit quaternion B to W, (x, y, z, w), or (w, x, y, z) with `scalar_first` (None: identity); normalised.
v_W : array_like, shape (3,), or pint.Quantity, optional
    Centre of mass velocity in W [m/s] (None: zero).
w_B : array_like, shape (3,), or pint.Quantity, optional
    Angular velocity of B in W, expressed in B [rad/s] (None: zero).
scalar_first : bool, default False
    Read q_WB as (w, x, y, z).

Raises
------
ValueError
    q_WB farther than 1e-6 from unit norm (| |q| - 1 | > 1e-6), a field of another shape or not finite, or
    a quantity of another dimension (the message names it).

See Also
--------
RigidBody, simulate, step, quat_normalize

Examples
--------
A quarter turn about z, read scalar first:

>>> s = rd.RigidBodyState(q_WB=[0.0, 0.0, np.sin(np.pi / 4), np.cos(np.pi / 4)], w_B=[0.0, 0.0, 1.0])
>>> s.quaternion(scalar_first=True).round(12)
array([0.70710678, 0.        , 0.        , 0.70710678])
)doc");
  rigid
      .def(py::init([](py::handle p_W, py::handle q_WB, py::handle v_W, py::handle w_B, py::handle scalar_first) {
             const bool wxyz = py_io::as_bool(scalar_first, "scalar_first");
             const Eigen::Quaterniond q =
                 q_WB.is_none() ? Eigen::Quaterniond::Identity() : as_unit_quaternion(q_WB, "q_WB", wxyz);
             return RigidBodyState{py_io::as_vector3_or_zero(py_io::in_si(p_W, "m", "p_W"), "p_W"), q,
                                   py_io::as_vector3_or_zero(py_io::in_si(v_W, "m/s", "v_W"), "v_W"),
                                   py_io::as_vector3_or_zero(py_io::in_si(w_B, "rad/s", "w_B"), "w_B")};
           }),
           py::arg("p_W") = py::none(), py::arg("q_WB") = py::none(), py::arg("v_W") = py::none(),
           py::arg("w_B") = py::none(), py::arg("scalar_first") = false)
      .def_property(
          "p_W", [](const RigidBodyState& s) { return read_only(s.p_W); },
          [](RigidBodyState& s, py::handle v) { s.p_W = py_io::as_vector3(py_io::in_si(v, "m", "p_W"), "p_W"); },
          "Centre of mass position p_W in W, shape (3,) [m].")
      .def_property(
          "q_WB", [](const RigidBodyState& s) { return read_only(s.q_WB); },
          [](RigidBodyState& s, py::handle v) { s.q_WB = as_unit_quaternion(v, "q_WB"); },
          "Attitude q_WB (B to W), shape (4,), (x, y, z, w); set from (x, y, z, w), normalised (ValueError beyond "
          "1e-6 of unit norm).")
      .def(
          "quaternion",
          [](const RigidBodyState& s, py::handle scalar_first) {
            return read_only(s.q_WB, py_io::as_bool(scalar_first, "scalar_first"));
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
>>> rd.RigidBodyState().quaternion(scalar_first=True)
array([1., 0., 0., 0.])
)doc")
      .def_property(
          "v_W", [](const RigidBodyState& s) { return read_only(s.v_W); },
          [](RigidBodyState& s, py::handle v) { s.v_W = py_io::as_vector3(py_io::in_si(v, "m/s", "v_W"), "v_W"); },
          "Centre of mass velocity v_W in W, shape (3,) [m/s].")
      .def_property(
          "w_B", [](const RigidBodyState& s) { return read_only(s.w_B); },
          [](RigidBodyState& s, py::handle v) { s.w_B = py_io::as_vector3(py_io::in_si(v, "rad/s", "w_B"), "w_B"); },
          "Angular velocity w_B of B in W, expressed in B, shape (3,) [rad/s].")
      .def("__repr__",
           [](const RigidBodyState& s) {
             return repr_call("RigidBodyState", {{"p_W", as_list(s.p_W)},
                                                 {"q_WB", py::object(py_io::to_array(s.q_WB, false))},
                                                 {"v_W", as_list(s.v_W)},
                                                 {"w_B", as_list(s.w_B)}});
           })
      .def(py::pickle(
          [](const RigidBodyState& s) {
            return py::make_tuple(py_io::to_array(s.p_W), py_io::to_array(s.q_WB, false), py_io::to_array(s.v_W),
                                  py_io::to_array(s.w_B));
          },
          [](const py::tuple& t) {
            pickled(t, 4, "RigidBodyState");
            const Eigen::Vector4d q = unpickled<4>(t[1], "RigidBodyState pickle q_WB");
            return RigidBodyState{unpickled<3>(t[0], "RigidBodyState pickle p_W"), py_io::read_quaternion(q.data(), false),
                                  unpickled<3>(t[2], "RigidBodyState pickle v_W"), unpickled<3>(t[3], "RigidBodyState pickle w_B")};
          }));
  def_equality(rigid, [](const RigidBodyState& a, const RigidBodyState& b) {
    return a.p_W == b.p_W && same(a.q_WB, b.q_WB) && a.v_W == b.v_W && a.w_B == b.w_B;
  });
}

void bind_models(py::module_& m) {
  bind_particle_and_planar_body(m);
  bind_rigid_body(m);
  bind_states(m);
}


// A result of two named parts (a, b) that still reads as the tuple it replaces: unpacking
// `a, b = result`, len() and result[0], result[1].
template <class T, class Parts>
void def_as_pair(py::class_<T>& cls, Parts parts) {
  cls.def("__len__", [](const T&) { return 2; })
      .def("__iter__", [parts](const T& x) { return py::iter(parts(x)); })
      .def("__getitem__", [parts](const T& x, py::handle i) { return parts(x).attr("__getitem__")(i); }, py::arg("index"));
}

void bind_result_types(py::module_& m) {
  py::class_<KineticEnergy> energy(m, "KineticEnergy",
      "Kinetic energy T [J], split as T = translational + rotational.\n"
      R"doc(
translational = 1/2 m v_W.v_W of the centre of mass, rotational = 1/2 w_B.I w_B about it (1/2 I_zz omega^2 for
a planar body, 0 for a particle); total = their sum. kinetic_energy's result. Immutable; pickles.

Parameters
----------
translational : float or pint.Quantity, default 0
    1/2 m v_W.v_W [J] (infinities allowed).
rotational : float or pint.Quantity, default 0
    1/2 w_B.I w_B about the centre of mass [J] (infinities allowed).

Raises
------
ValueError
    A NaN, or a quantity of another dimension (the message names it).

See Also
--------
kinetic_energy, potential_energy

Examples
--------
>>> T = rd.kinetic_energy(rd.RigidBody(2.0, [1.0, 2.0, 3.0]), rd.RigidBodyState(v_W=[1, 0, 0], w_B=[0, 0, 1]))
>>> T.translational, T.rotational, T.total
(1.0, 1.5, 2.5)
)doc");
  energy
      .def(py::init([](py::handle translational, py::handle rotational) {
             return KineticEnergy{py_io::as_extended_real(py_io::in_si(translational, "J", "translational"), "translational"),
                                  py_io::as_extended_real(py_io::in_si(rotational, "J", "rotational"), "rotational")};
           }),
           py::arg("translational") = 0.0, py::arg("rotational") = 0.0)
      .def_readonly("translational", &KineticEnergy::translational,
                    "Translational part 1/2 m v_W.v_W of the centre of mass [J].")
      .def_readonly("rotational", &KineticEnergy::rotational,
                    "Rotational part 1/2 w_B.I w_B about the centre of mass [J].")
      .def_property_readonly("total", &KineticEnergy::total, "Total kinetic energy, translational + rotational [J].")
      .def("__repr__",
           [](const KineticEnergy& T) {
             return repr_call("KineticEnergy",
                              {{"translational", py::float_(T.translational)}, {"rotational", py::float_(T.rotational)}});
           })
      .def(py::pickle([](const KineticEnergy& T) { return py::make_tuple(T.translational, T.rotational); },
                      [](const py::tuple& t) {
                        pickled(t, 2, "KineticEnergy");
                        return KineticEnergy{t[0].cast<double>(), t[1].cast<double>()};
                      }));
  def_equality(energy, [](const KineticEnergy& a, const KineticEnergy& b) {
    return a.translational == b.translational && a.rotational == b.rotational;
  });

  py::class_<ComWrench> wrench(m, "ComWrench",
      "Loads reduced to the centre of mass G: a force in W and a torque about G in B.\n"
      R"doc(
inverse_dynamics' result for a RigidBody; unpacks as ``f_W, tau_B = ...``. Immutable; pickles.

Parameters
----------
f_W : array_like, shape (3,), or pint.Quantity, optional
    Force in W [N] (None: zero).
tau_B : array_like, shape (3,), or pint.Quantity, optional
    Torque about the centre of mass, in B [N m] (None: zero).

Raises
------
ValueError
    A field of another shape, or a quantity of another dimension (the message names it).

See Also
--------
inverse_dynamics, BodyAcceleration, power

Examples
--------
Holding 2 kg against gravity while lifting it at 1 m/s^2 takes m (a_W - g) = 21.62 N:

>>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
>>> f_W, tau_B = rd.inverse_dynamics(body, rd.RigidBodyState(), a_W=[0, 0, 1], alpha_B=[1, 0, 0], gravity=True)
>>> f_W, tau_B
(array([ 0.  ,  0.  , 21.62]), array([1., 0., 0.]))
)doc");
  wrench
      .def(py::init([](py::handle f_W, py::handle tau_B) {
             return ComWrench{py_io::as_vector3_or_zero(py_io::in_si(f_W, "N", "f_W"), "f_W"),
                              py_io::as_vector3_or_zero(py_io::in_si(tau_B, "N*m", "tau_B"), "tau_B")};
           }),
           py::arg("f_W") = py::none(), py::arg("tau_B") = py::none())
      .def_property_readonly("f_W", [](const ComWrench& w) { return read_only(w.f_W); },
                             "Force f_W in W, shape (3,) [N].")
      .def_property_readonly("tau_B", [](const ComWrench& w) { return read_only(w.tau_B); },
                             "Torque tau_B about the centre of mass, in B, shape (3,) [N m].")
      .def("__repr__", [](const ComWrench& w) {
        return repr_call("ComWrench", {{"f_W", as_list(w.f_W)}, {"tau_B", as_list(w.tau_B)}});
      })
      .def(py::pickle([](const ComWrench& w) { return py::make_tuple(py_io::to_array(w.f_W), py_io::to_array(w.tau_B)); },
                      [](const py::tuple& t) {
                        pickled(t, 2, "ComWrench");
                        return ComWrench{unpickled<3>(t[0], "ComWrench pickle f_W"), unpickled<3>(t[1], "ComWrench pickle tau_B")};
                      }));
  def_equality(wrench, [](const ComWrench& a, const ComWrench& b) { return a.f_W == b.f_W && a.tau_B == b.tau_B; });
  def_as_pair(wrench, [](const ComWrench& w) { return py::make_tuple(read_only(w.f_W), read_only(w.tau_B)); });

  py::class_<PlanarWrench> planar_wrench(m, "PlanarWrench", R"doc(In-plane loads reduced to the centre of mass G.

A force in W's xy plane and a torque about the z axis through G: inverse_dynamics' result for a PlanarBody;
unpacks as ``f_W, tau = ...``. Immutable; pickles.

Parameters
----------
f_W : array_like, shape (2,), or pint.Quantity, optional
    Force in W [N] (None: zero).
tau : float or pint.Quantity, default 0
    Torque about the z axis through the centre of mass [N m].

Raises
------
ValueError
    A field of another shape, or a quantity of another dimension (the message names it).

See Also
--------
inverse_dynamics, PlanarAcceleration

Examples
--------
>>> body = rd.PlanarBody(2.0, 0.5)
>>> rd.inverse_dynamics(body, rd.PlanarBodyState(), a_W=[1.0, 0.0], alpha_B=2.0)
PlanarWrench(f_W=[2.0, 0.0], tau=1.0)
)doc");
  planar_wrench
      .def(py::init([](py::handle f_W, py::handle tau) {
             return PlanarWrench{py_io::as_vector2_or_zero(py_io::in_si(f_W, "N", "f_W"), "f_W"),
                                 py_io::as_scalar(py_io::in_si(tau, "N*m", "tau"), "tau")};
           }),
           py::arg("f_W") = py::none(), py::arg("tau") = 0.0)
      .def_property_readonly("f_W", [](const PlanarWrench& w) { return read_only(w.f_W); },
                             "Force f_W in W's xy plane, shape (2,) [N].")
      .def_readonly("tau", &PlanarWrench::tau, "Torque tau about the z axis through the centre of mass [N m].")
      .def("__repr__", [](const PlanarWrench& w) {
        return repr_call("PlanarWrench", {{"f_W", as_list(w.f_W)}, {"tau", py::float_(w.tau)}});
      })
      .def(py::pickle([](const PlanarWrench& w) { return py::make_tuple(py_io::to_array(w.f_W), w.tau); },
                      [](const py::tuple& t) {
                        pickled(t, 2, "PlanarWrench");
                        return PlanarWrench{unpickled<2>(t[0], "PlanarWrench pickle f_W"), t[1].cast<double>()};
                      }));
  def_equality(planar_wrench, [](const PlanarWrench& a, const PlanarWrench& b) { return a.f_W == b.f_W && a.tau == b.tau; });
  def_as_pair(planar_wrench, [](const PlanarWrench& w) { return py::make_tuple(read_only(w.f_W), w.tau); });

  py::class_<BodyAcceleration> acceleration(m, "BodyAcceleration", R"doc(Accelerations of a rigid body.

The centre of mass's acceleration in W and the angular acceleration in B: forward_dynamics' result for a
RigidBody; unpacks as ``a_W, alpha_B = ...``. Immutable; pickles.

Parameters
----------
a_W : array_like, shape (3,), or pint.Quantity, optional
    Centre of mass acceleration in W [m/s^2] (None: zero).
alpha_B : array_like, shape (3,), or pint.Quantity, optional
    Angular acceleration of B in W, expressed in B [rad/s^2] (None: zero).

Raises
------
ValueError
    A field of another shape, or a quantity of another dimension (the message names it).

See Also
--------
forward_dynamics, ComWrench

Examples
--------
1 N along y at 1 m along x: a_W = f/m, alpha_B = I^-1 (p_GP x f):

>>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
>>> a_W, alpha_B = rd.forward_dynamics(body, rd.RigidBodyState(), force=[0, 1.0, 0], point=[1.0, 0, 0])
>>> a_W, alpha_B.round(12)
(array([0. , 0.5, 0. ]), array([0.        , 0.        , 0.33333333]))
)doc");
  acceleration
      .def(py::init([](py::handle a_W, py::handle alpha_B) {
             return BodyAcceleration{py_io::as_vector3_or_zero(py_io::in_si(a_W, "m/s^2", "a_W"), "a_W"),
                                     py_io::as_vector3_or_zero(py_io::in_si(alpha_B, "rad/s^2", "alpha_B"), "alpha_B")};
           }),
           py::arg("a_W") = py::none(), py::arg("alpha_B") = py::none())
      .def_property_readonly("a_W", [](const BodyAcceleration& a) { return read_only(a.a_W); },
                             "Centre of mass acceleration a_W in W, shape (3,) [m/s^2].")
      .def_property_readonly("alpha_B", [](const BodyAcceleration& a) { return read_only(a.alpha_B); },
                             "Angular acceleration alpha_B of B in W, expressed in B, shape (3,) [rad/s^2].")
      .def("__repr__", [](const BodyAcceleration& a) {
        return repr_call("BodyAcceleration", {{"a_W", as_list(a.a_W)}, {"alpha_B", as_list(a.alpha_B)}});
      })
      .def(py::pickle(
          [](const BodyAcceleration& a) { return py::make_tuple(py_io::to_array(a.a_W), py_io::to_array(a.alpha_B)); },
          [](const py::tuple& t) {
            pickled(t, 2, "BodyAcceleration");
            return BodyAcceleration{unpickled<3>(t[0], "BodyAcceleration pickle a_W"),
                                    unpickled<3>(t[1], "BodyAcceleration pickle alpha_B")};
          }));
  def_equality(acceleration,
               [](const BodyAcceleration& a, const BodyAcceleration& b) { return a.a_W == b.a_W && a.alpha_B == b.alpha_B; });
  def_as_pair(acceleration, [](const BodyAcceleration& a) { return py::make_tuple(read_only(a.a_W), read_only(a.alpha_B)); });

  py::class_<PlanarAcceleration> planar_acceleration(m, "PlanarAcceleration", R"doc(Accelerations of a planar body.

The centre of mass's acceleration in W's xy plane and the angular acceleration about z: forward_dynamics'
result for a PlanarBody; unpacks as ``a_W, alpha = ...``. Immutable; pickles.

Parameters
----------
a_W : array_like, shape (2,), or pint.Quantity, optional
    Centre of mass acceleration in W [m/s^2] (None: zero).
alpha : float or pint.Quantity, default 0
    Angular acceleration about z [rad/s^2].

Raises
------
ValueError
    A field of another shape, or a quantity of another dimension (the message names it).

See Also
--------
forward_dynamics, PlanarWrench

Examples
--------
>>> body = rd.PlanarBody(2.0, 0.5)
>>> rd.forward_dynamics(body, rd.PlanarBodyState(), force=[0, 1.0], point=[1.0, 0])
PlanarAcceleration(a_W=[0.0, 0.5], alpha=2.0)
)doc");
  planar_acceleration
      .def(py::init([](py::handle a_W, py::handle alpha) {
             return PlanarAcceleration{py_io::as_vector2_or_zero(py_io::in_si(a_W, "m/s^2", "a_W"), "a_W"),
                                       py_io::as_scalar(py_io::in_si(alpha, "rad/s^2", "alpha"), "alpha")};
           }),
           py::arg("a_W") = py::none(), py::arg("alpha") = 0.0)
      .def_property_readonly("a_W", [](const PlanarAcceleration& a) { return read_only(a.a_W); },
                             "Centre of mass acceleration a_W in W's xy plane, shape (2,) [m/s^2].")
      .def_readonly("alpha", &PlanarAcceleration::alpha, "Angular acceleration alpha about z [rad/s^2].")
      .def("__repr__", [](const PlanarAcceleration& a) {
        return repr_call("PlanarAcceleration", {{"a_W", as_list(a.a_W)}, {"alpha", py::float_(a.alpha)}});
      })
      .def(py::pickle([](const PlanarAcceleration& a) { return py::make_tuple(py_io::to_array(a.a_W), a.alpha); },
                      [](const py::tuple& t) {
                        pickled(t, 2, "PlanarAcceleration");
                        return PlanarAcceleration{unpickled<2>(t[0], "PlanarAcceleration pickle a_W"), t[1].cast<double>()};
                      }));
  def_equality(planar_acceleration,
               [](const PlanarAcceleration& a, const PlanarAcceleration& b) { return a.a_W == b.a_W && a.alpha == b.alpha; });
  def_as_pair(planar_acceleration, [](const PlanarAcceleration& a) { return py::make_tuple(read_only(a.a_W), a.alpha); });
}

// Results with a warning when not finite (RuntimeWarning naming the quantity).
BodyAcceleration checked(const BodyAcceleration& a, const char* quantity) {
  py_io::warn_unless_finite(a.a_W.allFinite() && a.alpha_B.allFinite(), quantity,
                            "a_W " + format_value(a.a_W.transpose()) + ", alpha_B " + format_value(a.alpha_B.transpose()));
  return a;
}
PlanarAcceleration checked(const PlanarAcceleration& a, const char* quantity) {
  py_io::warn_unless_finite(a.a_W.allFinite() && std::isfinite(a.alpha), quantity,
                            "a_W " + format_value(a.a_W.transpose()) + ", alpha " + format_value(a.alpha));
  return a;
}
ComWrench checked(const ComWrench& w, const char* quantity) {
  py_io::warn_unless_finite(w.f_W.allFinite() && w.tau_B.allFinite(), quantity,
                            "f_W " + format_value(w.f_W.transpose()) + ", tau_B " + format_value(w.tau_B.transpose()));
  return w;
}
PlanarWrench checked(const PlanarWrench& w, const char* quantity) {
  py_io::warn_unless_finite(w.f_W.allFinite() && std::isfinite(w.tau), quantity,
                            "f_W " + format_value(w.f_W.transpose()) + ", tau " + format_value(w.tau));
  return w;
}

// ------------------------------------------------------------ the functions' docs (numpydoc)

const char* const state_param_doc =
    "body : RigidBody, PlanarBody or Particle\n"
    "    The body.\n"
    "state : RigidBodyState, PlanarBodyState or ParticleState\n"
    "    Its state, of the body's kind and finite (a state a diverged step returned is refused).\n";

const char* const state_raises_doc =
    "TypeError\n"
    "    body not one of the kinds listed, or state not of the body's kind (the message names it).\n"
    "ValueError\n"
    "    A state that is not finite or whose quaternion is farther than 1e-6 from unit norm (the message names\n"
    "    state.<field>); an argument of another shape, or a quantity of another dimension (the message names it).\n";

const std::string forward_dynamics_doc = std::string(
    "Accelerations of `body` in `state` under an applied force, torque and gravity.\n"
    R"doc(
The force f acts at `point` P (p_GP from the centre of mass G) and reduces to G as f and tau_G = tau + p_GP x f.
Per body kind:

- RigidBody: Newton m a_W = f_W + m g_W, Euler I alpha_B + w_B x I w_B = tau_B (I about G, in B).
- PlanarBody: m a_W = f_W + m g_W in W's xy plane, I_zz alpha = tau_G about z.
- Particle: a_W = f_W / m + g_W.
)doc") + pivoted_forward_dynamics_doc + R"doc(
Parameters
----------
body : RigidBody, PlanarBody, Particle, PivotedBody or PivotedPlanarBody
    The body.
state : RigidBodyState, PlanarBodyState, ParticleState, PivotedBodyState or PivotedPlanarBodyState
    Its state, of the body's kind and finite (a state a diverged step returned is refused).
force : array_like, shape (3,) or (2,), or pint.Quantity, optional
    Applied force f [N], expressed in `frame` (None: zero); shape (2,), in the plane, for the planar bodies.
torque : array_like, shape (3,), float or pint.Quantity, optional
    Applied torque tau [N m], expressed in `frame` (None: zero); a float about z for the planar bodies. A
    Particle takes None.
point : array_like, shape (3,) or (2,), or pint.Quantity, optional
    Point of application of the force, p_GP [m] from the centre of mass, expressed in `frame` (None: the
    centre of mass). A Particle takes None.
frame : {'world', 'body'}, default 'world'
    Frame of force, torque and point: W or B. A Particle takes 'world'.
gravity : None, bool or array_like, default None
    Uniform gravity g_W [m/s^2] in W: None (no gravity, docs/conventions.md), True (0, 0, -9.81) (False:
    none), or a vector, shape (3,). PlanarBody: None or an in-plane vector, shape (2,). PivotedPlanarBody: None
    or an in-plane vector, shape (2,) or (3,).

Returns
-------
BodyAcceleration, PlanarAcceleration, ndarray, PivotedAcceleration or PivotedPlanarAcceleration
    RigidBody: BodyAcceleration (a_W, shape (3,) [m/s^2] in W; alpha_B, shape (3,) [rad/s^2] in B).
    PlanarBody: PlanarAcceleration (a_W, shape (2,); alpha [rad/s^2] about z). Particle: a_W, ndarray of
    shape (3,) [m/s^2] in W. PivotedBody: PivotedAcceleration. PivotedPlanarBody: PivotedPlanarAcceleration.

Raises
------
)doc" + state_raises_doc + R"doc(ValueError
    torque or point given for a Particle, or frame 'body' for it; gravity True or False for a planar body.

Warns
-----
RuntimeWarning
    The result is not finite (an overflow; the message names forward_dynamics).

See Also
--------
inverse_dynamics, simulate, step

Examples
--------
>>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
>>> rd.forward_dynamics(body, rd.RigidBodyState(), gravity=True)
BodyAcceleration(a_W=[0.0, 0.0, -9.81], alpha_B=[0.0, 0.0, 0.0])

Torque-free, a spin about two principal axes still accelerates (the gyroscopic term -I^-1 (w_B x I w_B)):

>>> rd.forward_dynamics(body, rd.RigidBodyState(w_B=[1.0, 1.0, 0.0])).alpha_B.round(12)
array([ 0.        ,  0.        , -0.33333333])

A rod of L = 2 m and 3 kg pinned at one end, held horizontal, starts at alpha = -3 g / (2 L):

>>> rod = rd.PivotedPlanarBody(3.0, 3.0 * 2.0**2 / 12, p_OC_B=[1.0, 0.0])
>>> print(f"{rd.forward_dynamics(rod, rd.PivotedPlanarBodyState(), gravity=[0.0, -9.81]).alpha:.6f}")
-7.357500
)doc";

const std::string inverse_dynamics_doc = std::string(
    "The applied loads a motion requires, reduced to the centre of mass (undoes forward_dynamics).\n"
    R"doc(
Per body kind:

- RigidBody: f_W = m (a_W - g_W) in W, tau_B = I alpha_B + w_B x I w_B about the centre of mass in B.
- PlanarBody: f_W = m (a_W - g_W) in W's xy plane, tau = I_zz alpha about z.
- Particle: f_W = m (a_W - g_W).
)doc") + pivoted_inverse_dynamics_doc + R"doc(
Parameters
----------
body : RigidBody, PlanarBody, Particle, PivotedBody or PivotedPlanarBody
    The body.
state : RigidBodyState, PlanarBodyState, ParticleState, PivotedBodyState or PivotedPlanarBodyState
    Its state, of the body's kind and finite.
a_W : array_like, shape (3,) or (2,), or pint.Quantity
    Centre of mass acceleration in W [m/s^2]; shape (2,) for a PlanarBody. Required, except for the pivoted
    bodies, which take None (the pivot fixes it).
alpha_B : array_like, shape (3,), float or pint.Quantity
    Angular acceleration in B [rad/s^2]; a float about z for the planar bodies. A Particle takes None.
gravity : None, bool or array_like, default None
    Uniform gravity g_W [m/s^2] in W, as forward_dynamics takes it.

Returns
-------
ComWrench, PlanarWrench, ndarray, PivotedTorque or PivotedPlanarTorque
    RigidBody: ComWrench (f_W, shape (3,) [N] in W; tau_B, shape (3,) [N m] in B). PlanarBody: PlanarWrench
    (f_W, shape (2,); tau [N m] about z). Particle: f_W, ndarray of shape (3,) [N] in W. PivotedBody:
    PivotedTorque. PivotedPlanarBody: PivotedPlanarTorque.

Raises
------
)doc" + state_raises_doc + R"doc(TypeError
    a_W or alpha_B None where the body needs it (the message names it).
ValueError
    alpha_B given for a Particle; a_W given for a pivoted body.

Warns
-----
RuntimeWarning
    The result is not finite (an overflow; the message names inverse_dynamics).

See Also
--------
forward_dynamics, ComWrench, PivotedTorque

Examples
--------
It undoes forward_dynamics, gyroscopic term included:

>>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
>>> s = rd.RigidBodyState(w_B=[1.0, 1.0, 0.0])
>>> a = rd.forward_dynamics(body, s, force=[1.0, 0, 0], torque=[0, 0.5, 0], gravity=True)
>>> w = rd.inverse_dynamics(body, s, a_W=a.a_W, alpha_B=a.alpha_B, gravity=True)
>>> np.allclose(w.f_W, [1, 0, 0]), np.allclose(w.tau_B, [0, 0.5, 0])
(True, True)

The torque about the pivot that holds a top of 1 kg horizontal, its centre of mass 0.5 m out along x:

>>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.1, 0.1, 0.2]), p_OC_B=[0.0, 0.0, 0.5])
>>> level = rd.PivotedBodyState(q_WB=rd.rotvec_to_quat([0.0, np.pi / 2, 0.0]))
>>> rd.inverse_dynamics(top, level, alpha_B=[0, 0, 0], gravity=True).tau_O_B.round(12)
array([ 0.   , -4.905,  0.   ])
)doc";

const std::string linear_momentum_doc = std::string(R"doc(Linear momentum m v_W [kg m/s] of the centre of mass, in W.

Parameters
----------
)doc") + state_param_doc + R"doc(
Returns
-------
ndarray, shape (3,) or (2,)
    m v_W [kg m/s] in W; shape (2,) for a PlanarBody.

Raises
------
)doc" + state_raises_doc + R"doc(
See Also
--------
angular_momentum, kinetic_energy, apply_impulse

Examples
--------
>>> rd.linear_momentum(rd.Particle(3.0), rd.ParticleState(v_W=[0.0, 2.0, 0.0]))
array([0., 6., 0.])
)doc";

const std::string angular_momentum_doc = std::string(R"doc(Angular momentum about a point P fixed in W, expressed in W.

About P at p_WP ("Rigid body kinematics and dynamics" notes, eq. (4.42) and (4.65); None: the origin O of W):

- RigidBody: H_P = R_WB I w_B + (p_W - p_WP) x m v_W, shape (3,);
- PlanarBody: H_z = I_zz omega + (p_W - p_WP) x m v_W about the z axis through P, a float;
- Particle: (p_W - p_WP) x m v_W, shape (3,).

About the centre of mass: point=state.p_W.

Parameters
----------
)doc") + state_param_doc + R"doc(point : array_like, shape (3,) or (2,), or pint.Quantity, optional
    p_WP, the point P in W [m] (None: the origin of W); shape (2,) for a PlanarBody.

Returns
-------
ndarray, shape (3,), or float
    H_P [kg m^2/s] in W; for a PlanarBody, H_z [kg m^2/s] about z.

Raises
------
)doc" + state_raises_doc + R"doc(
See Also
--------
linear_momentum, kinetic_energy

Examples
--------
Spin I w = 6 about the centre of mass plus the orbit p_W x m v_W = 2 about the origin:

>>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
>>> s = rd.RigidBodyState(p_W=[1, 0, 0], v_W=[0, 1, 0], w_B=[0, 0, 2])
>>> rd.angular_momentum(body, s), rd.angular_momentum(body, s, point=s.p_W)
(array([0., 0., 8.]), array([0., 0., 6.]))
)doc";

const std::string kinetic_energy_doc = std::string(
    "Kinetic energy [J], split into its translational and rotational parts.\n"
    R"doc(
translational = 1/2 m v_W.v_W, rotational = 1/2 w_B.I w_B about the centre of mass (1/2 I_zz omega^2 for a
PlanarBody, 0 for a Particle), total = their sum.

Parameters
----------
)doc") + state_param_doc + R"doc(
Returns
-------
KineticEnergy
    translational, rotational and total [J].

Raises
------
)doc" + state_raises_doc + R"doc(
Warns
-----
RuntimeWarning
    A part is not finite (an overflow; the message names kinetic_energy).

See Also
--------
KineticEnergy, potential_energy, simulate

Examples
--------
A torque-free body keeps its kinetic energy:

>>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
>>> s0 = rd.RigidBodyState(v_W=[1, 0, 0], w_B=[1.0, 0.1, 0.2])
>>> s1 = rd.step(body, s0, 0.001, method="rkmk4")
>>> rd.kinetic_energy(body, s0).total, f"{rd.kinetic_energy(body, s1).total:.12f}"
(1.57, '1.570000000000')
)doc";

const std::string potential_energy_doc = std::string(
    "Potential energy of uniform gravity, V = -m g_W.p_W [J] (zero at the origin of W).\n"
    R"doc(
Parameters
----------
)doc") + state_param_doc + R"doc(gravity : None, bool or array_like, default None
    g_W [m/s^2] in W: None (the default, as in simulate: no field, so V = 0 J), True (0, 0, -9.81) or a
    vector, shape (3,); for a PlanarBody None or an in-plane vector, shape (2,).

Returns
-------
float
    V [J].

Raises
------
)doc" + state_raises_doc + R"doc(
See Also
--------
kinetic_energy, simulate

Examples
--------
>>> V = rd.potential_energy(rd.Particle(2.0), rd.ParticleState(p_W=[0, 0, 10.0]), gravity=True)
>>> print(f"{V:.6f}")  # m g h
196.200000
)doc";

const char* const power_doc = "Power [W] of a force at the centre of mass and a torque about it: f_W.v_W + tau_B.w_B.\n"
    R"doc(
Parameters
----------
state : RigidBodyState, PlanarBodyState or ParticleState
    The state, finite.
f_W : array_like, shape (3,) or (2,), or pint.Quantity
    Force at the centre of mass, in W [N]; shape (2,) for a PlanarBodyState.
tau_B : array_like, shape (3,), float or pint.Quantity, optional
    Torque about the centre of mass [N m] (None: none): in B, shape (3,), for a RigidBodyState; a float about
    z for a PlanarBodyState; None for a ParticleState.

Returns
-------
float
    The power [W].

Raises
------
TypeError
    state not one of the kinds listed (the message names it).
ValueError
    A state that is not finite, an argument of another shape or dimension, or tau_B for a ParticleState.

See Also
--------
inverse_dynamics, kinetic_energy

Examples
--------
>>> rd.power(rd.RigidBodyState(v_W=[1, 0, 0], w_B=[0, 0, 2]), f_W=[3, 0, 0], tau_B=[0, 0, 0.5])
4.0
)doc";

const std::string apply_impulse_doc = std::string("The state just after an impulse at a point and an angular impulse.\n"
    R"doc(
Impulse-momentum (K. Craig, "Rigid Body Dynamics" slides): m dv = impulse, I dw = p_GP x impulse +
angular_impulse, with p_GP the point of application from the centre of mass G; the position and the attitude
do not change.

Parameters
----------
)doc") + state_param_doc + R"doc(impulse : array_like, shape (3,) or (2,), or pint.Quantity
    The impulse [N s], in `frame`; shape (2,) for a PlanarBody.
point : array_like, shape (3,) or (2,), or pint.Quantity, optional
    p_GP [m] from the centre of mass, in `frame` (None: the centre of mass). A Particle takes None.
frame : {'world', 'body'}, default 'world'
    Frame of impulse, point and angular_impulse: W or B. A Particle takes 'world'.
angular_impulse : array_like, shape (3,), float or pint.Quantity, optional
    An angular impulse (impulsive torque) [N m s] in `frame` (None: none); a float about z for a PlanarBody.
    A Particle takes None.

Returns
-------
RigidBodyState, PlanarBodyState or ParticleState
    The state after the impulse.

Raises
------
)doc" + state_raises_doc + R"doc(ValueError
    point or angular_impulse given for a Particle, or frame 'body' for it.

Warns
-----
RuntimeWarning
    The new velocities are not finite (an overflow).

See Also
--------
linear_momentum, angular_momentum

Examples
--------
2 N s along y at 1 m along x: dv = J / m, dw_z = (p_GP x J)_z / I_zz = 2 / 3:

>>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
>>> after = rd.apply_impulse(body, rd.RigidBodyState(), impulse=[0, 2.0, 0], point=[1.0, 0, 0])
>>> after.v_W, after.w_B.round(12)
(array([0., 1., 0.]), array([0.        , 0.        , 0.66666667]))
)doc";


void bind_dynamics_functions(py::module_& m) {
  m.def(
      "forward_dynamics",
      [](py::handle body, py::handle state, py::handle force, py::handle torque, py::handle point, py::handle frame_arg,
         py::handle gravity) {
        if (is_pivoted(body)) return pivoted_forward_dynamics_py(body, state, force, torque, point, frame_arg, gravity);
        const Frame frame = as_frame(frame_arg);
        return dispatch(
            body, state,
            [&](const RigidBody& b, const RigidBodyState& s) {
              const ComWrench w =
                  wrench_at_com(s.q_WB, py_io::as_vector3_or_zero(py_io::in_si(force, "N", "force"), "force"),
                                py_io::as_vector3_or_zero(py_io::in_si(torque, "N*m", "torque"), "torque"),
                                py_io::as_vector3_or_zero(py_io::in_si(point, "m", "point"), "point"), frame);
              return checked(forward_dynamics(b, s, w, as_gravity(gravity)), "forward_dynamics");
            },
            [&](const PlanarBody& b, const PlanarBodyState& s) {
              const double tau = torque.is_none() ? 0.0 : py_io::as_scalar(py_io::in_si(torque, "N*m", "torque"), "torque");
              const PlanarWrench w =
                  wrench_at_com(s.theta, py_io::as_vector2_or_zero(py_io::in_si(force, "N", "force"), "force"), tau,
                                py_io::as_vector2_or_zero(py_io::in_si(point, "m", "point"), "point"), frame);
              return checked(forward_dynamics(b, s, w, as_planar_gravity(gravity)), "forward_dynamics");
            },
            [&](const Particle& p, const ParticleState& s) {
              require_none_for_particle(torque, "torque", "a point mass takes no torque");
              require_none_for_particle(point, "point", "a point mass has one point");
              if (frame != Frame::world) py_io::throw_value_error("frame", "'world' for a Particle", "'body'");
              const Eigen::Vector3d f_W = py_io::as_vector3_or_zero(py_io::in_si(force, "N", "force"), "force");
              return finite_result(forward_dynamics(p, s, f_W, as_gravity(gravity)), "forward_dynamics a_W");
            });
      },
      py::arg("body"), py::arg("state"), py::arg("force") = py::none(), py::arg("torque") = py::none(),
      py::arg("point") = py::none(), py::arg("frame") = "world", py::arg("gravity") = py::none(),
      forward_dynamics_doc.c_str());

  m.def(
      "inverse_dynamics",
      [](py::handle body, py::handle state, py::handle a_W, py::handle alpha_B, py::handle gravity) {
        if (is_pivoted(body)) return pivoted_inverse_dynamics_py(body, state, a_W, alpha_B, gravity);
        return dispatch(
            body, state,
            [&](const RigidBody& b, const RigidBodyState& s) {
              return checked(inverse_dynamics(b, s,
                                              BodyAcceleration{py_io::as_vector3(py_io::in_si(a_W, "m/s^2", "a_W"), "a_W"),
                                                               py_io::as_vector3(py_io::in_si(alpha_B, "rad/s^2", "alpha_B"), "alpha_B")},
                                              as_gravity(gravity)),
                             "inverse_dynamics");
            },
            [&](const PlanarBody& b, const PlanarBodyState& s) {
              return checked(inverse_dynamics(b, s,
                                              PlanarAcceleration{py_io::as_vector2(py_io::in_si(a_W, "m/s^2", "a_W"), "a_W"),
                                                                 py_io::as_scalar(py_io::in_si(alpha_B, "rad/s^2", "alpha_B"), "alpha_B")},
                                              as_planar_gravity(gravity)),
                             "inverse_dynamics");
            },
            [&](const Particle& p, const ParticleState& s) {
              require_none_for_particle(alpha_B, "alpha_B", "a point mass has no angular acceleration");
              return finite_result(inverse_dynamics(p, s,
                  py_io::as_vector3(py_io::in_si(a_W, "m/s^2", "a_W"), "a_W"), as_gravity(gravity)),
                                   "inverse_dynamics f_W");
            });
      },
      py::arg("body"), py::arg("state"), py::arg("a_W") = py::none(), py::arg("alpha_B") = py::none(), py::arg("gravity") = py::none(),
      inverse_dynamics_doc.c_str());

  m.def(
      "linear_momentum",
      [](py::handle body, py::handle state) {
        return dispatch(
            body, state,
            [](const RigidBody& b, const RigidBodyState& s) { return finite_result(linear_momentum(b, s), "linear_momentum"); },
            [](const PlanarBody& b, const PlanarBodyState& s) { return finite_result(linear_momentum(b, s), "linear_momentum"); },
            [](const Particle& p, const ParticleState& s) { return finite_result(linear_momentum(p, s), "linear_momentum"); });
      },
      py::arg("body"), py::arg("state"), linear_momentum_doc.c_str());

  m.def(
      "angular_momentum",
      [](py::handle body, py::handle state, py::handle point) {
        return dispatch(
            body, state,
            [&](const RigidBody& b, const RigidBodyState& s) {
              return finite_result(angular_momentum(b, s,
                  py_io::as_vector3_or_zero(py_io::in_si(point, "m", "point"), "point")), "angular_momentum");
            },
            [&](const PlanarBody& b, const PlanarBodyState& s) {
              return finite_result(angular_momentum(b, s,
                  py_io::as_vector2_or_zero(py_io::in_si(point, "m", "point"), "point")), "angular_momentum");
            },
            [&](const Particle& p, const ParticleState& s) {
              return finite_result(angular_momentum(p, s,
                  py_io::as_vector3_or_zero(py_io::in_si(point, "m", "point"), "point")), "angular_momentum");
            });
      },
      py::arg("body"), py::arg("state"), py::arg("point") = py::none(),
      angular_momentum_doc.c_str());

  m.def(
      "kinetic_energy",
      [](py::handle body, py::handle state) {
        return dispatch(
            body, state, [](const RigidBody& b, const RigidBodyState& s) { return checked(kinetic_energy(b, s)); },
            [](const PlanarBody& b, const PlanarBodyState& s) { return checked(kinetic_energy(b, s)); },
            [](const Particle& p, const ParticleState& s) { return checked(kinetic_energy(p, s)); });
      },
      py::arg("body"), py::arg("state"),
      kinetic_energy_doc.c_str());

  m.def(
      "potential_energy",
      [](py::handle body, py::handle state, py::handle gravity) {
        return dispatch(
            body, state,
            [&](const RigidBody& b, const RigidBodyState& s) {
              return finite_result(potential_energy(b, s, as_gravity(gravity)), "potential_energy");
            },
            [&](const PlanarBody& b, const PlanarBodyState& s) {
              return finite_result(potential_energy(b, s, as_planar_gravity(gravity)), "potential_energy");
            },
            [&](const Particle& p, const ParticleState& s) {
              return finite_result(potential_energy(p, s, as_gravity(gravity)), "potential_energy");
            });
      },
      py::arg("body"), py::arg("state"), py::arg("gravity") = py::none(),
      potential_energy_doc.c_str());

  m.def(
      "power",
      [](py::handle state, py::handle f_W, py::handle tau_B) -> py::object {
        if (is_instance<RigidBodyState>(state)) {
          const RigidBodyState& s = checked_state_of<RigidBodyState>(state, "RigidBody");
          return py::cast(finite_result(
              power(s, ComWrench{py_io::as_vector3(py_io::in_si(f_W, "N", "f_W"), "f_W"),
                                 py_io::as_vector3_or_zero(py_io::in_si(tau_B, "N*m", "tau_B"), "tau_B")}), "power"));
        }
        if (is_instance<PlanarBodyState>(state)) {
          const PlanarBodyState& s = checked_state_of<PlanarBodyState>(state, "PlanarBody");
          const double tau = tau_B.is_none() ? 0.0 : py_io::as_scalar(py_io::in_si(tau_B, "N*m", "tau_B"), "tau_B");
          return py::cast(finite_result(power(s, PlanarWrench{py_io::as_vector2(py_io::in_si(f_W, "N", "f_W"), "f_W"), tau}), "power"));
        }
        if (is_instance<ParticleState>(state)) {
          const ParticleState& s = checked_state_of<ParticleState>(state, "Particle");
          require_none_for_particle(tau_B, "tau_B", "a point mass takes no torque");
          return py::cast(finite_result(power(s, py_io::as_vector3(py_io::in_si(f_W, "N", "f_W"), "f_W")), "power"));
        }
        py_io::throw_type_error("state", "a RigidBodyState, PlanarBodyState or ParticleState", state);
      },
      py::arg("state"), py::arg("f_W"), py::arg("tau_B") = py::none(),
      power_doc);

  m.def(
      "apply_impulse",
      [](py::handle body, py::handle state, py::handle impulse, py::handle point, py::handle frame_arg,
         py::handle angular_impulse) {
        const Frame frame = as_frame(frame_arg);
        return dispatch(
            body, state,
            [&](const RigidBody& b, const RigidBodyState& s) {
              return checked(apply_impulse(b, s, py_io::as_vector3(py_io::in_si(impulse, "N*s", "impulse"), "impulse"),
                                           py_io::as_vector3_or_zero(py_io::in_si(point, "m", "point"), "point"), frame,
                                           py_io::as_vector3_or_zero(py_io::in_si(angular_impulse, "N*m*s", "angular_impulse"), "angular_impulse")),
                             "apply_impulse");
            },
            [&](const PlanarBody& b, const PlanarBodyState& s) {
              const double J = angular_impulse.is_none() ? 0.0 : py_io::as_scalar(py_io::in_si(angular_impulse, "N*m*s", "angular_impulse"), "angular_impulse");
              return checked(apply_impulse(b, s, py_io::as_vector2(py_io::in_si(impulse, "N*s", "impulse"), "impulse"),
                                           py_io::as_vector2_or_zero(py_io::in_si(point, "m", "point"), "point"), frame, J),
                             "apply_impulse");
            },
            [&](const Particle& p, const ParticleState& s) {
              require_none_for_particle(point, "point", "a point mass has one point");
              require_none_for_particle(angular_impulse, "angular_impulse", "a point mass takes no angular impulse");
              if (frame != Frame::world) py_io::throw_value_error("frame", "'world' for a Particle", "'body'");
              return checked(apply_impulse(p, s,
                  py_io::as_vector3(py_io::in_si(impulse, "N*s", "impulse"), "impulse")), "apply_impulse");
            });
      },
      py::arg("body"), py::arg("state"), py::arg("impulse"), py::arg("point") = py::none(),
      py::arg("frame") = "world", py::arg("angular_impulse") = py::none(),
      apply_impulse_doc.c_str());
}

}  // namespace

void bind_bodies(py::module_& m) {
  bind_models(m);
  bind_result_types(m);
  bind_dynamics_functions(m);
}

}  // namespace rigiddyn::bindings
