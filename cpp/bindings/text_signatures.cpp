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
#include "bindings.hpp"

#include <pybind11/pybind11.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

namespace py = pybind11;

namespace rigiddyn::bindings {
namespace {

// The default's text in a text signature: its repr when that is a Python literal (inspect evaluates it), math.inf
// for an infinite float (inspect looks the name up), else "..." (the parameter has a default, which the docstring
// states).
std::string default_text(const py::detail::argument_record& arg, const py::module_& ast) {
  if (arg.value && PyFloat_Check(arg.value.ptr())) {
    const double x = PyFloat_AsDouble(arg.value.ptr());
    if (std::isinf(x)) return x > 0 ? "math.inf" : "-math.inf";
  }
  if (!arg.descr) return "...";
  try {
    ast.attr("literal_eval")(arg.descr);
    return arg.descr;
  } catch (const py::error_already_set&) {
    return "...";
  }
}

// "(a, b=False, /, *, c=None)" of one pybind11 function record; "(*args, **kwargs)" for an overload set (no single
// signature: the docstring lists each).
std::string text_signature(const py::detail::function_record& rec, const py::module_& ast) {
  if (rec.next) return rec.is_method ? "(self, /, *args, **kwargs)" : "(*args, **kwargs)";
  std::string out = "(";
  const auto parameter = [&](std::size_t i) -> std::string {
    const bool named = i < rec.args.size() && rec.args[i].name;
    std::string name = named ? rec.args[i].name : "arg" + std::to_string(i);
    if (i == 0 && rec.is_method) return name;  // self: unbound through the class, dropped by a bound method
    if (rec.has_kwargs && i + 1 == rec.nargs) return "**" + name;
    if (rec.has_args && i == rec.nargs_pos) return "*" + name;
    if (named && (rec.args[i].descr || rec.args[i].value)) name += "=" + default_text(rec.args[i], ast);
    return name;
  };
  for (std::size_t i = 0; i < rec.nargs; ++i) {
    if (i > 0) out += ", ";
    if (i == rec.nargs_pos && !rec.has_args && i < rec.nargs && !(rec.has_kwargs && i + 1 == rec.nargs)) out += "*, ";
    out += parameter(i);
    if (rec.nargs_pos_only > 0 && i + 1 == rec.nargs_pos_only) out += ", /";
  }
  return out + ")";
}

// Puts "name(signature)\n--\n\n" in front of the C-level docstring of the pybind11 function `f` (as pybind11
// itself replaces it when an overload is added: the old string freed, a malloc'd one set).
void add_text_signature(PyObject* f, const py::module_& ast) {
  if (!PyCFunction_Check(f)) return;
  PyObject* self = PyCFunction_GET_SELF(f);  // pybind11's record of the function
  const py::detail::function_record* rec = self ? py::detail::function_record_ptr_from_PyObject(self) : nullptr;
  if (!rec || !rec->name) return;
  auto* function = reinterpret_cast<PyCFunctionObject*>(f);
  const char* old = PYBIND11_PYCFUNCTION_GET_DOC(function);
  const std::string doc = std::string(rec->name) + text_signature(*rec, ast) + "\n--\n\n" + (old ? old : "");
  char* text = static_cast<char*>(std::malloc(doc.size() + 1));
  if (!text) throw std::bad_alloc();
  std::memcpy(text, doc.c_str(), doc.size() + 1);
  std::free(const_cast<char*>(old));
  PYBIND11_PYCFUNCTION_SET_DOC(function, text);
}

// The text signatures of a class's methods and static methods (its constructor's too: __init__ is one of them)
void add_method_signatures(const py::dict& members, const py::module_& ast) {
  for (const auto item : members) {
    PyObject* f = item.second.ptr();
    if (PyInstanceMethod_Check(f)) {
      add_text_signature(PyInstanceMethod_GET_FUNCTION(f), ast);
    } else if (py::isinstance(item.second, py::module_::import("builtins").attr("staticmethod"))) {
      add_text_signature(item.second.attr("__func__").ptr(), ast);
    }
  }
}

// A warning's or an exception's (*args), as every exception takes (inspect finds none for a built-in base)
void exception_signature(const py::handle& cls, const py::module_& inspect) {
  const py::object parameter = inspect.attr("Parameter");
  cls.attr("__signature__") = inspect.attr("Signature")(
      py::make_tuple(parameter("args", parameter.attr("VAR_POSITIONAL"))));
}

// The class's __signature__: its constructor's without self; none for a class without an __init__
// of its own (a result or report that the core makes: calling it raises TypeError).
void add_class_signature(const py::handle& cls, const py::module_& ast, const py::module_& inspect) {
  if (PyType_IsSubtype(reinterpret_cast<PyTypeObject*>(cls.ptr()), reinterpret_cast<PyTypeObject*>(PyExc_BaseException))) {
    exception_signature(cls, inspect);
    return;
  }
  const py::dict members = cls.attr("__dict__");
  add_method_signatures(members, ast);
  if (!members.contains("__init__")) return;
  PyObject* init = py::handle(members["__init__"]).ptr();
  if (PyInstanceMethod_Check(init)) init = PyInstanceMethod_GET_FUNCTION(init);
  if (!PyCFunction_Check(init) || !PyCFunction_GET_SELF(init)) return;
  if (!py::hasattr(py::handle(init), "__text_signature__") || py::handle(init).attr("__text_signature__").is_none()) return;
  const py::object signature = inspect.attr("signature")(py::handle(init));  // (self, ...)
  const py::list parameters(signature.attr("parameters").attr("values")());
  cls.attr("__signature__") = signature.attr("replace")(py::arg("parameters") = parameters[py::slice(1, {}, {})]);
}

}  // namespace

void add_text_signatures(py::module_& m) {
  if (const char* stubgen = std::getenv("RIGIDDYN_STUBGEN"); stubgen && std::string(stubgen) == "1") return;
  const py::module_ ast = py::module_::import("ast"), inspect = py::module_::import("inspect");
  const py::dict names = m.attr("__dict__");
  for (const auto item : names) {
    if (PyType_Check(item.second.ptr())) {
      add_class_signature(item.second, ast, inspect);
    } else {
      add_text_signature(item.second.ptr(), ast);
    }
  }
}

}  // namespace rigiddyn::bindings
