#include "numpy_io.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <type_traits>

namespace rigiddyn::py_io {

// A double is not finite iff its 11 exponent bits are all ones, that is iff adding one to its exponent field carries
// into the sign bit: integer operations without a branch per entry, which the compiler vectorises (a test with an
// exit per entry runs one entry at a time).
bool all_finite(const double* p, py::ssize_t size) {
  constexpr std::uint64_t exponent = 0x7ff0000000000000, exponent_one = 0x0010000000000000, sign = 0x8000000000000000;
  const auto carry = [p](py::ssize_t i) {
    std::uint64_t bits;
    std::memcpy(&bits, p + i, sizeof bits);
    return (bits & exponent) + exponent_one;
  };
  std::uint64_t carries[4] = {};  // four chains of |= : one would wait on the previous |= every entry
  py::ssize_t i = 0;
  for (; i + 4 <= size; i += 4) {
    for (int k = 0; k < 4; ++k) carries[k] |= carry(i + k);
  }
  for (; i < size; ++i) carries[0] |= carry(i);
  return ((carries[0] | carries[1] | carries[2] | carries[3]) & sign) == 0;
}

namespace {

// Allocations up to this size are never refused in advance (checking costs a read of /proc/meminfo).
constexpr std::uint64_t always_allocatable = std::uint64_t{64} << 20;  // 64 MiB

std::string shape_string(const py::array& a) {
  std::ostringstream out;
  out << "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) out << (i ? ", " : "") << a.shape(i);
  out << (a.ndim() == 1 ? ",)" : ")");
  return out.str();
}

std::string tail_string(const std::vector<py::ssize_t>& tail, bool with_n) {
  std::ostringstream out;
  out << "(";
  if (with_n) out << "n" << (tail.empty() ? "" : ", ");
  for (size_t i = 0; i < tail.size(); ++i) out << (i ? ", " : "") << tail[i];
  out << ((tail.size() == 1 && !with_n) ? ",)" : ")");
  return out.str();
}

// A byte count for a message: "298 GiB".
std::string bytes_string(std::uint64_t bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double value = static_cast<double>(bytes);
  int unit = 0;
  while (value >= 1024.0 && unit < 6) value /= 1024.0, ++unit;
  std::ostringstream out;
  out.precision(3);
  out << value << " " << units[unit];
  return out.str();
}

void require_all_finite(const Array& a, const std::string& name) {
  const double* p = a.data();
  if (all_finite(p, a.size())) return;
  for (py::ssize_t i = 0; i < a.size(); ++i) {
    if (!std::isfinite(p[i])) {
      throw_value_error(name, "finite values", format_value(p[i]) + " at flat index " + std::to_string(i));
    }
  }
}

// Python types that are never array-like: refused before numpy sees them.
bool never_array_like(PyObject* p) {
  return p == Py_None || PyUnicode_Check(p) || PyBytes_Check(p) || PyComplex_Check(p) || PyDict_Check(p) ||
         PyAnySet_Check(p) || PyCallable_Check(p);
}

bool is_memory_error(const py::error_already_set& e) { return e.matches(PyExc_MemoryError); }

// numpy.asarray(obj): TypeError naming `name` for what numpy cannot read (ValueError for a
// ragged sequence); MemoryError and interrupts (KeyboardInterrupt) pass through.
py::array numpy_asarray(py::handle obj, const std::string& name, const std::string& expected) {
  if (never_array_like(obj.ptr())) throw_type_error(name, expected, obj);
  try {
    return py::module_::import("numpy").attr("asarray")(obj);
  } catch (py::error_already_set& e) {
    if (is_memory_error(e) || is_interrupt(e)) throw;
    if (e.matches(PyExc_ValueError)) throw_value_error(name, expected + " of a regular shape", describe(obj));
    throw_type_error(name, expected, obj);
  }
}

// raw as a C-contiguous array of T; MemoryError naming `name` if the copy does not fit.
template <class Target>
Target contiguous(const py::array& raw, const std::string& name) {
  if (Target::check_(raw)) return py::reinterpret_borrow<Target>(raw);
  std::uint64_t bytes = 0;
  if (__builtin_mul_overflow(static_cast<std::uint64_t>(raw.size()), sizeof(typename Target::value_type), &bytes)) {
    bytes = std::numeric_limits<std::uint64_t>::max();
  }
  const std::string what = std::string("a contiguous ") + (sizeof(typename Target::value_type) == 8 &&
                            std::is_floating_point_v<typename Target::value_type> ? "float64" : "int64") +
                            " copy of shape " + shape_string(raw);
  require_allocatable(bytes, name, what);
  try {
    return Target(raw);
  } catch (py::error_already_set& e) {
    if (!is_memory_error(e)) throw;
    PyErr_SetString(PyExc_MemoryError, (name + ": cannot allocate " + what + " (" + bytes_string(bytes) + ")").c_str());
    throw py::error_already_set();
  }
}

// hasattr(p, name), an interrupt met in a Python __getattr__ thrown on (PyObject_HasAttrString would clear it).
bool has_attribute(PyObject* p, const char* name) {
  PyObject* value = PyObject_GetAttrString(p, name);
  if (value == nullptr) {
    clear_error_unless_interrupt();
    return false;
  }
  Py_DECREF(value);
  return true;
}

// True for an object with a pint Quantity's attributes (any registry; pint is not imported to ask).
bool looks_like_quantity(PyObject* p) {
  return has_attribute(p, "magnitude") && has_attribute(p, "units") && has_attribute(p, "to");
}

// True when p is a quantity or a list/tuple holding one (`depth` levels of nesting looked into). Plain
// numbers, None, strings and numpy arrays answer at once, without an attribute lookup.
bool holds_quantity(PyObject* p, int depth) {
  if (PyFloat_Check(p) || PyLong_Check(p) || p == Py_None || PyUnicode_Check(p)) return false;
  const bool list = PyList_Check(p);
  if (list || PyTuple_Check(p)) {
    if (depth == 0) return false;
    const Py_ssize_t n = list ? PyList_GET_SIZE(p) : PyTuple_GET_SIZE(p);
    for (Py_ssize_t i = 0; i < n; ++i)
      if (holds_quantity(list ? PyList_GET_ITEM(p, i) : PyTuple_GET_ITEM(p, i), depth - 1)) return true;
    return false;
  }
  if (py::isinstance<py::array>(p)) return false;
  return looks_like_quantity(p);
}

}  // namespace

// ------------------------------------------------------------ interrupts

bool is_interrupt(const py::error_already_set& e) { return !e.matches(PyExc_Exception); }

void clear_error_unless_interrupt() {
  if (PyErr_ExceptionMatches(PyExc_Exception)) {
    PyErr_Clear();
  } else {
    throw py::error_already_set();
  }
}

// ------------------------------------------------------------ units

py::object in_si(py::handle obj, const char* unit, const char* name) {
  if (!holds_quantity(obj.ptr(), 2)) return py::reinterpret_borrow<py::object>(obj);
  return py::module_::import("rigiddyn.units").attr("to_si")(obj, unit, name);
}

// ------------------------------------------------------------ messages

std::string describe(py::handle obj) {
  if (obj.is_none()) return "None";
  if (py::isinstance<py::array>(obj)) {  // its dtype and shape: an array's repr spans lines
    const py::array a = py::reinterpret_borrow<py::array>(obj);
    return "an array of dtype " + std::string(py::str(a.dtype())) + " and shape " + shape_string(a);
  }
  std::string text;
  try {
    text = py::repr(obj);
  } catch (py::error_already_set& e) {
    if (is_interrupt(e)) throw;
    text = "(no repr)";
  }
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return std::string(Py_TYPE(obj.ptr())->tp_name) + " " + text;
}

void throw_type_error(const std::string& name, const std::string& expected, py::handle got) {
  throw py::type_error(name + ": expected " + expected + ", got " + describe(got));
}

void throw_value_error(const std::string& name, const std::string& expected, const std::string& got) {
  throw py::value_error(name + ": expected " + expected + ", got " + got);
}

// ------------------------------------------------------------ scalars and objects

namespace {

// A real number, possibly non-finite; bool refused.
double real_number(py::handle obj, const std::string& name) {
  PyObject* p = obj.ptr();
  if (PyFloat_Check(p)) return PyFloat_AS_DOUBLE(p);  // also numpy.float64
  if (PyLong_CheckExact(p)) {
    const double x = PyLong_AsDouble(p);
    if (x == -1.0 && PyErr_Occurred()) {
      PyErr_Clear();
      throw_value_error(name, "a finite number", "an integer beyond the range of double: " + describe(obj));
    }
    return x;
  }
  if (PyBool_Check(p)) throw_type_error(name, "a real number", obj);
  const py::array raw = numpy_asarray(obj, name, "a real number");
  const char kind = raw.dtype().kind();
  if (kind == 'b' || !(kind == 'i' || kind == 'u' || kind == 'f')) throw_type_error(name, "a real number", obj);
  if (raw.size() != 1) throw_value_error(name, "a scalar", "an array of shape " + shape_string(raw));
  return contiguous<Array>(raw, name).data()[0];
}

}  // namespace

double as_scalar(py::handle obj, const std::string& name) {
  const double x = real_number(obj, name);
  if (!std::isfinite(x)) throw_value_error(name, "a finite number", format_value(x));
  return x;
}

double as_positive(py::handle obj, const std::string& name) {
  const double x = real_number(obj, name);
  if (!(std::isfinite(x) && x > 0.0)) throw_value_error(name, "a finite number > 0", format_value(x));
  return x;
}

double as_extended_real(py::handle obj, const std::string& name) {
  const double x = real_number(obj, name);
  if (std::isnan(x)) throw_value_error(name, "a number (+-inf allowed)", format_value(x));
  return x;
}

std::optional<double> as_optional_scalar(py::handle obj, const std::string& name) {
  if (obj.is_none()) return std::nullopt;
  return as_scalar(obj, name);
}

std::int64_t as_int(py::handle obj, const std::string& name, std::int64_t lo, std::int64_t hi) {
  const auto expected = [&] { return "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]"; };
  PyObject* p = obj.ptr();
  if (PyBool_Check(p) || PyFloat_Check(p) || !PyIndex_Check(p)) throw_type_error(name, expected(), obj);
  const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(p));
  if (!index) {
    clear_error_unless_interrupt();
    throw_type_error(name, expected(), obj);
  }
  int overflow = 0;
  const long long value = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
  if (overflow != 0 || value < lo || value > hi) throw_value_error(name, expected(), std::string(py::str(index)));
  return value;
}

