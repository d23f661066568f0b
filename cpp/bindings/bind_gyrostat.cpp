// Python bindings of the gyrostat (models/gyrostat.hpp): Wheel, Gyrostat and GyrostatState. A gyrostat runs as a
// body of a Scene; simulate / step of a Gyrostat alone run its one-body scene (gyrostat_scene below).
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "common_args.hpp"
#include "numpy_io.hpp"
#include "repr.hpp"
#include "scene_run.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/models/gyrostat.hpp"
#include "rigiddyn/scene/scene.hpp"
#include "state_args.hpp"
#include "value_type.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using py_io::Array;

namespace {

py::object list_of(const Eigen::Vector3d& v) { return py_io::to_array(v); }

// ------------------------------------------------------------ Wheel

Wheel make_wheel(py::handle axis_B, py::handle inertia, py::handle motor_torque, py::handle t_start, py::handle t_end) {
  Wheel w;
  w.axis_B = py_io::as_vector3(axis_B, "axis_B");
  w.inertia = py_io::as_scalar(py_io::in_si(inertia, "kg*m^2", "inertia"), "inertia");
  w.motor_torque = py_io::as_scalar(py_io::in_si(motor_torque, "N*m", "motor_torque"), "motor_torque");
  w.t_start = py_io::as_scalar(py_io::in_si(t_start, "s", "t_start"), "t_start");
  w.t_end = py_io::as_extended_real(py_io::in_si(t_end, "s", "t_end"), "t_end");
  return checked_wheel(w);
}

// (t_end left out when the motor never stops: the default, and a repr that evaluates)
std::string wheel_repr(const Wheel& w) {
  std::string text = repr_call("Wheel", {{"axis_B", list_of(w.axis_B)},
                                         {"inertia", py::float_(w.inertia)},
                                         {"motor_torque", py::float_(w.motor_torque)},
                                         {"t_start", py::float_(w.t_start)}});
  if (std::isfinite(w.t_end)) text.insert(text.size() - 1, ", t_end=" + py::repr(py::float_(w.t_end)).cast<std::string>());
  return text;
}

bool same_wheel(const Wheel& a, const Wheel& b) {
  return a.axis_B == b.axis_B && a.inertia == b.inertia && a.motor_torque == b.motor_torque && a.t_start == b.t_start &&
         a.t_end == b.t_end;
}

void bind_wheel(py::module_& m) {
  py::class_<Wheel> cls(
      m, "Wheel", R"doc(A wheel of a Gyrostat, spun about an axis fixed in the body by a motor.

Its speed relative to the body is a state of the gyrostat (GyrostatState.wheel_speeds). Immutable; pickles; ==
compares every field.

Parameters
----------
axis_B : array_like, shape (3,)
    The spin axis in the body frame B (any non-zero length; the unit axis is kept).
inertia : float or pint.Quantity
    The wheel's moment of inertia about its spin axis [kg m^2], > 0.
motor_torque : float or pint.Quantity, default 0
    The motor's torque on the wheel about its axis [N m] (the body feels its reaction), applied for
    t_start <= t < t_end.
t_start, t_end : float or pint.Quantity, default 0 and inf
    The motor's time window [s] (a run splits its steps at both).

Raises
------
ValueError
    A zero or non-finite axis, an inertia not > 0, a non-finite torque, t_end not after t_start, or a quantity
    of another dimension (the message names it).

See Also
--------
Gyrostat, GyrostatState

Examples
--------
>>> rd.Wheel(axis_B=[0, 0, 2], inertia=0.01, motor_torque=0.002, t_end=5.0).axis_B
array([0., 0., 1.])
)doc");
  cls.def(py::init(&make_wheel), py::arg("axis_B"), py::arg("inertia"), py::arg("motor_torque") = 0.0,
          py::arg("t_start") = 0.0, py::arg("t_end") = std::numeric_limits<double>::infinity())
      .def_property_readonly("axis_B", [](const Wheel& w) { return py_io::read_only(w.axis_B); },
                             "The unit spin axis a in B, shape (3,).")
      .def_property_readonly("inertia", [](const Wheel& w) { return w.inertia; },
                             "Axial moment of inertia J about the spin axis [kg m^2].")
      .def_property_readonly("motor_torque", [](const Wheel& w) { return w.motor_torque; },
                             "Motor torque u on the wheel about its axis [N m].")
      .def_property_readonly("t_start", [](const Wheel& w) { return w.t_start; }, "The motor's start [s].")
      .def_property_readonly("t_end", [](const Wheel& w) { return w.t_end; }, "The motor's end [s] (inf: never).")
      .def("__repr__", &wheel_repr)
      .def(py::pickle(
          [](const Wheel& w) { return py::make_tuple(list_of(w.axis_B), w.inertia, w.motor_torque, w.t_start, w.t_end); },
          [](const py::tuple& t) {
            pickled_state(t, 5, "Wheel");
            return checked_wheel(Wheel{unpickled<3>(t[0], "Wheel pickle axis_B"), t[1].cast<double>(), t[2].cast<double>(),
                                       t[3].cast<double>(), t[4].cast<double>()});
          }));
  cls.def(
      "__eq__", [](const Wheel& a, py::handle b) { return equal_or_not_implemented(a, b, same_wheel); }, py::arg("other"));
  cls.attr("__hash__") = py::none();
}

// ------------------------------------------------------------ Gyrostat

std::vector<Wheel> as_wheels(py::handle obj) {
  constexpr const char* expected = "a sequence of Wheel";
  if (is_instance<Wheel>(obj)) return {obj.cast<Wheel>()};
  if (py::isinstance<py::str>(obj) || !py::isinstance<py::iterable>(obj)) py_io::throw_type_error("wheels", expected, obj);
  std::vector<Wheel> out;
  for (py::handle item : obj) {
    if (!is_instance<Wheel>(item)) {
      py_io::throw_type_error("wheels[" + std::to_string(out.size()) + "]", "a Wheel", item);
    }
    out.push_back(item.cast<Wheel>());
  }
  return out;
}

Gyrostat make_gyrostat(py::handle body, py::handle wheels) {
  const RigidBody& b = py_io::as_instance<RigidBody>(body, "body", "a RigidBody (the whole body with its wheels locked)");
  return Gyrostat(b, as_wheels(wheels));
}

py::list wheels_list(const Gyrostat& g) {
  py::list out;
  for (const Wheel& w : g.wheels()) out.append(py::cast(w));
  return out;
}

void bind_gyrostat_body(py::module_& m) {
  py::class_<Gyrostat> cls(
      m, "Gyrostat",
          "A rigid body carrying wheels spun by motors about axes fixed in the body: a reaction-wheel spacecraft.\n"
          R"doc(
Each wheel's speed relative to the body is a state (Hughes, "Spacecraft Attitude Dynamics", ch. 3). With I the
whole body's inertia about its centre of mass in B (wheels locked), wheel k's unit axis a_k, axial inertia J_k,
speed Omega_k relative to the body and motor torque u_k, the transverse inertia A = I - sum J_k a_k a_k^T:

    A dw/dt = tau_B - sum u_k a_k - w x (I w + h_w),  dOmega_k/dt = u_k / J_k - a_k . dw/dt,

h_w = sum J_k Omega_k a_k; kinetic energy T = 1/2 m |v|^2 + 1/2 w.A w + 1/2 sum J_k (a_k.w + Omega_k)^2.
Elements see it as its locked RigidBody. It runs in an inertial scene with explicit_euler, semi_implicit_euler,
rk4, rkmk4 or implicit_midpoint; simulate and step of a Gyrostat alone run its one-body scene. Immutable;
pickles; == compares body and wheels.

Parameters
----------
body : RigidBody
    The whole body with its wheels locked: mass [kg] and inertia_com [kg m^2] about its centre of mass in B,
    wheels included.
wheels : sequence of Wheel
    Its wheels (one Wheel alone is taken as a list of one).

Raises
------
TypeError
    body not a RigidBody, or wheels not a sequence of Wheel (the message names wheels[k]).
ValueError
    A wheel's axial inertia leaves A not positive definite (the message names wheels[k].inertia).

See Also
--------
Wheel, GyrostatState, RigidBody, simulate

Examples
--------
>>> sat = rd.Gyrostat(rd.RigidBody(100.0, [10.0, 12.0, 15.0]), [rd.Wheel([0, 0, 1], 0.05)])
>>> sat.transverse_inertia.diagonal()
array([10.  , 12.  , 14.95])

Motor torque spins the wheel up and the body the other way; the total angular momentum stays zero:

>>> sat = rd.Gyrostat(rd.RigidBody(100.0, [10.0, 12.0, 15.0]), [rd.Wheel([0, 0, 1], 0.05, motor_torque=0.01)])
>>> r = rd.simulate(sat, rd.GyrostatState(wheel_speeds=[0.0]), dt=0.1, steps=100)
>>> bool(r.w_B[-1, 0, 2] < 0 < r.wheel_speed[-1, 0]), bool(np.allclose(r.angular_momentum_W[-1], 0, atol=1e-12))
(True, True)
)doc");
  cls.def(py::init(&make_gyrostat), py::arg("body"), py::arg("wheels"))
      .def_property_readonly("body", [](const Gyrostat& g) { return g.body(); },
                             "The RigidBody with the wheels locked: mass [kg] and inertia about C in B [kg m^2] "
                             "(a copy).")
      .def_property_readonly("mass", &Gyrostat::mass, "Mass m [kg], wheels included.")
      .def_property_readonly("inertia_com", [](const Gyrostat& g) { return py_io::read_only(g.inertia_com()); },
                             "Inertia I about the centre of mass in B, wheels locked, shape (3, 3) [kg m^2].")
      .def_property_readonly("transverse_inertia", [](const Gyrostat& g) { return py_io::read_only(g.transverse_inertia()); },
                             "A = I - sum J_k a_k a_k^T in B, shape (3, 3) [kg m^2]: the body with its wheels free to "
                             "spin.")
      .def_property_readonly("wheels", [](const Gyrostat& g) { return py::tuple(wheels_list(g)); },
                             "The wheels, a tuple of Wheel in the order of the state's wheel_speeds.")
      .def("__repr__",
           [](const Gyrostat& g) { return repr_call("Gyrostat", {{"body", py::cast(g.body())}, {"wheels", wheels_list(g)}}); })
      .def(py::pickle([](const Gyrostat& g) { return py::make_tuple(g.body(), wheels_list(g)); },
                      [](const py::tuple& t) {
                        pickled_state(t, 2, "Gyrostat");
                        return make_gyrostat(t[0], t[1]);
                      }));
  cls.def(
      "__eq__",
      [](const Gyrostat& a, py::handle b) {
        return equal_or_not_implemented(a, b, [](const Gyrostat& x, const Gyrostat& y) {
          if (x.mass() != y.mass() || x.inertia_com() != y.inertia_com() || x.wheels().size() != y.wheels().size()) {
            return false;
          }
          for (std::size_t k = 0; k < x.wheels().size(); ++k) {
            if (!same_wheel(x.wheels()[k], y.wheels()[k])) return false;
          }
          return true;
        });
      },
      py::arg("other"));
  cls.attr("__hash__") = py::none();
}

// ------------------------------------------------------------ GyrostatState

Eigen::VectorXd as_wheel_speeds(py::handle obj) {
  if (obj.is_none()) return Eigen::VectorXd();
  const Array a = py_io::as_array(py_io::in_si(obj, "rad/s", "wheel_speeds"), "wheel_speeds");
  if (a.ndim() > 1) py_io::throw_value_error("wheel_speeds", "a 1-D array (one speed per wheel)", py_io::describe(obj));
  Eigen::VectorXd out(a.size());
  for (py::ssize_t k = 0; k < a.size(); ++k) out[k] = a.data()[k];
  require_finite(out, "wheel_speeds");
  return out;
}

void bind_gyrostat_state(py::module_& m) {
  py::class_<GyrostatState> cls(
      m, "GyrostatState", R"doc(State of a Gyrostat: the rigid body's state and its wheels' speeds.

Fields are assigned whole (converted and checked as the constructor does); the arrays read are read-only copies.
Pickles; == compares every field.

Parameters
----------
p_W : array_like, shape (3,), optional
    Centre of mass position in W [m] (None: zero).
q_WB : array_like, shape (4,), optional
    Unit quaternion B to W, (x, y, z, w), or (w, x, y, z) with scalar_first=True (None: identity; normalised).
v_W : array_like, shape (3,), optional
    Centre of mass velocity in W [m/s] (None: zero).
w_B : array_like, shape (3,), optional
    Angular velocity of B relative to W, in B [rad/s] (None: zero).
wheel_speeds : array_like, shape (nw,), optional
    Each wheel's speed relative to the body [rad/s], in the order of the gyrostat's wheels (None: none; a run
    checks one per wheel).
scalar_first : bool, default False
    Read q_WB as (w, x, y, z).

Raises
------
ValueError
    q_WB farther than 1e-6 from unit norm, wheel_speeds not 1-D or not finite, a field of another shape, or a
    quantity of another dimension (the message names it).

See Also
--------
Gyrostat, Wheel, simulate

Examples
--------
>>> rd.GyrostatState(w_B=[0, 0, 0.1], wheel_speeds=[100.0]).wheel_speeds
array([100.])
)doc");
  cls.def(py::init([](py::handle p_W, py::handle q_WB, py::handle v_W, py::handle w_B, py::handle wheel_speeds,
                      py::handle scalar_first) {
            const bool wxyz = py_io::as_bool(scalar_first, "scalar_first");
            return GyrostatState{py_io::as_vector3_or_zero(py_io::in_si(p_W, "m", "p_W"), "p_W"),
                                 q_WB.is_none() ? Eigen::Quaterniond::Identity() : as_unit_quaternion(q_WB, "q_WB", wxyz),
                                 py_io::as_vector3_or_zero(py_io::in_si(v_W, "m/s", "v_W"), "v_W"),
                                 py_io::as_vector3_or_zero(py_io::in_si(w_B, "rad/s", "w_B"), "w_B"),
                                 as_wheel_speeds(wheel_speeds)};
          }),
          py::arg("p_W") = py::none(), py::arg("q_WB") = py::none(), py::arg("v_W") = py::none(),
          py::arg("w_B") = py::none(), py::arg("wheel_speeds") = py::none(), py::arg("scalar_first") = false)
      .def_property(
          "p_W", [](const GyrostatState& s) { return py_io::read_only(s.p_W); },
          [](GyrostatState& s, py::handle v) { s.p_W = py_io::as_vector3(py_io::in_si(v, "m", "p_W"), "p_W"); },
          "Centre of mass position p_W in W, shape (3,) [m].")
      .def_property(
          "q_WB",
          [](const GyrostatState& s) {
            Array q = py_io::to_array(s.q_WB, false);
            py_io::set_read_only(q);
            return q;
          },
          [](GyrostatState& s, py::handle v) { s.q_WB = as_unit_quaternion(v, "q_WB"); },
          "Attitude q_WB (B to W), shape (4,), (x, y, z, w); set from (x, y, z, w), normalised (ValueError beyond "
          "1e-6 of unit norm).")
      .def_property(
          "v_W", [](const GyrostatState& s) { return py_io::read_only(s.v_W); },
          [](GyrostatState& s, py::handle v) { s.v_W = py_io::as_vector3(py_io::in_si(v, "m/s", "v_W"), "v_W"); },
          "Centre of mass velocity v_W in W, shape (3,) [m/s].")
      .def_property(
          "w_B", [](const GyrostatState& s) { return py_io::read_only(s.w_B); },
          [](GyrostatState& s, py::handle v) { s.w_B = py_io::as_vector3(py_io::in_si(v, "rad/s", "w_B"), "w_B"); },
          "Angular velocity w_B of B in W, expressed in B, shape (3,) [rad/s].")
      .def_property(
          "wheel_speeds", [](const GyrostatState& s) { return py_io::read_only(s.wheel_speeds); },
          [](GyrostatState& s, py::handle v) { s.wheel_speeds = as_wheel_speeds(v); },
          "Each wheel's speed relative to the body, shape (nw,) [rad/s].")
      .def("__repr__",
           [](const GyrostatState& s) {
             return repr_call("GyrostatState", {{"p_W", list_of(s.p_W)},
                                                {"q_WB", py::object(py_io::to_array(s.q_WB, false))},
                                                {"v_W", list_of(s.v_W)},
                                                {"w_B", list_of(s.w_B)},
                                                {"wheel_speeds", py::object(py_io::to_array(s.wheel_speeds))}});
           })
      .def(py::pickle(
          [](const GyrostatState& s) {
            return py::make_tuple(list_of(s.p_W), py_io::to_array(s.q_WB, false), list_of(s.v_W), list_of(s.w_B),
                                  py_io::to_array(s.wheel_speeds));
          },
          [](const py::tuple& t) {
            pickled_state(t, 5, "GyrostatState");
            const Eigen::Vector4d q = unpickled<4>(t[1], "GyrostatState pickle q_WB");
            return GyrostatState{unpickled<3>(t[0], "GyrostatState pickle p_W"), py_io::read_quaternion(q.data(), false),
                                 unpickled<3>(t[2], "GyrostatState pickle v_W"), unpickled<3>(t[3], "GyrostatState pickle w_B"),
                                 unpickled<Eigen::Dynamic>(t[4], "GyrostatState pickle wheel_speeds")};
          }));
  def_equality(cls, [](const GyrostatState& a, const GyrostatState& b) {
    return a.p_W == b.p_W && a.q_WB.coeffs() == b.q_WB.coeffs() && a.v_W == b.v_W && a.w_B == b.w_B &&
           a.wheel_speeds.size() == b.wheel_speeds.size() && a.wheel_speeds == b.wheel_speeds;
  });
}

}  // namespace

// ------------------------------------------------------------ the seams (bindings.hpp)

bool is_gyrostat(py::handle body) { return is_instance<Gyrostat>(body); }

py::object gyrostat_scene(py::handle model, py::handle loads, py::handle gravity) {
  return one_body_scene(model.cast<const Gyrostat&>(), as_gravity(gravity), loads);
}

void bind_gyrostat(py::module_& m) {
  bind_wheel(m);
  bind_gyrostat_body(m);
  bind_gyrostat_state(m);
}

}  // namespace rigiddyn::bindings
