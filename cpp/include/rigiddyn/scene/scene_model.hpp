// SceneModel: the integrator model (models/model_interface.hpp) of a compiled scene — any number of
// bodies of any kind and the force elements declared, nothing else.
//
// Coordinates y (Eigen::VectorXd), per body in the scene's order:
//   particle  (p_W 3, v_W 3)                        no attitude: a particle pays nothing for one
//   planar    (x, y, θ, v_x, v_y, ω)
//   rigid     (p_W 3, q_WB xyzw 4, v_W 3, w_B 3)
//   pivoted   (q_WB xyzw 4, w_B 3)                   pinned at O: the centre of mass follows the attitude
//   pivoted planar (θ, ω)
// and, right after its own, the mass m [kg] of a particle or rigid body with a MassFlow (scene/mass_flow.hpp;
// tangent ṁ); then t [s] (so that every method evaluates time-dependent forces at its own stage times), then one
// work slot per element [J] (its work since t0, integrated with the motion: dW_e/dt = P_e), then one mass-flow
// energy slot per body with a MassFlow, in the scene's order [J] (dE_b/dt = the mass-flow power below).
// Tangent ξ: per body (particle v_W, a_W; planar the 6 rates; rigid v_W, w_B, a_W, alpha_B; pivoted
// w_B, alpha_B; pivoted planar ω, α), then dt/dt = 1, then each element's power [W], then each mass-flow power [W].
//
// The work–energy balance with a mass flow. T = ½ m |v|² + ½ ω·I ω changes with the mass as well as with the work:
// m v̇ = f and I ω̇ + ω × I ω = τ (mass_flow.hpp) give
//   dT/dt = Σ_e P_e + ½ ṁ |v|² + ½ ω·(dI/dt) ω,     dI/dt = ṁ dI/dm (I_C0 ṁ/m0 under InertiaRule::scaled),
// the last two terms the mass-flow power of the body: the kinetic energy, at the body's own velocity, of the
// mass that leaves (ṁ < 0) or joins it. Its integral, the mass-flow energy E_b, is integrated with the motion as
// the works are, so that T − T(0) = Σ_e W_e + Σ_b E_b holds to the method's error on every run. Where a method
// moves the masses alone (drift, free_flow, mass_part: v and ω fixed), E_b takes the exact change of T there,
// ½ Δm |v|² + ½ ω·(I(m + Δm) − I(m)) ω; the kicks keep the masses (no E_b), and the splittings then close the
// balance to round-off but for the free rotation's own energy error (none with ExactRotation).
// "W" is the scene frame: in a moving frame F the states are relative to F and the model is the same
// (the compiled fictitious terms, scene/elements/fictitious_forces.hpp, add the frame's forces).
//
// One evaluation: every body's kinematics (body_kinematics.hpp) from y, wrenches zeroed, each element
// adds its wrenches once (one std::visit per element: an element that is not declared does not exist),
// then Newton–Euler per body in one function per kind (newton_euler below), the rigid bodies grouped
// by Euler form (a sphere pays nothing for the gyroscopic term), the pivoted bodies by the Euler form of
// their inertia about the pivot (models/pivoted_body.hpp: Euler's equations about O, the one home of the
// pivoted Newton–Euler); a body kind that is not present costs nothing. Scratch buffers are sized when the
// model is built: an evaluation allocates nothing (so a model is not shared between threads: each run
// copies its own).
#pragma once
#include "rigiddyn/exact/free_body.hpp"
#include "rigiddyn/integrators/exact_flow_kick.hpp"
#include "rigiddyn/integrators/free_flow_tags.hpp"
#include "rigiddyn/integrators/splitting_dlm.hpp"
#include "rigiddyn/overloaded.hpp"
#include "rigiddyn/models/euler_equations.hpp"
#include "rigiddyn/scene/elements/fictitious_forces.hpp"
#include "rigiddyn/scene/mass_flow.hpp"
#include "rigiddyn/scene/scene.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/so3/dexp_inv.hpp"
#include "rigiddyn/so3/exp_log.hpp"
#include "rigiddyn/so3/quaternion_kernels.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

namespace rigiddyn {

namespace detail {

// Where a body lives in y and ξ, and what Newton–Euler needs of it.
struct ParticleSlot {
  int body;          // index in the scene
  Eigen::Index y;    // offset in y
  Eigen::Index xi;   // offset in ξ
  double mass, inverse_mass;
};
struct PlanarSlot {
  int body;
  Eigen::Index y, xi;
  double mass, inverse_mass, inertia_zz, inverse_inertia_zz;
};
template <class Euler>
struct RigidSlot {
  int body;
  Eigen::Index y, xi;
  double mass, inverse_mass;
  Euler euler;
  FreeRotationFlow flow;  // the exact Euler–Poinsot flow of this body's inertia (free_flow<ExactRotation>)
};

// Newton–Euler of a particle: m a_W = f_W (its torque is ignored: a point takes none).
RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d particle_newton_euler(const ParticleSlot& b, const BodyWrench& w) {
  return Eigen::Vector3d(b.inverse_mass * w.f_W[0], b.inverse_mass * w.f_W[1], b.inverse_mass * w.f_W[2]);
}

// Newton–Euler of a planar body (Craig, "Rigid Body Dynamics" slides, plane kinetics): m a = f_xy,
// I_zz α = τ_z; returns (a_x, a_y, α). f_z and τ_x, τ_y are taken by the plane (the constraint reaction).
RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d planar_newton_euler(const PlanarSlot& b, const BodyWrench& w) {
  return Eigen::Vector3d(b.inverse_mass * w.f_W[0], b.inverse_mass * w.f_W[1], b.inverse_inertia_zz * w.tau_B[2]);
}

// Newton–Euler of a spatial rigid body about its centre of mass: m a_W = f_W, and Euler's equations
// I α_B + ω_B × I ω_B = τ_B in the body's form (models/euler_equations.hpp, their one home).
template <class Euler>
RIGIDDYN_ALWAYS_INLINE void rigid_newton_euler(const RigidSlot<Euler>& b, const Eigen::Vector3d& w_B, const BodyWrench& w,
                                               Eigen::Vector3d& a_W, Eigen::Vector3d& alpha_B) {
  a_W = Eigen::Vector3d(b.inverse_mass * w.f_W[0], b.inverse_mass * w.f_W[1], b.inverse_mass * w.f_W[2]);
  alpha_B = b.euler.angular_acceleration(w_B, w.tau_B);
}

// A rigid body pinned at O (models/pivoted_body.hpp): Euler's equations about O through euler_O, the Euler
// form of I_O; flow_O the exact free rotation about O (free_flow<ExactRotation>).
template <class Euler>
struct PivotedSlot {
  int body;
  Eigen::Index y, xi;
  double mass;
  Eigen::Vector3d c_B, p_WO;  // p_OC_B [m] in B, O [m] in W
  Euler euler_O;
  FreeRotationFlow flow_O;
};
// A planar body pinned at O (models/pivoted_planar_body.hpp).
struct PivotedPlanarSlot {
  int body;
  Eigen::Index y, xi;
  double mass, inertia_O_zz;
  Eigen::Vector2d c_B, p_WO;  // p_OC_B [m] in B's xy plane, O [m] in W's xy plane
};

// What a body with a MassFlow adds (scene/mass_flow.hpp): its mass coordinate m_y in y (m_xi in ξ: ṁ), the
// flow, its initial mass m0 [kg] and the names of messages.
struct MassCoordinate {
  Eigen::Index m_y, m_xi;
  MassFlow flow;
  double m0;
  std::string flow_name, body_name;  // "mass_flows[i]", the body's name
  Eigen::Index energy;               // its mass-flow energy's rank among the bodies with a MassFlow
};
// A particle with a MassFlow: y (p_W 3, v_W 3, m), ξ (v_W 3, a_W 3, ṁ).
struct MassParticleSlot {
  int body;
  Eigen::Index y, xi;
  MassCoordinate mass;
};
// A rigid body with a MassFlow under InertiaRule::scaled: Euler's equations of I_C0 (its form Euler) with the
// torque scaled by m0/m (mass_flow.hpp); y (p_W 3, q_WB 4, v_W 3, w_B 3, m), ξ (v_W, w_B, a_W, alpha_B, ṁ).
template <class Euler>
struct MassRigidSlot {
  int body;
  Eigen::Index y, xi;
  MassCoordinate mass;
  Euler euler;             // of I_C0
  FreeRotationFlow flow;   // the exact free rotation of I_C0 (that of I_C0 m/m0 too)
};
// The same under InertiaRule::function: I_C(m) from the user's function at each evaluation, Euler's
// equations in full form (a general 3×3 solve). The splitting methods are refused (compile).
struct FunctionRigidSlot {
  int body;
  Eigen::Index y, xi;
  MassCoordinate mass;
  Eigen::Matrix3d inertia_com0;  // I_C0 [kg m²] in B
};

// The Euler form and the torque scale of a variable-mass rigid body at the mass m [kg]
template <class Euler>
RIGIDDYN_ALWAYS_INLINE const Euler& euler_at(const MassRigidSlot<Euler>& s, double /*m*/) { return s.euler; }
template <class Euler>
RIGIDDYN_ALWAYS_INLINE double torque_scale_at(const MassRigidSlot<Euler>& s, double m) { return torque_scale(s.mass.m0, m); }
inline FullEuler euler_at(const FunctionRigidSlot& s, double m) {
  return FullEuler(inertia_at_mass(s.mass.flow, s.inertia_com0, s.mass.m0, m, s.mass.flow_name));
}
inline double torque_scale_at(const FunctionRigidSlot& /*s*/, double /*m*/) { return 1.0; }

RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d three_at(const Eigen::VectorXd& x, Eigen::Index i) {
  return Eigen::Vector3d(x[i], x[i + 1], x[i + 2]);
}

// 1/j! for j = 0 … 22
struct InverseFactorials {
  double value[23];
  constexpr InverseFactorials() : value() {
    double factorial = 1.0;
    for (int j = 0; j < 23; ++j) factorial *= (j == 0 ? 1.0 : j), value[j] = 1.0 / factorial;
  }
};
inline constexpr InverseFactorials inverse_factorials{};

// Σ_{n=0}^{8} (−x)^n / (2n + k)! (Horner): the Taylor series of the turn coefficients below at x = θ² < 1 (the first
// term left out, x⁹/(18 + k)!, is below 1e-18 of the first, 1/k!, for k = 2, 3, 4)
inline double alternating_factorial_series(double x, int k) {
  double sum = inverse_factorials.value[16 + k];
  for (int n = 7; n >= 0; --n) sum = inverse_factorials.value[2 * n + k] - x * sum;
  return sum;
}

// c2 = (1 − cos θ)/θ², c3 = (θ − sin θ)/θ³, c4 = (θ²/2 − 1 + cos θ)/θ⁴ (their series below θ = 1, where the
// closed forms cancel; above, the closed forms lose at most one digit)
struct TurnCoefficients {
  double c2, c3, c4;
};
inline TurnCoefficients turn_coefficients(double theta) {
  const double x = theta * theta;
  if (x < 1.0) return {alternating_factorial_series(x, 2), alternating_factorial_series(x, 3), alternating_factorial_series(x, 4)};
  const double half_sin = std::sin(0.5 * theta), one_minus_cos = 2.0 * half_sin * half_sin;
  return {one_minus_cos / x, (theta - std::sin(theta)) / (x * theta), (0.5 * x - one_minus_cos) / (x * x)};
}

// The exact flow over h [s] of a velocity u ∈ R³ under u̇ = a0 + M (u − u0): a0 the acceleration at the start,
// M u a part linear in u with M³ = −λ² M (M similar to a skew matrix of norm λ [1/s]: a Coriolis term), so that
// e^{sM} = 1 + sin(λs)/λ M + (1 − cos λs)/λ² M² and u(s) = u0 + ∫_0^s e^{rM} dr a0. With θ = λ h and the
// start increment h_a0 = h a0 (of the explicit kick):
//   Δu = u(h) − u0 = (1 + h c2 M + h² c3 M²) h_a0,    ∫_0^h u ds / h − u0 = (½ + h c3 M + h² c4 M²) h_a0,
// the second the mean velocity over the kick (the loads' work is f·∫u ds). c = turn_coefficients(λ h), apply_M(x) = M x.
template <class ApplyM>
void exact_linear_kick(const Eigen::Vector3d& h_a0, double h, const TurnCoefficients& c, const ApplyM& apply_M,
                       Eigen::Vector3d& du, Eigen::Vector3d& mean) {
  const Eigen::Vector3d M_a = apply_M(h_a0), MM_a = apply_M(M_a);
  du = h_a0 + (h * c.c2) * M_a + (h * h * c.c3) * MM_a;
  mean = 0.5 * h_a0 + (h * c.c3) * M_a + (h * h * c.c4) * MM_a;
}

// What the exact Coriolis kick of a body with an attitude needs: its inertia I [kg m²] in B (I_C; I_O for a
// pivoted body; I_C0 for a variable-mass body under the scaled rule), I⁻¹, det I and tr I.
struct CoriolisInertia {
  Eigen::Matrix3d inertia, inverse;
  double det = 0.0, trace = 0.0;
};
inline CoriolisInertia coriolis_inertia(const Eigen::Matrix3d& inertia) {
  return {inertia, inertia.inverse(), inertia.determinant(), inertia.trace()};
}

// The Coriolis torque of fictitious_forces.hpp, −(ω × I Ω_B + Ω_B × I ω − I (ω × Ω_B)), is s × ω with
// s = (2 I − tr I) Ω_B (the identity [Ω]× I + I [Ω]× = [(tr I − I) Ω]× for a symmetric I); about a pivot O it is
// the same with I_O (the moment about O of the Coriolis forces on the mass elements, that the model reduces as
// the torque about C plus c × f). The kick's rotation part is then I ω̇ = τ + s × ω: M = I⁻¹ [s]×, similar to
// the skew matrix of k = I^{1/2} s / √det I, so λ² = |k|² = s·I s / det I. Sets s and returns λ [1/s].
inline double coriolis_torque_axis(const CoriolisInertia& b, const Eigen::Vector3d& w_frame_B, Eigen::Vector3d& s) {
  s = 2.0 * (b.inertia * w_frame_B) - b.trace * w_frame_B;
  return std::sqrt(std::max(0.0, s.dot(b.inertia * s) / b.det));
}

// Whether a term is piecewise constant in time (it has set_time(t)).
template <class Term, class = void>
struct has_set_time : std::false_type {};
template <class Term>
struct has_set_time<Term, std::void_t<decltype(std::declval<Term&>().set_time(0.0))>> : std::true_type {};

}  // namespace detail

// The model of a scene whose elements compile to the terms UniformGravityTerm … FunctionForceTerm and
// the user's Extra terms (CustomForceTerm<F>, scene/custom_force.hpp). SceneModel = BasicSceneModel<>.
template <class... Extra>
class BasicSceneModel {
 public:
  using Coordinates = Eigen::VectorXd;
  using Tangent = Eigen::VectorXd;
  using Term = typename TermsOf<Element, FrameOriginTerm, EulerForceTerm, CentrifugalTerm, CoriolisTerm, Extra...>::type;

