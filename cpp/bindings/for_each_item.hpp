// The loop of the stacked bindings: one kernel call per item of a stack, without the GIL.
#pragma once
#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>

namespace rigiddyn::bindings {

// Runs kernel(i) for i in [0, n) without the GIL. A std::invalid_argument from item i of a stack
// gets " (item i)" appended, so the message names the argument and the offending item.
template <typename Kernel>
void for_each_item(pybind11::ssize_t n, bool stacked, Kernel kernel) {
  pybind11::gil_scoped_release release;
  pybind11::ssize_t i = 0;
  try {
    for (; i < n; ++i) kernel(i);
  } catch (const std::invalid_argument& e) {
    if (!stacked) throw;
    throw std::invalid_argument(std::string(e.what()) + " (item " + std::to_string(i) + ")");
  }
}

}  // namespace rigiddyn::bindings
