// The Python boundary of the bindings: every argument and every result goes through these
// functions, so that
//   - a value of the wrong type raises TypeError and a wrong value ValueError, both with a message
//     "<name>: expected <what>, got <value>" that names the argument (never pybind11's overload
//     dump: the bindings take their arguments as py::handle and convert them here);
//   - an array whose contiguous float64 copy (or a result that) does not fit in memory raises
//     MemoryError naming it, never a crash;
//   - a result that is not finite although the inputs were (overflow at extreme magnitudes) gives a
//     RuntimeWarning naming the quantity (finite_result), never a silent inf or NaN.
// Every check is O(1) per argument or one pass over an array; scalars, float64 arrays and bound
// objects take a fast path that calls no Python function.
//
// Layouts: a "stack" of items is either one item (shape `tail`) or n items (shape (n, *tail)).
// Quaternions cross the boundary as 4-arrays (x, y, z, w), or (w, x, y, z) when scalar_first.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "is_instance.hpp"
#include "rigiddyn/check.hpp"

namespace rigiddyn::py_io {

namespace py = pybind11;
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
using IndexArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

// ------------------------------------------------------------ interrupts
// True for a Python exception that a conversion must never swallow into its own TypeError/ValueError: one
// that is not an Exception (KeyboardInterrupt from a Ctrl-C met while Python code ran for the conversion, a
// __repr__ or __index__; SystemExit).
bool is_interrupt(const py::error_already_set& e);
// After a C API call failed: clears its Python error, or throws it on (error_already_set) when is_interrupt.
void clear_error_unless_interrupt();

// ------------------------------------------------------------ messages
// A value for a message: "None", an array's dtype and shape, or the type and a repr cut to 60
// characters ("str '1'").
std::string describe(py::handle obj);
// TypeError "<name>: expected <expected>, got <describe(got)>".
[[noreturn]] void throw_type_error(const std::string& name, const std::string& expected, py::handle got);
// ValueError "<name>: expected <expected>, got <got>".
[[noreturn]] void throw_value_error(const std::string& name, const std::string& expected, const std::string& got);

// ------------------------------------------------------------ scalars and objects
// A finite real number: a Python int or float, a numpy real scalar or an array of one element
// (bool is refused). TypeError for anything else, ValueError for NaN/inf.
double as_scalar(py::handle obj, const std::string& name);
// A finite real number > 0 (masses, lengths, densities, ...).
double as_positive(py::handle obj, const std::string& name);
// A real number that may be +-inf but not NaN (time bounds, a screw's pitch).
double as_extended_real(py::handle obj, const std::string& name);
// None -> nullopt, else as_scalar.
std::optional<double> as_optional_scalar(py::handle obj, const std::string& name);
// An integer (Python int, numpy integer; not bool, not float) in [lo, hi], else TypeError /
// ValueError naming the range.
std::int64_t as_int(py::handle obj, const std::string& name, std::int64_t lo = std::numeric_limits<std::int64_t>::min(),
                    std::int64_t hi = std::numeric_limits<std::int64_t>::max());
// True or False (a Python or numpy bool; not int).
bool as_bool(py::handle obj, const std::string& name);
// A str.
std::string as_string(py::handle obj, const std::string& name);
// One of the strings of `choices`, as its value: TypeError unless a str, ValueError listing them.
template <class E>
E as_choice(py::handle obj, const std::string& name, std::initializer_list<std::pair<const char*, E>> choices) {
  std::string listed;  // 'a', 'b' or 'c'
  size_t k = 0;
  for (const auto& [text, value] : choices) {
    listed += (k == 0 ? "" : (++k == choices.size() ? " or " : ", ")) + ("'" + std::string(text) + "'");
    k += (k == 0);
  }
  if (!py::isinstance<py::str>(obj)) throw_type_error(name, listed, obj);
  const std::string given = obj.cast<std::string>();
  for (const auto& [text, value] : choices)
    if (given == text) return value;
  throw_value_error(name, listed, "'" + given + "'");
}
// An instance of the bound class T (a reference into the Python object, alive for the call);
// TypeError "<name>: expected <expected>, got ..." otherwise.
template <class T>
T& as_instance(py::handle obj, const std::string& name, const std::string& expected) {
  if (!is_instance<T>(obj)) throw_type_error(name, expected, obj);
  return obj.cast<T&>();
}
// A value of the bound enum T (a copy: pybind11's enum caster may hold the value itself, so a reference would
// outlive it); TypeError "<name>: expected <expected>, got ..." otherwise.
template <class T>
T as_enum(py::handle obj, const std::string& name, const std::string& expected) {
  if (!py::isinstance<T>(obj)) throw_type_error(name, expected, obj);
  return obj.cast<T>();
}
// A bound spatial vector (Motion or Force: members angular, linear) whose parts are finite; ValueError
// "<name>: expected <expected> with finite values" otherwise (one made by an overflowing operation).
template <class T>
const T& as_finite_spatial(py::handle obj, const std::string& name, const std::string& expected) {
  const T& v = as_instance<T>(obj, name, expected);
  if (!(v.angular.allFinite() && v.linear.allFinite())) {
    throw_value_error(name, expected + " with finite values",
                      "angular " + format_value(v.angular.transpose()) + ", linear " + format_value(v.linear.transpose()));
  }
  return v;
}
// A callable object.
py::function as_callable(py::handle obj, const std::string& name, const std::string& expected);

// ------------------------------------------------------------ units
// The argument `obj` in the SI unit `unit` (a pint expression: "kg", "kg*m^2", "m/s", "N*m*s"), to be
// converted next by as_scalar, as_vector3, ... as a plain SI value: a pint Quantity of any registry
// (holding a number, or an array with one unit), or a list or tuple with quantities among its items
// (nested once: rows of a matrix), is converted by rigiddyn.units.to_si, which raises ValueError
// "<name>: expected <unit>, got <value>" for a quantity of another dimension; anything else is returned
// unchanged, without a Python call (a float is SI as it is). A quantity is recognised by its attributes
// (magnitude, units, to), so pint is imported only when one is passed.
py::object in_si(py::handle obj, const char* unit, const char* name);

// ------------------------------------------------------------ arrays
// True iff every p[0, size) is finite (no branch per entry).
bool all_finite(const double* p, py::ssize_t size);
// obj as a C-contiguous float64 array (no copy when it is one already). TypeError unless its dtype
// is bool, integer or real float (or it is not array-like), ValueError for a ragged sequence,
// MemoryError naming `name` when the float64 copy does not fit in memory.
Array as_array(py::handle obj, const std::string& name);
// obj as a C-contiguous int64 array; TypeError unless its dtype is integer.
IndexArray as_index_array(py::handle obj, const std::string& name);

// A stack of items of shape `tail`: the array, n (1 if single) and whether it was stacked.
// ValueError on a wrong shape or, unless the caller checks every item itself (EntryCheck::by_caller:
// no pass over the data here), a non-finite entry.
struct Stack {
  Array array;
  py::ssize_t n;
  bool stacked;
  const double* item(py::ssize_t i, py::ssize_t item_size) const { return array.data() + i * item_size; }
};
// Item i of a stack of items of `size` entries, or its one item when it is not stacked (broadcast)
inline const double* item(const Stack& s, py::ssize_t i, py::ssize_t size) { return s.item(s.stacked ? i : 0, size); }
// The number of entries of an item of shape `shape` (the product of its extents)
inline py::ssize_t item_size(const std::vector<py::ssize_t>& shape) {
  py::ssize_t size = 1;
  for (py::ssize_t extent : shape) size *= extent;
  return size;
}
// A 3-vector item read from, and written to, its 3 entries
inline Eigen::Vector3d read_vector(const double* p) { return Eigen::Vector3d(p[0], p[1], p[2]); }
inline void write_vector(const Eigen::Vector3d& v, double* out) { Eigen::Map<Eigen::Vector3d>{out} = v; }
enum class EntryCheck { all_finite, by_caller };
Stack as_stack(py::handle obj, const std::string& name, const std::vector<py::ssize_t>& tail,
               EntryCheck check = EntryCheck::all_finite);

// A new array for n outputs of shape `tail`, stacked like the input (shape tail if !stacked).
// MemoryError naming `name` when it does not fit in memory.
Array new_stack(py::ssize_t n, bool stacked, const std::vector<py::ssize_t>& tail, const std::string& name = "result");

// Memory the system can still give [bytes] (MemAvailable of /proc/meminfo, else free pages).
std::uint64_t available_memory_bytes();
// MemoryError "<name>: cannot allocate <what> (<bytes>; <available> available)" unless `bytes`
// fit in the available memory (checked only above 64 MiB, where an allocation may overcommit).
void require_allocatable(std::uint64_t bytes, const std::string& name, const std::string& what);

// Single items; ValueError on a wrong shape or a non-finite entry.
Eigen::Vector2d as_vector2(py::handle obj, const std::string& name);
Eigen::Vector3d as_vector3(py::handle obj, const std::string& name);
Eigen::Matrix3d as_matrix3(py::handle obj, const std::string& name);
Eigen::Matrix<double, 6, 1> as_vector6(py::handle obj, const std::string& name);
Eigen::Matrix<double, 6, 6> as_matrix6(py::handle obj, const std::string& name);
// The quaternion's coefficients as given (no normalisation, no norm check: the core checks).
Eigen::Quaterniond as_quaternion(py::handle obj, const std::string& name, bool scalar_first);
// Optional arguments: None -> the identity / zero, else as_matrix3 / as_vector3 / as_vector2.
inline Eigen::Matrix3d as_matrix3_or_identity(py::handle obj, const std::string& name) {
  return obj.is_none() ? Eigen::Matrix3d::Identity() : as_matrix3(obj, name);
}
inline Eigen::Vector3d as_vector3_or_zero(py::handle obj, const std::string& name) {
  return obj.is_none() ? Eigen::Vector3d::Zero() : as_vector3(obj, name);
}
inline Eigen::Vector2d as_vector2_or_zero(py::handle obj, const std::string& name) {
  return obj.is_none() ? Eigen::Vector2d::Zero() : as_vector2(obj, name);
}

// Reading and writing one quaternion item of a stack (4 doubles), in the chosen order.
Eigen::Quaterniond read_quaternion(const double* xyzw_or_wxyz, bool scalar_first);
void write_quaternion(const Eigen::Quaterniond& q, double* out, bool scalar_first);

// ------------------------------------------------------------ results
// Conversions of results to new numpy arrays.
Array to_array(const Eigen::Quaterniond& q, bool scalar_first);
template <typename Derived>
Array to_array(const Eigen::MatrixBase<Derived>& m) {
  const auto rows = m.rows(), cols = m.cols();
  Array out = (cols == 1) ? Array({rows}) : Array({rows, cols});
  double* p = out.mutable_data();
  for (Eigen::Index i = 0; i < rows; ++i)
    for (Eigen::Index j = 0; j < cols; ++j) p[i * cols + j] = m(i, j);
  return out;
}
// Makes `a` read-only (a.flags.writeable = False) by clearing its WRITEABLE flag directly: the Python attribute
// path costs about 1 µs (numpy's flags object calls ndarray.setflags), more than a short run's records.
inline void set_read_only(const py::array& a) {
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
}

// A read-only numpy copy of a member (vector (n,) or matrix (r, c)), so that `x.com[0] = 1` fails
// loudly instead of writing to a temporary.
template <typename Derived>
Array read_only(const Eigen::MatrixBase<Derived>& value) {
  Array out = to_array(value);
  py_io::set_read_only(out);
  return out;
}

// RuntimeWarning "<quantity>: expected a finite result, got <got> (...)": a result overflowed
// although every input was finite. Throws error_already_set when warnings are errors.
void warn_not_finite(const std::string& quantity, const std::string& got);
// The checked results: each warns (warn_not_finite) when a value is not finite, then returns it.
inline double finite_result(double value, const char* quantity) {
  if (!std::isfinite(value)) warn_not_finite(quantity, format_value(value));
  return value;
}
template <typename Derived>
Array finite_result(const Eigen::MatrixBase<Derived>& value, const char* quantity) {
  if (!value.allFinite()) warn_not_finite(quantity, format_value(value.eval()));
  return to_array(value);
}
// One pass over the array.
Array finite_result(Array value, const char* quantity);
// `finite` computed by the caller for a result object (e.g. every member of a Motion).
inline void warn_unless_finite(bool finite, const char* quantity, const std::string& got) {
  if (!finite) warn_not_finite(quantity, got);
}

}  // namespace rigiddyn::py_io
