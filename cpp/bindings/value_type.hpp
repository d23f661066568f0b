// Python value-type protocol shared by the bindings of the inertia, spatial, frames and exact
// layers: exact equality (==, bitwise on every member, NotImplemented for another type) and the
// checks of a pickled state tuple. The repr is repr.hpp's repr_call.
#pragma once
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>

#include "is_instance.hpp"

namespace rigiddyn::bindings {

// a == b for a bound class T, with equal(a, b) deciding; NotImplemented when b is not a T, so that
// Python falls back to identity (False) as for any other pair of types.
template <class T, class Equal>
pybind11::object equal_or_not_implemented(const T& a, pybind11::handle b, Equal equal) {
  if (!is_instance<T>(b)) return pybind11::reinterpret_borrow<pybind11::object>(Py_NotImplemented);
  return pybind11::bool_(equal(a, b.cast<const T&>()));
}

// Every entry equal (exact; NaN never equals).
template <class A, class B>
bool same(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  return (a.array() == b.array()).all();
}
// Every coefficient equal (q and -q, the same rotation, differ)
inline bool same(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) { return same(a.coeffs(), b.coeffs()); }

// The state of a pickled `type`: a tuple of `size` items, else ValueError naming the type.
inline pybind11::tuple pickled_state(const pybind11::handle state, size_t size, const std::string& type) {
  if (!pybind11::isinstance<pybind11::tuple>(state) || pybind11::len(state) != size) {
    throw pybind11::value_error(type + " state: expected a tuple of " + std::to_string(size) + " items, got " +
                                std::string(pybind11::repr(state)));
  }
  return pybind11::reinterpret_borrow<pybind11::tuple>(state);
}

}  // namespace rigiddyn::bindings
