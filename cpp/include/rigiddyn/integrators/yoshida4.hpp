// Fourth-order composition of the DLM splitting (splitting_dlm.hpp) by Yoshida's triple jump
// (Yoshida, Phys. Lett. A 150, 1990; Hairer, Lubich & Wanner, GNI II.4, eq. (4.4)):
//
//   Φ4(h) = Φ2(γ1 h) · Φ2(γ0 h) · Φ2(γ1 h),  γ1 = 1/(2 − 2^{1/3}),  γ0 = −2^{1/3}/(2 − 2^{1/3}),
//
// Φ2 the symmetric order-2 DLM step. The adjacent half-kicks of neighbouring sub-steps act at the
// same attitude and are merged (exact: the loads are constant over the step), so a step is
// kick · free · kick · free · kick · free · kick.
// Order 4; cost per step: 4 derivative evaluations (kicks; none without loads; 3 between records where the loads do
// not read the velocities: a run merges adjacent kicks, simulate/run_loop.hpp) + 3 DLM free
// rotations (15 axis rotations). Conserves what DLM conserves (|L|, spatial L_W, unit |q| to an
// unbiased round-off walk; energy bounded, symplectic). The negative middle sub-step makes its error
// constant larger than RK4's (about 25× on the free body) while it keeps the invariants.
// Written once against the model interface (loads_kick, free_flow): for models without a gyroscopic
// term (particle, planar body) it is the triple jump of velocity Verlet.
//
// Bodies whose mass changes (scene models with a MassFlow: has_mass_flow). The masses move with t in the free
// part, so the sub-steps would meet them at t0 + γ1 h = t0 + 1.35 h and t0 + (γ1 + γ0) h = t0 − 0.35 h, outside
// the step: a mass that runs low (or grows from little) within one step becomes zero or negative there although
// every mass of the run is positive. Such a model takes the three-part form instead: each sub-step is
//   Φ2(γ h) = M(γ h/2) · kick(γ h/2) · free(γ h) · kick(γ h/2) · M(γ h/2),
// M the masses' own part (mass_part: m += ṁ(t) γ h/2 at a frozen t), free the free part at fixed masses
// (free_flow_at_fixed_mass), kick the loads at fixed masses: three exactly solved flows in a symmetric order, so
// Φ2 is symmetric and of order 2 and the triple jump of it of order 4 (Hairer, Lubich & Wanner, GNI II.4). The
// adjacent M of neighbouring sub-steps merge (exact flows); the kicks do not (M moves the mass between them), so
// a step is M · kick · free · kick · M · kick · free · kick · M · kick · free · kick · M: 6 kicks, and the model's
// project (the attitudes normalised; the next step's start noted for the out-of-mass message). After each M the
// masses are those at the cumulative sums of the M coefficients, the fractions γ1/2, γ1 + γ0/2, 3γ1/2 + γ0, 1 =
// 0.676, 0.5, 0.324, 1 of the step: for a constant rate every mass the step meets lies between those at its ends.
// Moving the masses with the kicks' coefficients instead would keep the order only with kicks that integrate the
// changing mass exactly; clamping the free part's times into the step leaves the loads a trapezoidal rule
// (order 2).
#pragma once
#include "rigiddyn/always_inline.hpp"
#include "rigiddyn/integrators/splitting_dlm.hpp"

#include <type_traits>
#include <utility>

namespace rigiddyn {

namespace detail {
// True for a model with a masses' part (mass_part, free_flow_at_fixed_mass; and project)
template <class Model, class = void>
struct has_mass_part : std::false_type {};
template <class Model>
struct has_mass_part<Model, std::void_t<decltype(std::declval<const Model&>().mass_part(
                                std::declval<typename Model::Coordinates&>(), 0.0))>> : std::true_type {};
}  // namespace detail

namespace yoshida4_coefficients {
inline constexpr double gamma1 = 1.3512071919596576340476878;   // 1/(2 − 2^{1/3})
inline constexpr double gamma0 = -1.7024143839193152680953756;  // −2^{1/3}/(2 − 2^{1/3}) = 1 − 2 γ1
}  // namespace yoshida4_coefficients

struct Yoshida4 {
  template <class Model>
  using Workspace = NoWorkspace;

  template <class Model>
  RIGIDDYN_ALWAYS_INLINE static void step(const Model& model, typename Model::Coordinates& y, double h, NoWorkspace& /*w*/) {
    using namespace yoshida4_coefficients;
    if constexpr (detail::has_mass_part<Model>::value) {
      if (model.has_mass_flow()) return step_with_masses(model, y, h);
    }
    model.loads_kick(y, edge_kick * h);
    between_kicks(model, y, h);
    model.loads_kick(y, edge_kick * h);
  }

  // The step (at constant masses) opens and closes with loads_kick(edge_kick h): where the model's kicks merge (no
  // mass flow among them), the run takes a step's closing kick and the next step's opening kick as one
  // (simulate/run_loop.hpp, merged_steps): 3 force evaluations per step instead of 4.
  static constexpr double edge_kick = 0.5 * yoshida4_coefficients::gamma1;
  template <class Model>
  RIGIDDYN_ALWAYS_INLINE static void between_kicks(const Model& model, typename Model::Coordinates& y, double h) {
    using namespace yoshida4_coefficients;
    // the attitudes are normalised once, after the last free rotation
    model.template free_flow<DlmRotation<false>>(y, gamma1 * h);
    model.loads_kick(y, 0.5 * (gamma1 + gamma0) * h);
    model.template free_flow<DlmRotation<false>>(y, gamma0 * h);
    model.loads_kick(y, 0.5 * (gamma0 + gamma1) * h);
    model.template free_flow<DlmRotation<true>>(y, gamma1 * h);
  }

 private:
  // The three-part form for masses that change (top of the file)
  template <class Model>
  static void step_with_masses(const Model& model, typename Model::Coordinates& y, double h) {
    using namespace yoshida4_coefficients;
    model.mass_part(y, 0.5 * gamma1 * h);
    model.loads_kick(y, 0.5 * gamma1 * h);
    model.template free_flow_at_fixed_mass<DlmRotation<false>>(y, gamma1 * h);
    model.loads_kick(y, 0.5 * gamma1 * h);
    model.mass_part(y, 0.5 * (gamma1 + gamma0) * h);
    model.loads_kick(y, 0.5 * gamma0 * h);
    model.template free_flow_at_fixed_mass<DlmRotation<false>>(y, gamma0 * h);
    model.loads_kick(y, 0.5 * gamma0 * h);
    model.mass_part(y, 0.5 * (gamma0 + gamma1) * h);
    model.loads_kick(y, 0.5 * gamma1 * h);
    model.template free_flow_at_fixed_mass<DlmRotation<false>>(y, gamma1 * h);
    model.loads_kick(y, 0.5 * gamma1 * h);
    model.mass_part(y, 0.5 * gamma1 * h);
    model.project(y);  // the attitudes normalised once; the next step starts here (the out-of-mass message's)
  }
};

}  // namespace rigiddyn
