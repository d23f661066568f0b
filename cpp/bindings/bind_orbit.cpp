// Python bindings of the orbit layer: anomalies and Kepler's equation, classical elements ↔ state, the
// orbit frames (LVLH, RSW) and attitudes relative to them. A name table over rigiddyn/orbit/*.hpp.
// Every array argument is one item or a stack of n items (leading axis n); the stacked arguments of a
// call have the same n and a single item is used with every item of the others. The loops run in C++
// without the GIL; a ValueError from item i of a stack names the argument and the item.
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "common_args.hpp"
#include "for_each_item.hpp"
#include "numpy_io.hpp"
#include "rigiddyn/orbit/anomaly.hpp"
#include "rigiddyn/orbit/elements.hpp"
#include "rigiddyn/orbit/kepler_equation.hpp"
#include "rigiddyn/orbit/kepler_propagate.hpp"
#include "rigiddyn/orbit/orbit_frame.hpp"
#include "rigiddyn/so3/quaternion.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using namespace pybind11::literals;
using py_io::Array;
using Shape = std::vector<py::ssize_t>;

namespace {

using py_io::item_size;

// Several stacks read together: n items (the common length of the stacked ones), item(k, i) the i-th item
// of argument k (its only item when it is single). ValueError naming the argument whose length differs.
class Stacks {
 public:
  struct Spec {
    py::handle obj;
    const char* name;
    Shape shape;
  };
  explicit Stacks(std::initializer_list<Spec> specs) {
    const char* first = nullptr;
    for (const Spec& spec : specs) {
      stacks_.push_back(py_io::as_stack(spec.obj, spec.name, spec.shape));
      const py_io::Stack& s = stacks_.back();
      steps_.push_back(s.stacked ? item_size(spec.shape) : 0);
      if (!s.stacked) continue;
      if (first != nullptr && s.n != n_) {
        throw py::value_error(std::string(spec.name) + ": expected " + std::to_string(n_) + " items (as " + first +
                              "), got " + std::to_string(s.n));
      }
      if (first == nullptr) first = spec.name, n_ = s.n, stacked_ = true;
    }
  }
  py::ssize_t n() const { return n_; }
  bool stacked() const { return stacked_; }
  const double* item(size_t k, py::ssize_t i) const { return stacks_[k].array.data() + i * steps_[k]; }
  Array output(const Shape& shape, const char* name) const { return py_io::new_stack(n_, stacked_, shape, name); }

 private:
  std::vector<py_io::Stack> stacks_;
  std::vector<py::ssize_t> steps_;
  py::ssize_t n_ = 1;
  bool stacked_ = false;
};

using py_io::read_vector;
using py_io::write_vector;

// y = f(x, e) over two stacks of scalars: a float for two single values, else an array (n,).
template <typename F>
py::object map_scalar_pair(py::handle x, const char* x_name, py::handle e, const char* e_name, const char* quantity,
                           F f) {
  const Stacks in{{x, x_name, {}}, {e, e_name, {}}};
  Array out = in.output({}, quantity);
  double* o = out.mutable_data();
  for_each_item(in.n(), in.stacked(), [&](py::ssize_t i) { o[i] = f(*in.item(0, i), *in.item(1, i)); });
  out = py_io::finite_result(out, quantity);
  if (!in.stacked()) return py::float_(o[0]);
  return std::move(out);
}

double as_mu(py::handle mu) { return py_io::as_positive(py_io::in_si(mu, "m^3/s^2", "mu"), "mu"); }

OrbitFrame as_orbit_frame(py::handle frame) {
  return py_io::as_choice<OrbitFrame>(frame, "frame", {{"lvlh", OrbitFrame::lvlh}, {"rsw", OrbitFrame::rsw}});
}

// numpydoc pieces shared below
const char* const e_param =
    "e : float or array_like, shape (n,)\n"
    "    Eccentricity, finite and >= 0: 0 <= e < 1 an ellipse, e > 1 a hyperbola.\n";
const char* const state_params =
    "r_W : array_like, shape (3,) or (n, 3)\n"
    "    Position of the body relative to the central body's centre, in the inertial frame W [m].\n"
    "v_W : array_like, shape (3,) or (n, 3)\n"
    "    Velocity of the body relative to the central body, in W [m/s]; not parallel to `r_W`.\n";
const char* const frame_param =
    "frame : str, default 'lvlh'\n"
    "    'lvlh': z_O = -r/|r| (nadir), y_O = -h/|h| (opposite the orbit normal h = r x v), x_O = y_O x z_O\n"
    "    (along-track; along v on a circular orbit), the attitude texts' LVLH with roll, pitch and yaw axes\n"
    "    x, y, z (Wie, \"Space Vehicle Dynamics and Control\"). 'rsw': Hill's frame, x_O = r/|r| (R, radial out),\n"
    "    z_O = h/|h| (W, the orbit normal), y_O = z_O x x_O (S, along-track) (Vallado, \"Fundamentals of\n"
    "    Astrodynamics and Applications\").\n";
const char* const state_raises =
    "ValueError\n"
    "    A non-finite entry or a wrong shape (the message names `r_W` or `v_W` and, in a stack, the item),\n"
    "    stacks of different lengths, or r x v = 0 (the message names `r_W, v_W`: a rectilinear orbit has no\n"
    "    plane).\n";

// An argument and its name.
struct Named {
  py::handle value;
  const char* name;
};

// The loop of attitude_from_orbit_frame and attitude_to_orbit_frame: items (r_W, v_W, q, w) -> (q', w') by
// convert(r_W, v_W, q, w, frame), q checked a unit quaternion; the outputs named q_out and w_out.
template <class Convert>
auto map_attitudes(py::handle r_W, py::handle v_W, Named q, Named w, py::handle frame_arg, py::handle scalar_first_arg,
                   const char* q_out, const char* w_out, Convert convert) {
  const OrbitFrame frame = as_orbit_frame(frame_arg);
  const bool scalar_first = py_io::as_bool(scalar_first_arg, "scalar_first");
  const Stacks in{{r_W, "r_W", {3}}, {v_W, "v_W", {3}}, {q.value, q.name, {4}}, {w.value, w.name, {3}}};
  Array q_new = in.output({4}, q_out), w_new = in.output({3}, w_out);
  double *pq = q_new.mutable_data(), *pw = w_new.mutable_data();
  const std::string q_name = q.name;
  for_each_item(in.n(), in.stacked(), [&](py::ssize_t i) {
    const Eigen::Quaterniond q_in = checked_unit_quaternion(py_io::read_quaternion(in.item(2, i), scalar_first), q_name);
    const Attitude a = convert(read_vector(in.item(0, i)), read_vector(in.item(1, i)), q_in, read_vector(in.item(3, i)), frame);
    py_io::write_quaternion(a.q, pq + 4 * i, scalar_first);
    write_vector(a.w, pw + 3 * i);
  });
  return py::make_tuple(q_new, py_io::finite_result(w_new, w_out));
}

}  // namespace

