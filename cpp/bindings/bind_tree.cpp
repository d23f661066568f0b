// Python bindings of the kinematic-tree layer (cpp/include/rigiddyn/tree): the joint kinds, Tree, and
// Featherstone's algorithms forward_kinematics, rnea, bias_forces, crba and aba on numpy vectors.
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "numpy_io.hpp"
#include "repr.hpp"
#include "state_args.hpp"
#include "tree_equality.hpp"
#include "value_type.hpp"
#include "rigiddyn/tree/aba.hpp"
#include "rigiddyn/tree/crba.hpp"
#include "rigiddyn/tree/energy.hpp"
#include "rigiddyn/tree/forward_kinematics.hpp"
#include "rigiddyn/tree/joint.hpp"
#include "rigiddyn/tree/momentum.hpp"
#include "rigiddyn/tree/rnea.hpp"
#include "rigiddyn/tree/tree.hpp"
#include "rigiddyn/tree/workspace.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using namespace pybind11::literals;
using py_io::Array;

namespace {

// A 1-D vector argument (q, v, a, tau); its size and values are checked by the core, naming it.
Eigen::VectorXd as_vector(py::handle obj, const char* name) {
  const Array array = py_io::as_array(obj, name);
  if (array.ndim() != 1) py_io::throw_value_error(name, "a 1-D array", py_io::describe(obj));
  return Eigen::Map<const Eigen::VectorXd>(array.data(), array.size());
}

// A matrix as a 2-D array (rows, cols), also when it has one column (py_io::to_array makes that 1-D).
template <typename Derived>
Array matrix_array(const Eigen::MatrixBase<Derived>& m) {
  Array out({static_cast<py::ssize_t>(m.rows()), static_cast<py::ssize_t>(m.cols())});
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(out.mutable_data(), m.rows(), m.cols()) = m;
  return out;
}

const Tree& as_tree(py::handle obj) { return py_io::as_instance<Tree>(obj, "tree", "a Tree"); }

// The workspace the algorithms run in, kept between calls and made again only for a tree of another shape: a call
// then allocates nothing but its arguments and its result. Each call holds the GIL, so one call at a time uses it;
// take it after the arguments are converted (a conversion may call Python, and so another algorithm).
TreeWorkspace& workspace_for(const Tree& tree) {
  static std::optional<TreeWorkspace> kept;
  if (!kept || !kept->fits(tree)) kept.emplace(tree);
  return *kept;
}

// One of the joint classes.
Joint as_joint(py::handle obj) {
  if (is_instance<RevoluteJoint>(obj)) return obj.cast<RevoluteJoint>();
  if (is_instance<PrismaticJoint>(obj)) return obj.cast<PrismaticJoint>();
  if (is_instance<SphericalJoint>(obj)) return obj.cast<SphericalJoint>();
  if (is_instance<FreeJoint>(obj)) return obj.cast<FreeJoint>();
  if (is_instance<FixedJoint>(obj)) return obj.cast<FixedJoint>();
  py_io::throw_type_error("joint", "a RevoluteJoint, PrismaticJoint, SphericalJoint, FreeJoint or FixedJoint", obj);
}

// f_ext: None (no external force) or (n_links, 6) rows [n; f], each in its link's frame.
std::vector<Force> as_external_forces(py::handle obj, const Tree& tree) {
  std::vector<Force> f_ext;
  if (obj.is_none()) return f_ext;
  const Array array = py_io::as_array(obj, "f_ext");
  if (array.ndim() != 2 || array.shape(0) != tree.num_links() || array.shape(1) != 6) {
    py_io::throw_value_error("f_ext", "shape (n_links, 6) = (" + std::to_string(tree.num_links()) + ", 6)",
                             py_io::describe(obj));
  }
  for (int i = 0; i < tree.num_links(); ++i) f_ext.push_back(Force::from_vector(Eigen::Map<const Vector6d>(array.data() + 6 * i)));
  return f_ext;
}

const char* const tree_example =
    ">>> tree = rd.Tree(gravity=[0.0, 0.0, -9.81])\n"
    ">>> bob = rd.SpatialInertia(1.0, [0.0, 0.0, -1.0], 0.1 * np.eye(3))\n"
    ">>> tree.add_link(\"pendulum\", -1, rd.RevoluteJoint([1.0, 0.0, 0.0]), bob)\n0\n";

// The members every joint class has: nq, nv, transform(q), motion_subspace().
// == (the kind and axis), a repr that reads as the constructor call, and pickling (the axis, or nothing)
template <class J>
void bind_joint_value(py::class_<J>& c, const std::string& name) {
  constexpr bool has_axis = std::is_same_v<J, RevoluteJoint> || std::is_same_v<J, PrismaticJoint>;
  def_equality(c, [](const J& a, const J& b) { return same_joint(a, b); });
  c.def("__repr__", [name](const J& joint) -> std::string {
    if constexpr (has_axis) {
      return repr_call(name, {{"axis", py_io::to_array(joint.axis)}});
    } else {
      return name + "()";
    }
  });
  c.def(py::pickle(
      [](const J& joint) -> py::tuple {
        if constexpr (has_axis) {
          return py::make_tuple(py_io::to_array(joint.axis));
        } else {
          return py::tuple();
        }
      },
      [name](const py::tuple& state) -> J {
        if constexpr (has_axis) {
          return J(py_io::as_vector3(pickled_state(state, 1, name)[0], "axis"));
        } else {
          pickled_state(state, 0, name);
          return J();
        }
      }));
}

template <class J>
void bind_joint_members(py::class_<J>& c, const std::string& name, const std::string& q_example,
                        const std::string& transform_output, const std::string& subspace_output) {
  bind_joint_value(c, name);
  c.def_property_readonly("nq", [](const J&) { return J::nq; }, "Number of configuration coordinates q of the joint.")
      .def_property_readonly("nv", [](const J&) { return J::nv; }, "Number of velocity coordinates qd of the joint.")
      .def(
          "transform",
          [](const J& joint, py::handle q) {
            const Eigen::VectorXd q_J = as_vector(q, "q");
            if (q_J.size() != J::nq) py_io::throw_value_error("q", "shape (" + std::to_string(J::nq) + ",)", py_io::describe(q));
            require_finite(q_J.transpose(), "q");
            return joint.transform(q_J);
          },
          "q"_a,
          ("X_J(q): the pose of the successor frame L in the joint frame J.\n\n"
           "Parameters\n----------\nq : array_like, shape (joint.nq,)\n    The joint's configuration.\n\n"
           "Returns\n-------\nTransform\n    X_JL.\n\n"
           "Raises\n------\nValueError\n    q of another size or not finite.\n\n"
           "Examples\n--------\n>>> X = rd." + name + q_example + "\n" + transform_output)
              .c_str())
      .def(
          "motion_subspace", [](const J& joint) { return matrix_array(joint.motion_subspace()); },
          ("The motion subspace S, shape (6, nv), angular rows first, in the successor frame L.\n\n"
           "The joint's velocity qd moves L with the twist S qd relative to J (expressed in L).\n\n"
           "Returns\n-------\nndarray, shape (6, nv)\n\n"
           "Examples\n--------\n>>> rd." + name + subspace_output)
              .c_str());
}

void bind_joints(py::module_& m) {
  py::class_<RevoluteJoint> revolute(
      m, "RevoluteJoint",
      "A revolute joint: rotation by the angle q [rad] about a fixed axis.\n\n"
      "X_J(q) = (Rot(a, q), 0), S = [a; 0] (Featherstone, Rigid Body Dynamics Algorithms, Table 4.1); nq = nv = 1.\n\n"
      "Parameters\n----------\naxis : array_like, shape (3,), default (0, 0, 1)\n"
      "    The axis a in the joint frame (and the link frame), any non-zero length (normalised).\n\n"
      "Raises\n------\nValueError\n    A zero or non-finite axis.\n\n"
      "See Also\n--------\nPrismaticJoint, SphericalJoint, FreeJoint, FixedJoint, Tree\n\n"
      "Examples\n--------\n>>> rd.RevoluteJoint([0.0, 0.0, 2.0]).axis\narray([0., 0., 1.])\n");
  revolute.def(py::init([](py::handle axis) { return RevoluteJoint(py_io::as_vector3(axis, "axis")); }),
               "axis"_a = py::make_tuple(0.0, 0.0, 1.0))
      .def_property_readonly("axis", [](const RevoluteJoint& j) { return py_io::read_only(j.axis); },
                             "The unit axis a, in the joint frame and the link frame.");
  bind_joint_members(revolute, "RevoluteJoint", "().transform([np.pi / 2])",
                     ">>> X.rotation.round(12)\narray([[ 0., -1.,  0.],\n       [ 1.,  0.,  0.],\n       [ 0.,  0.,  1.]])\n",
                     "().motion_subspace().T\narray([[0., 0., 1., 0., 0., 0.]])\n");

  py::class_<PrismaticJoint> prismatic(
      m, "PrismaticJoint",
      "A prismatic joint: translation by q [m] along a fixed axis.\n\n"
      "X_J(q) = (1, a q), S = [0; a] (Featherstone, Rigid Body Dynamics Algorithms, Table 4.1); nq = nv = 1.\n\n"
      "Parameters\n----------\naxis : array_like, shape (3,), default (0, 0, 1)\n"
      "    The axis a in the joint frame (and the link frame), any non-zero length (normalised).\n\n"
      "Raises\n------\nValueError\n    A zero or non-finite axis.\n\n"
      "See Also\n--------\nRevoluteJoint, Tree\n\n"
      "Examples\n--------\n>>> rd.PrismaticJoint([3.0, 0.0, 4.0]).axis\narray([0.6, 0. , 0.8])\n");
  prismatic.def(py::init([](py::handle axis) { return PrismaticJoint(py_io::as_vector3(axis, "axis")); }),
                "axis"_a = py::make_tuple(0.0, 0.0, 1.0))
      .def_property_readonly("axis", [](const PrismaticJoint& j) { return py_io::read_only(j.axis); },
                             "The unit axis a, in the joint frame and the link frame.");
  bind_joint_members(prismatic, "PrismaticJoint", "([1.0, 0.0, 0.0]).transform([0.5])",
                     ">>> X.translation\narray([0.5, 0. , 0. ])\n",
                     "([1.0, 0.0, 0.0]).motion_subspace().T\narray([[0., 0., 0., 1., 0., 0.]])\n");

  py::class_<SphericalJoint> spherical(
      m, "SphericalJoint",
      "A spherical (ball) joint: any rotation about the common origin of the joint and link frames.\n\n"
      "Configuration: the unit quaternion q_JL as (x, y, z, w) (nq = 4); velocity: w_L, the angular velocity\n"
      "[rad/s] of the link relative to the joint frame, expressed in the link frame (nv = 3). X_J(q) = (R(q_JL), 0),\n"
      "S = [1; 0]; Tree.integrate moves q_JL on SO(3): q_JL ⊗ exp(w_L dt / 2).\n\n"
      "See Also\n--------\nFreeJoint, RevoluteJoint, Tree\n\n"
      "Examples\n--------\n>>> rd.SphericalJoint().nq, rd.SphericalJoint().nv\n(4, 3)\n");
  spherical.def(py::init<>());
  bind_joint_members(spherical, "SphericalJoint", "().transform([0.0, 0.0, np.sin(np.pi / 4), np.cos(np.pi / 4)])",
                     ">>> bool(np.allclose(X.rotation, rd.rot_z(np.pi / 2)))\nTrue\n",
                     "().motion_subspace()[:3]\narray([[1., 0., 0.],\n       [0., 1., 0.],\n       [0., 0., 1.]])\n");

  py::class_<FreeJoint> free(
      m, "FreeJoint",
      "A free joint: six degrees of freedom (a floating base).\n\n"
      "Configuration (nq = 7): (x, y, z, qx, qy, qz, qw), the link origin's position p_JL [m] in the joint frame\n"
      "and the unit quaternion q_JL. Velocity (nv = 6): the twist [w_L; v_L] of the link relative to the joint\n"
      "frame, expressed in the link frame (angular first; v_L the velocity [m/s] of the link's origin).\n"
      "X_J(q) = (R(q_JL), p_JL), S = 1. Tree.integrate: q_JL ⊗ exp(w_L dt / 2) and p_JL + R(q_JL) v_L dt.\n\n"
      "See Also\n--------\nSphericalJoint, Tree\n\n"
      "Examples\n--------\n>>> rd.FreeJoint().nq, rd.FreeJoint().nv\n(7, 6)\n");
  free.def(py::init<>());
  bind_joint_members(free, "FreeJoint", "().transform([1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 1.0])",
                     ">>> X.translation\narray([1., 2., 3.])\n",
                     "().motion_subspace().shape\n(6, 6)\n");

  py::class_<FixedJoint> fixed(
      m, "FixedJoint",
      "A fixed joint (a weld): the link is rigidly attached to its parent at its placement.\n\n"
      "X_J = 1, S has no columns, nq = nv = 0.\n\n"
      "See Also\n--------\nRevoluteJoint, Tree\n\n"
      "Examples\n--------\n>>> rd.FixedJoint().nq, rd.FixedJoint().nv\n(0, 0)\n");
  fixed.def(py::init<>());
  bind_joint_members(fixed, "FixedJoint", "().transform(np.zeros(0))", ">>> X.is_approx(rd.Transform())\nTrue\n",
                     "().motion_subspace().shape\n(6, 0)\n");
}

// A tree's pickled state: its gravity and, link by link, (name, parent, joint, inertia, placement)
py::tuple tree_state(const Tree& tree) {
  py::list links;
  for (const Link& link : tree.links()) {
    links.append(py::make_tuple(link.name, link.parent, std::visit([](const auto& j) { return py::cast(j); }, link.joint),
                                link.inertia, link.X_T));
  }
  return py::make_tuple(py_io::to_array(tree.gravity()), links);
}
// The tree of a state, its links added in order (add_link's checks name a bad one)
Tree tree_from_state(const py::tuple& state) {
  const py::tuple s = pickled_state(state, 2, "Tree");
  Tree tree(py_io::as_vector3(s[0], "gravity"));
  for (const py::handle item : py::list(s[1])) {
    const py::tuple link = pickled_state(item, 5, "Tree link");
    tree.add_link(py_io::as_string(link[0], "name"), static_cast<int>(py_io::as_int(link[1], "parent", -1, tree.num_links() - 1)),
                  as_joint(link[2]), py_io::as_instance<SpatialInertia>(link[3], "inertia", "a SpatialInertia"),
                  py_io::as_instance<Transform>(link[4], "placement", "a Transform"));
  }
  return tree;
}

void bind_tree_class(py::module_& m) {
  py::class_<Tree>(
      m, "Tree",
      (std::string("A kinematic tree of rigid links joined by joints, rooted at the world frame W.\n\n"
                   "Links are numbered 0, 1, ... in the order added, each after its parent. Link i sits at\n"
                   "X_λi = X_T X_J(q_i) in its parent λ(i) (W for parent -1): X_T its placement, X_J(q_i) its joint's\n"
                   "transform. The configuration q (nq,) stacks the joints' coordinates in link order, the velocity\n"
                   "v (nv,) their velocities (Featherstone, Rigid Body Dynamics Algorithms, ch. 4).\n\n"
                   "Parameters\n----------\ngravity : array_like, shape (3,), optional\n"
                   "    Uniform gravity g [m/s²] in W (None: no gravity).\n\n"
                   "Raises\n------\nValueError\n    A non-finite gravity.\n\n"
                   "See Also\n--------\nrnea, crba, aba, forward_kinematics\n\n"
                   "Examples\n--------\n") +
       tree_example + ">>> tree.nq, tree.nv, tree.link_names\n(1, 1, ['pendulum'])\n")
          .c_str())
      .def(py::init([](py::handle gravity) { return Tree(py_io::as_vector3_or_zero(gravity, "gravity")); }),
           "gravity"_a = py::none())
      .def(py::pickle(&tree_state, &tree_from_state))
      .def(
          "__eq__", [](const Tree& a, py::handle b) { return equal_or_not_implemented(a, b, &same_tree); }, "other"_a,
          "Whether `other` is a Tree with the same gravity and, link by link, the same names, parents, joints, "
          "placements and inertias (exact).")
      .def(
          "add_link",
          [](Tree& tree, py::handle name, py::handle parent, py::handle joint, py::handle inertia, py::handle placement) {
            const Transform X_T = placement.is_none() ? Transform()
                                                      : py_io::as_instance<Transform>(placement, "placement", "a Transform");
            return tree.add_link(py_io::as_string(name, "name"), static_cast<int>(py_io::as_int(parent, "parent", std::numeric_limits<int>::min(), std::numeric_limits<int>::max())),
                                 as_joint(joint), py_io::as_instance<SpatialInertia>(inertia, "inertia", "a SpatialInertia"),
                                 X_T);
          },
          "name"_a, "parent"_a, "joint"_a, "inertia"_a, "placement"_a = py::none(),
          (std::string("Append a link and return its index.\n\n"
                       "Parameters\n----------\nname : str\n    A name not yet used.\n"
                       "parent : int\n    The parent link's index, -1 for the world (parents are added first).\n"
                       "joint : RevoluteJoint, PrismaticJoint, SphericalJoint, FreeJoint or FixedJoint\n"
                       "    The joint from the parent to this link.\n"
                       "inertia : SpatialInertia\n    Mass, centre of mass [m] and inertia about it [kg m²], in the link\n"
                       "    frame; positive definite (every principal moment > 0).\n"
                       "placement : Transform, optional\n"
                       "    X_T: the joint frame in the parent's frame (None: identity).\n\n"
                       "Returns\n-------\nint\n    The new link's index.\n\n"
                       "Raises\n------\nValueError\n"
                       "    A used or empty name, a parent not in [-1, num_links - 1], or an inertia with a zero\n"
                       "    principal moment (a point mass); the message names the link.\n\n"
                       "Examples\n--------\n") +
           tree_example +
           ">>> tree.add_link(\"tip\", 0, rd.FixedJoint(), bob, rd.Transform(translation=[0.0, 0.0, -1.0]))\n1\n")
              .c_str())
      .def_property_readonly("num_links", &Tree::num_links, "Number of links n.")
      .def_property_readonly("nq", &Tree::nq, "Size of the configuration q.")
      .def_property_readonly("nv", &Tree::nv, "Size of the velocity v (and of accelerations and joint forces).")
      .def_property_readonly("gravity", [](const Tree& t) { return py_io::read_only(t.gravity()); },
                             "Uniform gravity g [m/s²] in W.")
      .def_property_readonly(
          "link_names",
          [](const Tree& t) {
            py::list names;
            for (const Link& link : t.links()) names.append(link.name);
            return names;
          },
          "The links' names, in index order.")
      .def_property_readonly(
          "parents",
          [](const Tree& t) {
            py::list parents;
            for (const Link& link : t.links()) parents.append(link.parent);
            return parents;
          },
          "The links' parent indices λ(i) (-1: the world), in index order.")
      .def_property_readonly(
          "joints",
          [](const Tree& t) {
            py::list joints;
            for (const Link& link : t.links()) joints.append(std::visit([](const auto& j) { return py::cast(j); }, link.joint));
            return joints;
          },
          "The links' joints (copies), in index order.")
      .def_property_readonly(
          "placements",
          [](const Tree& t) {
            py::list placements;
            for (const Link& link : t.links()) placements.append(py::cast(link.X_T));
            return placements;
          },
          "The links' placements X_T (Transforms: each joint frame in its parent's frame), in index order.")
      .def_property_readonly(
          "inertias",
          [](const Tree& t) {
            py::list inertias;
            for (const Link& link : t.links()) inertias.append(py::cast(link.inertia));
            return inertias;
          },
          "The links' SpatialInertias (each in its link frame), in index order.")
      .def(
          "link_index", [](const Tree& t, py::handle name) { return t.link_index(py_io::as_string(name, "name")); },
          "name"_a,
          (std::string("The index of the link called `name`.\n\n"
                       "Parameters\n----------\nname : str\n\n"
                       "Returns\n-------\nint\n\n"
                       "Raises\n------\nValueError\n    No link has that name.\n\n"
                       "Examples\n--------\n") +
           tree_example + ">>> tree.link_index(\"pendulum\")\n0\n")
              .c_str())
      .def(
          "neutral_configuration", [](const Tree& t) { return py_io::to_array(t.neutral_configuration()); },
          "The neutral configuration (nq,): every angle and offset 0, every quaternion (0, 0, 0, 1).\n\n"
          "Returns\n-------\nndarray, shape (tree.nq,)\n\n"
          "Examples\n--------\n>>> tree = rd.Tree()\n"
          ">>> tree.add_link(\"base\", -1, rd.FreeJoint(), rd.SpatialInertia(1.0, [0, 0, 0], np.eye(3)))\n0\n"
          ">>> tree.neutral_configuration()\narray([0., 0., 0., 0., 0., 0., 1.])\n")
      .def(
          "integrate",
          [](const Tree& t, py::handle q, py::handle v, py::handle dt) {
            const Eigen::VectorXd q_in = as_vector(q, "q"), v_in = as_vector(v, "v");
            Eigen::VectorXd q_out(t.nq());
            t.integrate(q_in, v_in, py_io::as_scalar(dt, "dt"), q_out);
            return py_io::to_array(q_out);
          },
          "q"_a, "v"_a, "dt"_a,
          "The configuration q ⊕ v dt reached from q moving with velocity v for a time dt [s].\n\n"
          "Joint by joint: q + qd dt for revolute and prismatic joints; q_JL ⊗ exp(w_L dt / 2) on SO(3) for a\n"
          "quaternion (spherical and free joints; the result is a unit quaternion); p_JL + R(q_JL) v_L dt for\n"
          "a free joint's position.\n\n"
          "Parameters\n----------\nq : array_like, shape (tree.nq,)\n    Configuration (unit quaternions within 1e-6).\n"
          "v : array_like, shape (tree.nv,)\n    Velocity.\ndt : float\n    Time step [s].\n\n"
          "Returns\n-------\nndarray, shape (tree.nq,)\n\n"
          "Raises\n------\nValueError\n    A wrong size, a non-finite value or a non-unit quaternion (naming it).\n\n"
          "Examples\n--------\nA ball joint turning at pi/2 rad/s about z for 1 s:\n\n"
          ">>> tree = rd.Tree()\n"
          ">>> tree.add_link(\"ball\", -1, rd.SphericalJoint(), rd.SpatialInertia(1.0, [0, 0, 0], np.eye(3)))\n0\n"
          ">>> q = tree.integrate(tree.neutral_configuration(), [0.0, 0.0, np.pi / 2], 1.0)\n"
          ">>> bool(np.allclose(q, [0.0, 0.0, np.sin(np.pi / 4), np.cos(np.pi / 4)]))\nTrue\n")
      .def(
          "kinetic_energy",
          [](const Tree& t, py::handle q, py::handle v) {
            const Eigen::VectorXd q_in = as_vector(q, "q"), v_in = as_vector(v, "v");
            return py_io::finite_result(kinetic_energy(t, q_in, v_in, workspace_for(t)), "kinetic_energy");
          },
          "q"_a, "v"_a,
          (std::string("Kinetic energy T = sum_i 1/2 v_i . I_i v_i [J] (= 1/2 v^T H(q) v).\n\n"
                       "Parameters\n----------\nq : array_like, shape (tree.nq,)\n    Configuration.\n"
                       "v : array_like, shape (tree.nv,)\n    Velocity.\n\n"
                       "Returns\n-------\nfloat\n\n"
                       "Raises\n------\nValueError\n    A wrong size, a non-finite value or a non-unit quaternion.\n\n"
                       "Examples\n--------\n") +
           tree_example + ">>> round(tree.kinetic_energy([0.0], [2.0]), 12)  # 1/2 (0.1 + 1.0) 2^2\n2.2\n")
              .c_str())
      .def(
          "potential_energy",
          [](const Tree& t, py::handle q) {
            const Eigen::VectorXd q_in = as_vector(q, "q");
            return py_io::finite_result(potential_energy(t, q_in, workspace_for(t)), "potential_energy");
          },
          "q"_a,
          (std::string("Potential energy V = -sum_i m_i g . p_W,Ci [J] of the uniform gravity (0 at W's origin).\n\n"
                       "Parameters\n----------\nq : array_like, shape (tree.nq,)\n    Configuration.\n\n"
                       "Returns\n-------\nfloat\n\n"
                       "Raises\n------\nValueError\n    A wrong size, a non-finite value or a non-unit quaternion.\n\n"
                       "Examples\n--------\n") +
           tree_example + ">>> round(tree.potential_energy([0.0]), 12)  # the bob 1 m below W's origin\n-9.81\n")
              .c_str());
}

void bind_algorithms(py::module_& m) {
  m.def(
      "forward_kinematics",
      [](py::handle tree_obj, py::handle q, py::handle v) {
        const Tree& tree = as_tree(tree_obj);
        const Eigen::VectorXd q_in = as_vector(q, "q");
        const Eigen::VectorXd v_in = v.is_none() ? Eigen::VectorXd::Zero(tree.nv()) : as_vector(v, "v");
        TreeWorkspace& ws = workspace_for(tree);
        forward_kinematics(tree, q_in, v_in, ws);
        const py::ssize_t n = tree.num_links();
        Array R({n, py::ssize_t{3}, py::ssize_t{3}}), p({n, py::ssize_t{3}}), V({n, py::ssize_t{6}});
        for (py::ssize_t i = 0; i < n; ++i) {
          Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(R.mutable_data() + 9 * i) = ws.X_W[i].rotation();
          Eigen::Map<Eigen::Vector3d>(p.mutable_data() + 3 * i) = ws.X_W[i].translation();
          Eigen::Map<Vector6d>(V.mutable_data() + 6 * i) = ws.v[i].to_vector();
        }
        return py::make_tuple(R, py_io::finite_result(p, "forward_kinematics p_WL"),
                              py_io::finite_result(V, "forward_kinematics V_L"));
      },
      "tree"_a, "q"_a, "v"_a = py::none(),
      (std::string("Forward kinematics: every link's pose in W and its twist.\n\n"
                   "X_λi = X_T X_J(q_i), X_Wi = X_Wλ X_λi, v_i = X_λi^-1 v_λ + S_i qd_i (Featherstone, Rigid Body\n"
                   "Dynamics Algorithms, Table 5.1).\n\n"
                   "Parameters\n----------\ntree : Tree\nq : array_like, shape (tree.nq,)\n    Configuration.\n"
                   "v : array_like, shape (tree.nv,), optional\n    Velocity (None: zero).\n\n"
                   "Returns\n-------\nR_WL : ndarray, shape (n, 3, 3)\n    Each link's orientation (link -> W coordinates).\n"
                   "p_WL : ndarray, shape (n, 3)\n    Each link's origin in W [m].\n"
                   "V_L : ndarray, shape (n, 6)\n"
                   "    Each link's twist in W, expressed in the link frame, [w; v] (v: the velocity of the link's\n"
                   "    origin) [rad/s, m/s].\n\n"
                   "Raises\n------\nValueError\n    A wrong size, a non-finite value or a non-unit quaternion (naming it).\n\n"
                   "Examples\n--------\n") +
       tree_example +
       ">>> R, p, V = rd.forward_kinematics(tree, [np.pi / 2], [1.0])\n"
       ">>> (R[0] @ bob.com + p[0]).round(12) + 0.0  # the bob swung up to +y\narray([0., 1., 0.])\n"
       ">>> V[0]\narray([1., 0., 0., 0., 0., 0.])\n")
          .c_str());
  m.def(
      "rnea",
      [](py::handle tree_obj, py::handle q, py::handle v, py::handle a, py::handle f_ext) {
        const Tree& tree = as_tree(tree_obj);
        const Eigen::VectorXd q_in = as_vector(q, "q"), v_in = as_vector(v, "v"), a_in = as_vector(a, "a");
        const std::vector<Force> forces = as_external_forces(f_ext, tree);
        return py_io::finite_result(py_io::to_array(rnea(tree, q_in, v_in, a_in, forces, workspace_for(tree))), "rnea");
      },
      "tree"_a, "q"_a, "v"_a, "a"_a, "f_ext"_a = py::none(),
      (std::string("Inverse dynamics by the recursive Newton-Euler algorithm: tau = H(q) a + C(q, v, f_ext).\n\n"
                   "Featherstone, Rigid Body Dynamics Algorithms, Table 5.1, with the tree's gravity as the base\n"
                   "acceleration -g: the joint forces that give the acceleration a.\n\n"
                   "Parameters\n----------\ntree : Tree\nq : array_like, shape (tree.nq,)\n    Configuration.\n"
                   "v : array_like, shape (tree.nv,)\n    Velocity.\na : array_like, shape (tree.nv,)\n    Acceleration.\n"
                   "f_ext : array_like, shape (n, 6), optional\n"
                   "    External force [n; f] on each link, in its link frame (moment about the link's origin)\n"
                   "    [N m, N] (None: none).\n\n"
                   "Returns\n-------\nndarray, shape (tree.nv,)\n    tau [N m for a rotation, N for a translation].\n\n"
                   "Raises\n------\nValueError\n    A wrong size, a non-finite value or a non-unit quaternion (naming it).\n\n"
                   "See Also\n--------\nbias_forces, crba, aba\n\n"
                   "Examples\n--------\nThe torque that holds the pendulum horizontal is m g l:\n\n") +
       tree_example + ">>> rd.rnea(tree, [np.pi / 2], [0.0], [0.0]).round(12)\narray([9.81])\n")
          .c_str());
  m.def(
      "bias_forces",
      [](py::handle tree_obj, py::handle q, py::handle v) {
        const Tree& tree = as_tree(tree_obj);
        const Eigen::VectorXd q_in = as_vector(q, "q"), v_in = as_vector(v, "v");
        return py_io::finite_result(py_io::to_array(bias_forces(tree, q_in, v_in, workspace_for(tree))), "bias_forces");
      },
      "tree"_a, "q"_a, "v"_a,
      (std::string("The bias forces C(q, v) = rnea(tree, q, v, 0): Coriolis, centrifugal and gravity terms.\n\n"
                   "The equation of motion is H(q) a + C(q, v) = tau.\n\n"
                   "Parameters\n----------\ntree : Tree\nq : array_like, shape (tree.nq,)\n    Configuration.\n"
                   "v : array_like, shape (tree.nv,)\n    Velocity.\n\n"
                   "Returns\n-------\nndarray, shape (tree.nv,)\n\n"
                   "Raises\n------\nValueError\n    A wrong size, a non-finite value or a non-unit quaternion (naming it).\n\n"
                   "See Also\n--------\nrnea, crba\n\n"
                   "Examples\n--------\n") +
       tree_example + ">>> rd.bias_forces(tree, [np.pi / 2], [3.0]).round(12)  # gravity only: no Coriolis term\n"
                      "array([9.81])\n")
          .c_str());
  m.def(
      "crba",
      [](py::handle tree_obj, py::handle q) {
        const Tree& tree = as_tree(tree_obj);
        const Eigen::VectorXd q_in = as_vector(q, "q");
        return py_io::finite_result(matrix_array(crba(tree, q_in, workspace_for(tree))), "crba");
      },
      "tree"_a, "q"_a,
      (std::string("The joint-space inertia matrix H(q) by the composite-rigid-body algorithm.\n\n"
                   "Featherstone, Rigid Body Dynamics Algorithms, Table 6.2: symmetric positive definite, with\n"
                   "T = 1/2 v^T H v.\n\n"
                   "Parameters\n----------\ntree : Tree\nq : array_like, shape (tree.nq,)\n    Configuration.\n\n"
                   "Returns\n-------\nndarray, shape (tree.nv, tree.nv)\n\n"
                   "Raises\n------\nValueError\n    A wrong size, a non-finite value or a non-unit quaternion (naming it).\n\n"
                   "See Also\n--------\nrnea, aba\n\n"
                   "Examples\n--------\nThe pendulum's moment of inertia about its axis, I_C + m l²:\n\n") +
       tree_example + ">>> rd.crba(tree, [0.3]).round(12)\narray([[1.1]])\n")
          .c_str());
  m.def(
      "aba",
      [](py::handle tree_obj, py::handle q, py::handle v, py::handle tau, py::handle f_ext) {
        const Tree& tree = as_tree(tree_obj);
        const Eigen::VectorXd q_in = as_vector(q, "q"), v_in = as_vector(v, "v"), tau_in = as_vector(tau, "tau");
        const std::vector<Force> forces = as_external_forces(f_ext, tree);
        return py_io::finite_result(py_io::to_array(aba(tree, q_in, v_in, tau_in, forces, workspace_for(tree))), "aba");
      },
      "tree"_a, "q"_a, "v"_a, "tau"_a, "f_ext"_a = py::none(),
      (std::string("Forward dynamics by the articulated-body algorithm: a = H(q)^-1 (tau - C(q, v, f_ext)).\n\n"
                   "Featherstone, Rigid Body Dynamics Algorithms, Table 7.1, in O(n); the inverse of rnea.\n\n"
                   "Parameters\n----------\ntree : Tree\nq : array_like, shape (tree.nq,)\n    Configuration.\n"
                   "v : array_like, shape (tree.nv,)\n    Velocity.\ntau : array_like, shape (tree.nv,)\n    Joint forces.\n"
                   "f_ext : array_like, shape (n, 6), optional\n"
                   "    External force [n; f] on each link, in its link frame (None: none).\n\n"
                   "Returns\n-------\nndarray, shape (tree.nv,)\n    The acceleration a.\n\n"
                   "Raises\n------\nValueError\n    A wrong size, a non-finite value or a non-unit quaternion (naming it).\n\n"
                   "See Also\n--------\nrnea, crba\n\n"
                   "Examples\n--------\nThe horizontal pendulum falls with I a = -m g l:\n\n") +
       tree_example + ">>> a = rd.aba(tree, [np.pi / 2], [0.0], [0.0])\n"
                      ">>> bool(np.isclose(a[0], -9.81 / 1.1))\nTrue\n")
          .c_str());
  m.def(
      "generalized_momentum",
      [](py::handle tree_obj, py::handle q, py::handle v) {
        const Tree& tree = as_tree(tree_obj);
        const Eigen::VectorXd q_in = as_vector(q, "q"), v_in = as_vector(v, "v");
        return py_io::finite_result(py_io::to_array(generalized_momentum(tree, q_in, v_in, workspace_for(tree))),
                                    "generalized_momentum");
      },
      "tree"_a, "q"_a, "v"_a,
      (std::string("The generalized momentum p = dT/dv = H(q) v, one entry per joint coordinate.\n\n"
                   "p_i = S_i^T h_i, with h_i the momentum of the subtree at link i (its links' I_k v_k carried to\n"
                   "link i's frame; Featherstone, Rigid Body Dynamics Algorithms, sec. 6.2): for a revolute joint the\n"
                   "angular momentum of everything beyond it about its axis, for a prismatic joint their linear\n"
                   "momentum along it.\n\n"
                   "Parameters\n----------\ntree : Tree\nq : array_like, shape (tree.nq,)\n    Configuration.\n"
                   "v : array_like, shape (tree.nv,)\n    Velocity.\n\n"
                   "Returns\n-------\nndarray, shape (tree.nv,)\n"
                   "    p [N m s for a rotation, N s for a translation; for a ball or free joint the link-frame\n"
                   "    angular momentum about the joint (and linear momentum)].\n\n"
                   "Raises\n------\nValueError\n    A wrong size, a non-finite value or a non-unit quaternion (naming it).\n\n"
                   "See Also\n--------\ngeneralized_momentum_rate, crba\n\n"
                   "Examples\n--------\n") +
       tree_example + ">>> rd.generalized_momentum(tree, [0.3], [2.0]).round(12)  # (I_C + m l^2) v\narray([2.2])\n")
          .c_str());
  m.def(
      "generalized_momentum_rate",
      [](py::handle tree_obj, py::handle q, py::handle v, py::handle f_ext) {
        const Tree& tree = as_tree(tree_obj);
        const Eigen::VectorXd q_in = as_vector(q, "q"), v_in = as_vector(v, "v");
        const std::vector<Force> forces = as_external_forces(f_ext, tree);
        return py_io::finite_result(
            py_io::to_array(generalized_momentum_rate(tree, q_in, v_in, forces, workspace_for(tree))),
            "generalized_momentum_rate");
      },
      "tree"_a, "q"_a, "v"_a, "f_ext"_a = py::none(),
      (std::string("The rate of the generalized momentum by Lagrange's equations: dp/dt = dT/dq + Q, joint forces\n"
                   "excluded (with joint forces tau, dp/dt = tau + this).\n\n"
                   "The momentum equation f = d(m v)/dt of a chain: dT/dq at fixed v (the momentum a joint gains as\n"
                   "the links beyond it move against their parents' motion) plus Q, the generalized force of gravity\n"
                   "and f_ext. For trees of revolute, prismatic and fixed joints (a ball or free joint's momentum rate\n"
                   "has a further term of its rotation group).\n\n"
                   "Parameters\n----------\ntree : Tree\nq : array_like, shape (tree.nq,)\n    Configuration.\n"
                   "v : array_like, shape (tree.nv,)\n    Velocity.\n"
                   "f_ext : array_like, shape (n, 6), optional\n"
                   "    External force [n; f] on each link, in its link frame (None: none).\n\n"
                   "Returns\n-------\nndarray, shape (tree.nv,)\n    dp/dt [N m for a rotation, N for a translation].\n\n"
                   "Raises\n------\nValueError\n    A wrong size, a non-finite value, or a ball or free joint (naming its link).\n\n"
                   "See Also\n--------\ngeneralized_momentum, aba\n\n"
                   "Examples\n--------\nThe horizontal pendulum's gravity torque, whatever its speed (one joint: dT/dq = 0):\n\n") +
       tree_example + ">>> rd.generalized_momentum_rate(tree, [np.pi / 2], [3.0]).round(12)\narray([-9.81])\n")
          .c_str());
}

}  // namespace

void bind_tree(py::module_& m) {
  bind_joints(m);
  bind_tree_class(m);
  bind_algorithms(m);
}

}  // namespace rigiddyn::bindings
