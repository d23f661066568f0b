#include "numpy_io.hpp"

#include <cmath>
#include <sstream>

namespace rigiddyn::py_io {

namespace {

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

void require_all_finite(const Array& a, const std::string& name) {
  const double* p = a.data();
  for (py::ssize_t i = 0; i < a.size(); ++i) {
    if (!std::isfinite(p[i])) {
      std::ostringstream out;
      out << name << ": expected finite values, got " << p[i] << " at flat index " << i;
      throw py::value_error(out.str());
    }
  }
}

}  // namespace

Array as_array(py::handle obj, const std::string& name) {
  py::array raw;
  try {
    raw = py::module_::import("numpy").attr("asarray")(obj);
  } catch (py::error_already_set&) {
    throw py::type_error(name + ": expected an array of real numbers, got " +
                         std::string(py::str(py::type::of(obj).attr("__name__"))));
  }
  const char kind = raw.dtype().kind();
  if (kind != 'b' && kind != 'i' && kind != 'u' && kind != 'f') {
    throw py::type_error(name + ": expected an array of real numbers, got dtype " +
                         std::string(py::str(raw.dtype())));
  }
  return Array::ensure(raw);
}

Stack as_stack(py::handle obj, const std::string& name, const std::vector<py::ssize_t>& tail) {
  Array a = as_array(obj, name);
  const auto t = static_cast<py::ssize_t>(tail.size());
  bool ok = (a.ndim() == t || a.ndim() == t + 1);
  const py::ssize_t offset = a.ndim() - t;
  for (py::ssize_t i = 0; ok && i < t; ++i) ok = a.shape(offset + i) == tail[static_cast<size_t>(i)];
  if (!ok) {
    throw py::value_error(name + ": expected shape " + tail_string(tail, false) + " or " +
                          tail_string(tail, true) + ", got " + shape_string(a));
  }
  require_all_finite(a, name);
  const bool stacked = offset == 1;
  return Stack{a, stacked ? a.shape(0) : 1, stacked};
}

Array new_stack(py::ssize_t n, bool stacked, const std::vector<py::ssize_t>& tail) {
  std::vector<py::ssize_t> shape;
  if (stacked) shape.push_back(n);
  shape.insert(shape.end(), tail.begin(), tail.end());
  return Array(shape);
}

double as_scalar(py::handle obj, const std::string& name) {
  Array a = as_array(obj, name);
  if (a.ndim() != 0 && a.size() != 1) {
    throw py::value_error(name + ": expected a scalar, got an array of shape " + shape_string(a));
  }
  require_all_finite(a, name);
  return a.data()[0];
}

namespace {
template <int R, int C>
Eigen::Matrix<double, R, C> as_fixed(py::handle obj, const std::string& name) {
  const std::vector<py::ssize_t> tail = (C == 1) ? std::vector<py::ssize_t>{R} : std::vector<py::ssize_t>{R, C};
  Array a = as_array(obj, name);
  bool ok = a.ndim() == static_cast<py::ssize_t>(tail.size());
  for (py::ssize_t i = 0; ok && i < a.ndim(); ++i) ok = a.shape(i) == tail[static_cast<size_t>(i)];
  if (!ok) throw py::value_error(name + ": expected shape " + tail_string(tail, false) + ", got " + shape_string(a));
  require_all_finite(a, name);
  return Eigen::Map<const Eigen::Matrix<double, R, C, (C == 1 ? Eigen::ColMajor : Eigen::RowMajor)>>(a.data());
}
}  // namespace

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

Array to_array(const Eigen::Quaterniond& q, bool scalar_first) {
  Array out({py::ssize_t{4}});
  write_quaternion(q, out.mutable_data(), scalar_first);
  return out;
}

}  // namespace rigiddyn::py_io
