// Python bindings of the frames layer: FrameKinematics, FrameMotion, FrameTree, PointVelocity,
// PointAcceleration and the formula-level functions. Arrays: vectors (3,), matrices (3, 3), float64.
#include <pybind11/stl.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "numpy_io.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/frames/frame_kinematics.hpp"
#include "rigiddyn/frames/frame_motion.hpp"
#include "rigiddyn/frames/frame_tree.hpp"
#include "rigiddyn/frames/point_kinematics.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using py_io::as_matrix3;
using py_io::as_matrix3_or_identity;
using py_io::as_vector3;
using py_io::as_vector3_or_zero;
using py_io::to_array;

namespace {

// A Python callable kept alive by C++ copies of a FrameMotion; the GIL is taken to call it and to
// release it, so the motion may be copied and destroyed without the GIL.
std::shared_ptr<py::object> hold(py::object f) {
  return std::shared_ptr<py::object>(new py::object(std::move(f)), [](py::object* p) {
    py::gil_scoped_acquire gil;
    delete p;
  });
}

// The value returned by a user motion: a FrameKinematics or a 6-sequence
// (R_PF, w_PF_P, alpha_PF_P, p_PF_P, v_PF_P, a_PF_P).
FrameKinematics kinematics_from_python(py::handle value) {
  if (py::isinstance<FrameKinematics>(value)) return value.cast<FrameKinematics>();
  if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) || py::len(value) != 6) {
    throw py::type_error("kinematics_at(t): expected a FrameKinematics or a 6-tuple (R_PF, w_PF_P, alpha_PF_P, "
                         "p_PF_P, v_PF_P, a_PF_P), got " +
                         std::string(py::str(py::type::of(value).attr("__name__"))));
  }
  const py::sequence s = value.cast<py::sequence>();
  FrameKinematics K;
  K.R_PF = as_matrix3(s[0], "kinematics_at(t)[0] (R_PF)");
  K.w_PF_P = as_vector3(s[1], "kinematics_at(t)[1] (w_PF_P)");
  K.alpha_PF_P = as_vector3(s[2], "kinematics_at(t)[2] (alpha_PF_P)");
  K.p_PF_P = as_vector3(s[3], "kinematics_at(t)[3] (p_PF_P)");
  K.v_PF_P = as_vector3(s[4], "kinematics_at(t)[4] (v_PF_P)");
  K.a_PF_P = as_vector3(s[5], "kinematics_at(t)[5] (a_PF_P)");
  return K;
}

FrameMotion motion_from_python(py::function kinematics_at) {
  std::shared_ptr<py::object> f = hold(std::move(kinematics_at));
  return FrameMotion([f](double t) {
    py::gil_scoped_acquire gil;
    const py::object value = (*f)(t);
    try {
      return kinematics_from_python(value);
    } catch (const py::value_error& e) {  // as std::invalid_argument, so the tree names the frame
      throw std::invalid_argument(e.what());
    }
  });
}


