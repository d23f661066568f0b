// Python bindings of the spatial layer (Featherstone's spatial algebra, angular part first):
// Motion, Force, Transform, Screw, the dense cross-product matrices, the screw of a twist, and the
// array functions transform_compose / transform_points.
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "common_args.hpp"
#include "numpy_io.hpp"
#include "repr.hpp"
#include "rigiddyn/so3/matrix.hpp"
#include "rigiddyn/spatial/cross.hpp"
#include "rigiddyn/spatial/force.hpp"
#include "rigiddyn/spatial/motion.hpp"
#include "rigiddyn/spatial/screw.hpp"
#include "rigiddyn/spatial/transform.hpp"
#include "value_type.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using namespace pybind11::literals;
using py_io::Array;
using py_io::Stack;

namespace {

using py_io::read_only;


// A finite scalar factor for `motion * s` (TypeError/ValueError naming "scalar").
double as_factor(py::handle s) { return py_io::as_scalar(s, "scalar"); }

// Bound arguments of this layer's classes (TypeError naming the argument otherwise; ValueError for
// one with a non-finite part).
const Motion& as_motion(py::handle obj, const std::string& name) {
  return py_io::as_finite_spatial<Motion>(obj, name, "a Motion");
}
const Force& as_force(py::handle obj, const std::string& name) {
  return py_io::as_finite_spatial<Force>(obj, name, "a Force");
}

// Results: a RuntimeWarning naming the quantity when a part overflowed.
template <class Spatial>  // Motion or Force
Spatial checked(const Spatial& s, const char* quantity) {
  py_io::warn_unless_finite(s.angular.allFinite() && s.linear.allFinite(), quantity,
                            "[" + format_value(s.angular.transpose()) + "; " + format_value(s.linear.transpose()) + "]");
  return s;
}
Transform checked(const Transform& X, const char* quantity) {
  py_io::warn_unless_finite(X.rotation().allFinite() && X.translation().allFinite(), quantity,
                            "translation " + format_value(X.translation().transpose()));
  return X;
}

// A binary operator a (op) b of two objects of the bound class T, checked; NotImplemented for any
// other b (so Python raises its TypeError, or tries b's reflected operator).
template <class T, class Op>
py::object binary_operator(const T& a, py::handle b, const char* quantity, Op op) {
  if (!is_instance<T>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
  return py::cast(checked(op(a, b.cast<const T&>()), quantity));
}

// + - (binary and unary) and scalar * of a Motion or Force, each result checked.
template <class Spatial>
void bind_linear_operators(py::class_<Spatial>& c, const std::string& type) {
  const std::string sum = type + ".__add__", difference = type + ".__sub__", product = type + ".__mul__";
  c.def(
       "__add__",
       [sum](const Spatial& a, py::handle b) {
         return binary_operator(a, b, sum.c_str(), [](const Spatial& x, const Spatial& y) { return x + y; });
       },
       py::is_operator())
      .def(
          "__sub__",
          [difference](const Spatial& a, py::handle b) {
            return binary_operator(a, b, difference.c_str(), [](const Spatial& x, const Spatial& y) { return x - y; });
          },
          py::is_operator())
      .def("__neg__", [](const Spatial& a) { return -a; }, py::is_operator())
      .def(
          "__mul__", [product](const Spatial& a, py::handle k) { return checked(a * as_factor(k), product.c_str()); },
          py::is_operator())
      .def(
          "__rmul__", [product](const Spatial& a, py::handle k) { return checked(a * as_factor(k), product.c_str()); },
          py::is_operator());
}

// Stacks that are one item (broadcast) or n items: the common n; ValueError naming the argument
// whose length differs from the first stacked one.
py::ssize_t common_count(const std::vector<std::pair<const Stack*, const char*>>& stacks) {
  const char* first = nullptr;
  py::ssize_t n = 1;
  for (const auto& [stack, name] : stacks) {
    if (!stack->stacked) continue;
    if (first == nullptr) {
      first = name;
      n = stack->n;
    } else if (stack->n != n) {
      throw py::value_error(std::string(name) + ": expected " + std::to_string(n) + " items (as " + first +
                            "), got " + std::to_string(stack->n));
    }
  }
  return n;
}

bool any_stacked(const std::vector<std::pair<const Stack*, const char*>>& stacks) {
  for (const auto& entry : stacks)
    if (entry.first->stacked) return true;
  return false;
}

using py_io::item;  // item i of a stack (item 0 of a single item, which broadcasts)

using RowMatrix3d = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

// Item i of a stack of 3-vectors, mapped in place (no copy).
Eigen::Map<const Eigen::Vector3d> vector_item(const Stack& s, py::ssize_t i) {
  return Eigen::Map<const Eigen::Vector3d>(item(s, i, 3));
}

// The rotations R[i] of a stack (3,3)|(n,3,3), each given rotation checked once by
// checked_rotation_matrix: a single (broadcast) one here, stacked ones as they are read. A bad
// rotation is reported as "<name>[i]: expected ..." ("<name>: ..." for a single one).
class RotationStack {
 public:
  RotationStack(const Stack& R, std::string name) : R_(R), name_(std::move(name)) {
    if (!R.stacked) single_ = checked(0);
  }
  Eigen::Matrix3d operator[](py::ssize_t i) const { return R_.stacked ? checked(i) : single_; }

 private:
  Eigen::Matrix3d checked(py::ssize_t i) const {
    const Eigen::Matrix3d R = Eigen::Map<const RowMatrix3d>(R_.item(i, 9));
    try {
      return checked_rotation_matrix(R, "rotation");
    } catch (const std::invalid_argument& e) {  // "rotation: expected ..."
      const std::string message = e.what();
      const std::string name = R_.stacked ? name_ + "[" + std::to_string(i) + "]" : name_;
      throw std::invalid_argument(name + message.substr(message.find(':')));
    }
  }
  const Stack& R_;
  std::string name_;
  Eigen::Matrix3d single_ = Eigen::Matrix3d::Identity();  // the broadcast rotation, if not stacked
};

// transform_compose: X_AC = X_AB * X_BC item by item, as Transform::operator* (R_AC = R_AB R_BC,
// p_AC = R_AB p_BC + p_AB); the translations are finite (as_stack checked them).
py::tuple transform_compose(py::handle R_AB_obj, py::handle p_AB_obj, py::handle R_BC_obj, py::handle p_BC_obj) {
  const Stack R_AB = py_io::as_stack(R_AB_obj, "R_AB", {3, 3}), p_AB = py_io::as_stack(p_AB_obj, "p_AB", {3});
  const Stack R_BC = py_io::as_stack(R_BC_obj, "R_BC", {3, 3}), p_BC = py_io::as_stack(p_BC_obj, "p_BC", {3});
  const std::vector<std::pair<const Stack*, const char*>> all = {
      {&R_AB, "R_AB"}, {&p_AB, "p_AB"}, {&R_BC, "R_BC"}, {&p_BC, "p_BC"}};
  const py::ssize_t n = common_count(all);
  const bool stacked = any_stacked(all);
  Array R_AC = py_io::new_stack(n, stacked, {3, 3}, "R_AC"), p_AC = py_io::new_stack(n, stacked, {3}, "p_AC");
  double* R_out = R_AC.mutable_data();
  double* p_out = p_AC.mutable_data();
  {
    py::gil_scoped_release release;
    const RotationStack rotations_AB(R_AB, "R_AB"), rotations_BC(R_BC, "R_BC");
    for (py::ssize_t i = 0; i < n; ++i) {
      const Eigen::Matrix3d R_ab = rotations_AB[i];
      Eigen::Map<RowMatrix3d>(R_out + 9 * i).noalias() = R_ab * rotations_BC[i];
      Eigen::Map<Eigen::Vector3d>(p_out + 3 * i).noalias() = R_ab * vector_item(p_BC, i) + vector_item(p_AB, i);
    }
  }
  // R_AC is a product of checked rotations (bounded); p_AC may overflow
  return py::make_tuple(R_AC, py_io::finite_result(p_AC, "transform_compose p_AC"));
}

// transform_points: p_A = R_AB p_B + p_AB item by item, as Transform::act_point.
Array transform_points(py::handle R_AB_obj, py::handle p_AB_obj, py::handle p_B_obj) {
  const Stack R_AB = py_io::as_stack(R_AB_obj, "R_AB", {3, 3}), p_AB = py_io::as_stack(p_AB_obj, "p_AB", {3});
  const Stack p_B = py_io::as_stack(p_B_obj, "p_B", {3});
  const std::vector<std::pair<const Stack*, const char*>> all = {{&R_AB, "R_AB"}, {&p_AB, "p_AB"}, {&p_B, "p_B"}};
  const py::ssize_t n = common_count(all);
  Array p_A = py_io::new_stack(n, any_stacked(all), {3}, "p_A");
  double* out = p_A.mutable_data();
  {
    py::gil_scoped_release release;
    const RotationStack rotations_AB(R_AB, "R_AB");
    for (py::ssize_t i = 0; i < n; ++i)
      Eigen::Map<Eigen::Vector3d>(out + 3 * i).noalias() = rotations_AB[i] * vector_item(p_B, i) + vector_item(p_AB, i);
  }
  return py_io::finite_result(p_A, "transform_points");
}

// A point map (act_point / act_inv_point) over one point (3,) or a stack (n, 3).
template <typename Map>
Array map_points(py::handle points_obj, const char* name, const char* quantity, Map&& map) {
  const Stack points = py_io::as_stack(points_obj, name, {3});
  Array out = py_io::new_stack(points.n, points.stacked, {3}, quantity);
  double* p = out.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < points.n; ++i) Eigen::Map<Eigen::Vector3d>(p + 3 * i) = map(vector_item(points, i));
  }
  return py_io::finite_result(out, quantity);
}

