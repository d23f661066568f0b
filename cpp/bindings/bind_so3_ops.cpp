// Python bindings of the SciPy-parity rotation operations (a name table over so3/nearest_rotation,
// slerp, angular_distance, align_vectors and quat_canonical): every function takes one item or a
// stack of n items (leading axis n) and returns the same, the loops over stacks in C++ with the
// GIL released. Quaternions are (x, y, z, w), or (w, x, y, z) with scalar_first=True; quaternion
// arguments must be unit quaternions (| |q| - 1 | <= 1e-6, then normalised), else ValueError
// naming the argument (and the item).
#include <pybind11/numpy.h>

#include <string>
#include <vector>

#include "bindings.hpp"
#include "for_each_item.hpp"
#include "numpy_io.hpp"
#include "rigiddyn/so3/align_vectors.hpp"
#include "rigiddyn/so3/angular_distance.hpp"
#include "rigiddyn/so3/nearest_rotation.hpp"
#include "rigiddyn/so3/quaternion.hpp"
#include "rigiddyn/so3/slerp.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using namespace pybind11::literals;
using py_io::Array;
using py_io::Stack;
using RowMajor3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

namespace {

constexpr double degrees_per_radian = 57.295779513082320876798154814105;  // 180 / pi

// Stacks that share the leading axis: each single item is used with every item of the others.
// ValueError naming the first stack whose length differs from the first stacked one's.
struct Broadcast {
  py::ssize_t n = 1;
  bool stacked = false;
};
Broadcast broadcast(std::initializer_list<std::pair<const Stack*, const char*>> stacks) {
  Broadcast b;
  const char* first = nullptr;
  for (const auto& [s, name] : stacks) {
    if (!s->stacked) continue;
    if (b.stacked && s->n != b.n) {
      throw py::value_error(std::string(name) + ": expected " + std::to_string(b.n) + " items (as " + first + "), got " +
                            std::to_string(s->n));
    }
    b = {s->n, true};
    if (!first) first = name;
  }
  return b;
}

// item i of a stack that may be a single broadcast item
const double* item(const Stack& s, py::ssize_t i, py::ssize_t size) { return s.array.data() + (s.stacked ? i * size : 0); }

Eigen::Quaterniond unit_quaternion(const double* p, bool scalar_first, const std::string& name) {
  return checked_unit_quaternion(py_io::read_quaternion(p, scalar_first), name);
}

void write_quaternion(Eigen::Quaterniond q, double* out, bool scalar_first, bool canonical) {
  py_io::write_quaternion(canonical ? quat_canonical(q) : q, out, scalar_first);
}

py::object float_or_array(const Array& a, bool stacked) {
  if (stacked) return a;
  return py::float_(a.data()[0]);
}

// `rng` as a numpy.random.Generator: a Generator itself, or None / a seed >= 0 given to
// numpy.random.default_rng (as SciPy's Rotation.random does).
py::object as_generator(py::handle rng) {
  const py::module_ random = py::module_::import("numpy.random");
  if (py::isinstance(rng, random.attr("Generator"))) return py::reinterpret_borrow<py::object>(rng);
  if (rng.is_none()) return random.attr("default_rng")();
  const std::int64_t seed = py_io::as_int(rng, "rng", 0);  // TypeError names the expected kinds below
  return random.attr("default_rng")(seed);
}

const char* const quaternion_out =
    "(x, y, z, w), or (w, x, y, z) if scalar_first; canonical=True gives the representative with w >= 0\n"
    "(SciPy's as_quat(canonical=True): at w = 0 the first non-zero of x, y, z is positive).";

}  // namespace

