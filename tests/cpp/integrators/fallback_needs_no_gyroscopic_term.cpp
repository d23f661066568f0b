// The fallbacks of the structure-preserving methods (velocity Verlet, its triple jump, the midpoint's
// fixed point) have no gyroscopic term: each asserts at compile time that the model it gets has none.
// Built twice by CMakeLists.txt: with GYROSCOPIC=0 (a particle-like model without the term) it must
// compile; with GYROSCOPIC=1 (the same model declaring the term, as a rigid-body model would that
// the method's rigid-body branch failed to match) the build of METHOD must stop at the static_assert.
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/models/particle.hpp"

#include <type_traits>

struct ParticleLikeModel : rigiddyn::ParticleModel {
  using rigiddyn::ParticleModel::ParticleModel;
};

namespace rigiddyn {
template <>
struct has_gyroscopic_term<ParticleLikeModel> : std::bool_constant<GYROSCOPIC != 0> {};
}  // namespace rigiddyn

void step_once() {
  const ParticleLikeModel model(rigiddyn::Particle(1.0));
  ParticleLikeModel::Coordinates y = ParticleLikeModel::Coordinates::Zero();
  rigiddyn::METHOD::step(model, y, 0.1);
}
