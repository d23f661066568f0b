// The order of accuracy a compiled scene actually has with its method: the method's order (method.hpp), except
// that the kick-based splittings (splitting_dlm, splitting_dlm_yoshida4, exact_flow_kick) fall to order 1 with a
// velocity-dependent element (drag, dampers, a PythonForce, which is treated as one): their kicks freeze the
// velocities. The Coriolis term of a moving frame is the exception: its kick takes the exact flow
// (so3/coriolis_flow.hpp), so the splittings keep their order with it.
#pragma once
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/element_traits.hpp"

#include <string>

namespace rigiddyn {

// True if `method` kicks with frozen velocities, so that an element of `traits` lowers it to order 1.
bool kick_freezes_velocities(Method method, const ElementTraits& traits);

// The global order of `compiled` under its method (0 for 'exact').
int scene_order(const CompiledScene& compiled);
// The global order of `compiled`'s scene under `method` (its elements' traits do not depend on the method it was
// compiled for), without compiling it for `method`.
int scene_order(const CompiledScene& compiled, Method method);

// The name of the first force the core cannot see into ("elements[i] (PythonForce)": a FunctionForce, which may
// switch inside a step, e.g. with an `if t > t_s`), "" when there is none. A switch inside a step costs every
// method its order there, and the nested grids h, 2h, 4h of a Richardson estimate can share the step the switch
// falls in, so that the estimate misses that error while its order check passes (global_error.hpp).
std::string opaque_force(const CompiledScene& compiled);

}  // namespace rigiddyn
