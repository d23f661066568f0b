// A rigid body pinned at a point O fixed in the scene frame (3 rotational DOF): the
// heavy top, the gyroscope. "W" below is the scene frame (W itself when the scene declares no moving
// frame). B is the body frame at the centre of mass C, as for RigidBody; C is at
//   p_WC = p_WO + R_WB p_OC_B.
// The body turns about O, so Euler's law is written about O (Craig, "Rigid Body Dynamics" slides,
// "Equations of motion for rotation": M_O = dH_O/dt about a point fixed in the ground, H_O = I_O ω) with
// the inertia about O by the parallel-axis theorem (same slides, "Parallel axis theorem", the products of
// inertia included):
//   I_O = I_C + m (|c|² 1 − c cᵀ),  c = p_OC_B,
// which in B is Euler's equations with I_O in place of I_C (models/euler_equations.hpp, their one home):
//   I_O α_B + ω_B × I_O ω_B = τ_O,  τ_O = τ_C + c × f_B (the applied wrench reduced to O).
// The pivot's reaction follows from Newton's law for C: R = m a_C − f with
//   a_C = R_WB (α × c + ω × (ω × c))  (Craig, "Rigid Body Kinematics", acceleration of a point of a body).
#pragma once
#include "rigiddyn/models/euler_equations.hpp"
#include "rigiddyn/models/rigid_body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"  // BodyKinematics, BodyWrench

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <stdexcept>
#include <string>
#include <type_traits>

namespace rigiddyn {

// A rigid body pinned at O. Throws std::invalid_argument naming p_OC_B / p_WO for non-finite entries, and
// p_OC_B when the pivot is so far from C that the rounding of the inertia about O loses more than
// max_digits_lost decimal digits of the inertia about C (digits_lost), or leaves it no longer positive
// definite (Euler's equations about O need its inverse).
class PivotedBody {
 public:
  // The most digits of I_C that the rounding of I_O may lose: I_O's moment about the axis through O and C
  // is I_C's about it, formed as a difference of terms up to m|c|², so it carries an error of ~ε m|c|² =
  // 2.2e-16 · 10^digits_lost of that moment: 22 % at 15 digits lost (the last digit kept), and rounding
  // noise beyond.
  static constexpr double max_digits_lost = 15.0;

  // body: mass [kg] and inertia_com [kg m²] about C in B; p_OC_B: C relative to O, in B [m] (zero allowed:
  // the free rotation about C); p_WO: O in the scene frame [m].
  PivotedBody(const RigidBody& body, const Eigen::Vector3d& p_OC_B, const Eigen::Vector3d& p_WO = Eigen::Vector3d::Zero());

  const RigidBody& body() const { return body_; }
  double mass() const { return body_.mass(); }
  const Eigen::Matrix3d& inertia_com() const { return body_.inertia_com(); }  // I_C [kg m²] in B
  const Eigen::Vector3d& p_OC_B() const { return p_OC_B_; }                   // c [m] in B
  const Eigen::Vector3d& p_WO() const { return p_WO_; }                       // O [m] in the scene frame
  // I_O = I_C + m (|c|² 1 − c cᵀ) [kg m²] about O, in B (parallel-axis theorem, products of inertia included)
  const Eigen::Matrix3d& inertia_O() const { return inertia_O_; }
  // Decimal digits of I_C lost when I_O is rounded: max(0, log10(m|c|² / λ_min(I_C))) (0 for c = 0): the
  // smallest moment of I_C is added to terms up to m|c|², so I_O keeps ~16 − digits_lost() of its digits.
  // At most max_digits_lost (the constructor refuses a farther pivot).
  double digits_lost() const { return digits_lost_; }
  // The form of Euler's equations I_O needs (spherical / principal / full), by RigidBody::euler_form's rule.
  EulerForm euler_form() const { return form_; }

