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
#include <limits>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "common_args.hpp"
#include "for_each_item.hpp"
#include "numpy_io.hpp"
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

py::ssize_t item_size(const Shape& shape) {
  py::ssize_t size = 1;
  for (py::ssize_t extent : shape) size *= extent;
  return size;
}

// item readers and writers (numpy items are C-contiguous: matrices row-major)
Eigen::Vector3d read_vector(const double* p) { return Eigen::Vector3d(p[0], p[1], p[2]); }
Eigen::Matrix3d read_matrix(const double* p) { return Eigen::Map<const RowMajor3>(p); }
void write_vector(const Eigen::Vector3d& v, double* out) { Eigen::Map<Eigen::Vector3d>{out} = v; }
void write_matrix(const Eigen::Matrix3d& R, double* out) { Eigen::Map<RowMajor3>{out} = R; }

// finite &= every entry of the item is finite (branch-free, on the item just written: no second pass)
inline void and_finite(bool& finite, const double* item, py::ssize_t size) {
  double zero = 0.0;
  for (py::ssize_t k = 0; k < size; ++k) zero += item[k] - item[k];  // NaN unless every entry is finite
  finite &= zero == 0.0;
}

// out[i] = f(in[i]) over a stack: items of shape `in_shape` -> items of shape `out_shape`.
// f(const double* in_item, double* out_item). A non-finite result warns naming `quantity`.
template <typename F>
Array map_unary(py::handle x, const char* name, const Shape& in_shape, const Shape& out_shape, const char* quantity, F f) {
  const Stack in = py_io::as_stack(x, name, in_shape);
  Array out = py_io::new_stack(in.n, in.stacked, out_shape, quantity);
  const double* a = in.array.data();
  double* o = out.mutable_data();
  const py::ssize_t a_size = item_size(in_shape), o_size = item_size(out_shape);
  bool finite = true;
  for_each_item(in.n, in.stacked, [&](py::ssize_t i) {
    f(a + i * a_size, o + i * o_size);
    and_finite(finite, o + i * o_size, o_size);
  });
  if (!finite) py_io::finite_result(out, quantity);
  return out;
}

// out[i] = f(x[i], y[i]) over two stacks; a single item is used with every item of the other.
// ValueError naming y when both are stacked with different lengths; a non-finite result warns.
template <typename F>
Array map_binary(py::handle x, const char* x_name, const Shape& x_shape, py::handle y, const char* y_name,
                 const Shape& y_shape, const Shape& out_shape, const char* quantity, F f) {
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
    and_finite(finite, o + i * o_size, o_size);
  });
  if (!finite) py_io::finite_result(out, quantity);
  return out;
}

// The Euler axis sequence argument: TypeError unless a str, ValueError unless a valid sequence.
EulerSequence as_sequence(py::handle seq) {
  if (!py::isinstance<py::str>(seq)) py_io::throw_type_error("seq", "a str such as 'xyz' or 'ZYX'", seq);
  return EulerSequence(seq.cast<std::string>(), "seq");
}

bool as_scalar_first(py::handle scalar_first) { return py_io::as_bool(scalar_first, "scalar_first"); }

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

}  // namespace

