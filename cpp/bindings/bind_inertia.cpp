// Python bindings of the inertia layer: SpatialInertia (mass, centre of mass, inertia about the
// centre of mass), validity report and repair, principal axes (single or (n,3,3) stacks, GIL
// released), primitives (mass= or density=), point masses, triangle meshes and density quadrature.
// Same names as C++ (rigiddyn/inertia/*.hpp, where the formulas are cited).
#include <pybind11/functional.h>
#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "numpy_io.hpp"
#include "repr.hpp"
#include "value_type.hpp"
#include "rigiddyn/inertia/density.hpp"
#include "rigiddyn/inertia/mesh.hpp"
#include "rigiddyn/inertia/point_masses.hpp"
#include "rigiddyn/inertia/primitives.hpp"
#include "rigiddyn/inertia/principal_axes.hpp"
#include "rigiddyn/inertia/spatial_inertia.hpp"
#include "rigiddyn/inertia/symmetry.hpp"
#include "rigiddyn/inertia/validity.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using namespace pybind11::literals;
using py_io::Array;

namespace {

using PointRows = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

// Exactly one of mass= [kg] and density=, each a number > 0 (ValueError naming both otherwise).
MassOrDensity mass_or_density(py::handle mass, py::handle density) {
  const std::optional<double> m = py_io::as_optional_scalar(mass, "mass");
  const std::optional<double> rho = py_io::as_optional_scalar(density, "density");
  if (m.has_value() == rho.has_value()) {
    throw py::value_error(std::string("mass, density: expected exactly one of mass= or density=, got ") +
                          (m ? "both" : "neither"));
  }
  if (m) return Mass{*m};
  return Density{*rho};
}

// An (n, 3) array of points (n >= 1).
PointRows as_points(py::handle obj, const std::string& name) {
  const py_io::Stack s = py_io::as_stack(obj, name, {3});
  if (!s.stacked) throw py::value_error(name + ": expected shape (n, 3), got (3,)");
  return Eigen::Map<const PointRows>(s.array.data(), s.n, 3);
}

// An (f, 3) integer array of vertex indices (TypeError unless integer dtype).
MeshFaces as_faces(py::handle obj) {
  const py_io::IndexArray a = py_io::as_index_array(obj, "faces");
  if (a.ndim() != 2 || a.shape(1) != 3) {
    throw py::value_error("faces: expected shape (f, 3), got " + std::string(py::str(a.attr("shape"))));
  }
  return Eigen::Map<const MeshFaces>(a.data(), a.shape(0), 3);
}

using py_io::read_only;

// MeshWeldWarning, the category of the warning saying what welding changed in a mesh (set by
// bind_mesh_and_density; the module keeps the class alive).
py::handle mesh_weld_warning;

// Warns `category` at the first Python frame outside the rigiddyn package (the user's call, also
// through rigiddyn's Python wrappers; what warnings.warn(skip_file_prefixes=...) does in Python 3.12).
void warn_at_caller(py::handle category, const std::string& message) {
  py::object frame = py::module_::import("sys").attr("_getframe")(0);
  int stacklevel = 1;
  for (; !frame.is_none(); frame = frame.attr("f_back"), ++stacklevel) {
    const std::string module = py::str(frame.attr("f_globals").attr("get")("__name__", ""));
    if (module != "rigiddyn" && module.rfind("rigiddyn.", 0) != 0) break;
  }
  if (PyErr_WarnEx(category.ptr(), message.c_str(), stacklevel) < 0) throw py::error_already_set();
}

// A MeshWeldWarning saying what the weld changed, when it changed anything.
void warn_if_welded(const char* function, const WeldReport& report) {
  if (report.welded_vertices == 0 && report.dropped_faces == 0) return;
  warn_at_caller(mesh_weld_warning, std::string(function) + ": welded " + std::to_string(report.welded_vertices) +
                                        " vertices lying within weld_tolerance " + format_value(report.tolerance) +
                                        " m of another (duplicates, as in STL files) and dropped " +
                                        std::to_string(report.dropped_faces) +
                                        " faces left degenerate; weld_tolerance=0 turns welding off");
}

// The weld_tolerance argument: None (default_weld_tolerance, relative to the mesh) or a distance [m].
std::optional<double> as_weld_tolerance(py::handle obj) { return py_io::as_optional_scalar(obj, "weld_tolerance"); }

using MeshBuild = SpatialInertia (*)(const Eigen::Ref<const MeshVertices>&, const Eigen::Ref<const MeshFaces>&,
                                     MassOrDensity, std::optional<double>, WeldReport*);

// A body from a triangle mesh (solid_mesh or mesh_shell): vertices (n, 3) [m], faces (f, 3), exactly
// one of mass= [kg] / density=, weld_tolerance; the mesh sums run without the GIL; warns what the weld changed.
SpatialInertia mesh_body(MeshBuild build, const char* function, py::handle vertices, py::handle faces,
                         py::handle mass, py::handle density, py::handle weld_tolerance) {
  const PointRows v = as_points(vertices, "vertices");
  const MeshFaces f = as_faces(faces);
  const MassOrDensity md = mass_or_density(mass, density);
  const std::optional<double> tolerance = as_weld_tolerance(weld_tolerance);
  WeldReport report;
  const SpatialInertia body = [&] {
    py::gil_scoped_release release;
    return build(v, f, md, tolerance, &report);
  }();
  warn_if_welded(function, report);
  return body;
}

// Indices as a read-only int64 numpy array of the given shape.
template <typename Indices>
py::array_t<std::int64_t> index_array(const Indices& values, std::vector<py::ssize_t> shape) {
  py::array_t<std::int64_t> out(shape);
  std::int64_t* data = out.mutable_data();
  for (py::ssize_t k = 0; k < out.size(); ++k) data[k] = static_cast<std::int64_t>(values.data()[k]);
  py_io::set_read_only(out);
  return out;
}

InertiaCheck check_arg(py::handle check) {
  return py_io::as_enum<InertiaCheck>(check, "check", "InertiaCheck.physical or InertiaCheck.allow_unrealizable");
}
const SpatialInertia& as_inertia(py::handle obj, const std::string& name) {
  return py_io::as_instance<SpatialInertia>(obj, name, "a SpatialInertia");
}
// A tolerance: a finite number >= 0.
double as_tolerance(py::handle obj, const std::string& name) {
  const double tolerance = py_io::as_scalar(obj, name);
  if (tolerance < 0.0) py_io::throw_value_error(name, "a number >= 0", format_value(tolerance));
  return tolerance;
}
// A quadrature order in [1, 32] (the rule doubles it: 64 points per axis at most).
int as_order(py::handle obj) { return static_cast<int>(py_io::as_int(obj, "order", 1, 32)); }

// A result of mass properties: a RuntimeWarning naming the quantity when a member overflowed.
SpatialInertia checked(const SpatialInertia& I, const char* quantity) {
  py_io::warn_unless_finite(std::isfinite(I.mass()) && I.com().allFinite() && I.inertia_com().allFinite(), quantity,
                            "mass " + format_value(I.mass()) + ", com " + format_value(I.com().transpose()));
  return I;
}

py::function as_density(py::handle rho) {
  return py_io::as_callable(rho, "rho", "a callable points (n, 3) -> densities (n,)");
}

// rho called once on all points (n, 3) of a rule; must return n values.
Eigen::VectorXd evaluate_vectorized(const py::function& rho, const QuadratureRule& rule) {
  const Array values = py_io::as_array(rho(py_io::to_array(rule.points)), "rho(points)");
  if (values.size() != rule.points.rows()) {
    throw py::value_error("rho(points): expected " + std::to_string(rule.points.rows()) +
                          " values (one per row of points), got " + std::to_string(values.size()));
  }
  return Eigen::Map<const Eigen::VectorXd>(values.data(), values.size());
}

// Principal axes as Python sees them: one inertia's (3,) moments and (3,3) axes, or the (n,3) and
// (n,3,3) arrays of a stack, read-only. Unpacks as (moments, axes).
struct PyPrincipalAxes {
  Array moments;
  Array axes;
};

// `value` itself, made read-only (a PrincipalAxes is a value: its arrays are not written to).
Array frozen(Array value) {
  py_io::set_read_only(value);
  return value;
}

// From user arrays: copies, checked to be (3,)/(3,3) or (n,3)/(n,3,3) with the same n.
PyPrincipalAxes make_principal_axes(py::handle moments_arg, py::handle axes_arg) {
  const py_io::Stack moments = py_io::as_stack(moments_arg, "moments", {3});
  const py_io::Stack axes = py_io::as_stack(axes_arg, "axes", {3, 3});
  if (moments.stacked != axes.stacked || moments.n != axes.n) {
    const std::string shape = moments.stacked ? "(" + std::to_string(moments.n) + ", 3, 3)" : "(3, 3)";
    throw py::value_error("axes: expected shape " + shape + " (as moments), got " +
                          std::string(py::str(axes.array.attr("shape"))));
  }
  return {frozen(moments.array.attr("copy")()), frozen(axes.array.attr("copy")())};
}

PyPrincipalAxes to_python(const PrincipalAxes& p) { return {read_only(p.moments), read_only(p.axes)}; }

py::tuple as_tuple(const PyPrincipalAxes& p) { return py::make_tuple(p.moments, p.axes); }

// An InertiaReport's fields as a tuple (its pickled state), in the order of the struct.
py::tuple report_state(const InertiaReport& r) {
  return py::make_tuple(r.mass, r.mass_positive, r.finite, r.asymmetry, r.asymmetry_tolerance, r.symmetric,
                        read_only(r.principal_moments), read_only(r.triangle_margins), r.condition_number,
                        r.tolerance, r.positive_semidefinite, r.triangle_inequality);
}
InertiaReport report_from_state(const py::tuple& state) {
  const py::tuple s = pickled_state(state, 12, "InertiaReport");
  InertiaReport r;
  r.mass = s[0].cast<double>();
  r.mass_positive = s[1].cast<bool>();
  r.finite = s[2].cast<bool>();
  r.asymmetry = s[3].cast<double>();
  r.asymmetry_tolerance = s[4].cast<double>();
  r.symmetric = s[5].cast<bool>();
  r.principal_moments = py_io::as_vector3(s[6], "principal_moments");
  r.triangle_margins = py_io::as_vector3(s[7], "triangle_margins");
  r.condition_number = s[8].cast<double>();
  r.tolerance = s[9].cast<double>();
  r.positive_semidefinite = s[10].cast<bool>();
  r.triangle_inequality = s[11].cast<bool>();
  return r;
}

void bind_principal_axes(py::module_& m) {
  py::class_<PyPrincipalAxes>(
      m, "PrincipalAxes",
      "Principal moments and axes of a rotational inertia (Craig, \"Principal Axes\").\n"
      "\n"
      "In the frame the inertia is expressed in: moments ascending [kg m^2], axes as columns (column k is\n"
      "the unit axis of moments[k]; right-handed, det +1), so that I = axes @ diag(moments) @ axes.T. For a\n"
      "stack of n inertias, arrays (n, 3) and (n, 3, 3). Unpacks as ``moments, axes = principal_axes(I)``.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "moments : array_like, shape (3,) or (n, 3)\n"
      "    Principal moments [kg m^2]; copied, read-only.\n"
      "axes : array_like, shape (3, 3) or (n, 3, 3)\n"
      "    Unit axes as columns; copied, read-only.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    Shapes that do not match (the message names `axes`).\n"
      "\n"
      "See Also\n"
      "--------\n"
      "principal_axes, SpatialInertia.principal_axes\n"
      "\n"
      "Examples\n"
      "--------\n"
      ">>> p = rd.solid_box([1.0, 2.0, 3.0], mass=12.0).principal_axes()\n"
      ">>> moments, axes = p\n"
      ">>> moments\n"
      "array([ 5., 10., 13.])\n"
      ">>> np.allclose(axes @ np.diag(moments) @ axes.T, np.diag([13.0, 10.0, 5.0]))\n"
      "True")
      .def(py::init(&make_principal_axes), "moments"_a, "axes"_a,
           "From moments (3,) [kg m^2] and axes (3,3) (or (n,3), (n,3,3)); copied, read-only; see the class.")
      .def_readonly("moments", &PyPrincipalAxes::moments,
                    "Principal moments (3,) or (n, 3), ascending [kg m^2], read-only.")
      .def_readonly("axes", &PyPrincipalAxes::axes,
                    "Principal axes (3,3) or (n,3,3): column k is the unit axis of moments[k], expressed in the\n"
                    "inertia's frame; det +1. Read-only.")
      .def("__len__", [](const PyPrincipalAxes&) { return 2; })
      .def("__iter__", [](const PyPrincipalAxes& p) { return as_tuple(p).attr("__iter__")(); })
      .def(
          "__getitem__",
          [](const PyPrincipalAxes& p, py::handle index) {
            const py::tuple items = as_tuple(p);
            return py::object(items[index]);
          },
          "index"_a,
          "0: moments, 1: axes (as the tuple (moments, axes)).")
      .def(
          "__eq__",
          [](const PyPrincipalAxes& p, py::handle other) {
            return equal_or_not_implemented(p, other, [](const PyPrincipalAxes& a, const PyPrincipalAxes& b) {
              const py::module_ np = py::module_::import("numpy");
              return np.attr("array_equal")(a.moments, b.moments).cast<bool>() &&
                     np.attr("array_equal")(a.axes, b.axes).cast<bool>();
            });
          },
          py::is_operator())
      .def("__repr__",
           [](const PyPrincipalAxes& p) { return repr_call("PrincipalAxes", {{"moments", p.moments}, {"axes", p.axes}}); })
      .def(py::pickle([](const PyPrincipalAxes& p) { return as_tuple(p); },
                      [](const py::tuple& state) {
                        const py::tuple s = pickled_state(state, 2, "PrincipalAxes");
                        return make_principal_axes(s[0], s[1]);
                      }));
}

void bind_types(py::module_& m) {
  py::enum_<InertiaCheck>(m, "InertiaCheck",
               "What a constructor requires of a rotational inertia.\n"
               "\n"
               "`physical`: symmetric, positive semi-definite and the triangle inequality I0 + I1 >= I2 on the\n"
               "principal moments (every real body). `allow_unrealizable`: symmetric positive semi-definite only; a\n"
               "documented opt-in for test problems such as Hairer-Lubich-Wanner's I = diag(2, 1, 2/3), never the\n"
               "default.\n"
               "\n"
               "Parameters\n"
               "----------\n"
               "value : int\n"
               "    0 (physical) or 1 (allow_unrealizable); TypeError otherwise.\n"
               "\n"
               "See Also\n"
               "--------\n"
               "SpatialInertia, inertia_report\n"
               "\n"
               "Examples\n"
               "--------\n"
               ">>> I = np.diag([2.0, 1.0, 2 / 3])\n"
               ">>> rd.SpatialInertia(1.0, [0, 0, 0], I, check=rd.InertiaCheck.allow_unrealizable).mass\n"
               "1.0\n"
               ">>> rd.InertiaCheck(0)\n"
               "<InertiaCheck.physical: 0>")
      .value("physical", InertiaCheck::physical)
      .value("allow_unrealizable", InertiaCheck::allow_unrealizable);  // a value not an int: call_errors.hpp

  py::class_<InertiaReport>(m, "InertiaReport",
                            "Validity report of a mass and a rotational inertia about the centre of mass.\n"
                            "\n"
                            "Made by inertia_report and SpatialInertia.report; == compares every field; it pickles.\n"
                            "\n"
                            "Parameters\n"
                            "----------\n"
                            "mass, inertia_com, scale\n"
                            "    As inertia_report (there is no constructor from Python).\n"
                            "\n"
                            "See Also\n"
                            "--------\n"
                            "inertia_report, nearest_valid_inertia\n"
                            "\n"
                            "Examples\n"
                            "--------\n"
                            ">>> r = rd.solid_box([1.0, 1.0, 1.0], mass=12.0).report()\n"
                            ">>> r.valid(), r.principal_moments.round(12), r.condition_number\n"
                            "(True, array([2., 2., 2.]), 1.0)")
      .def_readonly("mass", &InertiaReport::mass, "Mass m [kg].")
      .def_readonly("mass_positive", &InertiaReport::mass_positive, "Whether the mass is finite and > 0.")
      .def_readonly("finite", &InertiaReport::finite, "Whether every entry of the inertia is finite.")
      .def_readonly("asymmetry", &InertiaReport::asymmetry,
                    "Largest asymmetry max |I - I^T| [kg m^2] of the inertia about the centre of mass.")
      .def_readonly("symmetric", &InertiaReport::symmetric, "Whether asymmetry <= asymmetry_tolerance.")
      .def_property_readonly("principal_moments", [](const InertiaReport& r) { return read_only(r.principal_moments); },
                             "Principal moments (3,) ascending I0 <= I1 <= I2 [kg m^2] of the inertia about the\n"
                             "centre of mass (its symmetric part), read-only.")
      .def_property_readonly("triangle_margins", [](const InertiaReport& r) { return read_only(r.triangle_margins); },
                             "Triangle margins (3,) (I1+I2-I0, I0+I2-I1, I0+I1-I2) [kg m^2]; the last is binding;\n"
                             "read-only.")
      .def_readonly("condition_number", &InertiaReport::condition_number,
                    "Condition number I2 / I0 of the principal moments, dimensionless (inf when I0 <= 0).")
      .def_readonly("tolerance", &InertiaReport::tolerance,
                    "Absolute tolerance [kg m^2] of the positive semi-definite and triangle-inequality checks.")
      .def_readonly("positive_semidefinite", &InertiaReport::positive_semidefinite,
                    "Whether I0 >= -tolerance (the inertia is positive semi-definite).")
      .def_readonly("triangle_inequality", &InertiaReport::triangle_inequality,
                    "Whether I0 + I1 - I2 >= -tolerance (the triangle inequality on the principal moments).")
      .def_readonly("asymmetry_tolerance", &InertiaReport::asymmetry_tolerance,
                    "Largest asymmetry accepted, 1e-12 max |I_ij| [kg m^2].")
      .def(
          "valid", [](const InertiaReport& r, py::handle check) { return r.valid(check_arg(check)); },
          "check"_a = InertiaCheck::physical,
           "Whether every check required by `check` passes.\n\n"
           "Parameters\n----------\n"
           "check : InertiaCheck, default InertiaCheck.physical\n"
           "    physical: mass, finite, symmetric, PSD and triangle inequality; allow_unrealizable: all but\n"
           "    the last.\n\n"
           "Returns\n-------\nbool")
      .def("summary", &InertiaReport::summary,
           "One line with the principal moments and triangle margins [kg m^2], condition number, tolerance\n"
           "[kg m^2] and verdict.")
      .def(
          "__eq__",
          [](const InertiaReport& r, py::handle other) {
            return equal_or_not_implemented(r, other, [](const InertiaReport& a, const InertiaReport& b) {
              return a.mass == b.mass && a.mass_positive == b.mass_positive && a.finite == b.finite &&
                     a.asymmetry == b.asymmetry && a.asymmetry_tolerance == b.asymmetry_tolerance &&
                     a.symmetric == b.symmetric && same(a.principal_moments, b.principal_moments) &&
                     same(a.triangle_margins, b.triangle_margins) && a.condition_number == b.condition_number &&
                     a.tolerance == b.tolerance && a.positive_semidefinite == b.positive_semidefinite &&
                     a.triangle_inequality == b.triangle_inequality;
            });
          },
          py::is_operator(), "Exact equality of every field.")
      .def("__repr__",
           [](const InertiaReport& r) {
             return repr_call("InertiaReport", {{"mass", py::float_(r.mass)},
                                                {"principal_moments", py_io::to_array(r.principal_moments)},
                                                {"triangle_margins", py_io::to_array(r.triangle_margins)},
                                                {"condition_number", py::float_(r.condition_number)},
                                                {"tolerance", py::float_(r.tolerance)},
                                                {"valid", py::bool_(r.valid())}});
           })
      .def(py::pickle(&report_state, &report_from_state));

  bind_principal_axes(m);
}

// composite's parts: a sequence of SpatialInertia, or of (X_AB, SpatialInertia) pairs.
SpatialInertia composite_py(py::handle parts) {
  const char* expected = "a list of SpatialInertia or of (Transform X_AB, SpatialInertia) pairs";
  if (!py::isinstance<py::sequence>(parts) || py::isinstance<py::str>(parts)) py_io::throw_type_error("parts", expected, parts);
  const py::sequence items = py::reinterpret_borrow<py::sequence>(parts);
  if (py::len(items) == 0) throw py::value_error(std::string("parts: expected ") + expected + ", got an empty sequence");
  const bool pairs = py::isinstance<py::tuple>(items[0]);  // the first part sets the form of all
  if (!pairs && !is_instance<SpatialInertia>(items[0])) {
    py_io::throw_type_error("parts[0]", "a SpatialInertia or a (Transform X_AB, SpatialInertia) pair", items[0]);
  }
  std::vector<std::pair<Transform, SpatialInertia>> placed;
  std::vector<SpatialInertia> same_frame;
  for (size_t i = 0; i < py::len(items); ++i) {
    const std::string name = "parts[" + std::to_string(i) + "]";
    const py::object item = items[i];
    if (!pairs) {
      same_frame.push_back(py_io::as_instance<SpatialInertia>(item, name, "a SpatialInertia, as parts[0]"));
      continue;
    }
    if (!py::isinstance<py::tuple>(item) || py::len(item) != 2) {
      py_io::throw_type_error(name, "a (Transform X_AB, SpatialInertia) pair, as parts[0]", item);
    }
    const py::tuple pair = py::reinterpret_borrow<py::tuple>(item);
    placed.emplace_back(py_io::as_instance<Transform>(pair[0], name + "[0]", "a Transform"),
                        as_inertia(pair[1], name + "[1]"));
  }
  return pairs ? composite(placed) : composite(same_frame);
}

// SpatialInertia(mass=..., com=[...], inertia_com=[[...]]), with check=InertiaCheck.allow_unrealizable
// when the inertia violates the triangle inequality (built with that opt-in), so that it evaluates.
std::string spatial_inertia_repr(const SpatialInertia& I) {
  std::string text = repr_call("SpatialInertia", {{"mass", py::float_(I.mass())},
                                                  {"com", py_io::to_array(I.com())},
                                                  {"inertia_com", py_io::to_array(I.inertia_com())}});
  if (I.report().valid(InertiaCheck::physical)) return text;
  return text.substr(0, text.size() - 1) + ", check=InertiaCheck.allow_unrealizable)";
}

void bind_spatial_inertia(py::module_& m) {
  py::class_<SpatialInertia>(
      m, "SpatialInertia",
      "Mass properties of one rigid body: mass, centre of mass and rotational inertia about it.\n"
      "\n"
      "Mass m [kg], centre of mass c [m] and rotational inertia I_C [kg m^2] about the centre of mass, all\n"
      "expressed in one frame (moments on the diagonal of I_C, negated products off it). Constructors check\n"
      "validity. + composes two bodies in one frame, - removes a part (a hole); == compares exactly.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "mass : float\n"
      "    Mass m [kg], finite and > 0.\n"
      "com : array_like, shape (3,)\n"
      "    Centre of mass c [m].\n"
      "inertia_com : array_like, shape (3, 3)\n"
      "    Rotational inertia about the centre of mass [kg m^2].\n"
      "check : InertiaCheck, default InertiaCheck.physical\n"
      "    InertiaCheck.physical (triangle inequality required) or InertiaCheck.allow_unrealizable (opt-in:\n"
      "    symmetric PSD only, e.g. I = diag(2, 1, 2/3)).\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    A mass not finite and > 0, a non-finite com, or an inertia that fails `check` (the message gives\n"
      "    its principal moments, triangle margins and condition number).\n"
      "\n"
      "See Also\n"
      "--------\n"
      "inertia_report, composite, solid_box, from_point_masses\n"
      "\n"
      "Examples\n"
      "--------\n"
      "The parallel-axis theorem: a 2 kg sphere of radius 0.5 m centred 1 m from the origin along x has,\n"
      "about the origin, I = 2/5 m r^2 + m d^2 = 0.2 + 2 = 2.2 kg m^2 about the axes across the offset:\n"
      "\n"
      ">>> body = rd.SpatialInertia(2.0, [1.0, 0.0, 0.0], 0.2 * np.eye(3))\n"
      ">>> body.inertia_about_origin().diagonal().round(12)\n"
      "array([0.2, 2.2, 2.2])")
      .def(py::init([](py::handle mass, py::handle com, py::handle inertia_com, py::handle check) {
             return SpatialInertia(py_io::as_scalar(mass, "mass"), py_io::as_vector3(com, "com"),
                                   py_io::as_matrix3(inertia_com, "inertia_com"), check_arg(check));
           }),
           "mass"_a, "com"_a, "inertia_com"_a, "check"_a = InertiaCheck::physical,
           "From mass [kg] > 0, com (3,) [m] and inertia_com (3,3) [kg m^2] about the centre of mass, checked\n"
           "as `check` requires (InertiaCheck.physical by default); see the class.")
      .def_static(
          "from_inertia_about_point",
          [](py::handle mass, py::handle com, py::handle inertia, py::handle point, py::handle check) {
            return SpatialInertia::from_inertia_about_point(
                py_io::as_scalar(mass, "mass"), py_io::as_vector3(com, "com"),
                py_io::as_matrix3(inertia, "inertia_about_point"), py_io::as_vector3(point, "point"), check_arg(check));
          },
          "mass"_a, "com"_a, "inertia_about_point"_a, "point"_a, "check"_a = InertiaCheck::physical,
          "From the inertia about a point (parallel-axis theorem, Craig).\n"
          "\n"
          "I_C = I_P - m (|r|^2 1 - r r^T), r = c - p, all in one frame.\n"
          "\n"
          "Parameters\n"
          "----------\n"
          "mass : float\n"
          "    Mass m [kg], finite and > 0.\n"
          "com : array_like, shape (3,)\n"
          "    Centre of mass c [m].\n"
          "inertia_about_point : array_like, shape (3, 3)\n"
          "    Rotational inertia I_P about `point` [kg m^2].\n"
          "point : array_like, shape (3,)\n"
          "    The point p [m].\n"
          "check : InertiaCheck, default InertiaCheck.physical\n"
          "    What I_C must satisfy, as the constructor.\n"
          "\n"
          "Returns\n"
          "-------\n"
          "SpatialInertia\n"
          "\n"
          "Examples\n"
          "--------\n"
          "A 3 kg rod of length 2 m along z has m L^2/3 = 4 kg m^2 about its end, m L^2/12 = 1 kg m^2 about its\n"
          "centre:\n"
          "\n"
          ">>> rd.SpatialInertia.from_inertia_about_point(3.0, [0, 0, 1.0], np.diag([4.0, 4.0, 0.0]),\n"
          "...                                            [0, 0, 2.0]).inertia_com.diagonal()\n"
          "array([1., 1., 0.])")
      .def_static(
          "from_inertia_about_origin",
          [](py::handle mass, py::handle com, py::handle inertia, py::handle check) {
            return SpatialInertia::from_inertia_about_origin(py_io::as_scalar(mass, "mass"),
                                                             py_io::as_vector3(com, "com"),
                                                             py_io::as_matrix3(inertia, "inertia_about_origin"),
                                                             check_arg(check));
          },
          "mass"_a, "com"_a, "inertia_about_origin"_a, "check"_a = InertiaCheck::physical,
          "From the inertia about the frame's origin (parallel-axis theorem, Craig).\n"
          "\n"
          "Parameters\n"
          "----------\n"
          "mass : float\n"
          "    Mass m [kg], finite and > 0.\n"
          "com : array_like, shape (3,)\n"
          "    Centre of mass c [m].\n"
          "inertia_about_origin : array_like, shape (3, 3)\n"
          "    Rotational inertia I_O about the origin [kg m^2].\n"
          "check : InertiaCheck, default InertiaCheck.physical\n"
          "    What I_C must satisfy, as the constructor.\n"
          "\n"
          "Returns\n"
          "-------\n"
          "SpatialInertia\n"
          "\n"
          "Examples\n"
          "--------\n"
          ">>> body = rd.SpatialInertia.from_inertia_about_origin(3.0, [0, 0, 1.0], np.diag([4.0, 4.0, 0.0]))\n"
          ">>> body.inertia_com.diagonal()\n"
          "array([1., 1., 0.])")
      .def_static(
          "from_matrix",
          [](py::handle matrix, py::handle check) {
            return SpatialInertia::from_matrix(py_io::as_matrix6(matrix, "matrix"), check_arg(check));
          },
          "matrix"_a, "check"_a = InertiaCheck::physical,
          "From the (6, 6) spatial inertia about the origin.\n"
          "\n"
          "Angular first: [[I_O, m hat(c)], [m hat(c)^T, m 1]] (I_O [kg m^2], m hat(c) [kg m], m [kg]).\n"
          "\n"
          "Parameters\n"
          "----------\n"
          "matrix : array_like, shape (6, 6)\n"
          "    The spatial inertia about the frame's origin.\n"
          "check : InertiaCheck, default InertiaCheck.physical\n"
          "    What I_C must satisfy, as the constructor.\n"
          "\n"
          "Returns\n"
          "-------\n"
          "SpatialInertia\n"
          "\n"
          "Examples\n"
          "--------\n"
          ">>> body = rd.solid_box([1.0, 2.0, 3.0], mass=12.0).transformed(rd.Transform(translation=[1.0, 0, 0]))\n"
          ">>> rd.SpatialInertia.from_matrix(body.matrix()).is_approx(body)\n"
          "True")
      .def_static(
          "point_mass",
          [](py::handle mass, py::handle position) {
            return SpatialInertia::point_mass(py_io::as_scalar(mass, "mass"), py_io::as_vector3(position, "position"));
          },
          "mass"_a, "position"_a,
          "A point mass (zero inertia about its centre of mass).\n"
          "\n"
          "Parameters\n"
          "----------\n"
          "mass : float\n"
          "    Mass [kg], finite and > 0.\n"
          "position : array_like, shape (3,)\n"
          "    Its position [m], which becomes the centre of mass.\n"
          "\n"
          "Returns\n"
          "-------\n"
          "SpatialInertia\n"
          "\n"
          "Examples\n"
          "--------\n"
          ">>> rd.SpatialInertia.point_mass(2.0, [1.0, 0, 0]).inertia_about_origin().diagonal()\n"
          "array([0., 2., 2.])")
      .def_property_readonly("mass", &SpatialInertia::mass, "Mass m [kg].")
      .def_property_readonly("com", [](const SpatialInertia& I) { return read_only(I.com()); },
                             "Centre of mass c (3,) [m] in the frame of expression, a read-only copy.")
      .def_property_readonly("inertia_com", [](const SpatialInertia& I) { return read_only(I.inertia_com()); },
                             "Rotational inertia I_C (3,3) [kg m^2] about the centre of mass in the frame of\n"
                             "expression, a read-only copy.")
      .def(
          "inertia_about_point",
          [](const SpatialInertia& I, py::handle point) {
            return py_io::finite_result(I.inertia_about_point(py_io::as_vector3(point, "point")),
                                        "SpatialInertia.inertia_about_point");
          },
          "point"_a,
          "Rotational inertia about a point (parallel-axis theorem, Craig).\n"
          "\n"
          "I_P = I_C + m (|r|^2 1 - r r^T), r = c - p, in the frame of expression.\n"
          "\n"
          "Parameters\n"
          "----------\n"
          "point : array_like, shape (3,)\n"
          "    The point p [m].\n"
          "\n"
          "Returns\n"
          "-------\n"
          "ndarray, shape (3, 3)\n"
          "    I_P [kg m^2].\n"
          "\n"
          "Examples\n"
          "--------\n"
          "A 5 kg ball of radius 1 m about a point of its surface: 2/5 m r^2 + m r^2 = 7 kg m^2 across:\n"
          "\n"
          ">>> rd.solid_sphere(1.0, mass=5.0).inertia_about_point([1.0, 0, 0]).diagonal()\n"
          "array([2., 7., 7.])")
      .def("inertia_about_origin",
           [](const SpatialInertia& I) { return py_io::finite_result(I.inertia_about_origin(), "SpatialInertia.inertia_about_origin"); },
           "Rotational inertia (3,3) [kg m^2] about the frame's origin, in that frame: I_C + m (|c|^2 1 - c c^T).")
      .def("matrix", [](const SpatialInertia& I) { return py_io::finite_result(I.matrix(), "SpatialInertia.matrix"); },
           "Spatial inertia (6,6) about the frame's origin, angular first: [[I_O, m hat(c)], [m hat(c)^T, m 1]]\n"
           "(I_O [kg m^2], m [kg]).")
      .def(
          "momentum",
          [](const SpatialInertia& I, py::handle twist) {
            const Force h = I.momentum(py_io::as_finite_spatial<Motion>(twist, "twist", "a Motion"));
            py_io::warn_unless_finite(h.angular.allFinite() && h.linear.allFinite(), "SpatialInertia.momentum",
                                      format_value(h.to_vector().transpose()));
            return h;
          },
          "twist"_a,
          "Spatial momentum h = I V of a twist, about the frame's origin.\n"
          "\n"
          "Parameters\n"
          "----------\n"
          "twist : Motion\n"
          "    V = [w; v_O]: angular velocity w [rad/s] and velocity v_O [m/s] of the body point at the origin,\n"
          "    in the frame of expression.\n"
          "\n"
          "Returns\n"
          "-------\n"
          "Force\n"
          "    h = [moment of momentum about the origin [kg m^2/s]; linear momentum [kg m/s]].\n"
          "\n"
          "Examples\n"
          "--------\n"
          ">>> rd.solid_sphere(1.0, mass=5.0).momentum(rd.Motion(linear=[3.0, 0, 0])).linear  # m v\n"
          "array([15.,  0.,  0.])")
      .def(
          "kinetic_energy",
          [](const SpatialInertia& I, py::handle twist) {
            return py_io::finite_result(I.kinetic_energy(py_io::as_finite_spatial<Motion>(twist, "twist", "a Motion")),
                                        "SpatialInertia.kinetic_energy");
          },
          "twist"_a,
          "Kinetic energy T = 1/2 V . I V of a twist.\n"
          "\n"
          "Parameters\n"
          "----------\n"
          "twist : Motion\n"
          "    V = [w; v_O] [rad/s, m/s], as in momentum.\n"
          "\n"
          "Returns\n"
          "-------\n"
          "float\n"
          "    T [J].\n"
          "\n"
          "Examples\n"
          "--------\n"
          ">>> ball = rd.solid_sphere(1.0, mass=5.0)  # I = 2 kg m^2\n"
          ">>> spin, slide = rd.Motion(angular=[0, 0, 2.0]), rd.Motion(linear=[3.0, 0, 0])\n"
          ">>> ball.kinetic_energy(spin), ball.kinetic_energy(slide)  # 1/2 I w^2, 1/2 m v^2\n"
          "(4.0, 22.5)")
      .def(
          "angular_momentum_about_com",
          [](const SpatialInertia& I, py::handle w) {
            return py_io::finite_result(I.angular_momentum_about_com(py_io::as_vector3(w, "angular_velocity")),
                                        "SpatialInertia.angular_momentum_about_com");
          },
          "angular_velocity"_a,
          "Angular momentum about the centre of mass, H_C = I_C w.\n"
          "\n"
          "Parameters\n"
          "----------\n"
          "angular_velocity : array_like, shape (3,)\n"
          "    w [rad/s], in the frame of expression.\n"
          "\n"
          "Returns\n"
          "-------\n"
          "ndarray, shape (3,)\n"
          "    H_C [kg m^2/s], in the same frame.\n"
          "\n"
          "Examples\n"
          "--------\n"
          ">>> rd.solid_sphere(1.0, mass=5.0).angular_momentum_about_com([0, 0, 2.0])\n"
          "array([0., 0., 4.])")
      .def(
          "angular_momentum_about_point",
          [](const SpatialInertia& I, py::handle w, py::handle v, py::handle p) {
            return py_io::finite_result(I.angular_momentum_about_point(py_io::as_vector3(w, "angular_velocity"),
                                                                       py_io::as_vector3(v, "com_velocity"),
                                                                       py_io::as_vector3(p, "point")),
                                        "SpatialInertia.angular_momentum_about_point");
          },
          "angular_velocity"_a, "com_velocity"_a, "point"_a,
          "Angular momentum about a point, H_P = r_PC x (m v_C) + H_C (Craig).\n"
          "\n"
          "Parameters\n"
          "----------\n"
          "angular_velocity : array_like, shape (3,)\n"
          "    w [rad/s].\n"
          "com_velocity : array_like, shape (3,)\n"
          "    Velocity of the centre of mass v_C [m/s].\n"
          "point : array_like, shape (3,)\n"
          "    The point P [m]; r_PC = c - p.\n"
          "\n"
          "Returns\n"
          "-------\n"
          "ndarray, shape (3,)\n"
          "    H_P [kg m^2/s]; all vectors in the frame of expression.\n"
          "\n"
          "Examples\n"
          "--------\n"
          ">>> rd.solid_sphere(1.0, mass=5.0).angular_momentum_about_point([0, 0, 0], [1.0, 0, 0], [0, -1.0, 0])\n"
          "array([ 0.,  0., -5.])")
      .def(
          "rotated",
          [](const SpatialInertia& I, py::handle R) { return checked(I.rotated(py_io::as_matrix3(R, "R_AB")), "SpatialInertia.rotated"); },
          "R_AB"_a,
          "The same body re-expressed in frame A: c_A = R_AB c_B, I_C,A = R_AB I_C,B R_AB^T.\n"
          "\n"
          "Parameters\n"
          "----------\n"
          "R_AB : array_like, shape (3, 3)\n"
          "    Rotation taking B (this body's frame) coordinates to A coordinates.\n"
          "\n"
          "Returns\n"
          "-------\n"
          "SpatialInertia\n"
          "\n"
          "Examples\n"
          "--------\n"
          "A quarter turn about z swaps the x and y moments:\n"
          "\n"
          ">>> box = rd.solid_box([1.0, 2.0, 3.0], mass=12.0)\n"
          ">>> box.rotated(rd.rot_z(np.pi / 2)).inertia_com.diagonal().round(12)\n"
          "array([10., 13.,  5.])")
      .def(
          "transformed",
          [](const SpatialInertia& I, py::handle X_AB) {
            return checked(I.transformed(py_io::as_instance<Transform>(X_AB, "X_AB", "a Transform")),
                           "SpatialInertia.transformed");
          },
          "X_AB"_a,
           "The same body re-expressed in frame A: c_A = R_AB c_B + p_AB, I_C,A = R_AB I_C,B R_AB^T.\n"
          "\n"
          "Parameters\n"
          "----------\n"
          "X_AB : Transform\n"
          "    Pose of B (this body's frame) in A, p_AB [m].\n"
          "\n"
          "Returns\n"
          "-------\n"
          "SpatialInertia\n"
          "\n"
          "Examples\n"
          "--------\n"
          ">>> rd.solid_box([1.0, 2.0, 3.0], mass=12.0).transformed(rd.Transform(translation=[1.0, 0, 0])).com\n"
          "array([1., 0., 0.])")
      .def(
          "principal_axes", [](const SpatialInertia& I) { return to_python(I.principal_axes()); },
          "PrincipalAxes of I_C (about the centre of mass, in the frame of expression): moments ascending\n"
          "[kg m^2], axes as columns, right-handed.")
      .def("report", &SpatialInertia::report, "The validity report (InertiaReport) of the mass [kg] and I_C [kg m^2].")
      .def(
          "admits_symmetry_plane",
          [](const SpatialInertia& I, py::handle n, py::handle tolerance) {
            return I.admits_symmetry_plane(py_io::as_vector3(n, "normal"), as_tolerance(tolerance, "tolerance"));
          },
          "normal"_a, "tolerance"_a = 1e-9,
          "Whether the plane through the centre of mass with this normal (3,) can be a plane of symmetry\n"
          "(Craig: then the products of inertia with the normal vanish). Necessary, not sufficient.\n\n"
          "Parameters\n"
          "----------\n"
          "normal : array_like, shape (3,)\n"
          "    The plane's normal, in the frame of expression.\n"
          "tolerance : float, default 1e-9\n"
          "    Relative tolerance, >= 0.\n"
          "\n"
          "Returns\n"
          "-------\n"
          "bool\n"
          "\n"
          "Examples\n"
          "--------\n"
          ">>> box = rd.solid_box([1.0, 2.0, 3.0], mass=12.0)\n"
          ">>> box.admits_symmetry_plane([1.0, 0, 0]), box.admits_symmetry_plane([1.0, 1.0, 0])\n"
          "(True, False)")
      .def(py::self + py::self, "Composite of two bodies expressed in the same frame (ValueError naming the distance between the centres of mass\n"
           "where the sum's inertia would overflow: some 1e150 m or more).")
      .def(py::self - py::self, "This body with the part removed (a hole); ValueError if the rest is invalid.")
      .def(
          "remove",
          [](const SpatialInertia& I, py::handle part, py::handle check) {
            return I.remove(as_inertia(part, "part"), check_arg(check));
          },
          "part"_a, "check"_a = InertiaCheck::physical,
           "This body with `part` removed (a hole), checked as the constructor.\n"
           "\n"
           "Parameters\n"
           "----------\n"
           "part : SpatialInertia\n"
           "    The removed part, in the same frame.\n"
           "check : InertiaCheck, default InertiaCheck.physical\n"
           "    What the rest's I_C must satisfy.\n"
           "\n"
           "Returns\n"
           "-------\n"
           "SpatialInertia\n"
           "\n"
           "Examples\n"
           "--------\n"
           ">>> ball, core = rd.solid_sphere(2.0, density=1.0), rd.solid_sphere(1.0, density=1.0)\n"
           ">>> ball.remove(core).is_approx(rd.hollow_sphere(2.0, 1.0, density=1.0))\n"
           "True")
      .def(
          "is_approx",
          [](const SpatialInertia& I, py::handle other, py::handle prec) {
            return I.is_approx(as_inertia(other, "other"), as_tolerance(prec, "prec"));
          },
          "other"_a, "prec"_a = 1e-12,
          "True when mass, centre of mass and inertia_com agree to `prec` relative to their size (the centre of\n"
          "mass relative to the radius of gyration plus |com|). == compares exactly.\n\n"
          "Parameters\n"
          "----------\n"
          "other : SpatialInertia\n"
          "    The body to compare, in the same frame.\n"
          "prec : float, default 1e-12\n"
          "    Relative tolerance, >= 0.\n"
          "\n"
          "Returns\n"
          "-------\n"
          "bool\n"
          "\n"
          "Examples\n"
          "--------\n"
          ">>> box = rd.solid_box([1.0, 2.0, 3.0], mass=12.0)\n"
          ">>> other = rd.solid_box([1.0, 2.0, 3.0 + 1e-14], mass=12.0)\n"
          ">>> box.is_approx(other), box == other\n"
          "(True, False)")
      .def(
          "__eq__",
          [](const SpatialInertia& I, py::handle other) {
            return equal_or_not_implemented(I, other, [](const SpatialInertia& a, const SpatialInertia& b) {
              return a.mass() == b.mass() && same(a.com(), b.com()) && same(a.inertia_com(), b.inertia_com());
            });
          },
          py::is_operator(), "Exact equality of mass, com and inertia_com (is_approx: up to a tolerance).")
      .def("__repr__", &spatial_inertia_repr)
      .def(py::pickle(
          [](const SpatialInertia& I) { return py::make_tuple(I.mass(), read_only(I.com()), read_only(I.inertia_com())); },
          [](const py::tuple& state) {
            const py::tuple s = pickled_state(state, 3, "SpatialInertia");
            // the stored inertia was checked when built (with the check its builder chose); no projection here
            return SpatialInertia(py_io::as_scalar(s[0], "mass"), py_io::as_vector3(s[1], "com"),
                                  py_io::as_matrix3(s[2], "inertia_com"), InertiaCheck::allow_unrealizable);
          }));

  m.def(
      "composite",
      [](py::handle parts) { return checked(composite_py(parts), "composite"); },
      "parts"_a,
      "Mass properties of a body made of parts (exact).\n"
      "\n"
      "Masses add, the centre of mass is the mass-weighted mean, and each part's inertia is moved to the\n"
      "common centre of mass by the parallel-axis theorem (Craig):\n"
      "I_C = sum_k R_k I_Ck R_k^T + m_k (|r_k|^2 1 - r_k r_k^T), r_k the part's centre of mass relative to the\n"
      "composite's.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "parts : sequence of SpatialInertia, or of (Transform, SpatialInertia) pairs\n"
      "    The parts, all expressed in one frame A; or pairs (X_AB, part) with each part expressed in its own\n"
      "    frame B and placed in A by the Transform X_AB. The first item sets the form of all. Not empty.\n"
      "\n"
      "Returns\n"
      "-------\n"
      "SpatialInertia\n"
      "    Total mass [kg], centre of mass [m] and inertia_com [kg m^2] about it, expressed in A.\n"
      "\n"
      "Raises\n"
      "------\n"
      "TypeError\n"
      "    `parts` not a sequence, or an item not of the form of parts[0] (the message names it).\n"
      "ValueError\n"
      "    `parts` empty.\n"
      "\n"
      "Warns\n"
      "-----\n"
      "RuntimeWarning\n"
      "    A result that overflowed to a non-finite value.\n"
      "\n"
      "See Also\n"
      "--------\n"
      "SpatialInertia.transformed, SpatialInertia.remove, from_point_masses\n"
      "\n"
      "Examples\n"
      "--------\n"
      "Two half cubes side by side make the whole cube:\n"
      "\n"
      ">>> half = rd.solid_box([0.5, 1.0, 1.0], mass=1.0)\n"
      ">>> X_AL = rd.Transform(translation=[-0.25, 0, 0])\n"
      ">>> X_AR = rd.Transform(translation=[0.25, 0, 0])\n"
      ">>> rd.composite([(X_AL, half), (X_AR, half)]).is_approx(rd.solid_box([1.0, 1.0, 1.0], mass=2.0))\n"
      "True");
  m.def(
      "point_inertia",
      [](py::handle mass, py::handle r) {
        return py_io::finite_result(point_inertia(py_io::as_scalar(mass, "mass"), py_io::as_vector3(r, "r")), "point_inertia");
      },
      "mass"_a, "r"_a,
          "Rotational inertia of a point mass about the origin.\n"
          "\n"
          "I_O = m (|r|^2 1 - r r^T), the parallel-axis term of the theorem (Craig).\n"
          "\n"
          "Parameters\n"
          "----------\n"
          "mass : float\n"
          "    Mass m [kg], finite and > 0.\n"
          "r : array_like, shape (3,)\n"
          "    Position [m] of the mass relative to the origin, in any frame A.\n"
          "\n"
          "Returns\n"
          "-------\n"
          "ndarray, shape (3, 3)\n"
          "    Inertia about the origin [kg m^2], expressed in A (moments on the diagonal, negated products\n"
          "    off it).\n"
          "\n"
          "Raises\n"
          "------\n"
          "ValueError\n"
          "    `mass` not finite and > 0, or `r` not finite (the message names it).\n"
          "\n"
          "See Also\n"
          "--------\n"
          "from_point_masses, SpatialInertia.inertia_about_point\n"
          "\n"
          "Examples\n"
          "--------\n"
          "2 kg at 3 m on the z axis: m d^2 = 18 kg m^2 about x and y, nothing about z:\n"
          "\n"
          ">>> rd.point_inertia(2.0, [0.0, 0.0, 3.0])\n"
          "array([[18.,  0.,  0.],\n"
          "       [ 0., 18.,  0.],\n"
          "       [ 0.,  0.,  0.]])");
}

void bind_validity(py::module_& m) {
  m.attr("inertia_relative_tolerance") = inertia_relative_tolerance;
  m.def(
      "inertia_report",
      [](py::handle mass, py::handle inertia, py::handle scale) {
        return inertia_report(py_io::as_scalar(mass, "mass"), py_io::as_matrix3(inertia, "inertia_com"),
                              as_tolerance(scale, "scale"));
      },
      "mass"_a, "inertia_com"_a, "scale"_a = 0.0,
      "Validity report of a mass and a rotational inertia about the centre of mass.\n"
      "\n"
      "Checks the mass (finite, > 0), the inertia (finite, symmetric to 1e-12 max |I_ij|, positive\n"
      "semi-definite) and the triangle inequality I0 + I1 >= I2 on its ascending principal moments (from its\n"
      "symmetric part), each within tolerance = inertia_relative_tolerance * max(scale, |trace|) [kg m^2].\n"
      "Raises nothing on a bad inertia: the report says what fails.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "mass : float\n"
      "    Mass [kg].\n"
      "inertia_com : array_like, shape (3, 3)\n"
      "    Rotational inertia about the centre of mass [kg m^2], in any frame (moments on the diagonal,\n"
      "    negated products off it).\n"
      "scale : float, default 0.0\n"
      "    Size [kg m^2] of the numbers the inertia was computed from, >= 0 (0: the trace only).\n"
      "\n"
      "Returns\n"
      "-------\n"
      "InertiaReport\n"
      "    Principal moments, triangle margins, condition number, tolerance and each check.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    `scale` negative or `inertia_com` not of shape (3, 3) (the message names it).\n"
      "\n"
      "See Also\n"
      "--------\n"
      "nearest_valid_inertia, SpatialInertia.report, InertiaCheck\n"
      "\n"
      "Examples\n"
      "--------\n"
      "Hairer-Lubich-Wanner's test inertia diag(2, 1, 2/3) is symmetric and positive definite, but no real\n"
      "body has it (2/3 + 1 < 2):\n"
      "\n"
      ">>> r = rd.inertia_report(1.0, np.diag([2.0, 1.0, 2 / 3]))\n"
      ">>> r.valid(), r.valid(rd.InertiaCheck.allow_unrealizable)\n"
      "(False, True)\n"
      ">>> r.triangle_margins.round(12)\n"
      "array([ 2.33333333,  1.66666667, -0.33333333])");
  m.def(
      "nearest_valid_inertia",
      [](py::handle inertia) {
        return py_io::finite_result(nearest_valid_inertia(py_io::as_matrix3(inertia, "inertia")), "nearest_valid_inertia");
      },
      "inertia"_a,
      "Nearest rotational inertia that satisfies the triangle inequality (an explicit repair).\n"
      "\n"
      "The symmetric part's principal moments are projected onto the cone I_i + I_j >= I_k (nearest in the\n"
      "Frobenius norm), keeping its principal axes. A valid inertia is returned unchanged (symmetrised). Never\n"
      "applied implicitly.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "inertia : array_like, shape (3, 3)\n"
      "    Rotational inertia [kg m^2] about a point, in any frame.\n"
      "\n"
      "Returns\n"
      "-------\n"
      "ndarray, shape (3, 3)\n"
      "    The repaired inertia [kg m^2], about the same point and in the same frame.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    `inertia` not of shape (3, 3) or not finite.\n"
      "\n"
      "See Also\n"
      "--------\n"
      "inertia_report, InertiaCheck\n"
      "\n"
      "Examples\n"
      "--------\n"
      ">>> J = rd.nearest_valid_inertia(np.diag([2.0, 1.0, 2 / 3]))\n"
      ">>> J.diagonal().round(12)\n"
      "array([1.88888889, 1.11111111, 0.77777778])\n"
      ">>> rd.inertia_report(1.0, J).valid()\n"
      "True");
  m.def(
      "principal_axes",
      [](py::handle inertia) {
        const py_io::Stack s = py_io::as_stack(inertia, "inertia", {3, 3});
        Array moments = py_io::new_stack(s.n, s.stacked, {3}, "moments");
        Array axes = py_io::new_stack(s.n, s.stacked, {3, 3}, "axes");
        double* pm = moments.mutable_data();
        double* pa = axes.mutable_data();
        {
          py::gil_scoped_release release;
          using RowMatrix3d = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
          for (py::ssize_t i = 0; i < s.n; ++i) {
            const Eigen::Matrix3d I = Eigen::Map<const RowMatrix3d>(s.item(i, 9));
            const PrincipalAxes p = principal_axes(I);
            Eigen::Map<Eigen::Vector3d>(pm + 3 * i) = p.moments;
            Eigen::Map<RowMatrix3d>(pa + 9 * i) = p.axes;
          }
        }
        // unit axes; the moments overflow only for entries near the largest double
        return PyPrincipalAxes{frozen(py_io::finite_result(moments, "principal_axes moments")), frozen(axes)};
      },
      "inertia"_a,
      "Principal moments and axes of rotational inertias (Craig, \"Principal Axes\").\n"
      "\n"
      "I = axes @ diag(moments) @ axes.T, about the point and in the frame the inertia is given for. Reads the\n"
      "lower triangles (the matrices are taken as symmetric). Releases the GIL.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "inertia : array_like, shape (3, 3) or (n, 3, 3)\n"
      "    Symmetric rotational inertias [kg m^2].\n"
      "\n"
      "Returns\n"
      "-------\n"
      "PrincipalAxes\n"
      "    moments, shape (3,) or (n, 3), ascending [kg m^2]; axes, shape (3, 3) or (n, 3, 3), column k the\n"
      "    unit axis of moments[k], right-handed (det +1), canonical when moments coincide. Unpacks as\n"
      "    ``moments, axes = principal_axes(I)``.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    `inertia` of another shape (the message names it).\n"
      "\n"
      "See Also\n"
      "--------\n"
      "PrincipalAxes, SpatialInertia.principal_axes\n"
      "\n"
      "Examples\n"
      "--------\n"
      ">>> moments, axes = rd.principal_axes(np.diag([3.0, 1.0, 2.0]))\n"
      ">>> moments\n"
      "array([1., 2., 3.])\n"
      ">>> axes\n"
      "array([[0., 0., 1.],\n"
      "       [1., 0., 0.],\n"
      "       [0., 1., 0.]])\n"
      ">>> rd.principal_axes(np.stack([np.eye(3), np.diag([3.0, 1.0, 2.0])])).moments\n"
      "array([[1., 1., 1.],\n"
      "       [1., 2., 3.]])");
}

void bind_primitives(py::module_& m) {
  const auto md = [](py::handle mass, py::handle density) { return mass_or_density(mass, density); };
  const auto def1 = [&](const char* name, SpatialInertia (*f)(double, MassOrDensity), const char* arg,
                        const std::string& doc) {
    m.def(
        name,
        [f, md, arg](py::handle x, py::handle mass, py::handle density) {
          return f(py_io::as_scalar(x, arg), md(mass, density));
        },
        py::arg(arg), py::kw_only(), "mass"_a = py::none(), "density"_a = py::none(), doc.c_str());
  };
  const auto def2 = [&](const char* name, SpatialInertia (*f)(double, double, MassOrDensity), const char* a1,
                        const char* a2, const std::string& doc) {
    m.def(
        name,
        [f, md, a1, a2](py::handle x, py::handle y, py::handle mass, py::handle density) {
          return f(py_io::as_scalar(x, a1), py_io::as_scalar(y, a2), md(mass, density));
        },
        py::arg(a1), py::arg(a2), py::kw_only(), "mass"_a = py::none(), "density"_a = py::none(),
        doc.c_str());
  };
  const auto defv = [&](const char* name, SpatialInertia (*f)(const Eigen::Vector3d&, MassOrDensity), const char* arg,
                        const std::string& doc) {
    m.def(
        name,
        [f, md, arg](py::handle v, py::handle mass, py::handle density) {
          return f(py_io::as_vector3(v, arg), md(mass, density));
        },
        py::arg(arg), py::kw_only(), "mass"_a = py::none(), "density"_a = py::none(), doc.c_str());
  };
  def1("solid_sphere", &solid_sphere, "radius",
      "Mass properties of a solid sphere.\n"
      "\n"
      "I = 2/5 m r^2 1 about the centre.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "radius : float\n"
      "    Radius r [m].\n"
      "mass : float, optional\n"
      "    Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.\n"
      "density : float, optional\n"
      "    Volume density [kg/m^3], finite and > 0: m = density * volume.\n"
      "\n"
      "Returns\n"
      "-------\n"
      "SpatialInertia\n"
      "    Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the\n"
      "    shape's frame.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    `radius` not finite and > 0;\n"
      "    not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names\n"
      "    the argument).\n"
      "TypeError\n"
      "    An argument that is not a real number.\n"
      "\n"
      "See Also\n"
      "--------\n"
      "hollow_sphere, spherical_shell, solid_ellipsoid, SpatialInertia.transformed\n"
      "\n"
      "Examples\n"
      "--------\n"
      "A solid sphere of 2 kg and radius 0.5 m has I = 2/5 m r^2 = 0.2 kg m^2 about every axis:\n"
      "\n"
      ">>> rd.solid_sphere(0.5, mass=2.0).inertia_com.diagonal()\n"
      "array([0.2, 0.2, 0.2])\n"
      ">>> f\"{rd.solid_sphere(0.1, density=1000.0).mass:.6f}\"  # 4/3 pi r^3 rho\n"
      "'4.188790'");
  def2("hollow_sphere", &hollow_sphere, "outer_radius", "inner_radius",
       "Mass properties of a thick spherical shell (a solid sphere with a concentric spherical hole).\n"
       "\n"
       "I = 2/5 m (R^5 - r^5) / (R^3 - r^3) 1 about the centre; r = 0 is the solid sphere.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "outer_radius : float\n"
       "    Outer radius R [m], > 0.\n"
       "inner_radius : float\n"
       "    Inner radius r [m], in [0, R).\n"
       "mass : float, optional\n"
       "    Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.\n"
       "density : float, optional\n"
       "    Volume density [kg/m^3], finite and > 0: m = density * volume.\n"
       "\n"
       "Returns\n"
       "-------\n"
       "SpatialInertia\n"
       "    Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the\n"
       "    shape's frame.\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    `outer_radius` not finite and > 0, or `inner_radius` outside [0, outer_radius);\n"
       "    not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names\n"
       "    the argument).\n"
       "TypeError\n"
       "    An argument that is not a real number.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "solid_sphere, spherical_shell, SpatialInertia.transformed\n"
       "\n"
       "Examples\n"
       "--------\n"
       "With no hole it is the solid sphere; with R = 2 m, r = 1 m, m = 1 kg, I = 2/5 31/7 kg m^2:\n"
       "\n"
       ">>> rd.hollow_sphere(1.0, 0.0, mass=1.0).is_approx(rd.solid_sphere(1.0, mass=1.0))\n"
       "True\n"
       ">>> rd.hollow_sphere(2.0, 1.0, mass=1.0).inertia_com.diagonal().round(12)\n"
       "array([1.77142857, 1.77142857, 1.77142857])");
  def1("spherical_shell", &spherical_shell, "radius",
      "Mass properties of a thin spherical surface.\n"
      "\n"
      "I = 2/3 m r^2 1 about the centre.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "radius : float\n"
      "    Radius r [m].\n"
      "mass : float, optional\n"
      "    Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.\n"
      "density : float, optional\n"
      "    Area density [kg/m^2], finite and > 0: m = density * area.\n"
      "\n"
      "Returns\n"
      "-------\n"
      "SpatialInertia\n"
      "    Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the\n"
      "    shape's frame.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    `radius` not finite and > 0;\n"
      "    not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names\n"
      "    the argument).\n"
      "TypeError\n"
      "    An argument that is not a real number.\n"
      "\n"
      "See Also\n"
      "--------\n"
      "hollow_sphere, solid_sphere, SpatialInertia.transformed\n"
      "\n"
      "Examples\n"
      "--------\n"
      ">>> rd.spherical_shell(1.0, mass=3.0).inertia_com.diagonal()  # 2/3 m r^2\n"
      "array([2., 2., 2.])");
  defv("solid_box", &solid_box, "size",
      "Mass properties of a solid rectangular box.\n"
      "\n"
      "Edges (a, b, c) along x, y, z: I = m/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2) about the centre.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "size : array_like, shape (3,)\n"
      "    Edge lengths (a, b, c) [m] along x, y, z.\n"
      "mass : float, optional\n"
      "    Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.\n"
      "density : float, optional\n"
      "    Volume density [kg/m^3], finite and > 0: m = density * volume.\n"
      "\n"
      "Returns\n"
      "-------\n"
      "SpatialInertia\n"
      "    Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the\n"
      "    shape's frame (edges along x, y, z).\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    A `size` entry not finite and > 0;\n"
      "    not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names\n"
      "    the argument).\n"
      "TypeError\n"
      "    An argument that is not a real number.\n"
      "\n"
      "See Also\n"
      "--------\n"
      "box_shell, thin_plate, solid_ellipsoid, SpatialInertia.transformed\n"
      "\n"
      "Examples\n"
      "--------\n"
      ">>> rd.solid_box([1.0, 2.0, 3.0], mass=12.0).inertia_com.diagonal()  # m/12 (b^2+c^2, ...)\n"
      "array([13., 10.,  5.])");
  defv("box_shell", &box_shell, "size",
      "Mass properties of a closed thin-walled box (its six faces).\n"
      "\n"
      "Edges (a, b, c) along x, y, z, area density s:\n"
      "I_xx = 2 s [b c (b^2 + c^2)/12 + a c (c^2/12 + b^2/4) + a b (b^2/12 + c^2/4)], and cyclically.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "size : array_like, shape (3,)\n"
      "    Edge lengths (a, b, c) [m] along x, y, z.\n"
      "mass : float, optional\n"
      "    Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.\n"
      "density : float, optional\n"
      "    Area density [kg/m^2], finite and > 0: m = density * area.\n"
      "\n"
      "Returns\n"
      "-------\n"
      "SpatialInertia\n"
      "    Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the\n"
      "    shape's frame (edges along x, y, z).\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    A `size` entry not finite and > 0;\n"
      "    not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names\n"
      "    the argument).\n"
      "TypeError\n"
      "    An argument that is not a real number.\n"
      "\n"
      "See Also\n"
      "--------\n"
      "solid_box, thin_plate, mesh_shell, SpatialInertia.transformed\n"
      "\n"
      "Examples\n"
      "--------\n"
      "A thin-walled cube of edge a has I = 5/18 m a^2 about every axis:\n"
      "\n"
      ">>> rd.box_shell([1.0, 1.0, 1.0], mass=18.0).inertia_com.diagonal().round(12)\n"
      "array([5., 5., 5.])");
  def2("solid_cylinder", &solid_cylinder, "radius", "height",
       "Mass properties of a solid circular cylinder, axis z.\n"
       "\n"
       "I_zz = m r^2/2, I_xx = I_yy = m (3 r^2 + h^2)/12 about the centre.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "radius : float\n"
       "    Radius r [m].\n"
       "height : float\n"
       "    Height h [m] along z.\n"
       "mass : float, optional\n"
       "    Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.\n"
       "density : float, optional\n"
       "    Volume density [kg/m^3], finite and > 0: m = density * volume.\n"
       "\n"
       "Returns\n"
       "-------\n"
       "SpatialInertia\n"
       "    Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the\n"
       "    shape's frame (axis z).\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    `radius` or `height` not finite and > 0;\n"
       "    not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names\n"
       "    the argument).\n"
       "TypeError\n"
       "    An argument that is not a real number.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "hollow_cylinder, thin_disk, thin_rod, solid_capsule, SpatialInertia.transformed\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> rd.solid_cylinder(1.0, 2.0, mass=12.0).inertia_com.diagonal()  # m (3r^2+h^2)/12, m r^2/2\n"
       "array([7., 7., 6.])");
  m.def(
      "hollow_cylinder",
      [md](py::handle R, py::handle r, py::handle h, py::handle mass, py::handle density) {
        return hollow_cylinder(py_io::as_scalar(R, "outer_radius"), py_io::as_scalar(r, "inner_radius"),
                               py_io::as_scalar(h, "height"), md(mass, density));
      },
      "outer_radius"_a, "inner_radius"_a, "height"_a, py::kw_only(), "mass"_a = py::none(), "density"_a = py::none(),
      "Mass properties of a thick tube (open ends), axis z.\n"
      "\n"
      "I_zz = m (R^2 + r^2)/2, I_xx = I_yy = m (3 (R^2 + r^2) + h^2)/12 about the centre; r = 0 is the solid\n"
      "cylinder.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "outer_radius : float\n"
      "    Outer radius R [m], > 0.\n"
      "inner_radius : float\n"
      "    Inner radius r [m], in [0, R).\n"
      "height : float\n"
      "    Height h [m] along z, > 0.\n"
      "mass : float, optional\n"
      "    Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.\n"
      "density : float, optional\n"
      "    Volume density [kg/m^3], finite and > 0: m = density * volume.\n"
      "\n"
      "Returns\n"
      "-------\n"
      "SpatialInertia\n"
      "    Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the\n"
      "    shape's frame (axis z).\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    `outer_radius` or `height` not finite and > 0, or `inner_radius` outside [0, outer_radius);\n"
      "    not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names\n"
      "    the argument).\n"
      "TypeError\n"
      "    An argument that is not a real number.\n"
      "\n"
      "See Also\n"
      "--------\n"
      "solid_cylinder, SpatialInertia.transformed\n"
      "\n"
      "Examples\n"
      "--------\n"
      ">>> rd.hollow_cylinder(2.0, 1.0, 3.0, mass=4.0).inertia_com.diagonal().round(12)\n"
      "array([ 8.,  8., 10.])\n"
      ">>> rd.hollow_cylinder(1.0, 0.0, 2.0, mass=1.0).is_approx(rd.solid_cylinder(1.0, 2.0, mass=1.0))\n"
      "True");
  def1("thin_rod", &thin_rod, "length",
      "Mass properties of a thin rod along z.\n"
      "\n"
      "I_xx = I_yy = m L^2/12, I_zz = 0 about the centre.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "length : float\n"
      "    Length L [m] along z.\n"
      "mass : float, optional\n"
      "    Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.\n"
      "density : float, optional\n"
      "    Length density [kg/m], finite and > 0: m = density * length.\n"
      "\n"
      "Returns\n"
      "-------\n"
      "SpatialInertia\n"
      "    Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the\n"
      "    shape's frame (rod along z).\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    `length` not finite and > 0;\n"
      "    not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names\n"
      "    the argument).\n"
      "TypeError\n"
      "    An argument that is not a real number.\n"
      "\n"
      "See Also\n"
      "--------\n"
      "solid_cylinder, SpatialInertia.transformed\n"
      "\n"
      "Examples\n"
      "--------\n"
      ">>> rd.thin_rod(2.0, mass=3.0).inertia_com.diagonal()  # m L^2/12\n"
      "array([1., 1., 0.])");
  def1("thin_disk", &thin_disk, "radius",
      "Mass properties of a thin circular disk in the xy plane.\n"
      "\n"
      "I_xx = I_yy = m r^2/4, I_zz = m r^2/2 about the centre.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "radius : float\n"
      "    Radius r [m].\n"
      "mass : float, optional\n"
      "    Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.\n"
      "density : float, optional\n"
      "    Area density [kg/m^2], finite and > 0: m = density * area.\n"
      "\n"
      "Returns\n"
      "-------\n"
      "SpatialInertia\n"
      "    Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the\n"
      "    shape's frame (disk in the xy plane).\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    `radius` not finite and > 0;\n"
      "    not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names\n"
      "    the argument).\n"
      "TypeError\n"
      "    An argument that is not a real number.\n"
      "\n"
      "See Also\n"
      "--------\n"
      "solid_cylinder, thin_plate, SpatialInertia.transformed\n"
      "\n"
      "Examples\n"
      "--------\n"
      "Perpendicular-axis theorem, I_zz = I_xx + I_yy:\n"
      "\n"
      ">>> rd.thin_disk(2.0, mass=1.0).inertia_com.diagonal()\n"
      "array([1., 1., 2.])");
  def2("thin_plate", &thin_plate, "size_x", "size_y",
       "Mass properties of a thin rectangular plate in the xy plane.\n"
       "\n"
       "Edges (a, b) along x, y: I = m/12 diag(b^2, a^2, a^2 + b^2) about the centre.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "size_x : float\n"
       "    Edge a [m] along x.\n"
       "size_y : float\n"
       "    Edge b [m] along y.\n"
       "mass : float, optional\n"
       "    Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.\n"
       "density : float, optional\n"
       "    Area density [kg/m^2], finite and > 0: m = density * area.\n"
       "\n"
       "Returns\n"
       "-------\n"
       "SpatialInertia\n"
       "    Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the\n"
       "    shape's frame (plate in the xy plane).\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    `size_x` or `size_y` not finite and > 0;\n"
       "    not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names\n"
       "    the argument).\n"
       "TypeError\n"
       "    An argument that is not a real number.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "solid_box, thin_disk, SpatialInertia.transformed\n"
       "\n"
       "Examples\n"
       "--------\n"
       "Perpendicular-axis theorem, I_zz = I_xx + I_yy:\n"
       "\n"
       ">>> rd.thin_plate(1.0, 2.0, mass=12.0).inertia_com.diagonal()\n"
       "array([4., 1., 5.])");
  def2("solid_cone", &solid_cone, "radius", "height",
       "Mass properties of a solid right circular cone, axis z.\n"
       "\n"
       "Apex at z = 3h/4 and base at z = -h/4 (centre of mass at the origin):\n"
       "I_zz = 3/10 m r^2, I_xx = I_yy = m (3/20 r^2 + 3/80 h^2).\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "radius : float\n"
       "    Base radius r [m].\n"
       "height : float\n"
       "    Height h [m] along z.\n"
       "mass : float, optional\n"
       "    Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.\n"
       "density : float, optional\n"
       "    Volume density [kg/m^3], finite and > 0: m = density * volume.\n"
       "\n"
       "Returns\n"
       "-------\n"
       "SpatialInertia\n"
       "    Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the\n"
       "    shape's frame (axis z, apex at z = 3h/4).\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    `radius` or `height` not finite and > 0;\n"
       "    not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names\n"
       "    the argument).\n"
       "TypeError\n"
       "    An argument that is not a real number.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "solid_cylinder, SpatialInertia.transformed\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> rd.solid_cone(1.0, 4.0, mass=10.0).inertia_com.diagonal().round(12)\n"
       "array([7.5, 7.5, 3. ])");
  defv("solid_ellipsoid", &solid_ellipsoid, "semi_axes",
       "Mass properties of a solid ellipsoid.\n"
       "\n"
       "Semi-axes (a, b, c) along x, y, z: I = m/5 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2) about the centre.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "semi_axes : array_like, shape (3,)\n"
       "    Semi-axes (a, b, c) [m] along x, y, z.\n"
       "mass : float, optional\n"
       "    Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.\n"
       "density : float, optional\n"
       "    Volume density [kg/m^3], finite and > 0: m = density * volume.\n"
       "\n"
       "Returns\n"
       "-------\n"
       "SpatialInertia\n"
       "    Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the\n"
       "    shape's frame (semi-axes along x, y, z).\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A `semi_axes` entry not finite and > 0;\n"
       "    not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names\n"
       "    the argument).\n"
       "TypeError\n"
       "    An argument that is not a real number.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "solid_sphere, solid_box, SpatialInertia.transformed\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> rd.solid_ellipsoid([1.0, 2.0, 3.0], mass=5.0).inertia_com.diagonal()\n"
       "array([13., 10.,  5.])\n"
       ">>> rd.solid_ellipsoid([1.0, 1.0, 1.0], mass=1.0).is_approx(rd.solid_sphere(1.0, mass=1.0))\n"
       "True");
  def2("solid_capsule", &solid_capsule, "radius", "length",
       "Mass properties of a solid capsule along z: a cylinder capped by two hemispheres.\n"
       "\n"
       "Cylinder of radius r and length h, total length h + 2r. With m_c = rho pi r^2 h and m_h = rho 2/3 pi r^3\n"
       "(each hemisphere): I_zz = m_c r^2/2 + 4/5 m_h r^2,\n"
       "I_xx = I_yy = m_c (h^2/12 + r^2/4) + 2 m_h (2/5 r^2 + h^2/4 + 3/8 h r). A given mass is split in the\n"
       "same proportions.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "radius : float\n"
       "    Radius r [m] of the cylinder and the caps, > 0.\n"
       "length : float\n"
       "    Length h [m] of the cylinder along z, finite and >= 0.\n"
       "mass : float, optional\n"
       "    Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.\n"
       "density : float, optional\n"
       "    Volume density [kg/m^3], finite and > 0: m = density * volume.\n"
       "\n"
       "Returns\n"
       "-------\n"
       "SpatialInertia\n"
       "    Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the\n"
       "    shape's frame (axis z).\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    `radius` not finite and > 0, or `length` not finite and >= 0;\n"
       "    not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names\n"
       "    the argument).\n"
       "TypeError\n"
       "    An argument that is not a real number.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "solid_cylinder, solid_sphere, SpatialInertia.transformed\n"
       "\n"
       "Examples\n"
       "--------\n"
       "With a cylinder of length 0 it is a sphere:\n"
       "\n"
       ">>> rd.solid_capsule(1.0, 0.0, mass=1.0).is_approx(rd.solid_sphere(1.0, mass=1.0))\n"
       "True");
  m.def(
      "solid_tetrahedron",
      [md](py::handle vertices, py::handle mass, py::handle density) {
        const py_io::Stack s = py_io::as_stack(vertices, "vertices", {4, 3});
        if (s.stacked) throw py::value_error("vertices: expected shape (4, 3), got (" + std::to_string(s.n) + ", 4, 3)");
        const double* p = s.array.data();
        const auto v = [p](int i) { return Eigen::Vector3d(p[3 * i], p[3 * i + 1], p[3 * i + 2]); };
        return solid_tetrahedron(v(0), v(1), v(2), v(3), md(mass, density));
      },
      "vertices"_a, py::kw_only(), "mass"_a = py::none(), "density"_a = py::none(),
      "Mass properties of a solid tetrahedron given by its vertices.\n"
      "\n"
      "The centre of mass is the mean of the vertices; the inertia comes from the exact second moment\n"
      "integral x x^T dV = V/20 (sum v_i v_i^T + s s^T), s = sum v_i. Expressed in the frame of the vertices.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "vertices : array_like, shape (4, 3)\n"
      "    The four vertices [m], any order, in any frame A.\n"
      "mass : float, optional\n"
      "    Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.\n"
      "density : float, optional\n"
      "    Volume density [kg/m^3], finite and > 0: m = density * volume.\n"
      "\n"
      "Returns\n"
      "-------\n"
      "SpatialInertia\n"
      "    Mass [kg], centre of mass [m] and inertia_com [kg m^2] about it, expressed in A.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    `vertices` not of shape (4, 3), not finite or of zero volume; not exactly one of `mass` and\n"
      "    `density`, or that one not finite and > 0 (the message names the argument).\n"
      "\n"
      "See Also\n"
      "--------\n"
      "solid_mesh, from_point_masses\n"
      "\n"
      "Examples\n"
      "--------\n"
      "The corner tetrahedron has volume 1/6 m^3 and its centre of mass at (1/4, 1/4, 1/4):\n"
      "\n"
      ">>> tet = rd.solid_tetrahedron([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], density=6.0)\n"
      ">>> f\"{tet.mass:.12f}\", tet.com\n"
      "('1.000000000000', array([0.25, 0.25, 0.25]))");
  m.def(
      "from_point_masses",
      [](py::handle masses, py::handle positions) {
        const Array mv = py_io::as_array(masses, "masses");
        if (mv.ndim() != 1) {
          throw py::value_error("masses: expected shape (n,), got an array with " + std::to_string(mv.ndim()) +
                                " dimensions");
        }
        const Eigen::VectorXd mvec = Eigen::Map<const Eigen::VectorXd>(mv.data(), mv.size());
        return from_point_masses(mvec, as_points(positions, "positions"));
      },
      "masses"_a, "positions"_a,
      "Mass properties of a set of point masses.\n"
      "\n"
      "m = sum m_i, c = sum m_i p_i / m, I_C = sum m_i (|r_i|^2 1 - r_i r_i^T) with r_i = p_i - c\n"
      "(\"Rigid body kinematics and dynamics\" notes, eqs. (4.53)-(4.54)).\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "masses : array_like, shape (n,)\n"
      "    Masses m_i [kg], finite and >= 0, summing to > 0.\n"
      "positions : array_like, shape (n, 3)\n"
      "    Positions p_i [m], in any frame A; one row per mass.\n"
      "\n"
      "Returns\n"
      "-------\n"
      "SpatialInertia\n"
      "    Total mass [kg], centre of mass [m] and inertia_com [kg m^2] about it, expressed in A.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    Shapes that do not match, a mass that is negative or not finite (masses[i] named), masses summing\n"
      "    to 0, or positions not finite.\n"
      "\n"
      "See Also\n"
      "--------\n"
      "point_inertia, symmetry_planes, SpatialInertia.point_mass\n"
      "\n"
      "Examples\n"
      "--------\n"
      "A dumbbell of two 1 kg masses 2 m apart: I = 2 m d^2 = 2 kg m^2 about the axes across it:\n"
      "\n"
      ">>> body = rd.from_point_masses([1.0, 1.0], [[-1.0, 0, 0], [1.0, 0, 0]])\n"
      ">>> body.mass, body.com, body.inertia_com.diagonal()\n"
      "(2.0, array([0., 0., 0.]), array([0., 2., 2.]))");
}

// Symmetry planes as a list of (normal (3,), point (3,)) tuples.
py::list planes_to_list(const std::vector<SymmetryPlane>& planes) {
  py::list out;
  for (const SymmetryPlane& p : planes) out.append(py::make_tuple(py_io::to_array(p.normal), py_io::to_array(p.point)));
  return out;
}

void bind_symmetry(py::module_& m) {
  m.def(
      "symmetry_planes",
      [](py::handle masses, py::handle positions, py::handle tolerance_arg) {
        const double tolerance = as_tolerance(tolerance_arg, "tolerance");
        const Array mv = py_io::as_array(masses, "masses");
        if (mv.ndim() != 1) {
          throw py::value_error("masses: expected shape (n,), got an array with " + std::to_string(mv.ndim()) +
                                " dimensions");
        }
        const Eigen::VectorXd mvec = Eigen::Map<const Eigen::VectorXd>(mv.data(), mv.size());
        const PointRows p = as_points(positions, "positions");
        std::vector<SymmetryPlane> planes;
        {
          py::gil_scoped_release release;
          planes = symmetry_planes(mvec, p, tolerance);
        }
        return planes_to_list(planes);
      },
      "masses"_a, "positions"_a, "tolerance"_a = symmetry_tolerance,
      "Planes of symmetry of point masses (Craig, \"Plane of Symmetry\").\n"
      "\n"
      "A plane qualifies when its reflection maps every point onto a point of equal mass, within\n"
      "tolerance * L [m] (L the largest distance from the centre of mass to a point) and tolerance * mass.\n"
      "Candidates: the principal axes, and when principal moments coincide, normals built from the points;\n"
      "for such degenerate bodies (cube, regular tetrahedron) the planes found among them, not a proof of\n"
      "none else.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "masses : array_like, shape (n,)\n"
      "    Masses [kg], > 0.\n"
      "positions : array_like, shape (n, 3)\n"
      "    Positions [m], in any frame A.\n"
      "tolerance : float, default 1e-9\n"
      "    Relative tolerance, >= 0.\n"
      "\n"
      "Returns\n"
      "-------\n"
      "list of tuple (ndarray, ndarray)\n"
      "    One (normal, point) per plane, in A: normal, shape (3,), unit, its largest-magnitude component\n"
      "    positive; point, shape (3,) [m], the centre of mass.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    Shapes that do not match, bad masses or a negative tolerance (the message names it).\n"
      "\n"
      "See Also\n"
      "--------\n"
      "mesh_symmetry_planes, SpatialInertia.admits_symmetry_plane\n"
      "\n"
      "Examples\n"
      "--------\n"
      "A dumbbell along x is symmetric in the three coordinate planes through its centre:\n"
      "\n"
      ">>> planes = rd.symmetry_planes([1.0, 1.0], [[-1.0, 0, 0], [1.0, 0, 0]])\n"
      ">>> [normal for normal, point in planes]\n"
      "[array([1., 0., 0.]), array([0., 1., 0.]), array([0., 0., 1.])]");
  m.def(
      "mesh_symmetry_planes",
      [](py::handle vertices, py::handle faces, py::handle tolerance_arg, py::handle weld_tolerance) {
        const double tolerance = as_tolerance(tolerance_arg, "tolerance");
        const PointRows v = as_points(vertices, "vertices");
        const MeshFaces f = as_faces(faces);
        const std::optional<double> weld = as_weld_tolerance(weld_tolerance);
        std::vector<SymmetryPlane> planes;
        {
          py::gil_scoped_release release;
          planes = mesh_symmetry_planes(v, f, tolerance, weld);
        }
        return planes_to_list(planes);
      },
      "vertices"_a, "faces"_a, "tolerance"_a = symmetry_tolerance, py::kw_only(), "weld_tolerance"_a = py::none(),
      "Planes of symmetry of the uniform solid bounded by a closed, outward-oriented mesh.\n"
      "\n"
      "The planes of the solid, whatever its triangulation: a plane qualifies when its reflection maps the\n"
      "solid's oriented boundary onto itself (each reflected face covered by faces in the same plane and facing\n"
      "the same way, up to a strip of width tolerance * L along its edges, L the largest distance from the\n"
      "centre of mass to a vertex [m]; normals within tolerance). A faceted cylinder or capsule of s sections\n"
      "has the s planes through its axis and the plane normal to it, not the smooth solid's continuum.\n"
      "Candidates as in symmetry_planes. The mesh is welded first as in solid_mesh.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "vertices : array_like, shape (n, 3)\n"
      "    Vertex positions [m], in any frame A.\n"
      "faces : array_like of int, shape (f, 3)\n"
      "    Vertex indices of each triangle, counter-clockwise seen from outside.\n"
      "tolerance : float, default 1e-9\n"
      "    Relative tolerance, >= 0.\n"
      "weld_tolerance : float or None, default None\n"
      "    Weld distance [m] (None: 1e-8 x the bounding-box diagonal; 0: off).\n"
      "\n"
      "Returns\n"
      "-------\n"
      "list of tuple (ndarray, ndarray)\n"
      "    One (normal, point) per plane, in A: normal, shape (3,), unit, its largest-magnitude component\n"
      "    positive; point, shape (3,) [m], the solid's centre of mass.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    A bad mesh or tolerance (the message names the argument).\n"
      "\n"
      "See Also\n"
      "--------\n"
      "symmetry_planes, solid_mesh\n"
      "\n"
      "Examples\n"
      "--------\n"
      "The corner tetrahedron is symmetric in the three planes x = y, y = z and x = z:\n"
      "\n"
      ">>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]\n"
      ">>> faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]\n"
      ">>> len(rd.mesh_symmetry_planes(v, faces))\n"
      "3");
}

void bind_mesh_and_density(py::module_& m) {
  m.def(
      "require_closed_oriented_mesh",
      [](py::handle faces, py::handle n_vertices) {
        const MeshFaces f = as_faces(faces);
        require_closed_oriented_mesh(f, py_io::as_int(n_vertices, "n_vertices", 0));
      },
      "faces"_a, "n_vertices"_a,
      "Check that triangles form a closed, consistently oriented mesh.\n"
      "\n"
      "Every edge must be shared by exactly two faces, traversed once in each direction.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "faces : array_like of int, shape (f, 3)\n"
      "    Vertex indices of each triangle.\n"
      "n_vertices : int\n"
      "    Number of vertices n, >= 0; indices must lie in [0, n).\n"
      "\n"
      "Returns\n"
      "-------\n"
      "None\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    No faces, an index outside [0, n), a face repeating a vertex, an open edge or a misoriented edge\n"
      "    (the message names the face and the edge).\n"
      "\n"
      "See Also\n"
      "--------\n"
      "solid_mesh, weld_vertices\n"
      "\n"
      "Examples\n"
      "--------\n"
      ">>> faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]\n"
      ">>> rd.require_closed_oriented_mesh(faces, 4)\n"
      ">>> rd.require_closed_oriented_mesh(faces[:3], 4)\n"
      "Traceback (most recent call last):\n"
      "    ...\n"
      "ValueError: faces: expected a closed mesh (every edge shared by exactly two faces), got edge (2, 1) ...");
  m.def(
      "mesh_volume",
      [](py::handle vertices, py::handle faces) {
        return py_io::finite_result(mesh_volume(as_points(vertices, "vertices"), as_faces(faces)), "mesh_volume");
      },
      "vertices"_a, "faces"_a,
          "Signed volume enclosed by a triangle mesh.\n"
          "\n"
          "V = 1/6 sum_f v0 . (v1 x v2) over the faces (divergence theorem): positive for outward-oriented faces\n"
          "(counter-clockwise seen from outside), negative for inward ones. Meaningful for a closed mesh.\n"
          "\n"
          "Parameters\n"
          "----------\n"
          "vertices : array_like, shape (n, 3)\n"
          "    Vertex positions [m].\n"
          "faces : array_like of int, shape (f, 3)\n"
          "    Vertex indices of each triangle.\n"
          "\n"
          "Returns\n"
          "-------\n"
          "float\n"
          "    Signed volume [m^3].\n"
          "\n"
          "Raises\n"
          "------\n"
          "ValueError\n"
          "    A shape that does not match or an index outside [0, n) (the message names it).\n"
          "TypeError\n"
          "    `faces` not of an integer dtype.\n"
          "\n"
          "See Also\n"
          "--------\n"
          "solid_mesh, require_closed_oriented_mesh\n"
          "\n"
          "Examples\n"
          "--------\n"
          "The corner tetrahedron has volume 1/6 m^3; turning its faces inside out flips the sign:\n"
          "\n"
          ">>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]\n"
          ">>> faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]\n"
          ">>> f\"{rd.mesh_volume(v, faces):.12f}\"\n"
          "'0.166666666667'\n"
          ">>> f\"{rd.mesh_volume(v, [f[::-1] for f in faces]):.12f}\"\n"
          "'-0.166666666667'");
  m.def(
      "solid_mesh",
      [](py::handle vertices, py::handle faces, py::handle mass, py::handle density, py::handle weld_tolerance) {
        return mesh_body(&solid_mesh, "solid_mesh", vertices, faces, mass, density, weld_tolerance);
      },
      "vertices"_a, "faces"_a, py::kw_only(), "mass"_a = py::none(), "density"_a = py::none(),
      "weld_tolerance"_a = py::none(),
      "Solid bounded by a closed, outward-oriented triangle mesh: vertices (n, 3) [m], faces (f, 3),\n"
      "exact (divergence theorem). Vertices closer than weld_tolerance [m] are first welded into one, as\n"
      "trimesh does on load (None: 1e-8 x the bounding-box diagonal; 0: off), faces left degenerate dropped,\n"
      "and a MeshWeldWarning says how many. ValueError naming the first open or misoriented edge (input\n"
      "indices), or an inward orientation. Give exactly one of mass= [kg] or density= [kg/m^3].\n"
      "(rigiddyn.solid_mesh also accepts a trimesh object.)");
  m.def(
      "mesh_shell",
      [](py::handle vertices, py::handle faces, py::handle mass, py::handle density, py::handle weld_tolerance) {
        return mesh_body(&mesh_shell, "mesh_shell", vertices, faces, mass, density, weld_tolerance);
      },
      "vertices"_a, "faces"_a, py::kw_only(), "mass"_a = py::none(), "density"_a = py::none(),
      "weld_tolerance"_a = py::none(),
      "Thin shell made of the faces (any orientation, need not be closed): vertices (n, 3) [m], faces\n"
      "(f, 3), welded as in solid_mesh (weld_tolerance). Give exactly one of mass= [kg] or density= [kg/m^2].");
  mesh_weld_warning = PyErr_NewExceptionWithDoc(
      "rigiddyn._core.MeshWeldWarning",
      "Warned by solid_mesh and mesh_shell when welding merged vertices or dropped faces (a UserWarning;\n"
      "filter it with warnings.filterwarnings, or weld with weld_vertices first).",
      PyExc_UserWarning, nullptr);
  if (!mesh_weld_warning) throw py::error_already_set();
  m.attr("MeshWeldWarning") = mesh_weld_warning;
  py::class_<WeldedMesh>(m, "WeldedMesh",
      "A mesh after weld_vertices, with what the weld changed.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "vertices, faces, tolerance\n"
      "    As weld_vertices (there is no constructor from Python; it pickles).\n"
      "\n"
      "See Also\n"
      "--------\n"
      "weld_vertices, solid_mesh\n"
      "\n"
      "Examples\n"
      "--------\n"
      ">>> w = rd.weld_vertices([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]],\n"
      "...                      [[0, 1, 2], [3, 4, 5]])\n"
      ">>> w.vertex_index, w.dropped_faces\n"
      "(array([0, 1, 2, 4]), 0)")
      .def_property_readonly("vertices", [](const WeldedMesh& w) { return read_only(w.vertices); },
                             "Kept vertices (n', 3) [m] (each cluster's lowest-indexed), in input order and frame,\n"
                             "read-only.")
      .def_property_readonly("faces", [](const WeldedMesh& w) { return index_array(w.faces, {w.faces.rows(), 3}); },
                             "Non-degenerate faces (f', 3) int64, in input order, indexing vertices.")
      .def_property_readonly(
          "vertex_index",
          [](const WeldedMesh& w) { return index_array(w.vertex_index, {static_cast<py::ssize_t>(w.vertex_index.size())}); },
          "Input index (n',) int64 of each kept vertex.")
      .def_property_readonly(
          "face_index",
          [](const WeldedMesh& w) { return index_array(w.face_index, {static_cast<py::ssize_t>(w.face_index.size())}); },
          "Input index (f',) int64 of each kept face.")
      .def_property_readonly("welded_vertices", [](const WeldedMesh& w) { return w.report.welded_vertices; },
                             "Number of input vertices merged into another.")
      .def_property_readonly("dropped_faces", [](const WeldedMesh& w) { return w.report.dropped_faces; },
                             "Number of faces dropped for repeating a vertex after welding.")
      .def_property_readonly("tolerance", [](const WeldedMesh& w) { return w.report.tolerance; },
                             "Weld tolerance used [m].")
      .def("__repr__", [](const WeldedMesh& w) {
        return "WeldedMesh(" + std::to_string(w.vertices.rows()) + " vertices, " + std::to_string(w.faces.rows()) +
               " faces, welded_vertices=" + std::to_string(w.report.welded_vertices) +
               ", dropped_faces=" + std::to_string(w.report.dropped_faces) +
               ", tolerance=" + py::repr(py::float_(w.report.tolerance)).cast<std::string>() + ")";
      })
      .def(py::pickle(
          [](const WeldedMesh& w) {
            return py::make_tuple(read_only(w.vertices), index_array(w.faces, {w.faces.rows(), 3}),
                                  index_array(w.vertex_index, {static_cast<py::ssize_t>(w.vertex_index.size())}),
                                  index_array(w.face_index, {static_cast<py::ssize_t>(w.face_index.size())}),
                                  w.report.welded_vertices, w.report.dropped_faces, w.report.tolerance);
          },
          [](const py::tuple& state) {
            if (state.size() != 7) py_io::throw_value_error("state", "a tuple of 7 items (WeldedMesh.__getstate__)", py_io::describe(state));
            const auto indices = [](py::handle obj, const char* name) {
              const py_io::IndexArray a = py_io::as_index_array(obj, name);
              return std::vector<Eigen::Index>(a.data(), a.data() + a.size());
            };
            WeldedMesh w;
            w.vertices = as_points(state[0], "vertices");
            w.faces = as_faces(state[1]);
            w.vertex_index = indices(state[2], "vertex_index");
            w.face_index = indices(state[3], "face_index");
            w.report = {state[4].cast<Eigen::Index>(), state[5].cast<Eigen::Index>(), state[6].cast<double>()};
            return w;
          }));
  m.def(
      "weld_vertices",
      [](py::handle vertices, py::handle faces, py::handle tolerance_arg) {
        const PointRows v = as_points(vertices, "vertices");
        const MeshFaces f = as_faces(faces);
        const std::optional<double> tolerance = py_io::as_optional_scalar(tolerance_arg, "tolerance");
        py::gil_scoped_release release;
        return weld_vertices(v, f, tolerance ? *tolerance : default_weld_tolerance(v));
      },
      "vertices"_a, "faces"_a, "tolerance"_a = py::none(),
      "Merge vertices closer than a tolerance, as solid_mesh does before integrating.\n"
      "\n"
      "Clusters of vertices within `tolerance` of one another (grid hashing, O(n log n)) keep their\n"
      "lowest-indexed vertex; faces repeating a vertex afterwards are dropped. Warns nothing.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "vertices : array_like, shape (n, 3)\n"
      "    Vertex positions [m], finite.\n"
      "faces : array_like of int, shape (f, 3)\n"
      "    Vertex indices of each triangle, three distinct ones per face.\n"
      "tolerance : float or None, default None\n"
      "    Weld distance [m], finite and >= 0 (None: 1e-8 x the bounding-box diagonal).\n"
      "\n"
      "Returns\n"
      "-------\n"
      "WeldedMesh\n"
      "    The kept vertices and faces, their input indices and what the weld changed.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    Vertices not finite, a negative tolerance, an index outside [0, n) or a face repeating an index\n"
      "    (the message names it).\n"
      "\n"
      "See Also\n"
      "--------\n"
      "solid_mesh, mesh_shell, WeldedMesh\n"
      "\n"
      "Examples\n"
      "--------\n"
      "Two triangles of a square saved as in an STL file, each with its own copy of the shared vertices:\n"
      "\n"
      ">>> w = rd.weld_vertices([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]],\n"
      "...                      [[0, 1, 2], [3, 4, 5]])\n"
      ">>> w.welded_vertices, w.faces\n"
      "(2, array([[0, 1, 2],\n"
      "       [1, 3, 2]]))");

  bind_symmetry(m);

  py::class_<DensityIntegral>(m, "DensityIntegral",
               "Result of a density quadrature with its error estimate.\n"
               "\n"
               "All in the frame A of the points rho was evaluated at. == compares every field exactly; it pickles.\n"
               "\n"
               "Parameters\n"
               "----------\n"
               "inertia : SpatialInertia\n"
               "    Result of the higher-order rule, in A.\n"
               "mass_error : float\n"
               "    |m_high - m_low| [kg].\n"
               "com_error : float\n"
               "    |c_high - c_low| [m].\n"
               "inertia_error : float\n"
               "    ||I_C,high - I_C,low||_F [kg m^2], inertias about the centre of mass.\n"
               "evaluations : int\n"
               "    Points at which rho was evaluated, both rules together, >= 0.\n"
               "\n"
               "See Also\n"
               "--------\n"
               "integrate_density_over_box, integrate_density_over_mesh\n"
               "\n"
               "Examples\n"
               "--------\n"
               ">>> d = rd.integrate_density_over_box(lambda p: np.full(len(p), 1000.0), [0, 0, 0], [1, 1, 1])\n"
               ">>> f\"{d.inertia.mass:.9f}\", f\"{d.inertia.inertia_com[0, 0]:.9f}\", d.evaluations  # m a^2 / 6\n"
               "('1000.000000000', '166.666666667', 15552)")
      .def(py::init([](py::handle inertia, py::handle mass_error, py::handle com_error, py::handle inertia_error,
                       py::handle evaluations) {
             return DensityIntegral{as_inertia(inertia, "inertia"), py_io::as_scalar(mass_error, "mass_error"),
                                    py_io::as_scalar(com_error, "com_error"),
                                    py_io::as_scalar(inertia_error, "inertia_error"),
                                    static_cast<Eigen::Index>(py_io::as_int(evaluations, "evaluations", 0))};
           }),
           "inertia"_a, "mass_error"_a, "com_error"_a, "inertia_error"_a, "evaluations"_a,
           "From its fields (as the attributes).")
      .def_readonly("inertia", &DensityIntegral::inertia,
                    "SpatialInertia from the higher-order rule (mass [kg], centre of mass [m] and inertia about it\n"
                    "[kg m^2], in the frame of the points).")
      .def_readonly("mass_error", &DensityIntegral::mass_error, "Mass error estimate |m_high - m_low| [kg].")
      .def_readonly("com_error", &DensityIntegral::com_error,
                    "Centre-of-mass error estimate |c_high - c_low| [m], in the frame of the points.")
      .def_readonly("inertia_error", &DensityIntegral::inertia_error,
                    "Inertia error estimate ||I_C,high - I_C,low||_F [kg m^2], inertias about the centre of mass.")
      .def_readonly("evaluations", &DensityIntegral::evaluations,
                    "Number of points at which rho was evaluated (both rules).")
      .def(
          "__eq__",
          [](const DensityIntegral& d, py::handle other) {
            return equal_or_not_implemented(d, other, [](const DensityIntegral& a, const DensityIntegral& b) {
              return py::cast(a.inertia).equal(py::cast(b.inertia)) && a.mass_error == b.mass_error &&
                     a.com_error == b.com_error && a.inertia_error == b.inertia_error && a.evaluations == b.evaluations;
            });
          },
          py::is_operator(), "Exact equality of every field.")
      .def("__repr__",
           [](const DensityIntegral& d) {
             return repr_call("DensityIntegral", {{"inertia", py::cast(d.inertia)},
                                                  {"mass_error", py::float_(d.mass_error)},
                                                  {"com_error", py::float_(d.com_error)},
                                                  {"inertia_error", py::float_(d.inertia_error)},
                                                  {"evaluations", py::int_(d.evaluations)}});
           })
      .def(py::pickle(
          [](const DensityIntegral& d) {
            return py::make_tuple(d.inertia, d.mass_error, d.com_error, d.inertia_error, d.evaluations);
          },
          [](const py::tuple& state) {
            const py::tuple s = pickled_state(state, 5, "DensityIntegral");
            return DensityIntegral{s[0].cast<SpatialInertia>(), s[1].cast<double>(), s[2].cast<double>(),
                                   s[3].cast<double>(), s[4].cast<Eigen::Index>()};
          }));
  m.def(
      "integrate_density_over_box",
      [](py::handle rho_arg, py::handle lower, py::handle upper, py::handle order_arg, py::handle subdivisions_arg) {
        const py::function rho = as_density(rho_arg);
        const Eigen::Vector3d lo = py_io::as_vector3(lower, "lower"), hi = py_io::as_vector3(upper, "upper");
        const int order = as_order(order_arg);
        const int subdivisions = static_cast<int>(py_io::as_int(subdivisions_arg, "subdivisions", 1, 64));
        const QuadratureRule low = box_quadrature(lo, hi, order, subdivisions);
        const QuadratureRule high = box_quadrature(lo, hi, 2 * order, subdivisions);
        return compare_density_integrals(low, evaluate_vectorized(rho, low), high, evaluate_vectorized(rho, high));
      },
      "rho"_a, "lower"_a, "upper"_a, "order"_a = 6, "subdivisions"_a = 2,
      "Mass properties of a variable density over a box, by Gauss-Legendre quadrature.\n"
      "\n"
      "m = int rho dV, c = int rho x dV / m, I_C = int rho (|r|^2 1 - r r^T) dV with r = x - c\n"
      "(\"Rigid body kinematics and dynamics\" notes, eqs. (4.55), (4.56), (4.70)), each by the tensor\n"
      "Gauss-Legendre rule of `order` and of 2 * order points per axis of each of subdivisions^3 cells; the\n"
      "differences between the two are the error estimates.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "rho : callable\n"
      "    ``rho(points)``: points, ndarray, shape (n, 3) [m] -> densities, shape (n,) [kg/m^3], finite and\n"
      "    >= 0. Called once per rule.\n"
      "lower, upper : array_like, shape (3,)\n"
      "    Opposite corners [m] of the box, upper > lower componentwise, in any frame A.\n"
      "order : int, default 6\n"
      "    Points per cell axis of the lower rule, in [1, 32].\n"
      "subdivisions : int, default 2\n"
      "    Cells per box edge, in [1, 64].\n"
      "\n"
      "Returns\n"
      "-------\n"
      "DensityIntegral\n"
      "    The higher-order SpatialInertia (in A) and the mass, com and inertia error estimates.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    A bad box, order or subdivisions; rho returning the wrong number of values, a negative or\n"
      "    non-finite one, or a zero total mass (the message names it).\n"
      "TypeError\n"
      "    `rho` not callable.\n"
      "\n"
      "See Also\n"
      "--------\n"
      "integrate_density_over_mesh, solid_box\n"
      "\n"
      "Examples\n"
      "--------\n"
      "Density 1 + x [kg/m^3] over the unit cube: m = 3/2 kg, c_x = (1/2 + 1/3) / m = 5/9 m:\n"
      "\n"
      ">>> d = rd.integrate_density_over_box(lambda p: 1.0 + p[:, 0], [0, 0, 0], [1, 1, 1])\n"
      ">>> f\"{d.inertia.mass:.12f}\", f\"{d.inertia.com[0]:.12f}\", d.mass_error < 1e-12\n"
      "('1.500000000000', '0.555555555556', True)");
  m.def(
      "integrate_density_over_mesh",
      [](py::handle rho_arg, py::handle vertices, py::handle faces, py::handle order_arg) {
        const py::function rho = as_density(rho_arg);
        const PointRows v = as_points(vertices, "vertices");
        const MeshFaces f = as_faces(faces);
        const int order = as_order(order_arg);
        const QuadratureRule low = mesh_quadrature(v, f, order);
        const QuadratureRule high = mesh_quadrature(v, f, 2 * order);
        return compare_density_integrals(low, evaluate_vectorized(rho, low), high, evaluate_vectorized(rho, high));
      },
      "rho"_a, "vertices"_a, "faces"_a, "order"_a = 4,
      "Mass properties of a variable density over the solid bounded by a closed mesh.\n"
      "\n"
      "The solid is split into signed tetrahedra (one per face), each integrated by a\n"
      "collapsed Gauss-Legendre rule of order^3 and of (2 order)^3 points; the differences between the two\n"
      "rules are the error estimates. Integrals as integrate_density_over_box.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "rho : callable\n"
      "    ``rho(points)``: points, ndarray, shape (n, 3) [m] -> densities, shape (n,) [kg/m^3], finite and\n"
      "    >= 0; must be defined on the mesh's convex hull.\n"
      "vertices : array_like, shape (n, 3)\n"
      "    Vertex positions [m], in any frame A.\n"
      "faces : array_like of int, shape (f, 3)\n"
      "    Closed, outward-oriented triangles (counter-clockwise seen from outside).\n"
      "order : int, default 4\n"
      "    Points per axis of the lower rule, in [1, 32].\n"
      "\n"
      "Returns\n"
      "-------\n"
      "DensityIntegral\n"
      "    The higher-order SpatialInertia (in A) and the mass, com and inertia error estimates.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    An open, misoriented or inward mesh, a bad order, or rho values as in integrate_density_over_box\n"
      "    (the message names it).\n"
      "TypeError\n"
      "    `rho` not callable, or `faces` not of an integer dtype.\n"
      "\n"
      "See Also\n"
      "--------\n"
      "integrate_density_over_box, solid_mesh\n"
      "\n"
      "Examples\n"
      "--------\n"
      "A uniform density gives the exact solid:\n"
      "\n"
      ">>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]\n"
      ">>> faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]\n"
      ">>> d = rd.integrate_density_over_mesh(lambda p: np.full(len(p), 6.0), v, faces)\n"
      ">>> d.inertia.is_approx(rd.solid_tetrahedron(v, density=6.0)), d.evaluations\n"
      "(True, 2304)");
}

}  // namespace

void bind_inertia(py::module_& m) {
  bind_types(m);
  bind_spatial_inertia(m);
  bind_validity(m);
  bind_primitives(m);
  bind_mesh_and_density(m);
}

}  // namespace rigiddyn::bindings
