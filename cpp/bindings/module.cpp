// rigiddyn._core: the compiled core. Users import `rigiddyn`, which re-exports it.
#include "bindings.hpp"
#include "fast_call.hpp"
#include "pivoted.hpp"
#include "scene_run.hpp"
#include "rigiddyn/version.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "rigiddyn's C++ core (rotations, frames, spatial algebra, inertia, dynamics, orbits).";
  m.attr("__version__") = rigiddyn::version();
  rigiddyn::bindings::keep_freed_heap_for_reuse();
  rigiddyn::bindings::bind_so3(m);
  rigiddyn::bindings::bind_so3_ops(m);
  rigiddyn::bindings::bind_frames(m);
  rigiddyn::bindings::bind_spatial(m);
  rigiddyn::bindings::bind_inertia(m);
  rigiddyn::bindings::bind_bodies(m);
  rigiddyn::bindings::bind_pivoted(m);
  rigiddyn::bindings::bind_gyrostat(m);
  rigiddyn::bindings::bind_scene_elements(m);
  rigiddyn::bindings::bind_scene_frame(m);
  rigiddyn::bindings::bind_tolerance(m);  // before bind_scene and bind_dynamics: results hold a ToleranceChoice
  rigiddyn::bindings::bind_scene(m);  // before bind_dynamics: simulate's signature names SceneResult
  rigiddyn::bindings::bind_body_records(m);  // after bind_scene: it adds SceneResult.body
  rigiddyn::bindings::bind_dynamics(m);
  rigiddyn::bindings::bind_batch(m);
  rigiddyn::bindings::bind_exact(m);
  rigiddyn::bindings::bind_exact_dynamics(m);
  rigiddyn::bindings::bind_orbit(m);
  rigiddyn::bindings::bind_tree(m);
  rigiddyn::bindings::bind_tree_link(m);  // after bind_tree: it adds Tree.joint_states
  rigiddyn::bindings::mark_made_by_the_core(m);  // after every class it names
  rigiddyn::bindings::add_text_signatures(m);  // every function and class registered
  rigiddyn::bindings::install_fast_calls(m);  // last: the quick fronts take the docstrings with their signatures
}
