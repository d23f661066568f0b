// The small interface every model offers to the fixed-step integrators (integrators/*.hpp), so each
// method is written once and compiles, per model, to what a hand-written loop would be (no virtual
// call). A model is one or more bodies plus the loads held constant during the current step. Its state
// lives on (vector space) × SO(3)^k and is stored as flat coordinates y (an Eigen vector, fixed-size
// for the models of one body (scene/one_body_layouts.hpp), Eigen::VectorXd for any scene: an integrator sizes its workspace from y once per
// run, integrators/workspace.hpp, and never default-constructs a vector to index it; unit quaternions
// stored (x, y, z, w) inside y). Every member writes into vectors its caller sized, so that no evaluation
// allocates (out never overlaps y or Θ); the
// coordinates carry the work [J] each element has done since the start where it has no closed form, integrated
// alongside the motion (dW/dt = power), so the work-energy equation T2 − T1 = U12 (Craig, "Rigid Body Dynamics"
// slides) can be checked on any run.
//
//   using Coordinates, Tangent;               e.g. Eigen::Matrix<double, nq, 1>, Eigen::Matrix<double, nv, 1>
//   Eigen::Index tangent_count()              the size of ξ (a dynamic-size model only)
//   void rate(y, dy)                          dy = ẏ in coordinates (quaternion rate q̇ = ½ q ⊗ (ω_B, 0)),
//                                             for methods that add increments to y (Euler, RK4)
//   void project(y)                           back onto the state space (normalise the quaternions)
//   void velocity(y, ξ)                       ξ: body-trivialised velocity (ω_B for each attitude)
//   void retract(y, Θ, out)                   out = y ⊕ Θ: vector parts added, q ⊗ exp(Θ_rot) for attitudes
//   void velocity_at(y, Θ, ξ)                 ξ = ξ(y ⊕ Θ), free to skip the parts of y ⊕ Θ that ξ does
//                                             not read (RKMK4's stages)
//   void dexp_inv(Θ, ξ)                       ξ ← dexp⁻¹ of its attitude parts (identity elsewhere),
//                                             truncated after the second commutator (RKMK4)
//   void kick(y, h), kick_implicit_gyroscopic(y, h)
//                                             velocities += h × accelerations at y (semi-implicit
//                                             Euler; the second with the implicit gyroscopic term)
//   void drift(y, h)                          positions and attitudes (and work) moved over h with
//                                             the current velocities
//   double loads_kick(y, h)                   the exact flow of the loads part over h [s]: positions,
//                                             attitudes (and time) frozen, velocities += h M⁻¹ × the
//                                             applied wrench WITHOUT the gyroscopic term, work updated;
//                                             returns Σ |Δω_B| [rad/s] over the bodies whose free
//                                             rotation has a gyroscopic term (the spatial rigid bodies;
//                                             ExactFreeFlow refuses a step where it is non-zero)
//   template <class Rotation>
//   void free_flow(y, h)                      the free part over h [s]: p += h v for every body, each
//                                             attitude by the rotation flow Rotation (a tag of
//                                             integrators/free_flow_tags.hpp: DlmRotation<normalise>,
//                                             ExactRotation)
//   void record(y, t, out)                    append the record of y at time t [s] to a SceneSimulation
// and, optionally, bool implicit_midpoint_step(y, h): its own solve of the implicit midpoint rule
// (integrators/implicit_midpoint.hpp), and bool kicks_merge(): true when two loads_kick at the same positions,
// attitudes and t are one loads_kick of their summed h (the loads do not depend on the velocities, and no mass
// moves between them), so the run may merge a step's closing kick with the next step's opening one
// (simulate/run_loop.hpp; a model without it is never merged). The structure-preserving methods (splitting_dlm, yoshida4,
// exact_flow_kick) are compositions of loads_kick and free_flow only: the gyroscopic term lives in
// each model's free rotation, so no method has a branch (or a fallback) per kind of model.
#pragma once
#include "rigiddyn/always_inline.hpp"  // RIGIDDYN_ALWAYS_INLINE, for every model and integrator function

#include <Eigen/Core>

namespace rigiddyn {

}  // namespace rigiddyn
