// A call that no signature of a compiled function accepts raises a TypeError that says why (call_errors.cpp).
#pragma once
#include <pybind11/pybind11.h>

namespace rigiddyn::bindings {

// Appends to the public pybind11 function f (a module's function, a class's method, static method or __init__; not
// an operator) a last overload (*args, **kwargs) that pybind11 reaches only after every other overload failed, with
// and without conversions, and that raises a TypeError naming the reason: an unknown keyword (with the closest
// valid one), a missing or repeated argument, too many positional arguments, or the parameter whose value has the
// wrong type. f's docstring is kept as it was.
void add_call_errors(PyObject* f);

// pybind11's record of the compiled function f; nullptr for any other object
const pybind11::detail::function_record* record_of(PyObject* f);

// True for the overload add_call_errors appends (the text signatures and the stubs leave it out).
bool is_call_errors(const pybind11::detail::function_record& rec);

}  // namespace rigiddyn::bindings
