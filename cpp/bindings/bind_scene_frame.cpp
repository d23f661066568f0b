// Python bindings of a scene's moving frame (scene/scene_frame.hpp) and of a body's mass flow
// (scene/mass_flow.hpp): SceneFrame (rotating, earth, moving with a FrameMotion)
// and MassFlow (a constant rate or a Python callable of t; the inertia scaled with the mass or a Python
// callable of m). Python callables are called with the GIL taken for the call (a run releases it), as
// PythonForce does; an exception they raise stops the run and propagates, and a non-finite value raises
// ValueError naming the field (the core checks ṁ and the frame's values; the inertia is checked here).
// The Thrust element is bound with the other elements (bind_scene_elements.cpp).
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "numpy_io.hpp"
#include "repr.hpp"
#include "scene_run.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/mass_flow.hpp"
#include "rigiddyn/scene/scene_frame.hpp"
#include "value_type.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;

namespace {

// A Python callable shared by the C++ copies of a MassFlow, released with the GIL held: a scene holding it
// may be copied or destroyed in C++ while the GIL is released.
std::shared_ptr<py::object> hold(py::object f) {
  return std::shared_ptr<py::object>(new py::object(std::move(f)), [](py::object* p) {
    py::gil_scoped_acquire gil;
    delete p;
  });
}

// A callable's text in a repr: its qualified name when it has one (a module-level function), else its repr.
std::string callable_text(const py::object& f) {
  if (py::hasattr(f, "__qualname__") && !py::isinstance<py::type>(f)) {
    const std::string name = py::str(f.attr("__qualname__"));
    if (name.find('<') == std::string::npos) return name;
  }
  return py::repr(f);
}

// ------------------------------------------------------------ the scene frame

// The names of the fictitious terms, in their order ("origin", "euler", "centrifugal", "coriolis")
constexpr const char* term_names[] = {"origin", "euler", "centrifugal", "coriolis"};
constexpr bool FictitiousTerms::*term_members[] = {&FictitiousTerms::origin, &FictitiousTerms::euler,
                                                   &FictitiousTerms::centrifugal, &FictitiousTerms::coriolis};

// The terms as a tuple of their names, in order
py::tuple terms_tuple(const FictitiousTerms& terms) {
  py::list out;
  for (int k = 0; k < 4; ++k) {
    if (terms.*term_members[k]) out.append(term_names[k]);
  }
  return py::tuple(out);
}

// A collection of term names (any order) as FictitiousTerms: TypeError naming `terms` for a str or a non-iterable,
// ValueError for an unknown or repeated name.
FictitiousTerms as_terms(py::handle obj) {
  constexpr const char* expected = "a collection of the names 'origin', 'euler', 'centrifugal', 'coriolis'";
  if (py::isinstance<py::str>(obj) || !py::isinstance<py::iterable>(obj)) py_io::throw_type_error("terms", expected, obj);
  FictitiousTerms terms;
  for (const py::handle item : obj) {
    const std::string name = py::isinstance<py::str>(item) ? item.cast<std::string>() : std::string();
    int k = 0;
    while (k < 4 && name != term_names[k]) ++k;
    if (k == 4 || terms.*term_members[k]) {
      py_io::throw_value_error("terms", std::string(expected) + ", each once", py::repr(obj).cast<std::string>());
    }
    terms.*term_members[k] = true;
  }
  return terms;
}

// How a SceneFrame reads as a constructor call: ("rotating", axis, rate), ("earth", latitude) or ("moving",
// motion, terms) (terms: the tuple of the terms that act). A constant rotation about a fixed origin, F = W at t = 0,
// is rotating (earth when its axis and rate are those of SceneFrame::earth at some latitude, bit for bit).
py::tuple frame_state(const SceneFrame& frame) {
  const auto* rotation = frame.motion.function().target<ConstantRotation>();
  const bool simple = rotation && frame.constant_rotation && rotation->R_PF0 == Eigen::Matrix3d::Identity() &&
                      rotation->p_PF_P.isZero(0.0);
  if (!simple) return py::make_tuple("moving", py::cast(frame.motion), terms_tuple(frame.terms));
  if (rotation->rate == earth_rotation_rate && rotation->axis_P.x() == 0.0 && rotation->axis_P.y() >= 0.0) {
    // the latitude whose (0, cos, sin) is the axis bit for bit: atan2's, or one of its nearest neighbours
    double latitude = std::atan2(rotation->axis_P.z(), rotation->axis_P.y());
    for (int k = 0; k < 8; ++k) latitude = std::nextafter(latitude, -4.0);
    for (int k = 0; k <= 16; ++k, latitude = std::nextafter(latitude, 4.0)) {
      if (std::abs(latitude) > 1.57079632679489661923) continue;
      const Eigen::Vector3d axis(0.0, std::cos(latitude), std::sin(latitude));
      if (axis == rotation->axis_P) return py::make_tuple("earth", latitude);
    }
  }
  return py::make_tuple("rotating", py::list(py_io::to_array(rotation->axis_P).attr("tolist")()), rotation->rate);
}

SceneFrame frame_from_state(const py::tuple& s) {
  const std::string kind = py_io::as_string(s.size() > 0 ? py::object(s[0]) : py::object(py::none()), "SceneFrame pickle");
  if (kind == "rotating" && s.size() == 3) {
    return SceneFrame::rotating(py_io::as_vector3(s[1], "axis"), py_io::as_scalar(s[2], "rate"));
  }
  if (kind == "earth" && s.size() == 2) return SceneFrame::earth(py_io::as_scalar(s[1], "latitude"));
  if (kind == "moving" && (s.size() == 2 || s.size() == 3)) {
    FrameMotion motion = py_io::as_instance<FrameMotion>(s[1], "frame_motion", "a FrameMotion");
    return s.size() == 2 ? SceneFrame::moving(std::move(motion)) : SceneFrame::moving(std::move(motion), as_terms(s[2]));
  }
  py_io::throw_value_error("SceneFrame pickle",
                           "('rotating', axis, rate), ('earth', latitude) or ('moving', motion[, terms])",
                           py::repr(s).cast<std::string>());
}

// A FrameMotion as source text: its repr, or FrameMotion(kinematics_at=<qualified name>) for a motion of a
// picklable (module-level) Python function, so that the repr evaluates where that function is in scope.
std::string motion_text(const py::object& motion) {
  try {
    const py::tuple state = motion.attr("__getstate__")();
    if (py::str(state[0]).cast<std::string>() == "function") return "FrameMotion(kinematics_at=" + callable_text(state[1]) + ")";
  } catch (py::error_already_set& e) {  // a lambda or a closure: shown by its repr
    if (py_io::is_interrupt(e)) throw;
  }
  return py::repr(motion);
}

std::string frame_repr(const SceneFrame& frame) {
  const py::tuple s = frame_state(frame);
  const std::string kind = s[0].cast<std::string>();
  if (kind == "rotating") return repr_call("SceneFrame.rotating", {{"axis", s[1]}, {"rate", s[2]}});
  if (kind == "earth") return repr_call("SceneFrame.earth", {{"latitude", s[1]}});
  const bool declared = frame.terms != SceneFrame::moving(frame.motion).terms;  // not the motion's own
  return "SceneFrame.moving(frame_motion=" + motion_text(s[1]) +
         (declared ? ", terms=" + py::repr(s[2]).cast<std::string>() : std::string()) + ")";
}

const char* const scene_frame_doc = R"doc(The frame F a scene's states are relative to, moving relative to the inertial frame W.

Scene.frame (None: W itself). Built by its static constructors (no public constructor):

- SceneFrame.rotating(axis, rate): F turns at `rate` [rad/s] about `axis` (3,) (any non-zero length; fixed in F
  and in W) through its origin, fixed at W's origin; F = W at t = 0;
- SceneFrame.earth(latitude): the local frame (x east, y north, z up) at `latitude` [rad] on the turning Earth:
  Omega = 7.2921159e-5 rad/s about (0, cos(latitude), sin(latitude));
- SceneFrame.moving(frame_motion, terms=None): any motion of F relative to W, a FrameMotion (a Python
  kinematics_at(t) is called with the GIL taken, at each derivative evaluation); terms: the fictitious terms
  that act, when the motion leaves some identically zero.

Each physical argument: a float [its unit] or a pint quantity. Immutable; pickles (a FrameMotion of a
module-level function); == compares how it was built.

Notes
-----
Newton's and Euler's laws seen from F gain the fictitious terms ("Rigid body kinematics and dynamics" notes,
eqs. (4.39)-(4.40)): frame origin -m a_O, Euler -m alpha x r, centrifugal -m Omega x (Omega x r), Coriolis
-2 m Omega x v (and their torques on bodies with an attitude). Compiling a scene adds those that act
(SceneFrame.terms) as elements "FrameOriginForce", "EulerForce", "CentrifugalForce", "CoriolisForce" after the
scene's own (columns of SceneResult.work and power): the centrifugal and Coriolis ones for rotating and earth
(none at rate 0), none for a FrameMotion.fixed placement, every term for a general motion unless `terms` names
those that act (a motion turning at a constant rate has no Euler term, one whose origin does not accelerate no
origin term; each evaluation of the motion then checks that the values of the terms left out are zero, else
ValueError naming `frame`). Every element, state and record of the scene is then in F. A motion function
returning a non-finite value raises ValueError naming `frame`; an exception it raises propagates out of
simulate.

Examples
--------
)doc"
    R"doc(A particle at rest in W, seen from a frame turning at 1 rad/s about z, circles the other way: after a quarter
