// The small interface every model offers to the fixed-step integrators (integrators/*.hpp), so each
// method is written once and compiles, per model, to what a hand-written loop would be (no virtual
// call). A model is a body plus the loads held constant during the current step. Its state lives
// on (vector space) × SO(3)^k and is stored as flat coordinates y (a fixed-size Eigen vector; unit
// quaternions stored (x, y, z, w) inside it); the last coordinate of every model is the work [J]
// done by the applied loads (gravity included) since the start, integrated alongside the motion
// (dW/dt = power), so the work-energy equation T2 − T1 = U12 (Craig, "Rigid Body Dynamics" slides) can be checked on any run.
//
//   using Coordinates, Tangent;               Eigen::Matrix<double, nq, 1>, Eigen::Matrix<double, nv, 1>
//   Coordinates rate(y)                       ẏ in coordinates (quaternion rate q̇ = ½ q ⊗ (ω_B, 0)),
//                                             for methods that add increments to y (Euler, RK4)
//   void project(y)                           back onto the state space (normalise the quaternions)
//   Tangent velocity(y)                       ξ: body-trivialised velocity (ω_B for each attitude)
//   Coordinates retract(y, Θ)                 y ⊕ Θ: vector parts added, q ⊗ exp(Θ_rot) for attitudes
//   Tangent velocity_at(y, Θ)                 ξ(y ⊕ Θ), free to skip the parts of y ⊕ Θ that ξ does
//                                             not read (RKMK4's stages)
//   Tangent dexp_inv(Θ, ξ)                    dexp⁻¹ of the attitude parts (identity elsewhere),
//                                             truncated after the second commutator (RKMK4)
//   void kick(y, h), kick_implicit_gyroscopic(y, h)
//                                             velocities += h × accelerations at y (semi-implicit
//                                             Euler; the second with the implicit gyroscopic term)
//   void drift(y, h)                          positions and attitudes (and work) moved over h with
//                                             the current velocities
//   RecordedState record(y)                   a uniform description for simulate's recorder
// and states, next to its definition, whether its equations carry Euler's gyroscopic term
// (has_gyroscopic_term below): the structure-preserving methods may fall back to a plain
// kick-drift form only for models without one.
#pragma once
#include "rigiddyn/always_inline.hpp"  // RIGIDDYN_ALWAYS_INLINE, for every model and integrator function

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <type_traits>

namespace rigiddyn {

// True for a model whose equations of motion contain Euler's gyroscopic term ω × I ω (the spatial
// rigid body, in every Euler form and under every LoadKind), false for one without it (particle,
// planar body). Deliberately left undefined here: every model specialises it next to its own
// definition, so a method asking about a model that has not said fails to compile.
template <class Model>
struct has_gyroscopic_term;
template <class Model>
inline constexpr bool has_gyroscopic_term_v = has_gyroscopic_term<Model>::value;

// What simulate records of any model, in the rigid-body layout (a particle has q = identity and
// ω = 0; a planar body lives in the xy plane of W and turns about z).
struct RecordedState {
  Eigen::Vector3d p_W;            // centre of mass position in W [m]
  Eigen::Quaterniond q_WB;        // attitude, as stored (norm not forced to 1)
  Eigen::Vector3d v_W;            // centre of mass velocity in W [m/s]
  Eigen::Vector3d w_B;            // angular velocity in B [rad/s]
  double kinetic_energy;          // T = ½ m v·v + ½ ω·I ω [J]
  double potential_energy;        // V = −m g·p_W of uniform gravity (0 without gravity) [J]
  double angular_momentum_norm;   // |H_G| = |I ω| about the centre of mass [kg m²/s]
  double work;                    // work of all applied loads and gravity since t0 [J]
};

}  // namespace rigiddyn