bool as_bool(py::handle obj, const std::string& name) {
  PyObject* p = obj.ptr();
  if (PyBool_Check(p)) return p == Py_True;
  if (std::string(Py_TYPE(p)->tp_name) == "numpy.bool" || std::string(Py_TYPE(p)->tp_name) == "numpy.bool_") {
    return PyObject_IsTrue(p) == 1;
  }
  throw_type_error(name, "True or False", obj);
}

std::string as_string(py::handle obj, const std::string& name) {
  if (!py::isinstance<py::str>(obj)) throw_type_error(name, "a str", obj);
  return obj.cast<std::string>();
}

py::function as_callable(py::handle obj, const std::string& name, const std::string& expected) {
  if (!PyCallable_Check(obj.ptr())) throw_type_error(name, expected, obj);
  return py::reinterpret_borrow<py::function>(obj);
}

// ------------------------------------------------------------ arrays

Array as_array(py::handle obj, const std::string& name) {
  if (Array::check_(obj)) return py::reinterpret_borrow<Array>(obj);  // float64, C-contiguous: no copy
  const std::string expected = "an array of real numbers";
  const py::array raw = numpy_asarray(obj, name, expected);
  const char kind = raw.dtype().kind();
  if (kind != 'b' && kind != 'i' && kind != 'u' && kind != 'f') {
    throw_type_error(name, expected, obj);
  }
  return contiguous<Array>(raw, name);
}

