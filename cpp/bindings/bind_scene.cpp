// Python bindings of scenes (scene/scene.hpp, scene/compile.hpp, scene/simulate_scene.hpp): Scene (bodies
// and force elements as data), CompiledScene (the immutable model of one method), SceneResult (the
// records of a run, read-only numpy arrays adopting the C++ vectors) and the scene branch of
// rigiddyn.simulate / rigiddyn.step (routed here by bind_dynamics.cpp). The element classes are in
// bind_scene_elements.cpp. Compatibility warnings are rigiddyn.SceneCompatibilityWarning (a UserWarning).
#include <pybind11/stl.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "common_args.hpp"
#include "numpy_io.hpp"
#include "python_run.hpp"
#include "repr.hpp"
#include "scene_run.hpp"
#include "tolerance_run.hpp"
#include "tree_equality.hpp"
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/control_laws.hpp"
#include "rigiddyn/scene/controller.hpp"
#include "rigiddyn/scene/method_twins.hpp"
#include "rigiddyn/scene/one_body_scene.hpp"
#include "rigiddyn/scene/scene_order.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using py_io::Array;

namespace {

// rigiddyn.SceneCompatibilityWarning, created in bind_scene.
PyObject* scene_compatibility_warning = nullptr;

// ------------------------------------------------------------ bodies and their states

// A body of any kind of Body (the first alternative whose Python class `obj` is), else TypeError naming `name`.
template <class... B>
Body body_from(py::handle obj, const std::string& name, std::variant<B...>*) {
  std::optional<Body> out;
  ((!out && is_instance<B>(obj) ? (void)(out = obj.cast<const B&>()) : void()), ...);
  if (!out) {
    py_io::throw_type_error(name, "a Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody, Gyrostat or TreeLink", obj);
  }
  return *out;
}

Body as_body(py::handle obj, const std::string& name) { return body_from(obj, name, static_cast<Body*>(nullptr)); }

py::object body_object(const Body& body) {
  return std::visit([](const auto& b) { return py::cast(b); }, body);
}

// obj as the state of kind `kind` (its state class: the alternative of BodyState at that index), or none
template <std::size_t... K>
std::optional<BodyState> state_of_kind(py::handle obj, std::size_t kind, std::index_sequence<K...>) {
  std::optional<BodyState> out;
  ((kind == K && is_instance<std::variant_alternative_t<K, BodyState>>(obj)
        ? (void)(out = obj.cast<const std::variant_alternative_t<K, BodyState>&>())
        : void()),
   ...);
  return out;
}

// The state of body i of `scene`, else TypeError naming `name`[i] (the message made only then).
BodyState as_body_state(py::handle obj, const Scene& scene, std::size_t i, const std::string& name) {
  const Body& body = scene.bodies[i];
  std::optional<BodyState> out =
      state_of_kind(obj, body.index(), std::make_index_sequence<std::variant_size_v<BodyState>>());
  if (!out) {
    py_io::throw_type_error(name + "[" + std::to_string(i) + "]",
                            std::string("a ") + state_type_name(body.index()) + " (the state of body " +
                                std::to_string(i) + " '" + body_name(scene, i) + "')",
                            obj);
  }
  return std::move(*out);
}

// One state per body of `scene`, in its order: a list or tuple of the bodies' state classes.
std::vector<BodyState> as_scene_states(py::handle obj, const Scene& scene, const std::string& name) {
  const std::size_t nb = scene.bodies.size();
  const auto expected = [nb] {
    return "a list of " + std::to_string(nb) + " body states (one per body of the scene, in order)";
  };
  if (!py::isinstance<py::list>(obj) && !py::isinstance<py::tuple>(obj)) py_io::throw_type_error(name, expected(), obj);
  const std::size_t given = py::len(obj);
  if (given != nb) py_io::throw_value_error(name, expected(), std::to_string(given) + " states");
  std::vector<BodyState> out;
  out.reserve(nb);
  for (std::size_t i = 0; i < nb; ++i) out.push_back(as_body_state(obj[py::int_(i)], scene, i, name));
  return out;
}

py::list states_object(const std::vector<BodyState>& states) {
  py::list out;
  for (const BodyState& s : states) out.append(std::visit([](const auto& x) { return py::cast(x); }, s));
  return out;
}

// ------------------------------------------------------------ building a scene

// Adds `body` named `name` (None: the default "body<i>"; names are unique, checked in O(1) by the scene's name
// index) with its mass flow (None: a constant mass). Returns its index.
int add_body(Scene& scene, py::handle body, py::handle name, py::handle mass_flow, const std::string& body_arg,
             const std::string& name_arg, const std::string& flow_arg) {
  Body b = as_body(body, body_arg);
  std::optional<MassFlow> flow = as_mass_flow(mass_flow, flow_arg);
  const std::string given = name.is_none() ? std::string() : py_io::as_string(name, name_arg);
  const std::string effective = given.empty() ? "body" + std::to_string(scene.bodies.size()) : given;
  if (const auto other = find_body(scene, effective)) {
    py_io::throw_value_error(name_arg, "a name no other body of the scene has ('" + effective + "' is body " +
                                           std::to_string(*other) + "'s)",
                             name.is_none() ? "None" : "'" + given + "'");
  }
  return static_cast<int>(rigiddyn::add_body(scene, std::move(b), given, std::move(flow)));
}

// Adds every link of `tree` (a copy, shared by its links) as a body, in link order (rigiddyn::add_tree); returns
// their indices.
py::tuple add_tree(Scene& scene, py::handle tree_obj, py::handle name) {
  auto tree = std::make_shared<const Tree>(py_io::as_instance<Tree>(tree_obj, "tree", "a Tree"));
  const std::string prefix = name.is_none() ? std::string() : py_io::as_string(name, "name");
  return py::tuple(py::cast(rigiddyn::add_tree(scene, std::move(tree), prefix)));
}

// Adds `element` after checking it against the bodies so far (its compiled term's checks, messages
// naming `name`: "element.bodies[0]: expected a body index in [0, 2), got 5"). Returns its index.
int add_element(Scene& scene, py::handle element, const std::string& name) {
  Element e = as_element(element, name);
  std::visit(
      [&](const auto& spec) {
        using Spec = std::decay_t<decltype(spec)>;
        using Term = typename Spec::Term;
        if constexpr (std::is_same_v<Spec, Thrust>) {  // it needs the body's mass flow
          const Term check(spec, scene.bodies, scene.mass_flows, name);
          (void)check;
        } else {
          const Term check(spec, scene.bodies, name);
          (void)check;
        }
      },
      e);
  scene.elements.push_back(std::move(e));
  return static_cast<int>(scene.elements.size() - 1);
}

// Scene(bodies, body_names, elements, frame, mass_flows), each item checked as add_body/add check it.
// The links of one tree that arrive as copies (an unpickled scene, links gathered from several scenes) made to share
// their link 0's tree where their trees are the same (same_tree): compile needs a tree's links to hold one tree.
void share_trees(Scene& scene) {
  std::shared_ptr<const Tree> first;  // the tree of the last link 0
  for (Body& body : scene.bodies) {
    auto* link = std::get_if<TreeLink>(&body);
    if (link == nullptr) {
      first.reset();
    } else if (link->link == 0) {
      first = link->tree;
    } else if (first && link->tree != first && same_tree(*link->tree, *first)) {
      link->tree = first;
    }
  }
}

Scene make_scene(py::handle bodies, py::handle body_names, py::handle elements, py::handle frame, py::handle mass_flows) {
  Scene scene;
  auto items = [](py::handle obj, const char* name) {
    if (obj.is_none()) return py::list();
    if (!py::isinstance<py::list>(obj) && !py::isinstance<py::tuple>(obj)) py_io::throw_type_error(name, "None or a list", obj);
    return py::list(py::reinterpret_borrow<py::object>(obj));
  };
  const py::list b = items(bodies, "bodies"), names = items(body_names, "body_names"), e = items(elements, "elements"),
                 flows = items(mass_flows, "mass_flows");
  if (!body_names.is_none() && names.size() != b.size()) {
    py_io::throw_value_error("body_names", "None or one name (str or None) per body (" + std::to_string(b.size()) + ")",
                             std::to_string(names.size()) + " names");
  }
  if (!mass_flows.is_none() && flows.size() != b.size()) {
    py_io::throw_value_error("mass_flows", "None or one MassFlow (or None) per body (" + std::to_string(b.size()) + ")",
                             std::to_string(flows.size()) + " items");
  }
  if (!frame.is_none()) scene.frame = as_scene_frame(frame, "frame");
  for (std::size_t i = 0; i < b.size(); ++i) {
    const std::string k = "[" + std::to_string(i) + "]";
    add_body(scene, b[i], body_names.is_none() ? py::none() : py::object(names[i]),
             mass_flows.is_none() ? py::none() : py::object(flows[i]), "bodies" + k, "body_names" + k, "mass_flows" + k);
  }
  share_trees(scene);
  for (std::size_t i = 0; i < e.size(); ++i) add_element(scene, e[i], "elements[" + std::to_string(i) + "]");
  return scene;
}

py::list bodies_list(const Scene& s) {
  py::list out;
  for (const Body& b : s.bodies) out.append(body_object(b));
  return out;
}
py::list raw_names_list(const Scene& s) {  // None for a body named by default
  py::list out;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const bool named = i < s.body_names.size() && !s.body_names[i].empty();
    out.append(named ? py::object(py::str(s.body_names[i])) : py::object(py::none()));
  }
  return out;
}
py::tuple names_tuple(const Scene& s) {
  py::tuple out(s.bodies.size());
  for (std::size_t i = 0; i < s.bodies.size(); ++i) out[i] = py::str(body_name(s, i));
  return out;
}
py::list elements_list(const Scene& s) {
  py::list out;
  for (const Element& e : s.elements) out.append(element_object(e));
  return out;
}
py::object frame_object(const Scene& s) { return s.frame ? py::cast(*s.frame) : py::object(py::none()); }
// None when every mass is constant, else one MassFlow or None per body.
py::object mass_flows_object(const Scene& s) {
  if (s.mass_flows.empty()) return py::none();
  py::list out;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) out.append(has_mass_flow(s, i) ? py::cast(*s.mass_flows[i]) : py::none());
  return std::move(out);
}

// The repr lists frame and mass_flows only when the scene has them (so that it reads as it was built).
std::string scene_repr(const Scene& s) {
  std::string text =
      repr_call("Scene", {{"bodies", bodies_list(s)}, {"body_names", raw_names_list(s)}, {"elements", elements_list(s)}});
  text.pop_back();
  if (s.frame) text += ", frame=" + py::repr(frame_object(s)).cast<std::string>();
  if (!s.mass_flows.empty()) text += ", mass_flows=" + py::repr(mass_flows_object(s)).cast<std::string>();
  return text + ")";
}

