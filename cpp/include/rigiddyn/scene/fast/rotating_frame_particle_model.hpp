// RotatingFrameParticleModel: the fast model of ONE particle whose state is relative to a frame F turning at
// a constant angular velocity Ω about its fixed origin (SceneFrame::rotating / earth, constant_rotation),
// under at most uniform gravity g_F (given in F) — the fast path compile chooses for such a scene.
// Fixed-size coordinates, no allocation, no visit; the same members as SceneModel
// (scene/scene_model.hpp), so the run loop and every integrator take it unchanged. "W" in the records is F.
//
// Coordinates y (10,): (p_F 3, v_F 3, t, work of gravity, work of the centrifugal force, work of the
// Coriolis force) [m, m/s, s, J, J, J]; tangent ξ: their rates (a vector space: ξ = ẏ).
//
// Equations ("Rigid body kinematics and dynamics" notes, eqs. (4.39)–(4.40), with α = 0 and a_O = 0):
//   ṗ = v,  v̇ = g − Ω × (Ω × p) − 2 Ω × v,
//   powers m g·v, m a_cf·v (a_cf = −Ω × (Ω × p); = −dV_cf/dt, V_cf = −½ m |Ω × p|²) and m a_co·v
//   (a_co = −2 Ω × v: zero up to round-off, computed as the others so that the record shows it).
// The splitting methods (splitting_dlm, yoshida4, exact_flow_kick) compose loads_kick and free_flow. The
// Coriolis force depends on v, so the loads part (p frozen) is the linear ODE v̇ = c − 2 Ω × v with
// c = g − Ω × (Ω × p) constant: loads_kick applies its exact flow (v turns about Ω by −2|Ω|h while c acts;
// closed form below), so each composition keeps its order (2, and 4 for Yoshida's) and the kicks' time
// symmetry; the Coriolis force does no work in it, exactly. The free part is p += h v. The first-order
// kicks of semi-implicit Euler take v += h a(p, v) with the Coriolis term explicit (no gyroscopic term:
// kick_implicit_gyroscopic is the same kick).
// Why it stays beside the one engine: a particle in a turning frame has no one-body layout, and the generic model
// takes 5.4× its time per RK4 step (163 against 30 ns; `bench/bench_moving_frame.cpp`, rotating_particle_rk4 and
// rotating_particle_scene_rk4, each over the same hand-written loop; docs/perf/scenes.md §4.1).
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/models/model_interface.hpp"
#include "rigiddyn/models/particle.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/scene_frame.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"

#include <Eigen/Core>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigiddyn {

namespace detail {

// sin x / x (1 at x = 0)
inline double sinc(double x) { return x == 0.0 ? 1.0 : std::sin(x) / x; }

// (x − sin x) / x³ = (1 − sinc x) / x²: its Taylor series below |x| = 0.1 (the terms left out are below
// 2e-20 relative), the direct form above (x − sin x loses at most 4 digits there: ~1e-13 relative).
inline double one_minus_sinc_over_x2(double x) {
  const double x2 = x * x;
  if (std::abs(x) < 0.1) {
    return 1.0 / 6.0 - x2 * (1.0 / 120.0 - x2 * (1.0 / 5040.0 - x2 * (1.0 / 362880.0 - x2 / 39916800.0)));
  }
  return (x - std::sin(x)) / (x2 * x);
}

}  // namespace detail

class RotatingFrameParticleModel {
 public:
  using Coordinates = Eigen::Matrix<double, 10, 1>;
  using Tangent = Eigen::Matrix<double, 10, 1>;

