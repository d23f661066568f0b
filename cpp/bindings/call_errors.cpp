// The message of a call that fits no signature: pybind11 answers it with "incompatible function arguments" and the
// list of every overload; the overload appended here answers instead with the reason, read from pybind11's records
// of the other overloads (their parameters' names, kinds, defaults and the types in their signature line):
//   simulate(): unexpected keyword argument 'step' (did you mean 'steps'?)
//   InertiaCheck(): missing required argument 'value'
//   value: expected an int, got str 'x'
// It costs nothing on a call that succeeds: pybind11 tries the overloads in order, first without conversions, then
// with them, and this one loads its first parameter only in the pass with conversions, so it runs after every
// other overload failed both ways. (Most functions take their arguments as py::handle and name a value of the wrong
// type themselves, numpy_io.hpp; the type check here serves the parameters that pybind11 converts.)
#include "call_errors.hpp"

#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "numpy_io.hpp"
#include "rigiddyn/closest_name.hpp"

namespace py = pybind11;

namespace rigiddyn::bindings {

// The first positional argument of the appended overload, or the sentinel no_argument() when none was given. Its
// caster loads only with conversions allowed, so that pybind11 keeps the overload for its second pass.
struct AfterConversions {
  py::handle first;
};

}  // namespace rigiddyn::bindings

namespace pybind11::detail {
template <>
struct type_caster<rigiddyn::bindings::AfterConversions> {
  PYBIND11_TYPE_CASTER(rigiddyn::bindings::AfterConversions, const_name("object"));
  bool load(handle src, bool convert) {
    value.first = src;
    return convert;
  }
  static handle cast(const rigiddyn::bindings::AfterConversions&, return_value_policy, handle) { return none().release(); }
};
}  // namespace pybind11::detail