  // The bodies (checked when they were built) and the compiled terms, in the scene's order.
  BasicSceneModel(const std::vector<Body>& bodies, std::vector<Term> terms)
      : BasicSceneModel(bodies, std::move(terms), {}, {}) {}

  // The same with the bodies' mass flows (empty, or one per body: nullopt for a constant mass; a flow on a
  // particle or a rigid body only, checked by compile) and their names (for the out-of-mass message).
  BasicSceneModel(const std::vector<Body>& bodies, std::vector<Term> terms,
                  const std::vector<std::optional<MassFlow>>& mass_flows, const std::vector<std::string>& body_names)
      : terms_(std::move(terms)) {
    Eigen::Index y = 0, xi = 0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const int b = static_cast<int>(i);
      if (i < mass_flows.size() && mass_flows[i]) {
        add_mass_slot(bodies[i], b, *mass_flows[i], i < body_names.size() ? body_names[i] : "body" + std::to_string(i), y, xi);
        continue;
      }
      // one lambda per body kind: a kind added to Body and not handled here does not compile
      std::visit(overloaded{
                     [&](const Particle& p) {
                       particles_.push_back({b, y, xi, p.mass(), 1.0 / p.mass()});
                       y += 6, xi += 6;
                     },
                     [&](const PlanarBody& s) {
                       planars_.push_back({b, y, xi, s.mass(), 1.0 / s.mass(), s.inertia_zz(), 1.0 / s.inertia_zz()});
                       y += 6, xi += 6;
                     },
                     [&](const RigidBody& r) {
                       with_euler_form(r, [&](const auto& euler) {
                         using Euler = std::decay_t<decltype(euler)>;
                         std::get<std::vector<detail::RigidSlot<Euler>>>(rigid_).push_back(
                             {b, y, xi, r.mass(), 1.0 / r.mass(), euler, FreeRotationFlow(r.inertia_com())});
                       });
                       y += 13, xi += 12;
                     },
                     [&](const PivotedBody& o) {
                       with_euler_form(o, [&](const auto& euler_O) {
                         using Euler = std::decay_t<decltype(euler_O)>;
                         std::get<std::vector<detail::PivotedSlot<Euler>>>(pivoted_).push_back(
                             {b, y, xi, o.mass(), o.p_OC_B(), o.p_WO(), euler_O, FreeRotationFlow(o.inertia_O())});
                       });
                       y += 7, xi += 6;
                     },
                     [&](const PivotedPlanarBody& pendulum) {
                       pivoted_planars_.push_back(
                           {b, y, xi, pendulum.mass(), pendulum.inertia_O_zz(), pendulum.p_OC_B(), pendulum.p_WO()});
                       y += 2, xi += 2;
                     }},
                 bodies[i]);
    }
    t_y_ = y, t_xi_ = xi;
    kinematics_.resize(bodies.size());
    wrenches_.resize(bodies.size());
    power_.resize(terms_.size());
    element_wrenches_.assign(terms_.size(), std::vector<BodyWrench>(bodies.size()));
    has_pivoted_ = std::apply([](const auto&... group) { return (!group.empty() || ...); }, pivoted_);
    has_mass_rigid_ = std::apply([](const auto&... group) { return (!group.empty() || ...); }, mass_rigid_);
    q_y_.assign(bodies.size(), -1);
    for_each_rigid([&](const auto& s) { q_y_[s.body] = s.y + 3; });
    for_each_pivoted([&](const auto& s) { q_y_[s.body] = s.y; });
    for_each_mass_rigid([&](const auto& s) { q_y_[s.body] = s.y + 3; });
    for (std::size_t b = 0; b < bodies.size(); ++b) kinematics_[b].m = mass_of(bodies[b]);  // constant masses: set once
    reaction_W_.assign(bodies.size(), Eigen::Vector3d::Zero());
    momentum_O_W_.assign(bodies.size(), Eigen::Vector3d::Zero());
    find_coriolis_terms(bodies);
    stage_.resize(coordinate_count());
  }

  Eigen::Index coordinate_count() const { return t_y_ + 1 + extra_count(); }
  Eigen::Index tangent_count() const { return t_xi_ + 1 + extra_count(); }
  Eigen::Index time_index() const { return t_y_; }  // where t [s] is in y
  Eigen::Index work_index(std::size_t element) const { return t_y_ + 1 + static_cast<Eigen::Index>(element); }
  // True when a body's mass changes (a MassFlow): then the model has a mass part (mass_part) for the splittings'
  // three-part form (integrators/yoshida4.hpp)
  bool has_mass_flow() const { return !energy_body_.empty(); }
  std::size_t body_count() const { return kinematics_.size(); }
  std::size_t element_count() const { return terms_.size(); }
  const std::vector<Term>& terms() const { return terms_; }

