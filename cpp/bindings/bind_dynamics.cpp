// Python bindings of the dynamics layer: models (Particle, PlanarBody, RigidBody), their states,
// applied loads, one `step` of any method, `simulate`, and the method registry `methods()`.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "numpy_io.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/dynamics/particle_dynamics.hpp"
#include "rigiddyn/dynamics/planar_body_dynamics.hpp"
#include "rigiddyn/dynamics/rigid_body_dynamics.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <memory>
#include <string>
#include <variant>

namespace rigiddyn::bindings {

namespace py = pybind11;
using py_io::Array;

namespace {

Eigen::Vector2d as_vector2(py::handle obj, const std::string& name) {
  const py_io::Stack s = py_io::as_stack(obj, name, {2});
  if (s.stacked) throw py::value_error(name + ": expected shape (2,), got a stack of " + std::to_string(s.n));
  return Eigen::Vector2d(s.item(0, 2)[0], s.item(0, 2)[1]);
}

Frame as_frame(const std::string& frame) {
  if (frame == "world") return Frame::world;
  if (frame == "body") return Frame::body;
  throw_invalid("frame", "'world' or 'body'", "'" + frame + "'");
}

// None or False: no gravity; True: (0, 0, -9.81); else a 3-vector [m/s²].
Eigen::Vector3d as_gravity(py::handle obj) {
  if (obj.is_none()) return Eigen::Vector3d::Zero();
  if (py::isinstance<py::bool_>(obj)) return obj.cast<bool>() ? standard_gravity() : Eigen::Vector3d::Zero();
  return py_io::as_vector3(obj, "gravity");
}

std::vector<AppliedLoad> as_loads(py::handle obj) {
  std::vector<AppliedLoad> loads;
  if (obj.is_none()) return loads;
  if (py::isinstance<AppliedLoad>(obj)) return {obj.cast<AppliedLoad>()};
  for (py::handle item : obj) {
    if (!py::isinstance<AppliedLoad>(item)) {
      throw py::type_error("loads: expected AppliedLoad items, got " +
                           std::string(py::str(py::type::of(item).attr("__name__"))));
    }
    loads.push_back(item.cast<AppliedLoad>());
  }
  return loads;
}

// RigidBody's `check`: None (InertiaCheck.physical), an InertiaCheck, or, for backward compatibility,
// a bool meaning require_triangle_inequality (also accepted as that keyword).
InertiaCheck as_inertia_check(py::handle check, py::handle require_triangle_inequality) {
  auto from = [](py::handle obj, const std::string& name) {
    if (py::isinstance<py::bool_>(obj)) return obj.cast<bool>() ? InertiaCheck::physical : InertiaCheck::allow_unrealizable;
    if (py::isinstance<InertiaCheck>(obj)) return obj.cast<InertiaCheck>();
    throw py::type_error(name + ": expected an InertiaCheck (or a bool), got " +
                         std::string(py::str(py::type::of(obj).attr("__name__"))));
  };
  if (require_triangle_inequality.is_none()) return check.is_none() ? InertiaCheck::physical : from(check, "check");
  const InertiaCheck legacy = from(require_triangle_inequality, "require_triangle_inequality");
  if (!check.is_none() && from(check, "check") != legacy) {
    throw py::value_error("require_triangle_inequality: expected agreement with check, got both, conflicting");
  }
  return legacy;
}

SimulationOptions as_options(double dt, const std::string& method, py::handle loads, py::handle gravity, double t0) {
  SimulationOptions o;
  o.method = method_from_name(method, "method");
  o.dt = dt;
  o.t0 = t0;
  o.loads = as_loads(loads);
  o.gravity_W = as_gravity(gravity);
  return o;
}

// A numpy array taking ownership of a std::vector (no copy).
Array adopt(std::vector<double>&& data, std::vector<py::ssize_t> shape) {
  auto* owner = new std::vector<double>(std::move(data));
  py::capsule free_owner(owner, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return Array(shape, owner->data(), free_owner);
}

// simulate's result: numpy arrays, one row per record.
struct SimulationResult {
  Array t, p_W, q_WB, v_W, w_B, kinetic_energy, total_energy, angular_momentum_norm, quaternion_norm_error, work;
  bool diverged;
  std::int64_t unconverged_steps;
  double elapsed_seconds;
};

SimulationResult to_result(Trajectory&& tr, bool scalar_first) {
  const auto n = static_cast<py::ssize_t>(tr.size());
  if (scalar_first) {
    for (py::ssize_t i = 0; i < n; ++i) {
      double* q = tr.q_WB.data() + 4 * i;
      const double w = q[3];
      q[3] = q[2], q[2] = q[1], q[1] = q[0], q[0] = w;
    }
  }
  return SimulationResult{adopt(std::move(tr.t), {n}),
                          adopt(std::move(tr.p_W), {n, 3}),
                          adopt(std::move(tr.q_WB), {n, 4}),
                          adopt(std::move(tr.v_W), {n, 3}),
                          adopt(std::move(tr.w_B), {n, 3}),
                          adopt(std::move(tr.kinetic_energy), {n}),
                          adopt(std::move(tr.total_energy), {n}),
                          adopt(std::move(tr.angular_momentum_norm), {n}),
                          adopt(std::move(tr.quaternion_norm_error), {n}),
                          adopt(std::move(tr.work), {n}),
                          tr.diverged,
                          tr.unconverged_steps,
                          tr.elapsed_seconds};
}

template <class Body, class State>
SimulationResult simulate_py(const Body& body, const State& initial, double dt, std::int64_t steps,
                             const std::string& method, std::int64_t record_every, py::handle loads,
                             py::handle gravity, double t0, bool scalar_first) {
  SimulationOptions o = as_options(dt, method, loads, gravity, t0);
  o.steps = steps;
  o.record_every = record_every;
  Trajectory tr;
  {
    py::gil_scoped_release release;
    tr = simulate(body, initial, o);
  }
  if (tr.diverged) {
    const std::string msg = "simulate: the state became non-finite by t = " + format_value(tr.t.back()) +
                            " (method '" + method + "', dt = " + format_value(dt) + "); the run stopped there";
    if (PyErr_WarnEx(PyExc_RuntimeWarning, msg.c_str(), 1) != 0) throw py::error_already_set();
  }
  if (tr.unconverged_steps > 0) {
    const std::string msg = "simulate: the implicit solve of method '" + method + "' did not converge in " +
                            std::to_string(tr.unconverged_steps) + " of " + std::to_string(steps) +
                            " steps at dt = " + format_value(dt) +
                            " (its conservation is lost there); reduce dt (see methods() stability_limit)";
    if (PyErr_WarnEx(PyExc_RuntimeWarning, msg.c_str(), 1) != 0) throw py::error_already_set();
  }
  return to_result(std::move(tr), scalar_first);
}

template <class Body, class State>
State step_py(const Body& body, const State& state, double dt, const std::string& method, py::handle loads,
              py::handle gravity, double t) {
  return step(body, state, as_options(dt, method, loads, gravity, t));
}

// forward/inverse dynamics, momentum, energy, power and impulse of a RigidBody
void bind_dynamics_functions(py::module_& m) {
  py::class_<KineticEnergy>(m, "KineticEnergy", "Kinetic energy split: translational 1/2 m v.v, rotational 1/2 w.I w [J].")
      .def_readonly("translational", &KineticEnergy::translational, "[J]")
      .def_readonly("rotational", &KineticEnergy::rotational, "[J]")
      .def_property_readonly("total", &KineticEnergy::total, "[J]");

  m.def(
      "forward_dynamics",
      [](const RigidBody& body, const RigidBodyState& state, py::handle force, py::handle torque, py::handle point,
         const std::string& frame, py::handle gravity) {
        const ComWrench w = wrench_at_com(state.q_WB, py_io::as_vector3_or_zero(force, "force"), py_io::as_vector3_or_zero(torque, "torque"),
                                          py_io::as_vector3_or_zero(point, "point"), as_frame(frame));
        const BodyAcceleration a = forward_dynamics(body, state, w, as_gravity(gravity));
        return py::make_tuple(py_io::to_array(a.a_W), py_io::to_array(a.alpha_B));
      },
      py::arg("body"), py::arg("state"), py::arg("force") = py::none(), py::arg("torque") = py::none(),
      py::arg("point") = py::none(), py::arg("frame") = "world", py::arg("gravity") = py::none(),
      "Accelerations (a_W (3,) [m/s^2] of the centre of mass in W, alpha_B (3,) [rad/s^2] in B) of `body` in "
      "`state` under a force (3,) [N] applied at `point` (p_GP (3,) [m], position of the point relative to the "
      "centre of mass; None = the centre of mass) and a couple torque (3,) [N m], all expressed in `frame` "
      "('world' or 'body'), plus gravity (None/False, True = (0, 0, -9.81), or (3,) [m/s^2] in W). "
      "Newton: m a = f + m g; Euler: I alpha + w x I w = n_G.");

  m.def(
      "inverse_dynamics",
      [](const RigidBody& body, const RigidBodyState& state, py::handle a_W, py::handle alpha_B, py::handle gravity) {
        const ComWrench w = inverse_dynamics(
            body, state, BodyAcceleration{py_io::as_vector3(a_W, "a_W"), py_io::as_vector3(alpha_B, "alpha_B")},
            as_gravity(gravity));
        return py::make_tuple(py_io::to_array(w.f_W), py_io::to_array(w.n_B));
      },
      py::arg("body"), py::arg("state"), py::arg("a_W"), py::arg("alpha_B"), py::arg("gravity") = py::none(),
      "The applied wrench the motion requires: (f_W (3,) [N] in W, n_B (3,) [N m] about the centre of mass in B), "
      "f_W = m (a_W - g), n_B = I alpha_B + w_B x I w_B. Undoes forward_dynamics with a centre-of-mass load.");

  m.def(
      "linear_momentum",
      [](const RigidBody& body, const RigidBodyState& state) { return py_io::to_array(linear_momentum(body, state)); },
      py::arg("body"), py::arg("state"), "Linear momentum m v_W (3,) [kg m/s] in W.");

  m.def(
      "angular_momentum",
      [](const RigidBody& body, const RigidBodyState& state, py::handle point) {
        if (point.is_none()) return py_io::to_array(angular_momentum(body, state));
        return py_io::to_array(angular_momentum(body, state, py_io::as_vector3(point, "point")));
      },
      py::arg("body"), py::arg("state"), py::arg("point") = py::none(),
      "Angular momentum (3,) [kg m^2/s] in W about the point fixed in W at `point` (p_WP (3,) [m]; None = "
      "the centre of mass): H_P = R_WB I w_B + (p_W - p_WP) x m v_W.");

  m.def("kinetic_energy", py::overload_cast<const RigidBody&, const RigidBodyState&>(&kinetic_energy), py::arg("body"),
        py::arg("state"),
        "KineticEnergy(translational = 1/2 m v.v, rotational = 1/2 w_B.I w_B) [J].");

  m.def(
      "potential_energy",
      [](const RigidBody& body, const RigidBodyState& state, py::handle gravity) {
        return potential_energy(body, state, as_gravity(gravity));
      },
      py::arg("body"), py::arg("state"), py::arg("gravity") = true,
      "Potential energy of uniform gravity, -m g.p_W [J] (True = (0, 0, -9.81) m/s^2, or (3,) in W).");

  m.def(
      "power",
      [](const RigidBodyState& state, py::handle f_W, py::handle n_B) {
        return power(state, ComWrench{py_io::as_vector3(f_W, "f_W"), py_io::as_vector3(n_B, "n_B")});
      },
      py::arg("state"), py::arg("f_W"), py::arg("n_B"),
      "Power [W] of a force f_W (3,) [N] in W at the centre of mass and a moment n_B (3,) [N m] about it in B: "
      "f_W.v_W + n_B.w_B.");

  m.def(
      "apply_impulse",
      [](const RigidBody& body, const RigidBodyState& state, py::handle impulse, py::handle point,
         const std::string& frame, py::handle angular_impulse) {
        return apply_impulse(body, state, py_io::as_vector3(impulse, "impulse"), py_io::as_vector3_or_zero(point, "point"),
                             as_frame(frame), py_io::as_vector3_or_zero(angular_impulse, "angular_impulse"));
      },
      py::arg("body"), py::arg("state"), py::arg("impulse"), py::arg("point") = py::none(),
      py::arg("frame") = "world", py::arg("angular_impulse") = py::none(),
      "The state just after an impulse (3,) [N s] at `point` (p_GP (3,) [m] relative to the centre of mass; "
      "None = the centre of mass) and an angular impulse (3,) [N m s], all in `frame` ('world' or 'body'): "
      "m dv = impulse, I dw = p_GP x impulse + angular_impulse (impulse-momentum, seed 001).");
}

Eigen::Vector2d optional_vector2(py::handle obj, const std::string& name) {
  return obj.is_none() ? Eigen::Vector2d::Zero() : as_vector2(obj, name);
}

// The same functions for a Particle (everything in W, no rotation) and a PlanarBody (in-plane vectors
// (2,) in W, moments and angular quantities as z scalars); pybind11 picks the overload by the body type.
void bind_particle_planar_dynamics_functions(py::module_& m) {
  m.def(
      "forward_dynamics",
      [](const Particle& particle, const ParticleState& state, py::handle force, py::handle gravity) {
        return py_io::to_array(forward_dynamics(particle, state, py_io::as_vector3_or_zero(force, "force"), as_gravity(gravity)));
      },
      py::arg("body"), py::arg("state"), py::arg("force") = py::none(), py::arg("gravity") = py::none(),
      "Particle: acceleration a_W (3,) [m/s^2] = force/m + g under a force (3,) [N] in W and gravity "
      "(None/False, True = (0, 0, -9.81), or (3,) [m/s^2] in W).");
  m.def(
      "forward_dynamics",
      [](const PlanarBody& body, const PlanarBodyState& state, py::handle force, double torque, py::handle point,
         const std::string& frame, py::handle gravity) {
        const PlanarWrench w = wrench_at_com(state.theta, optional_vector2(force, "force"), torque,
                                             optional_vector2(point, "point"), as_frame(frame));
        const PlanarAcceleration a = forward_dynamics(body, state, w, optional_vector2(gravity, "gravity"));
        return py::make_tuple(py_io::to_array(a.a_W), a.alpha);
      },
      py::arg("body"), py::arg("state"), py::arg("force") = py::none(), py::arg("torque") = 0.0,
      py::arg("point") = py::none(), py::arg("frame") = "world", py::arg("gravity") = py::none(),
      "PlanarBody: (a_W (2,) [m/s^2] in W, alpha [rad/s^2]) under an in-plane force (2,) [N] applied at `point` "
      "(p_GP (2,) [m] from the centre of mass; None = the centre of mass), both in `frame` ('world' or 'body'), "
      "a couple torque [N m] about z, and in-plane gravity (None or (2,) [m/s^2] in W). m a = f + m g, "
      "I_zz alpha = n_G.");

  m.def(
      "inverse_dynamics",
      [](const Particle& particle, const ParticleState& state, py::handle a_W, py::handle gravity) {
        return py_io::to_array(inverse_dynamics(particle, state, py_io::as_vector3(a_W, "a_W"), as_gravity(gravity)));
      },
      py::arg("body"), py::arg("state"), py::arg("a_W"), py::arg("gravity") = py::none(),
      "Particle: the force f_W (3,) [N] in W the acceleration a_W (3,) [m/s^2] requires, m (a_W - g).");
  m.def(
      "inverse_dynamics",
      [](const PlanarBody& body, const PlanarBodyState& state, py::handle a_W, double alpha, py::handle gravity) {
        const PlanarWrench w =
            inverse_dynamics(body, state, PlanarAcceleration{as_vector2(a_W, "a_W"), alpha}, optional_vector2(gravity, "gravity"));
        return py::make_tuple(py_io::to_array(w.f_W), w.n);
      },
      py::arg("body"), py::arg("state"), py::arg("a_W"), py::arg("alpha"), py::arg("gravity") = py::none(),
      "PlanarBody: the wrench the motion requires, (f_W (2,) [N] in W, n [N m] about the centre of mass): "
      "f_W = m (a_W - g), n = I_zz alpha.");

  m.def(
      "linear_momentum",
      [](const Particle& particle, const ParticleState& state) { return py_io::to_array(linear_momentum(particle, state)); },
      py::arg("body"), py::arg("state"), "Particle: m v_W (3,) [kg m/s] in W.");
  m.def(
      "linear_momentum",
      [](const PlanarBody& body, const PlanarBodyState& state) { return py_io::to_array(linear_momentum(body, state)); },
      py::arg("body"), py::arg("state"), "PlanarBody: m v_W (2,) [kg m/s] in W.");

  m.def(
      "angular_momentum",
      [](const Particle& particle, const ParticleState& state, py::handle point) {
        if (point.is_none()) return py_io::to_array(angular_momentum(particle, state));
        return py_io::to_array(angular_momentum(particle, state, py_io::as_vector3(point, "point")));
      },
      py::arg("body"), py::arg("state"), py::arg("point") = py::none(),
      "Particle: (p_W - p_WP) x m v_W (3,) [kg m^2/s] in W about the point fixed in W at `point` (p_WP (3,) [m]; "
      "None = the particle itself: zero).");
  m.def(
      "angular_momentum",
      [](const PlanarBody& body, const PlanarBodyState& state, py::handle point) {
        if (point.is_none()) return angular_momentum(body, state);
        return angular_momentum(body, state, as_vector2(point, "point"));
      },
      py::arg("body"), py::arg("state"), py::arg("point") = py::none(),
      "PlanarBody: H_z [kg m^2/s] about the point fixed in W at `point` (p_WP (2,) [m]; None = the centre of "
      "mass): I_zz omega + (p_W - p_WP) x m v_W.");

  m.def("kinetic_energy", py::overload_cast<const Particle&, const ParticleState&>(&kinetic_energy), py::arg("body"),
        py::arg("state"), "Particle: KineticEnergy(translational = 1/2 m v.v, rotational = 0) [J].");
  m.def("kinetic_energy", py::overload_cast<const PlanarBody&, const PlanarBodyState&>(&kinetic_energy),
        py::arg("body"), py::arg("state"),
        "PlanarBody: KineticEnergy(translational = 1/2 m v.v, rotational = 1/2 I_zz omega^2) [J].");

  m.def(
      "potential_energy",
      [](const Particle& particle, const ParticleState& state, py::handle gravity) {
        return potential_energy(particle, state, as_gravity(gravity));
      },
      py::arg("body"), py::arg("state"), py::arg("gravity") = true,
      "Particle: -m g.p_W [J] (True = (0, 0, -9.81) m/s^2, or (3,) in W).");
  m.def(
      "potential_energy",
      [](const PlanarBody& body, const PlanarBodyState& state, py::handle gravity) {
        return potential_energy(body, state, as_vector2(gravity, "gravity"));
      },
      py::arg("body"), py::arg("state"), py::arg("gravity"),
      "PlanarBody: -m g.p_W [J] for in-plane gravity g (2,) [m/s^2] in W.");

  m.def(
      "power", [](const ParticleState& state, py::handle f_W) { return power(state, py_io::as_vector3(f_W, "f_W")); },
      py::arg("state"), py::arg("f_W"), "Particle: power f_W.v_W [W] of a force f_W (3,) [N] in W.");
  m.def(
      "power",
      [](const PlanarBodyState& state, py::handle f_W, double n) {
        return power(state, PlanarWrench{as_vector2(f_W, "f_W"), n});
      },
      py::arg("state"), py::arg("f_W"), py::arg("n"),
      "PlanarBody: power f_W.v_W + n omega [W] of a force f_W (2,) [N] in W at the centre of mass and a moment "
      "n [N m] about it.");

  m.def(
      "apply_impulse",
      [](const Particle& particle, const ParticleState& state, py::handle impulse) {
        return apply_impulse(particle, state, py_io::as_vector3(impulse, "impulse"));
      },
      py::arg("body"), py::arg("state"), py::arg("impulse"),
      "Particle: the state just after an impulse (3,) [N s] in W: m dv = impulse.");
  m.def(
      "apply_impulse",
      [](const PlanarBody& body, const PlanarBodyState& state, py::handle impulse, py::handle point,
         const std::string& frame, double angular_impulse) {
        return apply_impulse(body, state, as_vector2(impulse, "impulse"), optional_vector2(point, "point"),
                             as_frame(frame), angular_impulse);
      },
      py::arg("body"), py::arg("state"), py::arg("impulse"), py::arg("point") = py::none(),
      py::arg("frame") = "world", py::arg("angular_impulse") = 0.0,
      "PlanarBody: the state just after an in-plane impulse (2,) [N s] at `point` (p_GP (2,) [m] from the centre "
      "of mass; None = the centre of mass), both in `frame` ('world' or 'body'), and an angular impulse [N m s] "
      "about z: m dv = impulse, I_zz domega = p_GP x impulse + angular_impulse.");
}

const char* const simulate_doc = R"doc(
Integrate `model` from `initial` over `steps` fixed steps of `dt` [s] with `method` (see methods()),
in C++ with the GIL released, and record every `record_every`-th step (plus the first and the last).

model/initial: Particle/ParticleState, PlanarBody/PlanarBodyState or RigidBody/RigidBodyState.
loads: an AppliedLoad or a sequence of them (piecewise-constant schedule; the loads active at the start
  of a step act during the whole step). gravity: None/False (none), True ((0, 0, -9.81) m/s^2 in W) or a
  3-vector [m/s^2] in W. t0: initial time [s]. scalar_first: quaternions as (w, x, y, z).

Returns a SimulationResult, arrays with one row per record (n records): t (n,) [s]; p_W (n, 3) [m];
q_WB (n, 4) (x, y, z, w); v_W (n, 3) [m/s]; w_B (n, 3) [rad/s]; kinetic_energy (n,) [J];
total_energy (n,) kinetic + gravity potential [J]; angular_momentum_norm (n,) |H_G| [kg m^2/s];
quaternion_norm_error (n,) |q| - 1; work (n,) work of loads and gravity since t0 [J], integrated by the
same method (kinetic_energy - kinetic_energy[0] ~ work); diverged; unconverged_steps (implicit solves that
hit their iteration cap); elapsed_seconds (C++ loop wall time).
A particle records q = identity, w = 0; a planar body p = (x, y, 0), q = Rz(theta), w = (0, 0, omega).
Warns RuntimeWarning and stops if the state becomes non-finite; warns RuntimeWarning (naming dt and the
count) if an implicit solve did not converge. ValueError names a bad argument.
)doc";

const char* const step_doc = R"doc(
One step of `method` (see methods()) of length dt [s] from `state` at time t [s] under `loads`
(AppliedLoad or sequence) and `gravity` (None/False, True for (0, 0, -9.81) m/s^2, or a 3-vector).
Returns the new state (same type as `state`). ValueError names a bad argument.
)doc";

}  // namespace

