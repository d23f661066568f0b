// Python bindings of the exact references of bodies about a fixed point, moving frames and variable
// mass: the compound pendulum, the heavy
// symmetric (Lagrange) top, the free particle seen from a turning frame, the constant-rate burn
// (exact/compound_pendulum.hpp, lagrange_top.hpp, rotating_frame.hpp, constant_thrust.hpp). Each class
// keeps its constructor's arguments: its repr reads as that call, it pickles as them, and == compares them
// (the constructors are deterministic: equal arguments give bitwise equal states). at(t) takes a float or
// an (n,) array of times.
#include "bindings.hpp"
#include "numpy_io.hpp"
#include "repr.hpp"
#include "rigiddyn/exact/compound_pendulum.hpp"
#include "rigiddyn/exact/constant_thrust.hpp"
#include "rigiddyn/exact/lagrange_top.hpp"
#include "rigiddyn/exact/rotating_frame.hpp"
#include "value_type.hpp"

#include <string>

namespace rigiddyn::bindings {

namespace py = pybind11;
using py_io::Array;

namespace {

// == through the constructor's arguments (a tuple of bound objects and lists, compared by Python's ==),
// pickling as them; unhashable (== without a matching hash).
template <class T, class Args, class Make>
void def_value_semantics(py::class_<T>& cls, Args args, Make make, size_t size, const char* type) {
  cls.def(
         "__eq__",
         [args](const T& a, py::handle b) {
           return equal_or_not_implemented(a, b, [args](const T& x, const T& y) { return args(x).equal(args(y)); });
         },
         py::is_operator(), "Built from equal arguments (then every state is bitwise equal).")
      .def(py::pickle([args](const T& x) { return args(x); },
                      [make, size, type](const py::tuple& state) {
                        const py::tuple t = pickled_state(state, size, type);
                        return make(t);
                      }));
  cls.attr("__hash__") = py::none();
}

py::list python_list(const Eigen::Vector3d& v) { return py::cast<py::list>(py_io::to_array(v).attr("tolist")()); }

// A gravity (2,) (in W's xy plane) or (3,) [m/s^2] in W (a pint quantity is converted).
Eigen::Vector3d as_gravity_2_or_3(py::handle obj) {
  const Array g = py_io::as_array(py_io::in_si(obj, "m/s^2", "g_W"), "g_W");
  if (g.ndim() == 1 && g.shape(0) == 2) {
    const Eigen::Vector2d g2 = py_io::as_vector2(g, "g_W");
    return Eigen::Vector3d(g2.x(), g2.y(), 0.0);
  }
  return py_io::as_vector3(g, "g_W");
}

// ------------------------------------------------------------ compound pendulum

struct PyPendulum {
  CompoundPendulumSolution solution;
  PivotedPlanarBody body;
  Eigen::Vector3d g_W;
  PivotedPlanarBodyState state;
};

PyPendulum make_pendulum(py::handle body, py::handle g_W, py::handle state) {
  const PivotedPlanarBody& b = py_io::as_instance<PivotedPlanarBody>(body, "body", "a PivotedPlanarBody");
  const Eigen::Vector3d g = as_gravity_2_or_3(g_W);
  const PivotedPlanarBodyState& s = py_io::as_instance<PivotedPlanarBodyState>(state, "state", "a PivotedPlanarBodyState");
  return {CompoundPendulumSolution(b, g, s), b, g, s};
}

// (theta, omega): floats for a float t, (n,) arrays for an (n,) t.
py::tuple pendulum_at(const PyPendulum& self, py::handle t) {
  const py_io::Stack ts = py_io::as_stack(t, "t", {});
  if (!ts.stacked) {
    const PivotedPlanarBodyState s = self.solution.at(ts.array.data()[0]);
    return py::make_tuple(py_io::finite_result(s.theta, "CompoundPendulumSolution.at theta"),
                          py_io::finite_result(s.omega, "CompoundPendulumSolution.at omega"));
  }
  Array theta = py_io::new_stack(ts.n, true, {}, "theta"), omega = py_io::new_stack(ts.n, true, {}, "omega");
  double *pt = theta.mutable_data(), *pw = omega.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < ts.n; ++i) {
      const PivotedPlanarBodyState s = self.solution.at(*ts.item(i, 1));
      pt[i] = s.theta;
      pw[i] = s.omega;
    }
  }
  return py::make_tuple(py_io::finite_result(theta, "CompoundPendulumSolution.at theta"),
                        py_io::finite_result(omega, "CompoundPendulumSolution.at omega"));
}

py::tuple pendulum_args(const PyPendulum& s) { return py::make_tuple(s.body, python_list(s.g_W), s.state); }

