// The steps of the fast one-body models (scene/fast/; their runs are simulate_scene.cpp's), as the layouts' steps
// (simulate/run_one_body.hpp).
#include "run_one_body.hpp"

namespace rigiddyn {

#define RIGIDDYN_STEP_FAST_MODEL(MODEL)                                                                           \
  template SceneState detail::step_one_body(const MODEL&, const std::vector<BodyState>&, const SimulationOptions&,  \
                                            const std::vector<AppliedLoad>&);                                       \
  template BodyState detail::step_one_body_state(const MODEL&, const std::vector<BodyState>&, const SimulationOptions&, \
                                                 const std::vector<AppliedLoad>&);

RIGIDDYN_STEP_FAST_MODEL(PivotedBodyModel<SphericalEuler>)
RIGIDDYN_STEP_FAST_MODEL(PivotedBodyModel<PrincipalEuler>)
RIGIDDYN_STEP_FAST_MODEL(PivotedBodyModel<FullEuler>)
RIGIDDYN_STEP_FAST_MODEL(RotatingFrameParticleModel)
RIGIDDYN_STEP_FAST_MODEL(VariableMassParticleModel)

#undef RIGIDDYN_STEP_FAST_MODEL

}  // namespace rigiddyn