turn it is at (0, -1, 0) in F:

>>> frame = rd.SceneFrame.rotating([0.0, 0.0, 1.0], 1.0)
>>> frame.terms
('centrifugal', 'coriolis')
>>> scene = rd.Scene([rd.Particle(1.0)], frame=frame)
>>> at_rest_in_W = rd.ParticleState(p_W=(1.0, 0.0, 0.0), v_W=(0.0, -1.0, 0.0))
>>> result = rd.simulate(scene, [at_rest_in_W], np.pi / 2000, steps=1000, method="rk4")
>>> result.p_W[-1, 0].round(9)
array([ 0., -1.,  0.])
)doc";

void bind_frame_class(py::module_& m) {
  py::class_<SceneFrame> cls(m, "SceneFrame", scene_frame_doc);
  cls.def_static(
         "rotating",
         [](py::handle axis, py::handle rate) {
           const Eigen::Vector3d axis_F = py_io::as_vector3(axis, "axis");
           if (axis_F.isZero(0.0)) py_io::throw_value_error("axis", "a non-zero vector (3,)", format_value(axis_F.transpose()));
           return SceneFrame::rotating(axis_F, py_io::as_scalar(py_io::in_si(rate, "rad/s", "rate"), "rate"));
         },
         py::arg("axis"), py::arg("rate"),
         "F turning at `rate` [rad/s] about `axis` (3,) (non-zero) through its origin, fixed at W's origin; F = W at "
         "t = 0 (only the centrifugal and Coriolis terms act; the centrifugal one has a potential).")
      .def_static(
          "earth",
          [](py::handle latitude) {
            return SceneFrame::earth(py_io::as_scalar(py_io::in_si(latitude, "rad", "latitude"), "latitude"));
          },
          py::arg("latitude"),
          "The local frame at `latitude` [rad] in [-pi/2, pi/2] (a pint angle: '48.85 deg') on the turning Earth: x "
          "east, y north, z up, Omega = 7.2921159e-5 rad/s about (0, cos(latitude), sin(latitude)); its origin is "
          "taken as fixed (the centripetal acceleration of the ground is part of the local gravity, a UniformGravity).")
      .def_static(
          "moving",
          [](py::handle frame_motion, py::handle terms) {
            FrameMotion motion = py_io::as_instance<FrameMotion>(frame_motion, "frame_motion", "a FrameMotion");
            return terms.is_none() ? SceneFrame::moving(std::move(motion)) : SceneFrame::moving(std::move(motion), as_terms(terms));
          },
          py::arg("frame_motion"), py::arg("terms") = py::none(),
          "F moving relative to W as the FrameMotion `frame_motion` gives (P = W: R_WF, angular velocity and "
          "acceleration, origin position, velocity and acceleration, all in W). terms: None (a FrameMotion.fixed "
          "placement: none; a FrameMotion.constant_rotation: 'centrifugal' and 'coriolis'; any other motion: every "
          "term) or the names of the fictitious terms that act, among 'origin' (a_O not identically 0), 'euler' "
          "(alpha), 'centrifugal' and 'coriolis' (Omega: both or neither; 'euler' only with them); compile adds "
          "those alone, and each evaluation of the motion checks that the values of the others are zero "
          "(ValueError naming `frame` at that t). ValueError naming `terms` for a set that cannot be, or another "
          "set than a fixed placement's or a constant rotation's own.")
      .def_property_readonly("motion", [](const SceneFrame& f) { return f.motion; }, "the FrameMotion of F relative to W")
      .def_property_readonly("constant_rotation", [](const SceneFrame& f) { return f.constant_rotation; },
                             "True when F turns at a constant rate about its fixed origin (rotating, earth)")
      .def_property_readonly("terms", [](const SceneFrame& f) { return terms_tuple(f.terms); },
                             "the fictitious terms that act, a tuple of names among 'origin', 'euler', 'centrifugal', "
                             "'coriolis' (in that order): compile adds them as 'frame.<name>' (FrameOriginForce, "
                             "EulerForce, CentrifugalForce, CoriolisForce)")
      .def("__repr__", &frame_repr)
      .def(py::pickle(&frame_state, &frame_from_state))
      .def(
          "__eq__",
          [](const SceneFrame& a, py::handle b) {
            return equal_or_not_implemented(a, b, [](const SceneFrame& x, const SceneFrame& y) {
              return x.constant_rotation == y.constant_rotation && frame_state(x).equal(frame_state(y));
            });
          },
          py::arg("other"));
  cls.attr("__hash__") = py::none();
}