 private:
  RigidBody body_;
  Eigen::Vector3d p_OC_B_;
  Eigen::Vector3d p_WO_;
  Eigen::Matrix3d inertia_O_;
  double digits_lost_;
  EulerForm form_;
};

// The attitude q_WB (B to the scene frame) and the angular velocity w_B [rad/s] of B in the scene frame,
// expressed in B.
struct PivotedBodyState {
  Eigen::Quaterniond q_WB = Eigen::Quaterniond::Identity();
  Eigen::Vector3d w_B = Eigen::Vector3d::Zero();
};

// `state` with q_WB normalised; throws std::invalid_argument naming `name`.q_WB (not a unit quaternion
// within 1e-6, or non-finite) or `name`.w_B (non-finite).
PivotedBodyState checked_state(const PivotedBodyState& state, const std::string& name = "state");

// The Euler form Euler (SphericalEuler, PrincipalEuler, FullEuler) of the inertia I [kg m²] in B.
template <class Euler>
Euler make_euler(const Eigen::Matrix3d& I) {
  if constexpr (std::is_same_v<Euler, SphericalEuler>) {
    return SphericalEuler(I.trace() / 3.0);
  } else if constexpr (std::is_same_v<Euler, PrincipalEuler>) {
    return PrincipalEuler(I.diagonal());
  } else {
    return FullEuler(I);
  }
}

// Calls f(euler) with the form of Euler's equations of I_O (the pivoted body's euler_form()): the single
// runtime switch, as with_euler_form(RigidBody) is for I_C.
template <class F>
decltype(auto) with_euler_form(const PivotedBody& body, F&& f) {
  const Eigen::Matrix3d& I = body.inertia_O();
  switch (body.euler_form()) {
    case EulerForm::spherical: return f(make_euler<SphericalEuler>(I));
    case EulerForm::principal: return f(make_euler<PrincipalEuler>(I));
    case EulerForm::full: return f(make_euler<FullEuler>(I));
  }
  throw std::logic_error("with_euler_form: unknown EulerForm");
}

// R_WBᵀ v = R_BW v for the attitude q (x, y, z, w) [unit up to a method's error], written out:
// v − 2 s (u × v) + 2 u × (u × v), u = (x, y, z), s = w (Eigen's q.conjugate() * v, scalar by scalar so that
// no 2-wide packet reloads values just stored one by one; see euler_equations.hpp).
RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d rotate_to_body(const Eigen::Quaterniond& q_WB, const Eigen::Vector3d& v_W) {
  const Eigen::Vector3d u(q_WB.x(), q_WB.y(), q_WB.z());
  const Eigen::Vector3d u_x_v = cross_3(u, v_W), u_x_u_x_v = cross_3(u, u_x_v);
  const double s2 = 2.0 * q_WB.w();
  return Eigen::Vector3d(v_W[0] - s2 * u_x_v[0] + 2.0 * u_x_u_x_v[0], v_W[1] - s2 * u_x_v[1] + 2.0 * u_x_u_x_v[1],
                         v_W[2] - s2 * u_x_v[2] + 2.0 * u_x_u_x_v[2]);
}

// The wrench (f_W at C in the scene frame [N], tau_B about C in B [N m]) reduced to the pivot O, in B:
//   τ_O = tau_B + c × (R_BW f_W)  [N m]  (moment transfer, Craig, "Rigid Body Dynamics" slides),
// c = c_B = p_OC_B [m]. For a force applied at the body point P = C + r_B, pass c_B + r_B and tau_B the couple.
// Without a force the attitude is not read (the one-body layout without an element leaves it unformed at its stages).
RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d pivoted_torque_O(const Eigen::Vector3d& c_B, const Eigen::Quaterniond& q_WB,
                                                        const BodyWrench& wrench) {
  if (wrench.f_W[0] == 0.0 && wrench.f_W[1] == 0.0 && wrench.f_W[2] == 0.0) return wrench.tau_B;
  const Eigen::Vector3d c_x_f = cross_3(c_B, rotate_to_body(q_WB, wrench.f_W));
  return Eigen::Vector3d(wrench.tau_B[0] + c_x_f[0], wrench.tau_B[1] + c_x_f[1], wrench.tau_B[2] + c_x_f[2]);
}

// Euler's equations about O (Craig: M_O = dH_O/dt, H_O = I_O ω): the wrench (f_W at C, tau_B about C) reduced
// to O, then α_B = I_O⁻¹ (τ_O − ω × I_O ω) [rad/s²] in B through euler_O, the Euler form of I_O; c_B = p_OC_B
// [m], q_WB (unit), w_B [rad/s] in B.
template <class Euler>
RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d pivoted_angular_acceleration(const Euler& euler_O, const Eigen::Vector3d& c_B,
                                                                    const Eigen::Quaterniond& q_WB, const Eigen::Vector3d& w_B,
                                                                    const BodyWrench& wrench) {
  return euler_O.angular_acceleration(w_B, pivoted_torque_O(c_B, q_WB, wrench));
}

// The acceleration of the centre of mass [m/s²] in the scene frame: a_C = R_WB (α × c + ω × (ω × c)).
RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d pivoted_com_acceleration_W(const Eigen::Vector3d& c_B, const Eigen::Quaterniond& q_WB,
                                                                  const Eigen::Vector3d& w_B, const Eigen::Vector3d& alpha_B) {
  const Eigen::Vector3d a_x_c = cross_3(alpha_B, c_B), w_x_w_x_c = cross_3(w_B, cross_3(w_B, c_B));
  return q_WB * Eigen::Vector3d(a_x_c[0] + w_x_w_x_c[0], a_x_c[1] + w_x_w_x_c[1], a_x_c[2] + w_x_w_x_c[2]);
}

// The pivot's reaction on the body, in the scene frame [N]: Newton for C, R = m a_C − f_W, with f_W the
// resultant of every applied force (gravity included) and a_C of pivoted_com_acceleration_W; mass [kg],
// c_B [m], q_WB unit, w_B [rad/s] and alpha_B [rad/s²] in B.
inline Eigen::Vector3d pivot_reaction_W(double mass, const Eigen::Vector3d& c_B, const Eigen::Quaterniond& q_WB,
                                        const Eigen::Vector3d& w_B, const Eigen::Vector3d& alpha_B, const Eigen::Vector3d& f_W) {
  return mass * pivoted_com_acceleration_W(c_B, q_WB, w_B, alpha_B) - f_W;
}

// The kinematics elements see of the pinned body (body_kinematics.hpp), at its centre of mass:
// p_W = p_WO + R c [m], v_W = R (ω × c) [m/s], q_WB, w_B, and the mass m [kg].
BodyKinematics kinematics_of(const PivotedBody& body, const PivotedBodyState& state);

// H_O = R_WB I_O ω_B [kg m²/s]: the angular momentum about O, in the scene frame.
Eigen::Vector3d angular_momentum_O_W(const PivotedBody& body, const PivotedBodyState& state);

}  // namespace rigiddyn
