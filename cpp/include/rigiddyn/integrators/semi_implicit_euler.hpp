// Semi-implicit (symplectic) Euler, "kick then drift":
//   v1 = v0 + h a(x0, v0),   x1 = x0 ⊕ h v1   (for attitudes q1 = q0 ⊗ exp(h ω1), exact exponential).
// Order 1; 1 derivative evaluation per step. Symplectic for a particle and a planar body (bounded
// energy error); the attitude stays a unit quaternion. Two variants for the gyroscopic term of
// Euler's equations (identical for models without one):
//
// SemiImplicitEuler: explicit gyroscopic term ω1 = ω0 + h I⁻¹(n − ω0 × I ω0), what MuJoCo's and
//   Pinocchio's Euler do. WARNING: on a free rigid body it GAINS energy every step and blows up on
//   a fast spin about a non-symmetric axis (h |ω| of order 1 and beyond).
// SemiImplicitEulerImplicitGyroscopic: one Newton step on I(ω1 − ω0) + h ω1 × I ω1 = h n
//   (euler_equations.hpp): no blow-up on a fast spin; dissipative (energy decays monotonically) for
//   h |ω| below about 1; beyond that the single Newton step lets the energy grow transiently.
#pragma once
#include "rigiddyn/integrators/workspace.hpp"
#include "rigiddyn/models/model_interface.hpp"  // RIGIDDYN_ALWAYS_INLINE

namespace rigiddyn {

struct SemiImplicitEuler {
  template <class Model>
  using Workspace = NoWorkspace;

  template <class Model>
  RIGIDDYN_ALWAYS_INLINE static void step(const Model& model, typename Model::Coordinates& y, double h, NoWorkspace&) {
    model.kick(y, h);
    model.drift(y, h);
  }
};

struct SemiImplicitEulerImplicitGyroscopic {
  template <class Model>
  using Workspace = NoWorkspace;

  template <class Model>
  RIGIDDYN_ALWAYS_INLINE static void step(const Model& model, typename Model::Coordinates& y, double h, NoWorkspace&) {
    model.kick_implicit_gyroscopic(y, h);
    model.drift(y, h);
  }
};

}  // namespace rigiddyn
