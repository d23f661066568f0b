// The numpy boundary of the bindings: every array argument goes through these functions, so that
// bad input raises TypeError (not a real number array) or ValueError (wrong shape, NaN/Inf) with
// a message "<name>: expected ..., got ...", never a crash.
//
// Layouts: a "stack" of items is either one item (shape `tail`) or n items (shape (n, *tail)).
// Quaternions cross the boundary as 4-arrays (x, y, z, w), or (w, x, y, z) when scalar_first.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace rigiddyn::py_io {

namespace py = pybind11;
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// obj as a C-contiguous float64 array. TypeError unless its dtype is bool, integer or real float.
Array as_array(py::handle obj, const std::string& name);

// A stack of items of shape `tail`: the array, n (1 if single) and whether it was stacked.
// ValueError on a wrong shape or a non-finite entry.
struct Stack {
  Array array;
  py::ssize_t n;
  bool stacked;
  const double* item(py::ssize_t i, py::ssize_t item_size) const { return array.data() + i * item_size; }
};
Stack as_stack(py::handle obj, const std::string& name, const std::vector<py::ssize_t>& tail);

// A new array for n outputs of shape `tail`, stacked like the input (shape tail if !stacked).
Array new_stack(py::ssize_t n, bool stacked, const std::vector<py::ssize_t>& tail);

// Single items; ValueError on a wrong shape or a non-finite entry.
double as_scalar(py::handle obj, const std::string& name);
Eigen::Vector3d as_vector3(py::handle obj, const std::string& name);
Eigen::Matrix3d as_matrix3(py::handle obj, const std::string& name);
Eigen::Matrix<double, 6, 1> as_vector6(py::handle obj, const std::string& name);
Eigen::Matrix<double, 6, 6> as_matrix6(py::handle obj, const std::string& name);
// The quaternion's coefficients as given (no normalisation, no norm check: the core checks).
Eigen::Quaterniond as_quaternion(py::handle obj, const std::string& name, bool scalar_first);
// Optional arguments: None -> the identity / zero, else as_matrix3 / as_vector3.
inline Eigen::Matrix3d as_matrix3_or_identity(py::handle obj, const std::string& name) {
  return obj.is_none() ? Eigen::Matrix3d::Identity() : as_matrix3(obj, name);
}
inline Eigen::Vector3d as_vector3_or_zero(py::handle obj, const std::string& name) {
  return obj.is_none() ? Eigen::Vector3d::Zero() : as_vector3(obj, name);
}

// Reading and writing one quaternion item of a stack (4 doubles), in the chosen order.
Eigen::Quaterniond read_quaternion(const double* xyzw_or_wxyz, bool scalar_first);
void write_quaternion(const Eigen::Quaterniond& q, double* out, bool scalar_first);

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
// A read-only numpy copy of a member (vector (n,) or matrix (r, c)), so that `x.com[0] = 1` fails
// loudly instead of writing to a temporary.
template <typename Derived>
Array read_only(const Eigen::MatrixBase<Derived>& value) {
  Array out = to_array(value);
  out.attr("flags").attr("writeable") = false;
  return out;
}

}  // namespace rigiddyn::py_io
