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
#include "common_args.hpp"
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

using py_io::item;  // item i of a stack that may be a single broadcast item

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

// numpydoc pieces shared by the docstrings below (Parameters entries)
const char* const canonical_param =
    "canonical : bool, default False\n"
    "    Return the representative with w >= 0 (SciPy's ``as_quat(canonical=True)``: at w = 0 the first\n"
    "    non-zero of x, y, z is positive).\n";

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
      "The rotation matrix nearest to a matrix in the Frobenius norm (orthogonal Procrustes problem).\n"
      "\n"
      "With the SVD M = U S V^T, R = U diag(1, 1, det(U V^T)) V^T. For det M > 0 this is the orthogonal\n"
      "polar factor of M (Higham 1986, \"Computing the polar decomposition\"), the matrix SciPy's\n"
      "``Rotation.from_matrix(M).as_matrix()`` gives for a non-orthonormal M; for det M < 0 the smallest\n"
      "singular direction is flipped (Kabsch). Unique when M has rank >= 2 (and, for det M < 0, distinct\n"
      "two smallest singular values). Idempotent: a rotation matrix is returned unchanged to round-off.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "M : array_like, shape (3, 3) or (n, 3, 3)\n"
      "    Any finite matrices.\n"
      "\n"
      "Returns\n"
      "-------\n"
      "ndarray, shape (3, 3) or (n, 3, 3)\n"
      "    R, orthonormal with det +1 to round-off.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    A non-finite entry or a wrong shape (the message names `M`).\n"
      "\n"
      "See Also\n"
      "--------\n"
      "matrix_to_quat\n"
      "\n"
      "Examples\n"
      "--------\n"
      "A rotation matrix with rounding noise is cleaned up:\n"
      "\n"
      ">>> M = rd.rot_z(0.3) + 1e-4 * np.array([[1.0, 2.0, 0.0], [0.0, -1.0, 3.0], [2.0, 0.0, 1.0]])\n"
      ">>> R = rd.nearest_rotation(M)\n"
      ">>> np.allclose(R @ R.T, np.eye(3)), f\"{np.linalg.det(R):.12f}\"\n"
      "(True, '1.000000000000')\n"
      ">>> rd.nearest_rotation(np.diag([2.0, 3.0, 4.0])).round(12) + 0.0\n"
      "array([[1., 0., 0.],\n"
      "       [0., 1., 0.],\n"
      "       [0., 0., 1.]])");

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
      (std::string() +
       "The canonical quaternion of each rotation (q and -q are the same rotation).\n"
       "\n"
       "w > 0, or where w = 0 the first non-zero of x, y, z positive, exactly as SciPy's\n"
       "``Rotation.from_quat(q).as_quat(canonical=True)``.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "q : array_like, shape (4,) or (n, 4)\n"
       "    Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then\n"
       "    normalised).\n" +
       scalar_first_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (4,) or (n, 4)\n"
       "    q or -q, in the order of the input.\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names `q`\n"
       "    and, in a stack, the item), or a wrong shape.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "quat_normalize, matrix_to_quat\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> rd.quat_canonical([[0.0, 0.6, 0.0, -0.8], [0.0, -1.0, 0.0, 0.0]]) + 0.0\n"
       "array([[ 0. , -0.6,  0. ,  0.8],\n"
       "       [ 0. ,  1. ,  0. ,  0. ]])")
          .c_str());

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
      (std::string() +
       "Spherical linear interpolation from q0 (t = 0) to q1 (t = 1): shortest path, constant rate.\n"
       "\n"
       "q(t) = q0 ⊗ exp(t log(q0^-1 ⊗ q1)), the log at an angle in [0, pi] (Shoemake, \"Animating rotation\n"
       "with quaternion curves\"). Any finite t extrapolates along the arc. SciPy:\n"
       "``Slerp([0, 1], Rotation.from_quat([q0, q1]))(t)``. To interpolate between key rotations at key\n"
       "times use `slerp_keys`.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "q0, q1 : array_like, shape (4,) or (n, 4)\n"
       "    Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then\n"
       "    normalised).\n"
       "t : float or array_like, shape (n,)\n"
       "    Fraction of the way from q0 to q1 (dimensionless); single items of q0, q1, t are used with every\n"
       "    item of the stacks.\n" +
       scalar_first_param +
       canonical_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (4,) or (n, 4)\n"
       "    q(t), (x, y, z, w) or (w, x, y, z) if `scalar_first`.\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names it\n"
       "    and, in a stack, the item), a non-finite t, a wrong shape, or stacks of different lengths.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "slerp_keys, angular_distance\n"
       "\n"
       "Examples\n"
       "--------\n"
       "Halfway between the identity and a quarter turn about z is an eighth turn:\n"
       "\n"
       ">>> q1 = rd.rotvec_to_quat([0.0, 0.0, np.pi / 2])\n"
       ">>> q = rd.slerp([0.0, 0.0, 0.0, 1.0], q1, 0.5)\n"
       ">>> f\"{rd.quat_to_rotvec(q)[2]:.12f}\", f\"{np.pi / 4:.12f}\"\n"
       "('0.785398163397', '0.785398163397')")
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
      (std::string() +
       "Slerp through key rotations at key times.\n"
       "\n"
       "On [times[j], times[j+1]] the result is slerp(q[j], q[j+1], (t - times[j]) / (times[j+1] -\n"
       "times[j])). SciPy: ``Slerp(times, Rotation.from_quat(q))(t)``.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "times : array_like, shape (k,)\n"
       "    Key times, strictly increasing, k >= 2 (any time unit).\n"
       "q : array_like, shape (k, 4)\n"
       "    Key rotations, unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within\n"
       "    1e-6 of 1 (then normalised).\n"
       "t : float or array_like, shape (m,)\n"
       "    Times within [times[0], times[-1]], in the unit of `times`.\n" +
       scalar_first_param +
       canonical_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (4,) or (m, 4)\n"
       "    The interpolated rotations, (x, y, z, w) or (w, x, y, z) if `scalar_first`.\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    `times` not strictly increasing, `q` not of shape (k, 4) or not unit quaternions, `t` outside\n"
       "    the key times or non-finite (each message names the argument).\n"
       "TypeError\n"
       "    `times` not a 1-d array.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "slerp\n"
       "\n"
       "Examples\n"
       "--------\n"
       "Three keys about z; at t = 1.5 the turn is halfway from the second key to the third:\n"
       "\n"
       ">>> q = rd.rotvec_to_quat([[0.0, 0.0, 0.0], [0.0, 0.0, 0.5], [0.0, 0.0, 1.5]])\n"
       ">>> qt = rd.slerp_keys([0.0, 1.0, 2.0], q, [0.5, 1.5])\n"
       ">>> rd.quat_to_rotvec(qt).round(12)\n"
       "array([[0.  , 0.  , 0.25],\n"
       "       [0.  , 0.  , 1.  ]])")
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
      (std::string() +
       "Angle of the rotation taking q_a to q_b.\n"
       "\n"
       "The magnitude of q_a^-1 ⊗ q_b, 2 atan2(|d_xyz|, |d_w|) for d = q_a^-1 ⊗ q_b: in [0, pi], accurate\n"
       "near 0 and near pi; a metric on rotations, independent of the quaternions' signs. SciPy:\n"
       "``(r_a.inv() * r_b).magnitude()``.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "q_a, q_b : array_like, shape (4,) or (n, 4)\n"
       "    Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then\n"
       "    normalised). A single one is compared with every item of the other.\n" +
       scalar_first_param +
       "degrees : bool, default False\n"
       "    Return degrees instead of radians.\n"
       "\n"
       "Returns\n"
       "-------\n"
       "float or ndarray, shape (n,)\n"
       "    Angles [rad] in [0, pi] (degrees if `degrees`).\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names it\n"
       "    and, in a stack, the item), a wrong shape, or stacks of different lengths.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "quat_to_axis_angle, slerp\n"
       "\n"
       "Examples\n"
       "--------\n"
       "q and -q are the same rotation:\n"
       "\n"
       ">>> q = rd.rotvec_to_quat([0.2, 0.0, 0.0])\n"
       ">>> round(rd.angular_distance(q, -q), 12)\n"
       "0.0\n"
       ">>> rd.angular_distance([0.0, 0.0, 0.0, 1.0], [[0.0, 0.0, 1.0, 0.0]], degrees=True).round(9)\n"
       "array([180.])")
          .c_str());

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
      (std::string() +
       "Rotations drawn uniformly (Haar measure) from SO(3), as unit quaternions.\n"
       "\n"
       "Normalised standard normal 4-vectors are uniform on the unit sphere of R^4 (Shoemake 1992, \"Uniform\n"
       "random rotations\"). The draws are SciPy's: for the same generator state the result equals\n"
       "``Rotation.random(n, rng=rng).as_quat()``, and the generator advances by 4 n normal draws.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "n : int or None, default None\n"
       "    None for one rotation (shape (4,)), or a count >= 0 (shape (n, 4)).\n"
       "rng : numpy.random.Generator, int or None, default None\n"
       "    A generator, or None / a seed (int >= 0) given to ``numpy.random.default_rng``.\n" +
       scalar_first_param +
       canonical_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (4,) or (n, 4)\n"
       "    Unit quaternions, (x, y, z, w) or (w, x, y, z) if `scalar_first`.\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    `n` negative or too large to allocate.\n"
       "TypeError\n"
       "    `rng` not a Generator, None or an int seed.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "quat_canonical\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> q = rd.random_rotations(1000, rng=0, canonical=True)\n"
       ">>> q.shape, np.allclose(np.linalg.norm(q, axis=1), 1.0), bool((q[:, 3] >= 0).all())\n"
       "((1000, 4), True, True)")
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
      (std::string() +
       "The rotation that best maps vectors b onto vectors a (Wahba's problem).\n"
       "\n"
       "R minimises 1/2 sum_i w_i |a_i - R b_i|^2, by the SVD of B = sum_i w_i a_i b_i^T (Markley 1988,\n"
       "\"Attitude determination using vector observations and the singular value decomposition\"). SciPy:\n"
       "``Rotation.align_vectors(a, b, weights)``. One pair (N = 1): the smallest rotation taking the\n"
       "direction of b to that of a.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "a, b : array_like, shape (3,) or (N, 3)\n"
       "    The same vectors observed in two frames: with a in W and b in B the result is q_WB. Lengths act\n"
       "    as weights (normalise for equal weighting).\n"
       "weights : array_like, shape (N,), optional\n"
       "    Weights >= 0 (default all 1); one may be inf: that primary pair is aligned exactly and the\n"
       "    others only by the turn about it.\n"
       "return_sensitivity : bool, default False\n"
       "    Also return the sensitivity matrix (not for one pair or an infinite weight).\n" +
       scalar_first_param +
       "\n"
       "Returns\n"
       "-------\n"
       "q : ndarray, shape (4,)\n"
       "    The rotation, canonical (w >= 0), (x, y, z, w) or (w, x, y, z) if `scalar_first`.\n"
       "rssd : float\n"
       "    sqrt(sum_i w_i |a_i - R b_i|^2) over the finite weights [unit of a].\n"
       "sensitivity : ndarray, shape (3, 3)\n"
       "    Only with `return_sensitivity`: SciPy's covariance of the rotation-vector error [rad^2 per unit\n"
       "    of measurement variance].\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    `b` not of the shape of `a`, `weights` not of shape (N,), or `return_sensitivity` with one pair\n"
       "    or an infinite weight (each message names the argument).\n"
       "\n"
       "Warns\n"
       "-----\n"
       "UserWarning\n"
       "    When the optimal rotation is not unique or poorly defined (all pairs parallel, or zero weights).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "quat_rotate\n"
       "\n"
       "Examples\n"
       "--------\n"
       "Vectors measured in B and known in W give the attitude q_WB:\n"
       "\n"
       ">>> q_WB = rd.rotvec_to_quat([0.3, -0.5, 1.1])\n"
       ">>> b = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])\n"
       ">>> q, rssd = rd.align_vectors(rd.quat_rotate(q_WB, b), b)\n"
       ">>> np.allclose(q, rd.quat_canonical(q_WB)), rssd < 1e-12\n"
       "(True, True)")
          .c_str());
}

}  // namespace rigiddyn::bindings
