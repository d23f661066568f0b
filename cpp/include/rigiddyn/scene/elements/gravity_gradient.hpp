// The gravity gradient of a central attractor on an extended body: the second-order (MacCullagh) term of
// the attractor's potential on a body of inertia I about its centre of mass, which PointMassGravity (the
// first-order term, the body as a point) leaves out. Declare both for a satellite about a planet.
//
// Derivation. A mass element dm of the body at ρ from its centre of mass (in W) is at r + ρ from the
// attractor (r = p_body − p_W). Expanding −GM dm/|r + ρ| to second order in |ρ|/|r| and integrating,
// the first-order term vanishes (∫ρ dm = 0 about the centre of mass), and with ∫|ρ|² dm = ½ tr I and
// ∫ρρᵀ dm = ½ tr I 1 − I_W (I_W = R I Rᵀ, R = R_WB):
//   V₂ = −GM/(2|r|³) (tr I − 3 r̂ᵀ I_W r̂) = −GM tr I/(2|r|³) + 3GM s/(2|r|⁵),   s = rᵀ I_W r = r_Bᵀ I r_B,
// r_B = Rᵀ r. Its two generalised forces:
// - force, −∇_r V₂ with ∇_r |r|⁻ⁿ = −n r/|r|ⁿ⁺² and ∇_r s = 2 I_W r:
//     f_W = −3GM/(2|r|⁵) [(tr I − 5 s/|r|²) r + 2 I_W r];
//   (for a sphere, I = i 1: tr I − 5 s/|r|² = −2i, so f_W = 0: a sphere attracts as a point);
// - torque, −∂V₂/∂δθ under a small rotation of the body R → R exp([δθ]×) (δθ in B, the variation
//   conjugate to w_B): r_B → r_B + r_B × δθ, δs = 2 (I r_B)·(r_B × δθ) = 2 δθ·((I r_B) × r_B), so
//     tau_B = 3GM/|r|⁵ r_B × (I r_B).
// The element is conservative: f_W·v_W + tau_B·w_B = −dV₂/dt, so T + V is conserved with it.
// Particles have I = 0 and feel nothing (they are skipped). A pinned rigid body feels the same wrench at
// its centre of mass (the model reduces it to the pivot). A planar body (free or pinned) is refused: its in-plane moments
// I_xx, I_yy, which the in-plane torque needs, are not part of it. Singular at the attractor (r = 0).
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_bodies.hpp"
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/element_traits.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

namespace rigiddyn {

class GravityGradientTerm;

// The spec: gravitational parameter gm = G M [m³/s²] of an attractor fixed at p_W [m] in W, acting on
// `bodies` (empty: every body; particles are skipped, planar bodies refused).
struct GravityGradient {
  static constexpr const char* element_type = "GravityGradient";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "The gravity-gradient (MacCullagh) term of a central attractor gm at p_W in W on extended bodies: torque "
      "tau_B = 3 gm/|r|^5 r_B x (I r_B) [N m] and the matching force, so that the potential V2 = -gm/(2|r|^3) "
      "(tr I - 3 r^T I_W r/|r|^2) [J] is conserved with the motion; no effect on particles.";
  static constexpr const char* example = R"py(A body on a circular orbit at rest in W feels the torque 3 gm/|r|³ r̂ × I r̂ (here zero: r̂ along a principal
axis, an equilibrium):

>>> scene = rd.Scene([rd.RigidBody(1.0, [1.0, 2.0, 3.0])], elements=[rd.GravityGradient(gm=1.0)])
>>> start = rd.RigidBodyState(p_W=(10.0, 0.0, 0.0))
>>> result = rd.simulate(scene, [start], 0.01, steps=10, method="rk4")
>>> bool(np.allclose(result.w_B[-1, 0], 0.0, atol=1e-15))
True)py";  // the docstring's Examples (run as doctests)
  using Term = GravityGradientTerm;  // what compile makes of it
  double gm = 0.0;
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  BodyList bodies;

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        scalar_field("gm", &GravityGradient::gm, "m^3/s^2", "gravitational parameter GM of the central attractor [m^3/s^2]")
            .must_be_given().above_zero(),
        vector_field("p_W", &GravityGradient::p_W, "m", "(3,) position of the attractor in W [m]"),
        bodies_field(&GravityGradient::bodies));
  }
};