  // Sets every piecewise-constant element (a term with set_time: ScheduledLoads, ReactionWheel) to its piece
  // at time t [s]: called by the run loop at t0 and at each switch time, never per evaluation.
  void set_time(double t) {
    step_start_ = t;
    for (Term& term : terms_) {
      std::visit(
          [t](auto& e) {
            if constexpr (detail::has_set_time<std::decay_t<decltype(e)>>::value) e.set_time(t);
          },
          term);
    }
  }

  // ẏ: (v, a) per body, q̇ = ½ q ⊗ (ω_B, 0) for attitudes, dt/dt = 1, dW_e/dt = P_e, dE_b/dt = the mass-flow
  // power of body b.
  void rate(const Coordinates& y, Coordinates& dy) const {
    evaluate(y);
    for (const auto& s : particles_) {
      const Eigen::Vector3d a = detail::particle_newton_euler(s, wrenches_[s.body]);
      for (int i = 0; i < 3; ++i) dy[s.y + i] = y[s.y + 3 + i], dy[s.y + 3 + i] = a[i];
    }
    for (const auto& s : planars_) {
      const Eigen::Vector3d a = detail::planar_newton_euler(s, wrenches_[s.body]);
      for (int i = 0; i < 3; ++i) dy[s.y + i] = y[s.y + 3 + i], dy[s.y + 3 + i] = a[i];
    }
    for_each_rigid([&](const auto& s) {
      const Eigen::Vector3d w = detail::three_at(y, s.y + 10);
      Eigen::Vector3d a, alpha;
      detail::rigid_newton_euler(s, w, wrenches_[s.body], a, alpha);
      for (int i = 0; i < 3; ++i) dy[s.y + i] = y[s.y + 7 + i], dy[s.y + 7 + i] = a[i], dy[s.y + 10 + i] = alpha[i];
      quat_rate_body(y.data() + s.y + 3, w, dy.data() + s.y + 3);  // q̇ = ½ q ⊗ (ω_B, 0)
    });
    for_each_pivoted([&](const auto& s) {
      const BodyKinematics& k = kinematics_[s.body];
      const Eigen::Vector3d alpha = pivoted_angular_acceleration(s.euler_O, s.c_B, k.q_WB, k.w_B, wrenches_[s.body]);
      quat_rate_body(y.data() + s.y, k.w_B, dy.data() + s.y);  // q̇ = ½ q ⊗ (ω_B, 0)
      for (int i = 0; i < 3; ++i) dy[s.y + 4 + i] = alpha[i];
    });
    for (const auto& s : pivoted_planars_) dy[s.y] = y[s.y + 1], dy[s.y + 1] = pivoted_planar_alpha(s, y);
    for (const auto& s : mass_particles_) {
      const Eigen::Vector3d a = wrenches_[s.body].f_W / kinematics_[s.body].m;  // m v̇ = f (thrust included)
      for (int i = 0; i < 3; ++i) dy[s.y + i] = y[s.y + 3 + i], dy[s.y + 3 + i] = a[i];
      dy[s.mass.m_y] = mass_rate_at(s.mass, y);
      dy[energy_y(s.mass)] = mass_flow_power(s, y, dy[s.mass.m_y]);
    }
    for_each_mass_rigid([&](const auto& s) {
      const Eigen::Vector3d w = detail::three_at(y, s.y + 10);
      Eigen::Vector3d a, alpha;
      mass_rigid_newton_euler(s, w, a, alpha);
      for (int i = 0; i < 3; ++i) dy[s.y + i] = y[s.y + 7 + i], dy[s.y + 7 + i] = a[i], dy[s.y + 10 + i] = alpha[i];
      quat_rate_body(y.data() + s.y + 3, w, dy.data() + s.y + 3);
      dy[s.mass.m_y] = mass_rate_at(s.mass, y);
      dy[energy_y(s.mass)] = mass_flow_power(s, y, dy[s.mass.m_y]);
    });
    dy[t_y_] = 1.0;
    for (std::size_t e = 0; e < terms_.size(); ++e) dy[t_y_ + 1 + e] = power_[e];
  }

  // every attitude q ← q / |q|
  void project(Coordinates& y) const {
    for_each_rigid([&](const auto& s) { normalise_quaternion(y.data() + s.y + 3); });
    for_each_pivoted([&](const auto& s) { normalise_quaternion(y.data() + s.y); });
    for_each_mass_rigid([&](const auto& s) { normalise_quaternion(y.data() + s.y + 3); });
    step_start_ = y[t_y_];  // the methods that end with project: the next step starts here
  }

  // ξ = (velocities, accelerations per body; 1; element powers; mass-flow powers)
  void velocity(const Coordinates& y, Tangent& xi) const {
    evaluate(y);
    for (const auto& s : particles_) {
      const Eigen::Vector3d a = detail::particle_newton_euler(s, wrenches_[s.body]);
      for (int i = 0; i < 3; ++i) xi[s.xi + i] = y[s.y + 3 + i], xi[s.xi + 3 + i] = a[i];
    }
    for (const auto& s : planars_) {
      const Eigen::Vector3d a = detail::planar_newton_euler(s, wrenches_[s.body]);
      for (int i = 0; i < 3; ++i) xi[s.xi + i] = y[s.y + 3 + i], xi[s.xi + 3 + i] = a[i];
    }
    for_each_rigid([&](const auto& s) {
      const Eigen::Vector3d w = detail::three_at(y, s.y + 10);
      Eigen::Vector3d a, alpha;
      detail::rigid_newton_euler(s, w, wrenches_[s.body], a, alpha);
      for (int i = 0; i < 3; ++i) {
        xi[s.xi + i] = y[s.y + 7 + i], xi[s.xi + 3 + i] = w[i], xi[s.xi + 6 + i] = a[i], xi[s.xi + 9 + i] = alpha[i];
      }
    });
    for_each_pivoted([&](const auto& s) {
      const BodyKinematics& k = kinematics_[s.body];
      const Eigen::Vector3d alpha = pivoted_angular_acceleration(s.euler_O, s.c_B, k.q_WB, k.w_B, wrenches_[s.body]);
      for (int i = 0; i < 3; ++i) xi[s.xi + i] = k.w_B[i], xi[s.xi + 3 + i] = alpha[i];
    });
    for (const auto& s : pivoted_planars_) xi[s.xi] = y[s.y + 1], xi[s.xi + 1] = pivoted_planar_alpha(s, y);
    for (const auto& s : mass_particles_) {
      const Eigen::Vector3d a = wrenches_[s.body].f_W / kinematics_[s.body].m;
      for (int i = 0; i < 3; ++i) xi[s.xi + i] = y[s.y + 3 + i], xi[s.xi + 3 + i] = a[i];
      xi[s.mass.m_xi] = mass_rate_at(s.mass, y);
      xi[energy_xi(s.mass)] = mass_flow_power(s, y, xi[s.mass.m_xi]);
    }
    for_each_mass_rigid([&](const auto& s) {
      const Eigen::Vector3d w = detail::three_at(y, s.y + 10);
      Eigen::Vector3d a, alpha;
      mass_rigid_newton_euler(s, w, a, alpha);
      for (int i = 0; i < 3; ++i) {
        xi[s.xi + i] = y[s.y + 7 + i], xi[s.xi + 3 + i] = w[i], xi[s.xi + 6 + i] = a[i], xi[s.xi + 9 + i] = alpha[i];
      }
      xi[s.mass.m_xi] = mass_rate_at(s.mass, y);
      xi[energy_xi(s.mass)] = mass_flow_power(s, y, xi[s.mass.m_xi]);
    });
    xi[t_xi_] = 1.0;
    for (std::size_t e = 0; e < terms_.size(); ++e) xi[t_xi_ + 1 + e] = power_[e];
  }

  // y ⊕ Θ: vector parts added, q ← q ⊗ exp(Θ_rot) for each rigid body
  void retract(const Coordinates& y, const Tangent& theta, Coordinates& out) const {
    for (const auto& s : particles_) for (int i = 0; i < 6; ++i) out[s.y + i] = y[s.y + i] + theta[s.xi + i];
    for (const auto& s : planars_) for (int i = 0; i < 6; ++i) out[s.y + i] = y[s.y + i] + theta[s.xi + i];
    for_each_rigid([&](const auto& s) {
      for (int i = 0; i < 3; ++i) out[s.y + i] = y[s.y + i] + theta[s.xi + i];
      times_exp(y.data() + s.y + 3, detail::three_at(theta, s.xi + 3), out.data() + s.y + 3);
      for (int i = 0; i < 6; ++i) out[s.y + 7 + i] = y[s.y + 7 + i] + theta[s.xi + 6 + i];
    });
    for_each_pivoted([&](const auto& s) {
      times_exp(y.data() + s.y, detail::three_at(theta, s.xi), out.data() + s.y);
      for (int i = 0; i < 3; ++i) out[s.y + 4 + i] = y[s.y + 4 + i] + theta[s.xi + 3 + i];
    });
    for (const auto& s : pivoted_planars_) for (int i = 0; i < 2; ++i) out[s.y + i] = y[s.y + i] + theta[s.xi + i];
    for (const auto& s : mass_particles_) for (int i = 0; i < 7; ++i) out[s.y + i] = y[s.y + i] + theta[s.xi + i];
    for_each_mass_rigid([&](const auto& s) {
      for (int i = 0; i < 3; ++i) out[s.y + i] = y[s.y + i] + theta[s.xi + i];
      times_exp(y.data() + s.y + 3, detail::three_at(theta, s.xi + 3), out.data() + s.y + 3);
      for (int i = 0; i < 7; ++i) out[s.y + 7 + i] = y[s.y + 7 + i] + theta[s.xi + 6 + i];  // v, ω, m
    });
    for (Eigen::Index i = 0; i <= extra_count(); ++i) out[t_y_ + i] = y[t_y_ + i] + theta[t_xi_ + i];
  }

