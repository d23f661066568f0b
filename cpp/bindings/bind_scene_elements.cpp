// Python bindings of the force elements of a scene (scene/elements/*.hpp): UniformGravity,
// PointMassGravity, MutualGravity, GravityGradient, SpringDamper, Drag, ScheduledLoads, PythonForce
// (the C++ FunctionForce calling a Python callable with the GIL) and Thrust. Each class has a keyword constructor
// that converts and checks every argument by name (TypeError/ValueError "<argument>: expected ..."),
// read-only attributes, a repr that evaluates back to an equal element, pickle and ==. What needs the
// scene's bodies (an index in range, a load the body's kind can take) is checked by Scene.add.
#include <pybind11/stl.h>

#include <climits>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "common_args.hpp"
#include "numpy_io.hpp"
#include "python_run.hpp"
#include "scene_run.hpp"
#include "rigiddyn/scene/scene.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;

namespace {

// ------------------------------------------------------------ argument conversions

int as_body_index(py::handle obj, const std::string& name) {
  return static_cast<int>(py_io::as_int(obj, name, 0, INT_MAX));
}

// None (every body) or a non-empty sequence of distinct body indices.
BodyList as_body_list(py::handle obj, const std::string& name) {
  constexpr const char* expected = "None (every body) or a sequence of body indices";
  if (obj.is_none()) return {};
  if (py::isinstance<py::str>(obj) || py::isinstance<py::bytes>(obj) || !py::isinstance<py::iterable>(obj)) {
    py_io::throw_type_error(name, expected, obj);
  }
  BodyList out;
  for (py::handle item : obj) {
    const int b = as_body_index(item, name + "[" + std::to_string(out.size()) + "]");
    for (const int seen : out)
      if (seen == b) py_io::throw_value_error(name, "each body once", py::repr(obj).cast<std::string>());
    out.push_back(b);
  }
  if (out.empty()) py_io::throw_value_error(name, "None (every body) or a non-empty sequence of body indices", "[]");
  return out;
}

py::object body_list_object(const BodyList& bodies) {
  if (bodies.empty()) return py::none();
  py::tuple out(bodies.size());
  for (std::size_t k = 0; k < bodies.size(); ++k) out[k] = py::int_(bodies[k]);
  return std::move(out);
}

// ------------------------------------------------------------ the Python force

// The Python callable of a PythonForce, dropped with the GIL held: a scene holding it may be copied or
// destroyed in C++ while the GIL is released (copying the shared_ptr needs no GIL).
struct PythonCallable {
  py::object fn;
  explicit PythonCallable(py::object f) : fn(std::move(f)) {}
  PythonCallable(const PythonCallable&) = delete;
  PythonCallable& operator=(const PythonCallable&) = delete;
  ~PythonCallable() {
    py::gil_scoped_acquire gil;
    fn = py::object();
  }
};

// FunctionForce::f for a Python fn(t, body, p_W, q_WB, v_W, w_B) -> (f_W, tau_B): takes the GIL, calls
// fn with new (3,)/(4,) arrays and reads its two 3-vectors. An exception raised by fn, or a return value
// that is not two finite 3-vectors (ValueError naming fn), propagates out of the run.
class PythonForceCall {
 public:
  explicit PythonForceCall(py::object fn) : fn_(std::make_shared<PythonCallable>(std::move(fn))) {}

  void operator()(double t, const BodyKinematics& k, int body, Eigen::Vector3d& f_W, Eigen::Vector3d& tau_B) const {
    py::gil_scoped_acquire gil;
    const py::object out = fn_->fn(t, body, py_io::to_array(k.p_W), py_io::to_array(k.q_WB, false),
                                   py_io::to_array(k.v_W), py_io::to_array(k.w_B));
    if (!py::isinstance<py::sequence>(out) || py::isinstance<py::str>(out) || py::len(out) != 2) {
      py_io::throw_type_error("fn", "a callable returning (f_W (3,) [N], tau_B (3,) [N m])", out);
    }
    f_W = py_io::as_vector3(out[py::int_(0)], "fn: returned f_W");
    tau_B = py_io::as_vector3(out[py::int_(1)], "fn: returned tau_B");
  }

  const py::object& fn() const { return fn_->fn; }

