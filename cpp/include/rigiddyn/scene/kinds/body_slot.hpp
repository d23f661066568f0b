// What every body kind of the scene model shares (scene/kinds/, one file per kind; the list in kind_list.hpp).
//
// A kind's slot is where one body lives in the coordinates y and the tangent ξ (at_y, at_xi) plus the
// constants its Newton–Euler needs. Every slot has the same members, which the scene model calls for each
// body (scene_model.hpp; a member missing from a kind is a compile error there):
//   y_size, xi_size                  its coordinates and tangent components
//   kinematics(y, clock, k)          BodyKinematics from y (body_kinematics.hpp), as elements see the body
//   rate(y, clock, k, w, dy)         its part of ẏ under the wrench w at the kinematics k
//   velocity(y, clock, k, w, xi)     its part of ξ (velocities, accelerations)
//   retract(y, θ, out)               y ⊕ Θ: vector parts added, an attitude q ⊗ exp(Θ_rot)
//   dexp_inv(θ, xi)                  ω ← dexp⁻¹_{−Θ} ω on an attitude part, identity elsewhere
//   project(y)                       an attitude back on the unit sphere
//   kick(y, k, w, h, gyroscopic)     velocities += h × accelerations (the gyroscopic kick of an Euler form)
//   translate(y, h), turn(y, h)      p += h v; an attitude or angle by h ω at fixed ω (drift)
//   free_rotation<Rotation>(y, h)    its attitude and ω by the free flow Rotation (the splittings)
//   loads_kick(y, k, w, h, kicks)    the exact flow of the loads part (VelocityKicks below); returns |Δω|
//   record(y, k, w, sums, H_O, R)    its energy and momenta into sums, its own momentum and pivot reaction
//   coordinates(state, y), state(y)  from and to its BodyState
//   attitude_y()                     where q_WB is in y (−1 without one)
// and has_mass_flow (a kind whose mass is a coordinate: scene/kinds/mass_*_slot.hpp add the mass part). Two members are
// optional: set_time(t) (a kind with piecewise-constant inputs, set at each piece of a run, as the elements') and
// record_internal(y, out) (a kind with coordinates of its own beyond the body's motion: the gyrostat's wheel speeds),
// and midpoint_newton(y0, mid, next, h) (a kind with an attitude and Euler's gyroscopic term: its ω̄ by a Newton step
// and its q̄ by the exact midpoint of q̇ = ½ q ⊗ ω̄ in the implicit midpoint's fixed point, midpoint_newton_correction
// and midpoint_attitude of integrators/implicit_midpoint.hpp). Four more let a model skip what nothing needs
// (OneBodySceneModel, scene/one_body_scene_model.hpp): constrained = true (a kind held by a pivot or a plane, whose
// reaction is an external force), reads_kinematics = false (a kind whose rate, velocity and kick read y and the wrench,
// never the kinematics), motion_kinematics(y, clock, k) (the kinematics but the attitude q_WB, for an evaluation in
// which no term reads it) and retract_motion(y, θ, out) (retract but the attitude, for a stage whose velocity reads
// none).
// A slot's place (SlotPlace: its body's index and its offsets in y and ξ) is its base class: FirstPlace, known at
// compile time, for the one body of a OneBodySceneModel (the kinds that template on it: Place). The members a step
// calls (kinematics to loads_kick above) are forced inline (RIGIDDYN_ALWAYS_INLINE) in the kinds a one-body layout
// carries: its stages stay in registers only when the whole step inlines, and GCC's growth limits otherwise outline
// whichever call crosses them (a heavy top's RK4 step measured 3× when its kinematics was outlined).
// The pointers y, dy, ξ, θ are the whole vectors; a slot reads its own block at at_y / at_xi. A slot may span
// several consecutive bodies (a tree's links, kinds/tree_slot.hpp): it then reads their kinematics, wrenches and
// states, and writes their records, as the arrays that start at its first body's, and has states(y, first) in
// place of state(y).
#pragma once
#include "rigiddyn/always_inline.hpp"
#include "rigiddyn/exact/free_body.hpp"
#include "rigiddyn/integrators/exact_flow_kick.hpp"
#include "rigiddyn/integrators/free_flow_tags.hpp"
#include "rigiddyn/integrators/implicit_midpoint.hpp"  // midpoint_newton_correction, midpoint_attitude
#include "rigiddyn/integrators/splitting_dlm.hpp"
#include "rigiddyn/models/euler_equations.hpp"  // cross_3
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/so3/coriolis_flow.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <tuple>
#include <type_traits>
#include <vector>