// ------------------------------------------------------------ the mass flow

// MassFlow::rate_of_t for a Python rate(t) -> ṁ [kg/s]: takes the GIL for the call. A value that is not a
// real number raises TypeError naming `rate`; a non-finite one is returned as it is for the core's check,
// which names mass_flows[i].rate.
struct PythonRate {
  std::shared_ptr<py::object> f;
  double operator()(double t) const {
    py::gil_scoped_acquire gil;
    const py::object out = (*f)(t);
    if (py::isinstance<py::str>(out) || py::isinstance<py::bytes>(out) || py::isinstance<py::bool_>(out)) {
      py_io::throw_type_error("rate", "a callable rate(t) returning the mass rate [kg/s] (a float)", out);
    }
    const double rate = PyFloat_AsDouble(out.ptr());
    if (rate == -1.0 && PyErr_Occurred()) {
      py_io::clear_error_unless_interrupt();
      py_io::throw_type_error("rate", "a callable rate(t) returning the mass rate [kg/s] (a float)", out);
    }
    return rate;
  }
};

// MassFlow::inertia_of_mass for a Python inertia_rule(m) -> I_C (3, 3) [kg m^2] in B: takes the GIL for the
// call. TypeError naming `inertia_rule` for a value that is not a (3, 3) real array; ValueError naming it for a
// non-finite one (the core checks symmetry and positive definiteness, naming mass_flows[i].inertia_of_mass).
struct PythonInertia {
  std::shared_ptr<py::object> f;
  Eigen::Matrix3d operator()(double m) const {
    constexpr const char* expected = "a callable inertia_rule(m) returning the inertia about the centre of mass "
                                     "(3, 3) [kg m^2] in B";
    py::gil_scoped_acquire gil;
    const py::object out = (*f)(m);
    const py_io::Array I = py_io::as_array(out, "inertia_rule");
    if (I.ndim() != 2 || I.shape(0) != 3 || I.shape(1) != 3) py_io::throw_value_error("inertia_rule", expected, py_io::describe(out));
    const Eigen::Matrix3d value = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(I.data());
    if (!value.allFinite()) {
      // std::invalid_argument (not py::value_error): a C++ error the run and its callers handle as the core's
      throw std::invalid_argument("inertia_rule: expected " + std::string(expected) + " with finite values at m = " +
                                  format_value(m) + " kg, got " + format_value(value));
    }
    return value;
  }
};