 private:
  std::shared_ptr<PythonCallable> fn_;
};

// ------------------------------------------------------------ a field's value from Python and back

// "<field>: expected ..." for a scalar outside its bound.
void require_bound(double x, FieldBound bound, const char* key) {
  if (bound == FieldBound::nonnegative && x < 0.0) py_io::throw_value_error(key, "a finite number >= 0", format_value(x));
  if (bound == FieldBound::positive && !(x > 0.0)) py_io::throw_value_error(key, "a finite number > 0", format_value(x));
}

// The field's value from a Python object (a float or a pint quantity for a field with a unit), checked.
template <class Spec>
double from_python(py::handle v, const ElementField<Spec, double>& f) {
  const py::object si = *f.unit ? py_io::in_si(v, f.unit, f.key) : py::reinterpret_borrow<py::object>(v);
  if (f.infinite_ok && py::isinstance<py::float_>(si) && std::isinf(si.cast<double>())) return si.cast<double>();
  const double x = py_io::as_scalar(si, f.key);
  require_bound(x, f.bound, f.key);
  return x;
}
template <class Spec>
Eigen::Vector3d from_python(py::handle v, const ElementField<Spec, Eigen::Vector3d>& f) {
  return py_io::as_vector3(*f.unit ? py_io::in_si(v, f.unit, f.key) : py::reinterpret_borrow<py::object>(v), f.key);
}
template <class Spec>
std::vector<double> from_python(py::handle v, const ElementField<Spec, std::vector<double>>& f) {
  const py::object si = *f.unit ? py_io::in_si(v, f.unit, f.key) : py::reinterpret_borrow<py::object>(v);
  const py_io::Array a = py_io::as_array(si, f.key);
  if (a.ndim() != 1) {
    py_io::throw_value_error(f.key, "an array of shape (n,)", "shape " + py::str(a.attr("shape")).cast<std::string>());
  }
  std::vector<double> out(a.data(), a.data() + a.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::string entry = std::string(f.key) + "[" + std::to_string(i) + "]";
    if (!std::isfinite(out[i])) py_io::throw_value_error(entry, "a finite number", format_value(out[i]));
  }
  return out;
}
template <class Spec>
BodyList from_python(py::handle v, const ElementField<Spec, BodyList>& f) {
  return as_body_list(v, f.key);
}
template <class Spec>
int from_python(py::handle v, const ElementField<Spec, int>& f) {
  if (f.kind == FieldKind::optional_body && v.is_none()) return -1;
  return as_body_index(v, f.key);
}
template <class Spec>
std::vector<AppliedLoad> from_python(py::handle v, const ElementField<Spec, std::vector<AppliedLoad>>& f) {
  std::vector<AppliedLoad> loads = as_loads(v, f.key);
  check_loads(loads);  // names "loads[i]..."
  return loads;
}
template <class Spec>
Frame from_python(py::handle v, const ElementField<Spec, Frame>& f) {
  return as_frame(v, f.key);
}
template <class Spec>
ForceFunction from_python(py::handle v, const ElementField<Spec, ForceFunction>& f) {
  return PythonForceCall(py_io::as_callable(v, f.key, f.doc));
}

// The value as Python shows it: a float, a read-only (3,) array, None or a tuple of body indices, a body index
// (None for no body), a tuple of AppliedLoad, 'body' or 'world', the Python callable.
py::object to_python(double x, FieldKind) { return py::float_(x); }
py::object to_python(const Eigen::Vector3d& v, FieldKind) { return py_io::read_only(v); }
py::object to_python(const std::vector<double>& values, FieldKind) {
  return py_io::read_only(Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size())));
}
py::object to_python(const BodyList& bodies, FieldKind) { return body_list_object(bodies); }
py::object to_python(int body, FieldKind kind) {
  return kind == FieldKind::optional_body && body < 0 ? py::object(py::none()) : py::object(py::int_(body));
}
py::object to_python(const std::vector<AppliedLoad>& loads, FieldKind) {
  py::tuple out(loads.size());
  for (std::size_t i = 0; i < loads.size(); ++i) out[i] = py::cast(loads[i]);
  return std::move(out);
}
py::object to_python(Frame frame, FieldKind) { return py::str(frame == Frame::body ? "body" : "world"); }
py::object to_python(const ForceFunction& f, FieldKind) {
  const auto* call = f.target<PythonForceCall>();
  return call ? call->fn() : py::object(py::none());
}

// A default as source text shows it: a vector or an array as a tuple (the signature's "p_W=(0.0, 0.0, 0.0)").
template <class T>
py::object default_object(const T& value, FieldKind kind) {
  if constexpr (std::is_same_v<T, Eigen::Vector3d>) {
    return py::make_tuple(value.x(), value.y(), value.z());
  } else if constexpr (std::is_same_v<T, std::vector<double>>) {
    return py::tuple(py::cast(value));
  } else {
    return to_python(value, kind);
  }
}