namespace rigiddyn::detail {

// Where a body lives in y and ξ: its index in the scene and the offsets of its blocks
struct SlotPlace {
  int body;
  Eigen::Index at_y, at_xi;
};

// The place of the one body of a model at the start of y and ξ, known at compile time (a OneBodySceneModel: the slot's
// arithmetic on y then resolves to fixed offsets, which keeps the integrator's stages in registers)
struct FirstPlace {
  FirstPlace(int, Eigen::Index, Eigen::Index) {}
  static constexpr int body = 0;
  static constexpr Eigen::Index at_y = 0, at_xi = 0;
};

// The place of the slots a group tuple holds (its first kind, a ParticleSlot<Place>, says it)
template <class Groups>
using place_of = typename std::tuple_element_t<0, Groups>::value_type::place;

// The instant of an evaluation: t of y [s], and the start of the step being taken [s] (the out-of-mass message)
struct StepClock {
  double t, step_start;
};

// What record sums over the bodies: kinetic energy T [J], linear momentum L_W [kg m/s], angular momentum H_W about
// W's origin [kg m²/s]
struct RecordSums {
  double T = 0.0;
  Eigen::Vector3d L_W = Eigen::Vector3d::Zero(), H_W = Eigen::Vector3d::Zero();
  // m v, T = ½ m v·v and p × m v of a body's centre of mass
  void add_translation(const BodyKinematics& k) {
    T += 0.5 * k.m * k.v_W.squaredNorm();
    L_W += k.m * k.v_W;
    H_W += k.p_W.cross(k.m * k.v_W);
  }
};

// out[0..2] += h f_W [N], out[3..5] += h (p × f_W + R_WB τ_B) [N m] of one body's wrench w at its kinematics k: its
// impulses about W's origin (scene_model.hpp), τ_B = 0 taken as such unless `torques` (no term turns vectors)
RIGIDDYN_ALWAYS_INLINE void add_wrench_impulses(const BodyKinematics& k, const BodyWrench& w, bool torques, double h,
                                                double* out) {
  Eigen::Vector3d M_W = cross_3(k.p_W, w.f_W);
  if (torques) M_W += times_3x3(k.R_WB, w.tau_B);  // written out: Eigen's product was a call out of the inlined steps
  for (int i = 0; i < 3; ++i) out[i] += h * w.f_W[i], out[3 + i] += h * M_W[i];
}

// Appends one body's record to `out` (scene_simulation.hpp): its kinematics k, its attitude as integrated (q_y, the
// attitude's 4 numbers in y; null for a kind without one: k's), its momentum about its own point and its pivot's
// reaction, its mass (the last three not in a coarse run of the estimate: estimate_records)
inline void append_body_record(const BodyKinematics& k, const double* q_y, const Eigen::Vector3d& momentum_O_W,
                               const Eigen::Vector3d& reaction_W, SceneSimulation& out) {
  append_values<3>(out.p_W, k.p_W.data());
  const double* q = q_y != nullptr ? q_y : k.q_WB.coeffs().data();
  append_values<4>(out.q_WB, q);
  append_values<3>(out.v_W, k.v_W.data());
  append_values<3>(out.w_B, k.w_B.data());
  if (out.estimate_records) return;
  append_values<3>(out.pivot_reaction_W, reaction_W.data());
  append_values<3>(out.angular_momentum_O_W, momentum_O_W.data());
  out.mass.push_back(k.m);
}

// Appends the energies (T, V, T + V) and the momenta L_W, H_W of a record to `out` (T, T + V and H_W alone in a
// coarse run of the estimate: estimate_records)
inline void append_record_sums(const RecordSums& sums, double V, SceneSimulation& out) {
  out.kinetic_energy.push_back(sums.T);
  out.total_energy.push_back(sums.T + V);
  append_values<3>(out.angular_momentum_W, sums.H_W.data());
  if (out.estimate_records) return;
  out.potential_energy.push_back(V);
  append_values<3>(out.linear_momentum_W, sums.L_W.data());
}

// Whether a kind's rate, velocity or kick read the kinematics (true unless it says reads_kinematics = false)
template <class Slot, class = void>
struct reads_kinematics : std::true_type {};
template <class Slot>
struct reads_kinematics<Slot, std::enable_if_t<!Slot::reads_kinematics>> : std::false_type {};

// Whether a kind is held by a constraint of W whose reaction is an external force (constrained = true: a pivot, a
// plane), so that its momentum balance is not applicable
template <class Slot, class = void>
struct is_constrained : std::false_type {};
template <class Slot>
struct is_constrained<Slot, std::enable_if_t<Slot::constrained>> : std::true_type {};

// Whether a kind sets its bodies' R_WB in kinematics itself (sets_rotation_matrices: a tree's links, from forward
// kinematics; a planar body, a turn about z), so that the model does not rebuild it from q_WB.
template <class Slot, class = void>
struct sets_rotation_matrices : std::false_type {};
template <class Slot>
struct sets_rotation_matrices<Slot, std::enable_if_t<Slot::sets_rotation_matrices>> : std::true_type {};

// Whether a kind retracts without its attitude (retract_motion)
template <class Slot, class = void>
struct has_retract_motion : std::false_type {};
template <class Slot>
struct has_retract_motion<Slot, std::void_t<decltype(std::declval<const Slot&>().retract_motion(
                                    static_cast<const double*>(nullptr), static_cast<const double*>(nullptr),
                                    static_cast<double*>(nullptr)))>> : std::true_type {};

// Whether a kind fills its kinematics without the attitude (motion_kinematics)
template <class Slot, class = void>
struct has_motion_kinematics : std::false_type {};
template <class Slot>
struct has_motion_kinematics<Slot, std::void_t<decltype(std::declval<const Slot&>().motion_kinematics(
                                       static_cast<const double*>(nullptr), std::declval<const StepClock&>(),
                                       std::declval<BodyKinematics&>()))>> : std::true_type {};

RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d three(const double* x) { return Eigen::Vector3d(x[0], x[1], x[2]); }

// Whether a slot has midpoint_newton(y0, mid, next, h) (the kinds with an attitude and Euler's gyroscopic term)
template <class Slot, class = void>
struct has_midpoint_newton : std::false_type {};
template <class Slot>
struct has_midpoint_newton<Slot, std::void_t<decltype(std::declval<const Slot&>().midpoint_newton(
                                     std::declval<const double*>(), std::declval<const double*>(),
                                     std::declval<double*>(), 0.0))>> : std::true_type {};

template <bool normalise, class Euler>
void free_dlm(DlmRotation<normalise>, const Euler& euler, double* q, double* w, double h) {
  dlm_free_rotation<normalise>(euler, q, w, h);
}

// The free rotation over h [s] of an attitude q (x, y, z, w) and its ω_B [rad/s] by the flow Rotation: the
// body's own exact flow (ExactRotation: free_flow<ExactRotation>), or the DLM rotation of its Euler form
template <class Rotation, class Euler>
void free_rotation_by(Rotation, const Euler& euler, const FreeRotationFlow& flow, double* q, double* w, double h) {
  if constexpr (std::is_same_v<Rotation, ExactRotation>) {
    exact_free_rotation(flow, q, w, h);
  } else {
    free_dlm(Rotation{}, euler, q, w, h);
  }
}

// The velocity increments of the loads part over h [s] from the start increments h a0 (model_interface.hpp
// loads_kick): Δu = h a0 and the mean ū − u = h a0 / 2, or, in a turning frame (turning = true), the exact flow
// of u̇ = a0 + M u with the Coriolis part M (so3/coriolis_flow.hpp): M v = −2 Ω × v for a centre of mass (λ = 2|Ω|;
// Ω = (0, 0, Ω_z) in a planar body's plane), M ω = I⁻¹ (s × ω) for a 3-D attitude (coriolis_torque_axis).
template <bool turning>
struct VelocityKicks {
  double h;
  Eigen::Vector3d w_F = Eigen::Vector3d::Zero(), w_plane = Eigen::Vector3d::Zero();  // the frame's Ω [rad/s] in F
  TurnCoefficients c_F{}, c_plane{};  // of λ = 2|Ω| h and of λ = 2|Ω_z| h
  const std::vector<CoriolisInertia>* inertia = nullptr;  // per body (a 3-D attitude's)

