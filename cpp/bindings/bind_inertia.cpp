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
  out.attr("flags").attr("writeable") = false;
  return out;
}

InertiaCheck check_arg(py::handle check) {
  return py_io::as_instance<InertiaCheck>(check, "check", "InertiaCheck.physical or InertiaCheck.allow_unrealizable");
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

const char* kCheckDoc =
    "check: InertiaCheck.physical (default: triangle inequality required) or\n"
    "InertiaCheck.allow_unrealizable (opt-in: symmetric PSD only, e.g. I = diag(2, 1, 2/3)).";

// Principal axes as Python sees them: one inertia's (3,) moments and (3,3) axes, or the (n,3) and
// (n,3,3) arrays of a stack, read-only. Unpacks as (moments, axes).
struct PyPrincipalAxes {
  Array moments;
  Array axes;
};

// `value` itself, made read-only (a PrincipalAxes is a value: its arrays are not written to).
Array frozen(Array value) {
  value.attr("flags").attr("writeable") = false;
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
      "Principal moments and axes of a rotational inertia (Craig \"Principal Axes\"), in the frame the\n"
      "inertia is expressed in: moments ascending [kg m^2], axes as columns (column k is the unit axis of\n"
      "moments[k]; right-handed, det +1), so that I = axes @ diag(moments) @ axes.T. For a stack of n\n"
      "inertias, arrays (n, 3) and (n, 3, 3). Unpacks as `moments, axes = principal_axes(I)`.")
      .def(py::init(&make_principal_axes), "moments"_a, "axes"_a,
           "From moments (3,) [kg m^2] and axes (3,3) (or (n,3), (n,3,3)); copied, read-only.")
      .def_readonly("moments", &PyPrincipalAxes::moments, "(3,) or (n, 3) ascending [kg m^2], read-only")
      .def_readonly("axes", &PyPrincipalAxes::axes,
                    "(3,3) or (n,3,3): column k is the unit axis of moments[k], expressed in the inertia's frame;\n"
                    "det +1. Read-only.")
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
                          "What a constructor requires of a rotational inertia: `physical` (symmetric, PSD,\n"
                          "triangle inequality I0 + I1 >= I2 on the principal moments) or `allow_unrealizable`\n"
                          "(symmetric PSD only; a documented opt-in for test problems such as\n"
                          "Hairer-Lubich-Wanner's I = diag(2, 1, 2/3), never the default).")
      .value("physical", InertiaCheck::physical)
      .value("allow_unrealizable", InertiaCheck::allow_unrealizable)
      // reached only when pybind11's int constructor does not match: a TypeError naming `value`
      .def(py::init([](py::handle value) -> InertiaCheck {
             py_io::throw_type_error("value", "an int (0: physical, 1: allow_unrealizable)", value);
           }),
           "value"_a);

  py::class_<InertiaReport>(m, "InertiaReport",
                            "Validity report of (mass, inertia about the centre of mass); see inertia_report.")
      .def_readonly("mass", &InertiaReport::mass, "[kg]")
      .def_readonly("mass_positive", &InertiaReport::mass_positive)
      .def_readonly("finite", &InertiaReport::finite)
      .def_readonly("asymmetry", &InertiaReport::asymmetry, "max |I - I^T| [kg m^2]")
      .def_readonly("symmetric", &InertiaReport::symmetric)
      .def_property_readonly("principal_moments", [](const InertiaReport& r) { return read_only(r.principal_moments); },
                             "(3,) ascending I0 <= I1 <= I2 [kg m^2] of the inertia about the centre of mass")
      .def_property_readonly("triangle_margins", [](const InertiaReport& r) { return read_only(r.triangle_margins); },
                             "(3,) (I1+I2-I0, I0+I2-I1, I0+I1-I2) [kg m^2]; the last is binding")
      .def_readonly("condition_number", &InertiaReport::condition_number, "I2 / I0 (inf when I0 <= 0)")
      .def_readonly("tolerance", &InertiaReport::tolerance,
                    "absolute tolerance of the positive semi-definite and triangle-inequality checks [kg m^2]")
      .def_readonly("positive_semidefinite", &InertiaReport::positive_semidefinite)
      .def_readonly("triangle_inequality", &InertiaReport::triangle_inequality)
      .def_readonly("asymmetry_tolerance", &InertiaReport::asymmetry_tolerance,
                    "largest asymmetry accepted, 1e-12 max |I_ij| [kg m^2]")
      .def(
          "valid", [](const InertiaReport& r, py::handle check) { return r.valid(check_arg(check)); },
          "check"_a = InertiaCheck::physical,
           "True when every check required by `check` passes.")
      .def("summary", &InertiaReport::summary, "One line with the key numbers.")
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
  if (!pairs && !py::isinstance<SpatialInertia>(items[0])) {
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
      "Mass properties of one rigid body: mass m [kg], centre of mass c [m] and rotational inertia about\n"
      "the centre of mass I_C [kg m^2], all expressed in one frame. Constructors check validity\n"
      "(ValueError with the principal moments, triangle margins and condition number).")
      .def(py::init([](py::handle mass, py::handle com, py::handle inertia_com, py::handle check) {
             return SpatialInertia(py_io::as_scalar(mass, "mass"), py_io::as_vector3(com, "com"),
                                   py_io::as_matrix3(inertia_com, "inertia_com"), check_arg(check));
           }),
           "mass"_a, "com"_a, "inertia_com"_a, "check"_a = InertiaCheck::physical,
           (std::string("mass [kg] > 0, com (3,) [m], inertia_com (3,3) [kg m^2] about the centre of mass.\n") +
            kCheckDoc).c_str())
      .def_static(
          "from_inertia_about_point",
          [](py::handle mass, py::handle com, py::handle inertia, py::handle point, py::handle check) {
            return SpatialInertia::from_inertia_about_point(
                py_io::as_scalar(mass, "mass"), py_io::as_vector3(com, "com"),
                py_io::as_matrix3(inertia, "inertia_about_point"), py_io::as_vector3(point, "point"), check_arg(check));
          },
          "mass"_a, "com"_a, "inertia_about_point"_a, "point"_a, "check"_a = InertiaCheck::physical,
          "From the inertia (3,3) [kg m^2] about `point` (3,) [m] (parallel axis, Craig).")
      .def_static(
          "from_inertia_about_origin",
          [](py::handle mass, py::handle com, py::handle inertia, py::handle check) {
            return SpatialInertia::from_inertia_about_origin(py_io::as_scalar(mass, "mass"),
                                                             py_io::as_vector3(com, "com"),
                                                             py_io::as_matrix3(inertia, "inertia_about_origin"),
                                                             check_arg(check));
          },
          "mass"_a, "com"_a, "inertia_about_origin"_a, "check"_a = InertiaCheck::physical,
          "From the inertia (3,3) [kg m^2] about the frame's origin.")
      .def_static(
          "from_matrix",
          [](py::handle matrix, py::handle check) {
            return SpatialInertia::from_matrix(py_io::as_matrix6(matrix, "matrix"), check_arg(check));
          },
          "matrix"_a, "check"_a = InertiaCheck::physical,
          "From the (6,6) spatial inertia about the origin, angular first [[I_O, m hat(c)], [m hat(c)^T, m 1]].")
      .def_static(
          "point_mass",
          [](py::handle mass, py::handle position) {
            return SpatialInertia::point_mass(py_io::as_scalar(mass, "mass"), py_io::as_vector3(position, "position"));
          },
          "mass"_a, "position"_a, "A point mass [kg] at position (3,) [m].")
      .def_property_readonly("mass", &SpatialInertia::mass, "m [kg]")
      .def_property_readonly("com", [](const SpatialInertia& I) { return read_only(I.com()); },
                             "centre of mass (3,) [m], read-only copy")
      .def_property_readonly("inertia_com", [](const SpatialInertia& I) { return read_only(I.inertia_com()); },
                             "rotational inertia about the centre of mass (3,3) [kg m^2], read-only copy")
      .def(
          "inertia_about_point",
          [](const SpatialInertia& I, py::handle point) {
            return py_io::finite_result(I.inertia_about_point(py_io::as_vector3(point, "point")),
                                        "SpatialInertia.inertia_about_point");
          },
          "point"_a, "Inertia (3,3) [kg m^2] about point (3,) [m]: I_C + m (|r|^2 1 - r r^T), r = c - p.")
      .def("inertia_about_origin",
           [](const SpatialInertia& I) { return py_io::finite_result(I.inertia_about_origin(), "SpatialInertia.inertia_about_origin"); },
           "Inertia (3,3) [kg m^2] about the frame's origin.")
      .def("matrix", [](const SpatialInertia& I) { return py_io::finite_result(I.matrix(), "SpatialInertia.matrix"); },
           "(6,6) spatial inertia about the origin, angular first.")
      .def(
          "momentum",
          [](const SpatialInertia& I, py::handle twist) {
            const Force h = I.momentum(py_io::as_finite_spatial<Motion>(twist, "twist", "a Motion"));
            py_io::warn_unless_finite(h.angular.allFinite() && h.linear.allFinite(), "SpatialInertia.momentum",
                                      format_value(h.to_vector().transpose()));
            return h;
          },
          "twist"_a, "Spatial momentum h = I V (Force, moment about the origin) of the twist V = [w; v_O] (Motion).")
      .def(
          "kinetic_energy",
          [](const SpatialInertia& I, py::handle twist) {
            return py_io::finite_result(I.kinetic_energy(py_io::as_finite_spatial<Motion>(twist, "twist", "a Motion")),
                                        "SpatialInertia.kinetic_energy");
          },
          "twist"_a, "T = 1/2 V . I V [J] of the twist (Motion).")
      .def(
          "angular_momentum_about_com",
          [](const SpatialInertia& I, py::handle w) {
            return py_io::finite_result(I.angular_momentum_about_com(py_io::as_vector3(w, "angular_velocity")),
                                        "SpatialInertia.angular_momentum_about_com");
          },
          "angular_velocity"_a, "H_C = I_C w (3,) [kg m^2/s]; w (3,) [rad/s] in the frame.")
      .def(
          "angular_momentum_about_point",
          [](const SpatialInertia& I, py::handle w, py::handle v, py::handle p) {
            return py_io::finite_result(I.angular_momentum_about_point(py_io::as_vector3(w, "angular_velocity"),
                                                                       py_io::as_vector3(v, "com_velocity"),
                                                                       py_io::as_vector3(p, "point")),
                                        "SpatialInertia.angular_momentum_about_point");
          },
          "angular_velocity"_a, "com_velocity"_a, "point"_a,
          "H_P = r_PC x (m v_C) + H_C (3,) [kg m^2/s] (Craig); w [rad/s], v_C [m/s], point [m].")
      .def(
          "rotated",
          [](const SpatialInertia& I, py::handle R) { return checked(I.rotated(py_io::as_matrix3(R, "R_AB")), "SpatialInertia.rotated"); },
          "R_AB"_a,
          "Re-expressed in A: c_A = R_AB c_B, I_C,A = R_AB I_C,B R_AB^T.")
      .def(
          "transformed",
          [](const SpatialInertia& I, py::handle X_AB) {
            return checked(I.transformed(py_io::as_instance<Transform>(X_AB, "X_AB", "a Transform")),
                           "SpatialInertia.transformed");
          },
          "X_AB"_a,
           "Re-expressed in A (Transform X_AB): c_A = R_AB c_B + p_AB, I_C,A = R_AB I_C,B R_AB^T.")
      .def(
          "principal_axes", [](const SpatialInertia& I) { return to_python(I.principal_axes()); },
          "PrincipalAxes of I_C (about the centre of mass, in the frame of expression): moments ascending\n"
          "[kg m^2], axes as columns, right-handed.")
      .def("report", &SpatialInertia::report, "The validity report (InertiaReport).")
      .def(
          "admits_symmetry_plane",
          [](const SpatialInertia& I, py::handle n, py::handle tolerance) {
            return I.admits_symmetry_plane(py_io::as_vector3(n, "normal"), as_tolerance(tolerance, "tolerance"));
          },
          "normal"_a, "tolerance"_a = 1e-9,
          "Whether the plane through the centre of mass with this normal (3,) can be a plane of symmetry\n"
          "(Craig: then the products of inertia with the normal vanish). Necessary, not sufficient.")
      .def(py::self + py::self, "Composite of two bodies expressed in the same frame.")
      .def(py::self - py::self, "This body with the part removed (a hole); ValueError if the rest is invalid.")
      .def(
          "remove",
          [](const SpatialInertia& I, py::handle part, py::handle check) {
            return I.remove(as_inertia(part, "part"), check_arg(check));
          },
          "part"_a, "check"_a = InertiaCheck::physical,
           "This body with `part` removed (a hole), checked as the constructor.")
      .def(
          "is_approx",
          [](const SpatialInertia& I, py::handle other, py::handle prec) {
            return I.is_approx(as_inertia(other, "other"), as_tolerance(prec, "prec"));
          },
          "other"_a, "prec"_a = 1e-12,
          "True when mass, centre of mass and inertia_com agree to `prec` relative to their size (the centre of\n"
          "mass relative to the radius of gyration plus |com|). == compares exactly.")
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
      "Composite body: parts is a list of SpatialInertia (one frame) or of (X_AB, SpatialInertia) pairs,\n"
      "each part expressed in its B and placed in A by the Transform X_AB. Exact.");
  m.def(
      "point_inertia",
      [](py::handle mass, py::handle r) {
        return py_io::finite_result(point_inertia(py_io::as_scalar(mass, "mass"), py_io::as_vector3(r, "r")), "point_inertia");
      },
      "mass"_a, "r"_a, "m (|r|^2 1 - r r^T) (3,3) [kg m^2]: a point mass [kg] > 0 at r (3,) [m] about the origin.");
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
      "Validity report of mass [kg] and inertia_com (3,3) [kg m^2]: principal moments, triangle margins,\n"
      "condition number. Tolerance = inertia_relative_tolerance * max(scale, trace) [kg m^2], where scale is\n"
      "the size of the numbers the inertia was computed from (0: trace only).");
  m.def(
      "nearest_valid_inertia",
      [](py::handle inertia) {
        return py_io::finite_result(nearest_valid_inertia(py_io::as_matrix3(inertia, "inertia")), "nearest_valid_inertia");
      },
      "inertia"_a,
      "Explicit repair: the nearest (Frobenius) matrix (3,3) satisfying the triangle inequality, same\n"
      "principal axes; a valid inertia is returned unchanged. Never applied implicitly.");
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
      "Principal moments and axes of symmetric inertias (3,3) or (n,3,3) [kg m^2] (lower triangles read),\n"
      "about the point and in the frame the inertia is given for. Returns a PrincipalAxes: moments (3,)\n"
      "or (n,3) ascending [kg m^2], axes (3,3) or (n,3,3) with column k the unit axis of moments[k],\n"
      "right-handed, canonical when moments coincide; it unpacks as `moments, axes = principal_axes(I)`.\n"
      "Releases the GIL.");
}