// A precision >= 0 for is_approx.
double as_precision(py::handle prec) {
  const double value = py_io::as_scalar(prec, "prec");
  if (value < 0.0) py_io::throw_value_error("prec", "a number >= 0", format_value(value));
  return value;
}

// is_approx, == (exact), repr as the constructor call and pickling of a Motion or Force.
template <class Spatial>
void bind_value_protocol(py::class_<Spatial>& c, const std::string& type) {
  c.def(
       "is_approx",
       [type](const Spatial& a, py::handle b, py::handle prec) {
         return a.is_approx(py_io::as_instance<Spatial>(b, "other", "a " + type), as_precision(prec));
       },
       "other"_a, "prec"_a = 1e-12,
       ("True when the 6-vectors agree to `prec` relative to the smaller norm (Eigen's isApprox: |a - b| <=\n"
        "prec min(|a|, |b|), so only an exactly zero " + type + " is close to zero). == compares exactly.\n\n"
        "Parameters\n----------\nother : " + type + "\n    In the same frame.\n"
        "prec : float, default 1e-12\n    Relative tolerance, >= 0.\n\n"
        "Returns\n-------\nbool\n\n"
        "Raises\n------\nTypeError\n    other not a " + type + ".\nValueError\n    prec negative or not finite.\n\n"
        "Examples\n--------\n"
        ">>> rd." + type + "([1.0, 0.0, 0.0]).is_approx(rd." + type + "([1.0 + 1e-14, 0.0, 0.0]))\nTrue\n").c_str())
      .def(
          "__eq__",
          [](const Spatial& a, py::handle b) {
            return equal_or_not_implemented(a, b, [](const Spatial& x, const Spatial& y) {
              return same(x.angular, y.angular) && same(x.linear, y.linear);
            });
          },
          py::is_operator(), "Exact equality of the angular and linear parts.")
      .def("__repr__",
           [type](const Spatial& s) {
             return repr_call(type, {{"angular", py_io::to_array(s.angular)}, {"linear", py_io::to_array(s.linear)}});
           })
      .def(py::pickle([](const Spatial& s) { return py::make_tuple(read_only(s.angular), read_only(s.linear)); },
                      [type](const py::tuple& state) {
                        const py::tuple s = pickled_state(state, 2, type);
                        return Spatial(py_io::as_vector3(s[0], "angular"), py_io::as_vector3(s[1], "linear"));
                      }));
}

