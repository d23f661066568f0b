// A magnetic dipole carried by a body in a static magnetic field: a magnetorquer, a compass needle, a
// permanent magnet aboard a spacecraft. Each listed body carries the dipole moment m_B [A m²], fixed in its
// frame B (m_W = R_WB m_B); the field is a uniform B_W [T] plus that of a fixed source dipole of moment M_W
// [A m²] at p_S (the Earth's tilted dipole in an Earth-fixed scene frame, another magnet):
//   B(p) = B_W + k (3 r (r·M_W)/|r|⁵ − M_W/|r|³),   r = p − p_S,   k = μ₀/(4π)
// (Jackson, "Classical Electrodynamics", §5.6: the field of a magnetic dipole). On the body (Jackson §5.7:
// the force, torque and energy of a dipole in an external field):
//   potential  V = −m_W·B(p_W) [J];
//   torque     tau_B = m_B × B_B,   B_B = R_WBᵀ B(p_W)   (−∂V/∂δθ under R → R exp([δθ]×));
//   force      f_W = ∇_p (m_W·B) at a fixed attitude, zero in the uniform field; for the source dipole
//              f_W = 3k/|r|⁵ [(m·r) M + (M·r) m + (m·M) r − 5 (m·r)(M·r) r/|r|²]   (m = m_W, M = M_W).
// So f_W·v_W + tau_B·w_B = −dV/dt: T + V is conserved. A compass needle (moment of inertia I about an axis
// normal to m and B) swings as a pendulum, θ̈ = −(|m||B|/I) sin θ. Particles carry no attitude and are
// skipped; a planar body keeps the in-plane force and tau_z. Singular at the source (r = 0).
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

class MagneticDipoleTerm;

// The spec: the dipole m_B of each listed body (empty: every body; particles are skipped) in the uniform field
// B_W plus the field of the source dipole source_moment_W at source_p_W.
struct MagneticDipole {
  static constexpr const char* element_type = "MagneticDipole";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "A magnetic dipole m_B fixed in each listed body's frame B, in a static field: the uniform B_W plus the "
      "field of a fixed source dipole source_moment_W at source_p_W, B(p) = B_W + mu0/(4 pi) (3 r (r . M)/|r|^5 "
      "- M/|r|^3), r = p - source_p_W. Torque tau_B = m_B x B_B [N m], force f_W = grad(m_W . B) [N] (zero in a "
      "uniform field), potential V = -m_W . B [J]: the motion conserves T + V. A compass needle of moment of "
      "inertia I swings at sqrt(|m| |B| / I) [rad/s] for small angles. Particles (no attitude) are skipped; a "
      "planar body keeps the in-plane force and tau_z.";
  static constexpr const char* example = R"py(A compass needle (dipole m along its x axis) in a uniform field along x is at rest: no torque:

>>> needle = rd.RigidBody(1.0, [1e-4, 1e-3, 1e-3])
>>> field = rd.MagneticDipole(m_B=(1.0, 0.0, 0.0), B_W=(1e-4, 0.0, 0.0))
>>> result = rd.simulate(rd.Scene([needle], elements=[field]), [rd.RigidBodyState()], 0.01, steps=100, method="rk4")
>>> bool(np.allclose(result.w_B[-1, 0], 0.0, atol=1e-15))
True)py";  // the docstring's Examples (run as doctests)
  using Term = MagneticDipoleTerm;  // what compile makes of it
  Eigen::Vector3d m_B = Eigen::Vector3d::Zero();
  Eigen::Vector3d B_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d source_moment_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d source_p_W = Eigen::Vector3d::Zero();
  BodyList bodies;

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        vector_field("m_B", &MagneticDipole::m_B, "A*m^2", "(3,) magnetic dipole moment of each body, in its B [A m^2]")
            .must_be_given(),
        vector_field("B_W", &MagneticDipole::B_W, "T", "(3,) uniform magnetic flux density in W [T]"),
        vector_field("source_moment_W", &MagneticDipole::source_moment_W, "A*m^2",
                     "(3,) moment of the fixed source dipole, in W [A m^2] (zero: no source)"),
        vector_field("source_p_W", &MagneticDipole::source_p_W, "m", "(3,) position of the source dipole in W [m]"),
        bodies_field(&MagneticDipole::bodies));
  }
};