void bind_frame_kinematics(py::module_& m) {
  py::class_<FrameKinematics>(m, "FrameKinematics",
                              "Frame F relative to frame P at one instant (P = the parent of a FrameMotion, or the\n"
                              "`relative_to` frame of a FrameTree query). Every vector is expressed in P; SI units.")
      .def(py::init([](const py::object& R_PF, const py::object& w_PF_P, const py::object& alpha_PF_P,
                       const py::object& p_PF_P, const py::object& v_PF_P, const py::object& a_PF_P) {
             FrameKinematics K;
             K.R_PF = as_matrix3_or_identity(R_PF, "R_PF");
             K.w_PF_P = as_vector3_or_zero(w_PF_P, "w_PF_P");
             K.alpha_PF_P = as_vector3_or_zero(alpha_PF_P, "alpha_PF_P");
             K.p_PF_P = as_vector3_or_zero(p_PF_P, "p_PF_P");
             K.v_PF_P = as_vector3_or_zero(v_PF_P, "v_PF_P");
             K.a_PF_P = as_vector3_or_zero(a_PF_P, "a_PF_P");
             check_frame_kinematics(K);
             return K;
           }),
           py::arg("R_PF") = py::none(), py::arg("w_PF_P") = py::none(), py::arg("alpha_PF_P") = py::none(),
           py::arg("p_PF_P") = py::none(), py::arg("v_PF_P") = py::none(), py::arg("a_PF_P") = py::none(),
           "Arguments as the attributes (None: identity / zero). ValueError on a non-rotation R_PF or NaN/Inf.")
      .def_property_readonly("R_PF", [](const FrameKinematics& K) { return to_array(K.R_PF); },
                             "(3, 3) orientation of F in P: maps F coordinates to P coordinates.")
      .def_property_readonly("w_PF_P", [](const FrameKinematics& K) { return to_array(K.w_PF_P); },
                             "(3,) angular velocity of F relative to P [rad/s], expressed in P.")
      .def_property_readonly("alpha_PF_P", [](const FrameKinematics& K) { return to_array(K.alpha_PF_P); },
                             "(3,) angular acceleration of F relative to P (d/dt of w_PF) [rad/s^2], expressed in P.")
      .def_property_readonly("p_PF_P", [](const FrameKinematics& K) { return to_array(K.p_PF_P); },
                             "(3,) position of F's origin relative to P's origin [m], expressed in P.")
      .def_property_readonly("v_PF_P", [](const FrameKinematics& K) { return to_array(K.v_PF_P); },
                             "(3,) velocity of F's origin seen from P [m/s], expressed in P.")
      .def_property_readonly("a_PF_P", [](const FrameKinematics& K) { return to_array(K.a_PF_P); },
                             "(3,) acceleration of F's origin seen from P [m/s^2], expressed in P.");

  m.def("compose_kinematics", &compose_kinematics, py::arg("K_AP"), py::arg("K_PF"),
        "F relative to A from P relative to A and F relative to P (addition theorem for w; alpha with its\n"
        "w_AP x w_PF term; origin by seed 000 (4.38), (4.39)). Result expressed in A.");
  m.def("relative_kinematics", &relative_kinematics, py::arg("K_WA"), py::arg("K_WF"),
        "F relative to A from A and F relative to a common frame W; expressed in A. Inverse of compose_kinematics.");
}