bool same_scene(const Scene& a, const Scene& b) {
  return bodies_list(a).equal(bodies_list(b)) && raw_names_list(a).equal(raw_names_list(b)) &&
         elements_list(a).equal(elements_list(b)) && frame_object(a).equal(frame_object(b)) &&
         mass_flows_object(a).equal(mass_flows_object(b));
}

// ------------------------------------------------------------ compiling

// Each warning of a compiled scene as a SceneCompatibilityWarning.
void warn_compatibility(const CompiledSceneHandle& h) {
  for (const std::string& w : h.compiled->warnings()) {
    if (PyErr_WarnEx(scene_compatibility_warning, w.c_str(), 2) != 0) throw py::error_already_set();
  }
}

// compile_scene(scene, method) (std::invalid_argument -> ValueError with the reason); with `warn`, each
// of its warnings as a SceneCompatibilityWarning.
CompiledSceneHandle compile_handle(const Scene& scene, Method method, bool warn) {
  CompiledSceneHandle h{scene, method, std::make_shared<const CompiledScene>(compile_scene(scene, method))};
  if (warn) warn_compatibility(h);
  return h;
}

Method as_method_name(py::handle method) { return method_from_name(py_io::as_string(method, "method"), "method"); }

// The compiled model a run of `model` uses: a CompiledScene itself (method None or its own; held by the caller's
// object, not owned here), or a Scene compiled for `method` (None: rk4), with its warnings.
std::shared_ptr<const CompiledSceneHandle> compiled_for(py::handle model, py::handle method) {
  if (is_instance<CompiledSceneHandle>(model)) {
    const auto& h = model.cast<const CompiledSceneHandle&>();
    if (!method.is_none() && as_method_name(method) != h.method) {
      py_io::throw_value_error("method", "None or '" + method_info(h.method).name + "' (the method `model` was compiled for)",
                               "'" + py::str(method).cast<std::string>() + "'");
    }
    return std::shared_ptr<const CompiledSceneHandle>(std::shared_ptr<void>(), &h);
  }
  return std::make_shared<const CompiledSceneHandle>(
      compile_handle(model.cast<const Scene&>(), method.is_none() ? Method::rk4 : as_method_name(method), true));
}

// The one-body scene of a body (rigiddyn::one_body_scene) compiled for `method` (None: rk4), with its warnings; kept
// from the previous call on this thread while the body, its gravity, loads and method are the same (one_body_key), so
// that a loop of short runs of one body compiles its scene once. Shared, so that a run in progress keeps its own when a
// call made during it (a progress callback's) replaces the kept one.
std::shared_ptr<const CompiledSceneHandle> compiled_for(const OneBodyInputs& body, py::handle method) {
  thread_local std::vector<double> last_key, key;
  thread_local std::shared_ptr<const CompiledSceneHandle> last;
  const Method m = method.is_none() ? Method::rk4 : as_method_name(method);
  one_body_key(body.body, body.g_W, body.loads, key);
  key.push_back(static_cast<double>(m));
  if (last == nullptr || !same_one_body_key(key, last_key)) {
    last = std::make_shared<const CompiledSceneHandle>(
        compile_handle(rigiddyn::one_body_scene(body.body, body.g_W, body.loads), m, false));  // throws before the cache changes
    last_key.swap(key);
  }
  warn_compatibility(*last);
  return last;
}

// A scene's forces are its elements: simulate's loads and gravity must be left out.
void refuse_body_arguments(py::handle loads, py::handle gravity) {
  if (!loads.is_none()) {
    py_io::throw_value_error("loads", "None for a scene (declare a ScheduledLoads element)", py_io::describe(loads));
  }
  if (!gravity.is_none() && !(py::isinstance<py::bool_>(gravity) && !gravity.cast<bool>())) {
    py_io::throw_value_error("gravity", "None for a scene (declare a UniformGravity element)", py_io::describe(gravity));
  }
}

// ------------------------------------------------------------ results

// The compiled terms' class names, in the order of the work and power columns: the scene's elements, then the
// frame's fictitious terms ("CentrifugalForce", ...).
py::tuple element_kinds(const CompiledScene& compiled) { return py::tuple(py::cast(compiled.element_types())); }

// The SceneResult of run r of `compiled` (of `scene`), made in place (its Python object takes it without a move).
std::unique_ptr<SceneResult> to_scene_result(SceneSimulation&& r, const Scene& scene, const CompiledScene& compiled,
                                             bool scalar_first) {
  const auto n = static_cast<py::ssize_t>(r.size());
  const auto nb = static_cast<py::ssize_t>(scene.bodies.size());
  const auto ne = static_cast<py::ssize_t>(compiled.element_types().size());
  if (scalar_first) to_scalar_first(r.q_WB);
  const py::tuple wheel_bodies = wheel_bodies_of(scene);
  const auto nw = static_cast<py::ssize_t>(wheel_bodies.size());
  const JointCounts joints = joint_counts(scene.bodies);
  return std::unique_ptr<SceneResult>(new SceneResult{LazyArray(std::move(r.t), {n}),
                     LazyArray(std::move(r.p_W), {n, nb, 3}),
                     LazyArray(std::move(r.q_WB), {n, nb, 4}),
                     LazyArray(std::move(r.v_W), {n, nb, 3}),
                     LazyArray(std::move(r.w_B), {n, nb, 3}),
                     LazyArray(std::move(r.kinetic_energy), {n}),
                     LazyArray(std::move(r.potential_energy), {n}),
                     LazyArray(std::move(r.total_energy), {n}),
                     LazyArray(std::move(r.linear_momentum_W), {n, 3}),
                     LazyArray(std::move(r.angular_momentum_W), {n, 3}),
                     LazyArray(std::move(r.pivot_reaction_W), {n, nb, 3}),
                     LazyArray(std::move(r.angular_momentum_O_W), {n, nb, 3}),
                     LazyArray(std::move(r.mass), {n, nb}),
                     LazyArray(std::move(r.work), {n, ne}),
                     LazyArray(std::move(r.power), {n, ne}),
                     r.mass_flow_energy.empty() ? LazyArray::zeros({n, nb})  // no mass flow: all 0
                                                : LazyArray(std::move(r.mass_flow_energy), {n, nb}),
                     names_tuple(scene),
                     element_kinds(compiled),
                     LazyArray(std::move(r.wheel_speed), {n, nw}),
                     LazyArray(std::move(r.motor_work), {n, nw}),
                     wheel_bodies,
                     LazyArray(std::move(r.joint_q), {n, static_cast<py::ssize_t>(joints.q)}),
                     LazyArray(std::move(r.joint_v), {n, static_cast<py::ssize_t>(joints.v)}),
                     r.diverged,
                     r.unconverged_steps,
                     r.elapsed_seconds,
                     scalar_first});
}

// The arrays of a SceneResult in pickle order, with their shapes after the record axis (-1: bodies,
// -2: elements).
struct ResultArray {
  const char* name;
  LazyArray SceneResult::*member;
  std::vector<py::ssize_t> tail;
};
const ResultArray result_arrays[] = {
    {"t", &SceneResult::t, {}},
    {"p_W", &SceneResult::p_W, {-1, 3}},
    {"q_WB", &SceneResult::q_WB, {-1, 4}},
    {"v_W", &SceneResult::v_W, {-1, 3}},
    {"w_B", &SceneResult::w_B, {-1, 3}},
    {"kinetic_energy", &SceneResult::kinetic_energy, {}},
    {"potential_energy", &SceneResult::potential_energy, {}},
    {"total_energy", &SceneResult::total_energy, {}},
    {"linear_momentum_W", &SceneResult::linear_momentum_W, {3}},
    {"angular_momentum_W", &SceneResult::angular_momentum_W, {3}},
    {"pivot_reaction_W", &SceneResult::pivot_reaction_W, {-1, 3}},
    {"angular_momentum_O_W", &SceneResult::angular_momentum_O_W, {-1, 3}},
    {"mass", &SceneResult::mass, {-1}},
    {"work", &SceneResult::work, {-2}},
    {"power", &SceneResult::power, {-2}},
    {"mass_flow_energy", &SceneResult::mass_flow_energy, {-1}},
};
constexpr std::size_t result_array_count = sizeof(result_arrays) / sizeof(result_arrays[0]);

// result.error of r (LazyError): a deferred estimate reads the answer's columns from r's own arrays (GIL held)
py::object result_error(const SceneResult& r) {
  return r.error.get([&r] {
    const auto data = [](const LazyArray& column) { return column.values().first; };
    SceneColumns c;
    std::size_t q_size = 0;
    std::tie(c.t, c.n) = r.t.values();
    std::tie(c.q_WB, q_size) = r.q_WB.values();
    c.scalar_first = r.scalar_first;
    c.bodies = c.n == 0 ? 0 : static_cast<std::int64_t>(q_size / (4 * c.n));
    c.w_B = data(r.w_B), c.p_W = data(r.p_W), c.v_W = data(r.v_W);
    c.total_energy = data(r.total_energy), c.angular_momentum_W = data(r.angular_momentum_W);
    std::tie(c.kinetic_energy, c.kinetic_energy_size) = r.kinetic_energy.values();
    std::tie(c.mass, c.mass_size) = r.mass.values();
    std::tie(c.angular_momentum_O_W, c.angular_momentum_O_W_size) = r.angular_momentum_O_W.values();
    std::tie(c.work, c.work_size) = r.work.values();
    std::tie(c.mass_flow_energy, c.mass_flow_energy_size) = r.mass_flow_energy.values();
    std::tie(c.motor_work, c.motor_work_size) = r.motor_work.values();
    return c;
  });
}

py::tuple scene_result_state(const SceneResult& r) {
  py::tuple out(result_array_count + 14);
  for (std::size_t i = 0; i < result_array_count; ++i) out[i] = (r.*(result_arrays[i].member)).get();
  out[result_array_count] = r.body_names;
  out[result_array_count + 1] = r.elements;
  out[result_array_count + 2] = py::bool_(r.diverged);
  out[result_array_count + 3] = py::int_(r.unconverged_steps);
  out[result_array_count + 4] = py::float_(r.elapsed_seconds);
  out[result_array_count + 5] = py::bool_(r.scalar_first);
  out[result_array_count + 6] = r.wheel_speed.get();
  out[result_array_count + 7] = r.motor_work.get();
  out[result_array_count + 8] = r.wheel_bodies;
  out[result_array_count + 9] = result_error(r);
  out[result_array_count + 10] = r.balance.get();
  out[result_array_count + 11] = r.choice;
  out[result_array_count + 12] = r.joint_q.get();
  out[result_array_count + 13] = r.joint_v.get();
  return out;
}

