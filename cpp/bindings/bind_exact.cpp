// Python bindings of the exact layer: elliptic functions and the torque-free rigid body.
#include "bindings.hpp"
#include "numpy_io.hpp"
#include "repr.hpp"
#include "rigiddyn/dynamics/rigid_body_dynamics.hpp"  // KineticEnergy
#include "rigiddyn/exact/elliptic.hpp"
#include "rigiddyn/exact/free_body.hpp"
#include "value_type.hpp"

#include <optional>

namespace rigiddyn::bindings {

namespace py = pybind11;
using py_io::Array;

namespace {

// The parameter m in [0, 1] and its complement mc (None: 1 - m; pass it near m = 1, where 1 - m loses
// digits), checked by the core (ValueError naming m or mc).
EllipticParameter as_parameter(py::handle m, py::handle mc) {
  const double m_value = py_io::as_scalar(m, "m");
  const std::optional<double> mc_value = py_io::as_optional_scalar(mc, "mc");
  return elliptic_parameter(m_value, mc_value ? *mc_value : 1.0 - m_value);
}

// The characteristic n < 1 of Π.
double as_characteristic(py::handle n) {
  const double value = py_io::as_scalar(n, "n");
  if (!(value < 1.0)) py_io::throw_value_error("n", "a characteristic n < 1", format_value(value));
  return value;
}

// The solution together with its constructor's arguments as given (for ==, repr and pickle: the
// constructor is deterministic, so equal arguments build a bitwise equal solution) and the
// quaternion order chosen at construction.
struct PyTorqueFreeSolution {
  TorqueFreeSolution solution;
  Eigen::Matrix3d inertia;  // I_B [kg m^2] as given
  Eigen::Quaterniond q_WB;  // as given (the solution normalises its copy)
  Eigen::Vector3d w_B;      // [rad/s]
  bool scalar_first;
  InertiaCheck check;
};

py::object jacobi_ellipj_py(py::handle u, py::handle m, py::handle mc) {
  const py_io::Stack us = py_io::as_stack(u, "u", {});
  const EllipticParameter p = as_parameter(m, mc);
  if (!us.stacked) {
    const JacobiSnCnDn f = jacobi_ellipj(us.array.data()[0], p);
    return py::make_tuple(f.sn, f.cn, f.dn);
  }
  Array sn = py_io::new_stack(us.n, true, {}, "sn"), cn = py_io::new_stack(us.n, true, {}, "cn"),
        dn = py_io::new_stack(us.n, true, {}, "dn");
  double *psn = sn.mutable_data(), *pcn = cn.mutable_data(), *pdn = dn.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < us.n; ++i) {
      const JacobiSnCnDn f = jacobi_ellipj(*us.item(i, 1), p);
      psn[i] = f.sn;
      pcn[i] = f.cn;
      pdn[i] = f.dn;
    }
  }
  return py::make_tuple(sn, cn, dn);
}

// Π(am u, n|m) may exceed the double range only for |u| near it (l Π(n|m) with l ~ u/K): a RuntimeWarning then.
py::object ellippi_am_py(py::handle u, py::handle n, py::handle m, py::handle mc) {
  const py_io::Stack us = py_io::as_stack(u, "u", {});
  const double n_value = as_characteristic(n);
  const EllipticParameter p = as_parameter(m, mc);
  if (!us.stacked) return py::float_(py_io::finite_result(ellippi_am(us.array.data()[0], n_value, p), "ellippi_am"));
  Array out = py_io::new_stack(us.n, true, {});
  double* po = out.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < us.n; ++i) po[i] = ellippi_am(*us.item(i, 1), n_value, p);
  }
  return py_io::finite_result(out, "ellippi_am");
}

