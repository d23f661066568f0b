// The registry of fixed-step methods: a runtime Method, its metadata (name, order, derivative
// evaluations per step, what it conserves) and the single switch from a Method to the compiled
// integrator (visit_method), used once at the top of `step` and `simulate`, never inside a loop.
//
// Adding a method: write integrators/<method>.hpp (a struct with its scratch vectors
//   template <class Model> struct Workspace (or NoWorkspace; integrators/workspace.hpp)
// and its step
//   template <class Model> static void step(const Model&, typename Model::Coordinates&, double h, Workspace<Model>&)
// against models/model_interface.hpp), add an enumerator, a row of method_table() and a case in
// visit_method.
#pragma once
#include "rigiddyn/integrators/exact_flow_kick.hpp"
#include "rigiddyn/integrators/explicit_euler.hpp"
#include "rigiddyn/integrators/implicit_midpoint.hpp"
#include "rigiddyn/integrators/rk4.hpp"
#include "rigiddyn/integrators/rkmk4.hpp"
#include "rigiddyn/integrators/semi_implicit_euler.hpp"
#include "rigiddyn/integrators/splitting_dlm.hpp"
#include "rigiddyn/integrators/yoshida4.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace rigiddyn {

enum class Method {
  explicit_euler,
  semi_implicit_euler,
  semi_implicit_euler_implicit_gyroscopic,
  rk4,
  rkmk4,
  implicit_midpoint,
  splitting_dlm,
  splitting_dlm_yoshida4,
  exact_flow_kick,
  exact,
};

struct MethodInfo {
  Method method;
  std::string name;       // snake_case, as in Python
  int order;              // global order of accuracy (0 for "exact": no truncation error)
  int evaluations;        // derivative evaluations per step
  std::string conserves;  // what the method keeps exactly on a free rigid body
  std::string notes;      // known behaviour
  // Largest dt·|ω| [rad] (|ω| the largest body rate along the torque-free orbit) for which the method
  // is documented stable on a free spin: +inf if unconditionally stable, 0 if no step is (explicit
  // gyroscopic terms gain energy at every step). Beyond it the documented conservation is lost.
  double stability_limit;
  // True if the method reproduces torque-free motion exactly (to round-off) at any dt, so that on a
  // torque-free body its error does not shrink with dt and no observed order applies.
  bool exact_torque_free;
};

// Every method, in Method's order.
const std::vector<MethodInfo>& method_table();
// The row of method_table() for `method`.
const MethodInfo& method_info(Method method);
// The Method named `name`; throws std::invalid_argument naming `argument` for an unknown name.
Method method_from_name(const std::string& name, const std::string& argument = "method");

// Calls f(Integrator{}) with the integrator type of `method`.
template <class F>
decltype(auto) visit_method(Method method, F&& f) {
  switch (method) {
    case Method::explicit_euler: return f(ExplicitEuler{});
    case Method::semi_implicit_euler: return f(SemiImplicitEuler{});
    case Method::semi_implicit_euler_implicit_gyroscopic: return f(SemiImplicitEulerImplicitGyroscopic{});
    case Method::rk4: return f(Rk4{});
    case Method::rkmk4: return f(Rkmk4{});
    case Method::implicit_midpoint: return f(ImplicitMidpoint{});
    case Method::splitting_dlm: return f(SplittingDlm{});
    case Method::splitting_dlm_yoshida4: return f(Yoshida4{});
    case Method::exact_flow_kick: return f(ExactFlowKick{});
    case Method::exact: return f(ExactFreeFlow{});
  }
  throw std::invalid_argument("method: expected a rigiddyn::Method, got " + std::to_string(static_cast<int>(method)));
}

}  // namespace rigiddyn
