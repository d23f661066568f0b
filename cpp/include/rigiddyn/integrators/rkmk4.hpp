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
  // the four stage velocities K1 … K4, the stage increment Θ and the next state
  template <class Model>
  struct Workspace {
    typename Model::Tangent K1, K2, K3, K4, theta;
    typename Model::Coordinates next;
    Workspace(const Model& model, const typename Model::Coordinates& y)
        : K1(new_tangent(model)), K2(K1.size()), K3(K1.size()), K4(K1.size()), theta(K1.size()), next(y.size()) {}
  };

  template <class Model>
  RIGIDDYN_ALWAYS_INLINE static void step(const Model& model, typename Model::Coordinates& y, double h,
                                          Workspace<Model>& w) {
    using namespace rk4_tableau;
    model.velocity(y, w.K1);
    scaled(a21 * h, w.K1, w.theta);
    model.velocity_at(y, w.theta, w.K2);
    model.dexp_inv(w.theta, w.K2);
    scaled(a32 * h, w.K2, w.theta);
    model.velocity_at(y, w.theta, w.K3);
    model.dexp_inv(w.theta, w.K3);
    scaled(a43 * h, w.K3, w.theta);
    model.velocity_at(y, w.theta, w.K4);
    model.dexp_inv(w.theta, w.K4);
    for (Eigen::Index i = 0; i < w.theta.size(); ++i) {
      w.theta[i] = h * (b1 * w.K1[i] + b2 * w.K2[i] + b3 * w.K3[i] + b4 * w.K4[i]);
    }
    model.retract(y, w.theta, w.next);
    y.swap(w.next);
    model.project(y);
  }
};

}  // namespace rigiddyn