void bind_so3(py::module_& m) {
  // ------------------------------------------------------------ matrices
  m.def(
      "quat_to_matrix",
      [](py::handle q, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const std::string name = "q";
        return map_unary(q, "q", quaternion, matrix3, "quat_to_matrix", [&](const double* in, double* out) {
          write_matrix(quat_to_matrix(checked_unit_quaternion(py_io::read_quaternion(in, scalar_first), name)), out);
        });
      },
      "q"_a, "scalar_first"_a = false,
      "Rotation matrix R(q) of unit quaternions.\n\n"
      "q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first; unit norm within 1e-6.\n"
      "Returns R: (3, 3) or (n, 3, 3), active (R v rotates v; q_WB gives R_WB).");

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
      "Unit quaternion of rotation matrices, canonical sign w >= 0 (Shepperd's method, accurate at all angles).\n\n"
      "R: (3, 3) or (n, 3, 3), a rotation matrix up to rounding (det > 0, singular values within 0.05 of 1;\n"
      "projected onto the nearest rotation as SciPy's Rotation.from_matrix).\n"
      "Returns q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first.");

  // ------------------------------------------------------------ exp / log
  m.def(
      "rotvec_to_quat",
      [](py::handle rotvec, py::handle scalar_first_arg, py::handle degrees) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const AngleUnit unit = as_angle_unit(degrees);
        return map_unary(rotvec, "rotvec", vector3, quaternion, "rotvec_to_quat", [&](const double* in, double* out) {
          py_io::write_quaternion(rotvec_to_quat(unit.to_radians * read_vector(in)), out, scalar_first);
        });
      },
      "rotvec"_a, "scalar_first"_a = false, py::kw_only(), "degrees"_a = false,
      "Exponential map: unit quaternion of rotation vectors rotvec = angle * axis [rad] (any angle; exact near 0).\n\n"
      "rotvec: (3,) or (n, 3), in degrees if degrees=True. Returns q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first;\n"
      "w < 0 when the angle exceeds pi (no sign flip).");

  m.def(
      "quat_to_rotvec",
      [](py::handle q, py::handle scalar_first_arg, py::handle degrees) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const AngleUnit unit = as_angle_unit(degrees);
        const std::string name = "q";
        return map_unary(q, "q", quaternion, vector3, "quat_to_rotvec", [&](const double* in, double* out) {
          write_vector(quat_to_rotvec(checked_unit_quaternion(py_io::read_quaternion(in, scalar_first), name)) * unit.from_radians, out);
        });
      },
      "q"_a, "scalar_first"_a = false, py::kw_only(), "degrees"_a = false,
      "Logarithm map: rotation vector angle * axis [rad] of unit quaternions, angle in [0, pi].\n\n"
      "q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first. Returns (3,) or (n, 3),\n"
      "in degrees (angle in [0, 180]) if degrees=True.\n"
      "Accurate near angle 0 and near pi (atan2 form).");

  m.def(
      "rotvec_to_matrix",
      [](py::handle rotvec, py::handle degrees) {
        const AngleUnit unit = as_angle_unit(degrees);
        return map_unary(rotvec, "rotvec", vector3, matrix3, "rotvec_to_matrix",
                         [&](const double* in, double* out) { write_matrix(rotvec_to_matrix(unit.to_radians * read_vector(in)), out); });
      },
      "rotvec"_a, py::kw_only(), "degrees"_a = false,
      "Exponential map into rotation matrices (Rodrigues): rotvec = angle * axis [rad], (3,) or (n, 3)\n"
      "(in degrees if degrees=True).\n"
      "Returns R: (3, 3) or (n, 3, 3).");

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
      "Logarithm map of rotation matrices: rotation vector angle * axis [rad], angle in [0, pi].\n\n"
      "R: (3, 3) or (n, 3, 3), a rotation matrix up to rounding (det > 0, singular values within 0.05 of 1;\n"
      "projected onto the nearest rotation as SciPy's Rotation.from_matrix).\n"
      "Returns (3,) or (n, 3), in degrees if degrees=True.\n"
      "Accurate near 0 and pi.");

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
      "Unit quaternion of the rotation by angle [rad] about axis (right-hand rule).\n\n"
      "axis: (3,) or (n, 3), any non-zero length (normalised); angle: float or (n,), in degrees if degrees=True.\n"
      "Returns q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first.");

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
      "Axis (unit) and angle [rad] in [0, pi] (degrees in [0, 180] if degrees=True) of unit quaternions;\n"
      "the identity gives axis (1, 0, 0), angle 0.\n\n"
      "q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first.\n"
      "Returns (axis, angle): ((3,), float) or ((n, 3), (n,)).");

  // ------------------------------------------------------------ Euler angles
  const char* euler_note =
      "seq: 3 letters as SciPy, lowercase 'xyz' = extrinsic (fixed axes), uppercase 'XYZ' = intrinsic\n"
      "(moving axes); the 12 sequences xyz xzy yxz yzx zxy zyx xyx xzx yxy yzy zxz zyz in either case.\n";
  const std::string gimbal_note =
      "Gimbal lock: a UserWarning 'Gimbal lock detected. ...' (once per call) wherever SciPy warns: the\n"
      "middle angle of some item within 1e-7 rad of its singularity (Euler angles: 0 or pi in proper\n"
      "sequences, -pi/2 or pi/2 in Tait-Bryan ones; Davenport angles: the ends of its range). Within\n"
      "round-off of it (1e-13 rad) only the sum or difference of the first and third angles is defined:\n"
      "the third is set to 0 and the first carries it, with SciPy's message. Between 1e-13 and 1e-7 rad\n"
      "the angles are the exact ones and the message says so (SciPy sets the third to 0 there too, which\n"
      "moves the rotation by up to 2e-7 rad): the angles reproduce the rotation to round-off everywhere.\n";
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
      (std::string("Unit quaternion of Euler angles.\n\n") + euler_note +
       "angles: (3,) or (n, 3) [rad] (degrees if degrees=True), in the order of seq.\n"
       "Returns q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first.")
          .c_str());

  m.def(
      "quat_to_euler",
      [](py::handle seq, py::handle q, py::handle scalar_first_arg, py::handle degrees) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const EulerSequence s = as_sequence(seq);
        const AngleUnit unit = as_angle_unit(degrees);
        const std::string name = "q";
        GimbalLock worst = GimbalLock::none;
        Array angles = map_unary(q, "q", quaternion, vector3, "quat_to_euler", [&](const double* in, double* out) {
          GimbalLock lock;
          write_vector(quat_to_euler(s, checked_unit_quaternion(py_io::read_quaternion(in, scalar_first), name), &lock) * unit.from_radians, out);
          worst = std::max(worst, lock);
        });
        warn_gimbal_lock(worst);
        return angles;
      },
      "seq"_a, "q"_a, "scalar_first"_a = false, py::kw_only(), "degrees"_a = false,
      (std::string("Euler angles [rad] of unit quaternions (Bernardes & Viollet 2022).\n\n") + euler_note +
       "q: (4,) or (n, 4). Returns (3,) or (n, 3) [rad] (degrees if degrees=True): first and third in\n"
       "[-pi, pi], second in [0, pi] (proper) or [-pi/2, pi/2] (Tait-Bryan).\n" + gimbal_note)
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
      (std::string("Rotation matrix of Euler angles.\n\n") + euler_note +
       "angles: (3,) or (n, 3) [rad] (degrees if degrees=True). Returns R: (3, 3) or (n, 3, 3).")
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
      (std::string("Euler angles [rad] of rotation matrices (ranges as quat_to_euler; degrees if degrees=True).\n\n") +
       euler_note + "R: (3, 3) or (n, 3, 3), a rotation matrix up to rounding (det > 0, singular values within 0.05 of 1;\n"
       "projected onto the nearest rotation as SciPy's Rotation.from_matrix).\n"
       "Returns (3,) or (n, 3).\n" + gimbal_note)
          .c_str());

  // ------------------------------------------------------------ Davenport angles
  const std::string davenport_note =
      "axes: (3, 3), the rotation axes n1, n2, n3 as rows (any non-zero length, normalised), n2\n"
      "orthogonal to n1 and to n3 (|cos| <= 1e-7, as SciPy); order: 'e'/'extrinsic' (fixed axes,\n"
      "R = R_n3(a3) R_n2(a2) R_n1(a1)) or 'i'/'intrinsic' (moving axes, R = R_n1(a1) R_n2(a2) R_n3(a3)),\n"
      "as SciPy's Rotation.from_davenport / as_davenport. Coordinate axes give Euler angles.\n";
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
      (std::string("Unit quaternion of Davenport angles (rotations about three arbitrary axes).\n\n") + davenport_note +
       "angles: (3,) or (n, 3) [rad] (degrees if degrees=True), in the order of the axes.\n"
       "Returns q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first.")
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
      (std::string("Davenport angles [rad] of unit quaternions (Bernardes & Viollet 2022, arbitrary axes).\n\n") +
       davenport_note +
       "q: (4,) or (n, 4). Returns (3,) or (n, 3) [rad] (degrees if degrees=True), as SciPy: first and\n"
       "third in [-pi, pi], second in [-l, pi - l] if l >= 0, [-pi - l, -l] if l < 0, where\n"
       "l = atan2(m3 . (m1 x n2), m3 . m1) with (m1, m3) = (n1, n3), or (n3, n1) if intrinsic (proper Euler:\n"
       "l = 0, second in [0, pi]; Tait-Bryan: l = +-pi/2, second in [-pi/2, pi/2]).\n" + gimbal_note)
          .c_str());

  // ------------------------------------------------------------ modified Rodrigues parameters
  m.def(
      "quat_to_mrp",
      [](py::handle q, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const std::string name = "q";
        return map_unary(q, "q", quaternion, vector3, "quat_to_mrp", [&](const double* in, double* out) {
          write_vector(quat_to_mrp(checked_unit_quaternion(py_io::read_quaternion(in, scalar_first), name)), out);
        });
      },
      "q"_a, "scalar_first"_a = false,
      "Modified Rodrigues parameters p = axis tan(angle/4) of unit quaternions, the set with |p| <= 1\n"
      "(angle in [0, pi]; as SciPy's Rotation.as_mrp). Dimensionless.\n\n"
      "q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first. Returns (3,) or (n, 3).");

  m.def(
      "mrp_to_quat",
      [](py::handle mrp, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        return map_unary(mrp, "mrp", vector3, quaternion, "mrp_to_quat", [&](const double* in, double* out) {
          py_io::write_quaternion(mrp_to_quat(read_vector(in)), out, scalar_first);
        });
      },
      "mrp"_a, "scalar_first"_a = false,
      "Unit quaternion ((2 p, 1 - |p|^2) / (1 + |p|^2)) of modified Rodrigues parameters p (either shadow\n"
      "set: p and -p/|p|^2 are the same rotation; w < 0 when |p| > 1), as SciPy's Rotation.from_mrp.\n\n"
      "mrp: (3,) or (n, 3), any finite values. Returns q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if\n"
      "scalar_first.");

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
  bind_elementary("rot_x", &rot_x,
                  "Elementary rotation about x by angle [rad] (active): [[1, 0, 0], [0, c, -s], [0, s, c]].\n"
                  "angle: float or (n,), in degrees if degrees=True. Returns (3, 3) or (n, 3, 3).");
  bind_elementary("rot_y", &rot_y,
                  "Elementary rotation about y by angle [rad] (active): [[c, 0, s], [0, 1, 0], [-s, 0, c]].\n"
                  "angle: float or (n,), in degrees if degrees=True. Returns (3, 3) or (n, 3, 3).");
  bind_elementary("rot_z", &rot_z,
                  "Elementary rotation about z by angle [rad] (active): [[c, -s, 0], [s, c, 0], [0, 0, 1]].\n"
                  "angle: float or (n,), in degrees if degrees=True. Returns (3, 3) or (n, 3, 3).");

  // ------------------------------------------------------------ quaternion algebra
  m.def(
      "quat_multiply",
      [](py::handle q1, py::handle q2, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const std::string name1 = "q1", name2 = "q2";
        return map_binary(q1, "q1", quaternion, q2, "q2", quaternion, quaternion, "quat_multiply",
                          [&](const double* a, const double* b, double* out) {
                            py_io::write_quaternion(
                                quat_multiply(checked_unit_quaternion(py_io::read_quaternion(a, scalar_first), name1),
                                              checked_unit_quaternion(py_io::read_quaternion(b, scalar_first), name2)),
                                out, scalar_first);
                          });
      },
      "q1"_a, "q2"_a, "scalar_first"_a = false,
      "Hamilton product q1 ⊗ q2 of unit quaternions: R(q1 ⊗ q2) = R(q1) R(q2) (q2 applied first).\n\n"
      "q1, q2: (4,) or (n, 4) each (a single one is used with every item of the other).\n"
      "Returns (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first.");

  m.def(
      "quat_inverse",
      [](py::handle q, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const std::string name = "q";
        return map_unary(q, "q", quaternion, quaternion, "quat_inverse", [&](const double* in, double* out) {
          py_io::write_quaternion(quat_inverse(checked_unit_quaternion(py_io::read_quaternion(in, scalar_first), name)),
                                  out, scalar_first);
        });
      },
      "q"_a, "scalar_first"_a = false,
      "Inverse (conjugate) of unit quaternions: q_BW from q_WB. q: (4,) or (n, 4); returns the same shape.");

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
      "q / |q| for finite non-zero quaternions of any norm (ValueError for q = 0).\n"
      "q: (4,) or (n, 4); returns the same shape, sign unchanged.");

  m.def(
      "quat_rotate",
      [](py::handle q, py::handle v, py::handle scalar_first_arg) {
        const bool scalar_first = as_scalar_first(scalar_first_arg);
        const std::string name = "q";
        return map_binary(q, "q", quaternion, v, "v", vector3, vector3, "quat_rotate", [&](const double* a, const double* b, double* out) {
          write_vector(quat_rotate(checked_unit_quaternion(py_io::read_quaternion(a, scalar_first), name), read_vector(b)), out);
        });
      },
      "q"_a, "v"_a, "scalar_first"_a = false,
      "R(q) v: vectors rotated actively by unit quaternions (v_W = R_WB v_B for q = q_WB).\n\n"
      "q: (4,) or (n, 4); v: (3,) or (n, 3) (a single one is used with every item of the other).\n"
      "Returns (3,) or (n, 3).");

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
      "Exact attitude update for an angular velocity w [rad/s] constant over dt [s].\n\n"
      "frame='body': q ⊗ exp(w dt/2), w = w_B expressed in the body frame;\n"
      "frame='world': exp(w dt/2) ⊗ q, w = w_W expressed in the world frame;\n"
      "exp of a pure vector u is (sin|u| u/|u|, cos|u|).\n"
      "q: (4,) or (n, 4) unit quaternions q_WB; w: (3,) or (n, 3); dt: float.\n"
      "Returns (4,) or (n, 4), normalised, (x, y, z, w) or (w, x, y, z) if scalar_first.");

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
      "Quaternion rate dq/dt [1/s] of the attitude q = q_WB turning with angular velocity w [rad/s]:\n"
      "frame='body': dq/dt = 1/2 q ⊗ (w, 0), w = w_B expressed in the body frame;\n"
      "frame='world': dq/dt = 1/2 (w, 0) ⊗ q, w = w_W expressed in the world frame.\n"
      "q: (4,) or (n, 4) unit quaternions; w: (3,) or (n, 3) (a single one is used with every item of the\n"
      "other). Returns (4,) or (n, 4) in q's order, orthogonal to q, |dq/dt| = |w|/2.");

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
      "Angular velocity [rad/s] of the attitude q = q_WB changing at dq_dt [1/s], the inverse of quat_rate:\n"
      "frame='body': w_B = 2 vec(q* ⊗ dq/dt); frame='world': w_W = 2 vec(dq/dt ⊗ q*).\n"
      "The part of dq_dt along q (which would change |q|, not the rotation) is ignored.\n"
      "q: (4,) or (n, 4) unit quaternions; dq_dt: (4,) or (n, 4), any finite values, in q's order.\n"
      "Returns (3,) or (n, 3).");

  // ------------------------------------------------------------ skew matrices
  m.def(
      "hat",
      [](py::handle v) {
        return map_unary(v, "v", vector3, matrix3, "hat", [&](const double* in, double* out) { write_matrix(hat(read_vector(in)), out); });
      },
      "v"_a,
      "Skew-symmetric cross-product matrix S = hat(v), S x = v × x. v: (3,) or (n, 3); returns (3, 3) or (n, 3, 3).");

  m.def(
      "vee",
      [](py::handle S) {
        return map_unary(S, "S", matrix3, vector3, "vee", [&](const double* in, double* out) { write_vector(vee(read_matrix(in)), out); });
      },
      "S"_a,
      "Inverse of hat: v with hat(v) = (S - S^T)/2 (a symmetric part of S is ignored).\n"
      "S: (3, 3) or (n, 3, 3); returns (3,) or (n, 3).");
}

}  // namespace rigiddyn::bindings
