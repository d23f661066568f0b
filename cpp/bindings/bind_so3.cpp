// Python bindings of the so3 layer (rotations): a name table over rigiddyn/so3/*.hpp. Every
// function takes one item or a stack of n items (leading axis n) and returns the same; the loops
// over stacks run in C++ with the GIL released. Quaternions are (x, y, z, w), or (w, x, y, z) with
// scalar_first=True; every quaternion argument except quat_normalize's must be a unit quaternion
// (| |q| - 1 | <= 1e-6, then normalised) and every matrix argument a rotation matrix up to rounding
// (det > 0, singular values within 0.05 of 1: projected onto the nearest rotation unless orthonormal
// to SciPy's test, as Rotation.from_matrix; see nearest_rotation.hpp); otherwise ValueError naming
// the argument (and the item).
// Angles are radians inside; `degrees=True` converts at this boundary (as SciPy, x * (pi/180) in and
// x * (180/pi) out).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "common_args.hpp"
#include "for_each_item.hpp"
#include "numpy_io.hpp"
#include "so3_lanes.hpp"
#include "rigiddyn/always_inline.hpp"
#include "rigiddyn/so3/axis_angle.hpp"
#include "rigiddyn/so3/elementary.hpp"
#include "rigiddyn/so3/euler.hpp"
#include "rigiddyn/so3/exp_log.hpp"
#include "rigiddyn/so3/integrate.hpp"
#include "rigiddyn/so3/matrix.hpp"
#include "rigiddyn/so3/mrp.hpp"
#include "rigiddyn/so3/nearest_rotation.hpp"
#include "rigiddyn/so3/quaternion.hpp"
#include "rigiddyn/so3/skew.hpp"