  // particle: its mass; frame: F, a constant rotation (frame.constant_rotation); g_F [m/s²]: uniform gravity
  // in F (zero unless gravity_element >= 0); gravity_element, centrifugal_element, coriolis_element: the
  // indices of the UniformGravity element and of the compiled "frame.centrifugal" and "frame.coriolis" terms
  // among the scene's element_count elements, or -1 (allowed for the frame terms only when Ω = 0).
  // Throws std::invalid_argument naming the argument: frame not a constant rotation; non-finite g_F; an
  // index out of [-1, element_count) or repeated; gravity without a gravity element; Ω ≠ 0 without the
  // centrifugal and Coriolis elements.
  RotatingFrameParticleModel(const Particle& particle, const SceneFrame& frame, const Eigen::Vector3d& g_F, int gravity_element,
                             int centrifugal_element, int coriolis_element, std::size_t element_count)
      : mass_(particle.mass()),
        g_(g_F),
        gravity_element_(gravity_element),
        centrifugal_element_(centrifugal_element),
        coriolis_element_(coriolis_element),
        element_count_(element_count) {
    if (!frame.constant_rotation) {
      throw std::invalid_argument("frame: expected a constant rotation about a fixed origin (SceneFrame::rotating or earth), "
                                  "got a general motion (SceneFrame::moving)");
    }
    w_ = frame_terms(frame, 0.0).w_F;
    require_finite(g_F, "g_F");
    const int n = static_cast<int>(element_count);
    const int indices[3] = {gravity_element, centrifugal_element, coriolis_element};
    const char* names[3] = {"gravity_element", "centrifugal_element", "coriolis_element"};
    for (int i = 0; i < 3; ++i) {
      if (indices[i] < -1 || indices[i] >= n) throw_invalid(names[i], "-1 or an index in [0, " + std::to_string(n) + ")", indices[i]);
      for (int j = 0; j < i; ++j) {
        if (indices[i] >= 0 && indices[i] == indices[j]) throw_invalid(names[i], std::string("another element than ") + names[j], indices[i]);
      }
    }
    if (gravity_element < 0 && !g_F.isZero(0.0)) throw_invalid("g_F", "zero without a gravity element (gravity_element = -1)", g_F);
    if ((centrifugal_element < 0 || coriolis_element < 0) && !w_.isZero(0.0)) {
      throw std::invalid_argument("centrifugal_element: expected the indices of both frame terms for a turning frame (Ω = " +
                                  format_value(w_.transpose().eval()) + " rad/s), got centrifugal_element = " +
                                  std::to_string(centrifugal_element) + ", coriolis_element = " + std::to_string(coriolis_element));
    }
  }

  Eigen::Index coordinate_count() const { return 10; }
  Eigen::Index tangent_count() const { return 10; }
  static constexpr Eigen::Index time_index() { return 6; }  // where t [s] is in y
  // where element e's work is in y (the gravity, centrifugal or Coriolis slot; -1 for any other element,
  // which a scene on this fast path does not have)
  Eigen::Index work_index(std::size_t element) const {
    const int e = static_cast<int>(element);
    return e == gravity_element_ ? 7 : e == centrifugal_element_ ? 8 : e == coriolis_element_ ? 9 : -1;
  }
  std::size_t body_count() const { return 1; }
  std::size_t element_count() const { return element_count_; }
  const Eigen::Vector3d& w_F() const { return w_; }  // Ω in F [rad/s]

  // nothing is piecewise constant here: no switch times (simulate/run_loop.hpp switches_never)
  static void set_time(double /*t*/) {}
  static constexpr bool switches_never() { return true; }

  // ẏ = (v, g + a_cf + a_co, 1, m g·v, m a_cf·v, m a_co·v)
  RIGIDDYN_ALWAYS_INLINE void rate(const Coordinates& y, Coordinates& dy) const {
    Eigen::Vector3d a_cf, a_co;
    fictitious_accelerations(y, a_cf, a_co);
    // element by element (scalar stores; see rk4.hpp's axpy on store forwarding)
    for (int i = 0; i < 3; ++i) dy[i] = y[3 + i], dy[3 + i] = g_[i] + a_cf[i] + a_co[i];
    dy[6] = 1.0;
    dy[7] = mass_ * (g_[0] * y[3] + g_[1] * y[4] + g_[2] * y[5]);
    dy[8] = mass_ * (a_cf[0] * y[3] + a_cf[1] * y[4] + a_cf[2] * y[5]);
    dy[9] = mass_ * (a_co[0] * y[3] + a_co[1] * y[4] + a_co[2] * y[5]);
  }

  static void project(Coordinates& /*y*/) {}
  RIGIDDYN_ALWAYS_INLINE void velocity(const Coordinates& y, Tangent& xi) const { rate(y, xi); }
  static void retract(const Coordinates& y, const Tangent& theta, Coordinates& out) {
    for (int i = 0; i < 10; ++i) out[i] = y[i] + theta[i];
  }
  RIGIDDYN_ALWAYS_INLINE void velocity_at(const Coordinates& y, const Tangent& theta, Tangent& xi) const {
    Coordinates stage;
    retract(y, theta, stage);
    velocity(stage, xi);
  }
  static void dexp_inv(const Tangent& /*theta*/, Tangent& /*xi*/) {}