MassFlow make_mass_flow(py::handle rate, py::handle inertia_rule) {
  MassFlow flow;
  if (PyCallable_Check(rate.ptr())) {
    flow.rate_of_t = PythonRate{hold(py::reinterpret_borrow<py::object>(rate))};
  } else {
    flow.rate = py_io::as_scalar(py_io::in_si(rate, "kg/s", "rate"), "rate");
  }
  if (PyCallable_Check(inertia_rule.ptr())) {
    flow.inertia_rule = InertiaRule::function;
    flow.inertia_of_mass = PythonInertia{hold(py::reinterpret_borrow<py::object>(inertia_rule))};
  } else {
    constexpr const char* expected = "'scaled' or a callable inertia_rule(m) -> (3, 3) [kg m^2]";
    if (!py::isinstance<py::str>(inertia_rule)) py_io::throw_type_error("inertia_rule", expected, inertia_rule);
    if (inertia_rule.cast<std::string>() != "scaled") {
      py_io::throw_value_error("inertia_rule", expected, py::repr(inertia_rule).cast<std::string>());
    }
  }
  check_mass_flow(flow, "mass_flow");
  return flow;
}

// (rate, inertia_rule) as given: a float or the callable, 'scaled' or the callable; TypeError for a flow
// built in C++ from a C++ function.
py::tuple mass_flow_state(const MassFlow& flow) {
  py::object rate = py::float_(flow.rate), rule = py::str("scaled");
  if (flow.rate_of_t) {
    const auto* python = flow.rate_of_t.target<PythonRate>();
    if (!python) throw py::type_error("MassFlow: expected a rate given in Python, got a C++ function");
    rate = *python->f;
  }
  if (flow.inertia_rule == InertiaRule::function) {
    const auto* python = flow.inertia_of_mass.target<PythonInertia>();
    if (!python) throw py::type_error("MassFlow: expected an inertia_rule given in Python, got a C++ function");
    rule = *python->f;
  }
  return py::make_tuple(rate, rule);
}

