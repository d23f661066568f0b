// What the bindings of the bodies and their states share (bind_bodies.cpp, bind_pivoted.cpp, bind_gyrostat.cpp):
// a unit quaternion argument, == for a mutable value class, and the arrays of a pickled state.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "numpy_io.hpp"
#include "rigiddyn/so3/quaternion.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>

namespace rigiddyn::bindings {

// A unit quaternion from `obj` (checked_attitude: ValueError naming `name` farther than 1e-6 from unit norm), kept bit
// for bit when it is already unit to round-off so that a state rebuilt from its repr equals the original, normalised
// otherwise.
inline Eigen::Quaterniond as_unit_quaternion(pybind11::handle obj, const std::string& name, bool scalar_first = false) {
  return checked_attitude(py_io::as_quaternion(obj, name, scalar_first), name);
}

// __eq__ (the values compared by `equal`, an unrelated type gives NotImplemented) and no hash: the states are
// mutable.
template <class T, class Equal>
void def_equality(pybind11::class_<T>& cls, Equal equal) {
  cls.def(
      "__eq__",
      [equal](const T& a, pybind11::handle b) -> pybind11::object {
        if (!is_instance<T>(b)) return pybind11::reinterpret_borrow<pybind11::object>(Py_NotImplemented);
        return pybind11::bool_(equal(a, b.cast<const T&>()));
      },
      pybind11::arg("other"));
  cls.attr("__hash__") = pybind11::none();
}

// N numbers of a pickled array (N = Eigen::Dynamic: any count), bit for bit (not checked finite: a state a
// diverged step returned is pickled as it is).
template <int N>
Eigen::Matrix<double, N, 1> unpickled(pybind11::handle obj, const std::string& what) {
  const auto a = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>::ensure(obj);
  if (!a || (N == Eigen::Dynamic ? a.ndim() != 1 : a.size() != N)) {
    py_io::throw_value_error(what, N == Eigen::Dynamic ? std::string("a 1-D array") : std::to_string(N) + " numbers",
                             py_io::describe(obj));
  }
  return Eigen::Map<const Eigen::Matrix<double, N, 1>>(a.data(), a.size());
}

}  // namespace rigiddyn::bindings