PyTorqueFreeSolution make_solution(py::handle inertia, py::handle q_WB, py::handle w_B, py::handle scalar_first,
                                   py::handle check) {
  const bool first = py_io::as_bool(scalar_first, "scalar_first");
  const Eigen::Matrix3d I_B = py_io::as_matrix3(inertia, "inertia");
  const Eigen::Quaterniond q = py_io::as_quaternion(q_WB, "q_WB", first);
  const Eigen::Vector3d w = py_io::as_vector3(w_B, "w_B");
  const InertiaCheck c =
      py_io::as_enum<InertiaCheck>(check, "check", "InertiaCheck.physical or InertiaCheck.allow_unrealizable");
  return {TorqueFreeSolution(I_B, q, w, c), I_B, q, w, first, c};
}

bool same_arguments(const PyTorqueFreeSolution& a, const PyTorqueFreeSolution& b) {
  return same(a.inertia, b.inertia) && same(a.q_WB.coeffs(), b.q_WB.coeffs()) && same(a.w_B, b.w_B) &&
         a.scalar_first == b.scalar_first && a.check == b.check;
}

std::string solution_repr(const PyTorqueFreeSolution& s) {
  std::string text = repr_call("TorqueFreeSolution", {{"inertia", py_io::to_array(s.inertia)},
                                                      {"q_WB", py_io::to_array(s.q_WB, s.scalar_first)},
                                                      {"w_B", py_io::to_array(s.w_B)},
                                                      {"scalar_first", py::bool_(s.scalar_first)}});
  if (s.check == InertiaCheck::physical) return text;
  return text.substr(0, text.size() - 1) + ", check=InertiaCheck.allow_unrealizable)";
}

// Pickled state: (inertia, q_WB (in the order chosen), w_B, scalar_first, allow_unrealizable).
py::tuple solution_state(const PyTorqueFreeSolution& s) {
  return py::make_tuple(py_io::to_array(s.inertia), py_io::to_array(s.q_WB, s.scalar_first), py_io::to_array(s.w_B),
                        s.scalar_first, s.check == InertiaCheck::allow_unrealizable);
}
PyTorqueFreeSolution solution_from_state(const py::tuple& state) {
  const py::tuple s = pickled_state(state, 5, "TorqueFreeSolution");
  const InertiaCheck check = s[4].cast<bool>() ? InertiaCheck::allow_unrealizable : InertiaCheck::physical;
  return make_solution(s[0], s[1], s[2], s[3], py::cast(check));
}

py::tuple state_at_py(const PyTorqueFreeSolution& self, py::handle t) {
  const py_io::Stack ts = py_io::as_stack(t, "t", {});
  Array q = py_io::new_stack(ts.n, ts.stacked, {4}, "q_WB");
  Array w = py_io::new_stack(ts.n, ts.stacked, {3}, "w_B");
  double *pq = q.mutable_data(), *pw = w.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < ts.n; ++i) {
      const TorqueFreeState s = self.solution.state_at(*ts.item(i, 1));
      py_io::write_quaternion(s.q_WB, pq + 4 * i, self.scalar_first);
      for (int k = 0; k < 3; ++k) pw[3 * i + k] = s.w_B(k);
    }
  }
  return py::make_tuple(q, w);
}

}  // namespace

