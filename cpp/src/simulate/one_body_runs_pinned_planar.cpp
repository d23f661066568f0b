// The runs of the one-body layouts of a pinned planar body (simulate/run_one_body.hpp).
#include "run_one_body.hpp"

namespace rigiddyn {

using PinnedPlanar1 = detail::PivotedPlanarSlot<detail::FirstPlace>;

RIGIDDYN_RUN_ONE_BODY(PinnedPlanar1, none)
RIGIDDYN_RUN_ONE_BODY(PinnedPlanar1, gravity)
RIGIDDYN_RUN_ONE_BODY(PinnedPlanar1, gravity_and_loads)

}  // namespace rigiddyn
