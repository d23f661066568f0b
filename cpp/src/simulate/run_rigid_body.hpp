// Private to cpp/src/simulate: the definition of run_rigid_body (append_record.hpp), instantiated per Euler
// form by simulate.cpp (spherical, principal) and simulate_rigid_full.cpp.
#pragma once
#include "append_record.hpp"

namespace rigiddyn {

template <class Euler>
Trajectory run_rigid_body(double mass, const Euler& euler, const RigidBodyCoordinates& y, const SimulationOptions& o) {
  return visit_method(o.method, [&](auto integrator) {
    // every method runs on a model compiled for the loads of this run (LoadKind)
    return with_load_kind(o.loads, o.gravity_W, [&](auto kind) {
      return run_one_body<decltype(integrator)>(RigidBodyModel<Euler, kind.value>(mass, euler, o.gravity_W), y, o);
    });
  });
}

}  // namespace rigiddyn