std::string mass_flow_repr(const MassFlow& flow) {
  const py::tuple s = mass_flow_state(flow);
  auto text = [](const py::object& v) { return PyCallable_Check(v.ptr()) ? callable_text(v) : std::string(py::repr(v)); };
  return "MassFlow(rate=" + text(s[0]) + ", inertia_rule=" + text(s[1]) + ")";
}

const char* const mass_flow_doc = R"doc(The mass flow of a body: its mass changes at a given rate, its inertia by a rule.

Given to Scene.add_body(body, mass_flow=...) or Scene(..., mass_flows=[...]). The mass starts at the body's mass
and is a coordinate of the run (SceneResult.mass). Its force is the Thrust element, f = rate u_rel ("Rigid body
kinematics and dynamics" notes, eq. (4.36): m dv/dt = f + (dm/dt) u_rel). The mass leaving carries its own
angular momentum (no jet damping): I(m) dw/dt + w x I(m) w = tau. Immutable; pickles (callables defined at
module level); == compares rate and inertia_rule.

Parameters
----------
rate : float or callable, default 0.0
    dm/dt [kg/s]: a float (or a pint quantity; negative: the body loses mass) or a callable rate(t) -> float of
    the time t [s].
inertia_rule : {'scaled'} or callable, default 'scaled'
    How the rotational inertia about the centre of mass follows the mass: 'scaled' (I_C(m) = I_C0 m / m0: the
    body's shape is kept; every method applies) or a callable inertia_rule(m) -> (3, 3) [kg m^2] in B of the
    mass m [kg] (the splitting methods are refused).

Raises
------
ValueError
    A non-finite value of a callable (naming mass_flows[i].rate or inertia_rule); a mass reaching zero (naming
    mass_flows[i] and the step; for a constant rate before the run, naming steps and dt).

Notes
-----
Callables are called with the GIL taken, at each derivative evaluation; an exception they raise stops the run
and propagates. The kinetic energy the flow takes away or brings at the body's own velocity,
1/2 (dm/dt) |v|^2 + 1/2 w.(dI/dt) w integrated, is SceneResult.mass_flow_energy:
kinetic_energy - kinetic_energy[0] ~ work + mass-flow energy.

Examples
--------
)doc"
    R"doc(A particle of 2 kg losing 0.5 kg/s has 1 kg left after 2 s:

>>> scene = rd.Scene([rd.Particle(2.0)], mass_flows=[rd.MassFlow(rate=-0.5)])
>>> result = rd.simulate(scene, [rd.ParticleState()], 0.1, duration=2.0, method="rk4")
>>> result.mass[[0, 10, 20], 0].round(12)
array([2. , 1.5, 1. ])
)doc";

