// The scene of one body in W that simulate and step of a body run (the one engine's view of a body): the body,
// a UniformGravity and a ScheduledLoads on it; and its layout (scene/one_body_layouts.hpp) built without the scene,
// for step, whose every call would otherwise pay a compile.
#pragma once
#include "rigiddyn/models/loads.hpp"
#include "rigiddyn/scene/one_body_layouts.hpp"
#include "rigiddyn/scene/scene.hpp"

#include <Eigen/Core>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigiddyn {

// The scene of `body` alone in W, with UniformGravity(g_W) when with_gravity and ScheduledLoads(body 0, loads)
// when with_loads. Throws std::invalid_argument naming "gravity" for a PlanarBody under gravity out of its plane
// (the plane would take it silently), "loads[i]..." for a load that is not finite or that the body's kind cannot
// take (a torque on a particle; out of the plane on a planar body).
Scene one_body_scene(const Body& body, const Eigen::Vector3d& g_W, const std::vector<AppliedLoad>& loads,
                     bool with_gravity, bool with_loads);

// The same, each element declared where it acts: the gravity when g_W is not zero, the loads when there are any
Scene one_body_scene(const Body& body, const Eigen::Vector3d& g_W, const std::vector<AppliedLoad>& loads);

// The layout compile_scene chooses for one_body_scene(body, g_W, loads) (a particle, a planar or a rigid body),
// built from the two terms alone: no Scene, no checks of a whole scene, no SceneModel (step of a body builds one
// whenever its body, gravity or loads change). Throws as one_body_scene.
OneBodyModel one_body_layout(const Body& body, const Eigen::Vector3d& g_W, const std::vector<AppliedLoad>& loads);

// The numbers one_body_scene(body, g_W, loads) of a particle, a planar or a rigid body is made of, written to `key`
// (its contents replaced): the body's kind, mass and inertia, g_W [m/s²], and each load's force, torque, frame and
// window. Keys with the same bits (same_one_body_key) give the same scene, its layout and its compiled model: what a
// caller that runs one body again and again keeps instead of building them anew. Throws std::invalid_argument for
// another kind (a pinned body's pivot and a gyrostat's wheels are not in the key).
void one_body_key(const Body& body, const Eigen::Vector3d& g_W, const std::vector<AppliedLoad>& loads,
                  std::vector<double>& key);

// Whether two keys of one_body_key hold the same numbers bit for bit (a zero's sign included, which a result may keep).
bool same_one_body_key(const std::vector<double>& a, const std::vector<double>& b);

// one_body_layout(body, g_W, loads) as its type Layout (an alternative of OneBodyModel's layouts, e.g.
// OneBodySceneModel<detail::RigidSlot<PrincipalEuler, detail::FirstPlace>, OneBodyElements::none>) with the loads' piece
// at t0 [s] set: a model to step directly with an integrator (Integrator::step(layout, y, h, work) from
// layout.coordinates({state}, t0)). Throws std::invalid_argument when the body's layout is of another type, and as
// one_body_scene.
template <class Layout>
Layout one_body_layout_as(const Body& body, const Eigen::Vector3d& g_W, const std::vector<AppliedLoad>& loads,
                          double t0 = 0.0) {
  const OneBodyModel one_body = one_body_layout(body, g_W, loads);
  const Layout* layout = one_body_model_if<Layout>(one_body);
  if (layout == nullptr) {
    throw std::invalid_argument(std::string("one_body_layout_as: the layout of this ") + kind_name(body) +
                                " under these elements is of another type than the one asked for");
  }
  Layout out = *layout;
  out.set_time(t0);
  return out;
}

// The layout of `body` (of a kind that has one: std::monostate otherwise) under the compiled gravity and loads (those
// present, with their indices among the scene's elements) (one_body_layout.cpp)
OneBodyModel one_body_layout_of(const Body& body, std::optional<UniformGravityTerm> gravity, int gravity_element,
                                std::optional<ScheduledLoadsTerm> loads, int loads_element);

}  // namespace rigiddyn