void bind_pendulum(py::module_& m) {
  py::class_<PyPendulum> cls(
      m, "CompoundPendulumSolution",
      "Exact motion of the compound pendulum (a PivotedPlanarBody under uniform gravity) at any energy, in Jacobi's\n"
      "elliptic functions (Landau & Lifshitz, Mechanics §11; DLMF §22.19): libration sin(v/2) = k sn(w0 t + u0|k^2),\n"
      "rotation v/2 = am(k w0 t + u0|1/k^2), the separatrix and the equilibria, with v = theta - theta_stable the\n"
      "angle from the stable equilibrium (where R_WB p_OC_B points along g) and w0^2 = m g d / I_O. Accurate up\n"
      "to v0 -> pi: the complement 1 - k^2 is formed without cancellation.\n\n"
      "Parameters\n----------\n"
      "body : PivotedPlanarBody\n    Mass [kg], inertia_zz [kg m^2] about C, p_OC_B [m] in B, pivot p_WO [m] in W.\n"
      "g_W : array_like, shape (2,) or (3,)\n"
      "    Uniform gravity in W [m/s^2] (only its xy part acts); a pint quantity is converted.\n"
      "state : PivotedPlanarBodyState\n    theta [rad] and omega [rad/s] at t = 0.\n\n"
      "Raises\n------\nValueError\n    g_W, state.theta or state.omega non-finite (the message names it).\n"
      "TypeError\n    body or state of another type.\n\n"
      "See Also\n--------\nPivotedPlanarBody, jacobi_ellipj, ellipk, LagrangeTopSolution\n\n"
      "Examples\n--------\n"
      "A uniform rod 1 m long pinned at its end (I_O = m L^2/3, d = L/2, so w0^2 = 3 g/(2 L)), let go 0.5 rad\n"
      "from the bottom, swings back after one period 4 K(k^2)/w0:\n\n"
      ">>> rod = rd.PivotedPlanarBody(1.0, 1.0 / 12, [0.5, 0.0])\n"
      ">>> s = rd.CompoundPendulumSolution(rod, [0.0, -9.81], rd.PivotedPlanarBodyState(theta=-np.pi / 2 + 0.5))\n"
      ">>> s.case, f\"{s.omega0**2:.6f}\", bool(np.isclose(s.period, 4 * rd.ellipk(s.k_squared) / s.omega0))\n"
      "('libration', '14.715000', True)\n"
      ">>> theta, omega = s.at(s.period)\n"
      ">>> bool(np.isclose(theta, -np.pi / 2 + 0.5) and abs(omega) < 1e-12)\nTrue\n\n"
      "Immutable; pickles; == compares the constructor's arguments; unhashable.");
  cls.def(py::init(&make_pendulum), py::arg("body"), py::arg("g_W"), py::arg("state"),
           "body: a PivotedPlanarBody; g_W: (2,) or (3,) uniform gravity in W [m/s^2] (only its xy part acts);\n"
           "state: the PivotedPlanarBodyState (theta [rad], omega [rad/s]) at t = 0. ValueError naming g_W or\n"
           "state.theta / state.omega for non-finite values. See the class.")
      .def("at", &pendulum_at, py::arg("t"),
           "State at time t.\n\n"
           "Parameters\n----------\nt : float or array_like, shape (n,)\n    Time [s]; negative allowed.\n\n"
           "Returns\n-------\ntheta : float or ndarray, shape (n,)\n"
           "    Angle of B in W about z [rad], continuous from the initial theta (not wrapped; a rotating\n"
           "    pendulum's theta grows).\n"
           "omega : float or ndarray, shape (n,)\n    Angular velocity about z [rad/s].\n\n"
           "Examples\n--------\n"
           ">>> s = rd.CompoundPendulumSolution(rd.PivotedPlanarBody(1.0, 1.0 / 12, [0.5, 0.0]), [0.0, -9.81],\n"
           "...                                 rd.PivotedPlanarBodyState(theta=-np.pi / 2, omega=1.0))\n"
           ">>> [x.shape for x in s.at([0.0, 1.0, 2.0])]\n[(3,), (3,)]\n")
      .def_property_readonly("period", [](const PyPendulum& s) { return s.solution.period(); },
                             "Period [s]: 4 K(k^2)/w0 for a libration, the time of one turn for a rotation; inf at an\n"
                             "equilibrium, on the separatrix, and without torque and rate.")
      .def_property_readonly("case", [](const PyPendulum& s) { return to_string(s.solution.solution_case()); },
                             "'libration', 'rotation', 'separatrix', 'rest' (an equilibrium) or 'uniform' (no torque).")
      .def_property_readonly("omega0", [](const PyPendulum& s) { return py_io::finite_result(s.solution.omega0(), "CompoundPendulumSolution.omega0"); },
                             "w0 = sqrt(m g d / I_O) [rad/s], the small-oscillation angular frequency (0 without "
                             "torque).")
      .def_property_readonly("k_squared", [](const PyPendulum& s) { return py_io::finite_result(s.solution.k_squared(), "CompoundPendulumSolution.k_squared"); },
                             "k^2 = sin^2(v0/2) + (omega0_state/(2 w0))^2, dimensionless, of the initial state (> 1 "
                             "for a rotation).")
      .def_property_readonly("k_squared_complement", [](const PyPendulum& s) { return py_io::finite_result(s.solution.k_squared_complement(), "CompoundPendulumSolution.k_squared_complement"); },
                             "1 - k^2, computed without cancellation (cos^2(v0/2) at rest; negative for a rotation).")
      .def_property_readonly("amplitude", [](const PyPendulum& s) { return s.solution.amplitude(); },
                             "Amplitude 2 asin k of a libration about the stable equilibrium [rad] (pi otherwise).")
      .def_property_readonly("theta_stable", [](const PyPendulum& s) { return s.solution.theta_stable(); },
                             "theta of the stable equilibrium [rad] in (-pi, pi] (the angle of B in W about z).")
      .def_property_readonly("energy", [](const PyPendulum& s) { return py_io::finite_result(s.solution.energy(), "CompoundPendulumSolution.energy"); },
                             "Energy about O [J]: 1/2 I_O omega^2 - m g_W . (R_WB p_OC_B) (constant).")
      .def("__repr__", [](const PyPendulum& s) {
        return repr_call("CompoundPendulumSolution",
                         {{"body", py::cast(s.body)}, {"g_W", py_io::to_array(s.g_W)}, {"state", py::cast(s.state)}});
      });
  def_value_semantics(cls, &pendulum_args, [](const py::tuple& t) { return make_pendulum(t[0], t[1], t[2]); }, 3,
                      "CompoundPendulumSolution");
}

