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
// Solver: the fixed point ȳ = y0 + (h/2) ẏ(ȳ), each iterate's ω̄ corrected by Newton's step with the exact
// Jacobian of the gyroscopic term (midpoint_newton_correction below),
//   J = I + (h/2)(ω̄^ I − (I ω̄)^)   (the residual multiplied by I),
// the attitude dependence of couples given in W and of forces given in B left to the iteration
// (it converges linearly at a rate O(h²|n|/|I|) there, quadratically for torque-free bodies).
// Stops when the last change of the motion's coordinates is below `tolerance` relative to their size
// (midpoint_converged below), or after `max_iterations`: then the last iterate is kept and step() returns false,
// which simulate() counts (unconverged_steps of the run's records; the Python binding warns). At h|ω| ≲ 1 this is
// never reached; near the separatrix it happens from h|ω| ≈ 3.5.
//
// Order 2 (symmetric); cost per step: one derivative evaluation and one 3×3 solve per Newton
// iteration, typically 3–5 at h|ω| ~ 0.01–0.5. Conserves on a free body: the energy and |L|
// (quadratic invariants of Euler's equations) up to the solver tolerance, unit |q| exactly. Does
// NOT keep the spatial L_W (the attitude drifts from the invariable plane by O(h²) per unit time).
//
// Written once against the model interface, with one optional hook. A model may offer
//   bool implicit_midpoint_step(Coordinates& y, double h) const
// which takes the whole step by a solve of the midpoint equations that uses its structure and returns whether it
// converged: the scene model's fixed point below, which takes a kinematic tree by the variational midpoint method,
// its iterates mixed by Anderson's method (scene/scene_model.hpp, scene/kinds/tree_slot.hpp). A model without the hook
// (particle, planar body, any model whose coordinates are a vector space or whose derivative has no stiff
// gyroscopic part) gets the fixed-point iteration ȳ = y0 + (h/2) rate(ȳ) on its rate() with the same tolerance and
// cap, then y1 = 2ȳ − y0 and project(y1); a model that offers
//   void midpoint_newton(const Coordinates& y0, const Coordinates& mid, Coordinates& next, double h) const
// (a one-body scene layout) corrects each iterate there: its body's ω̄ by the Newton step of the gyroscopic term and
// its q̄ by the exact midpoint of q̇ = ½ q ⊗ ω̄.
#pragma once
#include "rigiddyn/always_inline.hpp"
#include "rigiddyn/integrators/workspace.hpp"
#include "rigiddyn/models/euler_equations.hpp"
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

// The Newton step of a body's mean angular velocity ω̄ in the implicit midpoint's fixed point ȳ = y0 + (h/2) ẏ(ȳ)
// (a model's midpoint_newton, above): next_w holds the map's ω0 + (h/2) ω̇(ȳ) at ω̄ = mid_w, and becomes
//   ω̄ − J⁻¹ I (ω̄ − next_w),  J = I + (h/2)(ω̄^ I − (I ω̄)^)
// the Jacobian of Euler's gyroscopic term (gyroscopic_jacobian): Newton's method, quadratic for a
// torque-free body (the torque's dependence on the state left to the iteration), where the plain map contracts only
// while (h/2)|∂ω̇/∂ω| < 1 (measured on I = (1, 2, 3): unconverged steps from h|ω| = 0.5, a wrong motion at 2). A
// sphere has no gyroscopic term: its map is left as it is.
template <class Euler>
RIGIDDYN_ALWAYS_INLINE void midpoint_newton_correction(const Euler& euler, const double* mid_w, double* next_w, double h) {
  if constexpr (!std::is_same_v<Euler, SphericalEuler>) {
    const Eigen::Matrix3d I = inertia_matrix(euler);
    const Eigen::Vector3d w_bar = Eigen::Vector3d(mid_w[0], mid_w[1], mid_w[2]);
    const Eigen::Matrix3d J = gyroscopic_jacobian(I, w_bar, times_3x3(I, w_bar), 0.5 * h);
    const Eigen::Vector3d residual = w_bar - Eigen::Vector3d(next_w[0], next_w[1], next_w[2]);
    const Eigen::Vector3d dw = solve_3x3(J.row(0), J.row(1), J.row(2), times_3x3(I, residual));
    for (int i = 0; i < 3; ++i) next_w[i] = w_bar[i] - dw[i];
  }
}

