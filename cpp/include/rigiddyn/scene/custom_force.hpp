// A user force compiled into the model: CustomForce<F> holds any C++ callable F,
// called directly (no std::function, no virtual call: the compiler can inline it) once per listed body
// per evaluation. Run it with simulate(scene, initial, options, custom_force...) (simulate_scene.hpp).
// FunctionForce (scene/elements/function_force.hpp) is the type-erased form for bindings.
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_bodies.hpp"
#include "rigiddyn/scene/element_traits.hpp"
#include "rigiddyn/scene/elements/function_force.hpp"  // detail::add_callable_wrenches

#include <Eigen/Core>

#include <string>
#include <vector>

namespace rigiddyn {

// The spec: f(t [s], const BodyKinematics& body, int index, Eigen::Vector3d& f_W, Eigen::Vector3d& tau_B)
// sets the force f_W [N] (in W, at the centre of mass) and the torque tau_B [N m] (about the centre of
// mass, in B) on body `index` (both arrive zeroed), for every body of `bodies` (empty: every body).
// `traits` declares what f depends on (scene/element_traits.hpp; by default everything, no potential):
// the compatibility checks of compile read it.
template <class F>
struct CustomForce {
  BodyList bodies;
  F f;
  ElementTraits traits{true, true, true, false, true};
};

// Deduces F: custom_force(bodies, f) or custom_force(bodies, f, traits).
template <class F>
CustomForce<F> custom_force(BodyList bodies, F f, ElementTraits traits = ElementTraits{true, true, true, false, true}) {
  return CustomForce<F>{std::move(bodies), std::move(f), traits};
}

// The compiled term (the term concept of scene/element_traits.hpp).
template <class F>
class CustomForceTerm {
 public:
  // Throws std::invalid_argument "<name>.bodies[k]: ..." for an index out of range or repeated.
  CustomForceTerm(const CustomForce<F>& spec, const std::vector<Body>& bodies, const std::string& name)
      : f_(spec.f), traits_(spec.traits), bodies_(detail::resolve_bodies(spec.bodies, bodies.size(), name)) {}

  ElementTraits traits() const { return traits_; }

  // Adds f's force and torque to each listed body; returns Σ f_W·v_W + tau_B·w_B [W].
  double add_wrenches(double t, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    return detail::add_callable_wrenches(f_, bodies_, t, kinematics, wrenches);
  }

  double potential(const std::vector<BodyKinematics>& /*kinematics*/) const { return 0.0; }

 private:
  F f_;
  ElementTraits traits_;
  std::vector<int> bodies_;
};

}  // namespace rigiddyn
