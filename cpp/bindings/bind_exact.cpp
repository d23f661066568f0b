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
      py_io::as_instance<InertiaCheck>(check, "check", "InertiaCheck.physical or InertiaCheck.allow_unrealizable");
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
      "Carlson's R_F(x, y, z) (DLMF 19.16.1) for finite x, y, z >= 0, at most one zero, of any magnitude;\n"
      "inf with a RuntimeWarning where the result exceeds the double range.");
  m.def(
      "elliprj",
      [](py::handle x, py::handle y, py::handle z, py::handle p) {
        return py_io::finite_result(elliprj(py_io::as_scalar(x, "x"), py_io::as_scalar(y, "y"), py_io::as_scalar(z, "z"),
                                            py_io::as_scalar(p, "p")),
                                    "elliprj");
      },
      py::arg("x"), py::arg("y"), py::arg("z"), py::arg("p"),
      "Carlson's R_J(x, y, z, p) (DLMF 19.16.2) for finite x, y, z >= 0, at most one zero, and p > 0, of any\n"
      "magnitude; inf with a RuntimeWarning where the result exceeds the double range.");
  m.def(
      "ellipk", [](py::handle m, py::handle mc) { return as_parameter(m, mc).K; }, py::arg("m"), py::arg("mc") = py::none(),
      "Complete elliptic integral K(m) = R_F(0, mc, 1) for the parameter m in [0, 1] (as scipy.special.ellipk).\n"
      "mc: the complement 1 - m (default 1 - m); pass it near m = 1, where 1 - m loses digits. inf at mc = 0.");
  m.def(
      "ellippi",
      [](py::handle n, py::handle m, py::handle mc) {
        const double n_value = as_characteristic(n);
        const EllipticParameter p = as_parameter(m, mc);
        return ellippi(n_value, p.m, p.mc);  // finite for n < 1, mc > 0 (ValueError naming mc at mc = 0)
      },
      py::arg("n"), py::arg("m"), py::arg("mc") = py::none(),
      "Complete elliptic integral of the third kind Pi(n|m) = int_0^{pi/2} dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t)),\n"
      "n < 1, m in [0, 1), mc = 1 - m (default 1 - m). A few ulps for n <= 0.9; relative error ~eps/(1 - n) nearer 1.");
  m.def("ellippi_am", &ellippi_am_py, py::arg("u"), py::arg("n"), py::arg("m"), py::arg("mc") = py::none(),
        "Incomplete Pi(am u, n|m) = int_0^u dv / (1 - n sn^2(v|m)) (mpmath.ellippi(n, am(u), m)), for u a scalar\n"
        "or a 1-d array (then an array of the same length), n < 1, mc = 1 - m (default 1 - m); +-inf with a\n"
        "RuntimeWarning where it exceeds the double range (|u| near it).");
  m.def("jacobi_ellipj", &jacobi_ellipj_py, py::arg("u"), py::arg("m"), py::arg("mc") = py::none(),
        "Jacobi elliptic functions (sn, cn, dn)(u|m) for u a scalar (floats) or a 1-d array (three arrays of\n"
        "shape (n,)), m in [0, 1]. mc: the complement 1 - m (default 1 - m); pass it near m = 1 for full\n"
        "accuracy (unlike scipy.special.ellipj, accurate near m = 1 at any u).");

  py::class_<PyTorqueFreeSolution>(m, "TorqueFreeSolution",
                                   "Exact motion of a torque-free rigid body (Euler-Poinsot): angular velocity in Jacobi's elliptic\n"
                                   "functions, attitude by Legendre's third integral (Landau & Lifshitz, Mechanics §37;\n"
                                   "Celledoni, Fassò, Säfström, Zanna 2008; docs/references.md), at any time t [s].")
      .def(py::init(&make_solution), py::arg("inertia"), py::arg("q_WB"), py::arg("w_B"), py::arg("scalar_first") = false,
           py::arg("check") = InertiaCheck::physical,
           "inertia: (3, 3) rotational inertia about the centre of mass, in B [kg m^2], symmetric positive definite\n"
           "and, under check=InertiaCheck.physical (default), with principal moments satisfying the triangle\n"
           "inequality I1 + I2 >= I3 (ValueError naming the moments otherwise; check=\n"
           "InertiaCheck.allow_unrealizable opts in to test problems such as diag(2, 1, 2/3));\n"
           "q_WB: (4,) initial attitude, (x, y, z, w) or (w, x, y, z) if scalar_first; w_B: (3,) initial angular\n"
           "velocity of B in W, expressed in B [rad/s]. Any finite magnitudes (the motion is computed in scaled\n"
           "units); ValueError naming w_B when a rate of the motion exceeds the double range, and naming inertia\n"
           "when its principal moments span so many orders (~1e150 and more) that the parameters of the elliptic\n"
           "functions, up to ~(I_max/I_min)^2 in scaled units, exceed it.")
      .def("state_at", &state_at_py, py::arg("t"),
           "State at time t [s] (scalar, or (n,) array; negative allowed): (q_WB, w_B) of shapes (4,), (3,) or\n"
           "(n, 4), (n, 3); q in the order chosen at construction. ValueError naming t when a phase (rate times t)\n"
           "exceeds the double range.")
      .def_property_readonly("period", [](const PyTorqueFreeSolution& s) { return s.solution.period(); },
                             "Period of w_B(t) [s]; inf if w_B is constant or on the separatrix. A flip takes half.")
      .def_property_readonly("case", [](const PyTorqueFreeSolution& s) { return to_string(s.solution.solution_case()); },
                             "'sphere', 'symmetric', 'A' (about axis 3), 'B' (about axis 1) or 'separatrix'.")
      .def_property_readonly("parameter_m", [](const PyTorqueFreeSolution& s) { return s.solution.parameter_m(); },
                             "Parameter m of the elliptic functions.")
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
