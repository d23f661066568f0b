// The seams between the bindings of the bodies about a fixed point (bind_pivoted.cpp) and the entry points
// that take any body: forward_dynamics / inverse_dynamics (bind_bodies.cpp), simulate / step
// (bind_dynamics.cpp) and the scene's bodies (bind_scene.cpp).
#pragma once
#include <pybind11/pybind11.h>

#include <string>

namespace rigiddyn::bindings {

// Registers PivotedBody, PivotedPlanarBody, their states and the results of their dynamics (after bind_bodies:
// PivotedBody holds a RigidBody).
void bind_pivoted(pybind11::module_& m);

// True for a PivotedBody or a PivotedPlanarBody.
bool is_pivoted(pybind11::handle body);

// rigiddyn.forward_dynamics / inverse_dynamics of a pivoted `body` (their arguments as documented there;
// pivoted_dynamics_doc below): a PivotedAcceleration / PivotedPlanarAcceleration, a PivotedTorque /
// PivotedPlanarTorque.
pybind11::object pivoted_forward_dynamics_py(pybind11::handle body, pybind11::handle state, pybind11::handle force,
                                             pybind11::handle torque, pybind11::handle point, pybind11::handle frame,
                                             pybind11::handle gravity);
pybind11::object pivoted_inverse_dynamics_py(pybind11::handle body, pybind11::handle state, pybind11::handle a_W,
                                             pybind11::handle alpha_B, pybind11::handle gravity);
extern const char* const pivoted_forward_dynamics_doc;
extern const char* const pivoted_inverse_dynamics_doc;

// The one-body Scene simulate/step run for a pivoted `model`: the body, UniformGravity(gravity) when
// gravity is not zero and ScheduledLoads(body=0, loads) when loads are given (argument names `gravity`,
// `loads` in the messages). A pivoted planar body takes an in-plane gravity, (2,) or (3,) [m/s^2] in W.
pybind11::object pivoted_scene(pybind11::handle model, pybind11::handle loads, pybind11::handle gravity);

}  // namespace rigiddyn::bindings