// ------------------------------------------------------------ one class per spec, from its field table

constexpr const char* field_kind_name(FieldKind kind) {
  switch (kind) {
    case FieldKind::scalar: return "scalar";
    case FieldKind::vector: return "vector";
    case FieldKind::array: return "array";
    case FieldKind::bodies: return "bodies";
    case FieldKind::body: return "body";
    case FieldKind::optional_body: return "optional_body";
    case FieldKind::loads: return "loads";
    case FieldKind::frame: return "frame";
    case FieldKind::callable: return "callable";
  }
  return "";
}

// A field as Python sees it (the class attribute `fields`): the scene file and describe() read it.
struct FieldInfo {
  std::string key, kind, unit, doc;
  bool required;
  py::object default_value;  // None when required
};

template <class Spec>
py::tuple field_infos() {
  const Spec defaults{};
  py::list out;
  for_each_field<Spec>([&](const auto& f) {
    out.append(FieldInfo{f.key, field_kind_name(f.kind), f.unit, f.doc, f.required,
                         f.required ? py::object(py::none()) : default_object(defaults.*(f.member), f.kind)});
  });
  return py::tuple(out);
}

// The spec from the field values in table order, each converted and checked by its field's name.
template <class Spec>
Spec spec_from(const py::tuple& values, const char* class_name) {
  Spec spec;
  std::size_t i = 0;
  for_each_field<Spec>([&](const auto& f) { spec.*(f.member) = from_python(values[i++], f); });
  if constexpr (std::is_same_v<Spec, FunctionForce>) spec.type_name = class_name;  // one name everywhere
  if constexpr (has_field_check<Spec>::value) spec.check_fields();
  return spec;
}

template <class Spec>
py::tuple values_of(const Spec& spec) {
  py::list out;
  for_each_field<Spec>([&](const auto& f) { out.append(to_python(spec.*(f.member), f.kind)); });
  return py::tuple(out);
}

// A field's value as source text: arrays as lists, an infinity as float('inf'), a named function by its qualified
// name (so that the repr of a PythonForce of a module-level function evaluates where that function is in scope).
std::string value_text(const py::object& v) {
  if (py::isinstance<py::float_>(v) && std::isinf(v.cast<double>())) {  // "inf" would not evaluate
    return v.cast<double>() > 0 ? "float('inf')" : "-float('inf')";
  }
  if (PyCallable_Check(v.ptr()) && py::hasattr(v, "__qualname__") && !py::isinstance<py::type>(v)) {
    const std::string name = py::str(v.attr("__qualname__"));
    if (name.find('<') == std::string::npos) return name;
  }
  return py::repr(py::hasattr(v, "tolist") ? v.attr("tolist")() : v);
}

// Field by field: arrays equal entry by entry, anything else by ==.
bool same_values(const py::tuple& a, const py::tuple& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    const py::object x = a[i], y = b[i];
    const py::object plain_x = py::hasattr(x, "tolist") ? x.attr("tolist")() : x;
    const py::object plain_y = py::hasattr(y, "tolist") ? y.attr("tolist")() : y;
    if (!plain_x.equal(plain_y)) return false;
  }
  return true;
}

// A field's type as numpydoc writes it.
constexpr const char* numpydoc_type(FieldKind kind) {
  switch (kind) {
    case FieldKind::scalar: return "float";
    case FieldKind::vector: return "array_like, shape (3,)";
    case FieldKind::array: return "array_like, shape (n,)";
    case FieldKind::bodies: return "sequence of int or None";
    case FieldKind::body: return "int";
    case FieldKind::optional_body: return "int or None";
    case FieldKind::loads: return "AppliedLoad or sequence of AppliedLoad";
    case FieldKind::frame: return "{'body', 'world'}";
    case FieldKind::callable: return "callable";
  }
  return "";
}

// The numpydoc docstring: the spec's text, a Parameters section from the field table, the units note, the Examples.
template <class Spec>
std::string class_doc(const char* text, const char* example) {
  const Spec defaults{};
  std::string doc = std::string(text) + "\n\nParameters\n----------\n";
  bool physical = false;
  for_each_field<Spec>([&](const auto& f) {
    const std::string unit = *f.unit ? std::string(" [") + f.unit + "]" : "";  // e.g. "float [m^3/s^2]"
    physical = physical || *f.unit;
    const std::string given =
        f.required ? "required" : "default " + py::repr(default_object(defaults.*(f.member), f.kind)).template cast<std::string>();
    doc += std::string(f.key) + " : " + numpydoc_type(f.kind) + unit + ", " + given + "\n    " + f.doc + "\n";
  });
  if (physical) {
    doc += "\nEach argument with a unit takes a float in that unit or a pint quantity (any registry; converted to "
           "that unit, ValueError naming the argument for another dimension).";
  }
  return doc + "\n\nExamples\n--------\n" + example;
}