void bind_so3_ops(py::module_& m) {
  // ------------------------------------------------------------ nearest rotation
  m.def(
      "nearest_rotation",
      [](py::handle M) {
        const Stack in = py_io::as_stack(M, "M", {3, 3});
        Array out = py_io::new_stack(in.n, in.stacked, {3, 3}, "nearest_rotation");
        const double* a = in.array.data();
        double* o = out.mutable_data();
        for_each_item(in.n, in.stacked, [&](py::ssize_t i) {
          Eigen::Map<RowMajor3>{o + 9 * i} = nearest_rotation(Eigen::Map<const RowMajor3>(a + 9 * i));
        });
        return out;
      },
      "M"_a,
      "The rotation matrix nearest to M in the Frobenius norm (orthogonal Procrustes problem).\n\n"
      "M: (3, 3) or (n, 3, 3), any finite matrices. With the SVD M = U S V^T, returns\n"
      "R = U diag(1, 1, det(U V^T)) V^T: (3, 3) or (n, 3, 3), orthonormal with det +1 to round-off.\n"
      "For det M > 0 this is the orthogonal polar factor of M (Higham 1986), the matrix SciPy's\n"
      "Rotation.from_matrix stores for a non-orthonormal M; for det M < 0 the smallest singular\n"
      "direction is flipped (Kabsch). Unique when M has rank >= 2 (and, for det M < 0, distinct two\n"
      "smallest singular values). Idempotent: a rotation matrix is returned unchanged to round-off.");

  // ------------------------------------------------------------ canonical sign
  m.def(
      "quat_canonical",
      [](py::handle q, py::handle scalar_first_arg) {
        const bool scalar_first = py_io::as_bool(scalar_first_arg, "scalar_first");
        const Stack in = py_io::as_stack(q, "q", {4});
        Array out = py_io::new_stack(in.n, in.stacked, {4}, "quat_canonical");
        const double* a = in.array.data();
        double* o = out.mutable_data();
        const std::string name = "q";
        for_each_item(in.n, in.stacked, [&](py::ssize_t i) {
          write_quaternion(unit_quaternion(a + 4 * i, scalar_first, name), o + 4 * i, scalar_first, true);
        });
        return out;
      },
      "q"_a, "scalar_first"_a = false,
      "The canonical quaternion of each rotation (q and -q are the same rotation): w > 0, or where\n"
      "w = 0 the first non-zero of x, y, z positive, exactly as SciPy's as_quat(canonical=True).\n\n"
      "q: (4,) or (n, 4) unit quaternions, (x, y, z, w) or (w, x, y, z) if scalar_first.\n"
      "Returns (4,) or (n, 4) in the same order.");

  // ------------------------------------------------------------ slerp
  m.def(
      "slerp",
      [](py::handle q0, py::handle q1, py::handle t, py::handle scalar_first_arg, py::handle canonical_arg) {
        const bool scalar_first = py_io::as_bool(scalar_first_arg, "scalar_first");
        const bool canonical = py_io::as_bool(canonical_arg, "canonical");
        const Stack s0 = py_io::as_stack(q0, "q0", {4});
        const Stack s1 = py_io::as_stack(q1, "q1", {4});
        const Stack st = py_io::as_stack(t, "t", {});
        const Broadcast b = broadcast({{&s0, "q0"}, {&s1, "q1"}, {&st, "t"}});
        Array out = py_io::new_stack(b.n, b.stacked, {4}, "slerp");
        double* o = out.mutable_data();
        const std::string name0 = "q0", name1 = "q1";
        for_each_item(b.n, b.stacked, [&](py::ssize_t i) {
          const Eigen::Quaterniond a = unit_quaternion(item(s0, i, 4), scalar_first, name0);
          const Eigen::Quaterniond c = unit_quaternion(item(s1, i, 4), scalar_first, name1);
          write_quaternion(slerp(a, c, *item(st, i, 1)), o + 4 * i, scalar_first, canonical);
        });
        return out;
      },
      "q0"_a, "q1"_a, "t"_a, "scalar_first"_a = false, "canonical"_a = false,
      (std::string("Spherical linear interpolation from q0 (t = 0) to q1 (t = 1), shortest path, constant rate.\n\n"
                   "q(t) = q0 * exp(t log(q0^-1 * q1)), the log at angle in [0, pi]: SciPy's\n"
                   "Slerp([0, 1], Rotation.from_quat([q0, q1]))(t). Any finite t extrapolates along the arc.\n"
                   "q0, q1: (4,) or (n, 4) unit quaternions; t: float or (n,) (dimensionless fraction);\n"
                   "single items are used with every item of the stacks. Returns (4,) or (n, 4),\n") +
       quaternion_out + "\nTo interpolate between key rotations at key times use slerp_keys.")
          .c_str());

  m.def(
      "slerp_keys",
      [](py::handle times, py::handle q, py::handle t, py::handle scalar_first_arg, py::handle canonical_arg) {
        const bool scalar_first = py_io::as_bool(scalar_first_arg, "scalar_first");
        const bool canonical = py_io::as_bool(canonical_arg, "canonical");
        const Stack st = py_io::as_stack(times, "times", {});
        const Stack sq = py_io::as_stack(q, "q", {4});
        if (!st.stacked) py_io::throw_type_error("times", "a 1-d array of key times", times);
        if (!sq.stacked) throw py::value_error("q: expected key rotations of shape (k, 4), got shape (4,)");
        std::vector<double> key_times(st.array.data(), st.array.data() + st.n);
        std::vector<Eigen::Quaterniond> keys;
        keys.reserve(sq.n);
        const std::string name = "q";
        for_each_item(sq.n, true, [&](py::ssize_t i) { keys.push_back(unit_quaternion(sq.array.data() + 4 * i, scalar_first, name)); });
        const KeyedSlerp interpolate(std::move(key_times), std::move(keys));
        const Stack se = py_io::as_stack(t, "t", {});
        Array out = py_io::new_stack(se.n, se.stacked, {4}, "slerp_keys");
        double* o = out.mutable_data();
        for_each_item(se.n, se.stacked, [&](py::ssize_t i) {
          write_quaternion(interpolate(se.array.data()[i]), o + 4 * i, scalar_first, canonical);
        });
        return out;
      },
      "times"_a, "q"_a, "t"_a, "scalar_first"_a = false, "canonical"_a = false,
      (std::string("Slerp through key rotations q[k] at key times times[k]: SciPy's Slerp(times, rotations)(t).\n\n"
                   "times: (k,) strictly increasing, k >= 2 [any time unit]; q: (k, 4) unit quaternions;\n"
                   "t: float or (m,) within [times[0], times[-1]] (ValueError outside). On [times[j], times[j+1]]\n"
                   "the result is slerp(q[j], q[j+1], (t - times[j]) / (times[j+1] - times[j])).\n"
                   "Returns (4,) or (m, 4), ") +
       quaternion_out)
          .c_str());

  // ------------------------------------------------------------ angular distance
  m.def(
      "angular_distance",
      [](py::handle q_a, py::handle q_b, py::handle scalar_first_arg, py::handle degrees_arg) {
        const bool scalar_first = py_io::as_bool(scalar_first_arg, "scalar_first");
        const double unit = py_io::as_bool(degrees_arg, "degrees") ? degrees_per_radian : 1.0;
        const Stack sa = py_io::as_stack(q_a, "q_a", {4});
        const Stack sb = py_io::as_stack(q_b, "q_b", {4});
        const Broadcast b = broadcast({{&sa, "q_a"}, {&sb, "q_b"}});
        Array out = py_io::new_stack(b.n, b.stacked, {}, "angular_distance");
        double* o = out.mutable_data();
        const std::string name_a = "q_a", name_b = "q_b";
        for_each_item(b.n, b.stacked, [&](py::ssize_t i) {
          o[i] = unit * angular_distance(unit_quaternion(item(sa, i, 4), scalar_first, name_a),
                                         unit_quaternion(item(sb, i, 4), scalar_first, name_b));
        });
        return float_or_array(out, b.stacked);
      },
      "q_a"_a, "q_b"_a, "scalar_first"_a = false, "degrees"_a = false,
      "Angle [rad, or degrees if degrees=True] in [0, pi] of the rotation taking q_a to q_b: the\n"
      "magnitude of q_a^-1 * q_b (SciPy's (r_a.inv() * r_b).magnitude()), a metric on rotations,\n"
      "independent of the quaternions' signs. 2 atan2(|d_xyz|, |d_w|): accurate near 0 and near pi.\n\n"
      "q_a, q_b: (4,) or (n, 4) unit quaternions, (x, y, z, w) or (w, x, y, z) if scalar_first; a single\n"
      "one is compared with every item of the other. Returns a float or (n,).");

  // ------------------------------------------------------------ random rotations
  m.def(
      "random_rotations",
      [](py::handle n_arg, py::handle rng_arg, py::handle scalar_first_arg, py::handle canonical_arg) {
        const bool scalar_first = py_io::as_bool(scalar_first_arg, "scalar_first");
        const bool canonical = py_io::as_bool(canonical_arg, "canonical");
        const bool stacked = !n_arg.is_none();
        const py::ssize_t n = stacked ? py_io::as_int(n_arg, "n", 0, std::int64_t(1) << 40) : 1;
        py_io::require_allocatable(std::uint64_t(n) * 4 * sizeof(double), "n", "the random draws");
        py::object rng;
        try {
          rng = as_generator(rng_arg);
        } catch (const py::type_error&) {
          py_io::throw_type_error("rng", "a numpy.random.Generator, None or a seed (int >= 0)", rng_arg);
        }
        // the draws of SciPy's Rotation.random: 4 standard normal numbers per rotation, in order
        const Array draws = py_io::as_array(rng.attr("normal")("size"_a = py::make_tuple(n, 4)), "rng");
        Array out = py_io::new_stack(n, stacked, {4}, "random_rotations");
        const double* d = draws.data();
        double* o = out.mutable_data();
        for_each_item(n, stacked, [&](py::ssize_t i) {
          // x, y, z, w of an isotropic normal vector in R^4, normalised: uniform on S^3, so the
          // rotation is Haar-uniform on SO(3) (K. Shoemake, "Uniform random rotations", Graphics Gems III, 1992)
          const Eigen::Quaterniond q = quat_normalize(Eigen::Quaterniond(Eigen::Vector4d(d[4 * i], d[4 * i + 1], d[4 * i + 2], d[4 * i + 3])), "rng");
          write_quaternion(q, o + 4 * i, scalar_first, canonical);
        });
        return out;
      },
      "n"_a = py::none(), "rng"_a = py::none(), "scalar_first"_a = false, "canonical"_a = false,
      (std::string("Rotations drawn uniformly (Haar measure) from SO(3), as unit quaternions.\n\n"
                   "n: None (one rotation, shape (4,)) or a count (shape (n, 4)). rng: a numpy.random.Generator,\n"
                   "or None / a seed (int >= 0) for numpy.random.default_rng. The draws are SciPy's: for the same\n"
                   "generator state the result equals Rotation.random(n, rng=rng).as_quat() (normalised\n"
                   "standard normal 4-vectors), and the generator advances by 4 n normal draws. Returns ") +
       quaternion_out)
          .c_str());

  // ------------------------------------------------------------ Wahba's problem
  m.def(
      "align_vectors",
      [](py::handle a, py::handle b, py::handle weights, py::handle return_sensitivity_arg, py::handle scalar_first_arg) {
        const bool return_sensitivity = py_io::as_bool(return_sensitivity_arg, "return_sensitivity");
        const bool scalar_first = py_io::as_bool(scalar_first_arg, "scalar_first");
        const Stack sa = py_io::as_stack(a, "a", {3});
        const Stack sb = py_io::as_stack(b, "b", {3});
        if (sa.stacked != sb.stacked || sa.n != sb.n) {
          throw py::value_error("b: expected the shape of a (" + py::str(sa.array.attr("shape")).cast<std::string>() +
                                "), got shape " + py::str(sb.array.attr("shape")).cast<std::string>());
        }
        Eigen::VectorXd w = Eigen::VectorXd::Ones(sa.n);
        if (!weights.is_none()) {
          const Array wa = py_io::as_array(weights, "weights");
          if (wa.ndim() != 1 || wa.shape(0) != sa.n) {
            throw py::value_error("weights: expected shape (" + std::to_string(sa.n) + ",) (one per vector), got shape " +
                                  py::str(wa.attr("shape")).cast<std::string>());
          }
          w = Eigen::Map<const Eigen::VectorXd>(wa.data(), sa.n);
        }
        const Eigen::Map<const Vectors3> A(sa.array.data(), sa.n, 3), B(sb.array.data(), sb.n, 3);
        VectorAlignment r;
        {
          py::gil_scoped_release release;
          r = align_vectors(A, B, w);
        }
        const bool special = sa.n == 1 || std::isinf(w.maxCoeff());
        if (return_sensitivity && special) {
          throw py::value_error(
              "return_sensitivity: expected False with one vector pair or an infinite weight (no sensitivity is "
              "defined there), got True");
        }
        if (!r.unique && PyErr_WarnEx(PyExc_UserWarning,
                                      "align_vectors: the optimal rotation is not unique or poorly defined for the "
                                      "given vectors (all pairs parallel, or zero weights)",
                                      1) != 0) {
          throw py::error_already_set();
        }
        // finite inputs give a finite rotation (scaled internally); rssd and sensitivity may overflow
        py_io::finite_result(r.rssd, "rssd");
        const Array q = py_io::to_array(r.q, scalar_first);
        if (return_sensitivity) return py::tuple(py::make_tuple(q, r.rssd, py_io::finite_result(r.sensitivity, "sensitivity")));
        return py::tuple(py::make_tuple(q, r.rssd));
      },
      "a"_a, "b"_a, "weights"_a = py::none(), "return_sensitivity"_a = false, "scalar_first"_a = false,
      "The rotation R that best maps the vectors b onto the vectors a (Wahba's problem), as SciPy's\n"
      "Rotation.align_vectors(a, b, weights): R minimises 1/2 sum_i w_i |a_i - R b_i|^2.\n\n"
      "a, b: (3,) or (N, 3), the same vectors observed in two frames: with a in W and b in B the result\n"
      "is q_WB. Lengths act as weights (normalise for equal weighting). weights: None (all 1) or (N,)\n"
      "of values >= 0; one may be inf: that primary pair is aligned exactly and the others only by the\n"
      "turn about it. One pair (N = 1): the smallest rotation taking the direction of b to that of a.\n"
      "General case by the SVD of B = sum w_i a_i b_i^T (Markley 1988), UserWarning when the optimum\n"
      "is not unique (all pairs parallel).\n"
      "Returns (q, rssd) or, with return_sensitivity=True, (q, rssd, sensitivity): q (4,) canonical\n"
      "(w >= 0), (x, y, z, w) or (w, x, y, z) if scalar_first; rssd = sqrt(sum_i w_i |a_i - R b_i|^2)\n"
      "[units of a] over the finite weights; sensitivity (3, 3), SciPy's covariance of the rotation-vector\n"
      "error [rad^2 per unit of measurement variance] (not for one pair or an infinite weight).");
}

}  // namespace rigiddyn::bindings