void bind_point_terms(py::module_& m) {
  py::class_<PointVelocity>(m, "PointVelocity",
                            "Velocity of a point Q moving in a frame F, seen from a frame A, term by term\n"
                            "(seed 000 (4.38)): total = origin + rotational + relative. Each (3,) [m/s], all\n"
                            "expressed in the same frame (the query's `expressed_in`).")
      .def_property_readonly("origin", [](const PointVelocity& v) { return to_array(v.origin); },
                             "velocity of F's origin seen from A")
      .def_property_readonly("rotational", [](const PointVelocity& v) { return to_array(v.rotational); },
                             "w_AF x r, r = position of Q relative to F's origin")
      .def_property_readonly("relative", [](const PointVelocity& v) { return to_array(v.relative); },
                             "velocity of Q seen from F")
      .def_property_readonly("total", [](const PointVelocity& v) { return to_array(v.total()); },
                             "velocity of Q seen from A (sum of the terms)")
      .def("__repr__", [](const PointVelocity& v) {
        return "PointVelocity(origin=" + format_value(v.origin.transpose()) + ", rotational=" +
               format_value(v.rotational.transpose()) + ", relative=" + format_value(v.relative.transpose()) + ")";
      });

  py::class_<PointAcceleration>(m, "PointAcceleration",
                                "Acceleration of a point Q moving in a frame F, seen from a frame A, term by term\n"
                                "(seed 000 (4.39), seed 001): total = origin + tangential + centripetal + relative +\n"
                                "coriolis. Each (3,) [m/s^2], all expressed in the query's `expressed_in` frame.")
      .def_property_readonly("origin", [](const PointAcceleration& a) { return to_array(a.origin); },
                             "acceleration of F's origin seen from A")
      .def_property_readonly("tangential", [](const PointAcceleration& a) { return to_array(a.tangential); },
                             "alpha_AF x r")
      .def_property_readonly("centripetal", [](const PointAcceleration& a) { return to_array(a.centripetal); },
                             "w_AF x (w_AF x r)")
      .def_property_readonly("relative", [](const PointAcceleration& a) { return to_array(a.relative); },
                             "acceleration of Q seen from F")
      .def_property_readonly("coriolis", [](const PointAcceleration& a) { return to_array(a.coriolis); },
                             "2 w_AF x v_rel, v_rel = velocity of Q seen from F")
      .def_property_readonly("total", [](const PointAcceleration& a) { return to_array(a.total()); },
                             "acceleration of Q seen from A (sum of the terms)")
      .def("__repr__", [](const PointAcceleration& a) {
        return "PointAcceleration(origin=" + format_value(a.origin.transpose()) + ", tangential=" +
               format_value(a.tangential.transpose()) + ", centripetal=" + format_value(a.centripetal.transpose()) +
               ", relative=" + format_value(a.relative.transpose()) + ", coriolis=" +
               format_value(a.coriolis.transpose()) + ")";
      });

  m.def(
      "point_velocity",
      [](const FrameKinematics& K_AF, const py::object& p, const py::object& v) {
        return point_velocity(K_AF, as_vector3(p, "p_FQ_F"), as_vector3(v, "v_FQ_F"));
      },
      py::arg("K_AF"), py::arg("p_FQ_F"), py::arg("v_FQ_F"),
      "Velocity terms of Q seen from A, expressed in A. K_AF: F relative to A; p_FQ_F (3,) [m] and v_FQ_F\n"
      "(3,) [m/s]: Q's position relative to F's origin and its velocity seen from F, expressed in F.");
  m.def(
      "point_acceleration",
      [](const FrameKinematics& K_AF, const py::object& p, const py::object& v, const py::object& a) {
        return point_acceleration(K_AF, as_vector3(p, "p_FQ_F"), as_vector3(v, "v_FQ_F"), as_vector3(a, "a_FQ_F"));
      },
      py::arg("K_AF"), py::arg("p_FQ_F"), py::arg("v_FQ_F"), py::arg("a_FQ_F"),
      "Acceleration terms of Q seen from A, expressed in A; a_FQ_F (3,) [m/s^2]: Q's acceleration seen\n"
      "from F, expressed in F; the rest as point_velocity.");
  m.def(
      "transport_derivative",
      [](const py::object& w, const py::object& u, const py::object& du) {
        return to_array(transport_derivative(as_vector3(w, "w_AB"), as_vector3(u, "u"), as_vector3(du, "du_dt_in_B")));
      },
      py::arg("w_AB"), py::arg("u"), py::arg("du_dt_in_B"),
      "Transport theorem (seed 001): d^A u/dt = d^B u/dt + w_AB x u. All (3,), expressed in one frame.");
}