  // ξ(y ⊕ Θ) (elements may read any attitude: the stage attitude is always built)
  void velocity_at(const Coordinates& y, const Tangent& theta, Tangent& xi) const {
    retract(y, theta, stage_);
    velocity(stage_, xi);
  }

  // ω ← dexp⁻¹_{−Θ} ω for each attitude part (so3/dexp_inv.hpp), identity elsewhere
  void dexp_inv(const Tangent& theta, Tangent& xi) const {
    const auto attitude = [&](Eigen::Index at) { dexp_inv_body(theta.data() + at, xi.data() + at); };
    for_each_rigid([&](const auto& s) { attitude(s.xi + 3); });
    for_each_pivoted([&](const auto& s) { attitude(s.xi); });
    for_each_mass_rigid([&](const auto& s) { attitude(s.xi + 3); });
  }

  // velocities += h × accelerations at y (the explicit gyroscopic term); positions, work, t unchanged
  void kick(Coordinates& y, double h) const { kick_with(y, h, [](const auto& euler, const auto& w, const auto& tau, double k) {
    return euler.explicit_gyroscopic_kick(w, tau, k);
  }); }
  // the same with the implicit gyroscopic term (one Newton step, euler_equations.hpp)
  void kick_implicit_gyroscopic(Coordinates& y, double h) const {
    kick_with(y, h, [](const auto& euler, const auto& w, const auto& tau, double k) { return euler.implicit_gyroscopic_kick(w, tau, k); });
  }

  // work_e += h P_e at y; then p += h v, q ← q ⊗ exp(h ω_B) (exact for constant ω), θ += h ω, m += h ṁ (and
  // E_b with it: advance_masses), t += h
  void drift(Coordinates& y, double h) const {
    evaluate(y);
    for (std::size_t e = 0; e < terms_.size(); ++e) y[t_y_ + 1 + e] += h * power_[e];
    translate(y, h);
    for (const auto& s : planars_) y[s.y + 2] += h * y[s.y + 5];
    for_each_rigid([&](const auto& s) {
      const double q[4] = {y[s.y + 3], y[s.y + 4], y[s.y + 5], y[s.y + 6]};
      times_exp(q, Eigen::Vector3d(h * y[s.y + 10], h * y[s.y + 11], h * y[s.y + 12]), y.data() + s.y + 3);
    });
    for_each_pivoted([&](const auto& s) {
      const double q[4] = {y[s.y], y[s.y + 1], y[s.y + 2], y[s.y + 3]};
      times_exp(q, Eigen::Vector3d(h * y[s.y + 4], h * y[s.y + 5], h * y[s.y + 6]), y.data() + s.y);
    });
    for (const auto& s : pivoted_planars_) y[s.y] += h * y[s.y + 1];
    for_each_mass_rigid([&](const auto& s) {
      const double q[4] = {y[s.y + 3], y[s.y + 4], y[s.y + 5], y[s.y + 6]};
      times_exp(q, Eigen::Vector3d(h * y[s.y + 10], h * y[s.y + 11], h * y[s.y + 12]), y.data() + s.y + 3);
    });
    advance_masses(y, h);
    project(y);
    y[t_y_] += h;
    step_start_ = y[t_y_];
  }

  // The exact flow of the loads part over h [s] (model_interface.hpp): the wrenches at y (positions,
  // attitudes, velocities and t as they are), v += h f/m, ω += h I⁻¹ τ (no gyroscopic term) and each
  // element's work += h Σ_b (f_eb·v̄_b + τ_eb·ω̄_b) with the mean velocities v̄ = v + Δv/2 (exact: the
  // velocities are linear in time in this flow). In a turning frame (a CoriolisTerm) the Coriolis force and
  // torque are linear in the velocities, so each velocity follows u̇ = a0 + M (u − u0) (a0 at the start, M u
  // the Coriolis part: M v = −2 Ω × v for a centre of mass, M ω = I⁻¹ (s × ω) for an attitude): its exact
  // flow is taken (detail::exact_linear_kick), so the kick stays a flow and the kick–free–kick compositions
  // keep their orders; v̄ is then the mean velocity of that flow, and the Coriolis work over the kick is zero
  // (its power is zero at every instant). Returns Σ |Δω_B| over the rigid bodies [rad/s].
  double loads_kick(Coordinates& y, double h) const {
    return coriolis_terms_.empty() ? loads_kick_with<false>(y, h) : loads_kick_with<true>(y, h);
  }

  // The free part over h [s]: p += h v for every body, θ += h ω for a planar body, each rigid body's
  // attitude and ω_B by the flow Rotation (DlmRotation<normalise>: dlm_free_rotation; ExactRotation: the
  // body's own FreeRotationFlow), t += h; no work (no load acts in this part).
  template <class Rotation>
  void free_flow(Coordinates& y, double h) const {
    free_motion<Rotation>(y, h);
    advance_masses(y, h);
    y[t_y_] += h;
    step_start_ = y[t_y_];
  }

  // The free part at fixed masses (free_flow without advance_masses): p, attitudes and ω_B, t += h. With mass_part,
  // the three parts of the splittings' form that keeps the masses inside each step (integrators/yoshida4.hpp,
  // which ends its step with project).
  template <class Rotation>
  void free_flow_at_fixed_mass(Coordinates& y, double h) const {
    free_motion<Rotation>(y, h);
    y[t_y_] += h;
  }

  // The masses' part over h [s] at the time t of y, which it keeps: m += h ṁ(t) for each body with a MassFlow (the
  // exact flow of ṁ at a frozen t), E_b with it (advance_masses' exact change of T); positions, velocities,
  // attitudes and works unchanged. The out-of-mass error (mass_flow.hpp) when a mass is no longer positive, in
  // the step from the last project (or the run's start).
  void mass_part(Coordinates& y, double h) const {
    const double t = y[t_y_];
    const auto move = [&](const auto& s) {
      const double rate = has_constant_rate(s.mass.flow) ? s.mass.flow.rate : mass_rate(s.mass.flow, t, s.mass.flow_name);
      change_mass(s, y, h * rate, t, step_start_);
    };
    for (const auto& s : mass_particles_) move(s);
    for_each_mass_rigid(move);
  }

  // p += h v, θ += h ω, each rigid body's attitude and ω_B by the flow Rotation (free_flow); masses and t unchanged
  template <class Rotation>
  void free_motion(Coordinates& y, double h) const {
    translate(y, h);
    for (const auto& s : planars_) y[s.y + 2] += h * y[s.y + 5];
    for_each_rigid([&](const auto& s) {
      if constexpr (std::is_same_v<Rotation, ExactRotation>) {
        exact_free_rotation(s.flow, y.data() + s.y + 3, y.data() + s.y + 10, h);
      } else {
        free_dlm(Rotation{}, s.euler, y.data() + s.y + 3, y.data() + s.y + 10, h);
      }
    });
    for_each_pivoted([&](const auto& s) {  // the free rotation about O: I_O in place of I_C
      if constexpr (std::is_same_v<Rotation, ExactRotation>) {
        exact_free_rotation(s.flow_O, y.data() + s.y, y.data() + s.y + 4, h);
      } else {
        free_dlm(Rotation{}, s.euler_O, y.data() + s.y, y.data() + s.y + 4, h);
      }
    });
    for (const auto& s : pivoted_planars_) y[s.y] += h * y[s.y + 1];
    for_each_mass_rigid([&](const auto& s) { mass_free_rotation(Rotation{}, s, y, h); });
  }