void bind_motion(py::module_& m) {
  py::class_<Motion> c(
      m, "Motion",
      "Spatial motion vector (twist) V = [w; v], angular part first.\n\n"
      "w is the angular velocity [rad/s] and v the velocity [m/s] of the body point at the origin of the frame\n"
      "of expression, both expressed in that frame: Plücker coordinates in Featherstone's convention (\"Rigid\n"
      "Body Dynamics Algorithms\"), the order of MuJoCo, Drake and RigidBodyDynamics.jl (Pinocchio puts\n"
      "the linear part first). The order matters only at to_vector / from_vector.\n\n"
      "Parameters\n----------\n"
      "angular : array_like, shape (3,), optional\n    w [rad/s] (None: zero).\n"
      "linear : array_like, shape (3,), optional\n    v [m/s] of the body point at the frame's origin (None: zero).\n\n"
      "Raises\n------\nValueError\n    A part of another shape or non-finite (the message names it).\n\n"
      "See Also\n--------\nForce, Transform, motion_cross_matrix, twist_to_screw\n\n"
      "Examples\n--------\n"
      "The power w . n + v . f of a force on a motion is the same in every frame:\n\n"
      ">>> V = rd.Motion([0.0, 0.0, 1.0], [1.0, 0.0, 0.0])\n"
      ">>> V.to_vector()\narray([0., 0., 1., 1., 0., 0.])\n"
      ">>> F = rd.Force([0.0, 0.0, 2.0], [0.0, 3.0, 0.0])\n"
      ">>> X = rd.Transform(rd.rot_z(np.pi / 2), [1.0, 0.0, 0.0])\n"
      ">>> V.dot(F), bool(np.isclose(X.act(V).dot(X.act(F)), V.dot(F)))\n(2.0, True)\n\n"
      "Immutable; supports +, -, scalar *; pickles; == compares exactly.");
  c.def(py::init([](py::handle angular, py::handle linear) {
         return Motion(py_io::as_vector3_or_zero(angular, "angular"), py_io::as_vector3_or_zero(linear, "linear"));
       }),
       "angular"_a = py::none(), "linear"_a = py::none(),
       "Motion from w (3,) [rad/s] and v (3,) [m/s] in one frame (None: zero); see the class.")
      .def_property_readonly("angular", [](const Motion& s) { return read_only(s.angular); },
                             "w (3,) [rad/s], expressed in the frame of the motion; read-only copy")
      .def_property_readonly("linear", [](const Motion& s) { return read_only(s.linear); },
                             "v (3,) [m/s] of the body point at the frame's origin, expressed in that frame; "
                             "read-only copy")
      .def("to_vector", [](const Motion& s) { return py_io::to_array(s.to_vector()); },
           "[w; v] as a (6,) array, angular first ([rad/s], [m/s]), in the motion's frame.")
      .def_static("from_vector", [](py::handle v) { return Motion::from_vector(py_io::as_vector6(v, "vector")); },
                  "vector"_a,
                  "Motion from a (6,) array [w; v], angular first ([rad/s], [m/s]); ValueError on another shape or "
                  "NaN/Inf.\n\n"
                  "Parameters\n----------\nvector : array_like, shape (6,)\n    [w; v] ([rad/s], [m/s]).\n\n"
                  "Returns\n-------\nMotion\n\n"
                  "Examples\n--------\n"
                  ">>> rd.Motion.from_vector([0.0, 0.0, 1.0, 1.0, 0.0, 0.0]).linear\narray([1., 0., 0.])\n")
      .def(
          "cross", [](const Motion& s, py::handle other) { return checked(s.cross(as_motion(other, "other")), "Motion.cross"); },
          "other"_a,
          "Motion cross product (crm): self x other = [w1 x w2; w1 x v2 + v1 x w2], in the common frame\n"
          "([rad/s^2], [m/s^2] for two twists).\n\n"
          "Parameters\n----------\nother : Motion\n    In the same frame.\n\n"
          "Returns\n-------\nMotion\n\n"
          "Examples\n--------\n"
          ">>> rd.Motion([0.0, 0.0, 1.0]).cross(rd.Motion(linear=[1.0, 0.0, 0.0])).linear\narray([0., 1., 0.])\n")
      .def(
          "cross_force",
          [](const Motion& s, py::handle force) { return checked(s.cross(as_force(force, "force")), "Motion.cross_force"); },
          "force"_a,
          "Force cross product (crf): self x* force = [w x n + v x f; w x f] ([N m/s], [N/s]), in the common frame.\n\n"
          "Parameters\n----------\nforce : Force\n    In this motion's frame.\n\n"
          "Returns\n-------\nForce\n\n"
          "Examples\n--------\n"
          ">>> rd.Motion([0.0, 0.0, 1.0]).cross_force(rd.Force(linear=[1.0, 0.0, 0.0])).linear\narray([0., 1., 0.])\n")
      .def(
          "dot",
          [](const Motion& s, py::handle force) {
            return py_io::finite_result(s.dot(as_force(force, "force")), "Motion.dot");
          },
          "force"_a,
          "Power w . n + v . f [W] of the force on this motion (same frame and reference point).\n\n"
          "Parameters\n----------\nforce : Force\n    [n; f] ([N m], [N]), in this motion's frame.\n\n"
          "Returns\n-------\nfloat\n    The power [W], the same in every frame.\n\n"
          "Examples\n--------\n"
          ">>> rd.Motion([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]).dot(rd.Force([0.0, 0.0, 2.0], [3.0, 0.0, 0.0]))\n5.0\n");
  bind_value_protocol(c, "Motion");
  bind_linear_operators(c, "Motion");
}