// result_array_count + 5, + 6, + 9, + 10, + 11 or + 12 items: a state without scalar_first (q_WB as (x, y, z, w)),
// without the wheels, without the error estimate, without the balance, without the choice of a run to a tolerance or
// without the joint columns, as earlier pickles
SceneResult scene_result_from_state(const py::tuple& t) {
  const std::size_t wheels = result_array_count + 9;  // the size of a state with the wheels
  if (t.size() != result_array_count + 5 && t.size() != result_array_count + 6 &&
      (t.size() < wheels || t.size() > wheels + 5 || t.size() == wheels + 4)) {
    py_io::throw_value_error("SceneResult pickle", "a tuple of " + std::to_string(result_array_count + 5) + ", " +
                             std::to_string(result_array_count + 6) + " or " + std::to_string(wheels) + " to " +
                             std::to_string(wheels + 3) + " or " + std::to_string(wheels + 5) + " items",
                             std::to_string(t.size()) + " items");
  }
  SceneResult r;
  r.body_names = py::tuple(t[result_array_count]);
  r.elements = py::tuple(t[result_array_count + 1]);
  const py::ssize_t n = py::len(t[0]);
  const auto nb = static_cast<py::ssize_t>(r.body_names.size()), ne = static_cast<py::ssize_t>(r.elements.size());
  for (std::size_t i = 0; i < result_array_count; ++i) {
    std::vector<py::ssize_t> shape{n};
    for (py::ssize_t d : result_arrays[i].tail) shape.push_back(d == -1 ? nb : d == -2 ? ne : d);
    Array a = Array::ensure(py::module_::import("numpy").attr("array")(t[i], "float64"));  // a copy
    bool ok = a && a.ndim() == static_cast<py::ssize_t>(shape.size());
    for (std::size_t d = 0; ok && d < shape.size(); ++d) ok = a.shape(d) == shape[d];
    if (!ok) {
      std::string expected = "shape (";
      for (std::size_t d = 0; d < shape.size(); ++d) expected += (d ? ", " : "") + std::to_string(shape[d]);
      py_io::throw_value_error(std::string("SceneResult pickle ") + result_arrays[i].name, expected + ")",
                               py_io::describe(t[i]));
    }
    py_io::set_read_only(a);
    r.*(result_arrays[i].member) = LazyArray(a);
  }
  r.diverged = t[result_array_count + 2].cast<bool>();
  r.unconverged_steps = t[result_array_count + 3].cast<std::int64_t>();
  r.elapsed_seconds = t[result_array_count + 4].cast<double>();
  r.scalar_first = t.size() >= result_array_count + 6 && t[result_array_count + 5].cast<bool>();
  r.wheel_bodies = t.size() >= wheels ? py::tuple(t[result_array_count + 8]) : py::tuple();
  if (t.size() >= wheels + 1) r.error = py::reinterpret_borrow<py::object>(t[wheels]);  // a GlobalError or None
  if (t.size() >= wheels + 2 && !t[wheels + 1].is_none()) r.balance = checked_balance(t[wheels + 1], "SceneResult pickle balance");
  if (t.size() >= wheels + 3 && !t[wheels + 2].is_none()) {
    if (!is_instance<ToleranceChoice>(t[wheels + 2])) {
      py_io::throw_type_error("SceneResult pickle choice", "a ToleranceChoice or None", t[wheels + 2]);
    }
    r.choice = py::reinterpret_borrow<py::object>(t[wheels + 2]);
  }
  const auto nw = static_cast<py::ssize_t>(r.wheel_bodies.size());
  // each wheel column, (n, nw) (empty in an earlier pickle)
  const auto wheel_column = [&](std::size_t at, const char* name) {
    Array a = t.size() >= wheels ? Array::ensure(py::module_::import("numpy").attr("array")(t[at], "float64"))
                                 : Array(std::vector<py::ssize_t>{n, 0});
    if (!a || a.ndim() != 2 || a.shape(0) != n || a.shape(1) != nw) {
      py_io::throw_value_error(std::string("SceneResult pickle ") + name,
                               "shape (" + std::to_string(n) + ", " + std::to_string(nw) + ")", py_io::describe(t[at]));
    }
    py_io::set_read_only(a);
    return a;
  };
  r.wheel_speed = LazyArray(wheel_column(result_array_count + 6, "wheel_speed"));
  r.motor_work = LazyArray(wheel_column(result_array_count + 7, "motor_work"));
  // the joint columns, (n, nq) and (n, nv) (empty in an earlier pickle)
  const auto joint_column = [&](std::size_t at, const char* name) {
    if (t.size() < wheels + 5) return Array(std::vector<py::ssize_t>{n, 0});
    Array a = Array::ensure(py::module_::import("numpy").attr("array")(t[at], "float64"));
    if (!a || a.ndim() != 2 || a.shape(0) != n) {
      py_io::throw_value_error(std::string("SceneResult pickle ") + name, "shape (" + std::to_string(n) + ", k)",
                               py_io::describe(t[at]));
    }
    py_io::set_read_only(a);
    return a;
  };
  r.joint_q = LazyArray(joint_column(wheels + 3, "joint_q"));
  r.joint_v = LazyArray(joint_column(wheels + 4, "joint_v"));
  return r;
}

}  // namespace

py::object one_body_scene(const Body& body, const Eigen::Vector3d& g_W, py::handle loads) {
  const std::vector<AppliedLoad> schedule = as_loads(loads);
  return py::cast(rigiddyn::one_body_scene(body, g_W, schedule));
}

py::tuple wheel_bodies_of(const Scene& scene) {
  py::list out;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    for (std::size_t k = 0; k < wheel_count(scene.bodies[b]); ++k) out.append(py::int_(b));
  }
  return py::tuple(out);
}

namespace {

std::string scene_result_repr(const SceneResult& r) {
  const Array t = r.t.get();
  const py::ssize_t n = t.shape(0);
  const py::object span = n == 0 ? py::object(py::list()) : py::object(py::make_tuple(t.at(0), t.at(n - 1)));
  return repr_call("SceneResult", {{"records", py::int_(n)},
                                   {"body_names", r.body_names},
                                   {"elements", r.elements},
                                   {"t", span},
                                   {"diverged", py::bool_(r.diverged)},
                                   {"unconverged_steps", py::int_(r.unconverged_steps)},
                                   {"elapsed_seconds", py::float_(r.elapsed_seconds)}});
}

bool all_finite(const Scene& scene, const std::vector<BodyState>& states) {
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (const auto* joint = std::get_if<JointState>(&states[i])) {  // a tree link's kinematics need the whole tree
      if (!(joint->q.allFinite() && joint->v.allFinite())) return false;
      continue;
    }
    const BodyKinematics k = kinematics_of(scene.bodies[i], states[i]);
    if (!(k.p_W.allFinite() && k.q_WB.coeffs().allFinite() && k.v_W.allFinite() && k.w_B.allFinite())) return false;
  }
  return true;
}

// Whether a step's result depends on its start time: a compiled term that does (a load with a time window, a
// Python force, the fictitious forces of a frame moving other than at a constant rotation: their traits), or a
// mass rate given as a function of t.
bool time_dependent(const CompiledScene& compiled) {
  for (const auto& flow : compiled.scene().mass_flows) {
    if (flow && !has_constant_rate(*flow)) return true;
  }
  for (const ElementTraits& traits : compiled.element_traits()) {
    if (traits.time_dependent) return true;
  }
  return false;
}

const char* const scene_doc = R"doc(Bodies and the force elements acting on them, as data, in a frame.

The bodies are Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody or Gyrostat; the elements
(UniformGravity, SpringDamper, Drag, ...) refer to bodies by index. The frame is W (inertial; the default) or the
SceneFrame `frame`: states, elements and records are then relative to it, with its fictitious forces compiled in.
A body may carry a MassFlow (its mass changes; a Thrust element gives its force). Compile it for a method with
compile(method) (a CompiledScene, immutable), or give it to rigiddyn.simulate / rigiddyn.step, which compile it.
Mutable (add_body, add, frame); pickles; == compares bodies, names, elements, frame and mass flows.

Parameters
----------
bodies : sequence of bodies, optional
    The bodies, indexed in order (add_body appends more).
body_names : sequence of str or None, optional
    One name or None per body (records and DataFrame columns use them).
elements : sequence of force elements, optional
    Checked against the bodies (add bodies first).
frame : SceneFrame or None, default None
    The frame the states are relative to; None: W.
mass_flows : sequence of MassFlow or None, optional
    One per body (None: a constant mass).

Raises
------
TypeError, ValueError
    A body, element or frame that is not valid, or an element naming a body that does not exist (the message
    names it).

See Also
--------
simulate : runs the scene.
load_scene : reads one from a TOML file (with units).
CompiledScene : the scene compiled for one method.

Examples
--------
)doc"
    R"doc(A satellite in a circular low Earth orbit keeps its orbital energy to RK4's error:

>>> scene = rd.Scene()
>>> scene.add_body(rd.RigidBody(500.0, [400.0, 300.0, 200.0]), name="sat")
0
>>> scene.add(rd.PointMassGravity(gm=3.986004418e14))
0
>>> start = rd.RigidBodyState(p_W=[7e6, 0.0, 0.0], v_W=[0.0, 7546.0, 0.0])
>>> result = rd.simulate(scene, [start], dt=1.0, steps=6000, method="rk4")
>>> result.body_names, result.elements
(('sat',), ('PointMassGravity',))
>>> E = result.total_energy
>>> bool(abs(E[-1] - E[0]) < 1e-12 * abs(E[0]))
True

The same kind of scene from lists, as repr prints it:

>>> rd.Scene([rd.Particle(1.0)], elements=[rd.UniformGravity()])
Scene(bodies=[Particle(mass=1.0)], body_names=[None], elements=[UniformGravity(g_W=[0.0, 0.0, -9.81], bodies=None)])
)doc";

const char* const compiled_scene_doc = R"doc(A scene compiled for one method: immutable; its derivative evaluates only the declared elements.

CompiledScene(scene, method='rk4') is scene.compile(method). Give it to rigiddyn.simulate / rigiddyn.step
(method None or its own). Pickles (as its scene and method); == compares both.

Parameters
----------
scene : Scene
    The bodies and elements (copied: later changes to the scene do not reach it).
method : str, default 'rk4'
    A name from methods(); a method the scene cannot take is refused here (ValueError naming it).

Examples
--------
)doc"
    R"doc(Compile once, run many times (here the DLM splitting, whose derivative evaluates the declared elements only):

>>> scene = rd.Scene([rd.Particle(1.0)], elements=[rd.UniformGravity()])
>>> compiled = scene.compile("splitting_dlm")
>>> compiled == rd.CompiledScene(scene, "splitting_dlm")
True
>>> result = rd.simulate(compiled, [rd.ParticleState()], 0.1, steps=10)
>>> result.p_W[-1, 0].round(12)
array([ 0.   ,  0.   , -4.905])
)doc";

const char* const scene_result_doc = R"doc(The records of simulate(scene, ...): one row per record, every array read-only.

n records, nb bodies in the scene's order, ne elements in the scene's order; every array shares the memory the
C++ run filled. "W" is the scene frame: W itself, or the scene's SceneFrame F (every array is then relative to
F). Made by simulate (no public constructor).

