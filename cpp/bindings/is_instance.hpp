// is_instance<T>(obj): isinstance(obj, C) for the Python class C bound to the C++ class T.
//
// pybind11's isinstance<T> finds C by T's typeid in a hash map and asks PyObject_IsInstance, which looks
// __instancecheck__ up on the metaclass, at every call: about 400 instructions for an object of another
// class, paid by every dispatch over the body kinds of a `step` or `simulate` call. Here C is found once
// per T (the classes live as long as the module) and the test is CPython's subtype test of obj's type,
// the answer PyObject_IsInstance gives for classes whose metaclass does not redefine __instancecheck__
// (pybind11's does not).
#pragma once
#include <pybind11/pybind11.h>

namespace rigiddyn {

template <class T>
bool is_instance(pybind11::handle obj) {
  static PyTypeObject* const bound = reinterpret_cast<PyTypeObject*>(pybind11::type::of<T>().ptr());
  return PyType_IsSubtype(Py_TYPE(obj.ptr()), bound) != 0;
}

}  // namespace rigiddyn
