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
// Written once against the model interface (loads_kick, free_flow): for models without a gyroscopic
// term (particle, planar body) it is the triple jump of velocity Verlet.
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
    // the attitudes are normalised once, after the last free rotation
    model.loads_kick(y, 0.5 * gamma1 * h);
    model.template free_flow<DlmRotation<false>>(y, gamma1 * h);
    model.loads_kick(y, 0.5 * (gamma1 + gamma0) * h);
    model.template free_flow<DlmRotation<false>>(y, gamma0 * h);
    model.loads_kick(y, 0.5 * (gamma0 + gamma1) * h);
    model.template free_flow<DlmRotation<true>>(y, gamma1 * h);
    model.loads_kick(y, 0.5 * gamma1 * h);
  }
};

}  // namespace rigiddyn