  VelocityKicks(double h_, const Eigen::Vector3d& w_frame, const std::vector<CoriolisInertia>* inertia_)
      : h(h_), inertia(inertia_) {
    if constexpr (turning) {
      w_F = w_frame, w_plane.z() = w_F.z();
      c_F = turn_coefficients(2.0 * w_F.norm() * h), c_plane = turn_coefficients(2.0 * std::abs(w_F.z()) * h);
    }
  }
  // Δv and v̄ − v of a centre of mass
  void translation(const Eigen::Vector3d& h_a0, Eigen::Vector3d& dv, Eigen::Vector3d& mean) const {
    linear(w_F, c_F, h_a0, dv, mean);
  }
  // the same for a planar body's centre of mass, in its plane
  void translation_in_plane(const Eigen::Vector3d& h_a0, Eigen::Vector3d& dv, Eigen::Vector3d& mean) const {
    linear(w_plane, c_plane, h_a0, dv, mean);
  }
  // Δω and ω̄ − ω of the 3-D attitude of body `body` at the attitude q_WB
  void rotation(int body, const Eigen::Quaterniond& q_WB, const Eigen::Vector3d& h_a0, Eigen::Vector3d& dw,
                Eigen::Vector3d& mean) const {
    if constexpr (turning) {
      const CoriolisInertia& b = (*inertia)[body];
      Eigen::Vector3d axis;
      const double lambda = coriolis_torque_axis(b, q_WB.conjugate() * w_F, axis);
      const auto coriolis = [&](const Eigen::Vector3d& w) { return Eigen::Vector3d(b.inverse * cross_3(axis, w)); };
      exact_linear_kick(h_a0, h, turn_coefficients(lambda * h), coriolis, dw, mean);
    } else {
      dw = h_a0, mean = 0.5 * h_a0;
    }
  }

 private:
  void linear(const Eigen::Vector3d& w, const TurnCoefficients& c, const Eigen::Vector3d& h_a0, Eigen::Vector3d& dv,
              Eigen::Vector3d& mean) const {
    if constexpr (turning) {
      const auto coriolis = [&](const Eigen::Vector3d& v) { return Eigen::Vector3d(-2.0 * cross_3(w, v)); };
      exact_linear_kick(h_a0, h, c, coriolis, dv, mean);
    } else {
      dv = h_a0, mean = 0.5 * h_a0;
    }
  }
};

}  // namespace rigiddyn::detail