template <class Spec>
constexpr bool keyword_only() {
  if constexpr (has_keyword_only<Spec>::value) {
    return Spec::keyword_only;
  } else {
    return true;
  }
}

// The argument of field I: named by its key, with its default unless it must be given.
template <class Spec, std::size_t I>
auto argument_of(const Spec& defaults) {
  constexpr auto f = std::get<I>(Spec::fields());
  if constexpr (f.required) {
    return py::arg(f.key);
  } else {
    return py::arg_v(f.key, default_object(defaults.*(f.member), f.kind));
  }
}

// The constructor: one argument per field, in table order.
template <class Spec, std::size_t... I>
void def_init(py::class_<Spec>& cls, const char* name, std::index_sequence<I...>) {
  const Spec defaults{};
  auto init = [name](decltype((void)I, py::handle())... v) { return spec_from<Spec>(py::make_tuple(v...), name); };
  if constexpr (keyword_only<Spec>()) {
    cls.def(py::init(init), py::kw_only(), argument_of<Spec, I>(defaults)...);
  } else {
    cls.def(py::init(init), argument_of<Spec, I>(defaults)...);
  }
}

// Binds Spec as the Python class `name` (its docstring `text`): the constructor, read-only attributes,
// a repr that evaluates back to an equal element, pickle, ==, and the class attribute `fields`.
template <class Spec>
void bind_element(py::module_& m, const char* name, const char* text, const char* example) {
  static const std::string doc = class_doc<Spec>(text, example);
  py::class_<Spec> cls(m, name, doc.c_str());
  def_init<Spec>(cls, name, std::make_index_sequence<field_count<Spec>()>());
  for_each_field<Spec>([&](const auto& f) {
    cls.def_property_readonly(f.key, [member = f.member, kind = f.kind](const Spec& e) { return to_python(e.*member, kind); },
                              f.doc);
  });
  cls.attr("fields") = field_infos<Spec>();
  cls.def("__repr__", [name](const Spec& e) {
    const py::tuple values = values_of(e);
    std::string text = std::string(name) + "(";
    std::size_t k = 0;
    for_each_field<Spec>([&](const auto& f) {
      text += (k ? ", " : "") + std::string(f.key) + "=" + value_text(values[k]);
      ++k;
    });
    return text + ")";
  });
  cls.def(py::pickle([](const Spec& e) { return values_of(e); },
                     [name](const py::tuple& t) {
                       if (t.size() != field_count<Spec>()) {
                         py_io::throw_value_error(std::string(name) + " pickle",
                                                  "a tuple of " + std::to_string(field_count<Spec>()) + " items",
                                                  std::to_string(t.size()) + " items");
                       }
                       return spec_from<Spec>(t, name);
                     }));
  cls.def(
      "__eq__",
      [](const Spec& a, py::handle b) -> py::object {
        if (!is_instance<Spec>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
        return py::bool_(same_values(values_of(a), values_of(b.cast<const Spec&>())));
      },
      py::arg("other"));
  cls.attr("__hash__") = py::none();
}

// The Python class of each spec: its element_type, except the function force, which holds a Python callable.
template <class Spec>
const char* class_name() {
  if constexpr (std::is_same_v<Spec, FunctionForce>) {
    return "PythonForce";
  } else {
    return Spec::element_type;
  }
}

constexpr const char* python_force_doc =
    "A force written in Python: fn(t, body, p_W, q_WB, v_W, w_B) -> (f_W, tau_B) is called for each listed "
    "body at every derivative evaluation, with t [s], the body's index, p_W (3,) [m] and v_W (3,) [m/s] in "
    "W, q_WB (4,) (x, y, z, w) and w_B (3,) [rad/s] in B (a particle: q_WB identity, w_B 0; a planar body: "
    "p_W = (x, y, 0), q_WB = Rz(theta), w_B = (0, 0, omega)); it returns f_W (3,) [N] in W at the centre "
    "of mass and tau_B (3,) [N m] in B. It is treated as time- and velocity-dependent. Each call takes "
    "the GIL (the run otherwise releases it: other Python threads wait during fn) and costs about 1.2 us "
    "per call against about 10 ns for a built-in element (measured 2026-11-24, 10 particles, RK4: "
    "python bench/python/bench_scene.py). An exception raised by fn stops the run and propagates; a return "
    "value other than two finite 3-vectors raises TypeError/ValueError naming fn.";

constexpr const char* python_force_example = R"py(The weight m g of a particle of 1 kg written in Python: it falls g t²/2:

>>> weight = rd.PythonForce(lambda t, body, p_W, q_WB, v_W, w_B: ((0.0, 0.0, -9.81), (0.0, 0.0, 0.0)))
>>> scene = rd.Scene([rd.Particle(1.0)], elements=[weight])
>>> result = rd.simulate(scene, [rd.ParticleState()], 0.01, duration=1.0, method="rk4")
>>> result.p_W[-1, 0].round(12)
array([ 0.   ,  0.   , -4.905]))py";