namespace rigiddyn::bindings {

namespace py = pybind11;
using namespace pybind11::literals;
using py_io::Array;
using py_io::Stack;
using Shape = std::vector<py::ssize_t>;
using RowMajor3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

namespace {

// layouts of one item
const Shape scalar{};
const Shape vector3{3};
const Shape quaternion{4};
const Shape matrix3{3, 3};

using py_io::item_size;

// item readers and writers (numpy items are C-contiguous: matrices row-major)
using py_io::read_vector;
using py_io::write_vector;
Eigen::Matrix3d read_matrix(const double* p) { return Eigen::Map<const RowMajor3>(p); }
void write_matrix(const Eigen::Matrix3d& R, double* out) { Eigen::Map<RowMajor3>{out} = R; }

// finite &= every entry of the item is finite (branch-free, on the item just written: no second pass)
inline void and_finite(bool& finite, const double* item, py::ssize_t size) {
  double zero = 0.0;
  for (py::ssize_t k = 0; k < size; ++k) zero += item[k] - item[k];  // NaN unless every entry is finite
  finite &= zero == 0.0;
}

// What the loops below check of each item they write: its entries finite (a non-finite one warns naming
// the quantity), what f returns (true where its item is finite: a test f has at hand, cheaper than reading
// the entries back), or nothing where the result is finite by construction (a polynomial or bounded map of
// unit quaternions checked on reading).
enum class Written { checked_finite, checked_by_f, finite_by_construction };

// out[i] = f(in[i]) over a stack: items of shape `in_shape` -> items of shape `out_shape`.
// f(const double* in_item, double* out_item); EntryCheck::by_caller where f checks every entry it reads
// (unit_quaternion_at).
template <Written written = Written::checked_finite, py_io::EntryCheck check = py_io::EntryCheck::all_finite, typename F>
Array map_unary(py::handle x, const char* name, const Shape& in_shape, const Shape& out_shape, const char* quantity, F f) {
  const Stack in = py_io::as_stack(x, name, in_shape, check);
  Array out = py_io::new_stack(in.n, in.stacked, out_shape, quantity);
  const double* a = in.array.data();
  double* o = out.mutable_data();
  const py::ssize_t a_size = item_size(in_shape), o_size = item_size(out_shape);
  bool finite = true;
  for_each_item(in.n, in.stacked, [&](py::ssize_t i) {
    if constexpr (written == Written::checked_by_f) {
      finite &= f(a + i * a_size, o + i * o_size);
    } else {
      f(a + i * a_size, o + i * o_size);
      if constexpr (written == Written::checked_finite) and_finite(finite, o + i * o_size, o_size);
    }
  });
  if (!finite) py_io::finite_result(out, quantity);
  return out;
}

// out[i] = f(x[i], y[i]) over two stacks; a single item is used with every item of the other.
// ValueError naming y when both are stacked with different lengths.
template <Written written = Written::checked_finite, typename F>
Array map_binary(py::handle x, const char* x_name, const Shape& x_shape, py::handle y, const char* y_name,
                 const Shape& y_shape, const Shape& out_shape, const char* quantity, F f) {
  static_assert(written != Written::checked_by_f, "checked_by_f: map_unary only");
  const Stack sx = py_io::as_stack(x, x_name, x_shape);
  const Stack sy = py_io::as_stack(y, y_name, y_shape);
  if (sx.stacked && sy.stacked && sx.n != sy.n) {
    throw py::value_error(std::string(y_name) + ": expected " + std::to_string(sx.n) + " items (as " + x_name +
                          "), got " + std::to_string(sy.n));
  }
  const bool stacked = sx.stacked || sy.stacked;
  const py::ssize_t n = sx.stacked ? sx.n : sy.n;
  Array out = py_io::new_stack(n, stacked, out_shape, quantity);
  const double* a = sx.array.data();
  const double* b = sy.array.data();
  double* o = out.mutable_data();
  // stride 0 broadcasts a single item
  const py::ssize_t a_step = sx.stacked ? item_size(x_shape) : 0, b_step = sy.stacked ? item_size(y_shape) : 0;
  const py::ssize_t o_size = item_size(out_shape);
  bool finite = true;
  for_each_item(n, stacked, [&](py::ssize_t i) {
    f(a + i * a_step, b + i * b_step, o + i * o_size);
    if constexpr (written == Written::checked_finite) and_finite(finite, o + i * o_size, o_size);
  });
  if (!finite) py_io::finite_result(out, quantity);
  return out;
}

// True iff the angle |r| of a finite rotation vector r is finite, the sum of squares of rotvec_to_quat (exp_log.hpp)
// not overflowing (|r| < 1.3e154 rad): then its quaternion is finite (sin, cos and sin(θ/2)/θ bounded).
inline bool finite_angle(const Eigen::Vector3d& r) {
  return std::isfinite(r.x() * r.x() + r.y() * r.y() + r.z() * r.z());
}

// f(std::true_type{}) for scalar-first quaternions, f(std::false_type{}) otherwise: the layout a
// compile-time constant of the loop inside f.
template <typename F>
Array with_layout(bool scalar_first, F f) {
  return scalar_first ? f(std::true_type{}) : f(std::false_type{});
}

// The |q|² range of checked_unit_quaternion's tolerance (| |q| - 1 | <= 1e-6), narrowed by 1e-15 so that
// every item inside it passes that check too. An item outside it takes the check itself, which normalises
// it or throws its message.
constexpr double unit_norm2_low = (1.0 - unit_quaternion_tolerance) * (1.0 - unit_quaternion_tolerance) + 1e-15;
constexpr double unit_norm2_high = (1.0 + unit_quaternion_tolerance) * (1.0 + unit_quaternion_tolerance) - 1e-15;

// The unit quaternion q / |q| of the item at p (layout (w, x, y, z) when ScalarFirst, else (x, y, z, w)),
// checked as checked_unit_quaternion does. With |q|² = 1 - e, |e| < 2.1e-6:
// (1 - e)^(-1/2) = 1 + e/2 + 3e²/8 + 5e³/16 + 35e⁴/128 + ..., the first omitted term below 6e-24, far under
// round-off: no square root or division per item.
template <bool ScalarFirst>
RIGIDDYN_ALWAYS_INLINE Eigen::Quaterniond unit_quaternion_at(const double* p, const std::string& name) {
  // component by component: a packet load of what was just read one by one would stall
  const double x = ScalarFirst ? p[1] : p[0], y = ScalarFirst ? p[2] : p[1], z = ScalarFirst ? p[3] : p[2];
  const double w = ScalarFirst ? p[0] : p[3];
  const double norm2 = (x * x + y * y) + (z * z + w * w);
  if (!(norm2 >= unit_norm2_low && norm2 <= unit_norm2_high)) return checked_unit_quaternion(Eigen::Quaterniond(w, x, y, z), name);
  const double e = 1.0 - norm2;
  const double k = 1.0 + e * (0.5 + e * (0.375 + e * 0.3125));
  return Eigen::Quaterniond(k * w, k * x, k * y, k * z);
}

// The entries of R(q) of unit quaternions (x, y, z, w), row-major: set(k, R_k) for k = 0..8, the products of
// Eigen's toRotationMatrix in the same order. T is double (one item) or lanes (so3_lanes.hpp: entry k of
// every item of a block).
template <typename T, typename Set>
RIGIDDYN_ALWAYS_INLINE void rotation_matrix_entries(const T& x, const T& y, const T& z, const T& w, Set set) {
  const T tx = 2.0 * x, ty = 2.0 * y, tz = 2.0 * z;
  const T twx = tx * w, twy = ty * w, twz = tz * w, txx = tx * x, txy = ty * x, txz = tz * x;
  const T tyy = ty * y, tyz = tz * y, tzz = tz * z;
  set(0, 1.0 - (tyy + tzz)), set(1, txy - twz), set(2, txz + twy);
  set(3, txy + twz), set(4, 1.0 - (txx + tzz)), set(5, tyz - twx);
  set(6, txz - twy), set(7, tyz + twx), set(8, 1.0 - (txx + tyy));
}

// Writes R(q) of a unit quaternion q at out, row-major, entry by entry (no column-major temporary to
// transpose).
RIGIDDYN_ALWAYS_INLINE void write_rotation_matrix(const Eigen::Quaterniond& q, double* out) {
  rotation_matrix_entries(q.x(), q.y(), q.z(), q.w(), [out](int k, double value) { out[k] = value; });
}

// Unit quaternions of a block, q_j = (x[j], y[j], z[j], w[j]).
template <typename T>
struct Quaternions {
  T x, y, z, w;
};

// The lane type of a block's entries.
template <typename E>
using LanesOf = std::remove_cv_t<std::remove_reference_t<decltype(std::declval<E>().e[0])>>;

// The quaternions of a block read in the layout of unit_quaternion_at, normalised as it does, in q; ok in the
// lanes whose |q|² is inside [unit_norm2_low, unit_norm2_high] (the block of an item outside takes
// unit_quaternion_at, which normalises such an item exactly or throws).
template <bool ScalarFirst, typename T>
RIGIDDYN_ALWAYS_INLINE void read_unit_quaternions(const Entries<T, 4>& in, Quaternions<T>& q, Mask<T>& ok) {
  const T& x = in.e[ScalarFirst ? 1 : 0];
  const T& y = in.e[ScalarFirst ? 2 : 1];
  const T& z = in.e[ScalarFirst ? 3 : 2];
  const T& w = in.e[ScalarFirst ? 0 : 3];
  const T norm2 = (x * x + y * y) + (z * z + w * w);
  ok = (norm2 >= unit_norm2_low) & (norm2 <= unit_norm2_high);
  const T e = 1.0 - norm2;
  const T k = 1.0 + e * (0.5 + e * (0.375 + e * 0.3125));
  q.x = k * x, q.y = k * y, q.z = k * z, q.w = k * w;
}

// Sets the quaternions (x, y, z, w) of a block in the layout of unit_quaternion_at.
template <bool ScalarFirst, typename T>
RIGIDDYN_ALWAYS_INLINE void set_quaternions(const T& x, const T& y, const T& z, const T& w, Entries<T, 4>& out) {
  out.e[ScalarFirst ? 1 : 0] = x, out.e[ScalarFirst ? 2 : 1] = y, out.e[ScalarFirst ? 3 : 2] = z, out.e[ScalarFirst ? 0 : 3] = w;
}

// out[i] = f(q[i]) over a stack of unit quaternions q (layout as unit_quaternion_at), in blocks (map_blocks):
// block(q_block, out_block, ok) writes the entries of the results of a block's quaternions, normalised by
// read_unit_quaternions, and clears ok in a lane it does not take; item(q_i, out_i) writes the result of one
// item (unit_quaternion_at), the same numbers. Every item's entries are checked by its norm (a non-finite one
// fails it), without a pass of their own; the results are finite by construction.
template <bool ScalarFirst, int out_size, typename Block, typename Item>
Array map_unit_quaternions(py::handle q, const std::string& name, const Shape& out_shape, const char* quantity, Block block, Item item) {
  const Stack in = py_io::as_stack(q, name, quaternion, py_io::EntryCheck::by_caller);
  Array out = py_io::new_stack(in.n, in.stacked, out_shape, quantity);
  const double* a = in.array.data();
  double* o = out.mutable_data();
  map_blocks<4, out_size>(
      a, o, in.n, in.stacked,
      [&block](const auto& q_in, auto& result, auto& ok) RIGIDDYN_INLINE_KERNEL {
        Quaternions<LanesOf<decltype(q_in)>> q_block;
        read_unit_quaternions<ScalarFirst>(q_in, q_block, ok);
        block(q_block, result, ok);
      },
      [&](py::ssize_t i) RIGIDDYN_INLINE_KERNEL { item(unit_quaternion_at<ScalarFirst>(a + 4 * i, name), o + i * out_size); });
  return out;
}

// Writes q at out in the layout of unit_quaternion_at.
template <bool ScalarFirst>
RIGIDDYN_ALWAYS_INLINE void write_quaternion_at(const Eigen::Quaterniond& q, double* out) {
  if constexpr (ScalarFirst) {
    out[0] = q.w(), out[1] = q.x(), out[2] = q.y(), out[3] = q.z();
  } else {
    out[0] = q.x(), out[1] = q.y(), out[2] = q.z(), out[3] = q.w();
  }
}

// The Euler axis sequence argument: TypeError unless a str, ValueError unless a valid sequence.
EulerSequence as_sequence(py::handle seq) {
  if (!py::isinstance<py::str>(seq)) py_io::throw_type_error("seq", "a str such as 'xyz' or 'ZYX'", seq);
  return EulerSequence(seq.cast<std::string>(), "seq");
}


// The user's angle unit: degrees (degrees=True) or radians. The factors are SciPy's (x * (pi/180) in,
// x * (180/pi) out), so that angles in degrees round exactly as SciPy's do.
constexpr double pi = 3.14159265358979323846;
struct AngleUnit {
  double to_radians, from_radians;
};
AngleUnit as_angle_unit(py::handle degrees) {
  if (py_io::as_bool(degrees, "degrees")) return {pi / 180.0, 180.0 / pi};
  return {1.0, 1.0};
}

// Warns as SciPy's as_euler (UserWarning, once per call) when the middle angle of some item was
// near gimbal lock (GimbalLock::near or ::at, see euler.hpp). Throws error_already_set when
// warnings are errors.
void warn_gimbal_lock(GimbalLock worst) {
  if (worst == GimbalLock::none) return;
  const char* message =
      worst == GimbalLock::at
          ? "Gimbal lock detected. Setting third angle to zero since it is not possible to uniquely determine all "
            "angles."
          : "Gimbal lock detected. The middle angle is within 1e-7 rad of its singularity: the first and third "
            "angles reproduce the rotation but amplify its round-off by more than 1e7 (SciPy sets the third to "
            "zero here).";
  if (PyErr_WarnEx(PyExc_UserWarning, message, 1) != 0) throw py::error_already_set();
}

// "e"/"extrinsic" -> false, "i"/"intrinsic" -> true (SciPy's spelling of Davenport orders).
bool as_intrinsic_order(py::handle order) {
  return py_io::as_choice<bool>(order, "order",
                                {{"e", false}, {"extrinsic", false}, {"i", true}, {"intrinsic", true}});
}

// An axis of any length for axis_angle_to_quat, whose |axis| must neither overflow nor underflow:
// one beyond the normal range of |axis|^2 (|axis| > 1e154 or < 1e-154) is first scaled to unit
// length without forming |axis|^2 (stableNormalized); any other axis is passed on unchanged.
Eigen::Vector3d direction(const Eigen::Vector3d& axis) {
  const double squared = axis.squaredNorm();
  const bool normal_range = squared >= std::numeric_limits<double>::min() && squared <= std::numeric_limits<double>::max();
  return normal_range || axis.isZero(0.0) ? axis : axis.stableNormalized();
}

// a 0-d result array (single item of shape ()) as a Python float
py::object scalar_or_array(const Array& a, bool stacked) {
  if (stacked) return a;
  return py::float_(a.data()[0]);
}

// numpydoc pieces shared by the docstrings below (Parameters, Raises and Warns entries)
const char* const q_param =
    "q : array_like, shape (4,) or (n, 4)\n"
    "    Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then\n"
    "    normalised).\n";
const char* const q_raises =
    "ValueError\n"
    "    A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names `q`\n"
    "    and, in a stack, the item), or a shape other than (4,) or (n, 4).\n"
    "TypeError\n"
    "    `q` not an array of real numbers, or `scalar_first` not a bool.\n";
const char* const R_param =
    "R : array_like, shape (3, 3) or (n, 3, 3)\n"
    "    Rotation matrices up to rounding: det > 0 and singular values within 0.05 of 1. One not\n"
    "    orthonormal to SciPy's test is projected onto the nearest rotation (`nearest_rotation`), as\n"
    "    SciPy's `Rotation.from_matrix` does.\n";
const char* const R_raises =
    "ValueError\n"
    "    A matrix with det <= 0 (a reflection or a singular matrix), a singular value farther than 0.05\n"
    "    from 1 or a non-finite entry (the message names `R` and, in a stack, the item), or a shape other\n"
    "    than (3, 3) or (n, 3, 3).\n";
const char* const degrees_param =
    "degrees : bool, default False, keyword-only\n"
    "    Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,\n"
    "    x * (180/pi) out).\n";
const char* const euler_seq_param =
    "seq : str\n"
    "    The axis sequence, 3 letters as SciPy's: lowercase 'xyz' = extrinsic (rotations about the\n"
    "    fixed axes of W), uppercase 'XYZ' = intrinsic (about the moving axes); the 12 sequences xyz xzy\n"
    "    yxz yzx zxy zyx xyx xzx yxy yzy zxz zyz in either case.\n";
const char* const euler_raises =
    "ValueError\n"
    "    `seq` not one of the 24 sequences.\n"
    "TypeError\n"
    "    `seq` not a str.\n";
const char* const gimbal_warns =
    "Warns\n"
    "-----\n"
    "UserWarning\n"
    "    'Gimbal lock detected. ...' (once per call) wherever SciPy warns: the middle angle of some item\n"
    "    within 1e-7 rad of its singularity (Euler angles: 0 or pi in proper sequences, -pi/2 or pi/2\n"
    "    in Tait-Bryan ones; Davenport angles: the ends of its range). Within round-off of it (1e-13 rad)\n"
    "    only the sum or difference of the first and third angles is defined: the third is set to 0 and\n"
    "    the first carries it, with SciPy's message. Between 1e-13 and 1e-7 rad the angles are the exact ones\n"
    "    and the message says so (SciPy sets the third to 0 there too, which moves the rotation by up to\n"
    "    2e-7 rad): the angles reproduce the rotation to round-off everywhere.\n";
const char* const davenport_params =
    "axes : array_like, shape (3, 3)\n"
    "    The rotation axes n1, n2, n3 as rows (any non-zero length, normalised), n2 orthogonal to n1 and\n"
    "    to n3 (|cos| <= 1e-7, as SciPy). Coordinate axes give Euler angles.\n"
    "order : str\n"
    "    'e' or 'extrinsic' (fixed axes, R = R_n3(a3) R_n2(a2) R_n1(a1)) or 'i' or 'intrinsic' (moving\n"
    "    axes, R = R_n1(a1) R_n2(a2) R_n3(a3)), as SciPy's `Rotation.from_davenport` / `as_davenport`.\n";
const char* const davenport_raises =
    "ValueError\n"
    "    `axes` not of shape (3, 3), with a zero row or with n2 not orthogonal to n1 and n3 (the message\n"
    "    names `axes`); `order` not one of 'e', 'extrinsic', 'i', 'intrinsic'.\n";

}  // namespace

void bind_so3(py::module_& m) {
  // ------------------------------------------------------------ matrices
  m.def(
      "quat_to_matrix",
      [](py::handle q, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const std::string name = "q";
        return with_layout(scalar_first, [&](auto first) {
          return map_unit_quaternions<first, 9>(
              q, name, matrix3, "quat_to_matrix",
              [](const auto& q_block, auto& R, auto&) RIGIDDYN_INLINE_KERNEL {
                rotation_matrix_entries(q_block.x, q_block.y, q_block.z, q_block.w, [&R](int k, const auto& R_k) { R.e[k] = R_k; });
              },
              write_rotation_matrix);
        });
      },
      "q"_a, "scalar_first"_a = false,
      (std::string() +
       "Rotation matrix of unit quaternions.\n"
       "\n"
       "R(q) is the active rotation: R v rotates v, and the attitude q_WB gives R_WB (B coordinates to W\n"
       "coordinates). SciPy: ``Rotation.from_quat(q).as_matrix()``.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       q_param +
       scalar_first_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3, 3) or (n, 3, 3)\n"
       "    R(q), orthonormal with det +1.\n"
       "\n"
       "Raises\n"
       "------\n" +
       q_raises +
       "\n"
       "See Also\n"
       "--------\n"
       "matrix_to_quat, quat_rotate, rot_x\n"
       "\n"
       "Examples\n"
       "--------\n"
       "A quarter turn about z takes x to y:\n"
       "\n"
       ">>> q = rd.rotvec_to_quat([0.0, 0.0, np.pi / 2])\n"
       ">>> rd.quat_to_matrix(q).round(12)\n"
       "array([[ 0., -1.,  0.],\n"
       "       [ 1.,  0.,  0.],\n"
       "       [ 0.,  0.,  1.]])")
          .c_str());

