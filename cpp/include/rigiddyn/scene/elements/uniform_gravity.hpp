// Uniform gravity: every listed body feels f_W = m g_W at its centre of mass (no torque about it), with
// the potential V = −m g_W·p_W (Craig, "Rigid Body Dynamics" slides, work of a constant force).
// A planar body keeps the in-plane part of f (the plane takes g_z: the constraint reaction).
#pragma once
#include "rigiddyn/always_inline.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_bodies.hpp"
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/element_traits.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

namespace rigiddyn {

class UniformGravityTerm;

// The spec: gravity g_W [m/s²] in W on `bodies` (empty: every body).
struct UniformGravity {
  static constexpr const char* element_type = "UniformGravity";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "Uniform gravity on the listed bodies: f_W = m g_W at each centre of mass, potential V = -m g_W . p_W "
      "[J]. A planar body keeps the in-plane part (the plane takes the rest).";
  static constexpr const char* example = R"py(A particle dropped from rest falls g t²/2 in t seconds:

>>> scene = rd.Scene([rd.Particle(1.0)], elements=[rd.UniformGravity(g_W=(0.0, 0.0, -9.81))])
>>> result = rd.simulate(scene, [rd.ParticleState()], 0.01, duration=2.0, method="rk4")
>>> result.p_W[-1, 0].round(12)
array([  0.  ,   0.  , -19.62]))py";  // the docstring's Examples (run as doctests)
  using Term = UniformGravityTerm;  // what compile makes of it
  Eigen::Vector3d g_W = Eigen::Vector3d(0.0, 0.0, -9.81);  // standard gravity, downwards along −z_W
  BodyList bodies;

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        vector_field("g_W", &UniformGravity::g_W, "m/s^2", "(3,) gravitational acceleration in W [m/s^2]"),
        bodies_field(&UniformGravity::bodies));
  }
};

// The compiled term: the listed bodies (their masses read from the kinematics, k.m, so
// that a body with a MassFlow feels its mass now).
class UniformGravityTerm {
 public:
  // Throws std::invalid_argument "<name>.g_W: ..." for a non-finite g_W and "<name>.bodies[k]: ..." for an
  // index out of range or repeated.
  UniformGravityTerm(const UniformGravity& spec, const std::vector<Body>& bodies, const std::string& name)
      : g_W_(spec.g_W), bodies_(detail::resolve_bodies(spec.bodies, bodies.size(), name)), loaded_(bodies_) {
    require_finite(spec.g_W, name + ".g_W");
  }

  static ElementTraits traits() {
    ElementTraits t{};
    t.reads_attitude = false, t.velocity_dependent = false, t.time_dependent = false;
    t.has_potential = true, t.has_torque = false;
    return t;
  }

  // f_W += m g_W on each listed body but those left to a tree; returns Σ m g_W·v_W [W] over every listed body.
  double add_wrenches(double /*t*/, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    double power = 0.0;
    for (const int b : loaded_) power += add_wrench(kinematics[b], wrenches[b]);
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero();  // of the links left to a tree: their power g_W·Σ m v_W
    for (const int b : left_to_tree_) momentum += kinematics[b].m * kinematics[b].v_W;
    return power + g_W_.dot(momentum);
  }

  // The term on one body of kinematics k (the one-body layout, scene/one_body_scene_model.hpp): wrench.f_W += m g_W;
  // returns m g_W·v_W [W].
  RIGIDDYN_ALWAYS_INLINE double add_wrench(const BodyKinematics& k, BodyWrench& wrench) const {
    const Eigen::Vector3d f = force(k.m);
    wrench.f_W += f;
    return f.dot(k.v_W);
  }

  // Bodies first … first + count − 1, the links of a tree whose articulated-body algorithm applies this gravity as
  // the base's acceleration (a₀ = −g, Featherstone §5.3; scene_model.hpp): their wrenches are left out of
  // add_wrenches, their power and potential kept. Returns false, changing nothing, unless every one is listed.
  bool leave_to_tree(int first, int count) {
    const auto in_tree = [&](int b) { return b >= first && b < first + count; };
    if (std::count_if(loaded_.begin(), loaded_.end(), in_tree) != count) return false;
    loaded_.erase(std::remove_if(loaded_.begin(), loaded_.end(), in_tree), loaded_.end());
    for (int b = first; b < first + count; ++b) left_to_tree_.push_back(b);
    return true;
  }

  // V = −Σ m g_W·p_W [J]
  double potential(const std::vector<BodyKinematics>& kinematics) const {
    double V = 0.0;
    for (const int b : bodies_) V += potential(kinematics[b]);
    return V;
  }

  // m g_W [N] on a body of mass m [kg]
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d force(double m) const { return m * g_W_; }

  // −m g_W·p_W [J] of one body of kinematics k
  double potential(const BodyKinematics& k) const { return -(k.m * g_W_.dot(k.p_W)); }

  const Eigen::Vector3d& g_W() const { return g_W_; }
  const std::vector<int>& bodies() const { return bodies_; }

 private:
  Eigen::Vector3d g_W_;
  std::vector<int> bodies_;       // every listed body
  std::vector<int> loaded_;       // those whose wrench add_wrenches adds
  std::vector<int> left_to_tree_; // those whose tree applies it (leave_to_tree)
};

}  // namespace rigiddyn