void bind_dynamics(py::module_& m) {
  py::class_<Particle>(m, "Particle", "A point mass (3 DOF; seed 000 section 4.11): mass [kg] > 0.")
      .def(py::init<double>(), py::arg("mass"))
      .def_property_readonly("mass", &Particle::mass, "mass [kg]");

  py::class_<PlanarBody>(m, "PlanarBody",
                         "A rigid body moving in the xy plane of W (x, y, theta; seed 001 plane kinetics): mass [kg] "
                         "and inertia_zz [kg m^2] about the z axis through the centre of mass, both > 0.")
      .def(py::init<double, double>(), py::arg("mass"), py::arg("inertia_zz"))
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
      .def(py::init([](double mass, py::handle inertia_com, py::handle check, py::handle require_triangle_inequality) {
             return RigidBody(mass, py_io::as_matrix3(inertia_com, "inertia_com"),
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

  py::class_<ParticleState>(m, "ParticleState", "Particle state: p_W (3,) [m] and v_W (3,) [m/s] in W.")
      .def(py::init([](py::handle p_W, py::handle v_W) {
             return ParticleState{py_io::as_vector3(p_W, "p_W"), py_io::as_vector3(v_W, "v_W")};
           }),
           py::arg("p_W") = Eigen::Vector3d::Zero(), py::arg("v_W") = Eigen::Vector3d::Zero())
      .def_property_readonly("p_W", [](const ParticleState& s) { return py_io::to_array(s.p_W); }, "(3,) [m]")
      .def_property_readonly("v_W", [](const ParticleState& s) { return py_io::to_array(s.v_W); }, "(3,) [m/s]");

  py::class_<PlanarBodyState>(m, "PlanarBodyState",
                              "Planar body state: p_W (2,) [m] centre of mass, theta [rad] angle of B about z, "
                              "v_W (2,) [m/s], omega [rad/s].")
      .def(py::init([](py::handle p_W, double theta, py::handle v_W, double omega) {
             return PlanarBodyState{as_vector2(p_W, "p_W"), theta, as_vector2(v_W, "v_W"), omega};
           }),
           py::arg("p_W") = Eigen::Vector2d::Zero(), py::arg("theta") = 0.0, py::arg("v_W") = Eigen::Vector2d::Zero(),
           py::arg("omega") = 0.0)
      .def_property_readonly("p_W", [](const PlanarBodyState& s) { return py_io::to_array(s.p_W); }, "(2,) [m]")
      .def_readonly("theta", &PlanarBodyState::theta, "[rad]")
      .def_property_readonly("v_W", [](const PlanarBodyState& s) { return py_io::to_array(s.v_W); }, "(2,) [m/s]")
      .def_readonly("omega", &PlanarBodyState::omega, "[rad/s]");

  py::class_<RigidBodyState>(m, "RigidBodyState",
                             "Rigid body state (docs/conventions.md): p_W (3,) centre of mass [m], q_WB (4,) unit "
                             "quaternion (x, y, z, w), or (w, x, y, z) with scalar_first=True, v_W (3,) [m/s] in W, "
                             "w_B (3,) angular velocity [rad/s] in B. q_WB is normalised; ValueError if | |q| - 1 | "
                             "> 1e-6.")
      .def(py::init([](py::handle p_W, py::handle q_WB, py::handle v_W, py::handle w_B, bool scalar_first) {
             RigidBodyState s{py_io::as_vector3(p_W, "p_W"), py_io::as_quaternion(q_WB, "q_WB", scalar_first),
                              py_io::as_vector3(v_W, "v_W"), py_io::as_vector3(w_B, "w_B")};
             return checked_state(s, "state");
           }),
           py::arg("p_W") = Eigen::Vector3d::Zero(), py::arg("q_WB") = Eigen::Vector4d(0, 0, 0, 1),
           py::arg("v_W") = Eigen::Vector3d::Zero(), py::arg("w_B") = Eigen::Vector3d::Zero(),
           py::arg("scalar_first") = false)
      .def_property_readonly("p_W", [](const RigidBodyState& s) { return py_io::to_array(s.p_W); }, "(3,) [m]")
      .def_property_readonly(
          "q_WB", [](const RigidBodyState& s) { return py_io::to_array(s.q_WB, false); }, "(4,) (x, y, z, w)")
      .def(
          "quaternion", [](const RigidBodyState& s, bool scalar_first) { return py_io::to_array(s.q_WB, scalar_first); },
          py::arg("scalar_first") = false, "q_WB (4,) as (x, y, z, w), or (w, x, y, z) with scalar_first=True")
      .def_property_readonly("v_W", [](const RigidBodyState& s) { return py_io::to_array(s.v_W); }, "(3,) [m/s]")
      .def_property_readonly("w_B", [](const RigidBodyState& s) { return py_io::to_array(s.w_B); }, "(3,) [rad/s]");

  py::class_<AppliedLoad>(m, "AppliedLoad",
                          "A load: force (3,) [N] through the centre of mass and couple torque (3,) [N m], both in "
                          "frame 'world' or 'body', active for t_start <= t < t_end [s].")
      .def(py::init([](py::handle force, py::handle torque, const std::string& frame, double t_start, double t_end) {
             AppliedLoad load{py_io::as_vector3(force, "force"), py_io::as_vector3(torque, "torque"), as_frame(frame),
                              t_start, t_end};
             check_loads({load});
             return load;
           }),
           py::arg("force") = Eigen::Vector3d::Zero(), py::arg("torque") = Eigen::Vector3d::Zero(),
           py::arg("frame") = "world", py::arg("t_start") = -std::numeric_limits<double>::infinity(),
           py::arg("t_end") = std::numeric_limits<double>::infinity())
      .def_property_readonly("force", [](const AppliedLoad& l) { return py_io::to_array(l.force); }, "(3,) [N]")
      .def_property_readonly("torque", [](const AppliedLoad& l) { return py_io::to_array(l.torque); }, "(3,) [N m]")
      .def_property_readonly(
          "frame", [](const AppliedLoad& l) { return l.frame == Frame::world ? "world" : "body"; }, "'world' or 'body'")
      .def_readonly("t_start", &AppliedLoad::t_start, "[s]")
      .def_readonly("t_end", &AppliedLoad::t_end, "[s]");

  py::class_<SimulationResult>(m, "SimulationResult", "simulate's records (see simulate).")
      .def_readonly("t", &SimulationResult::t, "(n,) time [s]")
      .def_readonly("p_W", &SimulationResult::p_W, "(n, 3) centre of mass position in W [m]")
      .def_readonly("q_WB", &SimulationResult::q_WB, "(n, 4) attitude, (x, y, z, w) unless scalar_first")
      .def_readonly("v_W", &SimulationResult::v_W, "(n, 3) centre of mass velocity in W [m/s]")
      .def_readonly("w_B", &SimulationResult::w_B, "(n, 3) angular velocity in B [rad/s]")
      .def_readonly("kinetic_energy", &SimulationResult::kinetic_energy, "(n,) [J]")
      .def_readonly("total_energy", &SimulationResult::total_energy, "(n,) kinetic + gravity potential [J]")
      .def_readonly("angular_momentum_norm", &SimulationResult::angular_momentum_norm,
                    "(n,) |H_G| about the centre of mass [kg m^2/s]")
      .def_readonly("quaternion_norm_error", &SimulationResult::quaternion_norm_error, "(n,) |q| - 1")
      .def_readonly("work", &SimulationResult::work, "(n,) work of loads and gravity since t0 [J]")
      .def_readonly("diverged", &SimulationResult::diverged, "True if the run stopped on a non-finite state")
      .def_readonly("unconverged_steps", &SimulationResult::unconverged_steps,
                    "number of steps whose implicit solve stopped at its iteration cap (implicit_midpoint; "
                    "0 for explicit methods); simulate warns RuntimeWarning when > 0")
      .def_readonly("elapsed_seconds", &SimulationResult::elapsed_seconds, "wall time of the C++ stepping loop [s]");

#define RIGIDDYN_SIMULATE_ARGS                                                                              \
  py::arg("model"), py::arg("initial"), py::arg("dt"), py::arg("steps"), py::arg("method") = "rk4",      \
      py::arg("record_every") = 1, py::arg("loads") = py::none(), py::arg("gravity") = py::none(),         \
      py::arg("t0") = 0.0, py::arg("scalar_first") = false
#define RIGIDDYN_STEP_ARGS                                                                                  \
  py::arg("model"), py::arg("state"), py::arg("dt"), py::arg("method") = "rk4", py::arg("loads") = py::none(), \
      py::arg("gravity") = py::none(), py::arg("t") = 0.0
  m.def("simulate", &simulate_py<RigidBody, RigidBodyState>, RIGIDDYN_SIMULATE_ARGS, simulate_doc);
  m.def("simulate", &simulate_py<PlanarBody, PlanarBodyState>, RIGIDDYN_SIMULATE_ARGS, simulate_doc);
  m.def("simulate", &simulate_py<Particle, ParticleState>, RIGIDDYN_SIMULATE_ARGS, simulate_doc);
  m.def("step", &step_py<RigidBody, RigidBodyState>, RIGIDDYN_STEP_ARGS, step_doc);
  m.def("step", &step_py<PlanarBody, PlanarBodyState>, RIGIDDYN_STEP_ARGS, step_doc);
  m.def("step", &step_py<Particle, ParticleState>, RIGIDDYN_STEP_ARGS, step_doc);
#undef RIGIDDYN_SIMULATE_ARGS
#undef RIGIDDYN_STEP_ARGS

  bind_dynamics_functions(m);
  bind_particle_planar_dynamics_functions(m);

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
          out.append(d);
        }
        return out;
      },
      "The fixed-step methods: a list of dicts with name, order (global), evaluations (derivative "
      "evaluations per step), conserves (what is kept exactly on a free rigid body), notes, stability_limit "
      "(largest dt*|w| [rad], |w| the largest body rate on the torque-free orbit, at which the method is "
      "documented stable on a free spin: inf if unconditionally, 0 if never) and exact_torque_free (True if "
      "torque-free motion is reproduced to round-off at any dt: no observed order applies).");
}

}  // namespace rigiddyn::bindings
