// Runtime signatures for the compiled functions and classes, so that inspect.signature, help() and IDEs see
// each callable's parameters: CPython reads a builtin's signature from the first line of its C-level
// docstring when it has the form "name(a, b=1, /, *, c=None)\n--\n\n" (its __text_signature__); pybind11 writes
// its typed signature line there instead, which inspect cannot parse. After every binding is registered, each
// function's docstring gets that line in front, built from pybind11's own record of the parameters (their names,
// positional-only and keyword-only marks, defaults), each method and static method of a class too, and each class
// the signature of its constructor (__signature__). The typed line pybind11 wrote stays first in __doc__, for
// readers and the stub generator:
// pybind11-stubgen reads those typed lines only where inspect finds no signature, so under RIGIDDYN_STUBGEN=1
// (set by the stub's generation, tests/python/test_stubs.py) the signatures are not added.
// The same pass gives each public function its last overload, the one that explains a call no other overload accepts
// (call_errors.hpp); it is left out of the text signatures, and under RIGIDDYN_STUBGEN=1 of the stub.
#include "bindings.hpp"
#include "call_errors.hpp"

#include <pybind11/pybind11.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

namespace py = pybind11;

namespace rigiddyn::bindings {
namespace {

// True for a value whose repr is a Python literal (what a text signature may hold): None, a bool, an int, a finite
// float, a str, or a tuple or list of them
bool is_literal(py::handle v) {
  PyObject* o = v.ptr();
  if (v.is_none() || PyBool_Check(o) || PyLong_Check(o) || PyUnicode_Check(o)) return true;
  if (PyFloat_Check(o)) return std::isfinite(PyFloat_AsDouble(o));
  if (PyTuple_Check(o) || PyList_Check(o)) {
    for (const auto item : v) {
      if (!is_literal(item)) return false;
    }
    return true;
  }
  return false;
}

// The default's text in a text signature: its repr when that is a Python literal (inspect evaluates it), math.inf
// for an infinite float (inspect looks the name up), else "..." (the parameter has a default, which the docstring
// states).
std::string default_text(const py::detail::argument_record& arg) {
  if (PyFloat_Check(arg.value.ptr()) && std::isinf(PyFloat_AsDouble(arg.value.ptr()))) {
    return PyFloat_AsDouble(arg.value.ptr()) > 0 ? "math.inf" : "-math.inf";
  }
  return is_literal(arg.value) ? py::repr(arg.value).cast<std::string>() : "...";
}

// The kind of parameter i of a pybind11 function record, as inspect.Parameter names it
const char* parameter_kind(const py::detail::function_record& rec, std::size_t i) {
  if (rec.has_kwargs && i + 1 == rec.nargs) return "VAR_KEYWORD";
  if (rec.has_args && i == rec.nargs_pos) return "VAR_POSITIONAL";
  if (i < rec.nargs_pos_only) return "POSITIONAL_ONLY";
  return i >= rec.nargs_pos ? "KEYWORD_ONLY" : "POSITIONAL_OR_KEYWORD";
}

// Its name: the binding's; where the binding names none, "args" and "kwargs" for py::args and py::kwargs (as
// pybind11's own docstring line writes them), "self" for a method's first, "arg<i>" otherwise
std::string parameter_name(const py::detail::function_record& rec, std::size_t i) {
  if (i < rec.args.size() && rec.args[i].name) return rec.args[i].name;
  if (rec.is_method && i == 0) return "self";
  const std::string kind = parameter_kind(rec, i);
  if (kind == "VAR_POSITIONAL") return "args";
  if (kind == "VAR_KEYWORD") return "kwargs";
  return "arg" + std::to_string(i);
}

// Whether it has a default (its value in rec.args)
bool has_default(const py::detail::function_record& rec, std::size_t i) {
  return i < rec.args.size() && rec.args[i].name && rec.args[i].value;
}

// Whether rec has other overloads than the one that explains a failed call (call_errors.hpp)
bool overloaded(const py::detail::function_record& rec) { return rec.next && !is_call_errors(*rec.next); }

// "(a, b=False, /, *, c=None)" of one pybind11 function record; "(*args, **kwargs)" for an overload set (no single
// signature: the docstring lists each). A method's self is listed: unbound through the class, a bound method drops
// it.
std::string text_signature(const py::detail::function_record& rec) {
  if (overloaded(rec)) return rec.is_method ? "(self, /, *args, **kwargs)" : "(*args, **kwargs)";
  std::string out = "(";
  bool keyword_only_marked = false;
  for (std::size_t i = 0; i < rec.nargs; ++i) {
    const std::string kind = parameter_kind(rec, i);
    if (i > 0) out += ", ";
    if (kind == "KEYWORD_ONLY" && !keyword_only_marked) out += "*, ";
    keyword_only_marked = keyword_only_marked || kind == "KEYWORD_ONLY" || kind == "VAR_POSITIONAL";
    out += (kind == "VAR_KEYWORD" ? "**" : kind == "VAR_POSITIONAL" ? "*" : "") + parameter_name(rec, i);
    if (has_default(rec, i)) out += "=" + default_text(rec.args[i]);
    if (kind == "POSITIONAL_ONLY" && i + 1 == rec.nargs_pos_only) out += ", /";
  }
  return out + ")";
}


// Puts "name(signature)\n--\n\n" in front of the C-level docstring of the pybind11 function `f` (as pybind11
// itself replaces it when an overload is added: the old string freed, a malloc'd one set).
void add_text_signature(PyObject* f) {
  const py::detail::function_record* rec = record_of(f);
  if (!rec) return;
  auto* function = reinterpret_cast<PyCFunctionObject*>(f);
  const char* old = PYBIND11_PYCFUNCTION_GET_DOC(function);
  const std::string doc = std::string(rec->name) + text_signature(*rec) + "\n--\n\n" + (old ? old : "");
  char* text = static_cast<char*>(std::malloc(doc.size() + 1));
  if (!text) throw std::bad_alloc();
  std::memcpy(text, doc.c_str(), doc.size() + 1);
  std::free(const_cast<char*>(old));
  PYBIND11_PYCFUNCTION_SET_DOC(function, text);
}

// The text signatures of a class's methods and static methods (its constructor's too: __init__ is one of them)
void add_method_signatures(const py::dict& members, const py::handle& staticmethod) {
  for (const auto item : members) {
    PyObject* f = item.second.ptr();
    if (PyInstanceMethod_Check(f)) f = PyInstanceMethod_GET_FUNCTION(f);
    else if (py::isinstance(item.second, staticmethod)) f = item.second.attr("__func__").ptr();
    else continue;
    add_call_errors(f);
    add_text_signature(f);
  }
}

// inspect.Signature of the parameters of one pybind11 function record, self left out, each default the object
// itself (as the text signature, built directly: parsing the text costs a fraction of a millisecond per class)
py::object signature_of(const py::detail::function_record& rec, const py::module_& inspect) {
  const py::object parameter = inspect.attr("Parameter");
  py::list parameters;
  for (std::size_t i = rec.is_method ? 1 : 0; i < rec.nargs; ++i) {
    const py::object kind = parameter.attr(parameter_kind(rec, i));
    parameters.append(has_default(rec, i)
                          ? parameter(parameter_name(rec, i), kind, py::arg("default") = rec.args[i].value)
                          : parameter(parameter_name(rec, i), kind));
  }
  return inspect.attr("Signature")(parameters);
}

// A warning's or an exception's (*args), as every exception takes (inspect finds none for a built-in base)
void exception_signature(const py::handle& cls, const py::module_& inspect) {
  const py::object parameter = inspect.attr("Parameter");
  cls.attr("__signature__") = inspect.attr("Signature")(
      py::make_tuple(parameter("args", parameter.attr("VAR_POSITIONAL"))));
}

// The class's __signature__: its constructor's without self (a class only the core makes has one that refuses every
// call, made_by_the_core.cpp); none for a class without an __init__ of its own.
void add_class_signature(const py::handle& cls, const py::module_& inspect, const py::handle& staticmethod) {
  const auto* type = reinterpret_cast<PyTypeObject*>(cls.ptr());
  if (PyType_IsSubtype(const_cast<PyTypeObject*>(type), reinterpret_cast<PyTypeObject*>(PyExc_BaseException))) {
    exception_signature(cls, inspect);
    return;
  }
  const py::dict members = cls.attr("__dict__");
  add_method_signatures(members, staticmethod);
  if (!members.contains("__init__")) return;
  PyObject* init = py::handle(members["__init__"]).ptr();
  if (PyInstanceMethod_Check(init)) init = PyInstanceMethod_GET_FUNCTION(init);
  const py::detail::function_record* rec = record_of(init);
  if (!rec) return;
  try {
    if (overloaded(*rec)) {  // several constructors: (*args, **kwargs), from their text signature (self dropped)
      const py::object signature = inspect.attr("signature")(py::handle(init));
      const py::list parameters(signature.attr("parameters").attr("values")());
      cls.attr("__signature__") = signature.attr("replace")(py::arg("parameters") = parameters[py::slice(1, {}, {})]);
    } else {
      cls.attr("__signature__") = signature_of(*rec, inspect);
    }
  } catch (const py::error_already_set&) {
    // parameters that no Python signature can hold (a required one after one with a default): none is set
  }
}

}  // namespace

void add_text_signatures(py::module_& m) {
  if (const char* stubgen = std::getenv("RIGIDDYN_STUBGEN"); stubgen && std::string(stubgen) == "1") return;
  const py::module_ inspect = py::module_::import("inspect");
  const py::object staticmethod = py::module_::import("builtins").attr("staticmethod");
  const py::dict names = m.attr("__dict__");
  for (const auto item : names) {
    if (PyType_Check(item.second.ptr())) {
      add_class_signature(item.second, inspect, staticmethod);
    } else {
      add_call_errors(item.second.ptr());
      add_text_signature(item.second.ptr());
    }
  }
}

}  // namespace rigiddyn::bindings