// ------------------------------------------------------------ Lagrange top

struct PyTop {
  LagrangeTopSolution solution;
  PivotedBody body;
  Eigen::Vector3d g_W;
  PivotedBodyState state;
  bool scalar_first;
};

PyTop make_top(py::handle body, py::handle g_W, py::handle state, py::handle scalar_first) {
  const bool first = py_io::as_bool(scalar_first, "scalar_first");
  const PivotedBody& b = py_io::as_instance<PivotedBody>(body, "body", "a PivotedBody");
  const Eigen::Vector3d g = py_io::as_vector3(py_io::in_si(g_W, "m/s^2", "g_W"), "g_W");
  const PivotedBodyState& s = py_io::as_instance<PivotedBodyState>(state, "state", "a PivotedBodyState");
  return {LagrangeTopSolution(b, g, s), b, g, s, first};
}

// (q_WB, w_B): (4,), (3,) or (n, 4), (n, 3).
py::tuple top_at(const PyTop& self, py::handle t) {
  const py_io::Stack ts = py_io::as_stack(t, "t", {});
  Array q = py_io::new_stack(ts.n, ts.stacked, {4}, "q_WB"), w = py_io::new_stack(ts.n, ts.stacked, {3}, "w_B");
  double *pq = q.mutable_data(), *pw = w.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < ts.n; ++i) {
      const PivotedBodyState s = self.solution.at(*ts.item(i, 1));
      py_io::write_quaternion(s.q_WB, pq + 4 * i, self.scalar_first);
      for (int k = 0; k < 3; ++k) pw[3 * i + k] = s.w_B(k);
    }
  }
  return py::make_tuple(py_io::finite_result(q, "LagrangeTopSolution.at q_WB"), py_io::finite_result(w, "LagrangeTopSolution.at w_B"));
}

// (phi, theta, psi): floats or (n,) arrays.
py::tuple top_angles_at(const PyTop& self, py::handle t) {
  const py_io::Stack ts = py_io::as_stack(t, "t", {});
  if (!ts.stacked) {
    const EulerAnglesZXZ a = self.solution.angles_at(ts.array.data()[0]);
    return py::make_tuple(py_io::finite_result(a.phi, "LagrangeTopSolution.angles_at phi"), a.theta,
                          py_io::finite_result(a.psi, "LagrangeTopSolution.angles_at psi"));
  }
  Array phi = py_io::new_stack(ts.n, true, {}, "phi"), theta = py_io::new_stack(ts.n, true, {}, "theta"),
        psi = py_io::new_stack(ts.n, true, {}, "psi");
  double *p1 = phi.mutable_data(), *p2 = theta.mutable_data(), *p3 = psi.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < ts.n; ++i) {
      const EulerAnglesZXZ a = self.solution.angles_at(*ts.item(i, 1));
      p1[i] = a.phi;
      p2[i] = a.theta;
      p3[i] = a.psi;
    }
  }
  return py::make_tuple(py_io::finite_result(phi, "LagrangeTopSolution.angles_at phi"), theta,
                        py_io::finite_result(psi, "LagrangeTopSolution.angles_at psi"));
}

py::tuple top_args(const PyTop& s) { return py::make_tuple(s.body, python_list(s.g_W), s.state, s.scalar_first); }