  // Appends the record of y at time t [s] to `out` (scene_simulation.hpp): the bodies, energies,
  // momenta, each element's work and power, and (when a body has a MassFlow) each body's mass-flow energy.
  void record(const Coordinates& y, double t, SceneSimulation& out) const {
    evaluate(y);
    out.t.push_back(t);
    double T = 0.0, V = 0.0;
    Eigen::Vector3d L_W = Eigen::Vector3d::Zero(), H_W = Eigen::Vector3d::Zero();
    // m v, T = ½ m v·v and p × m v of the centre of mass (H_W about W's origin)
    const auto translational = [&](int body) {
      const BodyKinematics& k = kinematics_[body];
      T += 0.5 * k.m * k.v_W.squaredNorm();
      L_W += k.m * k.v_W;
      H_W += k.p_W.cross(k.m * k.v_W);
    };
    for (const auto& s : particles_) translational(s.body);
    for (const auto& s : planars_) {
      translational(s.body);
      const double w = kinematics_[s.body].w_B[2];
      T += 0.5 * s.inertia_zz * w * w;
      momentum_O_W_[s.body] = Eigen::Vector3d(0.0, 0.0, s.inertia_zz * w);  // R_WB = Rz(θ) leaves the z axis
      H_W += momentum_O_W_[s.body];
    }
    for_each_rigid([&](const auto& s) {
      translational(s.body);
      const BodyKinematics& k = kinematics_[s.body];
      const Eigen::Vector3d h_B = s.euler.momentum(k.w_B);
      T += 0.5 * k.w_B.dot(h_B);
      momentum_O_W_[s.body] = k.q_WB * h_B;
      H_W += momentum_O_W_[s.body];
    });
    // a pinned body: T = ½ ω·I_O ω, H_O = R I_O ω, H about W's origin = p_WO × m v_C + H_O (H_O sums
    // (r − O) × v dm), the reaction from Newton's law for the centre of mass (models/pivoted_body.hpp)
    for_each_pivoted([&](const auto& s) {
      const BodyKinematics& k = kinematics_[s.body];
      const Eigen::Vector3d h_B = s.euler_O.momentum(k.w_B);
      T += 0.5 * k.w_B.dot(h_B);
      L_W += k.m * k.v_W;
      momentum_O_W_[s.body] = k.q_WB * h_B;
      H_W += s.p_WO.cross(k.m * k.v_W) + momentum_O_W_[s.body];
      const Eigen::Vector3d alpha = pivoted_angular_acceleration(s.euler_O, s.c_B, k.q_WB, k.w_B, wrenches_[s.body]);
      reaction_W_[s.body] = pivot_reaction_W(k.m, s.c_B, k.q_WB, k.w_B, alpha, wrenches_[s.body].f_W);
    });
    for (const auto& s : mass_particles_) translational(s.body);
    for_each_mass_rigid([&](const auto& s) {  // I_C(m) ω = (I_C0 m/m0) ω under the scaled rule
      translational(s.body);
      const BodyKinematics& k = kinematics_[s.body];
      const Eigen::Vector3d h_B = euler_at(s, k.m).momentum(k.w_B) / torque_scale_at(s, k.m);
      T += 0.5 * k.w_B.dot(h_B);
      momentum_O_W_[s.body] = k.q_WB * h_B;
      H_W += momentum_O_W_[s.body];
    });
    for (const auto& s : pivoted_planars_) {
      const BodyKinematics& k = kinematics_[s.body];
      const double w = k.w_B[2];
      T += 0.5 * s.inertia_O_zz * w * w;
      L_W += k.m * k.v_W;
      momentum_O_W_[s.body] = Eigen::Vector3d(0.0, 0.0, s.inertia_O_zz * w);
      H_W += Eigen::Vector3d(s.p_WO.x(), s.p_WO.y(), 0.0).cross(k.m * k.v_W) + momentum_O_W_[s.body];
      const Eigen::Vector2d c_W = pivoted_planar_c_W(s.c_B, y[s.y]);
      reaction_W_[s.body] = pivoted_planar_reaction_W(k.m, c_W, w, pivoted_planar_alpha(s, y), wrenches_[s.body].f_W);
    }
    for (std::size_t b = 0; b < kinematics_.size(); ++b) {
      const BodyKinematics& k = kinematics_[b];
      out.p_W.insert(out.p_W.end(), k.p_W.data(), k.p_W.data() + 3);
      if (q_y_[b] >= 0) {
        out.q_WB.insert(out.q_WB.end(), y.data() + q_y_[b], y.data() + q_y_[b] + 4);  // as integrated
      } else {
        out.q_WB.insert(out.q_WB.end(), k.q_WB.coeffs().data(), k.q_WB.coeffs().data() + 4);
      }
      out.v_W.insert(out.v_W.end(), k.v_W.data(), k.v_W.data() + 3);
      out.w_B.insert(out.w_B.end(), k.w_B.data(), k.w_B.data() + 3);
      out.pivot_reaction_W.insert(out.pivot_reaction_W.end(), reaction_W_[b].data(), reaction_W_[b].data() + 3);
      out.angular_momentum_O_W.insert(out.angular_momentum_O_W.end(), momentum_O_W_[b].data(), momentum_O_W_[b].data() + 3);
      out.mass.push_back(k.m);
    }
    for (const Term& term : terms_) V += std::visit([&](const auto& e) { return e.potential(kinematics_); }, term);
    out.kinetic_energy.push_back(T);
    out.potential_energy.push_back(V);
    out.total_energy.push_back(T + V);
    out.linear_momentum_W.insert(out.linear_momentum_W.end(), L_W.data(), L_W.data() + 3);
    out.angular_momentum_W.insert(out.angular_momentum_W.end(), H_W.data(), H_W.data() + 3);
    for (std::size_t e = 0; e < terms_.size(); ++e) out.work.push_back(y[t_y_ + 1 + e]);
    out.power.insert(out.power.end(), power_.begin(), power_.end());
    if (has_mass_flow()) {
      const std::size_t first = out.mass_flow_energy.size();
      out.mass_flow_energy.resize(first + kinematics_.size(), 0.0);
      for (std::size_t k = 0; k < energy_body_.size(); ++k) out.mass_flow_energy[first + energy_body_[k]] = y[energy_y(k)];
    }
  }

  // y of the bodies' states (each of its body's kind, checked by the caller) at time t [s], works and mass-flow
  // energies 0
  Coordinates coordinates(const std::vector<BodyState>& states, double t) const {
    Coordinates y = Coordinates::Zero(coordinate_count());
    for (const auto& s : particles_) {
      const auto& x = std::get<ParticleState>(states[s.body]);
      for (int i = 0; i < 3; ++i) y[s.y + i] = x.p_W[i], y[s.y + 3 + i] = x.v_W[i];
    }
    for (const auto& s : planars_) {
      const auto& x = std::get<PlanarBodyState>(states[s.body]);
      y.segment<6>(s.y) << x.p_W, x.theta, x.v_W, x.omega;
    }
    for_each_rigid([&](const auto& s) {
      const auto& x = std::get<RigidBodyState>(states[s.body]);
      y.template segment<3>(s.y) = x.p_W;
      y.template segment<4>(s.y + 3) = x.q_WB.coeffs();
      y.template segment<3>(s.y + 7) = x.v_W;
      y.template segment<3>(s.y + 10) = x.w_B;
    });
    for_each_pivoted([&](const auto& s) {
      const auto& x = std::get<PivotedBodyState>(states[s.body]);
      y.template segment<4>(s.y) = x.q_WB.coeffs();
      y.template segment<3>(s.y + 4) = x.w_B;
    });
    for (const auto& s : pivoted_planars_) {
      const auto& x = std::get<PivotedPlanarBodyState>(states[s.body]);
      y[s.y] = x.theta, y[s.y + 1] = x.omega;
    }
    for (const auto& s : mass_particles_) {
      const auto& x = std::get<ParticleState>(states[s.body]);
      for (int i = 0; i < 3; ++i) y[s.y + i] = x.p_W[i], y[s.y + 3 + i] = x.v_W[i];
      y[s.mass.m_y] = s.mass.m0;
    }
    for_each_mass_rigid([&](const auto& s) {
      const auto& x = std::get<RigidBodyState>(states[s.body]);
      y.template segment<3>(s.y) = x.p_W;
      y.template segment<4>(s.y + 3) = x.q_WB.coeffs();
      y.template segment<3>(s.y + 7) = x.v_W;
      y.template segment<3>(s.y + 10) = x.w_B;
      y[s.mass.m_y] = s.mass.m0;
    });
    y[t_y_] = t;
    step_start_ = t;
    return y;
  }

  // The bodies' states in y (attitudes as integrated)
  std::vector<BodyState> states(const Coordinates& y) const {
    std::vector<BodyState> out(body_count());
    for (const auto& s : particles_) out[s.body] = ParticleState{y.segment<3>(s.y), y.segment<3>(s.y + 3)};
    for (const auto& s : planars_) {
      out[s.body] = PlanarBodyState{y.segment<2>(s.y), y[s.y + 2], y.segment<2>(s.y + 3), y[s.y + 5]};
    }
    for_each_rigid([&](const auto& s) {
      RigidBodyState x;
      x.p_W = y.template segment<3>(s.y);
      x.q_WB.coeffs() = y.template segment<4>(s.y + 3);
      x.v_W = y.template segment<3>(s.y + 7);
      x.w_B = y.template segment<3>(s.y + 10);
      out[s.body] = x;
    });
    for_each_pivoted([&](const auto& s) {
      PivotedBodyState x;
      x.q_WB.coeffs() = y.template segment<4>(s.y);
      x.w_B = y.template segment<3>(s.y + 4);
      out[s.body] = x;
    });
    for (const auto& s : pivoted_planars_) out[s.body] = PivotedPlanarBodyState{y[s.y], y[s.y + 1]};
    for (const auto& s : mass_particles_) out[s.body] = ParticleState{y.segment<3>(s.y), y.segment<3>(s.y + 3)};
    for_each_mass_rigid([&](const auto& s) {
      RigidBodyState x;
      x.p_W = y.template segment<3>(s.y);
      x.q_WB.coeffs() = y.template segment<4>(s.y + 3);
      x.v_W = y.template segment<3>(s.y + 7);
      x.w_B = y.template segment<3>(s.y + 10);
      out[s.body] = x;
    });
    return out;
  }

  // Each body's mass in y [kg] (its constant mass, or its mass coordinate)
  std::vector<double> masses(const Coordinates& y) const {
    std::vector<double> out(body_count());
    for (std::size_t b = 0; b < out.size(); ++b) out[b] = kinematics_[b].m;
    for (const auto& s : mass_particles_) out[s.body] = y[s.mass.m_y];
    for_each_mass_rigid([&](const auto& s) { out[s.body] = y[s.mass.m_y]; });
    return out;
  }

 private:
  template <class F>
  void for_each_rigid(F&& f) const {
    std::apply([&](const auto&... group) { (for_each_in(group, f), ...); }, rigid_);
  }
  // (one test when the scene has no pivoted body, rather than one per Euler form)
  template <class F>
  void for_each_pivoted(F&& f) const {
    if (has_pivoted_) std::apply([&](const auto&... group) { (for_each_in(group, f), ...); }, pivoted_);
  }
  template <class Group, class F>
  static void for_each_in(const Group& group, F& f) {
    for (const auto& s : group) f(s);
  }

  template <class F>
  void for_each_mass_rigid(F&& f) const {
    if (has_mass_rigid_) std::apply([&](const auto&... group) { (for_each_in(group, f), ...); }, mass_rigid_);
  }