  m.def(
      "matrix_to_quat",
      [](py::handle R, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const std::string name = "R";
        return map_unary(R, "R", matrix3, quaternion, "matrix_to_quat", [&](const double* in, double* out) {
          py_io::write_quaternion(matrix_to_quat(projected_rotation_matrix(read_matrix(in), name)), out, scalar_first);
        });
      },
      "R"_a, "scalar_first"_a = false,
      (std::string() +
       "Unit quaternion of rotation matrices, canonical sign w >= 0.\n"
       "\n"
       "Shepperd's method in Markley's form (Markley 2008, \"Unit quaternion from rotation matrix\") with\n"
       "SciPy's choice of branch (the largest of R_00, R_11, R_22 and tr R): accurate at every angle,\n"
       "including pi. SciPy: ``Rotation.from_matrix(R).as_quat(canonical=True)``.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       R_param +
       scalar_first_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (4,) or (n, 4)\n"
       "    q with R(q) = R and w >= 0, (x, y, z, w) or (w, x, y, z) if `scalar_first`.\n"
       "\n"
       "Raises\n"
       "------\n" +
       R_raises +
       "\n"
       "See Also\n"
       "--------\n"
       "quat_to_matrix, nearest_rotation, quat_canonical\n"
       "\n"
       "Examples\n"
       "--------\n"
       "A half turn about x:\n"
       "\n"
       ">>> rd.matrix_to_quat(np.diag([1.0, -1.0, -1.0]))\n"
       "array([1., 0., 0., 0.])\n"
       ">>> rd.matrix_to_quat(np.eye(3), scalar_first=True)\n"
       "array([1., 0., 0., 0.])")
          .c_str());