void bind_top(py::module_& m) {
  py::class_<PyTop> cls(
      m, "LagrangeTopSolution",
      "Exact motion of the heavy symmetric (Lagrange) top about its fixed point O (Goldstein, Classical Mechanics\n"
      "§5.7; Landau & Lifshitz, Mechanics §35): u = cos(theta) = u1 + (u2 - u1) sn^2(lambda t + tau0|m) between the\n"
      "roots u1 <= u2 of the cubic u'^2 = (1 - u^2)(alpha - beta u) - (b - a u)^2, the precession phi and spin psi by\n"
      "Legendre's integral of the third kind. Euler angles Z-X-Z of the frame S (e1, e2, e3 = p_OC_B/|p_OC_B|, fixed "
      "in\n"
      "B) in the inertial frame N: z_N = -g_W/|g_W| (up), x_N the line of nodes at t = 0 (phi(0) = 0). Cases:\n"
      "'nutation' and 'sleeping' (e3 vertical, w_B along it); a motion whose axis passes through a vertical is "
      "refused\n"
      "(ValueError naming state).\n\n"
      "Parameters\n----------\n"
      "body : PivotedBody\n"
      "    Its inertia about O (inertia_O) symmetric about the axis O->C to 1e-12 relative, with C off O.\n"
      "g_W : array_like, shape (3,)\n    Uniform gravity in W [m/s^2], non-zero; a pint quantity is converted.\n"
      "state : PivotedBodyState\n    q_WB (B to W) and w_B [rad/s] (of B in W, expressed in B) at t = 0.\n"
      "scalar_first : bool, default False\n"
      "    The order of the quaternions at() and q_WN return ((x, y, z, w) by default).\n\n"
      "Raises\n------\nValueError\n"
      "    body not symmetric about O->C or with C at O (naming body); g_W zero or non-finite; a motion whose axis\n"
      "    passes through a vertical (naming state).\n\n"
      "See Also\n--------\nPivotedBody, TorqueFreeSolution, CompoundPendulumSolution, ellippi_am\n\n"
      "Examples\n--------\n"
      "A fast top (w3 = 50 rad/s) let go 0.3 rad from the vertical nods between 0.3 and 0.303 rad and precesses\n"
      "near the gyroscopic rate m g l / (I3 w3) = 0.0981 rad/s:\n\n"
      ">>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.5, 0.5, 0.2]), [0.0, 0.0, 0.1])\n"
      ">>> state = rd.PivotedBodyState(rd.rotvec_to_quat([0.3, 0.0, 0.0]), [0.0, 0.0, 50.0])\n"
      ">>> s = rd.LagrangeTopSolution(top, [0.0, 0.0, -9.81], state)\n"
      ">>> s.case, f\"{s.theta_min:.4f} {s.theta_max:.4f} {s.mean_precession_rate:.4f}\"\n"
      "('nutation', '0.3000 0.3030 0.0986')\n\n"
      "Immutable; pickles; == compares the constructor's arguments; unhashable.");
  cls.def(py::init(&make_top), py::arg("body"), py::arg("g_W"), py::arg("state"), py::arg("scalar_first") = false,
           "body: a PivotedBody whose inertia about O (inertia_O) is symmetric about the axis O->C to 1e-12 relative,\n"
           "with C off O (ValueError naming body otherwise); g_W: (3,) uniform gravity in W [m/s^2], non-zero;\n"
           "state: the PivotedBodyState (q_WB, w_B [rad/s] in B) at t = 0; scalar_first: the order of the quaternions\n"
           "at() returns ((x, y, z, w) by default). See the class.")
      .def("at", &top_at, py::arg("t"),
           "State at time t.\n\n"
           "Parameters\n----------\nt : float or array_like, shape (n,)\n    Time [s]; negative allowed.\n\n"
           "Returns\n-------\nq_WB : ndarray, shape (4,) or (n, 4)\n    B to W, in the order chosen at construction.\n"
           "w_B : ndarray, shape (3,) or (n, 3)\n    Angular velocity of B in W, expressed in B [rad/s].\n\n"
           "Examples\n--------\n"
           "The energy about O of the state at t = 2 s is the initial one:\n\n"
           ">>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.5, 0.5, 0.2]), [0.0, 0.0, 0.1])\n"
           ">>> state = rd.PivotedBodyState(rd.rotvec_to_quat([0.3, 0.0, 0.0]), [0.0, 0.0, 50.0])\n"
           ">>> s = rd.LagrangeTopSolution(top, [0.0, 0.0, -9.81], state)\n"
           ">>> later = rd.LagrangeTopSolution(top, [0.0, 0.0, -9.81], rd.PivotedBodyState(*s.at(2.0)))\n"
           ">>> bool(np.isclose(later.energy, s.energy))\nTrue\n")
      .def("angles_at", &top_angles_at, py::arg("t"),
           "Euler angles Z-X-Z of S in N at time t.\n\n"
           "Parameters\n----------\nt : float or array_like, shape (n,)\n    Time [s].\n\n"
           "Returns\n-------\nphi, theta, psi : float or ndarray, shape (n,)\n"
           "    Precession (phi(0) = 0), nutation (the tilt of e3 from the upward vertical), spin [rad]; phi and psi\n"
           "    continuous.\n\n"
           "Examples\n--------\n"
           ">>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.5, 0.5, 0.2]), [0.0, 0.0, 0.1])\n"
           ">>> state = rd.PivotedBodyState(rd.rotvec_to_quat([0.3, 0.0, 0.0]), [0.0, 0.0, 50.0])\n"
           ">>> s = rd.LagrangeTopSolution(top, [0.0, 0.0, -9.81], state)\n"
           ">>> phi, theta, psi = s.angles_at(s.nutation_period)\n"
           ">>> bool(np.isclose(theta, s.theta_min))\nTrue\n")
      .def_property_readonly("case", [](const PyTop& s) { return to_string(s.solution.solution_case()); },
                             "Kind of motion: 'nutation' or 'sleeping' (e3 vertical, w_B along it).")
      .def_property_readonly("theta_min", [](const PyTop& s) { return s.solution.theta_min(); },
                             "Smallest tilt of e3 from the upward vertical, acos(u2) [rad].")
      .def_property_readonly("theta_max", [](const PyTop& s) { return s.solution.theta_max(); },
                             "Largest tilt of e3 from the upward vertical, acos(u1) [rad].")
      .def_property_readonly("nutation_period", [](const PyTop& s) { return s.solution.nutation_period(); },
                             "Period of theta(t), 2 K(m)/lambda [s] (inf when sleeping).")
      .def_property_readonly("mean_precession_rate", [](const PyTop& s) { return py_io::finite_result(s.solution.mean_precession_rate(), "LagrangeTopSolution.mean_precession_rate"); },
                             "phi's change over one nutation period divided by it [rad/s] (0 when sleeping).")
      .def_property_readonly("elliptic_rate", [](const PyTop& s) { return py_io::finite_result(s.solution.elliptic_rate(), "LagrangeTopSolution.elliptic_rate"); },
                             "lambda = sqrt(beta (u3 - u1))/2 [1/s], the rate of the argument of sn.")
      .def_property_readonly("a", [](const PyTop& s) { return py_io::finite_result(s.solution.a(), "LagrangeTopSolution.a"); }, "a = I3 omega3 / I1 [rad/s].")
      .def_property_readonly("b", [](const PyTop& s) { return py_io::finite_result(s.solution.b(), "LagrangeTopSolution.b"); }, "b = H_z / I1 [rad/s].")
      .def_property_readonly("alpha", [](const PyTop& s) { return py_io::finite_result(s.solution.alpha(), "LagrangeTopSolution.alpha"); },
                             "alpha = 2 E'/I1 [1/s^2], E' the energy about O less 1/2 I3 omega3^2.")
      .def_property_readonly("beta", [](const PyTop& s) { return py_io::finite_result(s.solution.beta(), "LagrangeTopSolution.beta"); }, "beta = 2 m |g| l / I1 [1/s^2].")
      .def_property_readonly("roots", [](const PyTop& s) { return py_io::to_array(s.solution.roots()); },
                             "(3,) roots u1 <= u2 <= u3 of the cubic in u = cos(theta) (dimensionless).")
      .def_property_readonly("parameter_m", [](const PyTop& s) { return s.solution.parameter_m(); },
                             "m = (u2 - u1)/(u3 - u1), the parameter (m = k^2, dimensionless) of sn.")
      .def_property_readonly("parameter_mc", [](const PyTop& s) { return s.solution.parameter_mc(); },
                             "1 - m (dimensionless), computed without cancellation.")
      .def_property_readonly("I1", [](const PyTop& s) { return py_io::finite_result(s.solution.I1(), "LagrangeTopSolution.I1"); }, "I1 = I2, the transverse moment about O [kg m^2].")
      .def_property_readonly("I3", [](const PyTop& s) { return py_io::finite_result(s.solution.I3(), "LagrangeTopSolution.I3"); }, "I3, the axial moment [kg m^2].")
      .def_property_readonly("e3_B", [](const PyTop& s) { return py_io::to_array(s.solution.e3_B()); },
                             "(3,) the symmetry axis p_OC_B/|p_OC_B| in B.")
      .def_property_readonly("q_WN", [](const PyTop& s) { return py_io::to_array(s.solution.q_WN(), s.scalar_first); },
                             "(4,) the frame N of the Euler angles, N to W (in the order chosen at construction).")
      .def_property_readonly("energy", [](const PyTop& s) { return py_io::finite_result(s.solution.energy(), "LagrangeTopSolution.energy"); },
                             "Energy about O [J]: 1/2 w_B . I_O w_B - m g_W . (R_WB p_OC_B) (constant).")
      .def_property_readonly("H_z", [](const PyTop& s) { return py_io::finite_result(s.solution.H_z(), "LagrangeTopSolution.H_z"); },
                             "Angular momentum about O along the upward vertical -g_W/|g_W| [kg m^2/s] (constant).")
      .def_property_readonly("H_3", [](const PyTop& s) { return py_io::finite_result(s.solution.H_3(), "LagrangeTopSolution.H_3"); },
                             "Angular momentum about O along e3, I3 omega3 [kg m^2/s] (constant).")
      .def("__repr__", [](const PyTop& s) {
        std::string text = repr_call("LagrangeTopSolution",
                                     {{"body", py::cast(s.body)}, {"g_W", py_io::to_array(s.g_W)}, {"state", py::cast(s.state)}});
        return s.scalar_first ? text.substr(0, text.size() - 1) + ", scalar_first=True)" : text;
      });
  def_value_semantics(cls, &top_args, [](const py::tuple& t) { return make_top(t[0], t[1], t[2], t[3]); }, 4,
                      "LagrangeTopSolution");
}

