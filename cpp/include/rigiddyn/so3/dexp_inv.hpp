// The inverse of the derivative of the exponential map on SO(3), for the Runge–Kutta–Munthe-Kaas
// methods (integrators/rkmk4.hpp), on raw storage inside a model's flat tangent vector.
//
// Body frame: R = R0 exp(Θ̂) gives Θ̇ = dexp⁻¹_{−Θ} ω = ω + ½ Θ × ω + (1/12) Θ × (Θ × ω) + O(|Θ|⁴)
// (Iserles, Munthe-Kaas, Nørsett & Zanna, Acta Numerica 2000, §3; two commutators suffice for order 4).
#pragma once
#include "rigiddyn/always_inline.hpp"

namespace rigiddyn {

// w ← dexp⁻¹_{−Θ} w [rad/s], truncated after the second commutator; theta (3) [rad] and w (3) do not overlap.
RIGIDDYN_ALWAYS_INLINE void dexp_inv_body(const double* theta, double* w) {
  const double t0 = theta[0], t1 = theta[1], t2 = theta[2];
  const double w0 = w[0], w1 = w[1], w2 = w[2];
  const double a0 = t1 * w2 - t2 * w1, a1 = t2 * w0 - t0 * w2, a2 = t0 * w1 - t1 * w0;  // Θ × ω
  const double b0 = t1 * a2 - t2 * a1, b1 = t2 * a0 - t0 * a2, b2 = t0 * a1 - t1 * a0;  // Θ × (Θ × ω)
  w[0] = w0 + 0.5 * a0 + (1.0 / 12.0) * b0;
  w[1] = w1 + 0.5 * a1 + (1.0 / 12.0) * b1;
  w[2] = w2 + 0.5 * a2 + (1.0 / 12.0) * b2;
}

}  // namespace rigiddyn
