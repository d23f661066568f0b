// simulate's runs of a rigid body whose inertia needs FullEuler (run_rigid_body.hpp).
#include "run_rigid_body.hpp"

namespace rigiddyn {

template Trajectory run_rigid_body(double, const FullEuler&, const RigidBodyCoordinates&, const SimulationOptions&);

}  // namespace rigiddyn