IndexArray as_index_array(py::handle obj, const std::string& name) {
  if (IndexArray::check_(obj)) return py::reinterpret_borrow<IndexArray>(obj);
  const std::string expected = "an integer array";
  const py::array raw = numpy_asarray(obj, name, expected);
  const char kind = raw.dtype().kind();
  if (kind != 'i' && kind != 'u') throw_type_error(name, expected, obj);
  return contiguous<IndexArray>(raw, name);
}

Stack as_stack(py::handle obj, const std::string& name, const std::vector<py::ssize_t>& tail, EntryCheck check) {
  Array a = as_array(obj, name);
  const auto t = static_cast<py::ssize_t>(tail.size());
  bool ok = (a.ndim() == t || a.ndim() == t + 1);
  const py::ssize_t offset = a.ndim() - t;
  for (py::ssize_t i = 0; ok && i < t; ++i) ok = a.shape(offset + i) == tail[static_cast<size_t>(i)];
  if (!ok) throw_value_error(name, "shape " + tail_string(tail, false) + " or " + tail_string(tail, true), shape_string(a));
  if (check == EntryCheck::all_finite) require_all_finite(a, name);
  const bool stacked = offset == 1;
  return Stack{a, stacked ? a.shape(0) : 1, stacked};
}

Array new_stack(py::ssize_t n, bool stacked, const std::vector<py::ssize_t>& tail, const std::string& name) {
  std::vector<py::ssize_t> shape;
  if (stacked) shape.push_back(n);
  shape.insert(shape.end(), tail.begin(), tail.end());
  std::uint64_t bytes = sizeof(double);
  bool overflow = false;
  for (py::ssize_t extent : shape) overflow |= __builtin_mul_overflow(bytes, static_cast<std::uint64_t>(extent), &bytes);
  if (overflow) bytes = std::numeric_limits<std::uint64_t>::max();
  if (bytes > always_allocatable) {  // the message's shape string only where it may be needed
    std::string shape_text = "(";
    for (size_t i = 0; i < shape.size(); ++i) shape_text += (i ? ", " : "") + std::to_string(shape[i]);
    require_allocatable(bytes, name, "the result of shape " + shape_text + (shape.size() == 1 ? ",)" : ")"));
  }
  return Array(shape);
}