void bind_orbit(py::module_& m) {
  // ------------------------------------------------------------ anomalies and Kepler's equation
  m.def(
      "true_to_eccentric_anomaly",
      [](py::handle nu, py::handle e) {
        return map_scalar_pair(nu, "nu", e, "e", "true_to_eccentric_anomaly", true_to_eccentric_anomaly);
      },
      "nu"_a, "e"_a,
      (std::string() +
       "Eccentric anomaly E (ellipse) or hyperbolic anomaly H (hyperbola) of the true anomaly.\n"
       "\n"
       "tan(E/2) = sqrt((1 - e)/(1 + e)) tan(nu/2) for 0 <= e < 1, keeping nu's revolutions (E and nu differ\n"
       "by less than pi); tanh(H/2) = sqrt((e - 1)/(e + 1)) tan(nu/2) for e > 1 (Curtis, \"Orbital Mechanics\n"
       "for Engineering Students\", ch. 3).\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "nu : float or array_like, shape (n,)\n"
       "    True anomaly [rad], the angle from periapsis to the body in the direction of motion; for a\n"
       "    hyperbola within the asymptotes, 1 + e cos(nu) > 0.\n" +
       e_param +
       "\n"
       "Returns\n"
       "-------\n"
       "float or ndarray, shape (n,)\n"
       "    E or H [rad] (an array when either argument is one).\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A non-finite value, e < 0, e = 1 (a parabola has no eccentric anomaly) or a hyperbola's `nu`\n"
       "    beyond its asymptotes (the message names the argument and, in a stack, the item).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "eccentric_to_true_anomaly, eccentric_to_mean_anomaly, true_to_mean_anomaly\n"
       "\n"
       "Examples\n"
       "--------\n"
       "At periapsis and apoapsis the anomalies agree; a circle has E = nu:\n"
       "\n"
       ">>> rd.true_to_eccentric_anomaly([0.0, np.pi], 0.5).round(12)\n"
       "array([0.        , 3.14159265])\n"
       ">>> rd.true_to_eccentric_anomaly(1.0, 0.0)\n"
       "1.0")
          .c_str());

  m.def(
      "eccentric_to_true_anomaly",
      [](py::handle E, py::handle e) {
        return map_scalar_pair(E, "E", e, "e", "eccentric_to_true_anomaly", eccentric_to_true_anomaly);
      },
      "E"_a, "e"_a,
      (std::string() +
       "True anomaly of the eccentric anomaly E (ellipse) or hyperbolic anomaly H (hyperbola).\n"
       "\n"
       "tan(nu/2) = sqrt((1 + e)/(1 - e)) tan(E/2) for 0 <= e < 1, keeping E's revolutions;\n"
       "tan(nu/2) = sqrt((e + 1)/(e - 1)) tanh(H/2) for e > 1, |nu| < acos(-1/e) (Curtis, \"Orbital\n"
       "Mechanics for Engineering Students\", ch. 3).\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "E : float or array_like, shape (n,)\n"
       "    Eccentric anomaly (e < 1) or hyperbolic anomaly (e > 1) [rad].\n" +
       e_param +
       "\n"
       "Returns\n"
       "-------\n"
       "float or ndarray, shape (n,)\n"
       "    nu [rad].\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A non-finite value, e < 0 or e = 1 (the message names the argument).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "true_to_eccentric_anomaly, mean_to_true_anomaly\n"
       "\n"
       "Examples\n"
       "--------\n"
       "The round trip through the eccentric anomaly:\n"
       "\n"
       ">>> E = rd.true_to_eccentric_anomaly(2.0, 0.7)\n"
       ">>> round(rd.eccentric_to_true_anomaly(E, 0.7), 12)\n"
       "2.0")
          .c_str());

  m.def(
      "eccentric_to_mean_anomaly",
      [](py::handle E, py::handle e) {
        return map_scalar_pair(E, "E", e, "e", "eccentric_to_mean_anomaly", eccentric_to_mean_anomaly);
      },
      "E"_a, "e"_a,
      (std::string() +
       "Mean anomaly of the eccentric or hyperbolic anomaly: Kepler's equation.\n"
       "\n"
       "M = E - e sin E for 0 <= e < 1, M = e sinh H - H for e > 1 (Curtis, \"Orbital Mechanics for Engineering\n"
       "Students\", sec. 3.4 and 3.6), evaluated as (1 - e) E + e (E - sin E) and (e - 1) H + e (sinh H - H)\n"
       "with series for E - sin E and sinh H - H near 0: to a few ulps of M also near periapsis as e -> 1.\n"
       "M = n t grows linearly in the time t since periapsis (n = sqrt(mu/|a|^3)).\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "E : float or array_like, shape (n,)\n"
       "    Eccentric anomaly (e < 1) or hyperbolic anomaly (e > 1) [rad].\n" +
       e_param +
       "\n"
       "Returns\n"
       "-------\n"
       "float or ndarray, shape (n,)\n"
       "    M [rad].\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A non-finite value, e < 0 or e = 1 (the message names the argument).\n"
       "\n"
       "Warns\n"
       "-----\n"
       "RuntimeWarning\n"
       "    M overflows (|H| > 710 on a hyperbola).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "mean_to_eccentric_anomaly, true_to_mean_anomaly\n"
       "\n"
       "Examples\n"
       "--------\n"
       "Curtis's Example 3.1 (e = 0.37255, E = 1.7281 rad):\n"
       "\n"
       ">>> round(rd.eccentric_to_mean_anomaly(1.7281, 0.37255), 4)\n"
       "1.3601")
          .c_str());

  m.def(
      "mean_to_eccentric_anomaly",
      [](py::handle M, py::handle e) {
        return map_scalar_pair(M, "M", e, "e", "mean_to_eccentric_anomaly", mean_to_eccentric_anomaly);
      },
      "M"_a, "e"_a,
      (std::string() +
       "Eccentric (ellipse) or hyperbolic (hyperbola) anomaly of the mean anomaly: Kepler's equation solved.\n"
       "\n"
       "Solves M = E - e sin E (0 <= e < 1; M reduced to (-pi, pi], its revolutions kept) or M = e sinh H - H\n"
       "(e > 1) to round-off: a starter from the cubic (1 - e) x + e x^3/6 = M near periapsis (exact as e -> 1)\n"
       "or Danby's M + 0.85 e, then Halley's iteration kept inside a bracket of the root, bisecting where a step\n"
       "would leave it, for at most 200 steps (3 to 5 typically): it always returns.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "M : float or array_like, shape (n,)\n"
       "    Mean anomaly [rad], any finite value.\n" +
       e_param +
       "\n"
       "Returns\n"
       "-------\n"
       "float or ndarray, shape (n,)\n"
       "    E or H [rad] with Kepler's equation satisfied to round-off.\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A non-finite value, e < 0 or e = 1 (a parabola: `mean_to_true_anomaly` solves Barker's equation)\n"
       "    (the message names the argument and, in a stack, the item).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "eccentric_to_mean_anomaly, mean_to_true_anomaly\n"
       "\n"
       "Examples\n"
       "--------\n"
       "Curtis's Example 3.2 (M = 3.6029 rad, e = 0.37255: E = 3.4794 rad), and the residual:\n"
       "\n"
       ">>> E = rd.mean_to_eccentric_anomaly(3.6029, 0.37255)\n"
       ">>> round(E, 4), bool(abs(E - 0.37255 * np.sin(E) - 3.6029) < 1e-15)\n"
       "(3.4794, True)")
          .c_str());

  m.def(
      "true_to_mean_anomaly",
      [](py::handle nu, py::handle e) {
        return map_scalar_pair(nu, "nu", e, "e", "true_to_mean_anomaly", true_to_mean_anomaly);
      },
      "nu"_a, "e"_a,
      (std::string() +
       "Mean anomaly of the true anomaly, for every conic.\n"
       "\n"
       "Through the eccentric or hyperbolic anomaly for e != 1 (`true_to_eccentric_anomaly`,\n"
       "`eccentric_to_mean_anomaly`); Barker's equation M = D/2 + D^3/6, D = tan(nu/2), for the parabola\n"
       "e = 1 (Curtis, \"Orbital Mechanics for Engineering Students\", sec. 3.5), where M = sqrt(mu/p^3) t.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "nu : float or array_like, shape (n,)\n"
       "    True anomaly [rad]; for e >= 1 within the asymptotes, 1 + e cos(nu) > 0.\n"
       "e : float or array_like, shape (n,)\n"
       "    Eccentricity, finite and >= 0 (1 included).\n"
       "\n"
       "Returns\n"
       "-------\n"
       "float or ndarray, shape (n,)\n"
       "    M [rad].\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A non-finite value, e < 0 or `nu` beyond the asymptotes (the message names the argument).\n"
       "\n"
       "Warns\n"
       "-----\n"
       "RuntimeWarning\n"
       "    M overflows (nu within about 1e-100 rad of a hyperbola's asymptote).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "mean_to_true_anomaly\n"
       "\n"
       "Examples\n"
       "--------\n"
       "A parabola at nu = 90 deg: D = 1, M = 1/2 + 1/6:\n"
       "\n"
       ">>> round(rd.true_to_mean_anomaly(np.pi / 2, 1.0), 15)\n"
       "0.666666666666667")
          .c_str());

  m.def(
      "mean_to_true_anomaly",
      [](py::handle M, py::handle e) {
        return map_scalar_pair(M, "M", e, "e", "mean_to_true_anomaly", mean_to_true_anomaly);
      },
      "M"_a, "e"_a,
      (std::string() +
       "True anomaly of the mean anomaly, for every conic: where the body is a time M/n after periapsis.\n"
       "\n"
       "Kepler's equation solved (`mean_to_eccentric_anomaly`) for e != 1, then `eccentric_to_true_anomaly`;\n"
       "Barker's cubic D^3 + 3 D = 6 M in closed form for the parabola e = 1 (nu = 2 atan D). Keeps the\n"
       "revolutions of an ellipse's M.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "M : float or array_like, shape (n,)\n"
       "    Mean anomaly [rad].\n"
       "e : float or array_like, shape (n,)\n"
       "    Eccentricity, finite and >= 0 (1 included).\n"
       "\n"
       "Returns\n"
       "-------\n"
       "float or ndarray, shape (n,)\n"
       "    nu [rad]; for e >= 1 in (-acos(-1/e), acos(-1/e)).\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A non-finite value or e < 0 (the message names the argument).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "true_to_mean_anomaly, mean_to_eccentric_anomaly\n"
       "\n"
       "Examples\n"
       "--------\n"
       "Curtis's Example 3.2: 3 h after perigee on an orbit of e = 0.37255 and period 18834 s, nu = 193.2 deg:\n"
       "\n"
       ">>> M = 2 * np.pi * 10800 / 18834.0\n"
       ">>> round(float(np.degrees(rd.mean_to_true_anomaly(M, 0.37255))), 1)\n"
       "193.2")
          .c_str());

  // ------------------------------------------------------------ elements
  m.def(
      "semi_latus_rectum",
      [](py::handle a, py::handle e) { return map_scalar_pair(a, "a", e, "e", "semi_latus_rectum", semi_latus_rectum); },
      "a"_a, "e"_a,
      (std::string() +
       "Semi-latus rectum p = a (1 - e^2) of the semi-major axis: the first element of `elements_to_state`.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "a : float or array_like, shape (n,)\n"
       "    Semi-major axis [m]: > 0 for an ellipse, < 0 for a hyperbola (a = -mu/(2 energy)).\n"
       "e : float or array_like, shape (n,)\n"
       "    Eccentricity, finite, >= 0 and != 1 (a parabola's a is infinite: give its p).\n"
       "\n"
       "Returns\n"
       "-------\n"
       "float or ndarray, shape (n,)\n"
       "    p [m], > 0.\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    `a` not finite, 0 or of the wrong sign for `e`, or `e` not finite, < 0 or 1 (the message names it).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "elements_to_state\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> round(rd.semi_latus_rectum(7000e3, 0.1), 6)\n"
       "6930000.0\n"
       ">>> rd.semi_latus_rectum(-7000e3, 2.0)\n"
       "21000000.0")
          .c_str());

  m.def(
      "elements_to_state",
      [](py::handle elements, py::handle mu_arg) {
        const double mu = as_mu(mu_arg);
        const Stacks in{{elements, "elements", {6}}};
        Array r = in.output({3}, "r_W"), v = in.output({3}, "v_W");
        double *pr = r.mutable_data(), *pv = v.mutable_data();
        for_each_item(in.n(), in.stacked(), [&](py::ssize_t i) {
          const double* x = in.item(0, i);
          const OrbitState s = state_from_elements({x[0], x[1], x[2], x[3], x[4], x[5]}, mu);
          write_vector(s.r_W, pr + 3 * i);
          write_vector(s.v_W, pv + 3 * i);
        });
        return py::make_tuple(py_io::finite_result(r, "r_W"), py_io::finite_result(v, "v_W"));
      },
      "elements"_a, "mu"_a,
      "Position and velocity of classical orbital elements (Vallado's COE2RV).\n"
      "\n"
      "r_W = p/(1 + e cos nu) (cos nu P + sin nu Q), v_W = sqrt(mu/p) (-sin nu P + (e + cos nu) Q), with\n"
      "[P Q W] = R_z(raan) R_x(i) R_z(argp) (Vallado, \"Fundamentals of Astrodynamics and Applications\", ch. 2,\n"
      "COE2RV; Curtis, \"Orbital Mechanics for Engineering Students\", algorithm 4.5). Every conic, the\n"
      "parabola e = 1 included (through p). The special cases of `state_to_elements` (Omega = 0 when\n"
      "equatorial, omega = 0 when circular, the next angle carrying theirs) need nothing special here.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "elements : array_like, shape (6,) or (n, 6)\n"
      "    (p, e, i, raan, argp, nu): semi-latus rectum p > 0 [m] (`semi_latus_rectum` of a semi-major axis),\n"
      "    eccentricity e >= 0, inclination i, right ascension of the ascending node raan, argument of\n"
      "    periapsis argp and true anomaly nu [rad], each finite; for e >= 1, 1 + e cos(nu) > 0.\n"
      "mu : float\n"
      "    Gravitational parameter G M of the central body [m^3/s^2], > 0 (or a pint quantity).\n"
      "\n"
      "Returns\n"
      "-------\n"
      "r_W : ndarray, shape (3,) or (n, 3)\n"
      "    Position relative to the central body in the inertial frame W [m] (xy the reference plane).\n"
      "v_W : ndarray, shape (3,) or (n, 3)\n"
      "    Velocity in W [m/s].\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    `mu` not > 0; p <= 0, e < 0, a non-finite element, or nu beyond a hyperbola's asymptotes (the\n"
      "    message names p, e, i, raan, argp or nu and, in a stack, the item).\n"
      "\n"
      "See Also\n"
      "--------\n"
      "state_to_elements, semi_latus_rectum\n"
      "\n"
      "Examples\n"
      "--------\n"
      "Curtis's Example 4.7 (km and km/s: h = 80000 km^2/s, e = 1.4, i = 30, raan = 40, argp = 60, nu = 30 deg):\n"
      "\n"
      ">>> mu = 398600.0\n"
      ">>> p = 80000.0**2 / mu\n"
      ">>> r, v = rd.elements_to_state([p, 1.4, *np.radians([30.0, 40.0, 60.0, 30.0])], mu)\n"
      ">>> r.round(0), v.round(3)\n"
      "(array([-4040.,  4815.,  3629.]), array([-10.386,  -4.772,   1.744]))");

  m.def(
      "state_to_elements",
      [](py::handle r_W, py::handle v_W, py::handle mu_arg) {
        const double mu = as_mu(mu_arg);
        const Stacks in{{r_W, "r_W", {3}}, {v_W, "v_W", {3}}};
        Array out = in.output({6}, "elements");
        double* o = out.mutable_data();
        for_each_item(in.n(), in.stacked(), [&](py::ssize_t i) {
          const ClassicalElements el = elements_from_state(read_vector(in.item(0, i)), read_vector(in.item(1, i)), mu);
          double* x = o + 6 * i;
          x[0] = el.p, x[1] = el.e, x[2] = el.i, x[3] = el.raan, x[4] = el.argp, x[5] = el.nu;
        });
        return py_io::finite_result(out, "elements");
      },
      "r_W"_a, "v_W"_a, "mu"_a,
      (std::string() +
       "Classical orbital elements of a position and velocity (Vallado's RV2COE).\n"
       "\n"
       "h = r x v, p = |h|^2/mu, the eccentricity vector e = (v x h)/mu - r/|r|, i from h, the ascending node\n"
       "n = z_W x h (Vallado, \"Fundamentals of Astrodynamics and Applications\", ch. 2, RV2COE; Curtis,\n"
       "\"Orbital Mechanics for Engineering Students\", algorithm 4.2). Angles are measured in the direction\n"
       "of motion. Where an angle is undefined it is 0 and the next carries it, so `elements_to_state` gives\n"
       "the state back:\n"
       "\n"
       "- equatorial (sin i < 1e-12, i = 0 or pi): raan = 0, argp = the longitude of periapsis (from x_W);\n"
       "- circular (e < 1e-12): argp = 0, nu = the argument of latitude u (from the ascending node);\n"
       "- both: raan = argp = 0, nu = the true longitude (from x_W).\n"
       "\n"
       "Below those tolerances (far above the ~1e-15 round-off of e and sin i from a state) the state given\n"
       "back moves by at most 2 e |r| or 2 sin(i) |r|. Semi-major axis: a = p/(1 - e^2).\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       state_params +
       "mu : float\n"
       "    Gravitational parameter G M of the central body [m^3/s^2], > 0 (or a pint quantity).\n"
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (6,) or (n, 6)\n"
       "    (p, e, i, raan, argp, nu): p [m]; e; i in [0, pi]; raan, argp in [0, 2 pi); nu in [0, 2 pi) for\n"
       "    e < 1, in (-pi, pi) for e >= 1 [rad].\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    `mu` not > 0, r = 0 (the message names `r_W`), or as below.\n" +
       state_raises +
       "\n"
       "See Also\n"
       "--------\n"
       "elements_to_state, mean_to_true_anomaly\n"
       "\n"
       "Examples\n"
       "--------\n"
       "Vallado's Example 2-5 (km, km/s; mu = 398600.4418 km^3/s^2): e = 0.832853, i = 87.870, raan = 227.898,\n"
       "argp = 53.385, nu = 92.335 deg:\n"
       "\n"
       ">>> el = rd.state_to_elements([6524.834, 6862.875, 6448.296], [4.901327, 5.533756, -1.976341], 398600.4418)\n"
       ">>> float(round(el[1], 6)), np.degrees(el[2:]).round(3)\n"
       "(0.832853, array([ 87.869, 227.898,  53.385,  92.335]))")
          .c_str());

  m.def(
      "kepler_propagate",
      [](py::handle r_W, py::handle v_W, py::handle mu_arg, py::handle t) {
        const double mu = as_mu(mu_arg);
        const Stacks in{{r_W, "r_W", {3}}, {v_W, "v_W", {3}}, {py_io::in_si(t, "s", "t"), "t", {}}};
        Array r = in.output({3}, "r_W"), v = in.output({3}, "v_W");
        double *pr = r.mutable_data(), *pv = v.mutable_data();
        for_each_item(in.n(), in.stacked(), [&](py::ssize_t i) {
          const OrbitState s = kepler_propagate(read_vector(in.item(0, i)), read_vector(in.item(1, i)), mu, *in.item(2, i));
          write_vector(s.r_W, pr + 3 * i);
          write_vector(s.v_W, pv + 3 * i);
        });
        return py::make_tuple(py_io::finite_result(r, "r_W"), py_io::finite_result(v, "v_W"));
      },
      "r_W"_a, "v_W"_a, "mu"_a, "t"_a,
      (std::string() +
       "Position and velocity a time t after a given state on its two-body (Keplerian) orbit.\n"
       "\n"
       "Through the elements (`state_to_elements`): the mean anomaly advances at the mean motion, M = M0 + n t,\n"
       "n = sqrt(mu/a^3) (ellipse), sqrt(mu/(-a)^3) (hyperbola), sqrt(mu/p^3) (parabola, Barker's equation), then\n"
       "the true anomaly by Kepler's equation (`mean_to_true_anomaly`); the other elements are constant (Curtis,\n"
       "\"Orbital Mechanics for Engineering Students\", ch. 3). Exact but for round-off: no step size.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       state_params +
       "mu : float\n"
       "    Gravitational parameter G M of the central body [m^3/s^2], > 0 (or a pint quantity).\n"
       "t : float or array_like, shape (n,)\n"
       "    Time after the given state [s], any sign (or a pint quantity).\n"
       "\n"
       "Returns\n"
       "-------\n"
       "r_W : ndarray, shape (3,) or (n, 3)\n"
       "    Position at t, in W [m].\n"
       "v_W : ndarray, shape (3,) or (n, 3)\n"
       "    Velocity at t, in W [m/s].\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    `mu` not > 0, r = 0 (the message names `r_W`), `t` not finite, or as below.\n" +
       state_raises +
       "\n"
       "See Also\n"
       "--------\n"
       "state_to_elements, mean_to_true_anomaly\n"
       "\n"
       "Examples\n"
       "--------\n"
       "One period later the body is back (the kepler scene's orbit: a = 7000 km, e = 0.1, T = 5828.5 s):\n"
       "\n"
       ">>> mu = 398600.4418e9\n"
       ">>> r0, v0 = [6300e3, 0.0, 0.0], [0.0, 8342.475803771201, 0.0]\n"
       ">>> r, v = rd.kepler_propagate(r0, v0, mu, 2 * np.pi * np.sqrt(7000e3**3 / mu))\n"
       ">>> np.allclose(r, r0, rtol=0, atol=1e-6), np.allclose(v, v0, rtol=0, atol=1e-9)\n"
       "(True, True)")
          .c_str());

  // ------------------------------------------------------------ orbit frames
  m.def(
      "orbit_frame_rotation",
      [](py::handle r_W, py::handle v_W, py::handle frame_arg) {
        const OrbitFrame frame = as_orbit_frame(frame_arg);
        const Stacks in{{r_W, "r_W", {3}}, {v_W, "v_W", {3}}};
        Array out = in.output({3, 3}, "R_WO");
        double* o = out.mutable_data();
        for_each_item(in.n(), in.stacked(), [&](py::ssize_t i) {
          const Eigen::Matrix3d R = orbit_frame_rotation(read_vector(in.item(0, i)), read_vector(in.item(1, i)), frame);
          Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>{o + 9 * i} = R;
        });
        return out;
      },
      "r_W"_a, "v_W"_a, "frame"_a = "lvlh",
      (std::string() +
       "Rotation R_WO from an orbit frame O (LVLH or RSW) to the inertial frame W.\n"
       "\n"
       "The columns of R_WO are O's axes expressed in W, from the body's position and velocity. Use\n"
       "`matrix_to_quat` for q_WO.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       state_params + frame_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3, 3) or (n, 3, 3)\n"
       "    R_WO, orthonormal with det +1.\n"
       "\n"
       "Raises\n"
       "------\n" +
       state_raises +
       "    `frame` not 'lvlh' or 'rsw'.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "orbit_frame_angular_velocity, attitude_from_orbit_frame\n"
       "\n"
       "Examples\n"
       "--------\n"
       "Below the centre on -z_W, moving along +x_W: LVLH's z (third column) points up +z_W, to the centre:\n"
       "\n"
       ">>> rd.orbit_frame_rotation([0.0, 0.0, -7e6], [7.5e3, 0.0, 0.0]).round(12) + 0.0\n"
       "array([[1., 0., 0.],\n"
       "       [0., 1., 0.],\n"
       "       [0., 0., 1.]])")
          .c_str());

  m.def(
      "orbit_frame_angular_velocity",
      [](py::handle r_W, py::handle v_W) {
        const Stacks in{{r_W, "r_W", {3}}, {v_W, "v_W", {3}}};
        Array out = in.output({3}, "w_WO_W");
        double* o = out.mutable_data();
        for_each_item(in.n(), in.stacked(), [&](py::ssize_t i) {
          write_vector(orbit_frame_angular_velocity(read_vector(in.item(0, i)), read_vector(in.item(1, i))), o + 3 * i);
        });
        return py_io::finite_result(out, "w_WO_W");
      },
      "r_W"_a, "v_W"_a,
      (std::string() +
       "Angular velocity w_WO_W = (r x v)/|r|^2 of the orbit frames (LVLH and RSW alike) in W, expressed in W.\n"
       "\n"
       "The radius vector turns about the orbit normal at h/r^2 (h = r^2 dtheta/dt): on a circular orbit the\n"
       "orbit rate n = sqrt(mu/r^3), on an elliptic one faster at periapsis than at apoapsis. Exact for an\n"
       "acceleration along r (a Keplerian orbit); an acceleration out of the orbit plane would add a component\n"
       "along r, not included. In LVLH coordinates it is (0, -h/r^2, 0), in RSW (0, 0, h/r^2).\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       state_params +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3,) or (n, 3)\n"
       "    w_WO_W [rad/s].\n"
       "\n"
       "Raises\n"
       "------\n" +
       state_raises +
       "\n"
       "See Also\n"
       "--------\n"
       "orbit_frame_rotation\n"
       "\n"
       "Examples\n"
       "--------\n"
       "A circular orbit of radius 7000 km about the Earth turns at n = sqrt(mu/r^3):\n"
       "\n"
       ">>> mu, r = 3.986004418e14, 7.0e6\n"
       ">>> w = rd.orbit_frame_angular_velocity([r, 0.0, 0.0], [0.0, np.sqrt(mu / r), 0.0])\n"
       ">>> np.allclose(w, [0.0, 0.0, np.sqrt(mu / r**3)], rtol=1e-15, atol=0.0)\n"
       "True")
          .c_str());

  m.def(
      "attitude_from_orbit_frame",
      [](py::handle r_W, py::handle v_W, py::handle q_OB, py::handle w_OB_B, py::handle frame, py::handle scalar_first) {
        return map_attitudes(r_W, v_W, {q_OB, "q_OB"}, {w_OB_B, "w_OB_B"}, frame, scalar_first, "q_WB", "w_B",
                             attitude_from_orbit_frame);
      },
      "r_W"_a, "v_W"_a, "q_OB"_a, "w_OB_B"_a, "frame"_a = "lvlh", "scalar_first"_a = false,
      (std::string() +
       "Inertial attitude and rate (q_WB, w_B) of an attitude and rate given relative to an orbit frame O.\n"
       "\n"
       "q_WB = q_WO (x) q_OB and w_B = w_OB_B + R_WB^T w_WO_W (angular velocities add): the initial state of a\n"
       "body whose attitude is given relative to LVLH or RSW (q_OB = identity, w_OB_B = 0: a body that holds\n"
       "the orbit frame, as a gravity-gradient-stabilised satellite).\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       state_params +
       "q_OB : array_like, shape (4,) or (n, 4)\n"
       "    Attitude of the body B relative to O, unit quaternions (x, y, z, w) ((w, x, y, z) if\n"
       "    `scalar_first`); norm within 1e-6 of 1 (then normalised).\n"
       "w_OB_B : array_like, shape (3,) or (n, 3)\n"
       "    Angular velocity of B relative to O, expressed in B [rad/s].\n" +
       frame_param + scalar_first_param +
       "\n"
       "Returns\n"
       "-------\n"
       "q_WB : ndarray, shape (4,) or (n, 4)\n"
       "    Attitude of B in W, in the order of the input.\n"
       "w_B : ndarray, shape (3,) or (n, 3)\n"
       "    Angular velocity of B in W, expressed in B [rad/s] (`RigidBodyState`'s w_B).\n"
       "\n"
       "Raises\n"
       "------\n" +
       state_raises +
       "    A quaternion farther than 1e-6 from unit norm (the message names `q_OB`); `frame` not 'lvlh' or\n"
       "    'rsw'.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "attitude_to_orbit_frame, orbit_frame_rotation\n"
       "\n"
       "Examples\n"
       "--------\n"
       "Holding LVLH on the circular orbit of the shipped gravity_gradient scene: q_WB = identity there and\n"
       "w_B = (0, -n, 0), n = 1.078007612872506e-3 rad/s:\n"
       "\n"
       ">>> q, w = rd.attitude_from_orbit_frame([0.0, 0.0, -7e6], [7546.053290107541, 0.0, 0.0], [0, 0, 0, 1.0], np.zeros(3))\n"
       ">>> q.round(12), (w / 1.078007612872506e-3).round(12) + 0.0\n"
       "(array([0., 0., 0., 1.]), array([ 0., -1.,  0.]))")
          .c_str());

  m.def(
      "attitude_to_orbit_frame",
      [](py::handle r_W, py::handle v_W, py::handle q_WB, py::handle w_B, py::handle frame, py::handle scalar_first) {
        return map_attitudes(r_W, v_W, {q_WB, "q_WB"}, {w_B, "w_B"}, frame, scalar_first, "q_OB", "w_OB_B",
                             attitude_to_orbit_frame);
      },
      "r_W"_a, "v_W"_a, "q_WB"_a, "w_B"_a, "frame"_a = "lvlh", "scalar_first"_a = false,
      (std::string() +
       "Attitude and rate relative to an orbit frame O of an inertial attitude and rate (q_WB, w_B).\n"
       "\n"
       "q_OB = q_WO^-1 (x) q_WB and w_OB_B = w_B - R_WB^T w_WO_W: reads a recorded attitude relative to LVLH or\n"
       "RSW (the inverse of `attitude_from_orbit_frame`).\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       state_params +
       "q_WB : array_like, shape (4,) or (n, 4)\n"
       "    Attitude of the body B in W, unit quaternions (x, y, z, w) ((w, x, y, z) if `scalar_first`);\n"
       "    norm within 1e-6 of 1 (then normalised).\n"
       "w_B : array_like, shape (3,) or (n, 3)\n"
       "    Angular velocity of B in W, expressed in B [rad/s].\n" +
       frame_param + scalar_first_param +
       "\n"
       "Returns\n"
       "-------\n"
       "q_OB : ndarray, shape (4,) or (n, 4)\n"
       "    Attitude of B relative to O, in the order of the input.\n"
       "w_OB_B : ndarray, shape (3,) or (n, 3)\n"
       "    Angular velocity of B relative to O, expressed in B [rad/s].\n"
       "\n"
       "Raises\n"
       "------\n" +
       state_raises +
       "    A quaternion farther than 1e-6 from unit norm (the message names `q_WB`); `frame` not 'lvlh' or\n"
       "    'rsw'.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "attitude_from_orbit_frame, orbit_frame_rotation\n"
       "\n"
       "Examples\n"
       "--------\n"
       "A body turning at the orbit rate about -y_W on that orbit holds LVLH: no attitude or rate relative to it:\n"
       "\n"
       ">>> r, v = [0.0, 0.0, -7e6], [7546.053290107541, 0.0, 0.0]\n"
       ">>> q, w = rd.attitude_to_orbit_frame(r, v, [0, 0, 0, 1.0], [0.0, -1.078007612872506e-3, 0.0])\n"
       ">>> q.round(12), bool(np.abs(w).max() < 1e-18)\n"
       "(array([0., 0., 0., 1.]), True)")
          .c_str());
}

}  // namespace rigiddyn::bindings
