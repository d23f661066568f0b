// simulate(..., tolerance=): its arguments, the methods it tries, and the Python side of the outcome (the class
// ToleranceChoice, result.choice, and the exception ToleranceError), shared by the runs of one body
// (bind_dynamics.cpp) and of a scene (bind_scene.cpp); bind_tolerance.cpp registers both.
#pragma once
#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "rigiddyn/simulate/tolerance.hpp"

namespace rigiddyn::bindings {

// The cost cap without max_steps=: ten million steps.
constexpr std::int64_t default_max_steps = 10'000'000;

// simulate's tolerance arguments, converted.
struct ToleranceArgs {
  double tolerance;        // in the measure's unit
  ErrorMeasure measure;
  double horizon;          // duration [s]
  std::int64_t max_steps;  // the cost cap
};

// The tolerance arguments, or nullopt when tolerance is None (then measure and max_steps must be None too).
// With a tolerance: dt and steps None, a duration > 0 and error True (ValueError naming the argument otherwise);
// measure None takes `default_measure`; a pint quantity is converted to the measure's unit.
std::optional<ToleranceArgs> as_tolerance_args(pybind11::handle tolerance, pybind11::handle measure,
                                               pybind11::handle max_steps, pybind11::handle dt,
                                               pybind11::handle steps, pybind11::handle duration,
                                               pybind11::handle error, ErrorMeasure default_measure);

// The methods a run to a tolerance tries when `method` is None, highest order first: rk4, rkmk4,
// splitting_dlm_yoshida4, splitting_dlm, exact_flow_kick, semi_implicit_euler_implicit_gyroscopic and exact (each
// kept only where the model takes it). explicit_euler and semi_implicit_euler are left out (unstable on a fast
// spin), implicit_midpoint too (order 2 at the cost of order 4).
std::vector<Method> tolerance_methods();

// The ToleranceError for an unmet tolerance: its message is choice.reason, with the figures; its attributes
// choice (a ToleranceChoice), error (the certified, else predicted, error), tolerance, measure and result (the best
// run, or None).
[[noreturn]] void raise_tolerance_error(const ToleranceChoice& choice, pybind11::object result);

// A refusal before any run (a force the core cannot see into): ToleranceError naming `what` and why.
[[noreturn]] void refuse_tolerance(const std::string& what, const std::string& why);

}  // namespace rigiddyn::bindings
