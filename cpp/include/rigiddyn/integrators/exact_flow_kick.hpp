// Splitting "exact torque-free flow + kick by the loads" (Celledoni, Fassò, Säfström & Zanna,
// SIAM J. Sci. Comput. 30, 2008, the Strang form):
//
//   step(h) = kick(h/2) · [free translation(h), exact Euler–Poinsot flow(h)] · kick(h/2)
//
// The free rotation is the closed-form solution (exact/free_body.hpp: Jacobi elliptic functions,
// elliptic integral of the third kind for the attitude) over one step (FreeRotationFlow): the
// principal frame is computed once per body (each model holds the FreeRotationFlow of each of its
// rigid bodies, built with the model), the momentum-dependent parts at each step.
//
// ExactFlowKick: order 2 under loads (exact, to round-off, without couples); cost per step:
//   2 derivative evaluations (kicks; 1 between records where the loads do not read the velocities: a run merges
//   adjacent kicks, simulate/run_loop.hpp) + one FreeRotationFlow::advance (~0.2 µs, about two RK4 steps' worth: the
//   addition theorems over a short step, one Carlson R_F/R_J pair at near-unit arguments; ~0.5 µs on the full path of
//   long steps and extreme motions). Conserves on a free body everything the exact flow conserves: energy,
//   |L|, spatial L_W, unit |q| (to round-off per step). Under loads: the kinetic-energy change
//   equals the work of the kicks exactly; the translation is velocity Verlet (exact for a
//   constant world-frame force and gravity).
// ExactFreeFlow ("exact" in the registry, for `step` and models without attitude): the same step,
//   for torque-free bodies only: throws std::invalid_argument if a couple acts. simulate() with
//   Method::exact on one rigid body does not step at all: it evaluates the closed form at each record
//   time (scene/compile.hpp, CompiledScene::closed_form).
// Both are written once against the model interface (loads_kick, free_flow<ExactRotation>): for
// models without a gyroscopic term (particle, planar body) they are velocity Verlet, exact for
// constant loads (world-frame forces and couples) there.
#pragma once
#include "rigiddyn/always_inline.hpp"
#include "rigiddyn/exact/free_body.hpp"
#include "rigiddyn/integrators/free_flow_tags.hpp"
#include "rigiddyn/integrators/workspace.hpp"

#include <stdexcept>

namespace rigiddyn {

// The exact free rotation over h [s] (Euler–Poinsot, exact/free_body.hpp) of one body whose inertia
// `flow` was built for: q_WB_xyzw (4 doubles, x y z w, unit) and w_B (3 doubles, ω in B [rad/s]) are
// updated in place (NaN for a non-finite state). The per-body kernel of every model's
// free_flow<ExactRotation>.
inline void exact_free_rotation(const FreeRotationFlow& flow, double* q_WB_xyzw, double* w_B, double h) {
  Eigen::Quaterniond q_WB(Eigen::Vector4d(q_WB_xyzw[0], q_WB_xyzw[1], q_WB_xyzw[2], q_WB_xyzw[3]));
  Eigen::Vector3d w(w_B[0], w_B[1], w_B[2]);
  flow.advance(q_WB, w, h);
  for (int i = 0; i < 4; ++i) q_WB_xyzw[i] = q_WB.coeffs()[i];
  for (int i = 0; i < 3; ++i) w_B[i] = w[i];
}

// kick(h/2) · exact free flow(h) · kick(h/2); returns the Σ |Δω_B| of the two kicks [rad/s] (model.loads_kick).
template <class Model>
double exact_flow_kick_step(const Model& model, typename Model::Coordinates& y, double h) {
  double kicked = model.loads_kick(y, 0.5 * h);
  model.template free_flow<ExactRotation>(y, h);
  kicked += model.loads_kick(y, 0.5 * h);
  return kicked;
}

struct ExactFlowKick {
  template <class Model>
  using Workspace = NoWorkspace;

  template <class Model>
  RIGIDDYN_ALWAYS_INLINE static void step(const Model& model, typename Model::Coordinates& y, double h, NoWorkspace& /*w*/) {
    exact_flow_kick_step(model, y, h);
  }
  // The step opens and closes with loads_kick(edge_kick h) (simulate/run_loop.hpp, merged_steps)
  static constexpr double edge_kick = 0.5;
  template <class Model>
  RIGIDDYN_ALWAYS_INLINE static void between_kicks(const Model& model, typename Model::Coordinates& y, double h) {
    model.template free_flow<ExactRotation>(y, h);
  }
};

struct ExactFreeFlow {
  // the state at the start of the step (restored when the step is refused)
  template <class Model>
  struct Workspace {
    typename Model::Coordinates y0;
    Workspace(const Model& /*model*/, const typename Model::Coordinates& y) : y0(y.size()) {}
  };

  template <class Model>
  RIGIDDYN_ALWAYS_INLINE static void step(const Model& model, typename Model::Coordinates& y, double h, Workspace<Model>& w) {
    w.y0 = y;
    if (exact_flow_kick_step(model, y, h) != 0.0) {
      y = w.y0;
      throw std::invalid_argument(
          "method: expected a torque-free body for 'exact' (no torque), got a torque; use "
          "'exact_flow_kick' for bodies under torques");
    }
  }
};

}  // namespace rigiddyn