void bind_mass_flow_class(py::module_& m) {
  py::class_<MassFlow> cls(m, "MassFlow", mass_flow_doc);
  cls.def(py::init(&make_mass_flow), py::arg("rate") = 0.0, py::arg("inertia_rule") = "scaled")
      .def_property_readonly("rate", [](const MassFlow& f) { return py::object(mass_flow_state(f)[0]); },
                             "dm/dt [kg/s] (a float) or the callable rate(t)")
      .def_property_readonly("inertia_rule", [](const MassFlow& f) { return py::object(mass_flow_state(f)[1]); },
                             "'scaled' or the callable inertia_rule(m) -> (3, 3) [kg m^2]")
      .def("__repr__", &mass_flow_repr)
      .def(py::pickle(&mass_flow_state,
                      [](const py::tuple& t) {
                        pickled_state(t, 2, "MassFlow");
                        return make_mass_flow(t[0], t[1]);
                      }))
      .def(
          "__eq__",
          [](const MassFlow& a, py::handle b) {
            return equal_or_not_implemented(a, b, [](const MassFlow& x, const MassFlow& y) {
              return mass_flow_state(x).equal(mass_flow_state(y));
            });
          },
          py::arg("other"));
  cls.attr("__hash__") = py::none();
}

}  // namespace

SceneFrame as_scene_frame(py::handle obj, const std::string& name) {
  return py_io::as_instance<SceneFrame>(obj, name, "None (W, inertial) or a SceneFrame");
}

std::optional<MassFlow> as_mass_flow(py::handle obj, const std::string& name) {
  if (obj.is_none()) return std::nullopt;
  return py_io::as_instance<MassFlow>(obj, name, "None (a constant mass) or a MassFlow");
}

void bind_scene_frame(py::module_& m) {
  bind_frame_class(m);
  bind_mass_flow_class(m);
}

}  // namespace rigiddyn::bindings