std::uint64_t available_memory_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit) {
    if (key == "MemAvailable:") return kib * 1024;
  }
  const long pages = sysconf(_SC_AVPHYS_PAGES), page_size = sysconf(_SC_PAGESIZE);
  if (pages > 0 && page_size > 0) return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size);
  return std::numeric_limits<std::uint64_t>::max();  // unknown: let the allocation decide
}

void require_allocatable(std::uint64_t bytes, const std::string& name, const std::string& what) {
  if (bytes <= always_allocatable) return;
  const std::uint64_t available = available_memory_bytes();
  if (bytes <= available) return;
  const std::string size = bytes == std::numeric_limits<std::uint64_t>::max() ? "more than 16 EiB" : bytes_string(bytes);
  PyErr_SetString(PyExc_MemoryError,
                  (name + ": cannot allocate " + what + " (" + size + "; " + bytes_string(available) + " available)").c_str());
  throw py::error_already_set();
}

namespace {
template <int R, int C>
Eigen::Matrix<double, R, C> as_fixed(py::handle obj, const std::string& name) {
  const std::vector<py::ssize_t> tail = (C == 1) ? std::vector<py::ssize_t>{R} : std::vector<py::ssize_t>{R, C};
  Array a = as_array(obj, name);
  bool ok = a.ndim() == static_cast<py::ssize_t>(tail.size());
  for (py::ssize_t i = 0; ok && i < a.ndim(); ++i) ok = a.shape(i) == tail[static_cast<size_t>(i)];
  if (!ok) throw_value_error(name, "shape " + tail_string(tail, false), shape_string(a));
  require_all_finite(a, name);
  return Eigen::Map<const Eigen::Matrix<double, R, C, (C == 1 ? Eigen::ColMajor : Eigen::RowMajor)>>(a.data());
}
}  // namespace

Eigen::Vector2d as_vector2(py::handle obj, const std::string& name) { return as_fixed<2, 1>(obj, name); }
Eigen::Vector3d as_vector3(py::handle obj, const std::string& name) { return as_fixed<3, 1>(obj, name); }
Eigen::Matrix3d as_matrix3(py::handle obj, const std::string& name) { return as_fixed<3, 3>(obj, name); }
Eigen::Matrix<double, 6, 1> as_vector6(py::handle obj, const std::string& name) { return as_fixed<6, 1>(obj, name); }
Eigen::Matrix<double, 6, 6> as_matrix6(py::handle obj, const std::string& name) { return as_fixed<6, 6>(obj, name); }

Eigen::Quaterniond read_quaternion(const double* p, bool scalar_first) {
  return scalar_first ? Eigen::Quaterniond(p[0], p[1], p[2], p[3]) : Eigen::Quaterniond(p[3], p[0], p[1], p[2]);
}

void write_quaternion(const Eigen::Quaterniond& q, double* out, bool scalar_first) {
  if (scalar_first) {
    out[0] = q.w(); out[1] = q.x(); out[2] = q.y(); out[3] = q.z();
  } else {
    out[0] = q.x(); out[1] = q.y(); out[2] = q.z(); out[3] = q.w();
  }
}

Eigen::Quaterniond as_quaternion(py::handle obj, const std::string& name, bool scalar_first) {
  const Eigen::Vector4d c = as_fixed<4, 1>(obj, name);
  return read_quaternion(c.data(), scalar_first);
}

// ------------------------------------------------------------ results

Array to_array(const Eigen::Quaterniond& q, bool scalar_first) {
  Array out({py::ssize_t{4}});
  write_quaternion(q, out.mutable_data(), scalar_first);
  return out;
}

void warn_not_finite(const std::string& quantity, const std::string& got) {
  const std::string message = quantity + ": expected a finite result, got " + got +
                              " (every input was finite: their magnitudes overflow double precision)";
  if (PyErr_WarnEx(PyExc_RuntimeWarning, message.c_str(), 1) != 0) throw py::error_already_set();
}

Array finite_result(Array value, const char* quantity) {
  const double* p = value.data();
  if (!Eigen::Map<const Eigen::ArrayXd>(p, value.size()).allFinite()) {
    py::ssize_t i = 0;
    while (std::isfinite(p[i])) ++i;
    warn_not_finite(quantity, format_value(p[i]) + " at flat index " + std::to_string(i));
  }
  return value;
}

}  // namespace rigiddyn::py_io
