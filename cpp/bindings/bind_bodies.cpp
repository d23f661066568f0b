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
  if (py::isinstance<SpatialInertia>(mass)) {
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
  out.attr("flags").attr("writeable") = false;
  return out;
}
using py_io::read_only;

bool same(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) { return a.coeffs() == b.coeffs(); }

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
  if (py::isinstance<RigidBody>(body)) {
    return to_object(rigid(body.cast<const RigidBody&>(), checked_state_of<RigidBodyState>(state, "RigidBody")));
  }
  if (py::isinstance<PlanarBody>(body)) {
    return to_object(planar(body.cast<const PlanarBody&>(), checked_state_of<PlanarBodyState>(state, "PlanarBody")));
  }
  if (py::isinstance<Particle>(body)) {
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
  py::class_<Particle> particle(m, "Particle",
                                "A point mass (3 DOF; \"Rigid body kinematics and dynamics\" notes, section 4.11): mass "
                                "float [kg] > 0 or a pint quantity.");
  particle.def(py::init([](py::handle mass) { return Particle(py_io::as_scalar(py_io::in_si(mass, "kg", "mass"), "mass")); }), py::arg("mass"))
      .def_property_readonly("mass", &Particle::mass, "mass [kg]")
      .def("__repr__", [](const Particle& p) { return repr_call("Particle", {{"mass", py::float_(p.mass())}}); })
      .def(py::pickle([](const Particle& p) { return py::make_tuple(p.mass()); },
                      [](const py::tuple& t) { return Particle(pickled(t, 1, "Particle")[0].cast<double>()); }));
  def_equality(particle, [](const Particle& a, const Particle& b) { return a.mass() == b.mass(); });

  py::class_<PlanarBody> planar(m, "PlanarBody",
                                "A rigid body moving in the xy plane of W (x, y, theta; plane kinetics of Craig's \"Rigid "
                                "Body Dynamics\" slides): mass [kg] and inertia_zz [kg m^2] about the z axis through the "
                                "centre of mass, both > 0; each a float [unit] or a pint quantity.");
  planar
      .def(py::init([](py::handle mass, py::handle inertia_zz) {
             return PlanarBody(py_io::as_scalar(py_io::in_si(mass, "kg", "mass"), "mass"),
                               py_io::as_scalar(py_io::in_si(inertia_zz, "kg*m^2", "inertia_zz"), "inertia_zz"));
           }),
           py::arg("mass"), py::arg("inertia_zz"))
      .def_property_readonly("mass", &PlanarBody::mass, "mass [kg]")
      .def_property_readonly("inertia_zz", &PlanarBody::inertia_zz, "moment of inertia about z through G [kg m^2]")
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
      m, "RigidBody",
      "A spatial rigid body (6 DOF), in three forms:\n"
      "  RigidBody(mass, [I1, I2, I3])  mass [kg] > 0 and principal moments [kg m^2] about the centre of mass\n"
      "                                 (the body axes B principal: inertia_com = diag(I1, I2, I3));\n"
      "  RigidBody(mass, inertia_com)   inertia_com (3, 3) [kg m^2] about the centre of mass in B, moments on the\n"
      "                                 diagonal and negated products off it (I_xy = -sum x y dm);\n"
      "  RigidBody(spatial_inertia)     a SpatialInertia: its mass and inertia about its centre of mass, B placed\n"
      "                                 at the centre of mass with the SpatialInertia's axes.\n"
      "The inertia must be symmetric positive definite and is checked as every inertia of rigiddyn is\n"
      "(inertia_report): under check=InertiaCheck.physical (the default) the principal moments must satisfy the\n"
      "triangle inequality I_a + I_b >= I_c; check=InertiaCheck.allow_unrealizable accepts test bodies no real\n"
      "body has, e.g. I = diag(2, 1, 2/3). euler_form tells which form of Euler's equations it uses:\n"
      "'spherical', 'principal' or 'full'.\n"
      "mass and inertia_com: floats [kg], [kg m^2] or pint quantities (an array quantity for the inertia; converted, "
      "ValueError naming the argument for another dimension).");
  body.def(py::init(&as_rigid_body), py::arg("mass"), py::arg("inertia_com") = py::none(), py::arg("check") = py::none())
      .def_property_readonly("mass", &RigidBody::mass, "mass [kg]")
      .def_property_readonly(
          "inertia_com", [](const RigidBody& b) { return read_only(b.inertia_com()); },
          "(3, 3) inertia about the centre of mass in B [kg m^2] (read-only)")
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
          "'spherical' (no gyroscopic term), 'principal' (diagonal inertia) or 'full'")
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
  py::class_<ParticleState> particle(m, "ParticleState",
                                     "Particle state: p_W (3,) [m] and v_W (3,) [m/s] in W (None: zero), each floats [unit] "
                                     "or a pint quantity. Fields are assigned whole (s.v_W = [...]); their arrays are "
                                     "read-only.");
  particle
      .def(py::init([](py::handle p_W, py::handle v_W) {
             return ParticleState{py_io::as_vector3_or_zero(py_io::in_si(p_W, "m", "p_W"), "p_W"),
                                  py_io::as_vector3_or_zero(py_io::in_si(v_W, "m/s", "v_W"), "v_W")};
           }),
           py::arg("p_W") = py::none(), py::arg("v_W") = py::none())
      .def_property(
          "p_W", [](const ParticleState& s) { return read_only(s.p_W); },
          [](ParticleState& s, py::handle v) {
            s.p_W = py_io::as_vector3(py_io::in_si(v, "m", "p_W"), "p_W"); }, "(3,) position in W [m]")
      .def_property(
          "v_W", [](const ParticleState& s) { return read_only(s.v_W); },
          [](ParticleState& s, py::handle v) {
            s.v_W = py_io::as_vector3(py_io::in_si(v, "m/s", "v_W"), "v_W"); }, "(3,) velocity in W [m/s]")
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

  py::class_<PlanarBodyState> planar(m, "PlanarBodyState",
                                     "Planar body state: p_W (2,) [m] centre of mass in W, theta [rad] angle of B about "
                                     "z, v_W (2,) [m/s] in W, omega [rad/s] (None: zero), each floats [unit] or a pint "
                                     "quantity. Fields are assigned whole; "
                                     "their arrays are read-only.");
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
            s.p_W = py_io::as_vector2(py_io::in_si(v, "m", "p_W"), "p_W"); }, "(2,) centre of mass in W [m]")
      .def_property(
          "theta", [](const PlanarBodyState& s) { return s.theta; },
          [](PlanarBodyState& s, py::handle v) {
            s.theta = py_io::as_scalar(py_io::in_si(v, "rad", "theta"), "theta"); }, "angle of B about z [rad]")
      .def_property(
          "v_W", [](const PlanarBodyState& s) { return read_only(s.v_W); },
          [](PlanarBodyState& s, py::handle v) {
            s.v_W = py_io::as_vector2(py_io::in_si(v, "m/s", "v_W"), "v_W"); }, "(2,) velocity in W [m/s]")
      .def_property(
          "omega", [](const PlanarBodyState& s) { return s.omega; },
          [](PlanarBodyState& s, py::handle v) {
            s.omega = py_io::as_scalar(py_io::in_si(v, "rad/s", "omega"), "omega"); }, "angular velocity [rad/s]")
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
      m, "RigidBodyState",
      "Rigid body state (docs/conventions.md): p_W (3,) centre of mass in W [m], q_WB (4,) unit quaternion "
      "(x, y, z, w), or (w, x, y, z) with scalar_first=True, v_W (3,) centre of mass velocity in W [m/s], w_B (3,) "
      "angular velocity [rad/s] in B (None: zero, identity); p_W, v_W, w_B: floats [unit] or pint quantities. "
      "q_WB is normalised; ValueError if | |q| - 1 | > 1e-6. "
      "Fields are assigned whole (s.w_B = [...], s.q_WB = [x, y, z, w], checked as here); their arrays are "
      "read-only.");
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
          "(3,) centre of mass position in W [m]")
      .def_property(
          "q_WB", [](const RigidBodyState& s) { return read_only(s.q_WB); },
          [](RigidBodyState& s, py::handle v) { s.q_WB = as_unit_quaternion(v, "q_WB"); },
          "(4,) attitude (x, y, z, w), B to W; set from (x, y, z, w), normalised (ValueError beyond 1e-6 of unit "
          "norm)")
      .def(
          "quaternion",
          [](const RigidBodyState& s, py::handle scalar_first) {
            return read_only(s.q_WB, py_io::as_bool(scalar_first, "scalar_first"));
          },
          py::arg("scalar_first") = false, "q_WB (4,) as (x, y, z, w), or (w, x, y, z) with scalar_first=True")
      .def_property(
          "v_W", [](const RigidBodyState& s) { return read_only(s.v_W); },
          [](RigidBodyState& s, py::handle v) { s.v_W = py_io::as_vector3(py_io::in_si(v, "m/s", "v_W"), "v_W"); },
          "(3,) centre of mass velocity in W [m/s]")
      .def_property(
          "w_B", [](const RigidBodyState& s) { return read_only(s.w_B); },
          [](RigidBodyState& s, py::handle v) { s.w_B = py_io::as_vector3(py_io::in_si(v, "rad/s", "w_B"), "w_B"); },
          "(3,) angular velocity of B in W, expressed in B [rad/s]")
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