// The implicit midpoint's mean attitude for the mean angular velocity ω̄ (xyzw quaternions): the midpoint rule on
// q̇ = ½ q ⊗ (ω̄, 0), linear in q, solved exactly, q̄ = q0 ⊗ (1 − a)⁻¹ = q0 ⊗ (1, a)/(1 + |a|²), a = h ω̄/4, so that
// 2q̄ − q0 = q0 ⊗ (1 + a)(1 − a)⁻¹ is the Cayley step of the midpoint rule; the plain map
// contracts by h|ω|/4 an iterate only (20 iterates short of 1e-14 from h|ω| = 1).
RIGIDDYN_ALWAYS_INLINE void midpoint_attitude(const double* q0, const double* w_bar, double h, double* q_bar) {
  const Eigen::Vector3d a = (0.25 * h) * Eigen::Vector3d(w_bar[0], w_bar[1], w_bar[2]);
  const double scale = 1.0 / (1.0 + a.squaredNorm());
  const Eigen::Quaterniond mean = Eigen::Quaterniond(q0[3], q0[0], q0[1], q0[2]) *
                                  Eigen::Quaterniond(scale, scale * a.x(), scale * a.y(), scale * a.z());
  for (int i = 0; i < 4; ++i) q_bar[i] = mean.coeffs()[i];
}

// Whether a model says where t is in its coordinates (time_index(): the motion's coordinates come before it)
template <class Model, class = void>
struct has_time_index : std::false_type {};
template <class Model>
struct has_time_index<Model, std::void_t<decltype(std::declval<const Model&>().time_index())>> : std::true_type {};

// The fixed point's stopping test: the last change of the motion's coordinates (those before t, where the model says
// where t is; all of them otherwise) at most implicit_midpoint_solver::tolerance of their size. t and the run's
// bookkeeping after it (works and impulses, which grow over a run) are left out, so that a step converges alike
// from any t0 and at any point of a run: measured with them in, a free body's energy held to 7.7e-14 over 20 000
// steps from t0 = 0 and to 6.0e-12 from t0 = 1e9 s, where t's size loosened the test 1e9-fold.
template <class Model, class Coordinates>
bool midpoint_converged(const Model& model, const Coordinates& mid, const Coordinates& next) {
  Eigen::Index m = next.size();
  if constexpr (has_time_index<Model>::value) m = model.time_index();
  return (next.head(m) - mid.head(m)).norm() <= implicit_midpoint_solver::tolerance * next.head(m).norm();
}

// True for a model with the hook implicit_midpoint_step(y, h) (see the top of this file).
template <class Model, class = void>
struct has_implicit_midpoint_step : std::false_type {};
template <class Model>
struct has_implicit_midpoint_step<Model, std::void_t<decltype(std::declval<const Model&>().implicit_midpoint_step(
                                               std::declval<typename Model::Coordinates&>(), 0.0))>>
    : std::true_type {};

// True for a model with midpoint_newton(y0, mid, next, h) (see the top of this file).
template <class Model, class = void>
struct has_midpoint_newton : std::false_type {};
template <class Model>
struct has_midpoint_newton<Model, std::void_t<decltype(std::declval<const Model&>().midpoint_newton(
                                      std::declval<const typename Model::Coordinates&>(),
                                      std::declval<const typename Model::Coordinates&>(),
                                      std::declval<typename Model::Coordinates&>(), 0.0))>> : std::true_type {};

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
        if constexpr (has_midpoint_newton<Model>::value) model.midpoint_newton(y, w.mid, w.next, h);
        converged = midpoint_converged(model, w.mid, w.next);
        w.mid.swap(w.next);
      }
      y = 2.0 * w.mid - y;
      model.project(y);
      return converged;
    }
  }
};

}  // namespace rigiddyn