Attributes
----------
t : ndarray, shape (n,)
    Record times [s].
p_W, v_W : ndarray, shape (n, nb, 3)
    Centre of mass positions [m] and velocities [m/s] in W (a pinned body: its centre of mass).
q_WB : ndarray, shape (n, nb, 4)
    Attitudes, (x, y, z, w) unless simulate(..., scalar_first=True).
w_B : ndarray, shape (n, nb, 3)
    Angular velocities [rad/s] in each body's B. A particle records q_WB = identity and w_B = 0; a planar body
    p_W = (x, y, 0), q_WB = Rz(theta), w_B = (0, 0, omega).
pivot_reaction_W : ndarray, shape (n, nb, 3)
    The pivot's force on each body in W [N] (0 unpinned).
angular_momentum_O_W : ndarray, shape (n, nb, 3)
    Each body's angular momentum about its pivot (about its centre of mass unpinned), in W [kg m^2/s].
mass : ndarray, shape (n, nb)
    Masses [kg].
kinetic_energy, potential_energy, total_energy : ndarray, shape (n,)
    [J]; the kinetic energy relative to W; the potential energy is the sum of the elements' potentials, and the
    centrifugal one of a frame turning at a constant rate (total_energy is then the Jacobi integral).
linear_momentum_W : ndarray, shape (n, 3)
    [kg m/s] in W.
angular_momentum_W : ndarray, shape (n, 3)
    About W's origin [kg m^2/s].
work, power : ndarray, shape (n, ne)
    Each element's work since t0 [J] and its power at the record [W]; the columns are the scene's elements, then
    the frame's fictitious terms that act (CentrifugalForce, CoriolisForce, ...).
mass_flow_energy : ndarray, shape (n, nb)
    Each body's mass-flow energy since t0 [J]: the integral of 1/2 (dm/dt) |v|^2 + 1/2 w.(dI/dt) w, the kinetic
    energy its mass flow takes away or brings at its own velocity (0 for a constant mass).
body_names : tuple of str, shape (nb,)
    Label the body axis.
elements : tuple of str, shape (ne,)
    Each work and power column's class name.
diverged : bool
    True if the run stopped on a non-finite state.
unconverged_steps : int
    Steps whose implicit solve stopped at its iteration cap (0 for explicit methods).
elapsed_seconds : float
    Wall time of the C++ stepping loop [s].

Notes
-----
The work-energy balance, integrated by the run's method (to its error):
kinetic_energy - kinetic_energy[0] ~ work.sum(axis=1) + mass_flow_energy.sum(axis=1) (without a MassFlow the
last sum is 0: the work alone).

Examples
--------
Two particles under gravity: the change of kinetic energy is the work of gravity.

)doc"
    R"doc(>>> scene = rd.Scene([rd.Particle(2.0), rd.Particle(1.0)], elements=[rd.UniformGravity()])
>>> result = rd.simulate(scene, [rd.ParticleState(), rd.ParticleState(v_W=(1.0, 0.0, 0.0))], 0.01, steps=100)
>>> result.t.shape, result.p_W.shape, result.work.shape
((101,), (101, 2, 3), (101, 1))
>>> T = result.kinetic_energy
>>> bool(np.allclose(T - T[0], result.work.sum(axis=1), atol=1e-12))
True
)doc";

constexpr const char* add_tree_doc = R"doc(Adds every link of `tree` as a body of the scene, in link order; returns their indices.

Each link is a body (a TreeLink) that force elements act on, by its index or name: gravity at its centre of mass,
springs and drag at its points (given from its centre of mass, in axes parallel to its link frame), Python forces.
The tree's joints hold the links together: a run integrates the tree's q and v by the articulated-body algorithm
with the elements' wrenches as each link's external force. Each link body's state is a JointState (its joint's q
and v; Tree.joint_states makes them), and its records are the link's motion (centre of mass in W, R_WL, w_L).

Parameters
----------
tree : Tree
    The tree (copied), with no gravity of its own (add a UniformGravity element instead).
name : str, optional
    Names the bodies "<name>.<link name>" (None: each link's own name). No other body may have those names.

Returns
-------
tuple of int
    The bodies' indices, one per link.

Raises
------
ValueError
    A tree with no link or with gravity of its own, or a link name another body has (naming it).

See Also
--------
Tree, JointState, Tree.joint_states, Tree.coordinates_of

Notes
-----
A tree runs with the methods that integrate the whole motion (explicit_euler, semi_implicit_euler, rk4, rkmk4,
implicit_midpoint); the splittings need each body's free motion in closed form, which joined links do not have.

Examples
--------
A double pendulum of two rods released horizontal under gravity keeps its energy to RK4's error:

>>> rod = rd.SpatialInertia(1.0, [0.5, 0, 0], np.diag([1e-3, 1 / 12, 1 / 12]))
>>> tree = rd.Tree()
>>> tree.add_link("upper", -1, rd.RevoluteJoint([0, 1, 0]), rod)
0
>>> tree.add_link("lower", 0, rd.RevoluteJoint([0, 1, 0]), rod, rd.Transform(translation=[1, 0, 0]))
1
>>> scene = rd.Scene(elements=[rd.UniformGravity()])
>>> scene.add_tree(tree, "pendulum")
(0, 1)
>>> result = rd.simulate(scene, tree.joint_states([0.0, 0.0]), 0.001, duration=1.0, method="rk4")
>>> bool(abs(result.total_energy[-1] - result.total_energy[0]) < 1e-9)
True
>>> result.joint_q.shape  # the joint angles at each record
(1001, 2)
)doc";

}  // namespace

bool is_scene(py::handle model) {
  return is_instance<Scene>(model) || is_instance<CompiledSceneHandle>(model);
}

// Why a scene's momentum balances do not apply to its run ("" when they do; rigiddyn._balance): a force the impulses
// do not hold acts (a constraint's reaction, the momentum a mass flow carries, the exact Coriolis kick: the scenes of
// the fast models among them, which integrate no impulses), or the run is the closed form.
std::string momentum_balance_not_applicable(const CompiledScene& compiled) {
  const Scene& scene = compiled.scene();
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& b = scene.bodies[i];
    if (std::holds_alternative<PivotedBody>(b) || std::holds_alternative<PivotedPlanarBody>(b)) {
      return "a pinned body's pivot reaction is an external force whose impulse is not integrated";
    }
    if (std::holds_alternative<PlanarBody>(b)) return "a planar body's plane takes forces whose impulse is not integrated";
    if (const auto* link = std::get_if<TreeLink>(&b); link && link->link == 0 &&
                                                       !std::holds_alternative<FreeJoint>(link->tree->link(0).joint)) {
      return "a tree held by a joint to W takes its base's reaction, whose impulse is not integrated";
    }
    if (has_mass_flow(scene, i)) return "a mass flow carries momentum that is not integrated";
  }
  for (const std::string& type : compiled.element_types()) {
    if (type == "CoriolisForce") return "the Coriolis kick of a turning frame is not integrated into the impulses";
  }
  if (compiled.closed_form() && compiled.one_body_plan().loads_element >= 0) {
    return "the closed form of the run does not integrate the loads' impulses";
  }
  return {};
}

// The balance of a scene's run r of h at step dt (balance.hpp)
RunBalance scene_run_balance(const SceneSimulation& r, const CompiledSceneHandle& h, double dt) {
  return scene_balance(r, momentum_balance_not_applicable(*h.compiled), dt);
}

// The balance of a scene's run r of h at step dt (`made`, or made here), checked (accuracy_check.hpp) against its
// estimate e (null: none) at `level`: the balance with its verdicts and the AccuracyWarning's message ("" when it
// closes).
std::pair<RunBalance, std::string> checked_scene_balance(const SceneSimulation& r, const CompiledSceneHandle& h,
                                                         double dt, const GlobalErrorEstimate* e,
                                                         const std::optional<double>& level,
                                                         std::optional<RunBalance>&& made = std::nullopt) {
  RunBalance balance = made ? std::move(*made) : scene_run_balance(r, h, dt);
  BalanceBounds bounds;
  if (e != nullptr) bounds = scene_estimate_bounds(*e, r);
  std::string message = check_accuracy(balance, accuracy_check_of(level, r.t, e, &bounds, method_info(h.method).name, dt));
  return {std::move(balance), std::move(message)};
}

// The SceneResult of a run of h at step dt as its Python object: its error estimate (made, or `deferred`: made on
// its first read) and choice as given, its balance (`balance`, or made here) checked in the core with the
// AccuracyWarning at `level` when it does not close. A deferred estimate's balance closes under any estimate
// (simulate_scene_py: closes_under_any_estimate), so that its check, which would find nothing, is not made.
py::object scene_result_object(SceneSimulation&& r, const CompiledSceneHandle& h, double dt, bool scalar_first,
                               std::optional<GlobalErrorEstimate>&& estimate, py::object choice,
                               const std::optional<double>& level, std::optional<RunBalance>&& balance = std::nullopt,
                               LazyError deferred = LazyError()) {
  const GlobalErrorEstimate* e = estimate ? &*estimate : nullptr;
  std::pair<RunBalance, std::string> checked =
      deferred.pending() && balance
          ? std::pair<RunBalance, std::string>(std::move(*balance), std::string())
          : with_gil_released_for(r.size(),
                                  [&]() { return checked_scene_balance(r, h, dt, e, level, std::move(balance)); });
  warn_accuracy(checked.second, level, r.diverged);
  std::unique_ptr<SceneResult> result = to_scene_result(std::move(r), h.scene, *h.compiled, scalar_first);
  result->error = estimate ? LazyError(py::cast(to_global_error(std::move(*estimate)))) : std::move(deferred);
  result->choice = std::move(choice);
  result->balance = LazyBalance(std::move(checked.first));
  return py::cast(std::move(result));
}

// The quantity a tolerance bounds by default for a scene: the attitude when a body turns, else the position.
ErrorMeasure default_scene_measure(const Scene& scene) {
  for (const Body& body : scene.bodies) {
    if (!std::holds_alternative<Particle>(body)) return ErrorMeasure::attitude;
  }
  return ErrorMeasure::position;
}

