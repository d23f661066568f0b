// Methods that take the same steps on a scene whose bodies do not turn in 3D.
//
// The Lie-group methods differ from their plain forms only in how they move attitudes on SO(3): rkmk4 corrects
// rk4's stages by dexp⁻¹ and retracts by the exponential map (Munthe-Kaas), exact_flow_kick drifts by the exact
// torque-free rotation where splitting_dlm drifts by the DLM splitting's rotations (Celledoni et al.). A particle
// has no attitude, and a planar body (pivoted or not) turns about W's z axis alone, its attitude one angle θ whose
// exponential map is θ + Θ: on such bodies dexp⁻¹ is the identity and every rotation flow is θ += h ω, so that each
// Lie-group method takes its plain form's steps (up to the rounding of the operations the two order differently).
#pragma once
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/scene/body.hpp"

#include <algorithm>
#include <optional>
#include <vector>

namespace rigiddyn {

// The plain method `method` is on `bodies` (rk4 for rkmk4, splitting_dlm for exact_flow_kick) where none of them
// turns in 3D (each a particle or a planar body); none for another method or where a body turns in 3D.
inline std::optional<Method> plain_twin(Method method, const std::vector<Body>& bodies) {
  const bool turns_in_3d =
      std::any_of(bodies.begin(), bodies.end(), [](const Body& b) { return has_attitude(b) && !is_planar(b); });
  if (turns_in_3d) return std::nullopt;
  if (method == Method::rkmk4) return Method::rk4;
  if (method == Method::exact_flow_kick) return Method::splitting_dlm;
  return std::nullopt;
}

}  // namespace rigiddyn
