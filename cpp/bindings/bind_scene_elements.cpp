// Python bindings of the force elements of a scene (scene/elements/*.hpp): UniformGravity,
// PointMassGravity, MutualGravity, GravityGradient, SpringDamper, Drag, ScheduledLoads, PythonForce
// (the C++ FunctionForce calling a Python callable with the GIL) and Thrust. Each class has a keyword constructor
// that converts and checks every argument by name (TypeError/ValueError "<argument>: expected ..."),
// read-only attributes, a repr that evaluates back to an equal element, pickle and ==. What needs the
// scene's bodies (an index in range, a load the body's kind can take) is checked by Scene.add.
#include <pybind11/stl.h>

#include <climits>
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

double as_nonnegative(py::handle obj, const std::string& name) {
  const double x = py_io::as_scalar(obj, name);
  if (x < 0.0) py_io::throw_value_error(name, "a finite number >= 0", format_value(x));
  return x;
}

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

py::object vector_object(const Eigen::Vector3d& v) { return py_io::read_only(v); }

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

py::object python_fn(const FunctionForce& force) {
  const auto* call = force.f.target<PythonForceCall>();
  return call ? call->fn() : py::object(py::none());
}

// ------------------------------------------------------------ one binding for every element class

struct Field {
  const char* key;
  const char* doc;
};

// An element class: its fields (key, docstring) in constructor order, make (the checked spec from the
// field values in that order) and values (the field values of a spec, for attributes, repr, pickle, ==).
template <class T>
struct ElementClass {
  const char* name;
  std::vector<Field> fields;
  T (*make)(const py::tuple& values);
  py::tuple (*values)(const T& element);
};

// A field's value as source text: arrays as lists, a named function by its qualified name (so that the
// repr of a PythonForce of a module-level function evaluates where that function is in scope).
std::string value_text(const py::object& v) {
  if (PyCallable_Check(v.ptr()) && py::hasattr(v, "__qualname__") && !py::isinstance<py::type>(v)) {
    const std::string name = py::str(v.attr("__qualname__"));
    if (name.find('<') == std::string::npos) return name;
  }
  return py::repr(py::hasattr(v, "tolist") ? v.attr("tolist")() : v);
}

