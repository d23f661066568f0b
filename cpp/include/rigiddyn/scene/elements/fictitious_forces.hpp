// The fictitious forces and torques of a scene whose states are relative to a moving frame F
// (docs/fixed_point_frames_mass.md §2; the scene's SceneFrame, scene/scene_frame.hpp). Compile adds them after
// the user's elements; they are not user specs. "W" in the kinematics is F here: p_W = r, the centre of mass
// relative to F's origin, v_W = ṙ its velocity relative to F, q_WB = q_FB, w_B = ω, B's angular velocity
// relative to F, in B.
//
// Forces, at the centre of mass ("Rigid body kinematics and dynamics" notes, eqs. (4.39)–(4.40): Newton's
// law seen by an observer moving with F), with Ω, α, a_O of frame_terms (in F):
//   FrameOriginTerm  f = −m a_O              EulerForceTerm  f = −m α × r
//   CentrifugalTerm  f = −m Ω × (Ω × r)      CoriolisTerm    f = −2 m Ω × ṙ
// Torques about the centre of mass, in B, for bodies with an attitude (Ω_B = R_BF Ω, α_B = R_BF α, I = I_C):
//   EulerForceTerm   τ = −I α_B
//   CentrifugalTerm  τ = −Ω_B × I Ω_B
//   CoriolisTerm     τ = −(ω × I Ω_B + Ω_B × I ω − I (ω × Ω_B))
// Derivation (Craig, "Rigid Body Dynamics" slides: Euler's equations hold for the absolute angular velocity
// ω_abs = ω + Ω_B, in B): I ω̇_abs + ω_abs × I ω_abs = τ, and the rate of Ω_B's components in B is
//   dΩ_B/dt = R_BF α + Ṙ_BF Ω = α_B − ω × Ω_B   (Ṙ_FB = R_FB [ω]×, so Ṙ_BF = −[ω]× R_BF).
// Hence I ω̇ = τ − I α_B + I (ω × Ω_B) − (ω + Ω_B) × I (ω + Ω_B), and expanding the last product,
//   I ω̇ + ω × I ω = τ − I α_B − Ω_B × I Ω_B − (ω × I Ω_B + Ω_B × I ω − I (ω × Ω_B)):
// Euler's equations in F keep their form (the model's Euler form is unchanged) with the three torques above.
// Each is the moment about C of the point forces of the same name on the body's mass elements (a sum over
// point masses, tests/cpp/test_scene_frame.cpp): for Coriolis, −2 Σ m_i ρ_i × (Ω × (ω × ρ_i)).
// Power: Coriolis does no work, f·ṙ = 0 and τ·ω = −Ω_B·(I ω × ω) + (ω × Ω_B)·I ω = 0 (so its power is
// round-off). For a constant rotation (α = 0, a_O = 0) the centrifugal term is conservative with
//   V = −½ m |Ω × r|² − ½ Ω_B·I Ω_B      (f = −∇_r V; τ = −∂V/∂θ for a turn δθ of B: δΩ_B = Ω_B × δθ),
// so that kinetic energy relative to F plus the potentials is Jacobi's integral, conserved.
// Body kinds: a particle takes the forces only; a planar body (free or pinned) feels them all and its model
// keeps the in-plane force and τ_z (inertia_com_of: diag(0, 0, I_zz)); a pivoted body takes them at C, as
// every element, and its model reduces them to the pivot. The inertia is I_C0 m/m0 at the body's mass now
// m = k.m (exact for a constant mass, and the `scaled` rule of a MassFlow).
#pragma once
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_traits.hpp"
#include "rigiddyn/scene/scene_frame.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace rigiddyn {