void bind_force(py::module_& m) {
  py::class_<Force> c(
      m, "Force",
      "Spatial force vector (wrench) F = [n; f], angular part first.\n\n"
      "n is the moment [N m] about the origin of the frame of expression and f the force [N], both expressed in\n"
      "that frame: Featherstone's convention (\"Rigid Body Dynamics Algorithms\"), moment first as in\n"
      "MuJoCo and Drake. The order matters only at to_vector / from_vector.\n\n"
      "Parameters\n----------\n"
      "angular : array_like, shape (3,), optional\n    n [N m] about the frame's origin (None: zero).\n"
      "linear : array_like, shape (3,), optional\n    f [N] (None: zero).\n\n"
      "Raises\n------\nValueError\n    A part of another shape or non-finite (the message names it).\n\n"
      "See Also\n--------\nMotion, Transform, force_cross_matrix\n\n"
      "Examples\n--------\n"
      "A force f = (0, 1, 0) [N] through (1, 0, 0) [m], moved to the origin, has the moment p x f:\n\n"
      ">>> F = rd.Transform(translation=[1.0, 0.0, 0.0]).act(rd.Force(linear=[0.0, 1.0, 0.0]))\n"
      ">>> F.to_vector()\narray([0., 0., 1., 0., 1., 0.])\n\n"
      "Immutable; supports +, -, scalar *; pickles; == compares exactly.");
  c.def(py::init([](py::handle angular, py::handle linear) {
         return Force(py_io::as_vector3_or_zero(angular, "angular"), py_io::as_vector3_or_zero(linear, "linear"));
       }),
       "angular"_a = py::none(), "linear"_a = py::none(),
       "Force from n (3,) [N m] and f (3,) [N] in one frame (None: zero); see the class.")
      .def_property_readonly("angular", [](const Force& s) { return read_only(s.angular); },
                             "n (3,) [N m]: moment about the frame's origin, expressed in that frame; read-only copy")
      .def_property_readonly("linear", [](const Force& s) { return read_only(s.linear); },
                             "f (3,) [N], expressed in the frame of the force; read-only copy")
      .def("to_vector", [](const Force& s) { return py_io::to_array(s.to_vector()); },
           "[n; f] as a (6,) array, moment first ([N m], [N]), in the force's frame.")
      .def_static("from_vector", [](py::handle v) { return Force::from_vector(py_io::as_vector6(v, "vector")); },
                  "vector"_a,
                  "Force from a (6,) array [n; f], moment first ([N m], [N]); ValueError on another shape or "
                  "NaN/Inf.\n\n"
                  "Parameters\n----------\nvector : array_like, shape (6,)\n    [n; f] ([N m], [N]).\n\n"
                  "Returns\n-------\nForce\n\n"
                  "Examples\n--------\n"
                  ">>> rd.Force.from_vector([0.0, 0.0, 1.0, 0.0, 2.0, 0.0]).angular\narray([0., 0., 1.])\n");
  bind_value_protocol(c, "Force");
  bind_linear_operators(c, "Force");
}

// A Transform's action on a Motion or a Force (TypeError naming spatial_vector otherwise), checked.
template <class Act>
py::object act_on(py::handle spatial_vector, const char* quantity, Act act) {
  if (is_instance<Motion>(spatial_vector)) return py::cast(checked(act(as_motion(spatial_vector, "spatial_vector")), quantity));
  if (is_instance<Force>(spatial_vector)) return py::cast(checked(act(as_force(spatial_vector, "spatial_vector")), quantity));
  py_io::throw_type_error("spatial_vector", "a Motion or a Force", spatial_vector);
}