// The row-major (n, width) array of `values`.
py::array_t<double> rows(const std::vector<double>& values, py::ssize_t width) {
  py::array_t<double> out({static_cast<py::ssize_t>(values.size()) / width, width});
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

// The shipped law (scene/control_laws.hpp) of a rigiddyn.control.BDot or PDAttitude `law` (checked by its Python
// constructor) on `scene`, or none for any other law (a PDAttitude with a callable target included): those run in
// Python. ValueError naming controller.law.body for a body out of range.
std::optional<ControlLaw> shipped_law(py::handle law, const Scene& scene) {
  const py::module_ control = py::module_::import("rigiddyn.control");
  const bool bdot = py::type::of(law).is(control.attr("BDot")), pd = py::type::of(law).is(control.attr("PDAttitude"));
  if (!bdot && !pd) return std::nullopt;
  const int body = py_io::as_int(law.attr("body"), "controller.law.body", 0);
  if (body >= static_cast<int>(scene.bodies.size())) {
    py_io::throw_value_error("controller.law.body", "a body index in [0, " + std::to_string(scene.bodies.size()) + ")",
                             std::to_string(body));
  }
  if (bdot) {
    const MagneticDipoleTerm field(law.attr("dipole").cast<MagneticDipole>(), scene.bodies, "controller.law.dipole");
    const py::object m_max = law.attr("m_max");
    const double saturation = m_max.is_none() ? std::numeric_limits<double>::infinity() : m_max.cast<double>();
    const auto rate = law.attr("rate").cast<std::string>() == "gyro" ? BDotLaw::Rate::gyro : BDotLaw::Rate::difference;
    return ControlLaw(BDotLaw(law.attr("gain").cast<double>(), field, law.attr("element").cast<int>(), body, saturation, rate));
  }
  const py::object target = law.attr("q_target_WB");
  if (PyCallable_Check(target.ptr())) return std::nullopt;
  using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;
  std::optional<Eigen::Quaterniond> q_target_WB;
  if (!py::isinstance<py::str>(target)) {  // else 'lvlh'
    const Rows q(target);
    if (q.size() != 4) py_io::throw_value_error("controller.law.q_target_WB", "4 values (x, y, z, w)", std::to_string(q.size()));
    q_target_WB = Eigen::Quaterniond(q.data()[3], q.data()[0], q.data()[1], q.data()[2]);
  }
  const Rows P(law.attr("_allocation"));  // (nw, 3), checked by PDAttitude
  const Eigen::MatrixXd allocation =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(P.data(), P.shape(0), 3);
  return ControlLaw(PDAttitudeLaw(law.attr("k_p").cast<double>(), law.attr("k_d").cast<double>(), allocation,
                                  q_target_WB, body));
}

// A rigiddyn.control.BDot commands a magnetorquer: ValueError naming controller.law.element unless that element of
// `scene` is a MagneticDipole (a ScheduledLoads takes a command too, which would read the dipole as a force). An
// index out of range is left to the sample, which names it.
void check_bdot_element(py::handle law, const Scene& scene) {
  if (!py::type::of(law).is(py::module_::import("rigiddyn.control").attr("BDot"))) return;
  const int e = py_io::as_int(law.attr("element"), "controller.law.element", 0);
  if (e >= static_cast<int>(scene.elements.size()) || std::holds_alternative<MagneticDipole>(scene.elements[e])) return;
  py_io::throw_value_error("controller.law.element", "the index of a MagneticDipole in the scene (the magnetorquer "
                           "the law commands)", std::to_string(e) + " (a " + element_type_name(scene.elements[e]) + ")");
}

// The C++ Controller of a rigiddyn.Controller (rigiddyn/control.py, which checks the law's commands) on `scene`: its
// period, and a shipped law in C++ (shipped_law: without gyro noise) or a law that takes the GIL and calls its
// _sample(t, p_W, q_WB, v_W, w_B, wheel_speed, joint_q, joint_v) -> (wheel_torque or None, [(element, value (3,) or
// a number as a float: a ReactionWheel's speed [rad/s], a joint motor's torque [N m] or force [N]), ...]). The
// Python object outlives the run (the caller holds it). *shipped: whether the law runs in C++ (a copy of the
// Controller taken before a run then starts another run afresh: the law's state, a B-dot's last field, is in the
// copy).
Controller as_controller(py::handle controller, const Scene& scene, bool* shipped) {
  if (!py::isinstance(controller, py::module_::import("rigiddyn.control").attr("Controller"))) {
    py_io::throw_type_error("controller", "a rigiddyn.Controller or None", controller);
  }
  check_bdot_element(controller.attr("law"), scene);
  Controller out;
  out.period = py_io::as_scalar(controller.attr("period"), "controller.period");
  *shipped = false;
  if (controller.attr("w_B_noise").cast<double>() == 0.0) {
    if (std::optional<ControlLaw> law = shipped_law(controller.attr("law"), scene)) {
      out.law = std::move(*law);
      *shipped = true;
      return out;
    }
  }
  out.law = [sample = py::object(controller.attr("_sample"))](const SampledState& s) {
    py::gil_scoped_acquire gil;
    const py::tuple r = sample(s.t, rows(s.p_W, 3), rows(s.q_WB, 4), rows(s.v_W, 3), rows(s.w_B, 3),
                               rows(s.wheel_speed, 1).attr("ravel")(), rows(s.joint_q, 1).attr("ravel")(),
                               rows(s.joint_v, 1).attr("ravel")())
                            .cast<py::tuple>();
    ActuatorCommands c;
    if (!r[0].is_none()) {
      for (const py::handle u : r[0]) c.wheel_torque.push_back(u.cast<double>());
    }
    for (const py::handle item : r[1]) {
      const py::tuple command = item.cast<py::tuple>();
      if (py::isinstance<py::float_>(command[1])) {  // a ReactionWheel's speed [rad/s], a joint motor's force
        c.scalars.push_back({command[0].cast<int>(), command[1].cast<double>()});
      } else {
        c.elements.push_back({command[0].cast<int>(), py_io::as_vector3(command[1], "controller command")});
      }
    }
    return c;
  };
  return out;
}

// Whether the global error estimate may sample the law of `controller` (a rigiddyn.Controller on `scene`) again, from
// copies: a shipped law (in C++, or a Python object of a shipped class where gyro noise takes it through Python), or a
// controller declared repeatable.
bool repeatable_law(py::handle controller, const Scene& scene) {
  return controller.attr("repeatable").cast<bool>() || shipped_law(controller.attr("law"), scene).has_value();
}

// A controller as `controller` (a rigiddyn.Controller on `scene`, its law in Python or its gyro noise drawn in
// Python: repeatable_law) is now, for another run: a copy.deepcopy of it (the law's attributes and the noise
// generator's state), so that the run samples the law and draws the noise as a run from now does. Made with the
// GIL; TypeError naming controller.law where it cannot be copied, with `why` (what runs the law again, and what to
// pass instead).
Controller controller_copy(py::handle controller, const Scene& scene, const char* why) {
  const py::object deepcopy = py::module_::import("copy").attr("deepcopy");
  py::object copy;
  try {
    copy = deepcopy(controller);
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_Exception)) throw;
    const std::string message = "controller.law: expected a law that copy.deepcopy copies (" + std::string(why) +
                                "), got " + py::repr(controller.attr("law")).cast<std::string>() + " (" +
                                py::str(e.value()).cast<std::string>() + ")";
    py::raise_from(e, PyExc_TypeError, message.c_str());
    throw py::error_already_set();
  }
  bool shipped = false;
  return as_controller(copy, scene, &shipped);
}

// The controllers of the estimate's two coarse runs (global_error.hpp) of a run under `controller`, each a
// controller_copy made before the run, so that each coarse run samples the law as the run does.
std::vector<Controller> coarse_controllers(py::handle controller, const Scene& scene) {
  std::vector<Controller> out;
  for (int k = 0; k < 2; ++k) {
    out.push_back(controller_copy(controller, scene,
                                  "the global error estimate runs it again at 2 dt and 4 dt, each from a copy; or pass "
                                  "error=False"));
  }
  return out;
}

// The controllers of a run to a tolerance under `controller` (a rigiddyn.Controller on `scene`): a fresh one for each
// run the planner makes (its pilots, the run and its estimate's runs), each the controller as it is before any run (a
// law in C++ copied; a law in Python, declared repeatable, a copy.deepcopy made with the GIL), so that every run
// samples the law as the first would. The copies are kept until the object goes, with the GIL held (a law in Python
// holds Python objects). ValueError naming tolerance for a law in Python that is not declared repeatable.
class RunControllers {
 public:
  RunControllers(py::handle controller, const Scene& scene)
      : controller_(py::reinterpret_borrow<py::object>(controller)), scene_(scene) {
    bool shipped = false;
    pristine_ = as_controller(controller, scene, &shipped);
    require_positive(pristine_.period, "controller.period");
    if (shipped) return;
    if (!repeatable_law(controller, scene)) {
      py_io::throw_value_error("tolerance", "None under a controller whose law in Python is sampled by the run alone "
                               "(the planner's runs and the certificate's sample it again: declare it Controller(..., "
                               "repeatable=True), or pass dt=)", py::str(controller.attr("law")).cast<std::string>());
    }
    python_ = true;
  }
  RunControllers(const RunControllers&) = delete;
  RunControllers& operator=(const RunControllers&) = delete;

  double period() const { return pristine_.period; }
  // A fresh controller for the next run (callable without the GIL; the planner's runs come one after the other).
  const Controller& next() {
    if (!python_) return copies_.emplace_back(pristine_);
    py::gil_scoped_acquire gil;
    return copies_.emplace_back(controller_copy(
        controller_, scene_, "tolerance= runs it again in each of its runs, each from a copy; or pass dt="));
  }

 private:
  py::object controller_;
  const Scene& scene_;
  Controller pristine_;
  bool python_ = false;
  std::deque<Controller> copies_;  // (a deque: a copy stays where it is while its run uses it)
};

// The steps of a grid over the horizon T [s] on which every run's step divides controller.period / 4 (4 T / period of
// them: ToleranceRequest::grid_steps); ValueError naming duration where T is not a whole number of period / 4 (within
// 1e-9 relative: the rounding of a duration and a period given in decimals).
std::int64_t controller_grid_steps(double horizon, double period) {
  const double blocks = 4.0 * horizon / period;
  const double whole = std::round(blocks);
  if (!(whole >= 1.0) || std::abs(blocks - whole) > 1e-9 * blocks || whole > 9e15) {
    py_io::throw_value_error("duration",
                             "a whole number of controller.period / 4 = " + format_value(period / 4.0) +
                                 " s under tolerance= (every run's step then divides the period four times over, so "
                                 "that the certificate's runs at 2 dt and 4 dt step onto every sample)",
                             format_value(horizon) + " s");
  }
  return static_cast<std::int64_t>(whole);
}

