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
// For models without a gyroscopic term (particle, planar body): fixed-point iteration on ȳ with
// the same tolerance and cap.
#pragma once
#include "rigiddyn/integrators/splitting_parts.hpp"

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

// J⁻¹ r for the Jacobian J = I + τ (ω̄^ I − (I ω̄)^) (τ = h/2) of the midpoint residual multiplied by I:
// column j is I e_j + τ (ω̄ × I e_j − (I ω̄) × e_j); solved in closed form (solve_3x3: J = I + O(h|ω|)
// is far from singular where the iteration converges).
inline Eigen::Vector3d midpoint_newton_correction(const Eigen::Matrix3d& I, const Eigen::Vector3d& w_bar, double tau,
                                                  const Eigen::Vector3d& r) {
  const Eigen::Vector3d Iw = times_3x3(I, w_bar);
  Eigen::Matrix3d J;
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector3d w_x_Ij = cross_3(w_bar, I.col(j)), Iw_x_ej = cross_3(Iw, Eigen::Vector3d::Unit(j));
    for (int i = 0; i < 3; ++i) J(i, j) = I(i, j) + tau * (w_x_Ij(i) - Iw_x_ej(i));
  }
  return solve_3x3(J.row(0), J.row(1), J.row(2), r);
}

// Returns true if the Newton iteration converged within max_iterations.
template <class Euler, LoadKind kind>
bool implicit_midpoint_step(const RigidBodyModel<Euler, kind>& model, RigidBodyCoordinates& y, double h) {
  using namespace implicit_midpoint_solver;
  const Eigen::Matrix3d I = inertia_matrix(model.euler());
  const Eigen::Quaterniond q0(Eigen::Vector4d(y.segment<4>(3)));
  const Eigen::Vector3d v0 = y.segment<3>(7), w0 = y.segment<3>(10);
  Eigen::Vector3d w_bar = w0, v_bar = v0;
  RigidBodyCoordinates mid = y;  // ȳ = (y0 + y1)/2
  double power = 0.0;
  bool converged = false;
  for (int k = 0; k < max_iterations && !converged; ++k) {
    const Eigen::Quaterniond q1 = q0 * midpoint_rotation(h * w_bar);
    mid.segment<4>(3) = 0.5 * (q0.coeffs() + q1.coeffs());
    mid.segment<3>(7) = v_bar;
    mid.segment<3>(10) = w_bar;
    const RigidBodyTangent xi = model.velocity(mid);
    power = xi(12);
    const Eigen::Vector3d r_w = w_bar - w0 - 0.5 * h * xi.segment<3>(9);
    const Eigen::Vector3d r_v = v_bar - v0 - 0.5 * h * xi.segment<3>(6);
    const Eigen::Vector3d dw = midpoint_newton_correction(I, w_bar, 0.5 * h, times_3x3(I, r_w));
    w_bar -= dw;
    v_bar -= r_v;
    const bool w_done = dw.norm() <= tolerance * (w_bar.norm() + h * xi.segment<3>(9).norm());
    const bool v_done = r_v.norm() <= tolerance * (v_bar.norm() + h * xi.segment<3>(6).norm());
    converged = w_done && v_done;
  }
  y.segment<3>(0) += h * v_bar;
  y.segment<4>(3) = (q0 * midpoint_rotation(h * w_bar)).normalized().coeffs();
  y.segment<3>(7) = 2.0 * v_bar - v0;
  y.segment<3>(10) = 2.0 * w_bar - w0;
  y(13) += h * power;
  return converged;
}

// step() returns true if the solver converged (the only integrator whose step reports it).
struct ImplicitMidpoint {
  template <class Model>
  static bool step(const Model& model, typename Model::Coordinates& y, double h) {
    if constexpr (is_rigid_body_model_v<Model>) {
      return implicit_midpoint_step(model, y, h);
    } else {  // fixed point ȳ = y0 + (h/2) f(ȳ)
      static_assert(!has_gyroscopic_term_v<Model>,
                    "the fixed-point midpoint branch is for models without a gyroscopic term: a model with one must "
                    "take the rigid-body branch (Newton on the mean angular velocity)");
      using namespace implicit_midpoint_solver;
      typename Model::Coordinates mid = y;
      bool converged = false;
      for (int k = 0; k < max_iterations && !converged; ++k) {
        const typename Model::Coordinates next = y + (0.5 * h) * model.rate(mid);
        const double change = (next - mid).norm();
        mid = next;
        converged = change <= tolerance * mid.norm();
      }
      y = 2.0 * mid - y;
      model.project(y);
      return converged;
    }
  }
};

}  // namespace rigiddyn