// ------------------------------------------------------------ rotating frame

struct PyRotatingParticle {
  RotatingFrameFreeParticle solution;
  py::object frame;  // the SceneFrame given (for the repr)
  Eigen::Vector3d p0_F, v0_F;
};

PyRotatingParticle make_rotating_particle(py::handle frame, py::handle p0_F, py::handle v0_F) {
  const SceneFrame& f = py_io::as_instance<SceneFrame>(frame, "frame", "a SceneFrame (SceneFrame.rotating or SceneFrame.earth)");
  const Eigen::Vector3d p = py_io::as_vector3(py_io::in_si(p0_F, "m", "p0_F"), "p0_F");
  const Eigen::Vector3d v = py_io::as_vector3(py_io::in_si(v0_F, "m/s", "v0_F"), "v0_F");
  return {RotatingFrameFreeParticle(f, p, v), py::reinterpret_borrow<py::object>(frame), p, v};
}

// (p_F, v_F): (3,) or (n, 3).
py::tuple rotating_particle_at(const PyRotatingParticle& self, py::handle t) {
  const py_io::Stack ts = py_io::as_stack(t, "t", {});
  Array p = py_io::new_stack(ts.n, ts.stacked, {3}, "p_F"), v = py_io::new_stack(ts.n, ts.stacked, {3}, "v_F");
  double *pp = p.mutable_data(), *pv = v.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < ts.n; ++i) {
      const RotatingFrameParticleState s = self.solution.at(*ts.item(i, 1));
      for (int k = 0; k < 3; ++k) {
        pp[3 * i + k] = s.p_F(k);
        pv[3 * i + k] = s.v_F(k);
      }
    }
  }
  return py::make_tuple(py_io::finite_result(p, "RotatingFrameFreeParticle.at p_F"),
                        py_io::finite_result(v, "RotatingFrameFreeParticle.at v_F"));
}