// Appends the likely cause to every "not asymptotic" verdict of `e`, the estimate of a run of step dt under a
// controller sampled every `period` [s] that is not a whole number of 4 dt: the samples split the steps of the runs at
// 2 dt and 4 dt unlike those at dt, so that their errors are not the same multiple of dt^p, the premise of Richardson
// extrapolation (global_error.hpp; measured: a tumbling body under a constant thrust sampled every 0.1 s by rk4 is
// reliable at 1 % of its records with dt = 0.02 s, 99.5 % with 0.005 s). A whole number within 1e-9 relative: the
// rounding of a period and a dt given in decimals.
void name_off_grid_samples(GlobalErrorEstimate& e, double period, double dt) {
  const double steps_of_4dt = period / (4.0 * dt);
  if (std::abs(steps_of_4dt - std::round(steps_of_4dt)) <= 1e-9 * steps_of_4dt) return;
  char shortest[32];  // the period's shortest text that reads back as the same double
  const std::string_view every(shortest, static_cast<std::size_t>(std::to_chars(shortest, shortest + 32, period).ptr -
                                                                   shortest));
  const std::string cause = " (the controller's samples every " + std::string(every) +
                            " s split the steps of the runs at 2 dt and 4 dt unlike those at dt: a period that is a "
                            "multiple of 4 dt keeps them alike)";
  std::map<std::uint32_t, std::uint32_t> with_cause;  // a verdict's text → the text with its cause
  for (std::size_t i = 0; i < e.verdict.size(); ++i) {
    const std::uint32_t k = e.verdict.text_index(i);
    if (e.verdict.texts()[k].rfind("not asymptotic", 0) != 0) continue;
    auto found = with_cause.find(k);
    if (found == with_cause.end()) {
      const std::string text = e.verdict.texts()[k] + cause;  // a copy: add_text may move the texts
      found = with_cause.emplace(k, e.verdict.add_text(text)).first;
    }
    e.verdict.set_text(i, found->second);
  }
}

// result.error of a run of `compiled` from `initial` under options o (and the control law `pristine` as it was before
// the run: a law in C++, each coarse run under a fresh copy of it), made on its first read (LazyError): the estimate's
// two coarse runs (global_error.hpp) compared with the run's records, which its result keeps; the same values as the
// estimate made at once, bit for bit (a scene without an opaque force, under no law or a law in C++, is
// deterministic).
std::shared_ptr<DeferredEstimate> deferred_estimate(std::shared_ptr<const CompiledScene> compiled,
                                                    std::vector<BodyState> initial, SimulationOptions o,
                                                    std::optional<Controller> pristine) {
  o.monitor = nullptr;  // the run's monitor is gone by then
  auto d = std::make_shared<DeferredEstimate>();
  const int order = scene_order(*compiled);
  d->make = [compiled = std::move(compiled), initial = std::move(initial), o, order, pristine = std::move(pristine)](
                const SceneColumns& answer, PythonMonitor& monitor) -> std::optional<GlobalErrorEstimate> {
    bool interrupted = false;
    const auto run = [&](SimulationOptions coarse) {
      coarse.estimate_records = true;  // what the estimate reads of it
      coarse.monitor = coarse_monitor(monitor);
      if (!pristine) return simulate(*compiled, initial, coarse);
      const Controller fresh = *pristine;
      return simulate(*compiled, initial, coarse, fresh);
    };
    GlobalErrorEstimate e =
        global_error_of(answer_records(answer, o, order), o, order, interruptible(run, interrupted));
    if (interrupted) return std::nullopt;
    if (pristine) name_off_grid_samples(e, pristine->period, o.dt);
    return e;
  };
  return d;
}

// simulate(..., tolerance=) of a scene: a Scene is compiled for each candidate it takes (a CompiledScene is its
// own only candidate), each at the order it has (scene_order); the planner (tolerance.hpp) with the GIL released;
// ToleranceError when the tolerance is not met, or before any run for a force the certificate cannot check. Every run
// steps onto the loads' switch times at dt, 2 dt and 4 dt (grid_steps_through). Under a controller (None or a
// rigiddyn.Controller) each run samples a fresh copy of it (RunControllers) at steps that divide its period four times
// over (controller_grid_steps), and the closed form 'exact', which takes no law, is no candidate.
py::object simulate_scene_to_tolerance(py::handle model, py::handle method, const std::vector<BodyState>& initial,
                                       const CompiledSceneHandle& given, SimulationOptions base, const ToleranceArgs& a,
                                       py::handle progress, bool scalar_first, const std::optional<double>& level,
                                       py::handle controller) {
  if ((a.measure == ErrorMeasure::attitude || a.measure == ErrorMeasure::angular_velocity) &&
      default_scene_measure(given.scene) == ErrorMeasure::position) {  // its estimate would be round-off alone
    py_io::throw_value_error("measure",
                             "'position', 'velocity', 'energy' or 'angular_momentum' for a scene of particles "
                             "(none has an attitude)",
                             "'" + error_measure_name(a.measure) + "'");
  }
  const std::string opaque = opaque_force(*given.compiled);
  if (!opaque.empty()) {
    refuse_tolerance(opaque, "a force the core cannot see into may switch inside a step, which the global error "
                             "estimate cannot check (it is never called reliable); pass dt= and read result.error");
  }
  std::optional<RunControllers> controllers;
  if (!controller.is_none()) controllers.emplace(controller, given.scene);
  // every run's 4 dt ends at each of the loads' switch times (where they are fractions of the horizon that a grid of
  // at most switch_grid_limit steps holds; elsewhere the certificate takes no failing record), and divides a
  // controller's period
  std::int64_t grid_steps = controllers ? controller_grid_steps(a.horizon, controllers->period()) : 0;
  std::vector<double> switches = switch_times(given.compiled->switch_schedule(), base.t0, base.t0 + a.horizon);
  const std::int64_t switch_grid = grid_steps_through(switches, base.t0, a.horizon,
                                                      std::min(a.max_steps, switch_grid_limit));
  if (switch_grid > 1) grid_steps = on_grid(switch_grid, grid_steps);
  const bool fixed = is_instance<CompiledSceneHandle>(model) || !method.is_none();
  // the candidates, each compiled and probed only where the planner runs it (admit); the method asked for at once, its
  // refusal being the answer
  std::vector<ToleranceCandidate> candidates;
  for (const Method m : fixed ? std::vector<Method>{given.method} : tolerance_methods()) {
    if (controllers && m == Method::exact && !fixed) continue;
    candidates.push_back({m, scene_order(*given.compiled, m), plain_twin(m, given.scene.bodies)});
  }
  const auto index_of = [&](Method m) {
    return static_cast<std::size_t>(std::find_if(candidates.begin(), candidates.end(),
                                                 [&](const ToleranceCandidate& c) { return c.method == m; }) -
                                    candidates.begin());
  };
  std::vector<std::optional<CompiledSceneHandle>> compiled(candidates.size());  // each candidate's, once admitted
  // the scene compiled for m and a one-step run over the horizon: what the run refuses (std::invalid_argument: e.g.
  // 'exact' with a couple in a load)
  const auto compiled_and_probed = [&](Method m) {
    CompiledSceneHandle handle = m == given.method ? given : compile_handle(given.scene, m, false);
    SimulationOptions probe = base;
    probe.method = m, probe.dt = a.horizon, probe.steps = 1, probe.monitor = nullptr;
    simulate(*handle.compiled, initial, probe);
    compiled[index_of(m)] = std::move(handle);
  };
  if (fixed) compiled_and_probed(given.method);
  const auto admit = [&](const ToleranceCandidate& c) {
    if (compiled[index_of(c.method)]) return true;
    try {
      compiled_and_probed(c.method);
      return true;
    } catch (const std::invalid_argument&) {
      return false;  // a method the scene does not take
    }
  };
  PythonMonitor monitor(progress);
  if (monitor.needed()) base.monitor = [&monitor](std::int64_t steps_done) { return monitor(steps_done); };
  ToleranceRun<SceneSimulation> run;
  {
    py::gil_scoped_release release;
    run = run_to_tolerance<SceneSimulation>(
        candidates, base, {a.tolerance, a.measure, a.horizon, a.max_steps, 0.5, grid_steps, std::move(switches)},
        [&](const ToleranceCandidate& c, const SimulationOptions& o) {
          const CompiledScene& model_of_c = *compiled[index_of(c.method)]->compiled;
          SimulationOptions x = o;
          x.method = c.method;
          if (controllers) return simulate(model_of_c, initial, x, controllers->next());
          return simulate(model_of_c, initial, x);
        },
        admit);
  }
  if (run.interrupted) monitor.raise();
  if (!run.ran) raise_tolerance_error(run.choice, py::none());
  SimulationOptions final_options = base;
  final_options.method = run.choice.method, final_options.dt = run.choice.dt, final_options.steps = run.choice.steps;
  warn_after_run(run.records, final_options, method_info(run.choice.method).name);
  py::object result = scene_result_object(std::move(run.records), *compiled[index_of(run.choice.method)], run.choice.dt,
                                          scalar_first, std::optional(std::move(run.estimate)), py::cast(run.choice),
                                          run.choice.met ? level : std::nullopt);
  if (!run.choice.met) raise_tolerance_error(run.choice, result);
  return result;
}

