// A repr that reads as the constructor call, shared by every bound class:
//   RigidBodyState(p_W=[0.0, 0.0, 0.0], q_WB=[0.0, 0.0, 0.0, 1.0], ...)
// Numbers are printed by Python's repr (shortest text that round-trips), arrays as nested lists, so
// that `eval(repr(x), vars(rigiddyn))` rebuilds an equal object wherever the class has that
// constructor. Pickling is separate (py::pickle in each class's binding, state as a tuple).
#pragma once
#include <pybind11/pybind11.h>

#include <initializer_list>
#include <string>
#include <utility>

namespace rigiddyn::bindings {

using ReprField = std::pair<const char*, pybind11::object>;

// "name(key=value, ...)"; a value with .tolist() (numpy arrays and scalars) is shown as its list.
inline std::string repr_call(const std::string& name, std::initializer_list<ReprField> fields) {
  std::string text = name + "(";
  const char* separator = "";
  for (const auto& [key, value] : fields) {
    const pybind11::object shown = pybind11::hasattr(value, "tolist") ? value.attr("tolist")() : value;
    text += separator + std::string(key) + "=" + pybind11::repr(shown).cast<std::string>();
    separator = ", ";
  }
  return text + ")";
}

}  // namespace rigiddyn::bindings
