// The runs of the one-body layouts of a rigid body, one per Euler form (simulate/run_one_body.hpp).
#include "run_one_body.hpp"

namespace rigiddyn {

using Spherical1 = detail::RigidSlot<SphericalEuler, detail::FirstPlace>;
using Principal1 = detail::RigidSlot<PrincipalEuler, detail::FirstPlace>;
using Full1 = detail::RigidSlot<FullEuler, detail::FirstPlace>;

RIGIDDYN_RUN_ONE_BODY(Spherical1, none)
RIGIDDYN_RUN_ONE_BODY(Spherical1, gravity)
RIGIDDYN_RUN_ONE_BODY(Spherical1, gravity_and_loads)
RIGIDDYN_RUN_ONE_BODY(Principal1, none)
RIGIDDYN_RUN_ONE_BODY(Principal1, gravity)
RIGIDDYN_RUN_ONE_BODY(Principal1, gravity_and_loads)
RIGIDDYN_RUN_ONE_BODY(Full1, none)
RIGIDDYN_RUN_ONE_BODY(Full1, gravity)
RIGIDDYN_RUN_ONE_BODY(Full1, gravity_and_loads)

}  // namespace rigiddyn
