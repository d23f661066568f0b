// The implicit midpoint rule (Hairer, Lubich & Wanner, GNI I.1 and IV.2):
//
//   y1 = y0 + h f(ȳ),  ȳ = (y0 + y1)/2,
//
// applied to the whole rigid-body system. The attitude equation q̇ = ½ q ⊗ (ω, 0) is linear in q,
// so for a given mean angular velocity ω̄ its midpoint step is the Cayley transform
//   q1 = q0 ⊗ c,  c = ((1 − |a|²), 2a)/(1 + |a|²) (scalar, vector),  a = h ω̄/4,
// a unit quaternion: |q| is exact. The unknowns (ω̄, v̄) solve ω̄ = ω0 + (h/2) ω̇(ȳ),
// v̄ = v0 + (h/2) v̇(ȳ); then ω1 = 2ω̄ − ω0, v1 = 2v̄ − v0, p1 = p0 + h v̄, work1 = work0 + h P(ȳ).
//
// Solver: Newton on ω̄ with the exact Jacobian of the gyroscopic term,
//   J = I + (h/2)(ω̄^ I − (I ω̄)^)   (the residual multiplied by I),
// the attitude dependence of couples given in W and of forces given in B left to the iteration
// (it converges linearly at a rate O(h²|n|/|I|) there, quadratically for torque-free bodies).
// Stops when the correction is below `tolerance` relative to |ω̄| + h|ω̇| (and likewise for v̄),
// or after `max_iterations`: then the last iterate is kept and step() returns false, which simulate()
// counts (Trajectory::unconverged_steps; the Python binding warns). At h|ω| ≲ 1 this is never
// reached; near the separatrix it happens from h|ω| ≈ 3.5.
//
// Order 2 (symmetric); cost per step: one derivative evaluation and one 3×3 solve per Newton
// iteration, typically 3–5 at h|ω| ~ 0.01–0.5. Conserves on a free body: the energy and |L|
// (quadratic invariants of Euler's equations) up to the solver tolerance, unit |q| exactly. Does
// NOT keep the spatial L_W (the attitude drifts from the invariable plane by O(h²) per unit time).
//
// Written once against the model interface, with one optional hook. A model may offer
//   bool implicit_midpoint_step(Coordinates& y, double h) const
// which takes the whole step by a solve of the midpoint equations that uses its structure and returns whether it
// converged: RigidBodyModel's Newton iteration on ω̄ above (the Jacobian of Euler's equations gyroscopic_jacobian,
// the attitude by the Cayley map midpoint_rotation, the stopping rule of implicit_midpoint_solver); the scene
// model's fixed point below, which takes a kinematic tree by the variational midpoint method, its iterates mixed by
// Anderson's method (scene/scene_model.hpp, scene/kinds/tree_slot.hpp). A model without the hook
// (particle, planar body, any model whose coordinates are a vector space or whose derivative has no stiff
// gyroscopic part) gets the fixed-point iteration ȳ = y0 + (h/2) rate(ȳ) on its rate() with the same tolerance and
// cap, then y1 = 2ȳ − y0 and project(y1).
#pragma once
#include "rigiddyn/integrators/workspace.hpp"
#include "rigiddyn/models/model_interface.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <type_traits>
#include <utility>

namespace rigiddyn {

namespace implicit_midpoint_solver {
inline constexpr double tolerance = 1e-14;  // last correction / size of the unknown
inline constexpr int max_iterations = 20;
}  // namespace implicit_midpoint_solver

// The Cayley map of the midpoint rule on q̇ = ½ q ⊗ (ω, 0): c = (1 + a)(1 − a)⁻¹, a = (h ω̄/4, 0).
inline Eigen::Quaterniond midpoint_rotation(const Eigen::Vector3d& h_w) {
  const Eigen::Vector3d a = 0.25 * h_w;
  const double a2 = a.squaredNorm(), scale = 1.0 / (1.0 + a2);
  return Eigen::Quaterniond((1.0 - a2) * scale, 2.0 * scale * a.x(), 2.0 * scale * a.y(), 2.0 * scale * a.z());
}

// True for a model with the hook implicit_midpoint_step(y, h) (see the top of this file).
template <class Model, class = void>
struct has_implicit_midpoint_step : std::false_type {};
template <class Model>
struct has_implicit_midpoint_step<Model, std::void_t<decltype(std::declval<const Model&>().implicit_midpoint_step(
                                               std::declval<typename Model::Coordinates&>(), 0.0))>>
    : std::true_type {};

// step() returns true if the solver converged (the only integrator whose step reports it).
struct ImplicitMidpoint {
  // the fixed point's iterates ȳ and the rate at ȳ (unused by a model with the hook)
  template <class Model>
  struct Workspace {
    typename Model::Coordinates mid, next, rate;
    Workspace(const Model& /*model*/, const typename Model::Coordinates& y) : mid(y.size()), next(y.size()), rate(y.size()) {}
  };

  template <class Model>
  static bool step(const Model& model, typename Model::Coordinates& y, double h, Workspace<Model>& w) {
    if constexpr (has_implicit_midpoint_step<Model>::value) {
      return model.implicit_midpoint_step(y, h);
    } else {  // fixed point ȳ = y0 + (h/2) f(ȳ)
      using namespace implicit_midpoint_solver;
      w.mid = y;
      bool converged = false;
      for (int k = 0; k < max_iterations && !converged; ++k) {
        model.rate(w.mid, w.rate);
        w.next = y + (0.5 * h) * w.rate;
        const double change = (w.next - w.mid).norm();
        w.mid.swap(w.next);
        converged = change <= tolerance * w.mid.norm();
      }
      y = 2.0 * w.mid - y;
      model.project(y);
      return converged;
    }
  }
};

}  // namespace rigiddyn
