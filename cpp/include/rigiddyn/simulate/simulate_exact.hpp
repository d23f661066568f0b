// simulate with Method::exact on a rigid body: no time stepping; the closed-form torque-free motion
// (exact/free_body.hpp) evaluated at each record time t_i = t0 + i dt, so the error stays at
// round-off level (~eps × turned angle) however large dt and the run. The centre of mass moves
// ballistically, p = p0 + v0 t + ½ a t², v = v0 + a t, a = f_W/m + g (exact under a constant
// world-frame force); work(t) = m a·(p − p0).
#pragma once
#include "rigiddyn/simulate/simulate.hpp"

namespace rigiddyn {

// The Trajectory simulate(body, initial, options) returns for options.method == Method::exact
// (options already checked by simulate). Throws std::invalid_argument naming the load for a torque
// ("loads[i].torque"), a body-frame force ("loads[i].force") or a schedule that is not constant
// from t0 ("loads"): the exact method covers torque-free bodies under constant world-frame forces.
Trajectory simulate_exact(const RigidBody& body, const RigidBodyState& initial, const SimulationOptions& options);

}  // namespace rigiddyn