void bind_primitives(py::module_& m) {
  const auto md = [](py::handle mass, py::handle density) { return mass_or_density(mass, density); };
  const char* md_doc = " Give exactly one of mass= [kg] or density=.";
  const auto def1 = [&](const char* name, SpatialInertia (*f)(double, MassOrDensity), const char* arg,
                        const std::string& doc) {
    m.def(
        name,
        [f, md, arg](py::handle x, py::handle mass, py::handle density) {
          return f(py_io::as_scalar(x, arg), md(mass, density));
        },
        py::arg(arg), py::kw_only(), "mass"_a = py::none(), "density"_a = py::none(), (doc + md_doc).c_str());
  };
  const auto def2 = [&](const char* name, SpatialInertia (*f)(double, double, MassOrDensity), const char* a1,
                        const char* a2, const std::string& doc) {
    m.def(
        name,
        [f, md, a1, a2](py::handle x, py::handle y, py::handle mass, py::handle density) {
          return f(py_io::as_scalar(x, a1), py_io::as_scalar(y, a2), md(mass, density));
        },
        py::arg(a1), py::arg(a2), py::kw_only(), "mass"_a = py::none(), "density"_a = py::none(),
        (doc + md_doc).c_str());
  };
  const auto defv = [&](const char* name, SpatialInertia (*f)(const Eigen::Vector3d&, MassOrDensity), const char* arg,
                        const std::string& doc) {
    m.def(
        name,
        [f, md, arg](py::handle v, py::handle mass, py::handle density) {
          return f(py_io::as_vector3(v, arg), md(mass, density));
        },
        py::arg(arg), py::kw_only(), "mass"_a = py::none(), "density"_a = py::none(), (doc + md_doc).c_str());
  };
  def1("solid_sphere", &solid_sphere, "radius", "Solid sphere, radius [m]: I = 2/5 m r^2 1. Density [kg/m^3].");
  def2("hollow_sphere", &hollow_sphere, "outer_radius", "inner_radius",
       "Thick spherical shell [m]: I = 2/5 m (R^5 - r^5)/(R^3 - r^3) 1. Density [kg/m^3].");
  def1("spherical_shell", &spherical_shell, "radius", "Thin spherical surface [m]: I = 2/3 m r^2 1. Density [kg/m^2].");
  defv("solid_box", &solid_box, "size", "Solid box, edges size (3,) [m] along x, y, z. Density [kg/m^3].");
  defv("box_shell", &box_shell, "size", "Closed thin-walled box (six faces), edges (3,) [m]. Density [kg/m^2].");
  def2("solid_cylinder", &solid_cylinder, "radius", "height",
       "Solid cylinder, axis z: I_zz = m r^2/2, I_xx = m (3 r^2 + h^2)/12. Density [kg/m^3].");
  m.def(
      "hollow_cylinder",
      [md](py::handle R, py::handle r, py::handle h, py::handle mass, py::handle density) {
        return hollow_cylinder(py_io::as_scalar(R, "outer_radius"), py_io::as_scalar(r, "inner_radius"),
                               py_io::as_scalar(h, "height"), md(mass, density));
      },
      "outer_radius"_a, "inner_radius"_a, "height"_a, py::kw_only(), "mass"_a = py::none(), "density"_a = py::none(),
      "Thick tube, axis z: I_zz = m (R^2 + r^2)/2, I_xx = m (3 (R^2 + r^2) + h^2)/12. Density [kg/m^3]. Give\n"
      "exactly one of mass= [kg] or density=.");
  def1("thin_rod", &thin_rod, "length", "Thin rod along z: I_xx = I_yy = m L^2/12. Density [kg/m].");
  def1("thin_disk", &thin_disk, "radius", "Thin disk in the xy plane: I = m r^2 diag(1/4, 1/4, 1/2). Density [kg/m^2].");
  def2("thin_plate", &thin_plate, "size_x", "size_y",
       "Thin plate in the xy plane: I = m/12 diag(b^2, a^2, a^2 + b^2). Density [kg/m^2].");
  def2("solid_cone", &solid_cone, "radius", "height",
       "Solid cone, axis z, apex at z = 3h/4, base at z = -h/4 (com at origin): I_zz = 3/10 m r^2,\n"
       "I_xx = m (3/20 r^2 + 3/80 h^2). Density [kg/m^3].");
  defv("solid_ellipsoid", &solid_ellipsoid, "semi_axes",
       "Solid ellipsoid, semi-axes (3,) [m]: I = m/5 diag(b^2+c^2, a^2+c^2, a^2+b^2). Density [kg/m^3].");
  def2("solid_capsule", &solid_capsule, "radius", "length",
       "Solid capsule along z: cylinder of the given length [m] plus two hemispherical caps of radius [m].\n"
       "Density [kg/m^3].");
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
      "Solid tetrahedron with vertices (4, 3) [m], expressed in their frame. Density [kg/m^3]. Give exactly\n"
      "one of mass= [kg] or density=.");
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
      "Point masses (n,) [kg] >= 0 at positions (n, 3) [m] (Rigid-body notes (4.53)-(4.54)).");
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
      "Planes of symmetry (Craig \"Plane of Symmetry\") of point masses (n,) [kg] > 0 at positions\n"
      "(n, 3) [m]: the planes whose reflection maps every point onto a point of equal mass, within\n"
      "tolerance * (largest distance from the centre of mass to a point) [m] and tolerance * mass.\n"
      "Returns a list of (normal (3,) unit, largest-magnitude component positive; point (3,) [m] = the\n"
      "centre of mass), in the frame of the positions. Candidates: the principal axes, and when principal\n"
      "moments coincide, normals built from the points; for such\n"
      "degenerate bodies (cube, regular tetrahedron) the planes found among them, not a proof of none else.");
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
      "Planes of symmetry of the uniform solid bounded by a closed, outward-oriented mesh: vertices (n, 3)\n"
      "[m], faces (f, 3), welded as in solid_mesh (weld_tolerance). The planes of the solid, whatever its\n"
      "triangulation: a plane qualifies when its reflection maps the solid's oriented boundary onto itself\n"
      "(each reflected face covered by faces in the same plane and facing the same way, up to a strip of\n"
      "width tolerance * L along its edges, L = largest distance from the centre of mass to a vertex [m];\n"
      "normals within tolerance). A faceted cylinder or capsule of s sections has the s planes through its\n"
      "axis and the plane normal to it, not the smooth solid's continuum. Returns a list of (normal (3,)\n"
      "unit, largest-magnitude component positive; point (3,) [m] = the solid's centre of mass) in the frame\n"
      "of the vertices; candidates as in symmetry_planes. ValueError naming the argument on a bad mesh.");
}

