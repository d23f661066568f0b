// The exact flow of a velocity under a constant acceleration plus a Coriolis part, M³ = −λ² M (the kick of
// the splitting methods in a turning frame: scene/scene_model.hpp loads_kick), and what a body with a 3-D
// attitude needs for it (its inertia, the Coriolis torque's axis).
#pragma once
#include <Eigen/Core>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace rigiddyn {

namespace detail {

// 1/j! for j = 0 … 22
struct InverseFactorials {
  double value[23];
  constexpr InverseFactorials() : value() {
    double factorial = 1.0;
    for (int j = 0; j < 23; ++j) factorial *= (j == 0 ? 1.0 : j), value[j] = 1.0 / factorial;
  }
};
inline constexpr InverseFactorials inverse_factorials{};

// Σ_{n=0}^{8} (−x)^n / (2n + k)! (Horner): the Taylor series of the turn coefficients below at x = θ² < 1 (the first
// term left out, x⁹/(18 + k)!, is below 1e-18 of the first, 1/k!, for k = 2, 3, 4)
inline double alternating_factorial_series(double x, int k) {
  double sum = inverse_factorials.value[16 + k];
  for (int n = 7; n >= 0; --n) sum = inverse_factorials.value[2 * n + k] - x * sum;
  return sum;
}

}  // namespace detail

// c2 = (1 − cos θ)/θ², c3 = (θ − sin θ)/θ³, c4 = (θ²/2 − 1 + cos θ)/θ⁴ (their series below θ = 1, where the
// closed forms cancel; above, the closed forms lose at most one digit)
struct TurnCoefficients {
  double c2, c3, c4;
};
inline TurnCoefficients turn_coefficients(double theta) {
  const double x = theta * theta;
  if (x < 1.0) {
    return {detail::alternating_factorial_series(x, 2), detail::alternating_factorial_series(x, 3),
            detail::alternating_factorial_series(x, 4)};
  }
  const double half_sin = std::sin(0.5 * theta), one_minus_cos = 2.0 * half_sin * half_sin;
  return {one_minus_cos / x, (theta - std::sin(theta)) / (x * theta), (0.5 * x - one_minus_cos) / (x * x)};
}

// The exact flow over h [s] of a velocity u ∈ R³ under u̇ = a0 + M (u − u0): a0 the acceleration at the start,
// M u a part linear in u with M³ = −λ² M (M similar to a skew matrix of norm λ [1/s]: a Coriolis term), so that
// e^{sM} = 1 + sin(λs)/λ M + (1 − cos λs)/λ² M² and u(s) = u0 + ∫_0^s e^{rM} dr a0. With θ = λ h and the
// start increment h_a0 = h a0 (of the explicit kick):
//   Δu = u(h) − u0 = (1 + h c2 M + h² c3 M²) h_a0,    ∫_0^h u ds / h − u0 = (½ + h c3 M + h² c4 M²) h_a0,
// the second the mean velocity over the kick (the loads' work is f·∫u ds). c = turn_coefficients(λ h), apply_M(x) = M x.
template <class ApplyM>
void exact_linear_kick(const Eigen::Vector3d& h_a0, double h, const TurnCoefficients& c, const ApplyM& apply_M,
                       Eigen::Vector3d& du, Eigen::Vector3d& mean) {
  const Eigen::Vector3d M_a = apply_M(h_a0), MM_a = apply_M(M_a);
  du = h_a0 + (h * c.c2) * M_a + (h * h * c.c3) * MM_a;
  mean = 0.5 * h_a0 + (h * c.c3) * M_a + (h * h * c.c4) * MM_a;
}

// What the exact Coriolis kick of a body with an attitude needs: its inertia I [kg m²] in B (I_C; I_O for a
// pivoted body; I_C0 for a variable-mass body under the scaled rule), I⁻¹, det I and tr I.
struct CoriolisInertia {
  Eigen::Matrix3d inertia, inverse;
  double det = 0.0, trace = 0.0;
};
inline CoriolisInertia coriolis_inertia(const Eigen::Matrix3d& inertia) {
  return {inertia, inertia.inverse(), inertia.determinant(), inertia.trace()};
}

// The Coriolis torque of a frame turning at Ω_B (scene/elements/fictitious_forces.hpp),
// −(ω × I Ω_B + Ω_B × I ω − I (ω × Ω_B)), is s × ω with s = (2 I − tr I) Ω_B (the identity
// [Ω]× I + I [Ω]× = [(tr I − I) Ω]× for a symmetric I); about a pivot O it is the same with I_O. The kick's
// rotation part is then I ω̇ = τ + s × ω: M = I⁻¹ [s]×, similar to the skew matrix of k = I^{1/2} s / √det I,
// so λ² = |k|² = s·I s / det I. Sets s and returns λ [1/s].
inline double coriolis_torque_axis(const CoriolisInertia& b, const Eigen::Vector3d& w_frame_B, Eigen::Vector3d& s) {
  s = 2.0 * (b.inertia * w_frame_B) - b.trace * w_frame_B;
  return std::sqrt(std::max(0.0, s.dot(b.inertia * s) / b.det));
}

}  // namespace rigiddyn
