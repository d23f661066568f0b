// Python bindings of a tree's links as bodies of a scene (tree/tree_link.hpp): TreeLink (what Scene.add_tree adds,
// one per link), JointState (a link's state: its joint's q and v) and Tree.joint_states / Tree.coordinates_of, which
// split a tree's (q, v) into its links' states and stack them back.
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "numpy_io.hpp"
#include "repr.hpp"
#include "state_args.hpp"
#include "tree_equality.hpp"
#include "value_type.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/tree/tree_link.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

// A 1-D vector of finite floats (None: empty), naming `name` otherwise; its size is checked against a joint by a run.
Eigen::VectorXd as_joint_vector(py::handle obj, const char* name) {
  if (obj.is_none()) return Eigen::VectorXd(0);
  const py_io::Array array = py_io::as_array(obj, name);
  if (array.ndim() != 1) py_io::throw_value_error(name, "a 1-D array", py_io::describe(obj));
  Eigen::VectorXd out = Eigen::Map<const Eigen::VectorXd>(array.data(), array.size());
  require_finite(out.transpose(), name);
  return out;
}

constexpr const char* joint_state_doc = R"doc(The state of a tree link's body in a scene: its joint's coordinates and velocities.

A scene holds one body per link of a tree (Scene.add_tree), and the state of each is its joint's: q_i and v_i, the
link's segments of the tree's q and v. Tree.joint_states splits a tree's (q, v) into them, Tree.coordinates_of stacks
them back. A run checks each against its joint (sizes, finite values, a unit quaternion).

Parameters
----------
q : array_like, shape (nq_i,), optional
    The joint's coordinates: an angle [rad] (revolute), an offset [m] (prismatic), a unit quaternion (x, y, z, w)
    (spherical), (p_JL [m], q_JL) (free); nothing for a fixed joint (None: empty).
v : array_like, shape (nv_i,), optional
    Its velocities: a rate [rad/s] or [m/s], w_L [rad/s] in the link frame (spherical), [w_L; v_L] (free).

Raises
------
ValueError
    q or v not 1-D, or not finite (naming it).

See Also
--------
Tree.joint_states, Tree.coordinates_of, Scene.add_tree

Examples
--------
>>> s = rd.JointState([0.3], [-1.0])
>>> s.q, s.v
(array([0.3]), array([-1.]))
)doc";

constexpr const char* tree_link_doc = R"doc(A link of a kinematic tree as a body of a scene (made by Scene.add_tree).

Two are equal when they are the same link of equal trees (link by link: names, parents, joints, placements and
inertias), so that a scene with a tree equals its copies and the scene its file reads back to. A link pickles as
(its tree, its index); a scene made of unpickled links shares each tree among its links again.

Force elements act on a link as on any body: at its centre of mass, in axes B parallel to its link frame L
(points on it given from the centre of mass, in those axes); the tree's joints couple the links' motions. A run
records each link's centre of mass position and velocity in W, its attitude R_WL and its angular velocity in L.

See Also
--------
Scene.add_tree, JointState, Tree

Examples
--------
>>> tree = rd.Tree()
>>> tree.add_link("arm", -1, rd.RevoluteJoint([0, 1, 0]), rd.SpatialInertia(2.0, [0.5, 0, 0], np.diag([1e-3, 0.2, 0.2])))
0
>>> scene = rd.Scene()
>>> scene.add_tree(tree)
(0,)
>>> link = scene.bodies[0]
>>> link.name, link.link, link.mass
('arm', 0, 2.0)
)doc";

void bind_joint_state(py::module_& m) {
  py::class_<JointState> cls(m, "JointState", joint_state_doc);
  cls.def(py::init([](py::handle q, py::handle v) { return JointState{as_joint_vector(q, "q"), as_joint_vector(v, "v")}; }),
          "q"_a = py::none(), "v"_a = py::none())
      .def_property(
          "q", [](const JointState& s) { return py_io::read_only(s.q); },
          [](JointState& s, py::handle q) { s.q = as_joint_vector(q, "q"); }, "The joint's coordinates, shape (nq_i,).")
      .def_property(
          "v", [](const JointState& s) { return py_io::read_only(s.v); },
          [](JointState& s, py::handle v) { s.v = as_joint_vector(v, "v"); }, "The joint's velocities, shape (nv_i,).")
      .def("__repr__",
           [](const JointState& s) {
             return repr_call("JointState", {{"q", py::object(py_io::to_array(s.q))}, {"v", py::object(py_io::to_array(s.v))}});
           })
      .def(py::pickle([](const JointState& s) { return py::make_tuple(py_io::to_array(s.q), py_io::to_array(s.v)); },
                      [](const py::tuple& t) {
                        pickled_state(t, 2, "JointState");
                        return JointState{unpickled<Eigen::Dynamic>(t[0], "JointState pickle q"),
                                          unpickled<Eigen::Dynamic>(t[1], "JointState pickle v")};
                      }));
  def_equality(cls, [](const JointState& a, const JointState& b) {
    return a.q.size() == b.q.size() && a.v.size() == b.v.size() && a.q == b.q && a.v == b.v;
  });
}

