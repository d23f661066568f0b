// The loops of the stacked bindings: one kernel call per item of a stack, without the GIL (blocks of items:
// so3_lanes.hpp).
#pragma once
#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>

// Written after a lambda's parameter list: the kernel of an array loop inlined into the loop (GCC otherwise
// outlines it from the large binding functions, with its constants reloaded and its block passed through
// memory on every call).
#if defined(__GNUC__) || defined(__clang__)
#define RIGIDDYN_INLINE_KERNEL __attribute__((always_inline))
#else
#define RIGIDDYN_INLINE_KERNEL
#endif

namespace rigiddyn::bindings {

// The exception of item i of a stack: the message gets " (item i)" appended, so that it names the argument
// and the offending item.
[[noreturn]] inline void throw_for_item(const std::invalid_argument& e, pybind11::ssize_t i) {
  throw std::invalid_argument(std::string(e.what()) + " (item " + std::to_string(i) + ")");
}

// Runs kernel(i) for i in [0, n) without the GIL. A std::invalid_argument from item i of a stack
// names the item (throw_for_item).
template <typename Kernel>
void for_each_item(pybind11::ssize_t n, bool stacked, Kernel kernel) {
  pybind11::gil_scoped_release release;
  pybind11::ssize_t i = 0;
  try {
    for (; i < n; ++i) kernel(i);
  } catch (const std::invalid_argument& e) {
    if (!stacked) throw;
    throw_for_item(e, i);
  }
}

}  // namespace rigiddyn::bindings
