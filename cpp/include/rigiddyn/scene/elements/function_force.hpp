// A user force, type-erased: a std::function called once per listed body per evaluation with the time
// and the body's kinematics, returning a force f_W [N] (in W, at the centre of mass) and a torque tau_B
// [N m] (about the centre of mass, in B). The Python binding wraps a Python callable in it (holding the
// GIL in its call). C++ users who want no indirect call use CustomForce<F> (owner: the scene runner).
// The term knows nothing of the function, so it declares every dependence and no potential.
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_bodies.hpp"
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/element_traits.hpp"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <tuple>
#include <vector>

namespace rigiddyn {

namespace detail {

// Adds f's force and torque to each body of `bodies` (f(t, kinematics, index, f_W, tau_B) with both
// outputs zeroed first); returns Σ f_W·v_W + tau_B·w_B [W]. Shared by FunctionForceTerm and
// CustomForceTerm<F> (scene/custom_force.hpp), which differ only in how f is held.
template <class F>
double add_callable_wrenches(const F& f, const std::vector<int>& bodies, double t,
                             const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) {
  double power = 0.0;
  for (const int b : bodies) {
    Eigen::Vector3d f_W = Eigen::Vector3d::Zero(), tau_B = Eigen::Vector3d::Zero();
    f(t, kinematics[b], b, f_W, tau_B);
    wrenches[b].f_W += f_W;
    wrenches[b].tau_B += tau_B;
    power += f_W.dot(kinematics[b].v_W) + tau_B.dot(kinematics[b].w_B);
  }
  return power;
}

}  // namespace detail

// f(t [s], kinematics of the body, its index in the scene, f_W out, tau_B out): both outputs arrive zeroed.
using ForceFunction = std::function<void(double t, const BodyKinematics& body, int index, Eigen::Vector3d& f_W,
                                         Eigen::Vector3d& tau_B)>;

// The spec: the user function `f` applied to `bodies` (empty: every body), and the name the element goes by in
// records and messages (element_type_name: compile's warnings and refusals, the work and power columns' labels).
// The Python binding sets "PythonForce", its class's name, so that a Python user meets one name everywhere.
class FunctionForceTerm;

struct FunctionForce {
  static constexpr const char* element_type = "FunctionForce";  // the default of type_name
  static constexpr bool keyword_only = false;  // PythonForce(fn) reads well
  using Term = FunctionForceTerm;  // what compile makes of it
  BodyList bodies;
  ForceFunction f;
  std::string type_name = element_type;

  // the field table (scene/element_fields.hpp): the function first, as the Python class takes it
  static constexpr auto fields() {
    return std::make_tuple(ElementField<FunctionForce, ForceFunction>{"fn", &FunctionForce::f, FieldKind::callable, "",
                                                                      "a callable fn(t, body, p_W, q_WB, v_W, w_B) -> "
                                                                      "(f_W, tau_B)"}
                               .must_be_given(),
                           bodies_field(&FunctionForce::bodies));
  }
};

// The compiled term.
class FunctionForceTerm {
 public:
  // Throws std::invalid_argument "<name>.f: ..." for an empty function, "<name>.bodies[k]: ..." for an
  // index out of range or repeated.
  FunctionForceTerm(const FunctionForce& spec, const std::vector<Body>& bodies, const std::string& name)
      : f_(spec.f), bodies_(detail::resolve_bodies(spec.bodies, bodies.size(), name)) {
    if (!f_) throw std::invalid_argument(name + ".f: expected a callable, got an empty function");
  }

  static ElementTraits traits() {
    ElementTraits t{};
    t.reads_attitude = true, t.velocity_dependent = true, t.time_dependent = true;
    t.has_potential = false, t.has_torque = true;
    return t;
  }

  // Adds f's force and torque to each listed body; returns Σ f_W·v_W + tau_B·w_B [W].
  double add_wrenches(double t, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    return detail::add_callable_wrenches(f_, bodies_, t, kinematics, wrenches);
  }

  double potential(const std::vector<BodyKinematics>& /*kinematics*/) const { return 0.0; }

  const std::vector<int>& bodies() const { return bodies_; }

 private:
  ForceFunction f_;
  std::vector<int> bodies_;
};

}  // namespace rigiddyn