  // loads_kick without (turning = false) or with the exact Coriolis kick
  template <bool turning>
  double loads_kick_with(Coordinates& y, double h) const {
    fill_kinematics(y);
    const double t = y[t_y_];
    for (std::size_t e = 0; e < terms_.size(); ++e) {
      std::vector<BodyWrench>& w = element_wrenches_[e];
      for (BodyWrench& b : w) b.f_W.setZero(), b.tau_B.setZero();
      std::visit([&](const auto& term) { term.add_wrenches(t, kinematics_, w); }, terms_[e]);
    }
    for (BodyWrench& b : wrenches_) b.f_W.setZero(), b.tau_B.setZero();
    for (const auto& w : element_wrenches_) {
      for (std::size_t b = 0; b < w.size(); ++b) wrenches_[b].f_W += w[b].f_W, wrenches_[b].tau_B += w[b].tau_B;
    }
    Eigen::Vector3d w_F = Eigen::Vector3d::Zero(), w_plane = Eigen::Vector3d::Zero();  // the frame's Ω [rad/s] in F
    detail::TurnCoefficients c_F{}, c_plane{};  // of λ = 2|Ω| and of λ = 2|Ω_z|
    if constexpr (turning) {
      w_F = coriolis_frame_rate(t), w_plane.z() = w_F.z();
      c_F = detail::turn_coefficients(2.0 * w_F.norm() * h), c_plane = detail::turn_coefficients(2.0 * std::abs(w_F.z()) * h);
    }
    // Δv and v̄ − v of a centre of mass from h a0 = h f/m: M v = −2 Ω × v (λ = 2|Ω|; Ω = (0, 0, Ω_z) in a
    // planar body's plane, the in-plane part of −2 Ω × v)
    const auto translation_kick = [&](const Eigen::Vector3d& w, const detail::TurnCoefficients& c,
                                      const Eigen::Vector3d& h_a0, Eigen::Vector3d& dv, Eigen::Vector3d& mean) {
      if constexpr (turning) {
        const auto coriolis = [&](const Eigen::Vector3d& v) { return Eigen::Vector3d(-2.0 * cross_3(w, v)); };
        detail::exact_linear_kick(h_a0, h, c, coriolis, dv, mean);
      } else {
        dv = h_a0, mean = 0.5 * h_a0;
      }
    };
    // Δω and ω̄ − ω of a body with a 3-D attitude from h a0 = h I⁻¹ τ: M ω = I⁻¹ (s × ω) (detail::coriolis_torque_axis)
    const auto rotation_kick = [&](int body, const Eigen::Vector3d& h_a0, Eigen::Vector3d& dw, Eigen::Vector3d& mean) {
      if constexpr (turning) {
        const detail::CoriolisInertia& inertia = coriolis_inertia_[body];
        Eigen::Vector3d axis;
        const double lambda = detail::coriolis_torque_axis(inertia, kinematics_[body].q_WB.conjugate() * w_F, axis);
        const auto coriolis = [&](const Eigen::Vector3d& w) { return Eigen::Vector3d(inertia.inverse * cross_3(axis, w)); };
        detail::exact_linear_kick(h_a0, h, detail::turn_coefficients(lambda * h), coriolis, dw, mean);
      } else {
        dw = h_a0, mean = 0.5 * h_a0;
      }
    };
    // the velocity increments; kinematics_ then holds the mean velocities
    double kicked = 0.0;
    Eigen::Vector3d dv, mean_v, dw, mean_w;
    for (const auto& s : particles_) {
      translation_kick(w_F, c_F, h * detail::particle_newton_euler(s, wrenches_[s.body]), dv, mean_v);
      kinematics_[s.body].v_W += mean_v;
      for (int i = 0; i < 3; ++i) y[s.y + 3 + i] += dv[i];
    }
    for (const auto& s : planars_) {  // (no Coriolis torque about z: ω ẑ and Ω_B give τ_z = 0)
      const Eigen::Vector3d d = h * detail::planar_newton_euler(s, wrenches_[s.body]);
      translation_kick(w_plane, c_plane, Eigen::Vector3d(d[0], d[1], 0.0), dv, mean_v);
      kinematics_[s.body].v_W += mean_v;
      kinematics_[s.body].w_B[2] += 0.5 * d[2];
      for (int i = 0; i < 2; ++i) y[s.y + 3 + i] += dv[i];
      y[s.y + 5] += d[2];
    }
    for_each_rigid([&](const auto& s) {
      Eigen::Vector3d a, alpha;
      detail::rigid_newton_euler(s, Eigen::Vector3d::Zero(), wrenches_[s.body], a, alpha);  // ω = 0: I⁻¹ τ alone
      translation_kick(w_F, c_F, h * a, dv, mean_v);
      rotation_kick(s.body, h * alpha, dw, mean_w);
      kinematics_[s.body].v_W += mean_v;
      kinematics_[s.body].w_B += mean_w;
      for (int i = 0; i < 3; ++i) y[s.y + 7 + i] += dv[i], y[s.y + 10 + i] += dw[i];
      kicked += dw.norm();
    });
    for_each_pivoted([&](const auto& s) {
      // ω += h I_O⁻¹ τ_O (ω = 0 in Euler's equations: the torque alone); the mean v̄ = R (ω̄ × c)
      BodyKinematics& k = kinematics_[s.body];
      rotation_kick(s.body, h * pivoted_angular_acceleration(s.euler_O, s.c_B, k.q_WB, Eigen::Vector3d::Zero(), wrenches_[s.body]),
                    dw, mean_w);
      k.w_B += mean_w;
      k.v_W = k.q_WB * cross_3(k.w_B, s.c_B);
      for (int i = 0; i < 3; ++i) y[s.y + 4 + i] += dw[i];
      kicked += dw.norm();
    });
    for (const auto& s : pivoted_planars_) {  // (no Coriolis torque about O: in the plane f ∥ c_W, and τ_z = 0)
      BodyKinematics& k = kinematics_[s.body];
      const Eigen::Vector2d c_W = pivoted_planar_c_W(s.c_B, y[s.y]);
      const double d = h * pivoted_planar_angular_acceleration(s.inertia_O_zz, c_W, wrenches_[s.body]);
      k.w_B[2] += 0.5 * d;
      k.v_W = Eigen::Vector3d(-k.w_B[2] * c_W.y(), k.w_B[2] * c_W.x(), 0.0);
      y[s.y + 1] += d;
    }
    for (const auto& s : mass_particles_) {  // the mass frozen at its value now
      translation_kick(w_F, c_F, (h / kinematics_[s.body].m) * wrenches_[s.body].f_W, dv, mean_v);
      kinematics_[s.body].v_W += mean_v;
      for (int i = 0; i < 3; ++i) y[s.y + 3 + i] += dv[i];
    }
    for_each_mass_rigid([&](const auto& s) {
      Eigen::Vector3d a, alpha;
      mass_rigid_newton_euler(s, Eigen::Vector3d::Zero(), a, alpha);  // ω = 0: the scaled torque alone
      translation_kick(w_F, c_F, h * a, dv, mean_v);
      if constexpr (std::is_same_v<std::decay_t<decltype(s)>, detail::FunctionRigidSlot>) {
        dw = h * alpha, mean_w = 0.5 * dw;  // (I(m) of a function: the splitting methods are refused for it)
      } else {
        rotation_kick(s.body, h * alpha, dw, mean_w);  // scaled: M = I_C0⁻¹ [s]× with s of I_C0 (both scale by m/m0)
      }
      kinematics_[s.body].v_W += mean_v;
      kinematics_[s.body].w_B += mean_w;
      for (int i = 0; i < 3; ++i) y[s.y + 7 + i] += dv[i], y[s.y + 10 + i] += dw[i];
      kicked += dw.norm();
    });
    for (std::size_t e = 0; e < terms_.size(); ++e) {
      if constexpr (turning) {
        if (std::holds_alternative<CoriolisTerm>(terms_[e])) continue;  // its work over the exact kick: 0
      }
      double work = 0.0;
      const std::vector<BodyWrench>& w = element_wrenches_[e];
      for (std::size_t b = 0; b < w.size(); ++b) work += w[b].f_W.dot(kinematics_[b].v_W) + w[b].tau_B.dot(kinematics_[b].w_B);
      y[t_y_ + 1 + e] += h * work;
    }
    return kicked;
  }

  // The Coriolis terms among terms_ (their frames' Ω when constant) and, when there is one, the inertia each body
  // with a 3-D attitude turns with in the exact Coriolis kick (loads_kick): I_C of a rigid body (I_C0 under a
  // MassFlow), I_O of a pivoted one
  void find_coriolis_terms(const std::vector<Body>& bodies) {
    for (std::size_t e = 0; e < terms_.size(); ++e) {
      if (const auto* term = std::get_if<CoriolisTerm>(&terms_[e])) {
        const bool constant = term->frame().constant_rotation;
        coriolis_terms_.push_back({e, constant, constant ? frame_terms(term->frame(), 0.0).w_F : Eigen::Vector3d::Zero()});
      }
    }
    if (coriolis_terms_.empty()) return;
    coriolis_inertia_.resize(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (const auto* r = std::get_if<RigidBody>(&bodies[b])) coriolis_inertia_[b] = detail::coriolis_inertia(r->inertia_com());
      if (const auto* o = std::get_if<PivotedBody>(&bodies[b])) coriolis_inertia_[b] = detail::coriolis_inertia(o->inertia_O());
    }
  }

  // Ω_F [rad/s] of the Coriolis terms at t [s] (their sum: compile adds one)
  Eigen::Vector3d coriolis_frame_rate(double t) const {
    Eigen::Vector3d w = Eigen::Vector3d::Zero();
    for (const CoriolisFrame& c : coriolis_terms_) {
      w += c.constant ? c.w_F : frame_terms(std::get<CoriolisTerm>(terms_[c.element]).frame(), t).w_F;
    }
    return w;
  }