namespace rigiddyn::bindings {
namespace {

using py::detail::function_record;

// The name of the appended overload's first parameter: no keyword can match it, since it is no identifier
constexpr const char* first_parameter = "(first)";

// The default of that parameter (a private object: None may be the first argument)
py::handle no_argument() {
  static PyObject* sentinel = PyObject_CallNoArgs(reinterpret_cast<PyObject*>(&PyBaseObject_Type));  // never freed
  return sentinel;
}

// What a message calls the function: "simulate()", "Scene.add_body()", "InertiaCheck()" for a constructor
std::string call_name(const function_record& rec) {
  const bool in_class = PyType_Check(rec.scope.ptr());
  const std::string owner = in_class ? py::str(rec.scope.attr("__name__")).cast<std::string>() : "";
  if (std::strcmp(rec.name, "__init__") == 0) return owner + "()";
  return (in_class ? owner + "." : "") + rec.name + "()";
}

// Parameter name -> its type in pybind11's signature line "(self: X, a: typing.Any, b: float = 1.0, *, c: int) -> R"
std::map<std::string, std::string> annotations(const char* signature) {
  std::map<std::string, std::string> out;
  std::vector<std::string> items;
  std::string item;
  int depth = 0;
  char quote = 0;
  for (const char* c = signature; *c; ++c) {
    if (quote) {
      quote = *c == quote ? 0 : quote;
    } else if (*c == '\'' || *c == '"') {
      quote = *c;
    } else if (*c == '(' || *c == '[') {
      if (++depth == 1) continue;
    } else if (*c == ')' || *c == ']') {
      if (--depth == 0) break;
    } else if (*c == ',' && depth == 1) {
      items.push_back(item);
      item.clear();
      continue;
    }
    if (depth >= 1) item += *c;
  }
  items.push_back(item);
  for (std::string& text : items) {
    const auto start = text.find_first_not_of(" *");
    const auto colon = text.find(": ");
    if (start == std::string::npos || colon == std::string::npos) continue;  // "/" or "*"
    const auto end = text.find(" = ", colon);
    out[text.substr(start, colon - start)] = text.substr(colon + 2, end == std::string::npos ? end : end - colon - 2);
  }
  return out;
}

// Whether pybind11 could convert `value` to the type named `annotation`, and the type in words ("an int"); true for
// a type this does not know (it cannot tell)
bool converts(const std::string& annotation, py::handle value, const py::handle& scope, std::string& expected) {
  PyObject* o = value.ptr();
  if (annotation == "typing.Any" || annotation == "object") return true;
  if (annotation == "float" || annotation == "typing.SupportsFloat | typing.SupportsIndex") {
    expected = "a float";
    return PyFloat_Check(o) || PyIndex_Check(o) || py::hasattr(value, "__float__");
  }
  if (annotation == "int" || annotation == "typing.SupportsInt | typing.SupportsIndex") {
    expected = "an int";
    return !PyFloat_Check(o) && (PyIndex_Check(o) || py::hasattr(value, "__int__"));
  }
  if (annotation == "bool") {
    expected = "a bool";
    return PyBool_Check(o) || value.is_none() || py::hasattr(value, "__bool__");
  }
  if (annotation == "str") {
    expected = "a str";
    return PyUnicode_Check(o) || PyBytes_Check(o);
  }
  const std::string name = annotation.substr(annotation.rfind('.') + 1);  // rigiddyn._core.Motion -> Motion
  const py::module_ module = py::module_::import(
      py::str(PyType_Check(scope.ptr()) ? scope.attr("__module__") : scope.attr("__name__")).cast<std::string>().c_str());
  if (!py::hasattr(module, name.c_str()) || !PyType_Check(module.attr(name.c_str()).ptr())) return true;
  expected = "a " + name;
  return py::isinstance(value, module.attr(name.c_str()));
}

// The parameters of one overload after binding a call to them (Python's rules; self left out)
struct Binding {
  std::string misfit;                                   // why the call fits no signature of this overload, or ""
  std::vector<std::pair<std::size_t, py::handle>> bound;  // (parameter index, value)
};

std::string quoted_list(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    out += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + ("'" + names[k] + "'");
  }
  return out;
}

// Binds positional `args` and keyword `kwargs` to the parameters of rec, as Python binds a call to a signature
Binding bind(const function_record& rec, const py::tuple& args, const py::dict& kwargs) {
  const std::size_t first = rec.is_method ? 1 : 0;                             // self is bound already
  const std::size_t named = rec.nargs - (rec.has_args ? 1 : 0) - (rec.has_kwargs ? 1 : 0);  // no *args, **kwargs
  auto name = [&](std::size_t i) { return std::string(i < rec.args.size() && rec.args[i].name ? rec.args[i].name : ""); };
  std::vector<py::handle> value(named);
  Binding b;
  const std::size_t positional = rec.nargs_pos - first;
  if (args.size() > positional && !rec.has_args) {
    b.misfit = "takes " + std::to_string(positional) + " positional argument" + (positional == 1 ? "" : "s") + " but " +
               std::to_string(args.size()) + (args.size() == 1 ? " was" : " were") + " given";
    return b;
  }
  for (std::size_t k = 0; k < args.size() && k < positional; ++k) value[first + k] = args[k];
  std::vector<std::string> keywords;  // the names a keyword may take
  for (std::size_t i = std::max<std::size_t>(first, rec.nargs_pos_only); i < named; ++i) keywords.push_back(name(i));
  for (const auto item : kwargs) {
    const std::string key = py::str(item.first);
    std::size_t i = first;
    while (i < named && !(i >= rec.nargs_pos_only && name(i) == key)) ++i;
    if (i == named) {
      if (rec.has_kwargs) continue;
      b.misfit = "unexpected keyword argument '" + key + "'" + did_you_mean(key, keywords);
      return b;
    }
    if (value[i]) {
      b.misfit = "got multiple values for argument '" + key + "'";
      return b;
    }
    value[i] = item.second;
  }
  std::vector<std::string> missing;
  for (std::size_t i = first; i < named; ++i) {
    if (!value[i] && !(i < rec.args.size() && rec.args[i].value)) missing.push_back(name(i));
    if (value[i]) b.bound.emplace_back(i, value[i]);
  }
  if (!missing.empty()) {
    b.misfit = "missing required argument" + std::string(missing.size() == 1 ? " " : "s ") + quoted_list(missing);
  }
  return b;
}

// Raises the TypeError of a call (args, kwargs) that no overload of f before the appended one accepted
[[noreturn]] void refuse(PyObject* f, const py::tuple& args, const py::dict& kwargs) {
  const function_record* head = record_of(f);
  std::string misfit;
  for (const function_record* rec = head; rec && !is_call_errors(*rec); rec = rec->next) {
    const Binding b = bind(*rec, args, kwargs);
    if (!b.misfit.empty()) {
      if (misfit.empty()) misfit = b.misfit;  // the first overload's reason
      continue;
    }
    // the call fits this overload's parameters: one of its values has a type pybind11 could not convert
    const auto types = annotations(rec->signature);
    for (const auto& [i, value] : b.bound) {
      if (i >= rec->args.size() || !rec->args[i].name) continue;
      const std::string name = rec->args[i].name;
      std::string expected;
      if (value.is_none() && !rec->args[i].none) py_io::throw_type_error(name, "a value other than None", value);
      if (types.count(name) && !converts(types.at(name), value, rec->scope, expected)) {
        py_io::throw_type_error(name, expected, value);
      }
    }
    misfit = "no signature accepts these argument types: " + std::string(rec->name) + rec->signature;
  }
  throw py::type_error(call_name(*head) + ": " + misfit);
}

// The positional arguments of a call: the first one (if any) and the rest
py::tuple positional(const AfterConversions& first, const py::args& rest) {
  if (first.first.is(no_argument())) return rest;
  return py::tuple(py::make_tuple(first.first) + rest);
}

// The C-level docstring of the pybind11 function f, as a string to put back
std::string doc_of(PyObject* f) {
  const char* doc = PYBIND11_PYCFUNCTION_GET_DOC(reinterpret_cast<PyCFunctionObject*>(f));
  return doc ? doc : "";
}

// Replaces it (as pybind11 does when an overload is added: the old string freed, a malloc'd one set)
void set_doc(PyObject* f, const std::string& doc) {
  auto* function = reinterpret_cast<PyCFunctionObject*>(f);
  char* text = static_cast<char*>(std::malloc(doc.size() + 1));
  if (!text) throw std::bad_alloc();
  std::memcpy(text, doc.c_str(), doc.size() + 1);
  std::free(const_cast<char*>(PYBIND11_PYCFUNCTION_GET_DOC(function)));
  PYBIND11_PYCFUNCTION_SET_DOC(function, text);
}

}  // namespace