  // v += h a(p, v) (Coriolis explicit); p, t and the works unchanged
  RIGIDDYN_ALWAYS_INLINE void kick(Coordinates& y, double h) const {
    Eigen::Vector3d a_cf, a_co;
    fictitious_accelerations(y, a_cf, a_co);
    for (int i = 0; i < 3; ++i) y[3 + i] += h * (g_[i] + a_cf[i] + a_co[i]);
  }
  // no gyroscopic term: the same kick
  RIGIDDYN_ALWAYS_INLINE void kick_implicit_gyroscopic(Coordinates& y, double h) const { kick(y, h); }

  // works += h × powers at y, then p += h v, t += h
  RIGIDDYN_ALWAYS_INLINE void drift(Coordinates& y, double h) const {
    Coordinates dy;
    rate(y, dy);
    for (int i = 7; i < 10; ++i) y[i] += h * dy[i];
    for (int i = 0; i < 3; ++i) y[i] += h * y[3 + i];
    y[6] += h;
  }

  // The exact flow of the loads part over h [s] (p and t frozen): v̇ = c − 2 Ω × v, c = g − Ω × (Ω × p).
  // With ω = |Ω|, R(s) the turn about Ω by −2ωs and G(h) = ∫₀ʰ R, V(h) = ∫₀ʰ G:
  //   v(h) = R(h) v0 + G(h) c,                      ∫₀ʰ v = G(h) v0 + V(h) c,
  //   R(h) v = v − 2h sinc(2ωh) Ω×v + 2h² sinc²(ωh) Ω×(Ω×v),
  //   G(h) c = h c − h² sinc²(ωh) Ω×c + 4h³ S(2ωh) Ω×(Ω×c),
  //   V(h) c = ½h² c − 2h³ S(2ωh) Ω×c + ½h⁴ S(ωh)(1 + sinc ωh) Ω×(Ω×c),   S(x) = (x − sin x)/x³,
  // (Rodrigues' formula for R, integrated term by term; no division by ω, exact at Ω = 0); the works of
  // gravity and of the centrifugal force are m g·∫v and m a_cf·∫v (both forces are constant in this flow),
  // the Coriolis force's is zero. Returns 0 (a particle has no angular velocity).
  double loads_kick(Coordinates& y, double h) const {
    const Eigen::Vector3d p(y[0], y[1], y[2]), v0(y[3], y[4], y[5]);
    const Eigen::Vector3d a_cf = -w_.cross(w_.cross(p)), c = g_ + a_cf;
    const double omega = w_.norm();
    const double s1 = detail::sinc(omega * h), s2 = detail::sinc(2.0 * omega * h);
    const double S1 = detail::one_minus_sinc_over_x2(omega * h), S2 = detail::one_minus_sinc_over_x2(2.0 * omega * h);
    const double h2 = h * h, h3 = h2 * h;
    const Eigen::Vector3d w_v = w_.cross(v0), w_w_v = w_.cross(w_v), w_c = w_.cross(c), w_w_c = w_.cross(w_c);
    const Eigen::Vector3d v1 = v0 - (2.0 * h * s2) * w_v + (2.0 * h2 * s1 * s1) * w_w_v  // R v0
                               + h * c - (h2 * s1 * s1) * w_c + (4.0 * h3 * S2) * w_w_c;  // G c
    const Eigen::Vector3d v_integral = h * v0 - (h2 * s1 * s1) * w_v + (4.0 * h3 * S2) * w_w_v  // G v0
                                       + (0.5 * h2) * c - (2.0 * h3 * S2) * w_c + (0.5 * h2 * h2 * S1 * (1.0 + s1)) * w_w_c;
    y[7] += mass_ * g_.dot(v_integral);
    y[8] += mass_ * a_cf.dot(v_integral);
    for (int i = 0; i < 3; ++i) y[3 + i] = v1[i];
    return 0.0;
  }

  // The free part over h [s]: p += h v, t += h (no attitude: the rotation flow is not used; no force acts)
  template <class Rotation>
  RIGIDDYN_ALWAYS_INLINE void free_flow(Coordinates& y, double h) const {
    for (int i = 0; i < 3; ++i) y[i] += h * y[3 + i];
    y[6] += h;
  }