template <class Spec>
const char* class_text() {
  if constexpr (std::is_same_v<Spec, FunctionForce>) {
    return python_force_doc;
  } else {
    return Spec::doc;
  }
}

// The class's Examples (each element's spec has its own, a compile error where one is missing)
template <class Spec>
const char* class_example() {
  if constexpr (std::is_same_v<Spec, FunctionForce>) {
    return python_force_example;
  } else {
    return Spec::example;
  }
}

template <class... Spec>
py::tuple bind_elements(py::module_& m, std::variant<Spec...>*) {
  (bind_element<Spec>(m, class_name<Spec>(), class_text<Spec>(), class_example<Spec>()), ...);
  return py::make_tuple(m.attr(class_name<Spec>())...);
}

template <class... Spec>
std::string element_class_names(std::variant<Spec...>*) {
  std::string names;
  ((names += (names.empty() ? "" : ", ") + std::string(class_name<Spec>())), ...);
  return names;
}

// A Python element as the C++ Element, else TypeError naming `name`.
template <class... T>
Element element_from(py::handle obj, const std::string& name, std::variant<T...>*) {
  std::optional<Element> out;
  ((is_instance<T>(obj) ? (void)(out = obj.cast<const T&>()) : void()), ...);
  if (!out) {
    py_io::throw_type_error(name, "a force element (" + element_class_names(static_cast<Element*>(nullptr)) + ")", obj);
  }
  return *out;
}

}  // namespace

Element as_element(py::handle obj, const std::string& name) {
  return element_from(obj, name, static_cast<Element*>(nullptr));
}

py::object element_object(const Element& element) {
  return std::visit([](const auto& e) { return py::cast(e); }, element);
}

std::string element_kind(const Element& element) {
  return py::type::of(element_object(element)).attr("__name__").cast<std::string>();
}

const char* const element_field_doc = R"doc(One field of a force element class: its class attribute `fields`, in constructor order.

Made by the element classes (no public constructor); the scene files, describe() and the stability check read
them.

Attributes
----------
key : str
    The keyword and attribute.
kind : str
    'scalar', 'vector' (3,), 'bodies', 'body', 'optional_body', 'loads', 'frame' or 'callable'.
unit : str
    SI, pint syntax ('' when none).
required : bool
    The constructor needs it.
default : object
    None when required; a vector as a tuple.
doc : str
    What it is, with its unit.

Examples
--------
)doc"
    R"doc(>>> field = rd.SpringDamper.fields[4]
>>> field.key, field.unit, field.required
('stiffness', 'N/m', True)
>>> [f.key for f in rd.SpringDamper.fields]
['body_a', 'point_a_B', 'body_b', 'point_b', 'stiffness', 'rest_length', 'damping']
)doc";

void bind_scene_elements(py::module_& m) {
  py::class_<FieldInfo>(m, "ElementField", element_field_doc)
      .def_readonly("key", &FieldInfo::key)
      .def_readonly("kind", &FieldInfo::kind)
      .def_readonly("unit", &FieldInfo::unit)
      .def_readonly("required", &FieldInfo::required)
      .def_readonly("default", &FieldInfo::default_value)
      .def_readonly("doc", &FieldInfo::doc)
      .def("__repr__", [](const FieldInfo& f) {
        return "ElementField(key=" + py::repr(py::str(f.key)).cast<std::string>() + ", kind='" + f.kind + "', unit='" +
               f.unit + "', " + (f.required ? std::string("required") : "default=" + value_text(f.default_value)) + ")";
      });
  m.attr("FORCE_ELEMENTS") = bind_elements(m, static_cast<Element*>(nullptr));
}

}  // namespace rigiddyn::bindings