// The compiled term: the listed rigid bodies with their inertia about the centre of mass.
class GravityGradientTerm {
 public:
  // Throws std::invalid_argument "<name>.gm: ..." unless gm is finite and > 0, "<name>.p_W: ..." for a
  // non-finite p_W, "<name>.bodies[k]: ..." for an index out of range or repeated, and "<name>.bodies: ..."
  // when a planar body is among the bodies.
  GravityGradientTerm(const GravityGradient& spec, const std::vector<Body>& bodies, const std::string& name)
      : gm_(spec.gm), p_W_(spec.p_W) {
    require_positive(spec.gm, name + ".gm");
    require_finite(spec.p_W, name + ".p_W");
    for (const int b : detail::resolve_bodies(spec.bodies, bodies.size(), name)) {
      if (is_planar(bodies[b])) {
        throw_invalid(name + ".bodies",
                      "particles or rigid bodies (a planar body has no in-plane moments I_xx, I_yy, which the "
                      "gravity-gradient torque needs)",
                      "planar body " + std::to_string(b));
      }
      if (body_traits(bodies[b]).has_spatial_inertia) {
        bodies_.push_back(b);
        inertia_com_.push_back(inertia_com_of(bodies[b]));  // about the centre of mass, also when pinned
      }
    }
  }

  static ElementTraits traits() {
    ElementTraits t{};
    t.reads_attitude = true, t.velocity_dependent = false, t.time_dependent = false;
    t.has_potential = true, t.has_torque = true, t.needs_attitude = true;
    return t;
  }

  // Adds f_W and tau_B of the derivation above to each listed rigid body; returns Σ f_W·v_W + tau_B·w_B [W].
  double add_wrenches(double /*t*/, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    double power = 0.0;
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
      const BodyKinematics& body = kinematics[bodies_[k]];
      const Eigen::Matrix3d& I = inertia_com_[k];
      const Eigen::Vector3d r_W = body.p_W - p_W_;
      const Eigen::Vector3d r_B = body.R_WB.transpose() * r_W;
      const Eigen::Vector3d I_r_B = I * r_B;
      const double r2 = r_W.squaredNorm();
      const double c = gm_ / (r2 * r2 * std::sqrt(r2));  // GM/|r|⁵
      const double s = r_B.dot(I_r_B);
      const Eigen::Vector3d f_W = (-1.5 * c) * ((I.trace() - 5.0 * s / r2) * r_W + 2.0 * (body.R_WB * I_r_B));
      const Eigen::Vector3d tau_B = (3.0 * c) * r_B.cross(I_r_B);
      wrenches[bodies_[k]].f_W += f_W;
      wrenches[bodies_[k]].tau_B += tau_B;
      power += f_W.dot(body.v_W) + tau_B.dot(body.w_B);
    }
    return power;
  }

  // V₂ = Σ −GM/(2|r|³) (tr I − 3 r̂ᵀ I_W r̂) [J]
  double potential(const std::vector<BodyKinematics>& kinematics) const {
    double V = 0.0;
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
      const BodyKinematics& body = kinematics[bodies_[k]];
      const Eigen::Vector3d r_B = body.R_WB.transpose() * (body.p_W - p_W_);
      const double r2 = r_B.squaredNorm();
      V -= gm_ / (2.0 * r2 * std::sqrt(r2)) * (inertia_com_[k].trace() - 3.0 * r_B.dot(inertia_com_[k] * r_B) / r2);
    }
    return V;
  }

  // The rigid bodies it acts on (the listed ones without the particles).
  const std::vector<int>& bodies() const { return bodies_; }

 private:
  double gm_;                                   // [m³/s²]
  Eigen::Vector3d p_W_;                         // [m]
  std::vector<int> bodies_;
  std::vector<Eigen::Matrix3d> inertia_com_;    // [kg m²] in B, per rigid body
};

}  // namespace rigiddyn