  // Appends the record of y at time t [s] to `out` (scene_simulation.hpp), relative to F: the particle
  // (q_WB identity, w_B 0), T = ½ m v·v, V = −m g·p − ½ m |Ω × p|² (of the declared elements; T + V is
  // Jacobi's integral), L = m v, H = p × m v, no pivot (reaction 0), H about the centre of mass 0, the
  // mass, each element's work and power.
  void record(const Coordinates& y, double t, SceneSimulation& out) const {
    const Eigen::Vector3d p(y[0], y[1], y[2]), v(y[3], y[4], y[5]);
    Coordinates dy;
    rate(y, dy);
    out.t.push_back(t);
    out.p_W.insert(out.p_W.end(), p.data(), p.data() + 3);
    const double identity[4] = {0.0, 0.0, 0.0, 1.0}, zero[3] = {0.0, 0.0, 0.0};
    out.q_WB.insert(out.q_WB.end(), identity, identity + 4);
    out.v_W.insert(out.v_W.end(), v.data(), v.data() + 3);
    out.w_B.insert(out.w_B.end(), zero, zero + 3);
    out.pivot_reaction_W.insert(out.pivot_reaction_W.end(), zero, zero + 3);
    out.angular_momentum_O_W.insert(out.angular_momentum_O_W.end(), zero, zero + 3);
    out.mass.push_back(mass_);
    const double T = 0.5 * mass_ * v.squaredNorm();
    double V = 0.0;
    if (gravity_element_ >= 0) V -= mass_ * g_.dot(p);
    if (centrifugal_element_ >= 0) V -= 0.5 * mass_ * w_.cross(p).squaredNorm();
    out.kinetic_energy.push_back(T);
    out.potential_energy.push_back(V);
    out.total_energy.push_back(T + V);
    const Eigen::Vector3d L = mass_ * v, H = p.cross(L);
    out.linear_momentum_W.insert(out.linear_momentum_W.end(), L.data(), L.data() + 3);
    out.angular_momentum_W.insert(out.angular_momentum_W.end(), H.data(), H.data() + 3);
    for (std::size_t e = 0; e < element_count_; ++e) {
      const Eigen::Index i = work_index(e);
      out.work.push_back(i < 0 ? 0.0 : y[i]);
      out.power.push_back(i < 0 ? 0.0 : dy[i]);
    }
  }

  // y of the particle's state (p_F, v_F relative to F, checked by the caller) at time t [s], works 0
  static Coordinates coordinates(const ParticleState& state, double t) {
    Coordinates y = Coordinates::Zero();
    for (int i = 0; i < 3; ++i) y[i] = state.p_W[i], y[3 + i] = state.v_W[i];
    y[6] = t;
    return y;
  }
  // the same from the scene's body states (one, a ParticleState)
  static Coordinates coordinates(const std::vector<BodyState>& states, double t) {
    return coordinates(std::get<ParticleState>(states[0]), t);
  }

  // The particle's state in y, relative to F
  static ParticleState state(const Coordinates& y) { return ParticleState{y.segment<3>(0), y.segment<3>(3)}; }
  // the same as the scene's body states
  static std::vector<BodyState> states(const Coordinates& y) { return {BodyState(state(y))}; }

 private:
  // a_cf = −Ω × (Ω × p) and a_co = −2 Ω × v at y [m/s²], by scalars
  RIGIDDYN_ALWAYS_INLINE void fictitious_accelerations(const Coordinates& y, Eigen::Vector3d& a_cf, Eigen::Vector3d& a_co) const {
    const double wx = w_[0], wy = w_[1], wz = w_[2];
    const double px = y[0], py = y[1], pz = y[2], vx = y[3], vy = y[4], vz = y[5];
    const double cx = wy * pz - wz * py, cy = wz * px - wx * pz, cz = wx * py - wy * px;  // Ω × p
    a_cf = Eigen::Vector3d(cy * wz - cz * wy, cz * wx - cx * wz, cx * wy - cy * wx);         // (Ω × p) × Ω
    a_co = Eigen::Vector3d(-2.0 * (wy * vz - wz * vy), -2.0 * (wz * vx - wx * vz), -2.0 * (wx * vy - wy * vx));
  }

  double mass_;
  Eigen::Vector3d w_;  // Ω in F [rad/s]
  Eigen::Vector3d g_;  // g in F [m/s²]
  int gravity_element_, centrifugal_element_, coriolis_element_;
  std::size_t element_count_;
};

}  // namespace rigiddyn
