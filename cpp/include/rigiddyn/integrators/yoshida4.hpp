// Fourth-order composition of the DLM splitting (splitting_dlm.hpp) by Yoshida's triple jump
// (Yoshida, Phys. Lett. A 150, 1990; Hairer, Lubich & Wanner, GNI II.4, eq. (4.4)):
//
//   Φ4(h) = Φ2(γ1 h) · Φ2(γ0 h) · Φ2(γ1 h),  γ1 = 1/(2 − 2^{1/3}),  γ0 = −2^{1/3}/(2 − 2^{1/3}),
//
// Φ2 the symmetric order-2 DLM step. The adjacent half-kicks of neighbouring sub-steps act at the
// same attitude and are merged (exact: the loads are constant over the step), so a step is
// kick · free · kick · free · kick · free · kick.
// Order 4; cost per step: 4 derivative evaluations (kicks; none without loads) + 3 DLM free
// rotations (15 axis rotations). Conserves what DLM conserves (|L|, spatial L_W, unit |q| to an
// unbiased round-off walk; energy bounded, symplectic). The negative middle sub-step makes its error
// constant larger than RK4's (about 25× on the free body) while it keeps the invariants.
// For models without a gyroscopic term: the triple jump of velocity Verlet.
#pragma once
#include "rigiddyn/integrators/splitting_dlm.hpp"

namespace rigiddyn {

namespace yoshida4_coefficients {
inline constexpr double gamma1 = 1.3512071919596576340476878;   // 1/(2 − 2^{1/3})
inline constexpr double gamma0 = -1.7024143839193152680953756;  // −2^{1/3}/(2 − 2^{1/3}) = 1 − 2 γ1
}  // namespace yoshida4_coefficients

struct Yoshida4 {
  template <class Model>
  static void step(const Model& model, typename Model::Coordinates& y, double h) {
    using namespace yoshida4_coefficients;
    if constexpr (is_rigid_body_model_v<Model>) {
      // the attitude is normalised once, after the last free rotation
      loads_kick(model, y, 0.5 * gamma1 * h);
      free_translation(y, gamma1 * h);
      dlm_free_rotation<false>(model.euler(), y, gamma1 * h);
      loads_kick(model, y, 0.5 * (gamma1 + gamma0) * h);
      free_translation(y, gamma0 * h);
      dlm_free_rotation<false>(model.euler(), y, gamma0 * h);
      loads_kick(model, y, 0.5 * (gamma0 + gamma1) * h);
      free_translation(y, gamma1 * h);
      dlm_free_rotation(model.euler(), y, gamma1 * h);
      loads_kick(model, y, 0.5 * gamma1 * h);
    } else {  // the triple jump of velocity Verlet
      static_assert(!has_gyroscopic_term_v<Model>,
                    "Yoshida4's velocity-Verlet branch drops the gyroscopic term: a model with one must take the rigid-body branch");
      model.kick(y, 0.5 * gamma1 * h);
      model.drift(y, gamma1 * h);
      model.kick(y, 0.5 * (gamma1 + gamma0) * h);
      model.drift(y, gamma0 * h);
      model.kick(y, 0.5 * (gamma0 + gamma1) * h);
      model.drift(y, gamma1 * h);
      model.kick(y, 0.5 * gamma1 * h);
    }
  }
};

}  // namespace rigiddyn