py::tuple rotating_particle_args(const PyRotatingParticle& s) {
  return py::make_tuple(s.frame, python_list(s.p0_F), python_list(s.v0_F));
}

void bind_rotating_particle(py::module_& m) {
  py::class_<PyRotatingParticle> cls(
      m, "RotatingFrameFreeParticle",
      "Exact motion of a free particle seen from a frame F turning at a constant rate about a fixed axis through its\n"
      "origin: the straight line of the inertial frame turned into F, p_F(t) = R_FW(t) (p0 + v_W t), v_F = R_FW(t)\n"
      "(v_W - w x p_W) (\"Rigid body kinematics and dynamics\" notes §4.11.1); it solves a_F = -w x (w x p_F) -\n"
      "2 w x v_F (centrifugal and Coriolis only) and keeps the Jacobi integral 1/2|v_F|^2 - 1/2|w x p_F|^2.\n\n"
      "Parameters\n----------\n"
      "frame : SceneFrame\n    F, turning at a constant rate (SceneFrame.rotating or SceneFrame.earth).\n"
      "p0_F : array_like, shape (3,)\n    Position relative to F's origin at t = 0, in F [m].\n"
      "v0_F : array_like, shape (3,)\n    Velocity seen from F at t = 0, in F [m/s].\n\n"
      "Raises\n------\nValueError\n    A general moving frame (naming frame), or a non-finite vector (naming it).\n"
      "TypeError\n    frame not a SceneFrame.\n\n"
      "See Also\n--------\nSceneFrame, point_acceleration, FrameTree\n\n"
      "Examples\n--------\n"
      "A particle at rest in F, 1 m from the axis of a frame turning at 1 rad/s, flies off along the inertial\n"
      "tangent; a quarter turn later F sees it at (pi/2, -1, 0):\n\n"
      ">>> s = rd.RotatingFrameFreeParticle(rd.SceneFrame.rotating([0, 0, 1.0], 1.0), [1.0, 0, 0], [0, 0, 0])\n"
      ">>> p_F, v_F = s.at(np.pi / 2)\n"
      ">>> p_F.round(12), s.jacobi_integral\n(array([ 1.57079633, -1.        ,  0.        ]), -0.5)\n\n"
      "Immutable; pickles; == compares the constructor's arguments; unhashable.");
  cls.def(py::init(&make_rotating_particle), py::arg("frame"), py::arg("p0_F"), py::arg("v0_F"),
           "frame: a SceneFrame turning at a constant rate (SceneFrame.rotating or SceneFrame.earth; ValueError "
           "naming\n"
           "frame for a general moving frame); p0_F (3,) [m], v0_F (3,) [m/s]: position and velocity relative to F,\n"
           "in F, at t = 0. See the class.")
      .def("at", &rotating_particle_at, py::arg("t"),
           "State at time t.\n\n"
           "Parameters\n----------\nt : float or array_like, shape (n,)\n    Time [s].\n\n"
           "Returns\n-------\np_F : ndarray, shape (3,) or (n, 3)\n    Position relative to F's origin, in F [m].\n"
           "v_F : ndarray, shape (3,) or (n, 3)\n    Velocity seen from F, in F [m/s].\n\n"
           "Examples\n--------\n"
           "The Jacobi integral 1/2|v_F|^2 - 1/2|w x p_F|^2 stays constant:\n\n"
           ">>> s = rd.RotatingFrameFreeParticle(rd.SceneFrame.rotating([0, 0, 1.0], 1.0), [1.0, 0, 0], [0, 0, 0])\n"
           ">>> p_F, v_F = s.at(np.linspace(0.0, 3.0, 4))\n"
           ">>> J = 0.5 * (v_F**2).sum(axis=1) - 0.5 * (np.cross(s.w_F, p_F) ** 2).sum(axis=1)\n"
           ">>> bool(np.allclose(J, s.jacobi_integral))\nTrue\n")
      .def_property_readonly("w_F", [](const PyRotatingParticle& s) { return py_io::to_array(s.solution.w_F()); },
                             "(3,) F's angular velocity relative to W [rad/s], expressed in F.")
      .def_property_readonly("v_W", [](const PyRotatingParticle& s) { return py_io::to_array(s.solution.v_W()); },
                             "(3,) the constant inertial velocity [m/s], in F's axes at t = 0.")
      .def_property_readonly("jacobi_integral", [](const PyRotatingParticle& s) { return py_io::finite_result(s.solution.jacobi_integral(), "RotatingFrameFreeParticle.jacobi_integral"); },
                             "1/2 |v_F|^2 - 1/2 |w x p_F|^2 [J/kg], constant.")
      .def("__repr__", [](const PyRotatingParticle& s) {
        return repr_call("RotatingFrameFreeParticle",
                         {{"frame", s.frame}, {"p0_F", py_io::to_array(s.p0_F)}, {"v0_F", py_io::to_array(s.v0_F)}});
      });
  def_value_semantics(cls, &rotating_particle_args,
                      [](const py::tuple& t) { return make_rotating_particle(t[0], t[1], t[2]); }, 3,
                      "RotatingFrameFreeParticle");
}

