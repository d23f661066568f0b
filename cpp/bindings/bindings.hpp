// One registration function per layer, each in its own bind_<layer>.cpp; module.cpp calls them.
#pragma once
#include <pybind11/pybind11.h>

namespace rigiddyn::bindings {
void bind_so3(pybind11::module_& m);
void bind_so3_ops(pybind11::module_& m);
void bind_frames(pybind11::module_& m);
void bind_spatial(pybind11::module_& m);
void bind_inertia(pybind11::module_& m);
void bind_bodies(pybind11::module_& m);
void bind_gyrostat(pybind11::module_& m);  // after bind_bodies: a Gyrostat holds a RigidBody
// True for a Gyrostat; the one-body Scene simulate/step run for it: the body, UniformGravity(gravity) when gravity is
// not zero and ScheduledLoads(body=0, loads) when loads are given (bind_gyrostat.cpp)
bool is_gyrostat(pybind11::handle body);
pybind11::object gyrostat_scene(pybind11::handle model, pybind11::handle loads, pybind11::handle gravity);
void bind_tolerance(pybind11::module_& m);  // ToleranceChoice, ToleranceError (tolerance_run.hpp)
void bind_dynamics(pybind11::module_& m);
void bind_exact(pybind11::module_& m);
void bind_exact_dynamics(pybind11::module_& m);  // after bind_pivoted and bind_scene_frame
void bind_scene_elements(pybind11::module_& m);
void bind_scene(pybind11::module_& m);
void bind_body_records(pybind11::module_& m);  // after bind_scene: it adds SceneResult.body
void bind_batch(pybind11::module_& m);  // after bind_body_records: result.body gives BodyRecords
void bind_orbit(pybind11::module_& m);
void bind_tree(pybind11::module_& m);  // after bind_spatial and bind_inertia: a link holds a Transform and a SpatialInertia
void bind_tree_link(pybind11::module_& m);  // after bind_tree: TreeLink, JointState, Tree.joint_states
// The classes only the core makes: calling one raises TypeError naming what makes it (made_by_the_core.cpp)
void mark_made_by_the_core(pybind11::module_& m);
// glibc's malloc settings keeping the freed heap for the next runs (heap_reuse.cpp), unless the user chose them
void keep_freed_heap_for_reuse();
// Last: the runtime signatures (__text_signature__, a class's __signature__) of every function and class in m
void add_text_signatures(pybind11::module_& m);
}  // namespace rigiddyn::bindings