const char* const body_state_doc =
    "body: a RigidBody, PlanarBody or Particle; state: its state (RigidBodyState, PlanarBodyState or "
    "ParticleState), finite (ValueError naming it otherwise, e.g. for a state a diverged step returned). ";

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
                                   "Kinetic energy [J] split as T = translational + rotational: translational 1/2 m v_W.v_W "
                                   "of the centre of mass, rotational 1/2 w_B.I w_B about it (1/2 I_zz omega^2 for a planar "
                                   "body, 0 for a particle); total = their sum. Immutable.");
  energy
      .def(py::init([](py::handle translational, py::handle rotational) {
             return KineticEnergy{py_io::as_extended_real(py_io::in_si(translational, "J", "translational"), "translational"),
                                  py_io::as_extended_real(py_io::in_si(rotational, "J", "rotational"), "rotational")};
           }),
           py::arg("translational") = 0.0, py::arg("rotational") = 0.0)
      .def_readonly("translational", &KineticEnergy::translational, "1/2 m v.v [J]")
      .def_readonly("rotational", &KineticEnergy::rotational, "1/2 w.I w about the centre of mass [J]")
      .def_property_readonly("total", &KineticEnergy::total, "translational + rotational [J]")
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
                               "Loads reduced to the centre of mass G: f_W (3,) force in W [N] and tau_B (3,) torque "
                               "about G in B [N m] (inverse_dynamics' result; unpacks as f_W, tau_B = ...). Immutable.");
  wrench
      .def(py::init([](py::handle f_W, py::handle tau_B) {
             return ComWrench{py_io::as_vector3_or_zero(py_io::in_si(f_W, "N", "f_W"), "f_W"),
                              py_io::as_vector3_or_zero(py_io::in_si(tau_B, "N*m", "tau_B"), "tau_B")};
           }),
           py::arg("f_W") = py::none(), py::arg("tau_B") = py::none())
      .def_property_readonly("f_W", [](const ComWrench& w) { return read_only(w.f_W); }, "(3,) force in W [N]")
      .def_property_readonly("tau_B", [](const ComWrench& w) { return read_only(w.tau_B); },
                             "(3,) torque about the centre of mass in B [N m]")
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

  py::class_<PlanarWrench> planar_wrench(m, "PlanarWrench",
                                         "In-plane loads reduced to the centre of mass G: f_W (2,) force in W [N] and tau "
                                         "torque about z through G [N m] (inverse_dynamics' result for a PlanarBody; "
                                         "unpacks as f_W, tau = ...). Immutable.");
  planar_wrench
      .def(py::init([](py::handle f_W, py::handle tau) {
             return PlanarWrench{py_io::as_vector2_or_zero(py_io::in_si(f_W, "N", "f_W"), "f_W"),
                                 py_io::as_scalar(py_io::in_si(tau, "N*m", "tau"), "tau")};
           }),
           py::arg("f_W") = py::none(), py::arg("tau") = 0.0)
      .def_property_readonly("f_W", [](const PlanarWrench& w) { return read_only(w.f_W); }, "(2,) force in W [N]")
      .def_readonly("tau", &PlanarWrench::tau, "torque about z through the centre of mass [N m]")
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

  py::class_<BodyAcceleration> acceleration(m, "BodyAcceleration",
                                            "Accelerations of a rigid body: a_W (3,) of the centre of mass in W [m/s^2] "
                                            "and alpha_B (3,) angular, in B [rad/s^2] (forward_dynamics' result; "
                                            "unpacks as a_W, alpha_B = ...). Immutable.");
  acceleration
      .def(py::init([](py::handle a_W, py::handle alpha_B) {
             return BodyAcceleration{py_io::as_vector3_or_zero(py_io::in_si(a_W, "m/s^2", "a_W"), "a_W"),
                                     py_io::as_vector3_or_zero(py_io::in_si(alpha_B, "rad/s^2", "alpha_B"), "alpha_B")};
           }),
           py::arg("a_W") = py::none(), py::arg("alpha_B") = py::none())
      .def_property_readonly("a_W", [](const BodyAcceleration& a) { return read_only(a.a_W); },
                             "(3,) centre of mass acceleration in W [m/s^2]")
      .def_property_readonly("alpha_B", [](const BodyAcceleration& a) { return read_only(a.alpha_B); },
                             "(3,) angular acceleration in B [rad/s^2]")
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

  py::class_<PlanarAcceleration> planar_acceleration(m, "PlanarAcceleration",
                                                     "Accelerations of a planar body: a_W (2,) of the centre of mass in W "
                                                     "[m/s^2] and alpha about z [rad/s^2] (forward_dynamics' result; "
                                                     "unpacks as a_W, alpha = ...). Immutable.");
  planar_acceleration
      .def(py::init([](py::handle a_W, py::handle alpha) {
             return PlanarAcceleration{py_io::as_vector2_or_zero(py_io::in_si(a_W, "m/s^2", "a_W"), "a_W"),
                                       py_io::as_scalar(py_io::in_si(alpha, "rad/s^2", "alpha"), "alpha")};
           }),
           py::arg("a_W") = py::none(), py::arg("alpha") = 0.0)
      .def_property_readonly("a_W", [](const PlanarAcceleration& a) { return read_only(a.a_W); },
                             "(2,) centre of mass acceleration in W [m/s^2]")
      .def_readonly("alpha", &PlanarAcceleration::alpha, "angular acceleration about z [rad/s^2]")
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
      (std::string("Accelerations of `body` in `state` under a force applied at `point` and a torque `torque`.\n") +
       body_state_doc +
       "\ngravity: None (the default: no gravity, docs/conventions.md), True = (0, 0, -9.81) m/s^2, or a vector "
       "[m/s^2] in W.\n"
       "RigidBody: force (3,) [N] at point (p_GP (3,) [m], from the centre of mass; None = the centre of mass), "
       "torque (3,) [N m], all expressed in `frame` ('world' or 'body'), gravity (3,); returns a BodyAcceleration "
       "(a_W (3,) [m/s^2] of the centre of mass in W, alpha_B (3,) [rad/s^2] in B; unpacks as a_W, alpha_B). "
       "Newton: m a = f + m g; Euler: I alpha + w x I w = tau_G.\n"
       "PlanarBody: in-plane force (2,) [N] at point (2,) [m], torque [N m] about z, gravity (2,) [m/s^2]; "
       "returns a PlanarAcceleration (a_W (2,), alpha [rad/s^2]); I_zz alpha = tau_G.\n"
       "Particle: force (3,) [N] in W (torque and point None, frame 'world'); returns a_W (3,) = force/m + g.\n" +
       pivoted_forward_dynamics_doc)
          .c_str());

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
      (std::string("The applied loads the motion requires, reduced to the centre of mass (undoes forward_dynamics).\n") +
       body_state_doc +
       "\ngravity: None (the default: no gravity), True = (0, 0, -9.81) m/s^2, or a vector [m/s^2] in W.\n"
       "RigidBody: a_W (3,) [m/s^2] in W, alpha_B (3,) [rad/s^2] in B; returns a ComWrench: f_W (3,) [N] in W and "
       "tau_B (3,) [N m] about the centre of mass in B (unpacks as f_W, tau_B), f_W = m (a_W - g), "
       "tau_B = I alpha_B + w_B x I w_B.\n"
       "PlanarBody: a_W (2,), alpha_B [rad/s^2] about z, gravity (2,); returns a PlanarWrench: f_W (2,) [N] in W "
       "and tau [N m] about z (unpacks as f_W, tau).\n"
       "Particle: a_W (3,) (alpha_B None); returns f_W (3,) [N] in W = m (a_W - g).\n" + pivoted_inverse_dynamics_doc)
          .c_str());

  m.def(
      "linear_momentum",
      [](py::handle body, py::handle state) {
        return dispatch(
            body, state,
            [](const RigidBody& b, const RigidBodyState& s) { return finite_result(linear_momentum(b, s), "linear_momentum"); },
            [](const PlanarBody& b, const PlanarBodyState& s) { return finite_result(linear_momentum(b, s), "linear_momentum"); },
            [](const Particle& p, const ParticleState& s) { return finite_result(linear_momentum(p, s), "linear_momentum"); });
      },
      py::arg("body"), py::arg("state"),
      (std::string("Linear momentum m v_W [kg m/s] in W: (3,), or (2,) for a PlanarBody. ") + body_state_doc).c_str());

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
      (std::string("Angular momentum about the point P fixed in W at `point` (p_WP [m] in W; None = the world origin "
                   "O, as the \"Rigid body kinematics and dynamics\" notes define it, eq. (4.42) and (4.65)), expressed "
                   "in W. About the centre of mass: point=state.p_W. ") +
       body_state_doc +
       "\nRigidBody: (3,) [kg m^2/s], H_P = R_WB I w_B + (p_W - p_WP) x m v_W. PlanarBody: H_z [kg m^2/s] "
       "about the z axis through P, I_zz omega + (p_W - p_WP) x m v_W, point (2,). Particle: (3,), "
       "(p_W - p_WP) x m v_W.")
          .c_str());

  m.def(
      "kinetic_energy",
      [](py::handle body, py::handle state) {
        return dispatch(
            body, state, [](const RigidBody& b, const RigidBodyState& s) { return checked(kinetic_energy(b, s)); },
            [](const PlanarBody& b, const PlanarBodyState& s) { return checked(kinetic_energy(b, s)); },
            [](const Particle& p, const ParticleState& s) { return checked(kinetic_energy(p, s)); });
      },
      py::arg("body"), py::arg("state"),
      (std::string("Kinetic energy as a KineticEnergy [J]: translational = 1/2 m v_W.v_W, rotational = 1/2 w_B.I w_B "
                   "about the centre of mass (1/2 I_zz omega^2 for a PlanarBody, 0 for a Particle), total = their "
                   "sum. ") +
       body_state_doc)
          .c_str());

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
      (std::string("Potential energy of uniform gravity, V = -m g.p_W [J] (zero at the origin of W). gravity: None "
                   "(the default, as in simulate: no field, so V = 0 J), True = (0, 0, -9.81) m/s^2, or a vector "
                   "(3,) [m/s^2] in W; for a PlanarBody None or an in-plane (2,) [m/s^2]. ") +
       body_state_doc)
          .c_str());

  m.def(
      "power",
      [](py::handle state, py::handle f_W, py::handle tau_B) -> py::object {
        if (py::isinstance<RigidBodyState>(state)) {
          const RigidBodyState& s = checked_state_of<RigidBodyState>(state, "RigidBody");
          return py::cast(finite_result(
              power(s, ComWrench{py_io::as_vector3(py_io::in_si(f_W, "N", "f_W"), "f_W"),
                                 py_io::as_vector3_or_zero(py_io::in_si(tau_B, "N*m", "tau_B"), "tau_B")}), "power"));
        }
        if (py::isinstance<PlanarBodyState>(state)) {
          const PlanarBodyState& s = checked_state_of<PlanarBodyState>(state, "PlanarBody");
          const double tau = tau_B.is_none() ? 0.0 : py_io::as_scalar(py_io::in_si(tau_B, "N*m", "tau_B"), "tau_B");
          return py::cast(finite_result(power(s, PlanarWrench{py_io::as_vector2(py_io::in_si(f_W, "N", "f_W"), "f_W"), tau}), "power"));
        }
        if (py::isinstance<ParticleState>(state)) {
          const ParticleState& s = checked_state_of<ParticleState>(state, "Particle");
          require_none_for_particle(tau_B, "tau_B", "a point mass takes no torque");
          return py::cast(finite_result(power(s, py_io::as_vector3(py_io::in_si(f_W, "N", "f_W"), "f_W")), "power"));
        }
        py_io::throw_type_error("state", "a RigidBodyState, PlanarBodyState or ParticleState", state);
      },
      py::arg("state"), py::arg("f_W"), py::arg("tau_B") = py::none(),
      "Power [W] of a force f_W [N] in W at the centre of mass and a torque tau_B about it (None: none): "
      "f_W.v_W + tau_B.w_B. RigidBodyState: f_W (3,), tau_B (3,) [N m] in B; PlanarBodyState: f_W (2,), tau_B "
      "[N m] about z; ParticleState: f_W (3,) only.");

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
      (std::string("The state just after an impulse [N s] at `point` (p_GP [m] from the centre of mass; None = the "
                   "centre of mass) and an angular impulse [N m s] (None: none), all in `frame` ('world' or 'body'): "
                   "m dv = impulse, I dw = p_GP x impulse + angular_impulse (impulse-momentum, Craig's \"Rigid Body "
                   "Dynamics\" slides). ") +
       body_state_doc +
       "\nRigidBody: impulse, point, angular_impulse (3,). PlanarBody: impulse, point (2,), angular_impulse about z. "
       "Particle: impulse (3,) in W only.")
          .c_str());
}

}  // namespace

void bind_bodies(py::module_& m) {
  bind_models(m);
  bind_result_types(m);
  bind_dynamics_functions(m);
}

}  // namespace rigiddyn::bindings