void bind_frame_motion(py::module_& m) {
  py::class_<FrameMotion>(m, "FrameMotion",
                          "How a frame F moves relative to its parent P: a function of time t [s] giving its\n"
                          "FrameKinematics (all vectors expressed in P).")
      .def(py::init(&motion_from_python), py::arg("kinematics_at"),
           "General motion: kinematics_at(t) returns a FrameKinematics or a 6-tuple\n"
           "(R_PF (3,3), w_PF_P, alpha_PF_P, p_PF_P, v_PF_P, a_PF_P) (each (3,), expressed in P). The caller\n"
           "keeps them consistent (w, alpha the derivatives of R; v, a those of p); the tree checks each value\n"
           "(finite, R_PF a rotation) and raises ValueError naming the frame.")
      .def_static(
          "fixed",
          [](const py::object& R_PF, const py::object& p_PF_P) {
            return FrameMotion::fixed(as_matrix3_or_identity(R_PF, "R_PF"), as_vector3_or_zero(p_PF_P, "p_PF_P"));
          },
          py::arg("R_PF") = py::none(), py::arg("p_PF_P") = py::none(),
          "F fixed in P: orientation R_PF (3,3) (None: identity), origin at p_PF_P (3,) [m] in P (None: 0).")
      .def_static(
          "constant_rotation",
          [](const py::object& axis_P, double rate, const py::object& R_PF0, const py::object& p_PF_P) {
            return FrameMotion::constant_rotation(as_vector3(axis_P, "axis_P"), rate,
                                                  as_matrix3_or_identity(R_PF0, "R_PF0"), as_vector3_or_zero(p_PF_P, "p_PF_P"));
          },
          py::arg("axis_P"), py::arg("rate"), py::arg("R_PF0") = py::none(), py::arg("p_PF_P") = py::none(),
          "Simple angular velocity (seed 001): F turns at `rate` [rad/s] about axis_P (3,) (expressed in P, any\n"
          "non-zero length) through F's origin, which stays at p_PF_P [m] in P (None: 0).\n"
          "R_PF(t) = exp(hat(rate t axis_P/|axis_P|)) R_PF0 (R_PF0: orientation at t = 0, None: identity).")
      .def("at", &FrameMotion::at, py::arg("t"), "F relative to P at time t [s] (unchecked).");
}