  // The slot of a body with a MassFlow (a particle or a rigid body; compile refuses the other kinds)
  void add_mass_slot(const Body& body, int b, const MassFlow& flow, const std::string& body_name, Eigen::Index& y,
                     Eigen::Index& xi) {
    const std::string flow_name = "mass_flows[" + std::to_string(b) + "]";
    const auto energy = static_cast<Eigen::Index>(energy_body_.size());
    energy_body_.push_back(b);
    if (const auto* p = std::get_if<Particle>(&body)) {
      mass_particles_.push_back({b, y, xi, {y + 6, xi + 6, flow, p->mass(), flow_name, body_name, energy}});
      y += 7, xi += 7;
      return;
    }
    const RigidBody& r = std::get<RigidBody>(body);
    const detail::MassCoordinate mass{y + 13, xi + 12, flow, r.mass(), flow_name, body_name, energy};
    if (flow.inertia_rule == InertiaRule::function) {
      std::get<std::vector<detail::FunctionRigidSlot>>(mass_rigid_).push_back({b, y, xi, mass, r.inertia_com()});
    } else {
      with_euler_form(r, [&](const auto& euler) {
        using Euler = std::decay_t<decltype(euler)>;
        std::get<std::vector<detail::MassRigidSlot<Euler>>>(mass_rigid_).push_back(
            {b, y, xi, mass, euler, FreeRotationFlow(r.inertia_com())});
      });
    }
    y += 14, xi += 13;
  }

  // m of a body with a MassFlow in y, when positive; else the out-of-mass error (mass_flow.hpp) at t of y,
  // in the step from step_start_
  double checked_mass(const detail::MassCoordinate& c, const Coordinates& y) const {
    const double m = y[c.m_y];
    if (!(m > 0.0)) throw_out_of_mass(c.flow_name, c.body_name, m, y[t_y_], step_start_);
    return m;
  }
  // ṁ [kg/s] at t of y
  double mass_rate_at(const detail::MassCoordinate& c, const Coordinates& y) const {
    return mass_rate(c.flow, y[t_y_], c.flow_name);
  }

  // The masses over the free part of a splitting (t → t + h, t of y): m += h ṁ, exact for a constant rate,
  // the midpoint rule h ṁ(t + h/2) for a rate of t (second order, as the compositions), E_b with them
  // (change_mass); the out-of-mass error when a mass is no longer positive
  void advance_masses(Coordinates& y, double h) const {
    const double t = y[t_y_];
    const auto advance = [&](const auto& s) {
      const MassFlow& flow = s.mass.flow;
      const double rate = has_constant_rate(flow) ? flow.rate : mass_rate(flow, t + 0.5 * h, s.mass.flow_name);
      change_mass(s, y, h * rate, t + h, t);
    };
    for (const auto& s : mass_particles_) advance(s);
    for_each_mass_rigid(advance);
  }

  // m += dm for the body of slot s at fixed velocities, and E_b += the exact change of T that makes (the model's
  // top: ½ dm |v|² + ½ ω·(I(m + dm) − I(m)) ω); the out-of-mass error (at t, in the step from step_start) when
  // the new mass is not positive
  template <class Slot>
  void change_mass(const Slot& s, Coordinates& y, double dm, double t, double step_start) const {
    const detail::MassCoordinate& c = s.mass;
    const double m = y[c.m_y], m_new = m + dm;
    if (!(m_new > 0.0)) throw_out_of_mass(c.flow_name, c.body_name, m_new, t, step_start);
    y[energy_y(c)] += kinetic_energy_change(s, y, m, m_new);
    y[c.m_y] = m_new;
  }

  // The change of T [J] when the mass goes from m to m_new [kg] at the velocities of y: ½ (m_new − m) |v|², and for
  // a rigid body ½ ω·(I(m_new) − I(m)) ω (scaled: ½ ((m_new − m)/m0) ω·I_C0 ω)
  double kinetic_energy_change(const detail::MassParticleSlot& s, const Coordinates& y, double m, double m_new) const {
    return 0.5 * (m_new - m) * detail::three_at(y, s.y + 3).squaredNorm();
  }
  template <class Euler>
  double kinetic_energy_change(const detail::MassRigidSlot<Euler>& s, const Coordinates& y, double m, double m_new) const {
    const Eigen::Vector3d w = detail::three_at(y, s.y + 10);
    return 0.5 * (m_new - m) * (detail::three_at(y, s.y + 7).squaredNorm() + w.dot(s.euler.momentum(w)) / s.mass.m0);
  }
  double kinetic_energy_change(const detail::FunctionRigidSlot& s, const Coordinates& y, double m, double m_new) const {
    const Eigen::Vector3d w = detail::three_at(y, s.y + 10);
    const Eigen::Matrix3d dI = inertia_at_mass(s.mass.flow, s.inertia_com0, s.mass.m0, m_new, s.mass.flow_name) -
                               inertia_at_mass(s.mass.flow, s.inertia_com0, s.mass.m0, m, s.mass.flow_name);
    return 0.5 * (m_new - m) * detail::three_at(y, s.y + 7).squaredNorm() + 0.5 * w.dot(dI * w);
  }

  // The mass-flow power [W] of a body at y with the mass rate ṁ [kg/s] (the model's top): ½ ṁ |v|², and for a rigid
  // body ½ ṁ ω·(dI/dm) ω (inertia_mass_derivative: I_C0/m0 under the scaled rule)
  double mass_flow_power(const detail::MassParticleSlot& s, const Coordinates& y, double rate) const {
    return 0.5 * rate * detail::three_at(y, s.y + 3).squaredNorm();
  }
  template <class Euler>
  double mass_flow_power(const detail::MassRigidSlot<Euler>& s, const Coordinates& y, double rate) const {
    const Eigen::Vector3d w = detail::three_at(y, s.y + 10);
    return 0.5 * rate * (detail::three_at(y, s.y + 7).squaredNorm() + w.dot(s.euler.momentum(w)) / s.mass.m0);
  }
  double mass_flow_power(const detail::FunctionRigidSlot& s, const Coordinates& y, double rate) const {
    if (rate == 0.0) return 0.0;
    const Eigen::Vector3d w = detail::three_at(y, s.y + 10);
    const Eigen::Matrix3d dI_dm =
        inertia_mass_derivative(s.mass.flow, s.inertia_com0, s.mass.m0, y[s.mass.m_y], rate, s.mass.flow_name);
    return 0.5 * rate * (detail::three_at(y, s.y + 7).squaredNorm() + w.dot(dI_dm * w));
  }

  // How many slots follow t in y (and ξ): the works, then the mass-flow energies
  Eigen::Index extra_count() const { return static_cast<Eigen::Index>(terms_.size() + energy_body_.size()); }
  // where the k-th mass-flow energy is in y, and that of the flow c in y and ξ
  Eigen::Index energy_y(std::size_t k) const { return t_y_ + 1 + static_cast<Eigen::Index>(terms_.size() + k); }
  Eigen::Index energy_y(const detail::MassCoordinate& c) const { return energy_y(static_cast<std::size_t>(c.energy)); }
  Eigen::Index energy_xi(const detail::MassCoordinate& c) const {
    return t_xi_ + 1 + static_cast<Eigen::Index>(terms_.size()) + c.energy;
  }

  // Newton–Euler of a variable-mass rigid body at kinematics_ and wrenches_: m v̇ = f (mass_flow.hpp), and
  // Euler's equations I(m) ω̇ + ω × I(m) ω = τ (scaled: those of I_C0 with the torque m0/m τ)
  template <class Slot>
  void mass_rigid_newton_euler(const Slot& s, const Eigen::Vector3d& w_B, Eigen::Vector3d& a_W, Eigen::Vector3d& alpha_B) const {
    const BodyWrench& wrench = wrenches_[s.body];
    const double m = kinematics_[s.body].m;
    a_W = wrench.f_W / m;
    alpha_B = detail::euler_at(s, m).angular_acceleration(w_B, detail::torque_scale_at(s, m) * wrench.tau_B);
  }

  // The free rotation of a variable-mass rigid body under the scaled rule: that of I_C0 (ω × I ω = 0 is
  // unchanged by the factor m/m0)
  template <class Rotation, class Euler>
  static void mass_free_rotation(Rotation, const detail::MassRigidSlot<Euler>& s, Coordinates& y, double h) {
    if constexpr (std::is_same_v<Rotation, ExactRotation>) {
      exact_free_rotation(s.flow, y.data() + s.y + 3, y.data() + s.y + 10, h);
    } else {
      free_dlm(Rotation{}, s.euler, y.data() + s.y + 3, y.data() + s.y + 10, h);
    }
  }
  template <class Rotation>
  static void mass_free_rotation(Rotation, const detail::FunctionRigidSlot& /*s*/, Coordinates& /*y*/, double /*h*/) {
    throw std::logic_error("free_flow: a rigid body with InertiaRule::function has no free rotation (compile refuses "
                           "the splitting methods for it)");
  }

  // α [rad/s²] of a pinned planar body at y under its wrench (plane kinetics about O)
  double pivoted_planar_alpha(const detail::PivotedPlanarSlot& s, const Coordinates& y) const {
    return pivoted_planar_angular_acceleration(s.inertia_O_zz, pivoted_planar_c_W(s.c_B, y[s.y]), wrenches_[s.body]);
  }

  template <bool normalise, class Euler>
  static void free_dlm(DlmRotation<normalise>, const Euler& euler, double* q, double* w, double h) {
    dlm_free_rotation<normalise>(euler, q, w, h);
  }

  // p += h v for every body
  void translate(Coordinates& y, double h) const {
    for (const auto& s : particles_) for (int i = 0; i < 3; ++i) y[s.y + i] += h * y[s.y + 3 + i];
    for (const auto& s : planars_) for (int i = 0; i < 2; ++i) y[s.y + i] += h * y[s.y + 3 + i];
    for_each_rigid([&](const auto& s) { for (int i = 0; i < 3; ++i) y[s.y + i] += h * y[s.y + 7 + i]; });
    for (const auto& s : mass_particles_) for (int i = 0; i < 3; ++i) y[s.y + i] += h * y[s.y + 3 + i];
    for_each_mass_rigid([&](const auto& s) { for (int i = 0; i < 3; ++i) y[s.y + i] += h * y[s.y + 7 + i]; });
  }

