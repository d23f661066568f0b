// Error bounds for C++ tests that compare a long run with a closed form (the C++ twin of
// tests/python/_error_bounds.py). A step that rounds by e_k makes a difference that reaches time T
// through the flow's Jacobian: |y_N − y(T)| ≤ Σ_k ‖∂y(T)/∂y(t_k)‖ e_k (first order in e). Near a
// separatrix that Jacobian grows like e^{λ t}; the sum measures it instead of assuming a figure.
#pragma once
#include "rigiddyn/exact/free_body.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigiddyn::test {

inline constexpr double kRoundoff = std::numeric_limits<double>::epsilon();

// The distance between two unit quaternions as rotations (q and −q the same rotation): min |q1 ∓ q2|.
inline double rotation_distance(const Eigen::Quaterniond& q1, const Eigen::Quaterniond& q2) {
  return std::min((q1.coeffs() - q2.coeffs()).norm(), (q1.coeffs() + q2.coeffs()).norm());
}

// κ = I_max / I_min of a rotational inertia.
inline double inertia_condition(const Eigen::Matrix3d& I) {
  const Eigen::Vector3d moments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I, Eigen::EigenvaluesOnly).eigenvalues();
  return moments.maxCoeff() / moments.minCoeff();
}

// Largest |ω| on the torque-free orbit through w0: |I ω| / I_min.
inline double max_rate(const Eigen::Matrix3d& I, const Eigen::Vector3d& w0) {
  const Eigen::Vector3d moments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I, Eigen::EigenvaluesOnly).eigenvalues();
  return (I * w0).norm() / moments.minCoeff();
}

// From the scaled max-norm below to max(|Δω|_2, attitude angle): √3 max(1, |ω|).
inline double to_euclidean(const Eigen::Matrix3d& I, const Eigen::Vector3d& w0) {
  return std::sqrt(3.0) * std::max(1.0, max_rate(I, w0));
}

// Round-off of one exact free-flow step (or of one closed-form evaluation at t = 0), in the
// scaled norm below: a few ulps of the closed form (exact/free_body.hpp), κ eps from ω → I ω → ω
// and from the eigen-decomposition of a full I: 16 eps κ.
inline double exact_step_roundoff(const Eigen::Matrix3d& I) { return 16.0 * kRoundoff * inertia_condition(I); }

// Bound on TorqueFreeSolution::state_at(t) (free_body.hpp: "a few ulps at t = 0, growing as
// eps·|phase|"): 16 eps κ (1 + |ω| |t|), attitude [rad] and |Δω| relative to max(1, |ω|).
inline double closed_form_error(const Eigen::Matrix3d& I, const Eigen::Vector3d& w0, double t) {
  return exact_step_roundoff(I) * (1.0 + std::abs(t) * w0.norm());
}

// Σ_{k=1..n} ‖∂y(T)/∂y(t_k)‖, t_k = k T/n, of the torque-free flow along the closed-form solution
// from (q0, w0): y = (body-frame rotation vector [rad], ω_i / max(1, |ω_i|)), max-norm, induced
// norm = largest row sum; columns by forward differences (relative step 1e-7: truncation and the
// closed form's round-off/1e-7 both ≲ 1e-6 relative) of the closed form itself (the exact flow).
inline double torque_free_amplification_sum(const Eigen::Matrix3d& I, const Eigen::Quaterniond& q0,
                                            const Eigen::Vector3d& w0, double T, int n) {
  constexpr double kStep = 1e-7;
  // the test inertias need not be realizable (the closed form holds for any positive definite I)
  const TorqueFreeSolution solution(I, q0, w0, InertiaCheck::allow_unrealizable);
  double total = 1.0;  // k = n: the identity
  for (int k = 1; k < n; ++k) {
    const double t = T * k / n;
    const TorqueFreeState s = solution.state_at(t);
    const TorqueFreeState base =
        TorqueFreeSolution(I, s.q_WB, s.w_B, InertiaCheck::allow_unrealizable).state_at(T - t);
    Eigen::Matrix<double, 6, 6> J;
    for (int j = 0; j < 6; ++j) {
      Eigen::Quaterniond q = s.q_WB;
      Eigen::Vector3d w = s.w_B;
      if (j < 3) {
        q = q * Eigen::Quaterniond(Eigen::AngleAxisd(kStep, Eigen::Vector3d::Unit(j)));
      } else {
        w(j - 3) += kStep * std::max(1.0, std::abs(w(j - 3)));
      }
      const TorqueFreeState moved = TorqueFreeSolution(I, q, w, InertiaCheck::allow_unrealizable).state_at(T - t);
      const Eigen::AngleAxisd turn(base.q_WB.conjugate() * moved.q_WB);
      J.col(j).head<3>() = turn.angle() * turn.axis() / kStep;
      J.col(j).tail<3>() = (moved.w_B - base.w_B).cwiseQuotient(base.w_B.cwiseAbs().cwiseMax(1.0)) / kStep;
    }
    total += J.cwiseAbs().rowwise().sum().maxCoeff();
  }
  return total;
}

}  // namespace rigiddyn::test
