// Euler's equations for the rotation of a rigid body about its centre of mass, in the three forms an
// inertia can need (Craig, "Rigid Body Dynamics" slides, "Equations of motion for rotation"):
//   I ω̇ + ω × I ω = τ        (everything in the body frame B, torques about the centre of mass)
// - SphericalEuler: I = s 1, so ω × I ω = 0: no gyroscopic term at all;
// - PrincipalEuler: I = diag(I1, I2, I3) (B along principal axes):
//     I1 ω̇1 = τ1 + (I2 − I3) ω2 ω3, and cyclic;
// - FullEuler: any symmetric positive definite I (products of inertia present).
// A model is templated on one of them, chosen once (see RigidBody::form and with_euler_form), so a
// sphere pays nothing for the gyroscopic term. Every form has the same members:
//   momentum(w)                          h_B = I ω_B [kg m²/s]
//   angular_acceleration(w, tau)         ω̇_B = I⁻¹ (τ_B − ω × I ω) [rad/s²]
//   explicit_gyroscopic_kick(w, tau, h)  ω + h I⁻¹ (τ − ω × I ω)  (explicit gyroscopic term)
//   implicit_gyroscopic_kick(w, tau, h)  ω' from one Newton step on
//                                        I (ω' − ω) + h ω' × I ω' = h τ, started at ω' = ω
//
// The members are written element by element, each vector built from three scalar expressions:
// Eigen's arithmetic on Vector3d uses a 2-wide packet plus a scalar, and in the integrators' loops
// GCC then assembles packets in memory from values just stored as scalars (a store-forwarding
// stall on the critical path, measured 1.7x slower per step than a hand-written loop).
#pragma once
#include "rigiddyn/inertia/principal_axes.hpp"  // principal_decomposition
#include "rigiddyn/models/model_interface.hpp"   // RIGIDDYN_ALWAYS_INLINE

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigiddyn {

// I = s 1 [kg m²]: the gyroscopic term vanishes identically.
struct SphericalEuler {
  double inertia;
  double inverse_inertia;

  explicit SphericalEuler(double s) : inertia(s), inverse_inertia(1.0 / s) {}
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d momentum(const Eigen::Vector3d& w) const {
    return Eigen::Vector3d(inertia * w(0), inertia * w(1), inertia * w(2));
  }
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d angular_acceleration(const Eigen::Vector3d& /*w*/, const Eigen::Vector3d& tau) const {
    return Eigen::Vector3d(inverse_inertia * tau(0), inverse_inertia * tau(1), inverse_inertia * tau(2));
  }
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d explicit_gyroscopic_kick(const Eigen::Vector3d& w, const Eigen::Vector3d& tau, double h) const {
    const double k = h * inverse_inertia;
    return Eigen::Vector3d(w(0) + k * tau(0), w(1) + k * tau(1), w(2) + k * tau(2));
  }
  // no gyroscopic term: the implicit update is the explicit one, exactly
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d implicit_gyroscopic_kick(const Eigen::Vector3d& w, const Eigen::Vector3d& tau, double h) const {
    return explicit_gyroscopic_kick(w, tau, h);
  }
};

// A x for a 3×3 A, written out: Eigen's fixed-size product is not always inlined into the
// integrators' loops, and the call costs more than the product.
RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d times_3x3(const Eigen::Matrix3d& A, const Eigen::Vector3d& x) {
  return Eigen::Vector3d(A(0, 0) * x(0) + A(0, 1) * x(1) + A(0, 2) * x(2), A(1, 0) * x(0) + A(1, 1) * x(1) + A(1, 2) * x(2),
                         A(2, 0) * x(0) + A(2, 1) * x(1) + A(2, 2) * x(2));
}
// Aᵀ x, the same way. Both sum each row from left to right; Eigen's product may sum in another order, so replacing one
// by the other can move a result by round-off.
RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d transpose_times_3x3(const Eigen::Matrix3d& A, const Eigen::Vector3d& x) {
  return Eigen::Vector3d(A(0, 0) * x(0) + A(1, 0) * x(1) + A(2, 0) * x(2), A(0, 1) * x(0) + A(1, 1) * x(1) + A(2, 1) * x(2),
                         A(0, 2) * x(0) + A(1, 2) * x(1) + A(2, 2) * x(2));
}

// a × b, written out (see the note at the top)
RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d cross_3(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return Eigen::Vector3d(a(1) * b(2) - a(2) * b(1), a(2) * b(0) - a(0) * b(2), a(0) * b(1) - a(1) * b(0));
}

// x = J⁻¹ b for an invertible 3×3 J given by its rows r0, r1, r2, in closed form (adjugate,
// Cramer's rule): J⁻¹ = [r1 × r2, r2 × r0, r0 × r1] / (r0 · (r1 × r2)).
RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d solve_3x3(const Eigen::Vector3d& r0, const Eigen::Vector3d& r1,
                                                 const Eigen::Vector3d& r2, const Eigen::Vector3d& b) {
  const Eigen::Vector3d c0 = cross_3(r1, r2), c1 = cross_3(r2, r0), c2 = cross_3(r0, r1);
  const double inverse_det = 1.0 / (r0(0) * c0(0) + r0(1) * c0(1) + r0(2) * c0(2));
  return Eigen::Vector3d(inverse_det * (b(0) * c0(0) + b(1) * c1(0) + b(2) * c2(0)),
                         inverse_det * (b(0) * c0(1) + b(1) * c1(1) + b(2) * c2(1)),
                         inverse_det * (b(0) * c0(2) + b(1) * c1(2) + b(2) * c2(2)));
}

// The Jacobian ∂/∂ω' of the residual I (ω' − ω) + τ ω' × I ω' at ω' = w (I and w in B, τ [s]):
//   J = I + τ (ω̂ I − (I ω)^),  column j: I e_j + τ (ω × I e_j − (I ω) × e_j)
// (d(ω × I ω) = ω × I dω − (I ω) × dω). The one copy of the derivative of Euler's gyroscopic term:
// the implicit kick (gyroscopic_newton_kick, τ = h) and the implicit midpoint rule's Newton step
// (midpoint_newton_correction, integrators/implicit_midpoint.hpp, τ = h/2) both solve with it.
RIGIDDYN_ALWAYS_INLINE Eigen::Matrix3d gyroscopic_jacobian(const Eigen::Matrix3d& I, const Eigen::Vector3d& w,
                                                           const Eigen::Vector3d& Iw, double tau) {
  Eigen::Matrix3d J;
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector3d w_x_Ij = cross_3(w, I.col(j)), Iw_x_ej = cross_3(Iw, Eigen::Vector3d::Unit(j));
    for (int i = 0; i < 3; ++i) J(i, j) = I(i, j) + tau * (w_x_Ij(i) - Iw_x_ej(i));
  }
  return J;
}