const function_record* record_of(PyObject* f) {
  if (!PyCFunction_Check(f) || !PyCFunction_GET_SELF(f)) return nullptr;
  const function_record* rec = py::detail::function_record_ptr_from_PyObject(PyCFunction_GET_SELF(f));
  return rec && rec->name ? rec : nullptr;
}

bool is_call_errors(const function_record& rec) {
  const std::size_t i = rec.is_method ? 1 : 0;
  return rec.has_args && rec.has_kwargs && i < rec.args.size() && rec.args[i].name &&
         std::strcmp(rec.args[i].name, first_parameter) == 0;
}

void add_call_errors(PyObject* f) {
  const function_record* rec = record_of(f);
  if (!rec || rec->is_operator || (rec->name[0] == '_' && std::strcmp(rec->name, "__init__") != 0)) return;
  const std::string doc = doc_of(f);
  const py::handle function(f);
  if (rec->is_method) {
    py::cpp_function(
        [f](py::handle, AfterConversions first, const py::args& rest, const py::kwargs& kwargs) {
          refuse(f, positional(first, rest), kwargs);
        },
        py::name(rec->name), py::is_method(rec->scope), py::sibling(function),
        py::arg(first_parameter) = no_argument());
  } else {
    py::cpp_function(
        [f](AfterConversions first, const py::args& rest, const py::kwargs& kwargs) {
          refuse(f, positional(first, rest), kwargs);
        },
        py::name(rec->name), py::scope(rec->scope), py::sibling(function), py::arg(first_parameter) = no_argument());
  }
  set_doc(f, doc);  // pybind11 wrote the overloads' list
}

}  // namespace rigiddyn::bindings
