// A torsion spring and damper in a spherical (ball) joint of a tree (a flexible mount, a gimbal's restoring spring,
// a joint's viscous friction): with q_JL the joint's attitude, q0 = exp(rest_rotation) its rest attitude and
// φ = log(q0⁻¹ q_JL) the rotation from rest, in L [rad] (angle in [0, π]), the couple
//   τ_L = −k φ − c ω_L   [N m] in L (ω_L the joint's angular velocity),
// on the link and −τ on its parent (joint_force.hpp's couple pair: the tree's momenta are conserved). The spring's
// potential is V = ½ k |φ|²: along q = q0 exp(φ), φ̇ = dexp⁻¹_{−φ} ω_L (Hairer, Lubich & Wanner, GNI §IV.8;
// so3/dexp_inv.hpp), and dexp⁻¹_{−φ} = 1 + ½ φ̂ + c(|φ|) φ̂² with φᵀ φ̂ = 0, so dV/dt = k φ·φ̇ = k φ·ω_L: the
// negative of the spring's power (the law is conservative; the damper's power is −c |ω_L|²). The spring acts along
// the shorter rotation to rest: at half a turn from rest its couple flips (V is continuous there, its gradient not).
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/element_traits.hpp"
#include "rigiddyn/scene/elements/element_checks.hpp"
#include "rigiddyn/scene/elements/joint_force.hpp"
#include "rigiddyn/so3/exp_log.hpp"
#include "rigiddyn/tree/joints/spherical_joint.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <tuple>
#include <vector>

namespace rigiddyn {

struct SphericalSpringDamper;

// The compiled term.
class SphericalSpringDamperTerm {
 public:
  // Throws std::invalid_argument naming "<name>.body" for a body that is not a tree link (Scene.add_tree) or whose
  // joint is not spherical, "<name>.stiffness" / "<name>.damping" for a value negative or not finite and
  // "<name>.rest_rotation" for one not finite.
  SphericalSpringDamperTerm(const SphericalSpringDamper& spec, const std::vector<Body>& bodies, const std::string& name);

  ElementTraits traits() const {
    ElementTraits t{};
    t.reads_attitude = true, t.has_torque = true, t.velocity_dependent = c_ > 0.0, t.has_potential = true;
    return t;
  }

  // Adds the couple pair of τ_L = −k φ − c ω_L; returns its power τ_L · ω_L [W].
  double add_wrenches(double /*t*/, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    const Eigen::Vector3d w_L = Eigen::Map<const Eigen::Vector3d>(kinematics[link_].joint_v);
    const Eigen::Vector3d tau_L = -k_ * rotation_from_rest(kinematics) - c_ * w_L;
    detail::add_couple_pair(link_, parent_, tau_L, kinematics, wrenches);
    return tau_L.dot(w_L);
  }

  // V = ½ k |φ|² [J]
  double potential(const std::vector<BodyKinematics>& kinematics) const {
    return 0.5 * k_ * rotation_from_rest(kinematics).squaredNorm();
  }

 private:
  // φ = log(q0⁻¹ q_JL) [rad] in L, of the joint's quaternion as integrated (normalised first)
  Eigen::Vector3d rotation_from_rest(const std::vector<BodyKinematics>& kinematics) const {
    const Eigen::Quaterniond q_JL = SphericalJoint::quaternion(Eigen::Map<const Eigen::Vector4d>(kinematics[link_].joint_q));
    return quat_to_rotvec(q0_inverse_ * q_JL.normalized());
  }

  int link_, parent_ = -1;           // the link's body and its parent's (−1: W)
  double k_, c_;                     // [N m/rad], [N m s/rad]
  Eigen::Quaterniond q0_inverse_;    // q0⁻¹, the rest attitude's inverse
};

// The spec: the link body `body` (its joint spherical), stiffness k [N m/rad], rest rotation φ0 [rad] (the rest
// attitude q0 = exp(φ0) of the joint, J to L; zero: the joint frame's), damping c [N m s/rad], k and c >= 0.
struct SphericalSpringDamper {
  static constexpr const char* element_type = "SphericalSpringDamper";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "A torsion spring and damper in the spherical (ball) joint of the tree link `body` (a body of Scene.add_tree): "
      "with phi = log(q0^-1 q) the rotation [rad] (in the link frame, angle in [0, pi]) from the rest attitude q0 = "
      "exp(rest_rotation) to the joint's attitude q, the couple -(stiffness phi + damping w) [N m] in the link frame "
      "(w the joint's angular velocity [rad/s]) on the link and the opposite on its parent (W for a root link), so "
      "that a tree's momenta are conserved. Potential V = stiffness |phi|^2/2 [J]. The spring pulls along the shorter "
      "rotation to rest (its couple flips at half a turn).";
  static constexpr const char* example = R"py(A ball of I = 0.5 kg m² on a torsion spring of 2 N m/rad, twisted 0.1 rad about z, turns back and forth at
ω = √(k/I) = 2 rad/s: after one period π s it is back at its start:

>>> tree = rd.Tree()
>>> ball = tree.add_link("ball", -1, rd.SphericalJoint(), rd.SpatialInertia(2.0, [0.0, 0.0, 0.0], 0.5 * np.eye(3)))
>>> scene = rd.Scene()
>>> links = scene.add_tree(tree, "mount")
>>> scene.add(rd.SphericalSpringDamper(body=links[0], stiffness=2.0))
0
>>> start = [0.0, 0.0, np.sin(0.05), np.cos(0.05)]
>>> result = rd.simulate(scene, tree.joint_states(start), np.pi / 1000, steps=1000, method="rk4")
>>> bool(np.allclose(result.joint_q[-1], start, rtol=0, atol=1e-9))
True)py";  // the docstring's Examples (run as doctests)
  using Term = SphericalSpringDamperTerm;  // what compile makes of it
  int body = 0;
  double stiffness = 0.0;
  Eigen::Vector3d rest_rotation = Eigen::Vector3d::Zero();
  double damping = 0.0;

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        body_field("body", &SphericalSpringDamper::body, "index of the tree link whose spherical joint holds it"),
        scalar_field("stiffness", &SphericalSpringDamper::stiffness, "N*m/rad", "torsion stiffness k [N m/rad]").must_be_given().at_least_zero(),
        vector_field("rest_rotation", &SphericalSpringDamper::rest_rotation, "rad",
                     "(3,) rotation vector of the rest attitude q0 = exp(rest_rotation), joint frame to link frame [rad]"),
        scalar_field("damping", &SphericalSpringDamper::damping, "N*m*s/rad", "damping coefficient c [N m s/rad]").at_least_zero());
  }
};

inline SphericalSpringDamperTerm::SphericalSpringDamperTerm(const SphericalSpringDamper& spec, const std::vector<Body>& bodies,
                                                            const std::string& name)
    : link_(spec.body), k_(spec.stiffness), c_(spec.damping) {
  detail::joint_link<SphericalJoint>(spec.body, bodies, name + ".body", "spherical", &parent_);
  detail::require_nonnegative(spec.stiffness, name + ".stiffness");
  require_finite(spec.rest_rotation, name + ".rest_rotation");
  detail::require_nonnegative(spec.damping, name + ".damping");
  q0_inverse_ = rotvec_to_quat(spec.rest_rotation).conjugate();
}

}  // namespace rigiddyn
