// The runs of the one-body layouts of a rigid body of the spherical Euler form (simulate/run_one_body.hpp; one
// translation unit per form: the compiler inlines each layout's steps whole).
#include "run_one_body.hpp"

namespace rigiddyn {

using RigidSpherical1 = detail::RigidSlot<SphericalEuler, detail::FirstPlace>;

RIGIDDYN_RUN_ONE_BODY(RigidSpherical1, none)
RIGIDDYN_RUN_ONE_BODY(RigidSpherical1, gravity)
RIGIDDYN_RUN_ONE_BODY(RigidSpherical1, gravity_and_loads)

}  // namespace rigiddyn