void bind_transform(py::module_& m) {
  py::class_<Transform>(
      m, "Transform",
      "Rigid transform X_AB: R_AB (B coordinates -> A coordinates) and p_AB (B's origin in A) [m].\n\n"
      "Maps points (p_A = R_AB p_B + p_AB), motions and forces expressed in B to A; X_AB * X_BC = X_AC. On\n"
      "spatial vectors (angular part first) it is Featherstone's X (motion_matrix) and X* (force_matrix).\n\n"
      "Parameters\n----------\n"
      "rotation : array_like, shape (3, 3), optional\n    R_AB, orthonormal with det +1 (None: identity).\n"
      "translation : array_like, shape (3,), optional\n    p_AB [m], B's origin in A (None: zero).\n\n"
      "Raises\n------\nValueError\n    A non-rotation or non-finite input (the message names it).\n\n"
      "See Also\n--------\ntransform_compose, transform_points, Motion, Force\n\n"
      "Examples\n--------\n"
      "B turned a quarter turn about z, its origin at (1, 0, 0) in A:\n\n"
      ">>> X_AB = rd.Transform(rd.rot_z(np.pi / 2), [1.0, 0.0, 0.0])\n"
      ">>> X_AB.act_point([1.0, 0.0, 0.0]).round(12)\narray([1., 1., 0.])\n"
      ">>> (X_AB * X_AB.inverse()).is_approx(rd.Transform())\nTrue\n\n"
      "Immutable; pickles; == compares exactly.")
      .def(py::init([](py::handle rotation, py::handle translation) {
             return Transform(py_io::as_matrix3_or_identity(rotation, "rotation"),
                              py_io::as_vector3_or_zero(translation, "translation"));
           }),
           "rotation"_a = py::none(), "translation"_a = py::none(),
           "X_AB from rotation R_AB (3,3), orthonormal with det +1 (default identity), and translation\n"
           "p_AB (3,) [m] (default zero); see the class. ValueError on a non-rotation or non-finite input.")
      .def_static(
          "from_quat",
          [](py::handle q, py::handle translation, py::handle scalar_first) {
            const Eigen::Quaterniond q_AB = py_io::as_quaternion(q, "q_AB", as_scalar_first(scalar_first));
            return Transform::from_quat(q_AB, py_io::as_vector3_or_zero(translation, "translation"));
          },
          "q_AB"_a, "translation"_a = py::none(), "scalar_first"_a = false,
          "X_AB from a unit quaternion and a translation.\n\n"
          "Parameters\n----------\nq_AB : array_like, shape (4,)\n"
          "    Unit quaternion B -> A, (x, y, z, w), or (w, x, y, z) if `scalar_first`.\n"
          "translation : array_like, shape (3,), optional\n    p_AB [m], B's origin in A (None: zero).\n"
          "scalar_first : bool, default False\n    Read q_AB scalar first.\n\n"
          "Returns\n-------\nTransform\n    X_AB.\n\n"
          "Raises\n------\nValueError\n"
          "    A quaternion not of unit norm, or a non-finite or badly shaped argument (naming it).\n\n"
          "Examples\n--------\n"
          ">>> X = rd.Transform.from_quat([0.0, 0.0, np.sin(np.pi / 4), np.cos(np.pi / 4)], [1.0, 0.0, 0.0])\n"
          ">>> X.is_approx(rd.Transform(rd.rot_z(np.pi / 2), [1.0, 0.0, 0.0]))\nTrue\n")
      .def_property_readonly("rotation", [](const Transform& X) { return read_only(X.rotation()); },
                             "R_AB (3,3): maps B coordinates to A coordinates; read-only copy")
      .def_property_readonly("translation", [](const Transform& X) { return read_only(X.translation()); },
                             "p_AB (3,) [m]: B's origin relative to A's, expressed in A; read-only copy")
      .def(
          "quat",
          [](const Transform& X, py::handle scalar_first) { return py_io::to_array(X.quat(), as_scalar_first(scalar_first)); },
          "scalar_first"_a = false,
          "The rotation R_AB as a unit quaternion q_AB.\n\n"
          "Parameters\n----------\nscalar_first : bool, default False\n"
          "    Return (w, x, y, z) instead of (x, y, z, w).\n\n"
          "Returns\n-------\nndarray, shape (4,)\n    q_AB with w >= 0.\n\n"
          "Examples\n--------\n"
          ">>> rd.Transform(rd.rot_z(np.pi / 2)).quat(scalar_first=True).round(12)\n"
          "array([0.70710678, 0.        , 0.        , 0.70710678])\n")
      .def(
          "act_point",
          [](const Transform& X, py::handle p_B) {
            return map_points(p_B, "p_B", "Transform.act_point", [&X](const Eigen::Vector3d& p) { return X.act_point(p); });
          },
          "p_B"_a,
          "Map points from B to A: p_A = R_AB p_B + p_AB.\n\n"
          "Parameters\n----------\np_B : array_like, shape (3,) or (n, 3)\n    Points in B [m].\n\n"
          "Returns\n-------\nndarray, shape (3,) or (n, 3)\n    p_A, the points in A [m].\n\n"
          "Examples\n--------\n"
          ">>> rd.Transform(rd.rot_z(np.pi / 2), [1.0, 0.0, 0.0]).act_point([1.0, 0.0, 0.0]).round(12)\n"
          "array([1., 1., 0.])\n")
      .def(
          "act_inv_point",
          [](const Transform& X, py::handle p_A) {
            return map_points(p_A, "p_A", "Transform.act_inv_point",
                              [&X](const Eigen::Vector3d& p) { return X.act_inv_point(p); });
          },
          "p_A"_a,
          "Map points from A to B: p_B = R_AB^T (p_A - p_AB), the inverse of act_point.\n\n"
          "Parameters\n----------\np_A : array_like, shape (3,) or (n, 3)\n    Points in A [m].\n\n"
          "Returns\n-------\nndarray, shape (3,) or (n, 3)\n    p_B, the points in B [m].\n\n"
          "Examples\n--------\n"
          ">>> X = rd.Transform(rd.rot_z(np.pi / 2), [1.0, 0.0, 0.0])\n"
          ">>> X.act_inv_point(X.act_point([[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]])).round(12)\n"
          "array([[1., 2., 3.],\n       [4., 5., 6.]])\n")
      .def(
          "act",
          [](const Transform& X, py::handle spatial_vector) {
            return act_on(spatial_vector, "Transform.act", [&X](const auto& v) { return X.act(v); });
          },
          "spatial_vector"_a,
          "Express a spatial vector given in B in A (Featherstone's X for a Motion, X* for a Force).\n\n"
          "A Motion in B -> in A: [R w; R v + p x (R w)]; a Force in B -> in A: [R n + p x (R f); R f]\n"
          "(R = R_AB, p = p_AB, angular part first).\n\n"
          "Parameters\n----------\nspatial_vector : Motion or Force\n"
          "    Expressed in B (a Force's moment about B's origin).\n\n"
          "Returns\n-------\nMotion or Force\n    The same vector expressed in A (about A's origin).\n\n"
          "Raises\n------\nTypeError\n    spatial_vector neither a Motion nor a Force.\n\n"
          "Examples\n--------\n"
          ">>> rd.Transform(translation=[1.0, 0.0, 0.0]).act(rd.Force(linear=[0.0, 1.0, 0.0])).angular\n"
          "array([0., 0., 1.])\n")
      .def(
          "act_inv",
          [](const Transform& X, py::handle spatial_vector) {
            return act_on(spatial_vector, "Transform.act_inv", [&X](const auto& v) { return X.act_inv(v); });
          },
          "spatial_vector"_a,
          "Express a spatial vector given in A in B, the inverse of act.\n\n"
          "A Motion in A -> in B: [R^T w; R^T (v - p x w)]; a Force in A -> in B: [R^T (n - p x f); R^T f]\n"
          "(R = R_AB, p = p_AB, angular part first).\n\n"
          "Parameters\n----------\nspatial_vector : Motion or Force\n    Expressed in A.\n\n"
          "Returns\n-------\nMotion or Force\n    The same vector expressed in B.\n\n"
          "Raises\n------\nTypeError\n    spatial_vector neither a Motion nor a Force.\n\n"
          "Examples\n--------\n"
          ">>> X, V = rd.Transform(rd.rot_z(np.pi / 2), [1.0, 0.0, 0.0]), rd.Motion([0.0, 0.0, 1.0], [1.0, 0.0, 0.0])\n"
          ">>> X.act_inv(X.act(V)).is_approx(V)\nTrue\n")
      .def(
          "__mul__",
          [](const Transform& X_AB, py::handle X_BC) {
            return binary_operator(X_AB, X_BC, "Transform.__mul__",
                                   [](const Transform& a, const Transform& b) { return a * b; });
          },
          py::is_operator(), "X_AB * X_BC = X_AC.")
      .def("inverse", [](const Transform& X) { return checked(X.inverse(), "Transform.inverse"); },
           "X_BA = X_AB^-1: R_BA = R_AB^T, p_BA = -R_AB^T p_AB [m].")
      .def("motion_matrix", [](const Transform& X) { return py_io::finite_result(X.motion_matrix(), "Transform.motion_matrix"); },
           "Featherstone's X (6,6), angular first: [[R, 0], [hat(p) R, R]].")
      .def("force_matrix", [](const Transform& X) { return py_io::finite_result(X.force_matrix(), "Transform.force_matrix"); },
           "Featherstone's X* (6,6) = X^-T: [[R, hat(p) R], [0, R]].")
      .def(
          "is_approx",
          [](const Transform& a, py::handle b, py::handle prec) {
            return a.is_approx(py_io::as_instance<Transform>(b, "other", "a Transform"), as_precision(prec));
          },
          "other"_a, "prec"_a = 1e-12,
          "True when rotations and translations each agree to `prec` relative to the smaller norm (Eigen's\n"
          "isApprox; a zero translation compares only with an exactly zero one). == compares exactly.")
      .def(
          "__eq__",
          [](const Transform& a, py::handle b) {
            return equal_or_not_implemented(a, b, [](const Transform& x, const Transform& y) {
              return same(x.rotation(), y.rotation()) && same(x.translation(), y.translation());
            });
          },
          py::is_operator(), "Exact equality of rotation and translation.")
      .def("__repr__",
           [](const Transform& X) {
             return repr_call("Transform", {{"rotation", py_io::to_array(X.rotation())},
                                            {"translation", py_io::to_array(X.translation())}});
           })
      .def(py::pickle(
          [](const Transform& X) { return py::make_tuple(read_only(X.rotation()), read_only(X.translation())); },
          [](const py::tuple& state) {
            const py::tuple s = pickled_state(state, 2, "Transform");
            return Transform(py_io::as_matrix3(s[0], "rotation"), py_io::as_vector3(s[1], "translation"));
          }));
}

