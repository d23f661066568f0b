// The seams between the scene bindings (bind_scene.cpp, bind_scene_elements.cpp) and simulate/step of
// bind_dynamics.cpp, which route a Scene or a CompiledScene here.
#pragma once
#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "numpy_io.hpp"
#include "python_run.hpp"
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/models/loads.hpp"
#include "rigiddyn/scene/scene.hpp"

namespace rigiddyn {
class CompiledScene;  // rigiddyn/scene/compile.hpp
}  // namespace rigiddyn

namespace rigiddyn::bindings {

// A force element given from Python as the C++ Element (TypeError naming `name` for anything else), and
// back (a new Python object holding a copy); the Python class name of an element ("Drag", "PythonForce").
Element as_element(pybind11::handle obj, const std::string& name);
pybind11::object element_object(const Element& element);
std::string element_kind(const Element& element);

// The scene's frame and a body's mass flow given from Python (bind_scene_frame.cpp): a SceneFrame, a MassFlow
// or None (nullopt), else TypeError naming `name`; bind_scene_frame registers both classes.
SceneFrame as_scene_frame(pybind11::handle obj, const std::string& name);
std::optional<MassFlow> as_mass_flow(pybind11::handle obj, const std::string& name);
void bind_scene_frame(pybind11::module_& m);

// simulate's records of a scene (rigiddyn.SceneResult; its docstring in bind_scene.cpp).
struct SceneResult {
  LazyArray t, p_W, q_WB, v_W, w_B, kinetic_energy, potential_energy, total_energy, linear_momentum_W,
      angular_momentum_W, pivot_reaction_W, angular_momentum_O_W, mass, work, power, mass_flow_energy;
  pybind11::tuple body_names, elements;
  LazyArray wheel_speed;         // (n, nw) each gyrostat wheel's speed relative to its body [rad/s]
  LazyArray motor_work;          // (n, nw) each wheel's motor work since t0 [J]
  pybind11::tuple wheel_bodies;  // (nw,) the body index of each wheel
  LazyArray joint_q;             // (n, nq) the trees' configurations q (empty without a tree)
  LazyArray joint_v;             // (n, nv) their velocities v
  bool diverged;
  std::int64_t unconverged_steps;
  double elapsed_seconds;
  bool scalar_first = false;  // q_WB rows as (w, x, y, z)
  LazyError error{};  // a GlobalError (simulate(..., error=True)) or None
  LazyBalance balance{};  // a rigiddyn.Balance (every simulate run) or None (a batch result)
  pybind11::object choice = pybind11::none();  // a ToleranceChoice (simulate(..., tolerance=...)) or None
};

// simulate's arguments of a run to a tolerance (tolerance_run.hpp), as given.
struct ToleranceHandles {
  pybind11::handle tolerance, measure, max_steps;
};

// The body index of each gyrostat wheel of the scene, in the order of SceneSimulation::wheel_speed's columns.
pybind11::tuple wheel_bodies_of(const Scene& scene);

// The one-body Scene of simulate/step of a body (rigiddyn::one_body_scene: UniformGravity(g_W) when g_W is not zero and
// ScheduledLoads(body=0, loads) when loads are given), as a Python Scene.
pybind11::object one_body_scene(const Body& body, const Eigen::Vector3d& g_W, pybind11::handle loads);

// A compiled scene as Python holds it (rigiddyn.CompiledScene): the scene it came from (attributes, pickle), the method
// and the immutable C++ model, shared (never copied) by the runs.
struct CompiledSceneHandle {
  Scene scene;
  Method method;
  std::shared_ptr<const CompiledScene> compiled;
};

// What simulate of a particle, a planar body or a rigid body runs as its one-body scene: the body, uniform gravity
// g_W [m/s²] and the applied loads (converted from Python; the core checks them when it builds the scene).
struct OneBodyInputs {
  Body body;
  Eigen::Vector3d g_W;
  std::vector<AppliedLoad> loads;
};

// True for a Scene or a CompiledScene.
bool is_scene(pybind11::handle model);
// rigiddyn.simulate and rigiddyn.step of a Scene or a CompiledScene (their arguments as documented there); simulate
// of a body's one-body scene with `body` given (`model` the body, `initial` a tuple of its state, loads and gravity
// None: those are in `body`). Returns the SceneResult's Python object (its balance made and checked in the core,
// balance.hpp).
pybind11::object simulate_scene_py(pybind11::handle model, pybind11::handle initial, pybind11::handle dt,
                                   pybind11::handle steps, pybind11::handle method, pybind11::handle record_every,
                                   pybind11::handle loads, pybind11::handle gravity, pybind11::handle t0,
                                   pybind11::handle scalar_first, pybind11::handle progress,
                                   pybind11::handle duration, pybind11::handle error, pybind11::handle accuracy_level,
                                   const ToleranceHandles& to, pybind11::handle controller,
                                   const OneBodyInputs* body = nullptr);
pybind11::object step_scene_py(pybind11::handle model, pybind11::handle state, pybind11::handle dt,
                               pybind11::handle method, pybind11::handle loads, pybind11::handle gravity,
                               pybind11::handle t);

}  // namespace rigiddyn::bindings
