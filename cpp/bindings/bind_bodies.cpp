// Python bindings of the bodies and their dynamics: Particle, PlanarBody, RigidBody, their states,
// and the functions on them (forward and inverse dynamics, momentum, energy, power, impulse). Each
// function takes any of the three bodies: one entry point that dispatches on the body's type (so a
// wrong argument gives a TypeError naming it, not pybind11's overload list), checks the state it
// gets (finite, unit quaternion: a state returned by `step` may be neither) and warns when a result
// overflows. simulate/step and AppliedLoad are in bind_dynamics.cpp.
#include <pybind11/stl.h>

#include <string>
#include <type_traits>

#include "bindings.hpp"
#include "common_args.hpp"
#include "numpy_io.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/dynamics/particle_dynamics.hpp"
#include "rigiddyn/dynamics/planar_body_dynamics.hpp"
#include "rigiddyn/dynamics/rigid_body_dynamics.hpp"
#include "rigiddyn/simulate/simulate.hpp"  // standard_gravity
#include "rigiddyn/so3/quaternion.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using py_io::finite_result;

namespace {

// A planar body's in-plane gravity: None (none) or (2,) [m/s²] in W.
Eigen::Vector2d as_planar_gravity(py::handle obj) {
  if (py::isinstance<py::bool_>(obj)) {
    py_io::throw_value_error("gravity", "None or an in-plane vector (2,) [m/s^2] for a PlanarBody", py_io::describe(obj));
  }
  return py_io::as_vector2_or_zero(obj, "gravity");
}

// RigidBody's `check`: None (InertiaCheck.physical), an InertiaCheck, or, for backward compatibility,
// a bool meaning require_triangle_inequality (also accepted as that keyword).
InertiaCheck as_inertia_check(py::handle check, py::handle require_triangle_inequality) {
  auto from = [](py::handle obj, const std::string& name) {
    if (py::isinstance<py::bool_>(obj)) return obj.cast<bool>() ? InertiaCheck::physical : InertiaCheck::allow_unrealizable;
    if (py::isinstance<InertiaCheck>(obj)) return obj.cast<InertiaCheck>();
    py_io::throw_type_error(name, "an InertiaCheck (or a bool)", obj);
  };
  if (require_triangle_inequality.is_none()) return check.is_none() ? InertiaCheck::physical : from(check, "check");
  const InertiaCheck legacy = from(require_triangle_inequality, "require_triangle_inequality");
  if (!check.is_none() && from(check, "check") != legacy) {
    throw py::value_error("require_triangle_inequality: expected agreement with check, got both, conflicting");
  }
  return legacy;
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

void bind_models(py::module_& m) {
  py::class_<Particle>(m, "Particle",
                       "A point mass (3 DOF; \"Rigid body kinematics and dynamics\" notes, section 4.11): mass [kg] > 0.")
      .def(py::init([](py::handle mass) { return Particle(py_io::as_scalar(mass, "mass")); }), py::arg("mass"))
      .def_property_readonly("mass", &Particle::mass, "mass [kg]");

  py::class_<PlanarBody>(m, "PlanarBody",
                         "A rigid body moving in the xy plane of W (x, y, theta; plane kinetics of Craig's \"Rigid Body "
                         "Dynamics\" slides): mass [kg] and inertia_zz [kg m^2] about the z axis through the centre of "
                         "mass, both > 0.")
      .def(py::init([](py::handle mass, py::handle inertia_zz) {
             return PlanarBody(py_io::as_scalar(mass, "mass"), py_io::as_scalar(inertia_zz, "inertia_zz"));
           }),
           py::arg("mass"), py::arg("inertia_zz"))
      .def_property_readonly("mass", &PlanarBody::mass, "mass [kg]")
      .def_property_readonly("inertia_zz", &PlanarBody::inertia_zz, "moment of inertia about z through G [kg m^2]");

  py::class_<RigidBody>(m, "RigidBody",
                        "A spatial rigid body (6 DOF): mass [kg] > 0 and inertia_com (3, 3) [kg m^2] about the centre "
                        "of mass in the body frame B, symmetric positive definite, checked as every inertia of "
                        "rigiddyn is (inertia_report): under check=InertiaCheck.physical (default) the principal "
                        "moments must satisfy the triangle inequality; check=InertiaCheck.allow_unrealizable accepts "
                        "test bodies no real body has, e.g. I = diag(2, 1, 2/3). (require_triangle_inequality=False, "
                        "or False as the third positional argument, is the older spelling of allow_unrealizable.) "
                        "euler_form tells which form of Euler's equations it uses: 'spherical', 'principal' or "
                        "'full'.")
      .def(py::init([](py::handle mass, py::handle inertia_com, py::handle check, py::handle require_triangle_inequality) {
             return RigidBody(py_io::as_scalar(mass, "mass"), py_io::as_matrix3(inertia_com, "inertia_com"),
                              as_inertia_check(check, require_triangle_inequality));
           }),
           py::arg("mass"), py::arg("inertia_com"), py::arg("check") = py::none(),
           py::arg("require_triangle_inequality") = py::none())
      .def_property_readonly("mass", &RigidBody::mass, "mass [kg]")
      .def_property_readonly(
          "inertia_com", [](const RigidBody& b) { return py_io::to_array(b.inertia_com()); },
          "(3, 3) inertia about the centre of mass in B [kg m^2]")
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
          "'spherical' (no gyroscopic term), 'principal' (diagonal inertia) or 'full'");

  py::class_<ParticleState>(m, "ParticleState", "Particle state: p_W (3,) [m] and v_W (3,) [m/s] in W (None: zero).")
      .def(py::init([](py::handle p_W, py::handle v_W) {
             return ParticleState{py_io::as_vector3_or_zero(p_W, "p_W"), py_io::as_vector3_or_zero(v_W, "v_W")};
           }),
           py::arg("p_W") = py::none(), py::arg("v_W") = py::none())
      .def_property_readonly("p_W", [](const ParticleState& s) { return py_io::to_array(s.p_W); }, "(3,) [m]")
      .def_property_readonly("v_W", [](const ParticleState& s) { return py_io::to_array(s.v_W); }, "(3,) [m/s]");

  py::class_<PlanarBodyState>(m, "PlanarBodyState",
                              "Planar body state: p_W (2,) [m] centre of mass, theta [rad] angle of B about z, "
                              "v_W (2,) [m/s], omega [rad/s] (None: zero).")
      .def(py::init([](py::handle p_W, py::handle theta, py::handle v_W, py::handle omega) {
             return PlanarBodyState{py_io::as_vector2_or_zero(p_W, "p_W"), py_io::as_scalar(theta, "theta"),
                                    py_io::as_vector2_or_zero(v_W, "v_W"), py_io::as_scalar(omega, "omega")};
           }),
           py::arg("p_W") = py::none(), py::arg("theta") = 0.0, py::arg("v_W") = py::none(), py::arg("omega") = 0.0)
      .def_property_readonly("p_W", [](const PlanarBodyState& s) { return py_io::to_array(s.p_W); }, "(2,) [m]")
      .def_readonly("theta", &PlanarBodyState::theta, "[rad]")
      .def_property_readonly("v_W", [](const PlanarBodyState& s) { return py_io::to_array(s.v_W); }, "(2,) [m/s]")
      .def_readonly("omega", &PlanarBodyState::omega, "[rad/s]");

  py::class_<RigidBodyState>(m, "RigidBodyState",
                             "Rigid body state (docs/conventions.md): p_W (3,) centre of mass [m], q_WB (4,) unit "
                             "quaternion (x, y, z, w), or (w, x, y, z) with scalar_first=True, v_W (3,) [m/s] in W, "
                             "w_B (3,) angular velocity [rad/s] in B (None: zero, identity). q_WB is normalised; "
                             "ValueError if | |q| - 1 | > 1e-6.")
      .def(py::init([](py::handle p_W, py::handle q_WB, py::handle v_W, py::handle w_B, py::handle scalar_first) {
             const bool wxyz = py_io::as_bool(scalar_first, "scalar_first");
             const Eigen::Quaterniond q =
                 q_WB.is_none() ? Eigen::Quaterniond::Identity()
                                : checked_unit_quaternion(py_io::as_quaternion(q_WB, "q_WB", wxyz), "q_WB");
             return RigidBodyState{py_io::as_vector3_or_zero(p_W, "p_W"), q, py_io::as_vector3_or_zero(v_W, "v_W"),
                                   py_io::as_vector3_or_zero(w_B, "w_B")};
           }),
           py::arg("p_W") = py::none(), py::arg("q_WB") = py::none(), py::arg("v_W") = py::none(),
           py::arg("w_B") = py::none(), py::arg("scalar_first") = false)
      .def_property_readonly("p_W", [](const RigidBodyState& s) { return py_io::to_array(s.p_W); }, "(3,) [m]")
      .def_property_readonly(
          "q_WB", [](const RigidBodyState& s) { return py_io::to_array(s.q_WB, false); }, "(4,) (x, y, z, w)")
      .def(
          "quaternion",
          [](const RigidBodyState& s, py::handle scalar_first) {
            return py_io::to_array(s.q_WB, py_io::as_bool(scalar_first, "scalar_first"));
          },
          py::arg("scalar_first") = false, "q_WB (4,) as (x, y, z, w), or (w, x, y, z) with scalar_first=True")
      .def_property_readonly("v_W", [](const RigidBodyState& s) { return py_io::to_array(s.v_W); }, "(3,) [m/s]")
      .def_property_readonly("w_B", [](const RigidBodyState& s) { return py_io::to_array(s.w_B); }, "(3,) [rad/s]");
}

const char* const body_state_doc =
    "body: a RigidBody, PlanarBody or Particle; state: its state (RigidBodyState, PlanarBodyState or "
    "ParticleState), finite (ValueError naming it otherwise, e.g. for a state a diverged step returned). ";

void bind_dynamics_functions(py::module_& m) {
  py::class_<KineticEnergy>(m, "KineticEnergy", "Kinetic energy split: translational 1/2 m v.v, rotational 1/2 w.I w [J].")
      .def_readonly("translational", &KineticEnergy::translational, "[J]")
      .def_readonly("rotational", &KineticEnergy::rotational, "[J]")
      .def_property_readonly("total", &KineticEnergy::total, "[J]");

  m.def(
      "forward_dynamics",
      [](py::handle body, py::handle state, py::handle force, py::handle torque, py::handle point, py::handle frame_arg,
         py::handle gravity) {
        const Frame frame = as_frame(frame_arg);
        return dispatch(
            body, state,
            [&](const RigidBody& b, const RigidBodyState& s) {
              const ComWrench w = wrench_at_com(s.q_WB, py_io::as_vector3_or_zero(force, "force"),
                                                py_io::as_vector3_or_zero(torque, "torque"),
                                                py_io::as_vector3_or_zero(point, "point"), frame);
              const BodyAcceleration a = forward_dynamics(b, s, w, as_gravity(gravity));
              return py::make_tuple(finite_result(a.a_W, "forward_dynamics a_W"),
                                    finite_result(a.alpha_B, "forward_dynamics alpha_B"));
            },
            [&](const PlanarBody& b, const PlanarBodyState& s) {
              const double n = torque.is_none() ? 0.0 : py_io::as_scalar(torque, "torque");
              const PlanarWrench w = wrench_at_com(s.theta, py_io::as_vector2_or_zero(force, "force"), n,
                                                   py_io::as_vector2_or_zero(point, "point"), frame);
              const PlanarAcceleration a = forward_dynamics(b, s, w, as_planar_gravity(gravity));
              return py::make_tuple(finite_result(a.a_W, "forward_dynamics a_W"),
                                    finite_result(a.alpha, "forward_dynamics alpha"));
            },
            [&](const Particle& p, const ParticleState& s) {
              require_none_for_particle(torque, "torque", "a point mass takes no couple");
              require_none_for_particle(point, "point", "a point mass has one point");
              if (frame != Frame::world) py_io::throw_value_error("frame", "'world' for a Particle", "'body'");
              return finite_result(forward_dynamics(p, s, py_io::as_vector3_or_zero(force, "force"), as_gravity(gravity)),
                                   "forward_dynamics a_W");
            });
      },
      py::arg("body"), py::arg("state"), py::arg("force") = py::none(), py::arg("torque") = py::none(),
      py::arg("point") = py::none(), py::arg("frame") = "world", py::arg("gravity") = py::none(),
      (std::string("Accelerations of `body` in `state` under a force applied at `point` and a couple `torque`.\n") +
       body_state_doc +
       "\nRigidBody: force (3,) [N] at point (p_GP (3,) [m], from the centre of mass; None = the centre of mass), "
       "torque (3,) [N m], all expressed in `frame` ('world' or 'body'), gravity None/False, True = (0, 0, -9.81) "
       "or (3,) [m/s^2] in W; returns (a_W (3,) [m/s^2] of the centre of mass in W, alpha_B (3,) [rad/s^2] in B). "
       "Newton: m a = f + m g; Euler: I alpha + w x I w = n_G.\n"
       "PlanarBody: in-plane force (2,) [N] at point (2,) [m], torque [N m] about z, gravity None or (2,) "
       "[m/s^2]; returns (a_W (2,), alpha [rad/s^2]); I_zz alpha = n_G.\n"
       "Particle: force (3,) [N] in W (torque and point None, frame 'world'); returns a_W (3,) = force/m + g.")
          .c_str());

  m.def(
      "inverse_dynamics",
      [](py::handle body, py::handle state, py::handle a_W, py::handle alpha_B, py::handle gravity) {
        return dispatch(
            body, state,
            [&](const RigidBody& b, const RigidBodyState& s) {
              const ComWrench w = inverse_dynamics(
                  b, s, BodyAcceleration{py_io::as_vector3(a_W, "a_W"), py_io::as_vector3(alpha_B, "alpha_B")},
                  as_gravity(gravity));
              return py::make_tuple(finite_result(w.f_W, "inverse_dynamics f_W"), finite_result(w.n_B, "inverse_dynamics n_B"));
            },
            [&](const PlanarBody& b, const PlanarBodyState& s) {
              const PlanarWrench w =
                  inverse_dynamics(b, s, PlanarAcceleration{py_io::as_vector2(a_W, "a_W"), py_io::as_scalar(alpha_B, "alpha_B")},
                                   as_planar_gravity(gravity));
              return py::make_tuple(finite_result(w.f_W, "inverse_dynamics f_W"), finite_result(w.n, "inverse_dynamics n"));
            },
            [&](const Particle& p, const ParticleState& s) {
              require_none_for_particle(alpha_B, "alpha_B", "a point mass has no angular acceleration");
              return finite_result(inverse_dynamics(p, s, py_io::as_vector3(a_W, "a_W"), as_gravity(gravity)),
                                   "inverse_dynamics f_W");
            });
      },
      py::arg("body"), py::arg("state"), py::arg("a_W"), py::arg("alpha_B") = py::none(), py::arg("gravity") = py::none(),
      (std::string("The applied wrench the motion requires (undoes forward_dynamics with a centre-of-mass load).\n") +
       body_state_doc +
       "\nRigidBody: a_W (3,) [m/s^2] in W, alpha_B (3,) [rad/s^2] in B, gravity as forward_dynamics; returns "
       "(f_W (3,) [N] in W, n_B (3,) [N m] about the centre of mass in B), f_W = m (a_W - g), "
       "n_B = I alpha_B + w_B x I w_B.\n"
       "PlanarBody: a_W (2,), alpha_B [rad/s^2] about z, gravity None or (2,); returns (f_W (2,) [N], n [N m]).\n"
       "Particle: a_W (3,) (alpha_B None); returns f_W (3,) = m (a_W - g).")
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
              return finite_result(point.is_none() ? angular_momentum(b, s)
                                                   : angular_momentum(b, s, py_io::as_vector3(point, "point")),
                                   "angular_momentum");
            },
            [&](const PlanarBody& b, const PlanarBodyState& s) {
              return finite_result(point.is_none() ? angular_momentum(b, s)
                                                   : angular_momentum(b, s, py_io::as_vector2(point, "point")),
                                   "angular_momentum");
            },
            [&](const Particle& p, const ParticleState& s) {
              return finite_result(point.is_none() ? angular_momentum(p, s)
                                                   : angular_momentum(p, s, py_io::as_vector3(point, "point")),
                                   "angular_momentum");
            });
      },
      py::arg("body"), py::arg("state"), py::arg("point") = py::none(),
      (std::string("Angular momentum about the point fixed in W at `point` (p_WP [m]; None = the centre of mass, "
                   "for a Particle the particle itself). ") +
       body_state_doc +
       "\nRigidBody: (3,) [kg m^2/s] in W, H_P = R_WB I w_B + (p_W - p_WP) x m v_W. PlanarBody: H_z [kg m^2/s] "
       "about z, I_zz omega + (p_W - p_WP) x m v_W, point (2,). Particle: (3,), (p_W - p_WP) x m v_W.")
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
      (std::string("KineticEnergy(translational = 1/2 m v.v, rotational = 1/2 w_B.I w_B, 1/2 I_zz omega^2 for a "
                   "PlanarBody, 0 for a Particle) [J]. ") +
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
      py::arg("body"), py::arg("state"), py::arg("gravity") = true,
      (std::string("Potential energy of uniform gravity, -m g.p_W [J]: gravity True = (0, 0, -9.81) m/s^2, or (3,) "
                   "in W; for a PlanarBody an in-plane (2,) [m/s^2] (required). ") +
       body_state_doc)
          .c_str());

  m.def(
      "power",
      [](py::handle state, py::handle f_W, py::handle n_B) -> py::object {
        if (py::isinstance<RigidBodyState>(state)) {
          const RigidBodyState& s = checked_state_of<RigidBodyState>(state, "RigidBody");
          return py::cast(finite_result(
              power(s, ComWrench{py_io::as_vector3(f_W, "f_W"), py_io::as_vector3_or_zero(n_B, "n_B")}), "power"));
        }
        if (py::isinstance<PlanarBodyState>(state)) {
          const PlanarBodyState& s = checked_state_of<PlanarBodyState>(state, "PlanarBody");
          const double n = n_B.is_none() ? 0.0 : py_io::as_scalar(n_B, "n_B");
          return py::cast(finite_result(power(s, PlanarWrench{py_io::as_vector2(f_W, "f_W"), n}), "power"));
        }
        if (py::isinstance<ParticleState>(state)) {
          const ParticleState& s = checked_state_of<ParticleState>(state, "Particle");
          require_none_for_particle(n_B, "n_B", "a point mass takes no couple");
          return py::cast(finite_result(power(s, py_io::as_vector3(f_W, "f_W")), "power"));
        }
        py_io::throw_type_error("state", "a RigidBodyState, PlanarBodyState or ParticleState", state);
      },
      py::arg("state"), py::arg("f_W"), py::arg("n_B") = py::none(),
      "Power [W] of a force f_W [N] in W at the centre of mass and a moment n_B about it (None: none): "
      "f_W.v_W + n_B.w_B. RigidBodyState: f_W (3,), n_B (3,) [N m] in B; PlanarBodyState: f_W (2,), n_B [N m] "
      "about z; ParticleState: f_W (3,) only.");

  m.def(
      "apply_impulse",
      [](py::handle body, py::handle state, py::handle impulse, py::handle point, py::handle frame_arg,
         py::handle angular_impulse) {
        const Frame frame = as_frame(frame_arg);
        return dispatch(
            body, state,
            [&](const RigidBody& b, const RigidBodyState& s) {
              return checked(apply_impulse(b, s, py_io::as_vector3(impulse, "impulse"),
                                           py_io::as_vector3_or_zero(point, "point"), frame,
                                           py_io::as_vector3_or_zero(angular_impulse, "angular_impulse")),
                             "apply_impulse");
            },
            [&](const PlanarBody& b, const PlanarBodyState& s) {
              const double J = angular_impulse.is_none() ? 0.0 : py_io::as_scalar(angular_impulse, "angular_impulse");
              return checked(apply_impulse(b, s, py_io::as_vector2(impulse, "impulse"),
                                           py_io::as_vector2_or_zero(point, "point"), frame, J),
                             "apply_impulse");
            },
            [&](const Particle& p, const ParticleState& s) {
              require_none_for_particle(point, "point", "a point mass has one point");
              require_none_for_particle(angular_impulse, "angular_impulse", "a point mass takes no angular impulse");
              if (frame != Frame::world) py_io::throw_value_error("frame", "'world' for a Particle", "'body'");
              return checked(apply_impulse(p, s, py_io::as_vector3(impulse, "impulse")), "apply_impulse");
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
  bind_dynamics_functions(m);
}

}  // namespace rigiddyn::bindings