// ------------------------------------------------------------ constant thrust

ConstantThrustSolution make_thrust(py::handle m0, py::handle rate, py::handle u_rel_W, py::handle g_W, py::handle p0_W,
                                   py::handle v0_W) {
  return ConstantThrustSolution(py_io::as_scalar(py_io::in_si(m0, "kg", "m0"), "m0"),
                                py_io::as_scalar(py_io::in_si(rate, "kg/s", "rate"), "rate"),
                                py_io::as_vector3(py_io::in_si(u_rel_W, "m/s", "u_rel_W"), "u_rel_W"),
                                py_io::as_vector3_or_zero(py_io::in_si(g_W, "m/s^2", "g_W"), "g_W"),
                                py_io::as_vector3_or_zero(py_io::in_si(p0_W, "m", "p0_W"), "p0_W"),
                                py_io::as_vector3_or_zero(py_io::in_si(v0_W, "m/s", "v0_W"), "v0_W"));
}

// (p_W, v_W, mass): (3,), (3,), float or (n, 3), (n, 3), (n,).
py::tuple thrust_at(const ConstantThrustSolution& self, py::handle t) {
  const py_io::Stack ts = py_io::as_stack(t, "t", {});
  Array p = py_io::new_stack(ts.n, ts.stacked, {3}, "p_W"), v = py_io::new_stack(ts.n, ts.stacked, {3}, "v_W");
  Array mass = py_io::new_stack(ts.n, true, {}, "mass");
  double *pp = p.mutable_data(), *pv = v.mutable_data(), *pm = mass.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < ts.n; ++i) {
      const ConstantThrustState s = self.at(*ts.item(i, 1));
      for (int k = 0; k < 3; ++k) {
        pp[3 * i + k] = s.p_W(k);
        pv[3 * i + k] = s.v_W(k);
      }
      pm[i] = s.mass;
    }
  }
  p = py_io::finite_result(p, "ConstantThrustSolution.at p_W");
  v = py_io::finite_result(v, "ConstantThrustSolution.at v_W");
  if (!ts.stacked) return py::make_tuple(p, v, pm[0]);
  return py::make_tuple(p, v, mass);
}

std::string thrust_repr(const ConstantThrustSolution& s) {
  return repr_call("ConstantThrustSolution", {{"m0", py::float_(s.m0())},
                                              {"rate", py::float_(s.rate())},
                                              {"u_rel_W", py_io::to_array(s.u_rel_W())},
                                              {"g_W", py_io::to_array(s.g_W())},
                                              {"p0_W", py_io::to_array(s.p0_W())},
                                              {"v0_W", py_io::to_array(s.v0_W())}});
}

py::tuple thrust_args(const ConstantThrustSolution& s) {
  return py::make_tuple(s.m0(), s.rate(), python_list(s.u_rel_W()), python_list(s.g_W()), python_list(s.p0_W()), python_list(s.v0_W()));
}

