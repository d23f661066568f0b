// Euler's equations for the rotation of a rigid body about its centre of mass, in the three forms an
// inertia can need (seed 001, "Equations of motion for rotation"):
//   I ω̇ + ω × I ω = n        (everything in the body frame B, moments about the centre of mass)
// - SphericalEuler: I = s 1, so ω × I ω = 0: no gyroscopic term at all;
// - PrincipalEuler: I = diag(I1, I2, I3) (B along principal axes):
//     I1 ω̇1 = n1 + (I2 − I3) ω2 ω3, and cyclic;
// - FullEuler: any symmetric positive definite I (products of inertia present).
// A model is templated on one of them, chosen once (see RigidBody::form and with_euler_form), so a
// sphere pays nothing for the gyroscopic term. Every form has the same members:
//   momentum(w)                       h_B = I ω_B [kg m²/s]
//   angular_acceleration(w, n)        ω̇_B = I⁻¹ (n_B − ω × I ω) [rad/s²]
//   explicit_gyroscopic_kick(w, n, h) ω + h I⁻¹ (n − ω × I ω)  (explicit gyroscopic term)
//   implicit_gyroscopic_kick(w, n, h) ω' from one Newton step on
//                                     I (ω' − ω) + h ω' × I ω' = h n, started at ω' = ω
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigiddyn {

// I = s 1 [kg m²]: the gyroscopic term vanishes identically.
struct SphericalEuler {
  double inertia;
  double inverse_inertia;

  explicit SphericalEuler(double s) : inertia(s), inverse_inertia(1.0 / s) {}
  Eigen::Vector3d momentum(const Eigen::Vector3d& w) const { return inertia * w; }
  Eigen::Vector3d angular_acceleration(const Eigen::Vector3d& /*w*/, const Eigen::Vector3d& n) const {
    return inverse_inertia * n;
  }
  Eigen::Vector3d explicit_gyroscopic_kick(const Eigen::Vector3d& w, const Eigen::Vector3d& n, double h) const {
    return w + (h * inverse_inertia) * n;
  }
  // no gyroscopic term: the implicit update is the explicit one, exactly
  Eigen::Vector3d implicit_gyroscopic_kick(const Eigen::Vector3d& w, const Eigen::Vector3d& n, double h) const {
    return explicit_gyroscopic_kick(w, n, h);
  }
};

// One Newton step on F(ω') = I (ω' − ω) + h ω' × I ω' − h n = 0 from ω' = ω (the implicit
// gyroscopic term; I and n in B, h [s]):
//   F(ω) = h (ω × I ω − n),  J = ∂F/∂ω' = I + h (ω̂ I − (I ω)^),  ω' = ω − J⁻¹ F(ω).
inline Eigen::Vector3d gyroscopic_newton_kick(const Eigen::Matrix3d& I, const Eigen::Vector3d& w,
                                              const Eigen::Vector3d& n, double h) {
  const Eigen::Vector3d Iw = I * w;
  const Eigen::Vector3d F = h * (w.cross(Iw) - n);
  Eigen::Matrix3d J = I;
  for (int j = 0; j < 3; ++j) J.col(j) += h * (w.cross(I.col(j)) - Iw.cross(Eigen::Vector3d::Unit(j)));
  return w - J.inverse() * F;
}

// I = diag(I1, I2, I3) [kg m²] in B (principal axes).
struct PrincipalEuler {
  Eigen::Vector3d inertia;
  Eigen::Vector3d inverse_inertia;

  explicit PrincipalEuler(const Eigen::Vector3d& diagonal) : inertia(diagonal), inverse_inertia(diagonal.cwiseInverse()) {}
  Eigen::Vector3d momentum(const Eigen::Vector3d& w) const { return inertia.cwiseProduct(w); }
  Eigen::Vector3d angular_acceleration(const Eigen::Vector3d& w, const Eigen::Vector3d& n) const {
    return inverse_inertia.cwiseProduct(n - w.cross(momentum(w)));
  }
  Eigen::Vector3d explicit_gyroscopic_kick(const Eigen::Vector3d& w, const Eigen::Vector3d& n, double h) const {
    return w + h * angular_acceleration(w, n);
  }
  Eigen::Vector3d implicit_gyroscopic_kick(const Eigen::Vector3d& w, const Eigen::Vector3d& n, double h) const {
    return gyroscopic_newton_kick(inertia.asDiagonal().toDenseMatrix(), w, n, h);
  }

};

// Any symmetric positive definite I [kg m²] in B, products of inertia included.
struct FullEuler {
  Eigen::Matrix3d inertia;
  Eigen::Matrix3d inverse_inertia;

  explicit FullEuler(const Eigen::Matrix3d& I) : inertia(I), inverse_inertia(I.inverse()) {}
  Eigen::Vector3d momentum(const Eigen::Vector3d& w) const { return inertia * w; }
  Eigen::Vector3d angular_acceleration(const Eigen::Vector3d& w, const Eigen::Vector3d& n) const {
    return inverse_inertia * (n - w.cross(momentum(w)));
  }
  Eigen::Vector3d explicit_gyroscopic_kick(const Eigen::Vector3d& w, const Eigen::Vector3d& n, double h) const {
    return w + h * angular_acceleration(w, n);
  }
  Eigen::Vector3d implicit_gyroscopic_kick(const Eigen::Vector3d& w, const Eigen::Vector3d& n, double h) const {
    return gyroscopic_newton_kick(inertia, w, n, h);
  }
};

}  // namespace rigiddyn
