// A quick front for a module function called in a loop (step, simulate): pybind11's dispatcher looks up each
// parameter not given by position among a call's keywords by interning the parameter's C string (a new str, its
// hash and a dict lookup: about 0.1 µs a parameter, 1.3 µs for simulate's 17), so a keyword call costs well
// above a positional one. FastCall<fn, N> replaces the module's pybind11 function of N py::handle parameters by
// a built-in with the same docstring, text signature and record (inspect, help() and pickling see no change)
// that maps keywords to parameters by comparing pointers to names interned once, fills the defaults from
// pybind11's record and calls fn directly. A call it does not take as it is (too many positional arguments, an
// unknown or repeated keyword, a required argument missing) goes to the pybind11 function, which raises its
// usual error; an exception from fn is translated as pybind11 translates it.
#pragma once
#include <pybind11/pybind11.h>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

namespace rigiddyn::bindings {

// Replaces each function registered with FastCall::add by its quick front; called once every binding and text
// signature is in place (module.cpp). Does nothing under RIGIDDYN_STUBGEN=1: the stub is generated from the
// pybind11 functions themselves.
void install_fast_calls(pybind11::module_& m);

// Registers `install` to run in install_fast_calls.
void register_fast_call(void (*install)(pybind11::module_&));

// The number of parameters of a function
template <class R, class... A>
constexpr std::size_t parameter_count(R (*)(A...)) {
  return sizeof...(A);
}

template <auto Fn, std::size_t N = parameter_count(Fn)>
class FastCall {
 public:
  // Registers the module function `name` (bound to Fn, N parameters) for install_fast_calls.
  static void add(const char* name) {
    name_ = name;
    register_fast_call(&install);
  }

 private:
  static void install(pybind11::module_& m) {
    namespace py = pybind11;
    PyObject* checked = m.attr(name_).ptr();
    PyObject* self = PyCFunction_Check(checked) ? PyCFunction_GET_SELF(checked) : nullptr;
    const py::detail::function_record* rec = self ? py::detail::function_record_ptr_from_PyObject(self) : nullptr;
    if (rec == nullptr || rec->nargs != N || rec->has_args || rec->has_kwargs) {
      throw std::logic_error(std::string("FastCall: ") + name_ + " is not a pybind11 function of its parameters");
    }
    Py_INCREF(checked);  // kept for the process: it owns the record, the defaults and the docstring
    checked_ = checked;
    for (std::size_t i = 0; i < N; ++i) {
      names_[i] = PyUnicode_InternFromString(rec->args[i].name);  // kept for the process
      if (names_[i] == nullptr) throw py::error_already_set();
      defaults_[i] = rec->args[i].value.ptr();
    }
    positional_ = rec->nargs_pos;
    def_ = {name_, reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&call)), METH_FASTCALL | METH_KEYWORDS,
            PYBIND11_PYCFUNCTION_GET_DOC(reinterpret_cast<PyCFunctionObject*>(checked))};
    PyObject* quick = PyCFunction_NewEx(&def_, self, m.attr("__name__").ptr());
    if (quick == nullptr) throw py::error_already_set();
    m.attr(name_) = py::reinterpret_steal<py::object>(quick);
  }

  // The vectorcall of the built-in: arguments by position, then the values of the keywords `kwnames`.
  static PyObject* call(PyObject*, PyObject* const* args, Py_ssize_t nargsf, PyObject* kwnames) {
    namespace py = pybind11;
    const auto given = static_cast<std::size_t>(PyVectorcall_NARGS(nargsf));
    if (given > positional_) return PyObject_Vectorcall(checked_, args, nargsf, kwnames);
    std::array<PyObject*, N> full{};
    for (std::size_t i = 0; i < given; ++i) full[i] = args[i];
    const Py_ssize_t keywords = kwnames ? PyTuple_GET_SIZE(kwnames) : 0;
    for (Py_ssize_t k = 0; k < keywords; ++k) {
      const std::size_t i = parameter_of(PyTuple_GET_ITEM(kwnames, k));
      if (i == N || full[i] != nullptr) return PyObject_Vectorcall(checked_, args, nargsf, kwnames);
      full[i] = args[given + static_cast<std::size_t>(k)];
    }
    for (std::size_t i = 0; i < N; ++i) {
      if (full[i] == nullptr) full[i] = defaults_[i];
      if (full[i] == nullptr) return PyObject_Vectorcall(checked_, args, nargsf, kwnames);
    }
    try {
      return invoke(full, std::make_index_sequence<N>{});
    } catch (py::error_already_set& e) {
      e.restore();
      return nullptr;
    } catch (...) {
      py::detail::try_translate_exceptions();
      return nullptr;
    }
  }

  // The parameter a keyword names (N for none): its interned name's pointer, else an equal string.
  static std::size_t parameter_of(PyObject* keyword) {
    for (std::size_t i = 0; i < N; ++i) {
      if (names_[i] == keyword) return i;
    }
    for (std::size_t i = 0; i < N; ++i) {
      if (PyUnicode_Compare(names_[i], keyword) == 0) return i;
    }
    PyErr_Clear();  // a keyword that is no str: the pybind11 function says so
    return N;
  }

  template <std::size_t... I>
  static PyObject* invoke(const std::array<PyObject*, N>& full, std::index_sequence<I...>) {
    pybind11::object result = Fn(pybind11::handle(full[I])...);
    return result.release().ptr();
  }

  static inline const char* name_ = nullptr;
  static inline PyObject* checked_ = nullptr;
  static inline std::array<PyObject*, N> names_{};
  static inline std::array<PyObject*, N> defaults_{};
  static inline std::size_t positional_ = 0;
  static inline PyMethodDef def_{};
};

}  // namespace rigiddyn::bindings