  // ------------------------------------------------------------ exp / log
  m.def(
      "rotvec_to_quat",
      [](py::handle rotvec, py::handle scalar_first_arg, py::handle degrees) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const AngleUnit unit = as_angle_unit(degrees);
        return with_layout(scalar_first, [&](auto first) {
          return map_unary<Written::checked_by_f>(rotvec, "rotvec", vector3, quaternion, "rotvec_to_quat", [&](const double* in, double* out) {
            const Eigen::Vector3d r = unit.to_radians * read_vector(in);
            write_quaternion_at<first>(rotvec_to_quat(r), out);
            return finite_angle(r);
          });
        });
      },
      "rotvec"_a, "scalar_first"_a = false, py::kw_only(), "degrees"_a = false,
      (std::string() +
       "Exponential map: unit quaternion of rotation vectors.\n"
       "\n"
       "q = (sin(theta/2) u, cos(theta/2)) for rotvec = theta u [rad], u a unit axis; any angle, exact near\n"
       "0. No sign flip: w < 0 when the angle exceeds pi. SciPy: ``Rotation.from_rotvec(rotvec).as_quat()``.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "rotvec : array_like, shape (3,) or (n, 3)\n"
       "    Rotation vectors angle * axis [rad] (degrees if `degrees`), finite.\n" +
       scalar_first_param +
       degrees_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (4,) or (n, 4)\n"
       "    q, (x, y, z, w) or (w, x, y, z) if `scalar_first`.\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A non-finite entry, or a shape other than (3,) or (n, 3) (the message names `rotvec`).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "quat_to_rotvec, rotvec_to_matrix, axis_angle_to_quat\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> rd.rotvec_to_quat([0.0, 0.0, np.pi]).round(12)\n"
       "array([0., 0., 1., 0.])\n"
       ">>> rd.rotvec_to_quat([0.0, 90.0, 0.0], degrees=True)\n"
       "array([0.        , 0.70710678, 0.        , 0.70710678])")
          .c_str());

  m.def(
      "quat_to_rotvec",
      [](py::handle q, py::handle scalar_first_arg, py::handle degrees) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const AngleUnit unit = as_angle_unit(degrees);
        const std::string name = "q";
        return with_layout(scalar_first, [&](auto first) {
          return map_unary<Written::finite_by_construction, py_io::EntryCheck::by_caller>(q, "q", quaternion, vector3, "quat_to_rotvec", [&](const double* in, double* out) {
            write_vector(quat_to_rotvec(unit_quaternion_at<first>(in, name)) * unit.from_radians, out);
          });
        });
      },
      "q"_a, "scalar_first"_a = false, py::kw_only(), "degrees"_a = false,
      (std::string() +
       "Logarithm map: rotation vectors of unit quaternions.\n"
       "\n"
       "rotvec = theta u with theta in [0, pi] (q and -q give the same vector), by the atan2 form: accurate\n"
       "near angle 0 and near pi. SciPy: ``Rotation.from_quat(q).as_rotvec()``.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       q_param +
       scalar_first_param +
       degrees_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3,) or (n, 3)\n"
       "    Rotation vectors angle * axis [rad], angle in [0, pi] (degrees, angle in [0, 180], if\n"
       "    `degrees`).\n"
       "\n"
       "Raises\n"
       "------\n" +
       q_raises +
       "\n"
       "See Also\n"
       "--------\n"
       "rotvec_to_quat, quat_to_axis_angle, matrix_to_rotvec\n"
       "\n"
       "Examples\n"
       "--------\n"
       "The logarithm undoes the exponential for angles up to pi:\n"
       "\n"
       ">>> rotvec = np.array([0.3, -1.2, 2.0])\n"
       ">>> np.allclose(rd.quat_to_rotvec(rd.rotvec_to_quat(rotvec)), rotvec)\n"
       "True\n"
       ">>> rd.quat_to_rotvec([0.0, 0.0, -1.0, 0.0], degrees=True).round(9) + 0.0\n"
       "array([  0.,   0., 180.])")
          .c_str());

  m.def(
      "rotvec_to_matrix",
      [](py::handle rotvec, py::handle degrees) {
        const AngleUnit unit = as_angle_unit(degrees);
        // rotvec_to_matrix(rotvec) = quat_to_matrix(rotvec_to_quat(rotvec)), its matrix written in place
        return map_unary<Written::checked_by_f>(rotvec, "rotvec", vector3, matrix3, "rotvec_to_matrix", [&](const double* in, double* out) {
          const Eigen::Vector3d r = unit.to_radians * read_vector(in);
          write_rotation_matrix(rotvec_to_quat(r), out);
          return finite_angle(r);
        });
      },
      "rotvec"_a, py::kw_only(), "degrees"_a = false,
      (std::string() +
       "Exponential map into rotation matrices (Rodrigues' formula).\n"
       "\n"
       "R = I + sin(theta) hat(u) + (1 - cos(theta)) hat(u)^2 for rotvec = theta u [rad]. SciPy:\n"
       "``Rotation.from_rotvec(rotvec).as_matrix()``.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "rotvec : array_like, shape (3,) or (n, 3)\n"
       "    Rotation vectors angle * axis [rad] (degrees if `degrees`), finite.\n" +
       degrees_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3, 3) or (n, 3, 3)\n"
       "    R, orthonormal with det +1.\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A non-finite entry, or a shape other than (3,) or (n, 3) (the message names `rotvec`).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "matrix_to_rotvec, rotvec_to_quat, hat\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> rd.rotvec_to_matrix([0.0, 0.0, 90.0], degrees=True).round(12)\n"
       "array([[ 0., -1.,  0.],\n"
       "       [ 1.,  0.,  0.],\n"
       "       [ 0.,  0.,  1.]])")
          .c_str());

  m.def(
      "matrix_to_rotvec",
      [](py::handle R, py::handle degrees) {
        const AngleUnit unit = as_angle_unit(degrees);
        const std::string name = "R";
        return map_unary(R, "R", matrix3, vector3, "matrix_to_rotvec", [&](const double* in, double* out) {
          write_vector(matrix_to_rotvec(projected_rotation_matrix(read_matrix(in), name)) * unit.from_radians, out);
        });
      },
      "R"_a, py::kw_only(), "degrees"_a = false,
      (std::string() +
       "Logarithm map of rotation matrices: rotation vectors angle * axis.\n"
       "\n"
       "The angle is in [0, pi]; accurate near 0 and near pi. SciPy:\n"
       "``Rotation.from_matrix(R).as_rotvec()``.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       R_param +
       degrees_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3,) or (n, 3)\n"
       "    Rotation vectors [rad] (degrees if `degrees`).\n"
       "\n"
       "Raises\n"
       "------\n" +
       R_raises +
       "\n"
       "See Also\n"
       "--------\n"
       "rotvec_to_matrix, quat_to_rotvec\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> rd.matrix_to_rotvec(rd.rot_y(0.5)).round(12)\n"
       "array([0. , 0.5, 0. ])\n"
       ">>> rd.matrix_to_rotvec(np.diag([-1.0, 1.0, -1.0]), degrees=True).round(9)\n"
       "array([  0., 180.,   0.])")
          .c_str());

  // ------------------------------------------------------------ axis-angle
  m.def(
      "axis_angle_to_quat",
      [](py::handle axis, py::handle angle, py::handle scalar_first_arg, py::handle degrees) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const AngleUnit unit = as_angle_unit(degrees);
        return map_binary(axis, "axis", vector3, angle, "angle", scalar, quaternion, "axis_angle_to_quat",
                          [&](const double* u, const double* a, double* out) {
                            py_io::write_quaternion(axis_angle_to_quat(direction(read_vector(u)), unit.to_radians * *a), out, scalar_first);
                          });
      },
      "axis"_a, "angle"_a, "scalar_first"_a = false, py::kw_only(), "degrees"_a = false,
      (std::string() +
       "Unit quaternion of the rotation by an angle about an axis (right-hand rule).\n"
       "\n"
       "q = (sin(angle/2) u, cos(angle/2)), u = axis / |axis|. SciPy:\n"
       "``Rotation.from_rotvec(angle * u).as_quat()``.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "axis : array_like, shape (3,) or (n, 3)\n"
       "    Rotation axes, any non-zero finite length (normalised, also beyond the range where |axis|^2\n"
       "    would overflow or underflow).\n"
       "angle : float or array_like, shape (n,)\n"
       "    Rotation angles [rad] (degrees if `degrees`); a single axis or angle is used with every item of\n"
       "    the other.\n" +
       scalar_first_param +
       degrees_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (4,) or (n, 4)\n"
       "    q, (x, y, z, w) or (w, x, y, z) if `scalar_first`.\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A zero or non-finite axis, a non-finite angle, a wrong shape, or stacks of different lengths\n"
       "    (the message names `axis` or `angle`).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "quat_to_axis_angle, rotvec_to_quat\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> rd.axis_angle_to_quat([0.0, 0.0, 2.0], 180.0, degrees=True).round(12)\n"
       "array([0., 0., 1., 0.])\n"
       ">>> rd.axis_angle_to_quat([1.0, 0.0, 0.0], [0.0, np.pi], scalar_first=True).round(12)\n"
       "array([[1., 0., 0., 0.],\n"
       "       [0., 1., 0., 0.]])")
          .c_str());

  m.def(
      "quat_to_axis_angle",
      [](py::handle q, py::handle scalar_first_arg, py::handle degrees) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const AngleUnit unit = as_angle_unit(degrees);
        const Stack in = py_io::as_stack(q, "q", quaternion);
        // unit axes and angles in [0, pi]: finite by construction
        Array axis = py_io::new_stack(in.n, in.stacked, vector3, "axis");
        Array angle = py_io::new_stack(in.n, in.stacked, scalar, "angle");
        const double* a = in.array.data();
        double* u = axis.mutable_data();
        double* t = angle.mutable_data();
        const std::string name = "q";
        for_each_item(in.n, in.stacked, [&](py::ssize_t i) {
          const AxisAngle r = quat_to_axis_angle(checked_unit_quaternion(py_io::read_quaternion(a + 4 * i, scalar_first), name));
          write_vector(r.axis, u + 3 * i);
          t[i] = r.angle * unit.from_radians;
        });
        return py::make_tuple(axis, scalar_or_array(angle, in.stacked));
      },
      "q"_a, "scalar_first"_a = false, py::kw_only(), "degrees"_a = false,
      (std::string() +
       "Unit axis and angle in [0, pi] of unit quaternions.\n"
       "\n"
       "The identity gives axis (1, 0, 0), angle 0. SciPy has no axis-angle pair: ``as_rotvec`` gives their\n"
       "product, and ``magnitude`` the angle.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       q_param +
       scalar_first_param +
       degrees_param +
       "\n"
       "Returns\n"
       "-------\n"
       "axis : ndarray, shape (3,) or (n, 3)\n"
       "    Unit rotation axes.\n"
       "angle : float or ndarray, shape (n,)\n"
       "    Angles [rad] in [0, pi] (degrees in [0, 180] if `degrees`).\n"
       "\n"
       "Raises\n"
       "------\n" +
       q_raises +
       "\n"
       "See Also\n"
       "--------\n"
       "axis_angle_to_quat, quat_to_rotvec, angular_distance\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> axis, angle = rd.quat_to_axis_angle([0.0, 0.0, -np.sin(0.25), np.cos(0.25)])\n"
       ">>> axis.round(12), round(angle, 12)\n"
       "(array([ 0.,  0., -1.]), 0.5)\n"
       ">>> rd.quat_to_axis_angle([0.0, 0.0, 0.0, 1.0])\n"
       "(array([1., 0., 0.]), 0.0)")
          .c_str());

  // ------------------------------------------------------------ Euler angles
  m.def(
      "euler_to_quat",
      [](py::handle seq, py::handle angles, py::handle scalar_first_arg, py::handle degrees) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const EulerSequence s = as_sequence(seq);
        const AngleUnit unit = as_angle_unit(degrees);
        return map_unary(angles, "angles", vector3, quaternion, "euler_to_quat", [&](const double* in, double* out) {
          py_io::write_quaternion(euler_to_quat(s, unit.to_radians * read_vector(in)), out, scalar_first);
        });
      },
      "seq"_a, "angles"_a, "scalar_first"_a = false, py::kw_only(), "degrees"_a = false,
      (std::string() +
       "Unit quaternion of Euler angles.\n"
       "\n"
       "SciPy: ``Rotation.from_euler(seq, angles).as_quat()``.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       euler_seq_param +
       "angles : array_like, shape (3,) or (n, 3)\n"
       "    Angles [rad] (degrees if `degrees`), in the order of `seq`.\n" +
       scalar_first_param +
       degrees_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (4,) or (n, 4)\n"
       "    q, (x, y, z, w) or (w, x, y, z) if `scalar_first`.\n"
       "\n"
       "Raises\n"
       "------\n" +
       euler_raises +
       "ValueError\n"
       "    A non-finite angle or a wrong shape (the message names `angles`).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "quat_to_euler, euler_to_matrix, davenport_to_quat\n"
       "\n"
       "Examples\n"
       "--------\n"
       "Yaw, pitch and roll (intrinsic z-y'-x''); a yaw alone is a turn about z:\n"
       "\n"
       ">>> rd.euler_to_quat(\"ZYX\", [90.0, 0.0, 0.0], degrees=True)\n"
       "array([0.        , 0.        , 0.70710678, 0.70710678])\n"
       ">>> q = rd.euler_to_quat(\"ZYX\", [0.1, 0.2, 0.3])\n"
       ">>> np.allclose(rd.quat_to_matrix(q), rd.rot_z(0.1) @ rd.rot_y(0.2) @ rd.rot_x(0.3))\n"
       "True")
          .c_str());

  m.def(
      "quat_to_euler",
      [](py::handle seq, py::handle q, py::handle scalar_first_arg, py::handle degrees) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const EulerSequence s = as_sequence(seq);
        const AngleUnit unit = as_angle_unit(degrees);
        const std::string name = "q";
        GimbalLock worst = GimbalLock::none;
        Array angles = with_layout(scalar_first, [&](auto first) {
          return map_unary<Written::finite_by_construction, py_io::EntryCheck::by_caller>(q, "q", quaternion, vector3, "quat_to_euler", [&](const double* in, double* out) {
            GimbalLock lock;
            write_vector(quat_to_euler(s, unit_quaternion_at<first>(in, name), &lock) * unit.from_radians, out);
            worst = std::max(worst, lock);
          });
        });
        warn_gimbal_lock(worst);
        return angles;
      },
      "seq"_a, "q"_a, "scalar_first"_a = false, py::kw_only(), "degrees"_a = false,
      (std::string() +
       "Euler angles of unit quaternions.\n"
       "\n"
       "By the atan2-only method of Bernardes & Viollet (\"Quaternion to Euler angles conversion: a direct,\n"
       "general and computationally efficient method\"), accurate at all angles. SciPy:\n"
       "``Rotation.from_quat(q).as_euler(seq)``.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       euler_seq_param +
       q_param +
       scalar_first_param +
       degrees_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3,) or (n, 3)\n"
       "    Angles [rad] (degrees if `degrees`) in the order of `seq`: first and third in [-pi, pi], second\n"
       "    in [0, pi] (proper Euler sequences) or [-pi/2, pi/2] (Tait-Bryan).\n"
       "\n"
       "Raises\n"
       "------\n" +
       euler_raises +
       q_raises +
       "\n" +
       gimbal_warns +
       "\n"
       "See Also\n"
       "--------\n"
       "euler_to_quat, matrix_to_euler, quat_to_davenport\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> q = rd.euler_to_quat(\"ZYX\", [0.1, 0.2, 0.3])\n"
       ">>> rd.quat_to_euler(\"ZYX\", q).round(12)\n"
       "array([0.1, 0.2, 0.3])\n"
       ">>> rd.quat_to_euler(\"zxz\", rd.rotvec_to_quat([90.0, 0.0, 0.0], degrees=True), degrees=True)\n"
       "array([ 0., 90.,  0.])")
          .c_str());

  m.def(
      "euler_to_matrix",
      [](py::handle seq, py::handle angles, py::handle degrees) {
        const EulerSequence s = as_sequence(seq);
        const AngleUnit unit = as_angle_unit(degrees);
        return map_unary(angles, "angles", vector3, matrix3, "euler_to_matrix",
                         [&](const double* in, double* out) { write_matrix(euler_to_matrix(s, unit.to_radians * read_vector(in)), out); });
      },
      "seq"_a, "angles"_a, py::kw_only(), "degrees"_a = false,
      (std::string() +
       "Rotation matrix of Euler angles.\n"
       "\n"
       "Extrinsic 'xyz' is R = R_z(a3) R_y(a2) R_x(a1), intrinsic 'XYZ' is R = R_x(a1) R_y(a2) R_z(a3).\n"
       "SciPy: ``Rotation.from_euler(seq, angles).as_matrix()``.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       euler_seq_param +
       "angles : array_like, shape (3,) or (n, 3)\n"
       "    Angles [rad] (degrees if `degrees`), in the order of `seq`.\n" +
       degrees_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3, 3) or (n, 3, 3)\n"
       "    R, orthonormal with det +1.\n"
       "\n"
       "Raises\n"
       "------\n" +
       euler_raises +
       "ValueError\n"
       "    A non-finite angle or a wrong shape (the message names `angles`).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "matrix_to_euler, euler_to_quat, rot_x\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> R = rd.euler_to_matrix(\"xyz\", [0.1, 0.2, 0.3])\n"
       ">>> np.allclose(R, rd.rot_z(0.3) @ rd.rot_y(0.2) @ rd.rot_x(0.1))\n"
       "True")
          .c_str());

  m.def(
      "matrix_to_euler",
      [](py::handle seq, py::handle R, py::handle degrees) {
        const EulerSequence s = as_sequence(seq);
        const AngleUnit unit = as_angle_unit(degrees);
        const std::string name = "R";
        GimbalLock worst = GimbalLock::none;
        Array angles = map_unary(R, "R", matrix3, vector3, "matrix_to_euler", [&](const double* in, double* out) {
          GimbalLock lock;
          write_vector(matrix_to_euler(s, projected_rotation_matrix(read_matrix(in), name), &lock) * unit.from_radians, out);
          worst = std::max(worst, lock);
        });
        warn_gimbal_lock(worst);
        return angles;
      },
      "seq"_a, "R"_a, py::kw_only(), "degrees"_a = false,
      (std::string() +
       "Euler angles of rotation matrices.\n"
       "\n"
       "Ranges and method as `quat_to_euler`. SciPy: ``Rotation.from_matrix(R).as_euler(seq)``.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       euler_seq_param +
       R_param +
       degrees_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3,) or (n, 3)\n"
       "    Angles [rad] (degrees if `degrees`) in the order of `seq`: first and third in [-pi, pi], second\n"
       "    in [0, pi] (proper Euler sequences) or [-pi/2, pi/2] (Tait-Bryan).\n"
       "\n"
       "Raises\n"
       "------\n" +
       euler_raises +
       R_raises +
       "\n" +
       gimbal_warns +
       "\n"
       "See Also\n"
       "--------\n"
       "euler_to_matrix, quat_to_euler\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> R = rd.euler_to_matrix(\"ZXZ\", [0.4, 1.0, -0.7])\n"
       ">>> rd.matrix_to_euler(\"ZXZ\", R).round(12)\n"
       "array([ 0.4,  1. , -0.7])")
          .c_str());

  // ------------------------------------------------------------ Davenport angles
  m.def(
      "davenport_to_quat",
      [](py::handle axes, py::handle order, py::handle angles, py::handle scalar_first_arg, py::handle degrees) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const DavenportAxes n(py_io::as_matrix3(axes, "axes"), as_intrinsic_order(order), "axes");
        const AngleUnit unit = as_angle_unit(degrees);
        return map_unary(angles, "angles", vector3, quaternion, "davenport_to_quat", [&](const double* in, double* out) {
          py_io::write_quaternion(davenport_to_quat(n, unit.to_radians * read_vector(in)), out, scalar_first);
        });
      },
      "axes"_a, "order"_a, "angles"_a, "scalar_first"_a = false, py::kw_only(), "degrees"_a = false,
      (std::string() +
       "Unit quaternion of Davenport angles (rotations about three arbitrary axes).\n"
       "\n"
       "SciPy: ``Rotation.from_davenport(axes, order, angles).as_quat()``.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       davenport_params +
       "angles : array_like, shape (3,) or (n, 3)\n"
       "    Angles [rad] (degrees if `degrees`), in the order of the axes.\n" +
       scalar_first_param +
       degrees_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (4,) or (n, 4)\n"
       "    q, (x, y, z, w) or (w, x, y, z) if `scalar_first`.\n"
       "\n"
       "Raises\n"
       "------\n" +
       davenport_raises +
       "ValueError\n"
       "    A non-finite angle or a wrong shape (the message names `angles`).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "quat_to_davenport, euler_to_quat\n"
       "\n"
       "Examples\n"
       "--------\n"
       "Coordinate axes give Euler angles:\n"
       "\n"
       ">>> q = rd.davenport_to_quat(np.eye(3), \"extrinsic\", [0.1, 0.2, 0.3])\n"
       ">>> np.allclose(q, rd.euler_to_quat(\"xyz\", [0.1, 0.2, 0.3]))\n"
       "True")
          .c_str());

  m.def(
      "quat_to_davenport",
      [](py::handle axes, py::handle order, py::handle q, py::handle scalar_first_arg, py::handle degrees) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const DavenportAxes n(py_io::as_matrix3(axes, "axes"), as_intrinsic_order(order), "axes");
        const AngleUnit unit = as_angle_unit(degrees);
        const std::string name = "q";
        GimbalLock worst = GimbalLock::none;
        Array angles = map_unary(q, "q", quaternion, vector3, "quat_to_davenport", [&](const double* in, double* out) {
          GimbalLock lock;
          write_vector(quat_to_davenport(n, checked_unit_quaternion(py_io::read_quaternion(in, scalar_first), name), &lock) * unit.from_radians, out);
          worst = std::max(worst, lock);
        });
        warn_gimbal_lock(worst);
        return angles;
      },
      "axes"_a, "order"_a, "q"_a, "scalar_first"_a = false, py::kw_only(), "degrees"_a = false,
      (std::string() +
       "Davenport angles of unit quaternions (rotations about three arbitrary axes).\n"
       "\n"
       "By the method of Bernardes & Viollet (\"Quaternion to Euler angles conversion: a direct, general and\n"
       "computationally efficient method\") for arbitrary axes. SciPy:\n"
       "``Rotation.from_quat(q).as_davenport(axes, order)``.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       davenport_params +
       q_param +
       scalar_first_param +
       degrees_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3,) or (n, 3)\n"
       "    Angles [rad] (degrees if `degrees`) in the order of the axes, as SciPy: first and third in\n"
       "    [-pi, pi], second in [-l, pi - l] if l >= 0, [-pi - l, -l] if l < 0, where\n"
       "    l = atan2(m3 . (m1 x n2), m3 . m1) with (m1, m3) = (n1, n3), or (n3, n1) if intrinsic (proper\n"
       "    Euler: l = 0, second in [0, pi]; Tait-Bryan: l = +-pi/2, second in [-pi/2, pi/2]).\n"
       "\n"
       "Raises\n"
       "------\n" +
       davenport_raises +
       q_raises +
       "\n" +
       gimbal_warns +
       "\n"
       "See Also\n"
       "--------\n"
       "davenport_to_quat, quat_to_euler\n"
       "\n"
       "Examples\n"
       "--------\n"
       "Angles about tilted axes come back:\n"
       "\n"
       ">>> axes = [[1.0, 0.0, 1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]]\n"
       ">>> q = rd.davenport_to_quat(axes, \"i\", [0.5, -0.3, 1.2])\n"
       ">>> rd.quat_to_davenport(axes, \"i\", q).round(12)\n"
       "array([ 0.5, -0.3,  1.2])")
          .c_str());

  // ------------------------------------------------------------ modified Rodrigues parameters
  m.def(
      "quat_to_mrp",
      [](py::handle q, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const std::string name = "q";
        return with_layout(scalar_first, [&](auto first) {
          return map_unit_quaternions<first, 3>(
              q, name, vector3, "quat_to_mrp",
              [](const auto& q_block, auto& p, auto& ok) RIGIDDYN_INLINE_KERNEL {
                // p = v / (w + sign(w)) as quat_to_mrp (mrp.hpp); w = 0 (a half turn, whose sign its tie rule
                // picks) left to it
                ok &= q_block.w != 0.0;
                const auto denominator = q_block.w + (q_block.w > 0.0 ? 1.0 : -1.0);
                p.e[0] = q_block.x / denominator, p.e[1] = q_block.y / denominator, p.e[2] = q_block.z / denominator;
              },
              [](const Eigen::Quaterniond& q_i, double* out) { write_vector(quat_to_mrp(q_i), out); });
        });
      },
      "q"_a, "scalar_first"_a = false,
      (std::string() +
       "Modified Rodrigues parameters of unit quaternions.\n"
       "\n"
       "p = axis tan(angle/4) = (x, y, z) / (1 + w) for the representative with w >= 0, the set with\n"
       "|p| <= 1 (angle in [0, pi]); dimensionless (Shuster, \"A survey of attitude representations\"). SciPy:\n"
       "``Rotation.from_quat(q).as_mrp()``.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       q_param +
       scalar_first_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3,) or (n, 3)\n"
       "    p, |p| <= 1.\n"
       "\n"
       "Raises\n"
       "------\n" +
       q_raises +
       "\n"
       "See Also\n"
       "--------\n"
       "mrp_to_quat\n"
       "\n"
       "Examples\n"
       "--------\n"
       "A half turn about z has |p| = tan(pi/4) = 1, whatever the quaternion's sign:\n"
       "\n"
       ">>> rd.quat_to_mrp([0.0, 0.0, -1.0, 0.0]).round(12) + 0.0\n"
       "array([0., 0., 1.])")
          .c_str());

  m.def(
      "mrp_to_quat",
      [](py::handle mrp, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        return with_layout(scalar_first, [&](auto first) {
          const Stack in = py_io::as_stack(mrp, "mrp", vector3, py_io::EntryCheck::by_caller);
          Array out = py_io::new_stack(in.n, in.stacked, quaternion, "mrp_to_quat");
          const double* p = in.array.data();
          double* o = out.mutable_data();
          map_blocks<3, 4>(
              p, o, in.n, in.stacked,
              [first](const auto& p_block, auto& q, auto& ok) RIGIDDYN_INLINE_KERNEL {
                // q = (2 p, 1 - |p|²) / (1 + |p|²) for |p| <= 1, as mrp_to_quat (mrp.hpp), which takes a block with
                // some |p| > 1 or a non-finite p (and throws for it): finite by construction
                const auto &x = p_block.e[0], &y = p_block.e[1], &z = p_block.e[2];
                const auto n2 = (x * x + y * y) + z * z;
                ok = n2 <= 1.0;
                const auto s = 2.0 / (1.0 + n2);
                set_quaternions<first>(s * x, s * y, s * z, (1.0 - n2) / (1.0 + n2), q);
              },
              [&](py::ssize_t i) RIGIDDYN_INLINE_KERNEL { write_quaternion_at<first>(mrp_to_quat(read_vector(p + 3 * i)), o + 4 * i); });
          return out;
        });
      },
      "mrp"_a, "scalar_first"_a = false,
      (std::string() +
       "Unit quaternion of modified Rodrigues parameters.\n"
       "\n"
       "q = (2 p, 1 - |p|^2) / (1 + |p|^2): either shadow set is accepted (p and -p/|p|^2 are the same\n"
       "rotation; w < 0 when |p| > 1). SciPy: ``Rotation.from_mrp(p).as_quat()``.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "mrp : array_like, shape (3,) or (n, 3)\n"
       "    Modified Rodrigues parameters p, any finite values (dimensionless).\n" +
       scalar_first_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (4,) or (n, 4)\n"
       "    q, (x, y, z, w) or (w, x, y, z) if `scalar_first`.\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A non-finite entry or a wrong shape (the message names `mrp`).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "quat_to_mrp\n"
       "\n"
       "Examples\n"
       "--------\n"
       "A shadow set gives the same rotation:\n"
       "\n"
       ">>> p = np.array([0.2, -0.4, 0.1])\n"
       ">>> rd.angular_distance(rd.mrp_to_quat(p), rd.mrp_to_quat(-p / (p @ p))) < 1e-12\n"
       "True")
          .c_str());

  // ------------------------------------------------------------ elementary rotations
  const auto bind_elementary = [&m](const char* name, Eigen::Matrix3d (*rot)(double), const char* doc) {
    m.def(
        name,
        [rot, name](py::handle angle, py::handle degrees) {
          const AngleUnit unit = as_angle_unit(degrees);
          return map_unary(angle, "angle", scalar, matrix3, name, [&](const double* in, double* out) { write_matrix(rot(unit.to_radians * *in), out); });
        },
        "angle"_a, py::kw_only(), "degrees"_a = false, doc);
  };
  const std::string rot_x_doc =
      std::string() +
       "Elementary rotation matrix about x (active).\n"
       "\n"
       "R_x(a) = [[1, 0, 0], [0, c, -s], [0, s, c]] with c = cos a, s = sin a. SciPy:\n"
       "``Rotation.from_euler('x', angle).as_matrix()``.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "angle : float or array_like, shape (n,)\n"
       "    Angles [rad] (degrees if `degrees`).\n" +
       degrees_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3, 3) or (n, 3, 3)\n"
       "    R_x(angle).\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A non-finite angle or a shape other than () or (n,) (the message names `angle`).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "rot_y, rot_z, euler_to_matrix\n"
       "\n"
       "Examples\n"
       "--------\n"
       "A quarter turn about x takes y to z:\n"
       "\n"
       ">>> rd.rot_x(90.0, degrees=True).round(12) @ [0.0, 1.0, 0.0]\n"
       "array([0., 0., 1.])";
  bind_elementary("rot_x", &rot_x, rot_x_doc.c_str());
  const std::string rot_y_doc =
      std::string() +
       "Elementary rotation matrix about y (active).\n"
       "\n"
       "R_y(a) = [[c, 0, s], [0, 1, 0], [-s, 0, c]] with c = cos a, s = sin a. SciPy:\n"
       "``Rotation.from_euler('y', angle).as_matrix()``.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "angle : float or array_like, shape (n,)\n"
       "    Angles [rad] (degrees if `degrees`).\n" +
       degrees_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3, 3) or (n, 3, 3)\n"
       "    R_y(angle).\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A non-finite angle or a shape other than () or (n,) (the message names `angle`).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "rot_x, rot_z, euler_to_matrix\n"
       "\n"
       "Examples\n"
       "--------\n"
       "A quarter turn about y takes z to x:\n"
       "\n"
       ">>> rd.rot_y(np.pi / 2).round(12) @ [0.0, 0.0, 1.0]\n"
       "array([1., 0., 0.])";
  bind_elementary("rot_y", &rot_y, rot_y_doc.c_str());
  const std::string rot_z_doc =
      std::string() +
       "Elementary rotation matrix about z (active).\n"
       "\n"
       "R_z(a) = [[c, -s, 0], [s, c, 0], [0, 0, 1]] with c = cos a, s = sin a. SciPy:\n"
       "``Rotation.from_euler('z', angle).as_matrix()``.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "angle : float or array_like, shape (n,)\n"
       "    Angles [rad] (degrees if `degrees`).\n" +
       degrees_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3, 3) or (n, 3, 3)\n"
       "    R_z(angle).\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A non-finite angle or a shape other than () or (n,) (the message names `angle`).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "rot_x, rot_y, euler_to_matrix\n"
       "\n"
       "Examples\n"
       "--------\n"
       "A stack of angles gives a stack of matrices:\n"
       "\n"
       ">>> rd.rot_z([0.0, np.pi / 2]).round(12) @ [1.0, 0.0, 0.0]\n"
       "array([[1., 0., 0.],\n"
       "       [0., 1., 0.]])";
  bind_elementary("rot_z", &rot_z, rot_z_doc.c_str());

  // ------------------------------------------------------------ quaternion algebra
  m.def(
      "quat_multiply",
      [](py::handle q1, py::handle q2, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const std::string name1 = "q1", name2 = "q2";
        return with_layout(scalar_first, [&](auto first) {
          return map_binary<Written::finite_by_construction>(
              q1, "q1", quaternion, q2, "q2", quaternion, quaternion, "quat_multiply", [&](const double* a, const double* b, double* out) {
                write_quaternion_at<first>(quat_multiply(unit_quaternion_at<first>(a, name1), unit_quaternion_at<first>(b, name2)), out);
              });
        });
      },
      "q1"_a, "q2"_a, "scalar_first"_a = false,
      (std::string() +
       "Hamilton product q1 ⊗ q2 of unit quaternions.\n"
       "\n"
       "R(q1 ⊗ q2) = R(q1) R(q2): q2 is applied first, so q_WC = q_WB ⊗ q_BC. SciPy: ``r1 * r2``.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "q1, q2 : array_like, shape (4,) or (n, 4)\n"
       "    Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then\n"
       "    normalised). A single one is used with every item of the other.\n" +
       scalar_first_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (4,) or (n, 4)\n"
       "    q1 ⊗ q2, in the order of the input.\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names it\n"
       "    and, in a stack, the item), a wrong shape, or stacks of different lengths.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "quat_inverse, quat_rotate\n"
       "\n"
       "Examples\n"
       "--------\n"
       "A quarter turn about z applied twice is a half turn:\n"
       "\n"
       ">>> q = rd.rotvec_to_quat([0.0, 0.0, np.pi / 2])\n"
       ">>> rd.quat_multiply(q, q).round(12)\n"
       "array([0., 0., 1., 0.])")
          .c_str());

  m.def(
      "quat_inverse",
      [](py::handle q, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const std::string name = "q";
        return with_layout(scalar_first, [&](auto first) {
          return map_unit_quaternions<first, 4>(
              q, name, quaternion, "quat_inverse",
              [first](const auto& q_block, auto& q_inverse, auto&) RIGIDDYN_INLINE_KERNEL {
                set_quaternions<first>(-q_block.x, -q_block.y, -q_block.z, q_block.w, q_inverse);
              },
              [first](const Eigen::Quaterniond& q_i, double* out) { write_quaternion_at<first>(quat_inverse(q_i), out); });
        });
      },
      "q"_a, "scalar_first"_a = false,
      (std::string() +
       "Inverse (conjugate) of unit quaternions.\n"
       "\n"
       "q^-1 = (-x, -y, -z, w): q_BW from q_WB. SciPy: ``Rotation.from_quat(q).inv()``.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       q_param +
       scalar_first_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (4,) or (n, 4)\n"
       "    q^-1, in the order of the input.\n"
       "\n"
       "Raises\n"
       "------\n" +
       q_raises +
       "\n"
       "See Also\n"
       "--------\n"
       "quat_multiply\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> q = rd.rotvec_to_quat([0.3, -0.2, 0.9])\n"
       ">>> rd.quat_multiply(q, rd.quat_inverse(q)).round(12)\n"
       "array([0., 0., 0., 1.])")
          .c_str());

  m.def(
      "quat_normalize",
      [](py::handle q, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const std::string name = "q";
        return map_unary(q, "q", quaternion, quaternion, "quat_normalize", [&](const double* in, double* out) {
          py_io::write_quaternion(quat_normalize(py_io::read_quaternion(in, scalar_first), name), out, scalar_first);
        });
      },
      "q"_a, "scalar_first"_a = false,
      (std::string() +
       "Quaternions scaled to unit norm, q / |q|.\n"
       "\n"
       "For finite non-zero quaternions of any norm; the sign is unchanged (no canonical sign). SciPy\n"
       "normalises in ``Rotation.from_quat``.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "q : array_like, shape (4,) or (n, 4)\n"
       "    Finite non-zero quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`.\n" +
       scalar_first_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (4,) or (n, 4)\n"
       "    q / |q|, in the order of the input.\n"
       "\n"
       "Raises\n"
       "------\n"
       "ValueError\n"
       "    q = 0, a non-finite entry or a wrong shape (the message names `q` and, in a stack, the item).\n"
       "\n"
       "See Also\n"
       "--------\n"
       "quat_canonical\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> rd.quat_normalize([0.0, 0.0, -3.0, 4.0])\n"
       "array([ 0. ,  0. , -0.6,  0.8])")
          .c_str());

  m.def(
      "quat_rotate",
      [](py::handle q, py::handle v, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const std::string name = "q";
        return with_layout(scalar_first, [&](auto first) {
          return map_binary(q, "q", quaternion, v, "v", vector3, vector3, "quat_rotate", [&](const double* a, const double* b, double* out) {
            write_vector(quat_rotate(unit_quaternion_at<first>(a, name), read_vector(b)), out);
          });
        });
      },
      "q"_a, "v"_a, "scalar_first"_a = false,
      (std::string() +
       "Vectors rotated actively by unit quaternions, R(q) v.\n"
       "\n"
       "With q = q_WB, v_W = R_WB v_B. SciPy: ``Rotation.from_quat(q).apply(v)``.\n"
       "\n"
       "Parameters\n"
       "----------\n" +
       q_param +
       "v : array_like, shape (3,) or (n, 3)\n"
       "    Vectors (any unit); a single q or v is used with every item of the other.\n" +
       scalar_first_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3,) or (n, 3)\n"
       "    R(q) v, in the unit of v.\n"
       "\n"
       "Raises\n"
       "------\n" +
       q_raises +
       "ValueError\n"
       "    `v` of a wrong shape or non-finite, or stacks of different lengths.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "quat_to_matrix\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> q = rd.rotvec_to_quat([0.0, 0.0, np.pi / 2])\n"
       ">>> rd.quat_rotate(q, [[1.0, 0.0, 0.0], [0.0, 0.0, 2.0]]).round(12)\n"
       "array([[0., 1., 0.],\n"
       "       [0., 0., 2.]])")
          .c_str());

  m.def(
      "quat_integrate",
      [](py::handle q, py::handle w, py::handle dt, py::handle frame, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const double step = py_io::as_scalar(dt, "dt");
        const Frame f = as_frame(frame);
        const std::string name = "q";
        return map_binary(q, "q", quaternion, w, "w", vector3, quaternion, "quat_integrate", [&](const double* a, const double* b, double* out) {
          py_io::write_quaternion(
              quat_integrate(checked_unit_quaternion(py_io::read_quaternion(a, scalar_first), name), read_vector(b), step, f),
              out, scalar_first);
        });
      },
      "q"_a, "w"_a, "dt"_a, "frame"_a = "body", "scalar_first"_a = false,
      (std::string() +
       "Exact attitude update for an angular velocity constant over a step.\n"
       "\n"
       "frame='body': q(t + dt) = q ⊗ exp(w_B dt/2), w_B expressed in B; frame='world':\n"
       "q(t + dt) = exp(w_W dt/2) ⊗ q, w_W expressed in W; exp of a pure vector u is (sin|u| u/|u|, cos|u|)\n"
       "(Solà, \"Quaternion kinematics for the error-state Kalman filter\"). With SciPy, frame='body' is\n"
       "``r * Rotation.from_rotvec(w * dt)``.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "q : array_like, shape (4,) or (n, 4)\n"
       "    Attitudes q_WB, unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within\n"
       "    1e-6 of 1 (then normalised).\n"
       "w : array_like, shape (3,) or (n, 3)\n"
       "    Angular velocity [rad/s] of B in W, expressed in B (frame='body') or in W (frame='world'); a\n"
       "    single q or w is used with every item of the other.\n"
       "dt : float\n"
       "    Time step [s], finite.\n"
       "frame : {'body', 'world'}, default 'body'\n"
       "    The frame `w` is expressed in.\n" +
       scalar_first_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (4,) or (n, 4)\n"
       "    q(t + dt), normalised, in the order of the input.\n"
       "\n"
       "Raises\n"
       "------\n" +
       q_raises +
       "ValueError\n"
       "    `w` of a wrong shape or non-finite, a non-finite `dt`, stacks of different lengths, or `frame`\n"
       "    not 'body' or 'world'.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "quat_rate, rotvec_to_quat\n"
       "\n"
       "Examples\n"
       "--------\n"
       "Turning at pi/2 rad/s about z for 1 s is a quarter turn:\n"
       "\n"
       ">>> q = rd.quat_integrate([0.0, 0.0, 0.0, 1.0], [0.0, 0.0, np.pi / 2], 1.0)\n"
       ">>> rd.quat_to_rotvec(q).round(12)\n"
       "array([0.        , 0.        , 1.57079633])")
          .c_str());

  m.def(
      "quat_rate",
      [](py::handle q, py::handle w, py::handle frame, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const Frame f = as_frame(frame);
        const std::string name = "q";
        return map_binary(q, "q", quaternion, w, "w", vector3, quaternion, "quat_rate", [&](const double* a, const double* b, double* out) {
          py_io::write_quaternion(quat_rate(checked_unit_quaternion(py_io::read_quaternion(a, scalar_first), name), read_vector(b), f),
                                  out, scalar_first);
        });
      },
      "q"_a, "w"_a, "frame"_a = "body", "scalar_first"_a = false,
      (std::string() +
       "Quaternion rate dq/dt of an attitude turning with an angular velocity.\n"
       "\n"
       "frame='body': dq/dt = 1/2 q ⊗ (w_B, 0), w_B expressed in B; frame='world': dq/dt = 1/2 (w_W, 0) ⊗ q,\n"
       "w_W expressed in W (Solà, \"Quaternion kinematics for the error-state Kalman filter\"). The result is\n"
       "orthogonal to q, with |dq/dt| = |w|/2. SciPy has no equivalent.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "q : array_like, shape (4,) or (n, 4)\n"
       "    Attitudes q_WB, unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within\n"
       "    1e-6 of 1 (then normalised).\n"
       "w : array_like, shape (3,) or (n, 3)\n"
       "    Angular velocity [rad/s] of B in W, expressed in B (frame='body') or in W (frame='world'); a\n"
       "    single q or w is used with every item of the other.\n"
       "frame : {'body', 'world'}, default 'body'\n"
       "    The frame `w` is expressed in.\n" +
       scalar_first_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (4,) or (n, 4)\n"
       "    dq/dt [1/s], in the order of q.\n"
       "\n"
       "Raises\n"
       "------\n" +
       q_raises +
       "ValueError\n"
       "    `w` of a wrong shape or non-finite, stacks of different lengths, or `frame` not 'body' or\n"
       "    'world'.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "angular_velocity_from_quat_rate, quat_integrate\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> q = rd.rotvec_to_quat([0.4, 0.0, 0.0])\n"
       ">>> dq = rd.quat_rate(q, [0.0, 2.0, 0.0])\n"
       ">>> f\"{q @ dq:.12f}\", f\"{np.linalg.norm(dq):.12f}\"\n"
       "('0.000000000000', '1.000000000000')")
          .c_str());

  m.def(
      "angular_velocity_from_quat_rate",
      [](py::handle q, py::handle dq_dt, py::handle frame, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const Frame f = as_frame(frame);
        const std::string name = "q";
        return map_binary(q, "q", quaternion, dq_dt, "dq_dt", quaternion, vector3, "angular_velocity_from_quat_rate",
                          [&](const double* a, const double* b, double* out) {
                            write_vector(angular_velocity_from_quat_rate(
                                             checked_unit_quaternion(py_io::read_quaternion(a, scalar_first), name),
                                             py_io::read_quaternion(b, scalar_first), f),
                                         out);
                          });
      },
      "q"_a, "dq_dt"_a, "frame"_a = "body", "scalar_first"_a = false,
      (std::string() +
       "Angular velocity of an attitude changing at a quaternion rate (the inverse of `quat_rate`).\n"
       "\n"
       "frame='body': w_B = 2 vec(q* ⊗ dq/dt); frame='world': w_W = 2 vec(dq/dt ⊗ q*). The part of dq_dt\n"
       "along q (which would change |q|, not the rotation) is ignored. SciPy has no equivalent.\n"
       "\n"
       "Parameters\n"
       "----------\n"
       "q : array_like, shape (4,) or (n, 4)\n"
       "    Attitudes q_WB, unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within\n"
       "    1e-6 of 1 (then normalised).\n"
       "dq_dt : array_like, shape (4,) or (n, 4)\n"
       "    Quaternion rates [1/s], any finite values, in the order of q; a single q or dq_dt is used with\n"
       "    every item of the other.\n"
       "frame : {'body', 'world'}, default 'body'\n"
       "    The frame the result is expressed in.\n" +
       scalar_first_param +
       "\n"
       "Returns\n"
       "-------\n"
       "ndarray, shape (3,) or (n, 3)\n"
       "    Angular velocity [rad/s] of B in W, expressed in B (frame='body') or in W (frame='world').\n"
       "\n"
       "Raises\n"
       "------\n" +
       q_raises +
       "ValueError\n"
       "    `dq_dt` of a wrong shape or non-finite, stacks of different lengths, or `frame` not 'body' or\n"
       "    'world'.\n"
       "\n"
       "See Also\n"
       "--------\n"
       "quat_rate\n"
       "\n"
       "Examples\n"
       "--------\n"
       ">>> q = rd.rotvec_to_quat([0.4, -1.0, 0.3])\n"
       ">>> dq = rd.quat_rate(q, [1.0, 2.0, 3.0], frame=\"world\")\n"
       ">>> rd.angular_velocity_from_quat_rate(q, dq, frame=\"world\").round(12)\n"
       "array([1., 2., 3.])")
          .c_str());

  // ------------------------------------------------------------ skew matrices
  m.def(
      "hat",
      [](py::handle v) {
        return map_unary(v, "v", vector3, matrix3, "hat", [&](const double* in, double* out) { write_matrix(hat(read_vector(in)), out); });
      },
      "v"_a,
      "Skew-symmetric cross-product matrices.\n"
      "\n"
      "S = hat(v) = [[0, -v3, v2], [v3, 0, -v1], [-v2, v1, 0]], so that S x = v × x. SciPy has no\n"
      "equivalent.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "v : array_like, shape (3,) or (n, 3)\n"
      "    Vectors (any unit), finite.\n"
      "\n"
      "Returns\n"
      "-------\n"
      "ndarray, shape (3, 3) or (n, 3, 3)\n"
      "    hat(v), in the unit of v.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    A non-finite entry or a wrong shape (the message names `v`).\n"
      "\n"
      "See Also\n"
      "--------\n"
      "vee\n"
      "\n"
      "Examples\n"
      "--------\n"
      ">>> rd.hat([1.0, 2.0, 3.0]) @ [4.0, 5.0, 6.0]\n"
      "array([-3.,  6., -3.])\n"
      ">>> np.cross([1.0, 2.0, 3.0], [4.0, 5.0, 6.0])\n"
      "array([-3.,  6., -3.])");

  m.def(
      "vee",
      [](py::handle S) {
        return map_unary(S, "S", matrix3, vector3, "vee", [&](const double* in, double* out) { write_vector(vee(read_matrix(in)), out); });
      },
      "S"_a,
      "Vectors of skew-symmetric matrices, the inverse of `hat`.\n"
      "\n"
      "v with hat(v) = (S - S^T)/2: a symmetric part of S is ignored. SciPy has no equivalent.\n"
      "\n"
      "Parameters\n"
      "----------\n"
      "S : array_like, shape (3, 3) or (n, 3, 3)\n"
      "    Matrices, finite.\n"
      "\n"
      "Returns\n"
      "-------\n"
      "ndarray, shape (3,) or (n, 3)\n"
      "    v, in the unit of S.\n"
      "\n"
      "Raises\n"
      "------\n"
      "ValueError\n"
      "    A non-finite entry or a wrong shape (the message names `S`).\n"
      "\n"
      "See Also\n"
      "--------\n"
      "hat\n"
      "\n"
      "Examples\n"
      "--------\n"
      ">>> rd.vee(rd.hat([1.0, 2.0, 3.0]))\n"
      "array([1., 2., 3.])\n"
      ">>> rd.vee(rd.hat([1.0, 2.0, 3.0]) + np.ones((3, 3)))\n"
      "array([1., 2., 3.])");
}

}  // namespace rigiddyn::bindings