py::object simulate_scene_py(py::handle model, py::handle initial, py::handle dt, py::handle steps, py::handle method,
                             py::handle record_every, py::handle loads, py::handle gravity, py::handle t0,
                             py::handle scalar_first, py::handle progress, py::handle duration, py::handle error,
                             py::handle accuracy_level, const ToleranceHandles& to, py::handle controller,
                             const OneBodyInputs* body) {
  refuse_body_arguments(loads, gravity);
  const bool tolerance_given = !to.tolerance.is_none();
  SimulationOptions o;
  if (!tolerance_given) {  // its checks of dt, steps and duration (as_tolerance_args otherwise)
    as_tolerance_args(to.tolerance, to.measure, to.max_steps, dt, steps, duration, error, ErrorMeasure::attitude);
    o.dt = py_io::as_scalar(py_io::in_si(dt, "s", "dt"), "dt");
    o.steps = as_steps(steps, duration, o.dt);
  }
  o.record_every = py_io::as_int(record_every, "record_every", 1);
  o.t0 = py_io::as_scalar(py_io::in_si(t0, "s", "t0"), "t0");
  const bool first = py_io::as_bool(scalar_first, "scalar_first");
  const bool estimate_error = py_io::as_bool(error, "error");
  const std::optional<double> level = as_accuracy_level(accuracy_level);
  const std::shared_ptr<const CompiledSceneHandle> held = body ? compiled_for(*body, method) : compiled_for(model, method);
  const CompiledSceneHandle& h = *held;
  o.method = h.method;
  std::vector<BodyState> initial_states = as_scene_states(initial, h.scene, "initial");
  if (tolerance_given) {
    const auto a = as_tolerance_args(to.tolerance, to.measure, to.max_steps, dt, steps, duration, error,
                                     default_scene_measure(h.scene));
    return simulate_scene_to_tolerance(model, method, initial_states, h, o, *a, progress, first, level, controller);
  }
  bool shipped_law = false;
  const std::optional<Controller> control =
      controller.is_none() ? std::nullopt : std::optional<Controller>(as_controller(controller, h.scene, &shipped_law));
  PythonMonitor monitor(progress);
  if (monitor.needed()) o.monitor = [&monitor](std::int64_t steps_done) { return monitor(steps_done); };
  // a law in Python (or gyro noise): the coarse runs' copies of it, made before the run (released with the GIL held),
  // where it is repeatable; else no estimate (unrepeated)
  const bool python_law = estimate_error && control && !shipped_law;
  const bool unrepeated = python_law && !repeatable_law(controller, h.scene);
  std::vector<Controller> python_coarse;
  if (python_law && !unrepeated) python_coarse = coarse_controllers(controller, h.scene);
  SceneSimulation r;
  std::optional<GlobalErrorEstimate> estimate;
  std::optional<RunBalance> balance;
  LazyError deferred;
  {
    // a controlled run releases the GIL however short: monte_carlo runs such samples from several threads at once
    const GilReleasedForRun release(control ? std::numeric_limits<std::int64_t>::max() : o.steps,
                                    h.scene.bodies.size());
    // a law in C++: its state before the run (a B-dot's last field), copied for each coarse run
    const std::optional<Controller> pristine = shipped_law ? control : std::nullopt;
    r = control ? simulate(*h.compiled, initial_states, o, *control) : simulate(*h.compiled, initial_states, o);
    // at the order the compiled scene has (scene_order.hpp); a controlled run's coarse runs each under a fresh copy
    // of its law, a law in Python's made now (it takes the GIL at its samples: not deferred)
    if (unrepeated && !r.interrupted) {
      estimate = no_estimate(r.size(), r.body_count, scene_order(*h.compiled),
                             "no estimate: the controller's law in Python is sampled by the run alone (declare it "
                             "Controller(..., repeatable=True) to have the runs at 2 dt and 4 dt sample copies of it)");
    } else if (estimate_error && !r.interrupted) {
      const std::string opaque = opaque_force(*h.compiled);
      if (opaque.empty() && progress.is_none() && python_coarse.empty()) {
        balance = scene_run_balance(r, h, o.dt);
        if (closes_under_any_estimate(*balance, level.value_or(default_accuracy_level))) {
          // (the states' last use)
          deferred = LazyError(deferred_estimate(h.compiled, std::move(initial_states), o, pristine));
        }
      }
      if (!deferred.pending()) {
        std::size_t coarse_runs = 0;  // the 2h run's law, then the 4h run's
        const auto run = [&](SimulationOptions coarse) {
          coarse.estimate_records = true;  // what the estimate reads of it
          if (!control) return simulate(*h.compiled, initial_states, coarse);
          if (!python_coarse.empty()) {
            return simulate(*h.compiled, initial_states, coarse, python_coarse[coarse_runs++]);
          }
          const Controller fresh = *pristine;
          return simulate(*h.compiled, initial_states, coarse, fresh);
        };
        estimate = global_error(r, o, scene_order(*h.compiled), interruptible(run, r.interrupted), opaque);
        if (control) name_off_grid_samples(*estimate, control->period, o.dt);
      }
    }
  }
  if (r.interrupted) monitor.raise();  // the records so far are dropped with r
  warn_after_run(r, o, method_info(h.method).name);
  return scene_result_object(std::move(r), h, o.dt, first, std::move(estimate), py::none(), level, std::move(balance),
                             std::move(deferred));
}

py::object step_scene_py(py::handle model, py::handle state, py::handle dt, py::handle method, py::handle loads,
                         py::handle gravity, py::handle t) {
  refuse_body_arguments(loads, gravity);
  SimulationOptions o;
  o.dt = py_io::as_scalar(py_io::in_si(dt, "s", "dt"), "dt");
  const std::shared_ptr<const CompiledSceneHandle> held = compiled_for(model, method);
  const CompiledSceneHandle& h = *held;
  o.method = h.method;
  for (std::size_t i = 0; i < h.scene.bodies.size(); ++i) {  // a body state does not carry its mass
    if (has_mass_flow(h.scene, i)) {
      py_io::throw_value_error("model", "a scene without mass flows for step (a body's state does not carry its mass, "
                               "so a second step would restart from the initial mass; use simulate)",
                               "mass_flows[" + std::to_string(i) + "] of body '" + body_name(h.scene, i) + "'");
    }
  }
  if (!t.is_none()) {
    o.t0 = py_io::as_scalar(py_io::in_si(t, "s", "t"), "t");
  } else if (time_dependent(*h.compiled)) {
    py_io::throw_value_error("t", "the time [s] of `state` (the scene has a PythonForce, a load with a time window, a "
                             "moving frame or a mass rate of t; pass t=... and use the time returned)", "None");
  }
  const std::vector<BodyState> current = as_scene_states(state, h.scene, "state");
  SceneState next;
  {
    const GilReleasedForRun release(1, h.scene.bodies.size());
    next = step(*h.compiled, current, o);
  }
  if (!all_finite(h.scene, next.bodies)) {
    const std::string msg = "step: the state became non-finite in the step of dt = " + format_value(o.dt) +
                            (t.is_none() ? std::string() : " from t = " + format_value(o.t0)) + " (method '" +
                            method_info(h.method).name + "')";
    if (PyErr_WarnEx(PyExc_RuntimeWarning, msg.c_str(), 1) != 0) throw py::error_already_set();
  }
  py::list states = states_object(next.bodies);
  if (t.is_none()) return std::move(states);
  return py::make_tuple(states, o.t0 + o.dt);
}

