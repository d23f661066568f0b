// Splitting "exact torque-free flow + kick by the loads" (Celledoni, Fassò, Säfström & Zanna,
// SIAM J. Sci. Comput. 30, 2008, the Strang form):
//
//   step(h) = kick(h/2) · [free translation(h), exact Euler–Poinsot flow(h)] · kick(h/2)
//
// The free rotation is the closed-form solution (exact/free_body.hpp: Jacobi elliptic functions,
// elliptic integral of the third kind for the attitude) over one step (FreeRotationFlow): the
// principal frame is computed once per inertia (kept per thread while the inertia stays the same),
// the momentum-dependent parts at each step.
//
// ExactFlowKick: order 2 under loads (exact, to round-off, without couples); cost per step:
//   2 derivative evaluations (kicks) + one FreeRotationFlow::advance (~0.5 µs: two Carlson
//   R_F/R_J pairs, one sn/cn/dn, K; a few RK4 steps' worth). Conserves on a free body everything the exact flow conserves: energy,
//   |L|, spatial L_W, unit |q| (to round-off per step). Under loads: the kinetic-energy change
//   equals the work of the kicks exactly; the translation is velocity Verlet (exact for a
//   constant world-frame force and gravity).
// ExactFreeFlow ("exact" in the registry, for `step` and models without attitude): the same step,
//   for torque-free bodies only: throws std::invalid_argument if a couple acts. simulate() with
//   Method::exact does not step at all: it evaluates the closed form at each record time
//   (simulate/simulate_exact.hpp).
// For models without a gyroscopic term (particle, planar body) both are velocity Verlet, exact for
// constant loads (world-frame forces and couples) there.
#pragma once
#include "rigiddyn/exact/free_body.hpp"
#include "rigiddyn/integrators/splitting_parts.hpp"

#include <stdexcept>

namespace rigiddyn {

// The FreeRotationFlow of the inertia I_B [kg m²]: built on the first call and again whenever I_B
// changes (one per thread), so that the principal frame is not recomputed at every step.
inline const FreeRotationFlow& free_rotation_flow(const Eigen::Matrix3d& I_B) {
  thread_local FreeRotationFlow flow(Eigen::Matrix3d::Identity());
  if (flow.inertia() != I_B) flow = FreeRotationFlow(I_B);
  return flow;
}

// The exact free rotation over h [s] (Euler–Poinsot, exact/free_body.hpp).
template <class Euler>
void exact_free_rotation(const Euler& euler, RigidBodyCoordinates& y, double h) {
  Eigen::Quaterniond q_WB(Eigen::Vector4d(y.segment<4>(3)));
  Eigen::Vector3d w_B = y.segment<3>(10);
  free_rotation_flow(inertia_matrix(euler)).advance(q_WB, w_B, h);
  y.segment<4>(3) = q_WB.coeffs();
  y.segment<3>(10) = w_B;
}

// kick(h/2) · exact free flow(h) · kick(h/2); returns the sum of |Δω| of the two kicks [rad/s].
template <class Euler, LoadKind kind>
double exact_flow_kick_step(const RigidBodyModel<Euler, kind>& model, RigidBodyCoordinates& y, double h) {
  double kicked = loads_kick(model, y, 0.5 * h).norm();
  free_translation(y, h);
  exact_free_rotation(model.euler(), y, h);
  kicked += loads_kick(model, y, 0.5 * h).norm();
  return kicked;
}

struct ExactFlowKick {
  template <class Model>
  static void step(const Model& model, typename Model::Coordinates& y, double h) {
    if constexpr (is_rigid_body_model_v<Model>) {
      exact_flow_kick_step(model, y, h);
    } else {  // no gyroscopic term (asserted in velocity_verlet)
      velocity_verlet(model, y, h);
    }
  }
};

struct ExactFreeFlow {
  template <class Model>
  static void step(const Model& model, typename Model::Coordinates& y, double h) {
    if constexpr (is_rigid_body_model_v<Model>) {
      const RigidBodyCoordinates y0 = y;
      if (exact_flow_kick_step(model, y, h) != 0.0) {
        y = y0;
        throw std::invalid_argument(
            "method: expected a torque-free body for 'exact' (no torque), got a torque; use "
            "'exact_flow_kick' for bodies under torques");
      }
    } else {  // no gyroscopic term (asserted in velocity_verlet)
      velocity_verlet(model, y, h);
    }
  }
};

}  // namespace rigiddyn