// The compiled term: the listed bodies that carry an attitude.
class MagneticDipoleTerm {
 public:
  static constexpr double mu0_over_4pi = 1.0000000005443757e-7;  // μ₀/(4π) [N/A²], μ₀ = 1.25663706212e-6 (CODATA 2018)

  // Throws std::invalid_argument "<name>.<field>: ..." for a non-finite vector and "<name>.bodies[k]: ..."
  // for an index out of range or repeated.
  MagneticDipoleTerm(const MagneticDipole& spec, const std::vector<Body>& bodies, const std::string& name)
      : m_B_(spec.m_B), B_W_(spec.B_W), M_W_(spec.source_moment_W), p_S_(spec.source_p_W) {
    require_finite(spec.m_B, name + ".m_B");
    require_finite(spec.B_W, name + ".B_W");
    require_finite(spec.source_moment_W, name + ".source_moment_W");
    require_finite(spec.source_p_W, name + ".source_p_W");
    for (const int b : detail::resolve_bodies(spec.bodies, bodies.size(), name)) {
      if (has_attitude(bodies[b])) bodies_.push_back(b);
    }
  }

  ElementTraits traits() const {
    ElementTraits t{};
    t.reads_attitude = true, t.velocity_dependent = false, t.time_dependent = false;
    t.has_potential = true, t.has_torque = true, t.needs_attitude = true;
    t.has_force = !M_W_.isZero(0.0);  // the uniform field's gradient is zero
    return t;
  }

  // The field B(p_W) [T] in W.
  Eigen::Vector3d field_W(const Eigen::Vector3d& p_W) const {
    if (M_W_.isZero(0.0)) return B_W_;
    const Eigen::Vector3d r = p_W - p_S_;
    const double r2 = r.squaredNorm(), r3 = r2 * std::sqrt(r2);
    return B_W_ + (mu0_over_4pi / r3) * (3.0 * r.dot(M_W_) / r2 * r - M_W_);
  }

  // Adds f_W and tau_B above to each listed body; returns Σ f_W·v_W + tau_B·w_B [W].
  double add_wrenches(double /*t*/, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    double power = 0.0;
    for (const int b : bodies_) {
      const BodyKinematics& body = kinematics[b];
      const Eigen::Vector3d tau_B = m_B_.cross(body.R_WB.transpose() * field_W(body.p_W));
      const Eigen::Vector3d f_W = source_force_W(body.R_WB * m_B_, body.p_W);
      wrenches[b].f_W += f_W;
      wrenches[b].tau_B += tau_B;
      power += f_W.dot(body.v_W) + tau_B.dot(body.w_B);
    }
    return power;
  }

  // A controller's command (scene/controller.hpp): the dipole m_B [A m²] of every listed body, from now on.
  void command(const Eigen::Vector3d& m_B) { m_B_ = m_B; }

  // V = Σ −m_W·B(p_W) [J]
  double potential(const std::vector<BodyKinematics>& kinematics) const {
    double V = 0.0;
    for (const int b : bodies_) V -= (kinematics[b].R_WB * m_B_).dot(field_W(kinematics[b].p_W));
    return V;
  }

  // The bodies it acts on (the listed ones without the particles).
  const std::vector<int>& bodies() const { return bodies_; }

 private:
  // ∇_p (m_W·B) of the source dipole's field (the uniform part has none).
  Eigen::Vector3d source_force_W(const Eigen::Vector3d& m_W, const Eigen::Vector3d& p_W) const {
    if (M_W_.isZero(0.0)) return Eigen::Vector3d::Zero();
    const Eigen::Vector3d r = p_W - p_S_;
    const double r2 = r.squaredNorm(), r5 = r2 * r2 * std::sqrt(r2);
    const double m_r = m_W.dot(r), M_r = M_W_.dot(r);
    return (3.0 * mu0_over_4pi / r5) * (m_r * M_W_ + M_r * m_W + m_W.dot(M_W_) * r - (5.0 * m_r * M_r / r2) * r);
  }

  Eigen::Vector3d m_B_;   // [A m²] in B
  Eigen::Vector3d B_W_;   // [T] in W
  Eigen::Vector3d M_W_;   // [A m²] in W
  Eigen::Vector3d p_S_;   // [m] in W
  std::vector<int> bodies_;
};

}  // namespace rigiddyn