void bind_scene(py::module_& m) {
  scene_compatibility_warning = PyErr_NewExceptionWithDoc(
      "rigiddyn._core.SceneCompatibilityWarning",
      "Warned when a scene is compiled for a method whose properties its elements break (e.g. velocity-dependent "
      "forces with a splitting method: order 1 in the damping, energy behaviour not symplectic). A UserWarning.",
      PyExc_UserWarning, nullptr);
  if (scene_compatibility_warning == nullptr) throw py::error_already_set();
  m.attr("SceneCompatibilityWarning") = py::handle(scene_compatibility_warning);

  // both classes first, so that each one's signatures name the other
  py::class_<Scene> scene(m, "Scene", scene_doc);
  py::class_<CompiledSceneHandle> compiled(m, "CompiledScene", compiled_scene_doc);
  scene.def(py::init(&make_scene), py::arg("bodies") = py::none(), py::arg("body_names") = py::none(),
            py::arg("elements") = py::none(), py::arg("frame") = py::none(), py::arg("mass_flows") = py::none())
      .def(
          "add_body",
          [](Scene& s, py::handle body, py::handle name, py::handle mass_flow) {
            return add_body(s, body, name, mass_flow, "body", "name", "mass_flow");
          },
          py::arg("body"), py::arg("name") = py::none(), py::arg("mass_flow") = py::none(),
          "Adds `body` (a Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody, Gyrostat or TreeLink) named `name` (a str no "
          "other body has; None: 'body<index>') with its mass flow `mass_flow` (a MassFlow; None: a constant mass); "
          "returns its index, by which elements refer to it.")
      .def(
          "add_tree", [](Scene& s, py::handle tree, py::handle name) { return add_tree(s, tree, name); }, py::arg("tree"),
          py::arg("name") = py::none(), add_tree_doc)
      .def(
          "add", [](Scene& s, py::handle element) { return add_element(s, element, "element"); }, py::arg("element"),
          "Adds a force element (an instance of a class of rigiddyn.FORCE_ELEMENTS) after checking it against the bodies added so far (indices in range, "
          "loads the body's kind can take: ValueError naming element.<field>); returns its index (the column of "
          "SceneResult.work and power).")
      .def_property_readonly("bodies", [](const Scene& s) { return py::tuple(bodies_list(s)); },
                             "tuple of the bodies (copies), in index order")
      .def_property_readonly("body_names", &names_tuple, "tuple of the bodies' names (str), in index order")
      .def_property_readonly("elements", [](const Scene& s) { return py::tuple(elements_list(s)); },
                             "tuple of the force elements (copies), in the order added")
      .def_property(
          "frame", &frame_object,
          [](Scene& s, py::handle frame) {
            s.frame = frame.is_none() ? std::nullopt : std::optional<SceneFrame>(as_scene_frame(frame, "frame"));
          },
          "the SceneFrame F the states, elements and records are relative to, or None (the default: W, inertial); "
          "assignable")
      .def_property_readonly(
          "mass_flows",
          [](const Scene& s) {
            py::tuple out(s.bodies.size());
            for (std::size_t i = 0; i < s.bodies.size(); ++i) out[i] = has_mass_flow(s, i) ? py::cast(*s.mass_flows[i]) : py::none();
            return out;
          },
          "tuple of each body's MassFlow, or None for a constant mass, in index order")
      .def(
          "compile",
          [](const Scene& s, py::handle method) { return compile_handle(s, as_method_name(method), true); },
          py::arg("method") = "rk4",
          "The scene compiled for `method` (a name of methods()): an immutable CompiledScene whose derivative "
          "evaluates only the declared elements. ValueError with the reason when the method cannot run the scene "
          "(e.g. 'exact' with any force element); SceneCompatibilityWarning when it runs it with weaker "
          "properties (velocity-dependent elements with a splitting method).")
      // describe and to_toml live in Python (rigiddyn/scene_describe.py, rigiddyn/scene_file.py)
      .def(
          "describe",
          [](py::object self, py::handle method) {
            return py::module_::import("rigiddyn.scene_describe").attr("describe")(self, method);
          },
          py::arg("method") = py::none(),
          "A text table of the scene: bodies (kind, mass [kg], inertia [kg m^2] in B, state), force elements "
          "(parameters in SI with their frames, properties, the terms on each body), the frame (W, inertial), the "
          "units and, with `method` (a name of methods()), its order and the compile's verdict "
          "(rigiddyn.scene_describe.describe).")
      .def(
          "to_toml",
          [](py::object self, py::handle initial, py::handle run, py::handle name, py::handle description) {
            return py::module_::import("rigiddyn.scene_file")
                .attr("scene_to_toml")(self, initial, run, name, description);
          },
          py::arg("initial") = py::none(), py::arg("run") = py::none(), py::arg("name") = py::none(),
          py::arg("description") = py::none(),
          "The canonical scene file (TOML text: SI units, radians, q_WB as (x, y, z, w)) of the scene with "
          "`initial` (one state per body, or None), `run` (a rigiddyn.scene_file.RunOptions or None), `name` and "
          "`description`; rigiddyn.load_scene reads it back to the same scene (rigiddyn.scene_file.scene_to_toml).")
      .def("__repr__", &scene_repr)
      .def(py::pickle(
          [](const Scene& s) {
            return py::make_tuple(bodies_list(s), raw_names_list(s), elements_list(s), frame_object(s), mass_flows_object(s));
          },
          [](const py::tuple& t) {
            if (t.size() != 5) py_io::throw_value_error("Scene pickle", "a tuple of 5 items", std::to_string(t.size()) + " items");
            return make_scene(t[0], t[1], t[2], t[3], t[4]);
          }))
      .def(
          "__eq__",
          [](const Scene& a, py::handle b) -> py::object {
            if (!is_instance<Scene>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
            return py::bool_(same_scene(a, b.cast<const Scene&>()));
          },
          py::arg("other"));
  scene.attr("__hash__") = py::none();

  compiled
      .def(py::init([](py::handle s, py::handle method) {
             return compile_handle(py_io::as_instance<Scene>(s, "scene", "a Scene"), as_method_name(method), true);
           }),
           py::arg("scene"), py::arg("method") = "rk4")
      .def_property_readonly("scene", [](const CompiledSceneHandle& h) { return h.scene; },
                             "the Scene it was compiled from (a copy)")
      .def_property_readonly("method", [](const CompiledSceneHandle& h) { return method_info(h.method).name; },
                             "the method's name (see methods())")
      .def_property_readonly(
          "warnings", [](const CompiledSceneHandle& h) { return py::tuple(py::cast(h.compiled->warnings())); },
          "tuple of the compatibility warnings (str) compiling gave")
      .def_property_readonly(
          "element_traits",
          [](const CompiledSceneHandle& h) {
            py::list out;
            for (const ElementTraits& t : h.compiled->element_traits()) {
              py::dict d;
              d["reads_attitude"] = t.reads_attitude, d["velocity_dependent"] = t.velocity_dependent;
              d["time_dependent"] = t.time_dependent, d["has_potential"] = t.has_potential, d["has_torque"] = t.has_torque;
              d["has_force"] = t.has_force, d["needs_attitude"] = t.needs_attitude;
              d["zero_net_wrench"] = t.zero_net_wrench;
              out.append(d);
            }
            return py::tuple(out);
          },
          "tuple of dict, one per compiled term in the order of SceneResult.work's columns (the scene's elements, "
          "then the frame's fictitious terms): reads_attitude, velocity_dependent, time_dependent, has_potential "
          "(its forces derive from a potential energy), has_torque, has_force, needs_attitude (it skips particles) and "
          "zero_net_wrench (its forces sum to zero and so do their moments: internal forces, which add nothing to the "
          "impulses) (bool each)")
      .def(
          "describe",
          [](py::object self) { return py::module_::import("rigiddyn.scene_describe").attr("describe")(self); },
          "Scene.describe of its scene with its method: bodies, force elements, frame, units, the method's order "
          "and the compile's verdict (rigiddyn.scene_describe.describe).")
      .def("__repr__",
           [](const CompiledSceneHandle& h) {
             return "CompiledScene(scene=" + scene_repr(h.scene) + ", method='" + method_info(h.method).name + "')";
           })
      .def(py::pickle(
          [](const CompiledSceneHandle& h) { return py::make_tuple(h.scene, method_info(h.method).name); },
          [](const py::tuple& t) {
            if (t.size() != 2) py_io::throw_value_error("CompiledScene pickle", "a tuple of 2 items", std::to_string(t.size()) + " items");
            return compile_handle(py_io::as_instance<Scene>(t[0], "scene", "a Scene"), as_method_name(t[1]), false);
          }))
      .def(
          "__eq__",
          [](const CompiledSceneHandle& a, py::handle b) -> py::object {
            if (!is_instance<CompiledSceneHandle>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
            const auto& other = b.cast<const CompiledSceneHandle&>();
            return py::bool_(a.method == other.method && same_scene(a.scene, other.scene));
          },
          py::arg("other"));
  compiled.attr("__hash__") = py::none();

  py::class_<SceneResult>(m, "SceneResult", scene_result_doc)
      .def_property_readonly("t", array_of(&SceneResult::t), "(n,) time [s]")
      .def_property_readonly("p_W", array_of(&SceneResult::p_W), "(n, nb, 3) centre of mass positions in W [m]")
      .def_property_readonly("q_WB", array_of(&SceneResult::q_WB),
                             "(n, nb, 4) attitudes, (x, y, z, w) unless scalar_first")
      .def_property_readonly("v_W", array_of(&SceneResult::v_W), "(n, nb, 3) centre of mass velocities in W [m/s]")
      .def_property_readonly("w_B", array_of(&SceneResult::w_B),
                             "(n, nb, 3) angular velocities, each in its body's B [rad/s]")
      .def_property_readonly("kinetic_energy", array_of(&SceneResult::kinetic_energy), "(n,) sum over the bodies [J]")
      .def_property_readonly("potential_energy", array_of(&SceneResult::potential_energy),
                             "(n,) sum of the elements' potentials [J]")
      .def_property_readonly("total_energy", array_of(&SceneResult::total_energy), "(n,) kinetic + potential [J]")
      .def_property_readonly("linear_momentum_W", array_of(&SceneResult::linear_momentum_W),
                             "(n, 3) sum of m v_W, in W [kg m/s]")
      .def_property_readonly("angular_momentum_W", array_of(&SceneResult::angular_momentum_W),
                    "(n, 3) about W's origin, in W: sum of p_W x m v_W + R_WB I w_B [kg m^2/s]")
      .def_property_readonly("pivot_reaction_W", array_of(&SceneResult::pivot_reaction_W),
                    "(n, nb, 3) the pivot's force on each body, in W [N] (0 for a body not pinned)")
      .def_property_readonly("angular_momentum_O_W", array_of(&SceneResult::angular_momentum_O_W),
                    "(n, nb, 3) each body's angular momentum about its pivot O (about its centre of mass when not "
                    "pinned), in W [kg m^2/s]")
      .def_property_readonly("mass", array_of(&SceneResult::mass),
                             "(n, nb) each body's mass [kg] (changing under a MassFlow)")
      .def_property_readonly("work", array_of(&SceneResult::work), "(n, ne) each element's work since t0 [J]")
      .def_property_readonly("power", array_of(&SceneResult::power), "(n, ne) each element's power at the record [W]")
      .def_property_readonly("mass_flow_energy", array_of(&SceneResult::mass_flow_energy),
                    "(n, nb) each body's mass-flow energy since t0 [J]: the integral of 1/2 (dm/dt) |v|^2 + 1/2 "
                    "w.(dI/dt) w (0 for a constant mass); kinetic_energy - kinetic_energy[0] ~ work.sum(axis=1) + "
                    "mass_flow_energy.sum(axis=1)")
      .def_property_readonly("wheel_speed", array_of(&SceneResult::wheel_speed),
                    "(n, nw) each gyrostat wheel's speed relative to its body [rad/s], the wheels of the gyrostats in "
                    "the scene's order (nw = 0 without a gyrostat)")
      .def_property_readonly("motor_work", array_of(&SceneResult::motor_work),
                    "(n, nw) each wheel's motor work since t0 [J], the integral of its motor torque times its speed: "
                    "kinetic_energy - kinetic_energy[0] ~ work.sum(axis=1) + mass_flow_energy.sum(axis=1) + "
                    "motor_work.sum(axis=1)")
      .def_readonly("wheel_bodies", &SceneResult::wheel_bodies, "(nw,) tuple of the body index of each wheel")
      .def_property_readonly("joint_q", array_of(&SceneResult::joint_q),
                             "(n, k) the trees' configurations q, k the sum of their sizes (Scene.add_tree; the trees "
                             "in the scene's order, each its Tree's q: angles [rad], offsets [m], quaternions (x, y, z, "
                             "w) as integrated); (n, 0) without a tree")
      .def_property_readonly("joint_v", array_of(&SceneResult::joint_v),
                             "(n, k) the trees' velocities v, k the sum of their sizes (each its Tree's v: rates "
                             "[rad/s], [m/s], w_L [rad/s] in the link frame); (n, 0) without a tree")
      .def_readonly("body_names", &SceneResult::body_names, "(nb,) tuple of the bodies' names")
      .def_readonly("elements", &SceneResult::elements,
                    "(ne,) tuple of the elements' class names, then the frame's fictitious terms' ('CentrifugalForce', "
                    "...)")
      .def_readonly("diverged", &SceneResult::diverged, "True if the run stopped on a non-finite state")
      .def_readonly("unconverged_steps", &SceneResult::unconverged_steps,
                    "number of steps whose implicit solve stopped at its iteration cap (0 for explicit methods)")
      .def_readonly("elapsed_seconds", &SceneResult::elapsed_seconds, "wall time of the C++ stepping loop [s]")
      .def_property_readonly("balance", [](const SceneResult& r) { return r.balance.get(); },
                    "The energy and momentum balance of every record (a Balance), or None (a batch result).")
      .def_property_readonly("error", &result_error,
                    "The global error estimate of every record (a GlobalError: per body (n, nb) for the state, per "
                    "record (n,) for the energy and |L|), or None (simulate(..., error=False)). A run whose balances "
                    "close makes it on this first read (simulate's error), a batch's sample with its batch's: the "
                    "same values.")
      .def_readonly("choice", &SceneResult::choice,
                    "What simulate(..., tolerance=) chose and why (a ToleranceChoice), or None (a run at a given dt).")
      .def_readonly("scalar_first", &SceneResult::scalar_first,
                    "True if q_WB's rows are (w, x, y, z): the result of simulate(..., scalar_first=True)")
      .def("__repr__", &scene_result_repr)
      .def(py::pickle(&scene_result_state, &scene_result_from_state))
      .def(
          "to_dataframe",
          [](py::object self, py::handle scalar_first, py::handle units) {
            return py::module_::import("rigiddyn.scene_result")
                .attr("to_dataframe")(self, scalar_first, py::arg("units") = units);
          },
          py::arg("scalar_first") = py::none(), py::kw_only(), py::arg("units") = py::none(),
          "A pandas.DataFrame of the records (needs pandas): one row per record, one column per scalar with its "
          "unit (wide format; rigiddyn.scene_result documents the columns): 't [s]', then per body "
          "'<name>:p_W_x [m]' .. '<name>:q_WB_x' .. '<name>:v_W_x [m/s]' .. '<name>:w_B_x [rad/s]' .. through "
          "'<name>:mass [kg]' and '<name>:mass_flow_energy [J]' (and a gyrostat's '<name>:wheel_speed_<k> [rad/s]'), then "
          "'kinetic_energy [J]', 'potential_energy [J]', 'total_energy [J]', 'linear_momentum_W_x [kg m/s]' .., "
          "'angular_momentum_W_x [kg m^2/s]' .., then per element i 'work[i] <Class> [J]' and 'power[i] <Class> "
          "[W]'; q_WB's columns in the result's order ('<name>:q_WB_w' first when its scalar_first is True). "
          "scalar_first: None (the default) for the order the result records; True or False declares the order "
          "of its q_WB rows instead. units: the units of the columns, {dimension: unit} (keys length, angle, time, "
          "mass, energy, power, force; rigiddyn.output_units), e.g. {'length': 'km', 'time': 'h'} gives 't [h]', "
          "'<name>:p_W_x [km]', '<name>:v_W_x [km/h]'; None (the default): SI. TypeError or ValueError naming a bad "
          "units (an unknown dimension, an unknown unit, a unit of another dimension).");
}

}  // namespace rigiddyn::bindings