  template <class GyroscopicKick>
  void kick_with(Coordinates& y, double h, GyroscopicKick&& gyroscopic_kick) const {
    evaluate(y);
    for (const auto& s : particles_) {
      const Eigen::Vector3d a = detail::particle_newton_euler(s, wrenches_[s.body]);
      for (int i = 0; i < 3; ++i) y[s.y + 3 + i] += h * a[i];
    }
    for (const auto& s : planars_) {
      const Eigen::Vector3d a = detail::planar_newton_euler(s, wrenches_[s.body]);
      for (int i = 0; i < 3; ++i) y[s.y + 3 + i] += h * a[i];
    }
    for_each_rigid([&](const auto& s) {
      const BodyWrench& wrench = wrenches_[s.body];
      const Eigen::Vector3d w = gyroscopic_kick(s.euler, detail::three_at(y, s.y + 10), wrench.tau_B, h);
      for (int i = 0; i < 3; ++i) y[s.y + 7 + i] += (h * s.inverse_mass) * wrench.f_W[i], y[s.y + 10 + i] = w[i];
    });
    for_each_pivoted([&](const auto& s) {  // Euler's equations about O with the wrench reduced to O
      const BodyKinematics& k = kinematics_[s.body];
      const Eigen::Vector3d w = gyroscopic_kick(s.euler_O, k.w_B, pivoted_torque_O(s.c_B, k.q_WB, wrenches_[s.body]), h);
      for (int i = 0; i < 3; ++i) y[s.y + 4 + i] = w[i];
    });
    for (const auto& s : pivoted_planars_) y[s.y + 1] += h * pivoted_planar_alpha(s, y);
    for (const auto& s : mass_particles_) {
      const Eigen::Vector3d dv = (h / kinematics_[s.body].m) * wrenches_[s.body].f_W;
      for (int i = 0; i < 3; ++i) y[s.y + 3 + i] += dv[i];
    }
    for_each_mass_rigid([&](const auto& s) {  // Euler's equations of I_C0 with the torque scaled by m0/m
      const BodyWrench& wrench = wrenches_[s.body];
      const double m = kinematics_[s.body].m;
      const Eigen::Vector3d w =
          gyroscopic_kick(euler_at(s, m), detail::three_at(y, s.y + 10), torque_scale_at(s, m) * wrench.tau_B, h);
      for (int i = 0; i < 3; ++i) y[s.y + 7 + i] += (h / m) * wrench.f_W[i], y[s.y + 10 + i] = w[i];
    });
  }

  // kinematics_ from y as elements see them (body_kinematics.hpp; rigid attitudes normalised)
  void fill_kinematics(const Coordinates& y) const {
    for (const auto& s : particles_) {
      BodyKinematics& k = kinematics_[s.body];
      k.p_W = detail::three_at(y, s.y);
      k.v_W = detail::three_at(y, s.y + 3);
    }
    for (const auto& s : planars_) {
      BodyKinematics& k = kinematics_[s.body];
      k.p_W = Eigen::Vector3d(y[s.y], y[s.y + 1], 0.0);
      const double half = 0.5 * y[s.y + 2];
      k.q_WB = Eigen::Quaterniond(std::cos(half), 0.0, 0.0, std::sin(half));
      k.v_W = Eigen::Vector3d(y[s.y + 3], y[s.y + 4], 0.0);
      k.w_B = Eigen::Vector3d(0.0, 0.0, y[s.y + 5]);
    }
    for_each_rigid([&](const auto& s) {
      BodyKinematics& k = kinematics_[s.body];
      k.p_W = detail::three_at(y, s.y);
      k.q_WB = Eigen::Quaterniond(y[s.y + 6], y[s.y + 3], y[s.y + 4], y[s.y + 5]);
      k.q_WB.coeffs() *= 1.0 / k.q_WB.coeffs().norm();
      k.v_W = detail::three_at(y, s.y + 7);
      k.w_B = detail::three_at(y, s.y + 10);
    });
    for_each_pivoted([&](const auto& s) {  // at the centre of mass: p = O + R c, v = R (ω × c)
      BodyKinematics& k = kinematics_[s.body];
      k.q_WB = Eigen::Quaterniond(y[s.y + 3], y[s.y], y[s.y + 1], y[s.y + 2]);
      k.q_WB.coeffs() *= 1.0 / k.q_WB.coeffs().norm();
      k.w_B = detail::three_at(y, s.y + 4);
      k.p_W = s.p_WO + k.q_WB * s.c_B;
      k.v_W = k.q_WB * cross_3(k.w_B, s.c_B);
    });
    for (const auto& s : pivoted_planars_) {  // p = (O + c_W, 0), v = ω ẑ × c_W, q = Rz(θ)
      BodyKinematics& k = kinematics_[s.body];
      const double theta = y[s.y], w = y[s.y + 1];
      const Eigen::Vector2d c_W = pivoted_planar_c_W(s.c_B, theta);
      k.p_W = Eigen::Vector3d(s.p_WO.x() + c_W.x(), s.p_WO.y() + c_W.y(), 0.0);
      k.q_WB = Eigen::Quaterniond(std::cos(0.5 * theta), 0.0, 0.0, std::sin(0.5 * theta));
      k.v_W = Eigen::Vector3d(-w * c_W.y(), w * c_W.x(), 0.0);
      k.w_B = Eigen::Vector3d(0.0, 0.0, w);
    }
    for (const auto& s : mass_particles_) {
      BodyKinematics& k = kinematics_[s.body];
      k.p_W = detail::three_at(y, s.y);
      k.v_W = detail::three_at(y, s.y + 3);
      k.m = checked_mass(s.mass, y);
    }
    for_each_mass_rigid([&](const auto& s) {
      BodyKinematics& k = kinematics_[s.body];
      k.p_W = detail::three_at(y, s.y);
      k.q_WB = Eigen::Quaterniond(y[s.y + 6], y[s.y + 3], y[s.y + 4], y[s.y + 5]);
      k.q_WB.coeffs() *= 1.0 / k.q_WB.coeffs().norm();
      k.v_W = detail::three_at(y, s.y + 7);
      k.w_B = detail::three_at(y, s.y + 10);
      k.m = checked_mass(s.mass, y);
    });
  }

  // kinematics_ at y, wrenches_ = Σ of every element's wrenches, power_[e] = element e's power
  void evaluate(const Coordinates& y) const {
    fill_kinematics(y);
    for (BodyWrench& w : wrenches_) w.f_W.setZero(), w.tau_B.setZero();
    const double t = y[t_y_];
    for (std::size_t e = 0; e < terms_.size(); ++e) {
      power_[e] = std::visit([&](const auto& term) { return term.add_wrenches(t, kinematics_, wrenches_); }, terms_[e]);
    }
  }

  std::vector<Term> terms_;
  std::vector<detail::ParticleSlot> particles_;
  std::vector<detail::PlanarSlot> planars_;
  std::tuple<std::vector<detail::RigidSlot<SphericalEuler>>, std::vector<detail::RigidSlot<PrincipalEuler>>,
             std::vector<detail::RigidSlot<FullEuler>>>
      rigid_;
  Eigen::Index t_y_ = 0, t_xi_ = 0;  // offsets of t in y and ξ
  std::tuple<std::vector<detail::PivotedSlot<SphericalEuler>>, std::vector<detail::PivotedSlot<PrincipalEuler>>,
             std::vector<detail::PivotedSlot<FullEuler>>>
      pivoted_;
  std::vector<detail::PivotedPlanarSlot> pivoted_planars_;
  std::vector<detail::MassParticleSlot> mass_particles_;
  std::tuple<std::vector<detail::MassRigidSlot<SphericalEuler>>, std::vector<detail::MassRigidSlot<PrincipalEuler>>,
             std::vector<detail::MassRigidSlot<FullEuler>>, std::vector<detail::FunctionRigidSlot>>
      mass_rigid_;
  // the start [s] of the step being taken, for the out-of-mass message (set_time, coordinates, project,
  // drift, free_flow; a run copies its model and steps it on one thread)
  mutable double step_start_ = std::numeric_limits<double>::quiet_NaN();
  bool has_pivoted_ = false, has_mass_rigid_ = false;  // any slot in pivoted_, mass_rigid_
  std::vector<Eigen::Index> q_y_;  // offset of each body's q_WB in y, −1 without one (for the recorder only)
  std::vector<int> energy_body_;   // the bodies with a MassFlow, in the scene's order (their mass-flow energies')
  // scratch, sized here (an evaluation allocates nothing)
  mutable std::vector<BodyKinematics> kinematics_;
  mutable std::vector<BodyWrench> wrenches_;
  mutable std::vector<double> power_;
  mutable std::vector<std::vector<BodyWrench>> element_wrenches_;  // per element (loads_kick's exact work)
  mutable std::vector<Eigen::Vector3d> reaction_W_, momentum_O_W_;  // per body, for the recorder only
  mutable Coordinates stage_;  // y ⊕ Θ of velocity_at
  // the Coriolis terms (loads_kick's exact kick; empty without a turning frame) and the bodies' inertias for it
  struct CoriolisFrame {
    std::size_t element;
    bool constant;          // the frame's rotation is constant: Ω_F below
    Eigen::Vector3d w_F;    // [rad/s] in F
  };
  std::vector<CoriolisFrame> coriolis_terms_;
  std::vector<detail::CoriolisInertia> coriolis_inertia_;  // per body (set for rigid and pivoted bodies)
};

using SceneModel = BasicSceneModel<>;

}  // namespace rigiddyn