// One Newton step on F(ω') = I (ω' − ω) + h ω' × I ω' − h tau = 0 from ω' = ω (the implicit
// gyroscopic term; I and tau in B, h [s]):
//   F(ω) = h (ω × I ω − tau),  J = ∂F/∂ω' = I + h (ω̂ I − (I ω)^),  ω' = ω − J⁻¹ F(ω).
RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d gyroscopic_newton_kick(const Eigen::Matrix3d& I, const Eigen::Vector3d& w,
                                                              const Eigen::Vector3d& tau, double h) {
  const Eigen::Vector3d Iw = times_3x3(I, w);
  const Eigen::Vector3d w_x_Iw = cross_3(w, Iw);
  const Eigen::Vector3d F(h * (w_x_Iw(0) - tau(0)), h * (w_x_Iw(1) - tau(1)), h * (w_x_Iw(2) - tau(2)));
  const Eigen::Matrix3d J = gyroscopic_jacobian(I, w, Iw, h);
  const Eigen::Vector3d dw = solve_3x3(J.row(0), J.row(1), J.row(2), F);
  return Eigen::Vector3d(w(0) - dw(0), w(1) - dw(1), w(2) - dw(2));
}

// I = diag(I1, I2, I3) [kg m²] in B (principal axes).
struct PrincipalEuler {
  Eigen::Vector3d inertia;
  Eigen::Vector3d inverse_inertia;

