// Runge–Kutta–Munthe-Kaas 4 (RKMK4; Munthe-Kaas 1999): classical RK4 in the Lie algebra of
// (vector space) × SO(3), with stage increments Θ_i = h Σ_j a_ij K_j, stage states y0 ⊕ Θ_i and
//   K_i = dexp⁻¹_{Θ_i}(ξ(y0 ⊕ Θ_i)),  y1 = y0 ⊕ h Σ_i b_i K_i
// (⊕ = Model::retract, exp on SO(3); dexp⁻¹ truncated after two commutators, enough for order 4).
// Order 4 in every coordinate, attitude included; 4 derivative evaluations per step (+ 4
// exponentials). The attitude stays on SO(3) (unit quaternion to round-off, renormalised) without
// projection; energy and |L| drift by O(h⁴) per unit time like RK4's.
// Without the dexp⁻¹ correction ("RK4 through the exponential") the attitude is only order 2.
#pragma once
#include "rigiddyn/models/model_interface.hpp"  // RIGIDDYN_ALWAYS_INLINE
#include "rigiddyn/integrators/rk4.hpp"

namespace rigiddyn {

struct Rkmk4 {
  template <class Model>
  RIGIDDYN_ALWAYS_INLINE static void step(const Model& model, typename Model::Coordinates& y, double h) {
    using namespace rk4_tableau;
    using Tangent = typename Model::Tangent;
    const Tangent K1 = model.velocity(y);
    const Tangent theta2 = scaled(a21 * h, K1);
    const Tangent K2 = model.dexp_inv(theta2, model.velocity_at(y, theta2));
    const Tangent theta3 = scaled(a32 * h, K2);
    const Tangent K3 = model.dexp_inv(theta3, model.velocity_at(y, theta3));
    const Tangent theta4 = scaled(a43 * h, K3);
    const Tangent K4 = model.dexp_inv(theta4, model.velocity_at(y, theta4));
    Tangent theta(K1.size());
    for (Eigen::Index i = 0; i < theta.size(); ++i) theta[i] = h * (b1 * K1[i] + b2 * K2[i] + b3 * K3[i] + b4 * K4[i]);
    y = model.retract(y, theta);
    model.project(y);
  }
};

}  // namespace rigiddyn