namespace detail {

// A body with an attitude, as the fictitious torques need it.
struct TurningBody {
  int body;
  Eigen::Matrix3d inertia_per_mass;  // I_C0 / m0 [m²] in B: I_C = m inertia_per_mass at the mass m now
};

// What every fictitious term keeps: the frame (its values at t; computed once when the rotation is
// constant), the scene's bodies and those with an attitude.
class FictitiousBase {
 public:
  FictitiousBase(const SceneFrame& frame, const std::vector<Body>& bodies)
      : frame_(frame), constant_(frame.constant_rotation), body_count_(static_cast<int>(bodies.size())) {
    if (constant_) constant_terms_ = frame_terms(frame, 0.0);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (has_attitude(bodies[i])) turning_.push_back({static_cast<int>(i), inertia_com_of(bodies[i]) / mass_of(bodies[i])});
    }
  }

  const SceneFrame& frame() const { return frame_; }

 protected:
  // Ω, α, a_O in F at t [s] (frame_terms: throws naming "frame" on non-finite values)
  FrameTerms terms_at(double t) const { return constant_ ? constant_terms_ : frame_terms(frame_, t); }

  ElementTraits base_traits() const {
    const bool turning = !turning_.empty();
    ElementTraits t{};
    t.reads_attitude = turning, t.velocity_dependent = false, t.time_dependent = !constant_;
    t.has_potential = false, t.has_torque = turning;
    return t;
  }

  SceneFrame frame_;
  bool constant_;
  FrameTerms constant_terms_;
  int body_count_;
  std::vector<TurningBody> turning_;
};

}  // namespace detail

// f = −m a_O on every body [N] (F's origin accelerating relative to W).
class FrameOriginTerm : public detail::FictitiousBase {
 public:
  // frame: the scene's frame; bodies: the scene's bodies (the term acts on each); name: unused (its values
  // are checked by frame_terms, which names "frame").
  FrameOriginTerm(const SceneFrame& frame, const std::vector<Body>& bodies, const std::string& /*name*/)
      : FictitiousBase(frame, bodies) {}

  ElementTraits traits() const {
    ElementTraits t = base_traits();
    t.reads_attitude = false, t.has_torque = false;
    return t;
  }

  // f_W += −m a_O; returns Σ f·ṙ [W].
  double add_wrenches(double t, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    const Eigen::Vector3d a_O = terms_at(t).a_O_F;
    double power = 0.0;
    for (int b = 0; b < body_count_; ++b) {
      const Eigen::Vector3d f = -kinematics[b].m * a_O;
      wrenches[b].f_W += f;
      power += f.dot(kinematics[b].v_W);
    }
    return power;
  }

  // none (a_O is a function of time) [J]
  double potential(const std::vector<BodyKinematics>& /*kinematics*/) const { return 0.0; }
};

// f = −m α × r at the centre of mass; τ_B = −I_C α_B on bodies with an attitude.
class EulerForceTerm : public detail::FictitiousBase {
 public:
  EulerForceTerm(const SceneFrame& frame, const std::vector<Body>& bodies, const std::string& /*name*/)
      : FictitiousBase(frame, bodies) {}

  ElementTraits traits() const { return base_traits(); }

  // returns Σ f·ṙ + τ·ω [W]
  double add_wrenches(double t, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    const Eigen::Vector3d alpha = terms_at(t).alpha_F;
    double power = 0.0;
    for (int b = 0; b < body_count_; ++b) {
      const BodyKinematics& k = kinematics[b];
      const Eigen::Vector3d f = -k.m * alpha.cross(k.p_W);
      wrenches[b].f_W += f;
      power += f.dot(k.v_W);
    }
    for (const detail::TurningBody& s : turning_) {
      const BodyKinematics& k = kinematics[s.body];
      const Eigen::Vector3d alpha_B = k.R_WB.transpose() * alpha;
      const Eigen::Vector3d tau = -k.m * (s.inertia_per_mass * alpha_B);
      wrenches[s.body].tau_B += tau;
      power += tau.dot(k.w_B);
    }
    return power;
  }

  double potential(const std::vector<BodyKinematics>& /*kinematics*/) const { return 0.0; }
};