void bind_thrust(py::module_& m) {
  py::class_<ConstantThrustSolution> cls(
      m, "ConstantThrustSolution",
      "Exact motion of a particle whose mass changes at a constant rate, m(t) = m0 + rate t, with the thrust\n"
      "rate u_rel_W along a fixed direction and uniform gravity (\"Rigid body kinematics and dynamics\" notes, eq. "
      "(4.36):\n"
      "m v' = m g + rate u_rel): v(t) = v0 + g t + u_rel ln(m(t)/m0), p(t) = p0 + v0 t + g t^2/2 + u_rel t h(x)/x "
      "with\n"
      "x = rate t/m0, h(x) = (1 + x) ln(1 + x) - x (series near x = 0). Everything in the inertial frame W.\n\n"
      "Parameters\n----------\n"
      "m0 : float\n    Mass at t = 0 [kg], > 0.\n"
      "rate : float\n    dm/dt [kg/s] (negative: losing mass).\n"
      "u_rel_W : array_like, shape (3,)\n    Velocity of the ejected mass relative to the particle, in W [m/s].\n"
      "g_W : array_like, shape (3,), optional\n    Uniform gravity in W [m/s^2] (None: zero).\n"
      "p0_W : array_like, shape (3,), optional\n    Position at t = 0 in W [m] (None: zero).\n"
      "v0_W : array_like, shape (3,), optional\n    Velocity at t = 0 in W [m/s] (None: zero).\n\n"
      "Each may be a pint quantity (converted to SI).\n\n"
      "Raises\n------\nValueError\n    m0 <= 0 or a non-finite value (naming the argument).\n\n"
      "See Also\n--------\nMassFlow, Thrust\n\n"
      "Examples\n--------\n"
      "Burning half of the mass at 2000 m/s exhaust speed gives Tsiolkovsky's 2000 ln 2 m/s:\n\n"
      ">>> c = rd.ConstantThrustSolution(100.0, -1.0, [0.0, 0.0, -2000.0])\n"
      ">>> p_W, v_W, mass = c.at(50.0)\n"
      ">>> mass, bool(np.isclose(v_W[2], 2000 * np.log(2))), bool(np.isclose(c.delta_v(50.0), v_W[2]))\n"
      "(50.0, True, True)\n\n"
      "Immutable; pickles; == compares the constructor's arguments; unhashable.");
  cls.def(py::init(&make_thrust), py::arg("m0"), py::arg("rate"), py::arg("u_rel_W"), py::arg("g_W") = py::none(),
           py::arg("p0_W") = py::none(), py::arg("v0_W") = py::none(),
           "m0: mass at t = 0 [kg] > 0; rate: dm/dt [kg/s] (negative: losing mass); u_rel_W (3,): velocity of the\n"
           "ejected mass relative to the particle, in W [m/s]; g_W (3,) [m/s^2], p0_W (3,) [m], v0_W (3,) [m/s] "
           "(None:\n"
           "zero). ValueError naming the argument for m0 <= 0 or a non-finite value. See the class.")
      .def("at", &thrust_at, py::arg("t"),
           "State at time t.\n\n"
           "Parameters\n----------\nt : float or array_like, shape (n,)\n    Time [s].\n\n"
           "Returns\n-------\np_W : ndarray, shape (3,) or (n, 3)\n    Position in W [m].\n"
           "v_W : ndarray, shape (3,) or (n, 3)\n    Velocity in W [m/s].\n"
           "mass : float or ndarray, shape (n,)\n    m0 + rate t [kg].\n\n"
           "Raises\n------\nValueError\n    t where the mass m0 + rate t is not positive (burn-out), naming t.\n\n"
           "Examples\n--------\n"
           ">>> rd.ConstantThrustSolution(100.0, -1.0, [0.0, 0.0, -2000.0]).at([0.0, 50.0])[2]\narray([100.,  50.])\n")
      .def(
          "delta_v", [](const ConstantThrustSolution& s, py::handle m1) {
            return py_io::finite_result(s.delta_v(py_io::as_scalar(m1, "m1")), "ConstantThrustSolution.delta_v");
          },
          py::arg("m1"),
          "Tsiolkovsky: the speed the thrust gives while the mass goes from m0 to m1.\n\n"
          "Parameters\n----------\nm1 : float\n    The final mass [kg].\n\n"
          "Returns\n-------\nfloat\n    |u_rel| ln(m0/m1) [m/s].\n\n"
          "Examples\n--------\n"
          ">>> f\"{rd.ConstantThrustSolution(100.0, -1.0, [0.0, 0.0, -2000.0]).delta_v(50.0):.6f}\"\n'1386.294361'\n")
      .def(
          "mass_at", [](const ConstantThrustSolution& s, py::handle t) {
            return py_io::finite_result(s.mass_at(py_io::as_scalar(t, "t")), "ConstantThrustSolution.mass_at");
          },
          py::arg("t"),
          "Mass m0 + rate t [kg] at time t (not checked positive).\n\n"
          "Parameters\n----------\nt : float\n    Time [s].\n\n"
          "Returns\n-------\nfloat\n    m0 + rate t [kg].\n\n"
          "Examples\n--------\n"
          ">>> rd.ConstantThrustSolution(100.0, -1.0, [0.0, 0.0, -2000.0]).mass_at(10.0)\n90.0\n")
      .def_property_readonly("burnout_time", &ConstantThrustSolution::burnout_time,
                             "-m0/rate [s], when the mass reaches zero; inf when rate >= 0.")
      .def_property_readonly("m0", &ConstantThrustSolution::m0, "Mass at t = 0 [kg].")
      .def_property_readonly("rate", &ConstantThrustSolution::rate, "Rate of change of the mass dm/dt [kg/s].")
      .def_property_readonly("u_rel_W", [](const ConstantThrustSolution& s) { return py_io::to_array(s.u_rel_W()); },
                             "(3,) velocity of the ejected mass relative to the particle, in W [m/s]")
      .def_property_readonly("g_W", [](const ConstantThrustSolution& s) { return py_io::to_array(s.g_W()); },
                             "(3,) uniform gravity in W [m/s^2]")
      .def("__repr__", &thrust_repr);
  def_value_semantics(cls, &thrust_args, [](const py::tuple& t) { return make_thrust(t[0], t[1], t[2], t[3], t[4], t[5]); },
                      6, "ConstantThrustSolution");
}

}  // namespace

void bind_exact_dynamics(pybind11::module_& m) {
  bind_pendulum(m);
  bind_top(m);
  bind_rotating_particle(m);
  bind_thrust(m);
}

}  // namespace rigiddyn::bindings