void bind_screw(py::module_& m) {
  py::class_<Screw>(
      m, "Screw",
      "Screw of a twist (instantaneous screw axis), all in the twist's frame.\n\n"
      "A unit direction, the point of the axis closest to the origin [m], the pitch [m/rad] (inf for a pure\n"
      "translation) and the magnitude (|w| [rad/s], or |v| [m/s] for a pure translation): the twist turns at\n"
      "`magnitude` about the axis while it slides along it at pitch times that.\n\n"
      "Parameters\n----------\n"
      "direction : array_like, shape (3,)\n    Unit axis direction (checked by screw_to_twist).\n"
      "point : array_like, shape (3,)\n    A point of the axis [m].\n"
      "pitch : float\n    Translation per turn angle [m/rad]; inf for a pure translation.\n"
      "magnitude : float\n    |w| [rad/s] (or |v| [m/s] for pitch inf).\n\n"
      "See Also\n--------\ntwist_to_screw, screw_to_twist, Motion\n\n"
      "Examples\n--------\n"
      ">>> s = rd.Screw([0.0, 0.0, 1.0], [-1.0, 0.0, 0.0], 0.25, 2.0)\n"
      ">>> rd.screw_to_twist(s).to_vector()\narray([0. , 0. , 2. , 0. , 2. , 0.5])\n\n"
      "Immutable; pickles; == compares every part exactly.")
      .def(py::init([](py::handle direction, py::handle point, py::handle pitch, py::handle magnitude) {
             return Screw{py_io::as_vector3(direction, "direction"), py_io::as_vector3(point, "point"),
                          py_io::as_extended_real(pitch, "pitch"), py_io::as_scalar(magnitude, "magnitude")};
           }),
           "direction"_a, "point"_a, "pitch"_a, "magnitude"_a,
           "Screw from its parts (checked by screw_to_twist): direction (3,) unit, point (3,) [m], pitch [m/rad]\n"
           "(inf: pure translation), magnitude [rad/s] (or [m/s]).")
      .def_property_readonly("direction", [](const Screw& s) { return read_only(s.direction); },
                             "Unit axis direction (3,), expressed in the twist's frame.")
      .def_property_readonly("point", [](const Screw& s) { return read_only(s.point); },
                             "(3,) [m], the point of the axis closest to the twist's frame's origin, expressed in "
                             "that frame")
      .def_readonly("pitch", &Screw::pitch, "Pitch [m/rad] along the axis; inf for a pure translation.")
      .def_readonly("magnitude", &Screw::magnitude, "Magnitude |w| [rad/s], or |v| [m/s] for a pure translation.")
      .def(
          "__eq__",
          [](const Screw& a, py::handle b) {
            return equal_or_not_implemented(a, b, [](const Screw& x, const Screw& y) {
              return same(x.direction, y.direction) && same(x.point, y.point) && x.pitch == y.pitch &&
                     x.magnitude == y.magnitude;
            });
          },
          py::is_operator(), "Exact equality of every part.")
      .def("__repr__",
           [](const Screw& s) {
             const std::string text = repr_call("Screw", {{"direction", py_io::to_array(s.direction)},
                                                          {"point", py_io::to_array(s.point)},
                                                          {"pitch", py::float_(s.pitch)},
                                                          {"magnitude", py::float_(s.magnitude)}});
             // a pure translation's pitch +inf, written so that the text evaluates
             const std::string inf = "pitch=inf,";
             const size_t at = text.find(inf);
             return at == std::string::npos ? text : text.substr(0, at) + "pitch=float('inf')," + text.substr(at + inf.size());
           })
      .def(py::pickle(
          [](const Screw& s) {
            return py::make_tuple(read_only(s.direction), read_only(s.point), s.pitch, s.magnitude);
          },
          [](const py::tuple& state) {
            const py::tuple s = pickled_state(state, 4, "Screw");
            return Screw{py_io::as_vector3(s[0], "direction"), py_io::as_vector3(s[1], "point"),
                         py_io::as_extended_real(s[2], "pitch"), py_io::as_scalar(s[3], "magnitude")};
          }));
  m.def(
      "twist_to_screw", [](py::handle twist) { return twist_to_screw(as_motion(twist, "twist")); }, "twist"_a,
        "The screw (instantaneous screw axis) of a twist.\n\n"
        "For V = [w; v] (angular first): direction w/|w|, point (w x v)/|w|^2, pitch (w . v)/|w|^2, magnitude\n"
        "|w|; for w = 0: pitch inf, direction v/|v|, point 0, magnitude |v|. Chasles' theorem: every rigid\n"
        "motion is a rotation about the axis with a slide along it.\n\n"
        "Parameters\n----------\ntwist : Motion\n    [w; v] ([rad/s], [m/s]) in any frame.\n\n"
        "Returns\n-------\nScrew\n    Its axis, pitch [m/rad] and magnitude, in the twist's frame.\n\n"
        "Raises\n------\nValueError\n    The zero twist (no axis), or a non-finite one.\nTypeError\n"
        "    twist not a Motion.\n\n"
        "See Also\n--------\nscrew_to_twist, Screw\n\n"
        "Examples\n--------\n"
        ">>> s = rd.twist_to_screw(rd.Motion([0.0, 0.0, 2.0], [0.0, 2.0, 0.5]))\n"
        ">>> s.direction, s.point, s.pitch, s.magnitude\n"
        "(array([0., 0., 1.]), array([-1.,  0.,  0.]), 0.25, 2.0)\n"
        ">>> rd.twist_to_screw(rd.Motion(linear=[0.0, 0.0, 3.0])).pitch\ninf\n");
  m.def(
      "screw_to_twist",
      [](py::handle screw) {
        return checked(screw_to_twist(py_io::as_instance<Screw>(screw, "screw", "a Screw")), "screw_to_twist");
      },
      "screw"_a,
        "The twist of a screw, inverse of twist_to_screw.\n\n"
        "w = magnitude direction, v = magnitude (point x direction + pitch direction) (v = magnitude direction for\n"
        "pitch inf), angular part first.\n\n"
        "Parameters\n----------\nscrew : Screw\n    Unit direction, point [m], pitch [m/rad], magnitude.\n\n"
        "Returns\n-------\nMotion\n    [w; v] ([rad/s], [m/s]) in the screw's frame.\n\n"
        "Raises\n------\nValueError\n"
        "    A direction that is not a unit vector, or a non-finite part (the message names it).\n"
        "TypeError\n    screw not a Screw.\n\n"
        "See Also\n--------\ntwist_to_screw, Screw\n\n"
        "Examples\n--------\n"
        ">>> V = rd.Motion([0.0, 0.0, 2.0], [0.0, 2.0, 0.5])\n"
        ">>> rd.screw_to_twist(rd.twist_to_screw(V)) == V\nTrue\n");
}

}  // namespace