// f = −m Ω × (Ω × r) at the centre of mass; τ_B = −Ω_B × I_C Ω_B on bodies with an attitude.
class CentrifugalTerm : public detail::FictitiousBase {
 public:
  CentrifugalTerm(const SceneFrame& frame, const std::vector<Body>& bodies, const std::string& /*name*/)
      : FictitiousBase(frame, bodies) {}

  ElementTraits traits() const {
    ElementTraits t = base_traits();
    t.has_potential = constant_;
    return t;
  }

  // returns Σ f·ṙ + τ·ω [W] (= −dV/dt for a constant rotation)
  double add_wrenches(double t, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    const Eigen::Vector3d w = terms_at(t).w_F;
    double power = 0.0;
    for (int b = 0; b < body_count_; ++b) {
      const BodyKinematics& k = kinematics[b];
      const Eigen::Vector3d f = -k.m * w.cross(w.cross(k.p_W));
      wrenches[b].f_W += f;
      power += f.dot(k.v_W);
    }
    for (const detail::TurningBody& s : turning_) {
      const BodyKinematics& k = kinematics[s.body];
      const Eigen::Vector3d w_B = k.R_WB.transpose() * w;
      const Eigen::Vector3d tau = -k.m * w_B.cross(s.inertia_per_mass * w_B);
      wrenches[s.body].tau_B += tau;
      power += tau.dot(k.w_B);
    }
    return power;
  }

  // V = Σ (−½ m |Ω × r|² − ½ Ω_B·I_C Ω_B) [J] for a constant rotation; 0 otherwise (no potential)
  double potential(const std::vector<BodyKinematics>& kinematics) const {
    if (!constant_) return 0.0;
    const Eigen::Vector3d& w = constant_terms_.w_F;
    double V = 0.0;
    for (int b = 0; b < body_count_; ++b) V -= 0.5 * kinematics[b].m * w.cross(kinematics[b].p_W).squaredNorm();
    for (const detail::TurningBody& s : turning_) {
      const BodyKinematics& k = kinematics[s.body];
      const Eigen::Vector3d w_B = k.R_WB.transpose() * w;
      V -= 0.5 * k.m * w_B.dot(s.inertia_per_mass * w_B);
    }
    return V;
  }
};

// f = −2 m Ω × ṙ at the centre of mass; τ_B = −(ω × I_C Ω_B + Ω_B × I_C ω − I_C (ω × Ω_B)) on bodies with an
// attitude (ω = w_B, relative to F). It does no work: its power is zero up to round-off.
class CoriolisTerm : public detail::FictitiousBase {
 public:
  CoriolisTerm(const SceneFrame& frame, const std::vector<Body>& bodies, const std::string& /*name*/)
      : FictitiousBase(frame, bodies) {}

  ElementTraits traits() const {
    ElementTraits t = base_traits();
    t.velocity_dependent = true;
    return t;
  }

  // returns Σ f·ṙ + τ·ω [W] (0 up to round-off)
  double add_wrenches(double t, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    const Eigen::Vector3d w = terms_at(t).w_F;
    double power = 0.0;
    for (int b = 0; b < body_count_; ++b) {
      const BodyKinematics& k = kinematics[b];
      const Eigen::Vector3d f = (-2.0 * k.m) * w.cross(k.v_W);
      wrenches[b].f_W += f;
      power += f.dot(k.v_W);
    }
    for (const detail::TurningBody& s : turning_) {
      const BodyKinematics& k = kinematics[s.body];
      const Eigen::Vector3d w_B = k.R_WB.transpose() * w;
      const Eigen::Matrix3d& J = s.inertia_per_mass;
      const Eigen::Vector3d tau = -k.m * (k.w_B.cross(J * w_B) + w_B.cross(J * k.w_B) - J * k.w_B.cross(w_B));
      wrenches[s.body].tau_B += tau;
      power += tau.dot(k.w_B);
    }
    return power;
  }

  double potential(const std::vector<BodyKinematics>& /*kinematics*/) const { return 0.0; }
};

}  // namespace rigiddyn