void bind_frame_tree(py::module_& m) {
  py::class_<FrameTree>(m, "FrameTree",
                        "A tree of reference frames rooted at the inertial frame 'world'. Each frame is placed\n"
                        "relative to its parent by a FrameMotion. Queries relate any frame F (`frame`) to any\n"
                        "frame A (`relative_to`) at time t [s], with results expressed in `expressed_in` E.\n"
                        "Unknown names, duplicates and cycles raise ValueError.")
      .def(py::init<>(), "A tree holding only 'world'.")
      .def_property_readonly_static("world", [](const py::object&) { return FrameTree::world; },
                                    "The root's name, 'world'.")
      .def("add_frame", &FrameTree::add_frame, py::arg("name"), py::arg("parent"), py::arg("motion"),
           "Adds frame `name` under `parent` (which must exist), placed by `motion`.")
      .def("set_parent", &FrameTree::set_parent, py::arg("name"), py::arg("parent"), py::arg("motion"),
           "Moves frame `name` and its subtree under `parent`, placed by `motion`. ValueError if that would\n"
           "make a cycle (parent is `name` or one of its descendants) or `name` is 'world'.")
      .def("has_frame", &FrameTree::has_frame, py::arg("name"))
      .def("parent", &FrameTree::parent, py::arg("name"), "The parent's name ('' for 'world').")
      .def("frame_names", &FrameTree::frame_names, "All names: 'world' first, then in the order added.")
      .def("kinematics", &FrameTree::kinematics, py::arg("frame"), py::arg("relative_to"), py::arg("t"),
           "FrameKinematics of `frame` F relative to `relative_to` A at t, expressed in A.")
      .def(
          "rotation",
          [](const FrameTree& tree, const std::string& frame, const std::string& relative_to, double t) {
            return to_array(tree.rotation(frame, relative_to, t));
          },
          py::arg("frame"), py::arg("relative_to"), py::arg("t"),
          "R_AF (3,3): maps `frame` F coordinates to `relative_to` A coordinates at t.")
      .def(
          "angular_velocity",
          [](const FrameTree& tree, const std::string& frame, const std::string& relative_to,
             const std::string& expressed_in, double t) {
            return to_array(tree.angular_velocity(frame, relative_to, expressed_in, t));
          },
          py::arg("frame"), py::arg("relative_to"), py::arg("expressed_in"), py::arg("t"),
          "w_AF_E (3,) [rad/s]: angular velocity of F relative to A (addition theorem), expressed in E.")
      .def(
          "angular_acceleration",
          [](const FrameTree& tree, const std::string& frame, const std::string& relative_to,
             const std::string& expressed_in, double t) {
            return to_array(tree.angular_acceleration(frame, relative_to, expressed_in, t));
          },
          py::arg("frame"), py::arg("relative_to"), py::arg("expressed_in"), py::arg("t"),
          "alpha_AF_E (3,) [rad/s^2]: d/dt in A of w_AF, expressed in E (includes the w x w terms; no\n"
          "addition theorem for angular accelerations, seed 001).")
      .def(
          "transport_derivative",
          [](const FrameTree& tree, const py::object& u, const py::object& du, const std::string& from_frame,
             const std::string& to_frame, const std::string& expressed_in, double t) {
            return to_array(tree.transport_derivative(as_vector3(u, "u_E"), as_vector3(du, "du_B_E"), from_frame,
                                                      to_frame, expressed_in, t));
          },
          py::arg("u_E"), py::arg("du_B_E"), py::arg("from_frame"), py::arg("to_frame"), py::arg("expressed_in"),
          py::arg("t"),
          "Transport theorem (seed 001): the derivative of u seen from A = `to_frame`, from its derivative\n"
          "du_B_E seen from B = `from_frame`: du_B_E + w_AB x u_E. u_E, du_B_E and the result (3,) in E.")
      .def(
          "point_position",
          [](const FrameTree& tree, const std::string& frame, const py::object& p, const std::string& relative_to,
             const std::string& expressed_in, double t) {
            return to_array(tree.point_position(frame, as_vector3(p, "p_FQ_F"), relative_to, expressed_in, t));
          },
          py::arg("frame"), py::arg("p_FQ_F"), py::arg("relative_to"), py::arg("expressed_in"), py::arg("t"),
          "p_AQ_E (3,) [m]: position of Q relative to A's origin, expressed in E; p_FQ_F (3,): Q relative\n"
          "to F's origin, expressed in F.")
      .def(
          "point_velocity",
          [](const FrameTree& tree, const std::string& frame, const py::object& p, const py::object& v,
             const std::string& relative_to, const std::string& expressed_in, double t) {
            return tree.point_velocity(frame, as_vector3(p, "p_FQ_F"), as_vector3(v, "v_FQ_F"), relative_to,
                                       expressed_in, t);
          },
          py::arg("frame"), py::arg("p_FQ_F"), py::arg("v_FQ_F"), py::arg("relative_to"), py::arg("expressed_in"),
          py::arg("t"),
          "PointVelocity of Q seen from A, terms expressed in E. Q at p_FQ_F [m] moving with v_FQ_F [m/s] as\n"
          "seen from F (both (3,), expressed in F; zeros for a point fixed in F).")
      .def(
          "point_acceleration",
          [](const FrameTree& tree, const std::string& frame, const py::object& p, const py::object& v,
             const py::object& a, const std::string& relative_to, const std::string& expressed_in, double t) {
            return tree.point_acceleration(frame, as_vector3(p, "p_FQ_F"), as_vector3(v, "v_FQ_F"),
                                           as_vector3(a, "a_FQ_F"), relative_to, expressed_in, t);
          },
          py::arg("frame"), py::arg("p_FQ_F"), py::arg("v_FQ_F"), py::arg("a_FQ_F"), py::arg("relative_to"),
          py::arg("expressed_in"), py::arg("t"),
          "PointAcceleration of Q seen from A (origin, tangential, centripetal, relative, coriolis, total),\n"
          "terms expressed in E [m/s^2]; a_FQ_F (3,): Q's acceleration seen from F, expressed in F.");
}

}  // namespace

void bind_frames(py::module_& m) {
  bind_frame_kinematics(m);
  bind_point_terms(m);
  bind_frame_motion(m);
  bind_frame_tree(m);
}

}  // namespace rigiddyn::bindings