void bind_spatial(py::module_& m) {
  bind_force(m);
  bind_motion(m);
  // Force.dot names Motion in its signature, so it is added once Motion is registered.
  py::reinterpret_borrow<py::class_<Force>>(m.attr("Force"))
      .def(
          "dot",
          [](const Force& f, py::handle motion) {
            return py_io::finite_result(f.dot(as_motion(motion, "motion")), "Force.dot");
          },
          "motion"_a,
          "Power w . n + v . f [W] of this force on the motion (same frame and reference point).\n\n"
          "Parameters\n----------\nmotion : Motion\n    [w; v] ([rad/s], [m/s]), in this force's frame.\n\n"
          "Returns\n-------\nfloat\n    The power [W], the same in every frame.\n\n"
          "Examples\n--------\n"
          ">>> rd.Force([0.0, 0.0, 2.0], [3.0, 0.0, 0.0]).dot(rd.Motion([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]))\n5.0\n");
  bind_transform(m);
  bind_screw(m);
  m.def(
      "motion_cross_matrix",
      [](py::handle motion) { return py_io::to_array(motion_cross_matrix(as_motion(motion, "motion"))); }, "motion"_a,
      "Motion cross-product matrix crm(V) (Featherstone, \"Rigid Body Dynamics Algorithms\").\n\n"
      "crm(V) = [[hat(w), 0], [hat(v), hat(w)]] for V = [w; v] (angular first), so that crm(V) V2 = V x V2\n"
      "(Motion.cross).\n\n"
      "Parameters\n----------\nmotion : Motion\n    V = [w; v] ([rad/s], [m/s]).\n\n"
      "Returns\n-------\nndarray, shape (6, 6)\n"
      "    crm(V), in V's frame (hat(w) blocks [rad/s], hat(v) block [m/s]).\n\n"
      "Raises\n------\nTypeError\n    motion not a Motion.\n\n"
      "See Also\n--------\nforce_cross_matrix, Motion.cross\n\n"
      "Examples\n--------\n"
      ">>> V, V2 = rd.Motion([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]), rd.Motion([1.0, 2.0, 3.0], [4.0, 5.0, 6.0])\n"
      ">>> bool(np.allclose(rd.motion_cross_matrix(V) @ V2.to_vector(), V.cross(V2).to_vector()))\nTrue\n"
      ">>> bool(np.allclose(rd.motion_cross_matrix(V) @ V.to_vector(), 0.0))  # V x V = 0\nTrue\n");
  m.def(
      "force_cross_matrix",
      [](py::handle motion) { return py_io::to_array(force_cross_matrix(as_motion(motion, "motion"))); }, "motion"_a,
      "Force cross-product matrix crf(V) (Featherstone, \"Rigid Body Dynamics Algorithms\").\n\n"
      "crf(V) = [[hat(w), hat(v)], [0, hat(w)]] = -crm(V)^T for V = [w; v] (angular first), so that\n"
      "crf(V) F = V x* F (Motion.cross_force), as in the Newton-Euler equation I a + V x* I V.\n\n"
      "Parameters\n----------\nmotion : Motion\n    V = [w; v] ([rad/s], [m/s]).\n\n"
      "Returns\n-------\nndarray, shape (6, 6)\n"
      "    crf(V), in V's frame (hat(w) blocks [rad/s], hat(v) block [m/s]).\n\n"
      "Raises\n------\nTypeError\n    motion not a Motion.\n\n"
      "See Also\n--------\nmotion_cross_matrix, Motion.cross_force\n\n"
      "Examples\n--------\n"
      ">>> V, F = rd.Motion([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]), rd.Force([0.0, 0.0, 2.0], [0.0, 3.0, 0.0])\n"
      ">>> bool(np.allclose(rd.force_cross_matrix(V), -rd.motion_cross_matrix(V).T))\nTrue\n"
      ">>> bool(np.allclose(rd.force_cross_matrix(V) @ F.to_vector(), V.cross_force(F).to_vector()))\nTrue\n");
  m.def("transform_compose", &transform_compose, "R_AB"_a, "p_AB"_a, "R_BC"_a, "p_BC"_a,
        "Compose rigid transforms item by item, X_AC = X_AB * X_BC, on arrays.\n\n"
        "R_AC = R_AB R_BC, p_AC = R_AB p_BC + p_AB, as Transform.__mul__, for stacks of n transforms; a single\n"
        "item broadcasts against the stacked ones.\n\n"
        "Parameters\n----------\n"
        "R_AB : array_like, shape (3, 3) or (n, 3, 3)\n    Rotations B -> A (orthonormal, det +1).\n"
        "p_AB : array_like, shape (3,) or (n, 3)\n    B's origin in A [m].\n"
        "R_BC : array_like, shape (3, 3) or (n, 3, 3)\n    Rotations C -> B.\n"
        "p_BC : array_like, shape (3,) or (n, 3)\n    C's origin in B [m].\n\n"
        "Returns\n-------\nR_AC : ndarray, shape (3, 3) or (n, 3, 3)\n    Rotations C -> A.\n"
        "p_AC : ndarray, shape (3,) or (n, 3)\n    C's origin in A [m] (stacked if any input is).\n\n"
        "Raises\n------\nValueError\n"
        "    A non-rotation (naming it and the item, e.g. R_AB[2]), a non-finite value, a bad shape, or\n"
        "    stacks of different lengths (naming the argument).\n\n"
        "See Also\n--------\nTransform, transform_points\n\n"
        "Examples\n--------\n"
        "Two quarter turns about z, each with a step of 1 m along its frame's x:\n\n"
        ">>> R, p = rd.transform_compose(rd.rot_z(np.pi / 2), [1.0, 0, 0], rd.rot_z(np.pi / 2), [1.0, 0, 0])\n"
        ">>> bool(np.allclose(R, rd.rot_z(np.pi))), p.round(12)\n(True, array([1., 1., 0.]))\n");
  m.def("transform_points", &transform_points, "R_AB"_a, "p_AB"_a, "p_B"_a,
        "Map points from frame B to frame A item by item: p_A = R_AB p_B + p_AB, on arrays.\n\n"
        "As Transform.act_point for stacks of n transforms or points; a single item broadcasts against the\n"
        "stacked ones.\n\n"
        "Parameters\n----------\n"
        "R_AB : array_like, shape (3, 3) or (n, 3, 3)\n    Rotations B -> A (orthonormal, det +1).\n"
        "p_AB : array_like, shape (3,) or (n, 3)\n    B's origin in A [m].\n"
        "p_B : array_like, shape (3,) or (n, 3)\n    Points in B [m].\n\n"
        "Returns\n-------\nndarray, shape (3,) or (n, 3)\n    p_A, the points in A [m] (stacked if any input is).\n\n"
        "Raises\n------\nValueError\n"
        "    A non-rotation, a non-finite value, a bad shape, or stacks of different lengths (naming the\n"
        "    argument).\n\n"
        "See Also\n--------\nTransform.act_point, transform_compose\n\n"
        "Examples\n--------\n"
        ">>> rd.transform_points(rd.rot_z(np.pi / 2), [1.0, 0.0, 0.0], [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]).round(12)\n"
        "array([[1., 1., 0.],\n       [0., 0., 0.]])\n");
}

}  // namespace rigiddyn::bindings
