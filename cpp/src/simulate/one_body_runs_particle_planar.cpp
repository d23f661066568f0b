// The runs of the one-body layouts of a particle and of a planar body (simulate/run_one_body.hpp).
#include "run_one_body.hpp"

namespace rigiddyn {

using Particle1 = detail::ParticleSlot<detail::FirstPlace>;
using Planar1 = detail::PlanarSlot<detail::FirstPlace>;

RIGIDDYN_RUN_ONE_BODY(Particle1, none)
RIGIDDYN_RUN_ONE_BODY(Particle1, gravity)
RIGIDDYN_RUN_ONE_BODY(Particle1, gravity_and_loads)
RIGIDDYN_RUN_ONE_BODY(Planar1, none)
RIGIDDYN_RUN_ONE_BODY(Planar1, gravity)
RIGIDDYN_RUN_ONE_BODY(Planar1, gravity_and_loads)

}  // namespace rigiddyn