  explicit PrincipalEuler(const Eigen::Vector3d& diagonal) : inertia(diagonal), inverse_inertia(diagonal.cwiseInverse()) {}
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d momentum(const Eigen::Vector3d& w) const {
    return Eigen::Vector3d(inertia(0) * w(0), inertia(1) * w(1), inertia(2) * w(2));
  }
  // I1 ω̇1 = τ1 + (I2 − I3) ω2 ω3, and cyclic (Craig, "Rigid Body Dynamics" slides, Euler's equations in principal axes)
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d angular_acceleration(const Eigen::Vector3d& w, const Eigen::Vector3d& tau) const {
    return Eigen::Vector3d(inverse_inertia(0) * (tau(0) + (inertia(1) - inertia(2)) * w(1) * w(2)),
                           inverse_inertia(1) * (tau(1) + (inertia(2) - inertia(0)) * w(2) * w(0)),
                           inverse_inertia(2) * (tau(2) + (inertia(0) - inertia(1)) * w(0) * w(1)));
  }
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d explicit_gyroscopic_kick(const Eigen::Vector3d& w, const Eigen::Vector3d& tau, double h) const {
    const Eigen::Vector3d alpha = angular_acceleration(w, tau);
    return Eigen::Vector3d(w(0) + h * alpha(0), w(1) + h * alpha(1), w(2) + h * alpha(2));
  }
  // gyroscopic_newton_kick for diagonal I: with d = (I3 − I2, I1 − I3, I2 − I1),
  //   F_i = h (d_i ω_j ω_k − n_i),  J = diag(I) + h [[0, d1 ω3, d1 ω2], [d2 ω3, 0, d2 ω1], [d3 ω2, d3 ω1, 0]]
  // ((i, j, k) cyclic), solved in closed form.
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d implicit_gyroscopic_kick(const Eigen::Vector3d& w, const Eigen::Vector3d& tau,
                                                                  double h) const {
    const double d0 = inertia(2) - inertia(1), d1 = inertia(0) - inertia(2), d2 = inertia(1) - inertia(0);
    const Eigen::Vector3d F(h * (d0 * w(1) * w(2) - tau(0)), h * (d1 * w(2) * w(0) - tau(1)), h * (d2 * w(0) * w(1) - tau(2)));
    const Eigen::Vector3d J0(inertia(0), h * d0 * w(2), h * d0 * w(1)), J1(h * d1 * w(2), inertia(1), h * d1 * w(0)),
        J2(h * d2 * w(1), h * d2 * w(0), inertia(2));
    const Eigen::Vector3d dw = solve_3x3(J0, J1, J2, F);
    return Eigen::Vector3d(w(0) - dw(0), w(1) - dw(1), w(2) - dw(2));
  }
};

// Any symmetric positive definite I [kg m²] in B, products of inertia included. Its principal frame is
// computed once here, for the splittings that turn about the principal axes (splitting_parts.hpp).
struct FullEuler {
  Eigen::Matrix3d inertia;
  Eigen::Matrix3d inverse_inertia;
  Eigen::Vector3d principal_moments;  // ascending [kg m²]
  Eigen::Quaterniond q_BP;            // principal frame P in B: I = R_BP diag(principal_moments) R_BPᵀ to round-off

  explicit FullEuler(const Eigen::Matrix3d& I) : inertia(I), inverse_inertia(I.inverse()) {
    const PrincipalAxes P = principal_decomposition(I);
    principal_moments = P.moments;
    q_BP = Eigen::Quaterniond(P.axes).normalized();
  }
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d momentum(const Eigen::Vector3d& w) const { return times_3x3(inertia, w); }
  // ω̇ = I⁻¹ (tau − ω × I ω)
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d angular_acceleration(const Eigen::Vector3d& w, const Eigen::Vector3d& tau) const {
    const Eigen::Vector3d w_x_Iw = cross_3(w, momentum(w));
    return times_3x3(inverse_inertia, Eigen::Vector3d(tau(0) - w_x_Iw(0), tau(1) - w_x_Iw(1), tau(2) - w_x_Iw(2)));
  }
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d explicit_gyroscopic_kick(const Eigen::Vector3d& w, const Eigen::Vector3d& tau, double h) const {
    const Eigen::Vector3d alpha = angular_acceleration(w, tau);
    return Eigen::Vector3d(w(0) + h * alpha(0), w(1) + h * alpha(1), w(2) + h * alpha(2));
  }
  RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d implicit_gyroscopic_kick(const Eigen::Vector3d& w, const Eigen::Vector3d& tau, double h) const {
    return gyroscopic_newton_kick(inertia, w, tau, h);
  }
};

// Euler's equations solved for the torque (inverse dynamics): τ_B = I ω̇ + ω × I ω [N m] for the angular
// velocity w and acceleration alpha in B, with the form's own I ω (momentum).
template <class Euler>
Eigen::Vector3d euler_torque(const Euler& euler, const Eigen::Vector3d& w, const Eigen::Vector3d& alpha) {
  const Eigen::Vector3d I_alpha = euler.momentum(alpha), w_x_Iw = cross_3(w, euler.momentum(w));
  return Eigen::Vector3d(I_alpha(0) + w_x_Iw(0), I_alpha(1) + w_x_Iw(1), I_alpha(2) + w_x_Iw(2));
}

// The rotational inertia about the centre of mass in B as a matrix [kg m²].
inline Eigen::Matrix3d inertia_matrix(const SphericalEuler& e) { return e.inertia * Eigen::Matrix3d::Identity(); }
inline Eigen::Matrix3d inertia_matrix(const PrincipalEuler& e) { return e.inertia.asDiagonal(); }
inline Eigen::Matrix3d inertia_matrix(const FullEuler& e) { return e.inertia; }

}  // namespace rigiddyn