void bind_exact(pybind11::module_& m) {
  m.def(
      "elliprf",
      [](py::handle x, py::handle y, py::handle z) {
        return py_io::finite_result(
            elliprf(py_io::as_scalar(x, "x"), py_io::as_scalar(y, "y"), py_io::as_scalar(z, "z")), "elliprf");
      },
      py::arg("x"), py::arg("y"), py::arg("z"),
      "Carlson's symmetric elliptic integral of the first kind R_F(x, y, z).\n\n"
      "R_F(x, y, z) = 1/2 int_0^inf dt / sqrt((t + x)(t + y)(t + z)) (DLMF 19.16.1), symmetric in its arguments,\n"
      "to a few ulps for finite arguments of any magnitude (1e-300 to 1e300 together). K(m) = R_F(0, 1 - m, 1).\n\n"
      "Parameters\n----------\n"
      "x, y, z : float\n    Finite, >= 0, at most one of them zero.\n\n"
      "Returns\n-------\nfloat\n    R_F(x, y, z) (it never exceeds the double range).\n\n"
      "Raises\n------\nValueError\n"
      "    An argument negative or non-finite, or two of them zero (the message names it).\n\n"
      "See Also\n--------\nelliprj, ellipk\nscipy.special.elliprf : The same function (same argument order).\n\n"
      "Examples\n--------\n"
      "R_F(0, 1, 1) = K(0) = pi/2, and R_F(x, x, x) = 1/sqrt(x):\n\n"
      ">>> bool(np.isclose(rd.elliprf(0.0, 1.0, 1.0), np.pi / 2))\nTrue\n"
      ">>> bool(np.isclose(rd.elliprf(2.0, 2.0, 2.0), 1 / np.sqrt(2.0)))\nTrue\n");
  m.def(
      "elliprj",
      [](py::handle x, py::handle y, py::handle z, py::handle p) {
        return py_io::finite_result(elliprj(py_io::as_scalar(x, "x"), py_io::as_scalar(y, "y"), py_io::as_scalar(z, "z"),
                                            py_io::as_scalar(p, "p")),
                                    "elliprj");
      },
      py::arg("x"), py::arg("y"), py::arg("z"), py::arg("p"),
      "Carlson's symmetric elliptic integral of the third kind R_J(x, y, z, p).\n\n"
      "R_J(x, y, z, p) = 3/2 int_0^inf dt / ((t + p) sqrt((t + x)(t + y)(t + z))) (DLMF 19.16.2), symmetric in\n"
      "x, y, z, to a few ulps for finite arguments of any magnitude; Pi(n|m) = R_F(0, 1 - m, 1) +\n"
      "(n/3) R_J(0, 1 - m, 1, 1 - n).\n\n"
      "Parameters\n----------\n"
      "x, y, z : float\n    Finite, >= 0, at most one of them zero.\n"
      "p : float\n    Finite, > 0.\n\n"
      "Returns\n-------\nfloat\n"
      "    R_J(x, y, z, p); inf with a RuntimeWarning where it exceeds the double range (R_J ~\n"
      "    1/sqrt(x y z p) for tiny arguments), 0 or a subnormal below it.\n\n"
      "Raises\n------\nValueError\n"
      "    x, y or z negative, two of them zero, p <= 0, or a non-finite argument (the message names\n"
      "    it).\n\n"
      "See Also\n--------\nelliprf, ellippi\nscipy.special.elliprj : The same function (same argument order).\n\n"
      "Examples\n--------\n"
      "R_J(x, x, x, x) = x^(-3/2):\n\n"
      ">>> rd.elliprj(4.0, 4.0, 4.0, 4.0)\n0.125\n");
  m.def(
      "ellipk", [](py::handle m, py::handle mc) { return as_parameter(m, mc).K; }, py::arg("m"), py::arg("mc") = py::none(),
      "Complete elliptic integral of the first kind K(m).\n\n"
      "K(m) = int_0^{pi/2} dt / sqrt(1 - m sin^2 t) = R_F(0, mc, 1), the quarter period of the Jacobi elliptic\n"
      "functions. The argument is the parameter m = k^2 (k the modulus), as scipy.special.ellipk takes it. K is\n"
      "computed from the complement mc, so that K ~ ln(16/mc)/2 keeps full relative precision as m -> 1.\n\n"
      "Parameters\n----------\n"
      "m : float\n    Parameter m = k^2, 0 <= m <= 1.\n"
      "mc : float, optional\n    Its complement 1 - m, in [0, 1] and equal to 1 - m to within 4 eps (default: "
      "computed as\n"
      "    1 - m). Pass it near m = 1, where 1 - m loses digits.\n\n"
      "Returns\n-------\nfloat\n    K(m); inf at mc = 0.\n\n"
      "Raises\n------\nValueError\n    m or mc outside [0, 1], non-finite, or mc not 1 - m (the message names it).\n\n"
      "See Also\n--------\nelliprf, ellippi, jacobi_ellipj\n"
      "scipy.special.ellipk : The same function of m; scipy.special.ellipkm1 takes mc.\n\n"
      "Examples\n--------\n"
      "K(0) = pi/2 and K(1/2) = Gamma(1/4)^2 / (4 sqrt(pi)):\n\n"
      ">>> rd.ellipk(0.0) == np.pi / 2\nTrue\n"
      ">>> from math import gamma\n"
      ">>> bool(np.isclose(rd.ellipk(0.5), gamma(0.25) ** 2 / (4 * np.sqrt(np.pi))))\nTrue\n\n"
      "Near m = 1, given mc, K follows ln(16/mc)/2 (m = 1 - 1e-20 rounds to 1.0):\n\n"
      ">>> f\"{rd.ellipk(1.0, mc=1e-20):.9f} {np.log(16 / 1e-20) / 2:.9f}\"\n'24.412145291 24.412145291'\n");
  m.def(
      "ellippi",
      [](py::handle n, py::handle m, py::handle mc) {
        const double n_value = as_characteristic(n);
        const EllipticParameter p = as_parameter(m, mc);
        return ellippi(n_value, p.m, p.mc);  // finite for n < 1, mc > 0 (ValueError naming mc at mc = 0)
      },
      py::arg("n"), py::arg("m"), py::arg("mc") = py::none(),
      "Complete elliptic integral of the third kind Pi(n|m).\n\n"
      "Pi(n|m) = int_0^{pi/2} dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t)) for the characteristic n < 1 and the\n"
      "parameter m = k^2 (as scipy.special.ellipk takes it). A few ulps for n <= 0.9; relative error\n"
      "~eps/(1 - n) nearer 1.\n\n"
      "Parameters\n----------\n"
      "n : float\n    Characteristic, n < 1.\n"
      "m : float\n    Parameter m = k^2, 0 <= m < 1.\n"
      "mc : float, optional\n    Its complement 1 - m, > 0 and equal to 1 - m to within 4 eps (default: computed as 1 "
      "- m).\n\n"
      "Returns\n-------\nfloat\n    Pi(n|m), finite.\n\n"
      "Raises\n------\nValueError\n"
      "    n >= 1 (naming n); m or mc outside [0, 1] or mc not 1 - m; mc = 0, where Pi(n|1) diverges\n"
      "    (naming mc).\n\n"
      "See Also\n--------\nellippi_am, ellipk, elliprj\n"
      "scipy.special.elliprj : SciPy has no Pi(n|m); it is elliprf(0, 1 - m, 1) + n/3 elliprj(0, 1 - m, 1, 1 - n).\n\n"
      "Examples\n--------\n"
      "Pi(0|m) = K(m), and Pi(n|0) = pi / (2 sqrt(1 - n)):\n\n"
      ">>> bool(np.isclose(rd.ellippi(0.0, 0.5), rd.ellipk(0.5)))\nTrue\n"
      ">>> bool(np.isclose(rd.ellippi(0.5, 0.0), np.pi / (2 * np.sqrt(0.5))))\nTrue\n");
  m.def("ellippi_am", &ellippi_am_py, py::arg("u"), py::arg("n"), py::arg("m"), py::arg("mc") = py::none(),
        "Incomplete elliptic integral of the third kind at the amplitude am u, Pi(am u, n|m).\n\n"
        "Pi(am u, n|m) = int_0^u dv / (1 - n sn^2(v|m)) for any finite u (mpmath.ellippi(n, am(u), m)), the\n"
        "parameter m = k^2; Pi(am(u + 2K), n|m) = Pi(am u, n|m) + 2 Pi(n|m), K = K(m).\n\n"
        "Parameters\n----------\n"
        "u : float or array_like, shape (n,)\n    Argument of the Jacobi functions, finite.\n"
        "n : float\n    Characteristic, n < 1.\n"
        "m : float\n    Parameter m = k^2, 0 <= m <= 1.\n"
        "mc : float, optional\n    Its complement 1 - m, equal to 1 - m to within 4 eps (default: computed as 1 - "
        "m).\n\n"
        "Returns\n-------\nfloat or ndarray, shape (n,)\n"
        "    Pi(am u, n|m), of u's shape; +-inf with a RuntimeWarning where it exceeds the double range\n"
        "    (|u| near it).\n\n"
        "Raises\n------\nValueError\n"
        "    n >= 1, m or mc outside [0, 1] or mc not 1 - m, u non-finite or of another shape (the\n"
        "    message names it).\n\n"
        "See Also\n--------\nellippi, jacobi_ellipj\n\n"
        "Notes\n-----\nSciPy has no incomplete integral of the third kind: for |am u| <= pi/2 it is\n"
        "s R_F(c^2, d^2, 1) + (n/3) s^3 R_J(c^2, d^2, 1, 1 - n s^2) with (s, c, d) = (sn, cn, dn)(u|m)\n"
        "(scipy.special.ellipj, elliprf, elliprj).\n\n"
        "Examples\n--------\n"
        "At u = K(m) it is the complete integral; for m = 0 (am u = u), atan(sqrt(1 - n) tan u) / sqrt(1 - n):\n\n"
        ">>> K = rd.ellipk(0.5)\n"
        ">>> bool(np.isclose(rd.ellippi_am(K, 0.3, 0.5), rd.ellippi(0.3, 0.5)))\nTrue\n"
        ">>> bool(np.isclose(rd.ellippi_am(0.7, 0.4, 0.0), np.arctan(np.sqrt(0.6) * np.tan(0.7)) / np.sqrt(0.6)))\n"
        "True\n"
        ">>> rd.ellippi_am([0.0, 2 * K], 0.3, 0.5) / rd.ellippi(0.3, 0.5)\narray([0., 2.])\n");
  m.def("jacobi_ellipj", &jacobi_ellipj_py, py::arg("u"), py::arg("m"), py::arg("mc") = py::none(),
        "Jacobi elliptic functions sn(u|m), cn(u|m), dn(u|m).\n\n"
        "sn u = sin(am u), cn u = cos(am u), dn u = sqrt(1 - m sn^2 u), where am is the inverse of\n"
        "u = int_0^am dt / sqrt(1 - m sin^2 t), for the parameter m = k^2 (as scipy.special.ellipj takes it).\n"
        "Absolute error a few ulps for |u| up to K(m), growing as eps |u| beyond; m = 1 gives (tanh u, sech u,\n"
        "sech u). Unlike scipy.special.ellipj, accurate near m = 1 at any u when mc is given.\n\n"
        "Parameters\n----------\n"
        "u : float or array_like, shape (n,)\n    Argument, finite.\n"
        "m : float\n    Parameter m = k^2, 0 <= m <= 1.\n"
        "mc : float, optional\n    Its complement 1 - m, equal to 1 - m to within 4 eps (default: computed as 1 - m); "
        "pass it\n"
        "    near m = 1 for full accuracy.\n\n"
        "Returns\n-------\nsn, cn, dn : float or ndarray, shape (n,)\n"
        "    Three floats for a scalar u, three arrays of u's length for an array.\n\n"
        "Raises\n------\nValueError\n"
        "    u non-finite or not a scalar or 1-d array, m or mc outside [0, 1], or mc not 1 - m (the\n"
        "    message names it).\n\n"
        "See Also\n--------\nellipk, ellippi_am\n"
        "scipy.special.ellipj : The same functions of (u, m), with am u as a fourth result.\n\n"
        "Examples\n--------\n"
        "sn K = 1 and cn K = 0 at the quarter period K(m); sn^2 + cn^2 = 1 and dn^2 + m sn^2 = 1:\n\n"
        ">>> sn, cn, dn = rd.jacobi_ellipj(rd.ellipk(0.5), 0.5)\n"
        ">>> print(f\"{sn:.12f} {abs(cn):.12f} {dn:.12f}\")\n1.000000000000 0.000000000000 0.707106781187\n"
        ">>> sn, cn, dn = rd.jacobi_ellipj(np.linspace(0.0, 5.0, 6), 0.7)\n"
        ">>> bool(np.allclose(sn**2 + cn**2, 1.0) and np.allclose(dn**2 + 0.7 * sn**2, 1.0))\nTrue\n");

  py::class_<PyTorqueFreeSolution> cls(
      m, "TorqueFreeSolution",
      "Exact motion of a torque-free rigid body (Euler-Poinsot) at any time t [s].\n\n"
      "The angular velocity w_B(t) in Jacobi's elliptic functions, the attitude q_WB(t) by Legendre's third\n"
      "integral (Landau & Lifshitz, Mechanics §37; Celledoni, Fassò, Säfström, Zanna 2008; docs/references.md):\n"
      "the solution of I_B dw_B/dt = -w_B x I_B w_B, dq_WB/dt = 1/2 q_WB ⊗ [w_B; 0], which keeps the angular\n"
      "momentum L_W = R_WB I_B w_B and the kinetic energy constant. Any finite magnitudes (the motion is computed\n"
      "in scaled units).\n\n"
      "Parameters\n----------\n"
      "inertia : array_like, shape (3, 3)\n"
      "    Rotational inertia I_B about the centre of mass, in B [kg m^2], symmetric positive definite and, under\n"
      "    check=InertiaCheck.physical, with principal moments satisfying the triangle inequality I1 + I2 >= I3.\n"
      "q_WB : array_like, shape (4,)\n"
      "    Initial attitude, B to W, (x, y, z, w) ((w, x, y, z) if `scalar_first`); normalised.\n"
      "w_B : array_like, shape (3,)\n    Initial angular velocity of B in W, expressed in B [rad/s].\n"
      "scalar_first : bool, default False\n    Read q_WB, and return the quaternions of state_at, scalar first.\n"
      "check : InertiaCheck, default InertiaCheck.physical\n"
      "    InertiaCheck.allow_unrealizable opts in to test problems such as diag(2, 1, 2/3).\n\n"
      "Raises\n------\nValueError\n"
      "    An inertia not symmetric positive definite or, under InertiaCheck.physical, breaking the triangle\n"
      "    inequality (naming the moments); w_B when a rate of the motion exceeds the double range; inertia when\n"
      "    its principal moments span so many orders (~1e150 and more) that the parameters of the elliptic\n"
      "    functions, up to ~(I_max/I_min)^2 in scaled units, exceed it; a non-finite or badly shaped argument.\n\n"
      "See Also\n--------\njacobi_ellipj, ellippi_am, LagrangeTopSolution, simulate\n\n"
      "Examples\n--------\n"
      "w_B returns after one period; L_W = R_WB I_B w_B stays constant:\n\n"
      ">>> I_B = np.diag([1.0, 2.0, 3.0])\n"
      ">>> s = rd.TorqueFreeSolution(I_B, [0, 0, 0, 1], [0.1, 1.0, 0.1])\n"
      ">>> s.case, round(s.period, 6)\n('A', 22.996263)\n"
      ">>> q_WB, w_B = s.state_at(s.period)\n"
      ">>> bool(np.allclose(w_B, [0.1, 1.0, 0.1]))\nTrue\n"
      ">>> q_WB, w_B = s.state_at(3.7)\n"
      ">>> bool(np.allclose(rd.quat_rotate(q_WB, I_B @ w_B), s.angular_momentum_W))\nTrue\n\n"
      "Immutable; pickles; == compares the constructor's arguments.");
  cls.def(py::init(&make_solution), py::arg("inertia"), py::arg("q_WB"), py::arg("w_B"), py::arg("scalar_first") = false,
           py::arg("check") = InertiaCheck::physical,
           "The exact motion from I_B (3, 3) [kg m^2] about the centre of mass in B, q_WB (4,) and w_B (3,) [rad/s]\n"
           "in B at t = 0 (see the class).")
      .def("state_at", &state_at_py, py::arg("t"),
           "State at time t.\n\n"
           "Parameters\n----------\nt : float or array_like, shape (n,)\n    Time [s]; negative allowed.\n\n"
           "Returns\n-------\nq_WB : ndarray, shape (4,) or (n, 4)\n"
           "    Attitude, B to W, in the order chosen at construction.\n"
           "w_B : ndarray, shape (3,) or (n, 3)\n    Angular velocity of B in W, expressed in B [rad/s].\n\n"
           "Raises\n------\nValueError\n    t when a phase (rate times t) exceeds the double range, or t non-finite.\n"
           "\n"
           "Examples\n--------\n"
           ">>> s = rd.TorqueFreeSolution(np.diag([1.0, 2.0, 3.0]), [0, 0, 0, 1], [0.1, 1.0, 0.1])\n"
           ">>> [a.shape for a in s.state_at([0.0, 1.0, 2.0])]\n[(3, 4), (3, 3)]\n")
      .def_property_readonly("period", [](const PyTorqueFreeSolution& s) { return s.solution.period(); },
                             "Period of w_B(t) [s] (w_B in B); inf if w_B is constant or on the separatrix. A flip "
                             "takes half.")
      .def_property_readonly("case", [](const PyTorqueFreeSolution& s) { return to_string(s.solution.solution_case()); },
                             "'sphere', 'symmetric', 'A' (about axis 3), 'B' (about axis 1) or 'separatrix'.")
      .def_property_readonly("parameter_m", [](const PyTorqueFreeSolution& s) { return s.solution.parameter_m(); },
                             "Parameter m = k^2 of the elliptic functions of w_B(t) (dimensionless, in [0, 1]).")
      .def_property_readonly("parameter_mc", [](const PyTorqueFreeSolution& s) { return s.solution.parameter_mc(); },
                             "Complement 1 - m, computed without cancellation.")
      .def_property_readonly("principal_moments",
                             [](const PyTorqueFreeSolution& s) { return py_io::to_array(s.solution.principal_moments()); },
                             "(3,) principal moments I1 <= I2 <= I3 [kg m^2] about the centre of mass.")
      .def_property_readonly("R_BP", [](const PyTorqueFreeSolution& s) { return py_io::to_array(s.solution.R_BP()); },
                             "(3, 3) rotation from the sorted principal frame P to B (columns: principal axes in B).")
      .def_property_readonly(
          "angular_momentum_W",
          [](const PyTorqueFreeSolution& s) {
            return py_io::finite_result(s.solution.angular_momentum_W(), "TorqueFreeSolution.angular_momentum_W");
          },
          "(3,) constant angular momentum about the centre of mass, expressed in W, L_W [kg m^2/s]; inf with a\n"
          "RuntimeWarning beyond the double range.")
      .def_property_readonly(
          "kinetic_energy",
          [](const PyTorqueFreeSolution& s) {
            // the centre of mass does not enter the torque-free rotation: its kinetic energy is not part of it
            return KineticEnergy{0.0, py_io::finite_result(s.solution.kinetic_energy(), "TorqueFreeSolution.kinetic_energy")};
          },
          "Constant KineticEnergy of the rotation [J]: rotational 1/2 w_B . I_B w_B, translational 0 (the\n"
          "centre of mass is not part of this solution); inf with a RuntimeWarning beyond the double range.")
      .def(
          "__eq__",
          [](const PyTorqueFreeSolution& a, py::handle b) { return equal_or_not_implemented(a, b, &same_arguments); },
          py::is_operator(), "Built from exactly equal arguments (then every state is bitwise equal).")
      .def("__repr__", &solution_repr)
      .def(py::pickle(&solution_state, &solution_from_state));
}

}  // namespace rigiddyn::bindings
