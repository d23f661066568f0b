// The left Jacobian of SO(3) (Chirikjian, Stochastic Models, Information Theory, and Lie Groups, vol. 2, §10.6;
// Solà, Deray & Atchuthan, "A micro Lie theory for state estimation in robotics", 2018, eqs. 143–146):
//   exp(φ + δ) = exp(J_l(φ) δ) exp(φ) + O(δ²),   J_l(φ) = I + (1 − cos θ)/θ² φ̂ + (θ − sin θ)/θ³ φ̂²,   θ = |φ|,
// and its transpose, the right Jacobian J_r(φ) = J_l(−φ) = J_l(φ)ᵀ: exp(φ + δ) = exp(φ) exp(J_r(φ) δ), so that a
// body turning as R0 exp(φ(t)) has the angular velocity ω_B = J_r(φ) φ̇ in its own frame.
#pragma once
#include "rigiddyn/so3/skew.hpp"

#include <Eigen/Core>

#include <cmath>

namespace rigiddyn {

// J_l(φ) for a rotation vector φ [rad]; (1 − cos θ)/θ² as ½ (sin(θ/2)/(θ/2))² (no cancellation), (θ − sin θ)/θ³ by
// its series 1/6 − θ²/120 below θ = 1e-4 (the closed form loses eps/θ² there, but multiplies θ²: J_l to ~eps).
inline Eigen::Matrix3d left_jacobian(const Eigen::Vector3d& phi) {
  const double theta = phi.norm();
  double a, b;
  if (theta < 1e-4) {
    a = 0.5 - theta * theta / 24.0, b = 1.0 / 6.0 - theta * theta / 120.0;
  } else {
    const double s = std::sin(0.5 * theta) / (0.5 * theta);
    a = 0.5 * s * s, b = (theta - std::sin(theta)) / (theta * theta * theta);
  }
  const Eigen::Matrix3d P = hat(phi);
  return Eigen::Matrix3d::Identity() + a * P + b * P * P;
}

}  // namespace rigiddyn