void bind_mesh_and_density(py::module_& m) {
  m.def(
      "require_closed_oriented_mesh",
      [](py::handle faces, py::handle n_vertices) {
        const MeshFaces f = as_faces(faces);
        require_closed_oriented_mesh(f, py_io::as_int(n_vertices, "n_vertices", 0));
      },
      "faces"_a, "n_vertices"_a,
      "ValueError unless faces (f, 3) index [0, n_vertices) and form a closed, consistently oriented mesh.");
  m.def(
      "mesh_volume",
      [](py::handle vertices, py::handle faces) {
        return py_io::finite_result(mesh_volume(as_points(vertices, "vertices"), as_faces(faces)), "mesh_volume");
      },
      "vertices"_a, "faces"_a, "Signed volume [m^3] of the mesh vertices (n, 3) [m], faces (f, 3).");
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
  py::class_<WeldedMesh>(m, "WeldedMesh", "A mesh after weld_vertices, with what the weld changed.")
      .def_property_readonly("vertices", [](const WeldedMesh& w) { return read_only(w.vertices); },
                             "(n', 3) [m] the kept vertices (each cluster's lowest-indexed), in input order")
      .def_property_readonly("faces", [](const WeldedMesh& w) { return index_array(w.faces, {w.faces.rows(), 3}); },
                             "(f', 3) int64 the non-degenerate faces, in input order, indexing vertices")
      .def_property_readonly(
          "vertex_index",
          [](const WeldedMesh& w) { return index_array(w.vertex_index, {static_cast<py::ssize_t>(w.vertex_index.size())}); },
          "(n',) int64 input index of each kept vertex")
      .def_property_readonly(
          "face_index",
          [](const WeldedMesh& w) { return index_array(w.face_index, {static_cast<py::ssize_t>(w.face_index.size())}); },
          "(f',) int64 input index of each kept face")
      .def_property_readonly("welded_vertices", [](const WeldedMesh& w) { return w.report.welded_vertices; },
                             "input vertices merged into another")
      .def_property_readonly("dropped_faces", [](const WeldedMesh& w) { return w.report.dropped_faces; },
                             "faces repeating a vertex after welding, dropped")
      .def_property_readonly("tolerance", [](const WeldedMesh& w) { return w.report.tolerance; },
                             "weld tolerance used [m]")
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
      "Welds vertices (n, 3) [m] closer than tolerance [m] (None: 1e-8 x the bounding-box diagonal), as\n"
      "solid_mesh does: clusters of vertices within tolerance of one another (grid hashing, O(n log n)) keep\n"
      "their lowest-indexed vertex; faces (f, 3) repeating a vertex afterwards are dropped. Returns a\n"
      "WeldedMesh (vertices, faces, welded_vertices, dropped_faces, ...); warns nothing.");

  bind_symmetry(m);

  py::class_<DensityIntegral>(m, "DensityIntegral",
                              "Result of a density quadrature with its error estimate (all in the frame of the\n"
                              "points rho was evaluated at).")
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
                    "SpatialInertia from the higher-order rule (centre of mass and inertia about it, in the frame\n"
                    "of the points)")
      .def_readonly("mass_error", &DensityIntegral::mass_error, "|m_high - m_low| [kg]")
      .def_readonly("com_error", &DensityIntegral::com_error, "|c_high - c_low| [m]")
      .def_readonly("inertia_error", &DensityIntegral::inertia_error,
                    "||I_C,high - I_C,low||_F [kg m^2], inertias about the centre of mass")
      .def_readonly("evaluations", &DensityIntegral::evaluations, "points at which rho was evaluated")
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
      "Mass properties of density rho over the box [lower, upper] (3,) [m] by Gauss-Legendre quadrature\n"
      "(Rigid-body notes (4.55), (4.56), (4.70)) at `order` and 2*order points per cell axis, subdivisions^3 cells.\n"
      "rho is called with points (n, 3) [m] and returns (n,) densities [kg/m^3] >= 0. Returns a\n"
      "DensityIntegral (high-order result, differences to the low order as error estimate).");
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
      "Mass properties of density rho over the solid bounded by a closed mesh (signed tetrahedra, collapsed\n"
      "Gauss-Legendre, order^3 and (2 order)^3 points per face). rho: points (n, 3) -> (n,) [kg/m^3], must\n"
      "be defined on the mesh's convex hull. Returns a DensityIntegral.");
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