template <class T>
std::string element_repr(const ElementClass<T>& c, const T& element) {
  const py::tuple values = c.values(element);
  std::string text = std::string(c.name) + "(";
  for (std::size_t i = 0; i < c.fields.size(); ++i) {
    text += (i ? ", " : "") + std::string(c.fields[i].key) + "=" + value_text(values[i]);
  }
  return text + ")";
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

// Binds the class with `init` (the keyword constructor, whose py::arg list follows) and the protocol.
template <class T, class Init, class... Args>
py::class_<T> bind_element(py::module_& m, const ElementClass<T>& c, const char* doc, Init init, const Args&... args) {
  py::class_<T> cls(m, c.name, doc);
  cls.def(py::init(init), args...);
  for (std::size_t i = 0; i < c.fields.size(); ++i) {
    cls.def_property_readonly(c.fields[i].key, [values = c.values, i](const T& e) { return py::object(values(e)[i]); },
                              c.fields[i].doc);
  }
  cls.def("__repr__", [c](const T& e) { return element_repr(c, e); });
  cls.def(py::pickle([values = c.values](const T& e) { return values(e); },
                     [c](const py::tuple& t) {
                       if (t.size() != c.fields.size()) {
                         py_io::throw_value_error(std::string(c.name) + " pickle",
                                                  "a tuple of " + std::to_string(c.fields.size()) + " items",
                                                  std::to_string(t.size()) + " items");
                       }
                       return c.make(t);
                     }));
  cls.def(
      "__eq__",
      [values = c.values](const T& a, py::handle b) -> py::object {
        if (!py::isinstance<T>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
        return py::bool_(same_values(values(a), values(b.cast<const T&>())));
      },
      py::arg("other"));
  cls.attr("__hash__") = py::none();
  return cls;
}

// ------------------------------------------------------------ the element classes

const ElementClass<UniformGravity> uniform_gravity{
    UniformGravity::element_type,
    {{"g_W", "(3,) gravitational acceleration in W [m/s^2]"},
     {"bodies", "None (every body) or a tuple of the indices of the bodies it acts on"}},
    [](const py::tuple& v) {
      UniformGravity e;
      e.g_W = py_io::as_vector3(py_io::in_si(v[0], "m/s^2", "g_W"), "g_W");
      e.bodies = as_body_list(v[1], "bodies");
      return e;
    },
    [](const UniformGravity& e) -> py::tuple { return py::make_tuple(vector_object(e.g_W), body_list_object(e.bodies)); }};

const ElementClass<PointMassGravity> point_mass_gravity{
    PointMassGravity::element_type,
    {{"gm", "gravitational parameter GM of the attractor [m^3/s^2]"},
     {"p_W", "(3,) position of the fixed attractor in W [m]"},
     {"softening", "softening length epsilon [m] (0: none)"},
     {"bodies", "None (every body) or a tuple of the indices of the bodies it acts on"}},
    [](const py::tuple& v) {
      PointMassGravity e;
      e.gm = py_io::as_positive(py_io::in_si(v[0], "m^3/s^2", "gm"), "gm");
      e.p_W = py_io::as_vector3(py_io::in_si(v[1], "m", "p_W"), "p_W");
      e.softening = as_nonnegative(py_io::in_si(v[2], "m", "softening"), "softening");
      e.bodies = as_body_list(v[3], "bodies");
      return e;
    },
    [](const PointMassGravity& e) -> py::tuple {
      return py::make_tuple(e.gm, vector_object(e.p_W), e.softening, body_list_object(e.bodies));
    }};

const ElementClass<MutualGravity> mutual_gravity{
    MutualGravity::element_type,
    {{"G", "gravitational constant [m^3/(kg s^2)]"},
     {"softening", "softening length epsilon [m] (0: none)"},
     {"bodies", "None (every body) or a tuple of the indices of the bodies that attract each other"}},
    [](const py::tuple& v) {
      MutualGravity e;
      e.G = py_io::as_positive(py_io::in_si(v[0], "m^3/(kg*s^2)", "G"), "G");
      e.softening = as_nonnegative(py_io::in_si(v[1], "m", "softening"), "softening");
      e.bodies = as_body_list(v[2], "bodies");
      return e;
    },
    [](const MutualGravity& e) -> py::tuple { return py::make_tuple(e.G, e.softening, body_list_object(e.bodies)); }};

const ElementClass<GravityGradient> gravity_gradient{
    GravityGradient::element_type,
    {{"gm", "gravitational parameter GM of the central attractor [m^3/s^2]"},
     {"p_W", "(3,) position of the attractor in W [m]"},
     {"bodies", "None (every body) or a tuple of the indices of the bodies it acts on"}},
    [](const py::tuple& v) {
      GravityGradient e;
      e.gm = py_io::as_positive(py_io::in_si(v[0], "m^3/s^2", "gm"), "gm");
      e.p_W = py_io::as_vector3(py_io::in_si(v[1], "m", "p_W"), "p_W");
      e.bodies = as_body_list(v[2], "bodies");
      return e;
    },
    [](const GravityGradient& e) -> py::tuple { return py::make_tuple(e.gm, vector_object(e.p_W), body_list_object(e.bodies)); }};

const ElementClass<SpringDamper> spring_damper{
    SpringDamper::element_type,
    {{"body_a", "index of the body at end a"},
     {"point_a_B", "(3,) end a in body a's frame B, from its centre of mass [m]"},
     {"body_b", "index of the body at end b, or None: end b is the world anchor point_b"},
     {"point_b", "(3,) end b: in body b's frame B from its centre of mass, or in W if body_b is None [m]"},
     {"stiffness", "spring stiffness k [N/m]"},
     {"rest_length", "rest length l0 [m]"},
     {"damping", "damping coefficient c [N s/m]"}},
    [](const py::tuple& v) {
      SpringDamper e;
      e.body_a = as_body_index(v[0], "body_a");
      e.point_a_B = py_io::as_vector3(py_io::in_si(v[1], "m", "point_a_B"), "point_a_B");
      e.body_b = v[2].is_none() ? -1 : as_body_index(v[2], "body_b");
      if (e.body_b == e.body_a) {
        py_io::throw_value_error("body_b", "None (a world anchor) or a body other than body_a = " + std::to_string(e.body_a),
                                 std::to_string(e.body_b));
      }
      e.point_b = py_io::as_vector3(py_io::in_si(v[3], "m", "point_b"), "point_b");
      e.stiffness = as_nonnegative(py_io::in_si(v[4], "N/m", "stiffness"), "stiffness");
      e.rest_length = as_nonnegative(py_io::in_si(v[5], "m", "rest_length"), "rest_length");
      e.damping = as_nonnegative(py_io::in_si(v[6], "N*s/m", "damping"), "damping");
      return e;
    },
    [](const SpringDamper& e) -> py::tuple {
      return py::make_tuple(e.body_a, vector_object(e.point_a_B), e.body_b < 0 ? py::object(py::none()) : py::int_(e.body_b),
                            vector_object(e.point_b), e.stiffness, e.rest_length, e.damping);
    }};

const ElementClass<Drag> drag{
    Drag::element_type,
    {{"linear", "c1 of f_W = -(c1 + c2 |v_W|) v_W [N s/m]"},
     {"quadratic", "c2 of f_W = -(c1 + c2 |v_W|) v_W [N s^2/m^2]"},
     {"angular_linear", "d1 of tau_B = -(d1 + d2 |w_B|) w_B [N m s/rad]"},
     {"angular_quadratic", "d2 of tau_B = -(d1 + d2 |w_B|) w_B [N m s^2/rad^2]"},
     {"bodies", "None (every body) or a tuple of the indices of the bodies it acts on"}},
    [](const py::tuple& v) {
      Drag e;
      e.linear = as_nonnegative(py_io::in_si(v[0], "N*s/m", "linear"), "linear");
      e.quadratic = as_nonnegative(py_io::in_si(v[1], "N*s^2/m^2", "quadratic"), "quadratic");
      e.angular_linear = as_nonnegative(py_io::in_si(v[2], "N*m*s", "angular_linear"), "angular_linear");
      e.angular_quadratic = as_nonnegative(py_io::in_si(v[3], "N*m*s^2", "angular_quadratic"), "angular_quadratic");
      e.bodies = as_body_list(v[4], "bodies");
      return e;
    },
    [](const Drag& e) -> py::tuple {
      return py::make_tuple(e.linear, e.quadratic, e.angular_linear, e.angular_quadratic, body_list_object(e.bodies));
    }};

const ElementClass<ScheduledLoads> scheduled_loads{
    ScheduledLoads::element_type,
    {{"body", "index of the body the loads act on"},
     {"loads", "tuple of AppliedLoad: the piecewise-constant schedule"},
     {"point_B", "(3,) point of application of the forces in B, from the centre of mass [m]"}},
    [](const py::tuple& v) {
      ScheduledLoads e;
      e.body = as_body_index(v[0], "body");
      e.loads = as_loads(v[1], "loads");
      check_loads(e.loads);  // names "loads[i]..."
      e.point_B = py_io::as_vector3(py_io::in_si(v[2], "m", "point_B"), "point_B");
      return e;
    },
    [](const ScheduledLoads& e) -> py::tuple {
      py::tuple loads(e.loads.size());
      for (std::size_t i = 0; i < e.loads.size(); ++i) loads[i] = py::cast(e.loads[i]);
      return py::make_tuple(e.body, loads, vector_object(e.point_B));
    }};

const ElementClass<FunctionForce> python_force{
    "PythonForce",
    {{"fn", "the callable fn(t, body, p_W, q_WB, v_W, w_B) -> (f_W, tau_B)"},
     {"bodies", "None (every body) or a tuple of the indices of the bodies it acts on"}},
    [](const py::tuple& v) {
      FunctionForce e;
      e.type_name = "PythonForce";  // this class's name, in records and messages (compile's element_type_name)
      e.f = PythonForceCall(py_io::as_callable(v[0], "fn", "a callable fn(t, body, p_W, q_WB, v_W, w_B) -> (f_W, tau_B)"));
      e.bodies = as_body_list(v[1], "bodies");
      return e;
    },
    [](const FunctionForce& e) -> py::tuple { return py::make_tuple(python_fn(e), body_list_object(e.bodies)); }};

const ElementClass<Thrust> thrust{
    Thrust::element_type,
    {{"body", "index of the body (one with a MassFlow) whose exchanged mass pushes it"},
     {"u_rel", "(3,) velocity of the exchanged mass relative to the body, in `frame` [m/s]"},
     {"frame", "'body' (u_rel in B, turning with the body) or 'world' (in the scene frame W)"},
     {"r_B", "(3,) point of application in B, from the centre of mass [m]"}},
    [](const py::tuple& v) {
      Thrust e;
      e.body = as_body_index(v[0], "body");
      e.u_rel = py_io::as_vector3(py_io::in_si(v[1], "m/s", "u_rel"), "u_rel");
      e.frame = as_frame(v[2], "frame");
      e.r_B = py_io::as_vector3(py_io::in_si(v[3], "m", "r_B"), "r_B");
      return e;
    },
    [](const Thrust& e) -> py::tuple {
      return py::make_tuple(e.body, vector_object(e.u_rel), e.frame == Frame::body ? "body" : "world",
                            vector_object(e.r_B));
    }};

// A Python element as the C++ Element, else TypeError naming `name`.
template <class... T>
Element element_from(py::handle obj, const std::string& name, std::variant<T...>*) {
  std::optional<Element> out;
  ((py::isinstance<T>(obj) ? (void)(out = obj.cast<const T&>()) : void()), ...);
  if (!out) {
    py_io::throw_type_error(name, "a force element (UniformGravity, PointMassGravity, MutualGravity, GravityGradient, "
                            "SpringDamper, Drag, ScheduledLoads, PythonForce or Thrust)", obj);
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

void bind_scene_elements(py::module_& m) {
  const auto none = py::none();
  bind_element(m, uniform_gravity,
               "Uniform gravity on the listed bodies: f_W = m g_W at each centre of mass, potential V = -m g_W . p_W "
               "[J]. g_W (3,) [m/s^2] in W (default (0, 0, -9.81)); bodies: None (every body) or body indices. A "
               "planar body keeps the in-plane part (the plane takes the rest)."
               " Each physical argument: a float [its unit above] or a pint quantity (any registry; converted to that "
               "unit, ValueError naming the argument for another dimension).",
               [](py::handle g_W, py::handle bodies) { return uniform_gravity.make(py::make_tuple(g_W, bodies)); },
               py::kw_only(), py::arg("g_W") = py::make_tuple(0.0, 0.0, -9.81), py::arg("bodies") = none);
  bind_element(m, point_mass_gravity,
               "A fixed attractor of gravitational parameter gm [m^3/s^2] at p_W (3,) [m] in W: on each listed body "
               "f_W = -gm m r/(|r|^2 + softening^2)^(3/2), r = p_body - p_W, potential V = -gm m/sqrt(|r|^2 + "
               "softening^2) [J]; softening [m] >= 0; bodies: None (every body) or body indices."
               " Each physical argument: a float [its unit above] or a pint quantity (any registry; converted to that "
               "unit, ValueError naming the argument for another dimension).",
               [](py::handle gm, py::handle p_W, py::handle softening, py::handle bodies) {
                 return point_mass_gravity.make(py::make_tuple(gm, p_W, softening, bodies));
               },
               py::kw_only(), py::arg("gm"), py::arg("p_W") = py::make_tuple(0.0, 0.0, 0.0),
               py::arg("softening") = 0.0, py::arg("bodies") = none);
  bind_element(m, mutual_gravity,
               "Newtonian gravity between the listed bodies (direct O(N^2) sum over the pairs): f on i = -G m_i m_j r/"
               "(|r|^2 + softening^2)^(3/2), r = p_i - p_j [N], potential V = sum -G m_i m_j/sqrt(|r|^2 + softening^2) "
               "[J]. G [m^3/(kg s^2)] (default 6.67430e-11); softening [m] >= 0; bodies: None (every body) or body "
               "indices."
               " Each physical argument: a float [its unit above] or a pint quantity (any registry; converted to that "
               "unit, ValueError naming the argument for another dimension).",
               [](py::handle G, py::handle softening, py::handle bodies) {
                 return mutual_gravity.make(py::make_tuple(G, softening, bodies));
               },
               py::kw_only(), py::arg("G") = 6.67430e-11, py::arg("softening") = 0.0, py::arg("bodies") = none);
  bind_element(m, gravity_gradient,
               "The gravity-gradient (MacCullagh) term of a central attractor gm [m^3/s^2] at p_W (3,) [m] in W on "
               "extended bodies: torque tau_B = 3 gm/|r|^5 r_B x (I r_B) [N m] and the matching force, so that the "
               "potential V2 = -gm/(2|r|^3) (tr I - 3 r^T I_W r/|r|^2) [J] is conserved with the motion; no effect on "
               "particles. bodies: None (every body) or body indices."
               " Each physical argument: a float [its unit above] or a pint quantity (any registry; converted to that "
               "unit, ValueError naming the argument for another dimension).",
               [](py::handle gm, py::handle p_W, py::handle bodies) {
                 return gravity_gradient.make(py::make_tuple(gm, p_W, bodies));
               },
               py::kw_only(), py::arg("gm"), py::arg("p_W") = py::make_tuple(0.0, 0.0, 0.0), py::arg("bodies") = none);
  bind_element(m, spring_damper,
               "A linear spring and damper between point_a_B (3,) [m] of body_a (in its frame B, from its centre of "
               "mass) and point_b (3,) [m] of body_b (in its B) or, body_b None, the world anchor point_b in W. Force "
               "on a: -(stiffness (l - rest_length) + damping dl/dt) u, u = (x_a - x_b)/l, l = |x_a - x_b| [N], along the "
               "line (no force at l = 0), so the pair conserves momentum and angular momentum; the opposite on b; torque r x f "
               "about each centre of mass. stiffness [N/m], rest_length [m], damping [N s/m], each >= 0. Potential "
               "V = stiffness (l - rest_length)^2/2 [J]."
               " Each physical argument: a float [its unit above] or a pint quantity (any registry; converted to that "
               "unit, ValueError naming the argument for another dimension).",
               [](py::handle body_a, py::handle point_a_B, py::handle body_b, py::handle point_b, py::handle stiffness,
                  py::handle rest_length, py::handle damping) {
                 return spring_damper.make(
                     py::make_tuple(body_a, point_a_B, body_b, point_b, stiffness, rest_length, damping));
               },
               py::kw_only(), py::arg("body_a"), py::arg("point_a_B") = py::make_tuple(0.0, 0.0, 0.0),
               py::arg("body_b") = none, py::arg("point_b") = py::make_tuple(0.0, 0.0, 0.0), py::arg("stiffness"),
               py::arg("rest_length") = 0.0, py::arg("damping") = 0.0);
  bind_element(m, drag,
               "Linear and quadratic drag on the listed bodies: f_W = -(linear + quadratic |v_W|) v_W [N] at the "
               "centre of mass and tau_B = -(angular_linear + angular_quadratic |w_B|) w_B [N m]; coefficients >= 0 "
               "([N s/m], [N s^2/m^2], [N m s/rad], [N m s^2/rad^2]). Velocity-dependent: the splitting methods "
               "warn (SceneCompatibilityWarning). bodies: None (every body) or body indices."
               " Each physical argument: a float [its unit above] or a pint quantity (any registry; converted to that "
               "unit, ValueError naming the argument for another dimension).",
               [](py::handle linear, py::handle quadratic, py::handle angular_linear, py::handle angular_quadratic,
                  py::handle bodies) {
                 return drag.make(py::make_tuple(linear, quadratic, angular_linear, angular_quadratic, bodies));
               },
               py::kw_only(), py::arg("linear") = 0.0, py::arg("quadratic") = 0.0, py::arg("angular_linear") = 0.0,
               py::arg("angular_quadratic") = 0.0, py::arg("bodies") = none);
  bind_element(m, scheduled_loads,
               "The piecewise-constant schedule `loads` (AppliedLoad or a sequence: force [N] and torque [N m], each "
               "in W or B, active on [t_start, t_end) [s]) on body `body`, the forces applied at point_B (3,) [m] (in "
               "B, from the centre of mass; adds the torque point_B x f_B). A run splits its steps at the switch "
               "times, as simulate does for one body."
               " Each physical argument: a float [its unit above] or a pint quantity (any registry; converted to that "
               "unit, ValueError naming the argument for another dimension).",
               [](py::handle body, py::handle loads, py::handle point_B) {
                 return scheduled_loads.make(py::make_tuple(body, loads, point_B));
               },
               py::kw_only(), py::arg("body"), py::arg("loads") = py::tuple(),
               py::arg("point_B") = py::make_tuple(0.0, 0.0, 0.0));
  bind_element(m, python_force,
               "A force written in Python: fn(t, body, p_W, q_WB, v_W, w_B) -> (f_W, tau_B) is called for each listed "
               "body at every derivative evaluation, with t [s], the body's index, p_W (3,) [m] and v_W (3,) [m/s] in "
               "W, q_WB (4,) (x, y, z, w) and w_B (3,) [rad/s] in B (a particle: q_WB identity, w_B 0; a planar body: "
               "p_W = (x, y, 0), q_WB = Rz(theta), w_B = (0, 0, omega)); it returns f_W (3,) [N] in W at the centre "
               "of mass and tau_B (3,) [N m] in B. It is treated as time- and velocity-dependent. Each call takes "
               "the GIL (the run otherwise releases it: other Python threads wait during fn) and costs about 1.2 us "
               "per call against about 10 ns for a built-in element (measured 2026-11-24, 10 particles, RK4: "
               "python bench/python/bench_scene.py). An exception "
               "raised by fn stops the run and propagates; a return value other than two finite 3-vectors raises "
               "TypeError/ValueError naming fn. bodies: None (every body) or body indices.",
               [](py::handle fn, py::handle bodies) { return python_force.make(py::make_tuple(fn, bodies)); },
               py::arg("fn"), py::arg("bodies") = none);
  bind_element(m, thrust,
               "The thrust of a body whose mass changes (its MassFlow, given to Scene.add_body): f = (dm/dt) u_rel "
               "[N] (\"Rigid body kinematics and dynamics\" notes, eq. (4.36): d(m v)/dt = f + (dm/dt)(v + u_rel), so "
               "m dv/dt = f + (dm/dt) u_rel), u_rel (3,) [m/s] the velocity of the mass leaving (dm/dt < 0: u_rel "
               "backwards pushes forwards) or joining the body, relative to it, in `frame` ('body': in B, turning "
               "with the body; 'world': in the scene frame W), applied at r_B (3,) [m] in B from the centre of mass "
               "(adds the torque r_B x f_B). Scene.add refuses it (ValueError naming element.body) on a body without "
               "a MassFlow. No potential; its power is in SceneResult.power."
               " Each physical argument: a float [its unit above] or a pint quantity (any registry; converted to that "
               "unit, ValueError naming the argument for another dimension).",
               [](py::handle body, py::handle u_rel, py::handle frame, py::handle r_B) {
                 return thrust.make(py::make_tuple(body, u_rel, frame, r_B));
               },
               py::arg("body"), py::arg("u_rel"), py::arg("frame") = "body",
               py::arg("r_B") = py::make_tuple(0.0, 0.0, 0.0));
}

}  // namespace rigiddyn::bindings