void bind_tree_link_class(py::module_& m) {
  py::class_<TreeLink> cls(m, "TreeLink", tree_link_doc);
  cls
      .def_property_readonly("tree", [](const TreeLink& l) { return *l.tree; }, "A copy of the tree the link belongs to.")
      .def_property_readonly("link", [](const TreeLink& l) { return l.link; }, "The link's index in its tree.")
      .def_property_readonly("name", &TreeLink::name, "The link's name in its tree.")
      .def_property_readonly("mass", &TreeLink::mass, "Its mass [kg].")
      .def_property_readonly(
          "inertia_com", [](const TreeLink& l) { return py_io::read_only(l.inertia_com()); },
          "Its inertia about its centre of mass, in axes parallel to the link frame, shape (3, 3) [kg m^2].")
      .def_property_readonly(
          "com", [](const TreeLink& l) { return py_io::read_only(l.com()); },
          "Its centre of mass in the link frame L, shape (3,) [m].")
      .def(py::pickle([](const TreeLink& l) { return py::make_tuple(*l.tree, l.link); },
                      [](const py::tuple& state) {
                        const py::tuple s = pickled_state(state, 2, "TreeLink");
                        auto tree = std::make_shared<const Tree>(py_io::as_instance<Tree>(s[0], "tree", "a Tree"));
                        const auto link = static_cast<int>(py_io::as_int(s[1], "link", 0, tree->num_links() - 1));
                        return TreeLink{std::move(tree), link};
                      }))
      .def("__repr__", [](const TreeLink& l) {
        return repr_call("TreeLink", {{"link", py::int_(l.link)}, {"name", py::str(l.name())}, {"mass", py::float_(l.mass())}});
      });
  def_equality(cls, [](const TreeLink& a, const TreeLink& b) {
    return a.link == b.link && (a.tree == b.tree || same_tree(*a.tree, *b.tree));
  });
}

// Tree.joint_states(q, v) and Tree.coordinates_of(states)
void bind_tree_split(py::module_& m) {
  py::class_<Tree> tree = py::reinterpret_borrow<py::class_<Tree>>(m.attr("Tree"));
  tree.def(
          "joint_states",
          [](const Tree& t, py::handle q, py::handle v) {
            const Eigen::VectorXd q_in = q.is_none() ? t.neutral_configuration() : as_joint_vector(q, "q");
            const Eigen::VectorXd v_in = v.is_none() ? Eigen::VectorXd::Zero(t.nv()) : as_joint_vector(v, "v");
            t.check_configuration(q_in);
            t.check_velocity(v_in, "v");
            py::list out;
            for (const Link& link : t.links()) {
              out.append(JointState{q_in.segment(link.idx_q, link.nq), v_in.segment(link.idx_v, link.nv)});
            }
            return out;
          },
          "q"_a = py::none(), "v"_a = py::none(),
          R"doc(The links' JointStates of the tree's configuration q and velocity v: one per link, in link order.

Parameters
----------
q : array_like, shape (tree.nq,), optional
    Configuration (None: the neutral one).
v : array_like, shape (tree.nv,), optional
    Velocity (None: at rest).

Returns
-------
list of JointState
    The states of the bodies Scene.add_tree adds for the tree, in their order.

Raises
------
ValueError
    A wrong size, a non-finite value or a non-unit quaternion (naming it).

Examples
--------
>>> tree = rd.Tree()
>>> rod = rd.SpatialInertia(1.0, [0.5, 0, 0], np.diag([1e-3, 0.1, 0.1]))
>>> tree.add_link("upper", -1, rd.RevoluteJoint([0, 1, 0]), rod)
0
>>> tree.add_link("lower", 0, rd.RevoluteJoint([0, 1, 0]), rod, rd.Transform(translation=[1, 0, 0]))
1
>>> tree.joint_states([0.1, 0.2], [0.0, -1.0])
[JointState(q=[0.1], v=[0.0]), JointState(q=[0.2], v=[-1.0])]
)doc")
      .def(
          "coordinates_of",
          [](const Tree& t, py::handle states) {
            const py::sequence seq = py::reinterpret_borrow<py::sequence>(states);
            if (!py::isinstance<py::sequence>(states) || py::len(seq) != static_cast<std::size_t>(t.num_links())) {
              py_io::throw_value_error("states", "a sequence of " + std::to_string(t.num_links()) + " JointStates (one per link)",
                                       py_io::describe(states));
            }
            Eigen::VectorXd q(t.nq()), v(t.nv());
            const auto shared = std::make_shared<const Tree>(t);  // the links checked_state reads
            for (int i = 0; i < t.num_links(); ++i) {
              const std::string name = "states[" + std::to_string(i) + "]";
              const JointState s = checked_state(TreeLink{shared, i},
                                                 py_io::as_instance<JointState>(seq[i], name, "a JointState"), name);
              const Link& link = t.link(i);
              q.segment(link.idx_q, link.nq) = s.q, v.segment(link.idx_v, link.nv) = s.v;
            }
            return py::make_tuple(py_io::to_array(q), py_io::to_array(v));
          },
          "states"_a,
          R"doc(The tree's configuration q and velocity v stacked from its links' JointStates.

The inverse of joint_states: e.g. of the link bodies' states that a scene's step returns.

Parameters
----------
states : sequence of JointState
    One per link, in link order.

Returns
-------
q : ndarray, shape (tree.nq,)
v : ndarray, shape (tree.nv,)

Raises
------
ValueError
    Not one JointState per link, or one that does not fit its joint (naming it).

Examples
--------
>>> tree = rd.Tree()
>>> tree.add_link("ball", -1, rd.SphericalJoint(), rd.SpatialInertia(1.0, [0, 0, -1], np.eye(3)))
0
>>> q, v = tree.coordinates_of([rd.JointState([0, 0, 0, 1], [0.0, 0.0, 2.0])])
>>> q, v
(array([0., 0., 0., 1.]), array([0., 0., 2.]))
)doc");
}

}  // namespace

void bind_tree_link(py::module_& m) {
  bind_joint_state(m);
  bind_tree_link_class(m);
  bind_tree_split(m);
}

}  // namespace rigiddyn::bindings
