// SceneModel: the integrator model (models/model_interface.hpp) of a compiled scene — any number of
// bodies of any kind and the force elements declared, nothing else (scene_api.md §3).
//
// Coordinates y (Eigen::VectorXd), per body in the scene's order:
//   particle  (p_W 3, v_W 3)                        no attitude: a particle pays nothing for one
//   planar    (x, y, θ, v_x, v_y, ω)
//   rigid     (p_W 3, q_WB xyzw 4, v_W 3, w_B 3)
// then t [s] (so that every method evaluates time-dependent forces at its own stage times), then one
// work slot per element [J] (its work since t0, integrated with the motion: dW_e/dt = P_e).
// Tangent ξ: per body (particle v_W, a_W; planar the 6 rates; rigid v_W, w_B, a_W, alpha_B), then
// dt/dt = 1, then each element's power [W].
//
// One evaluation: every body's kinematics (body_kinematics.hpp) from y, wrenches zeroed, each element
// adds its wrenches once (one std::visit per element: an element that is not declared does not exist),
// then Newton–Euler per body in one function per kind (newton_euler below), the rigid bodies grouped
// by Euler form (a sphere pays nothing for the gyroscopic term). Scratch buffers are sized when the
// model is built: an evaluation allocates nothing (so a model is not shared between threads: each run
// copies its own).
#pragma once
#include "rigiddyn/exact/free_body.hpp"
#include "rigiddyn/integrators/exact_flow_kick.hpp"
#include "rigiddyn/integrators/free_flow_tags.hpp"
#include "rigiddyn/integrators/splitting_dlm.hpp"
#include "rigiddyn/models/euler_equations.hpp"
#include "rigiddyn/scene/scene.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/so3/exp_log.hpp"
#include "rigiddyn/so3/quaternion_kernels.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
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

RIGIDDYN_ALWAYS_INLINE Eigen::Vector3d three_at(const Eigen::VectorXd& x, Eigen::Index i) {
  return Eigen::Vector3d(x[i], x[i + 1], x[i + 2]);
}

}  // namespace detail

// The model of a scene whose elements compile to the terms UniformGravityTerm … FunctionForceTerm and
// the user's Extra terms (CustomForceTerm<F>, scene/custom_force.hpp). SceneModel = BasicSceneModel<>.
template <class... Extra>
class BasicSceneModel {
 public:
  using Coordinates = Eigen::VectorXd;
  using Tangent = Eigen::VectorXd;
  using Term = std::variant<UniformGravityTerm, PointMassGravityTerm, MutualGravityTerm, GravityGradientTerm,
                            SpringDamperTerm, DragTerm, ScheduledLoadsTerm, FunctionForceTerm, Extra...>;

  // The bodies (checked when they were built) and the compiled terms, in the scene's order.
  BasicSceneModel(const std::vector<Body>& bodies, std::vector<Term> terms) : terms_(std::move(terms)) {
    Eigen::Index y = 0, xi = 0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const int b = static_cast<int>(i);
      if (const auto* p = std::get_if<Particle>(&bodies[i])) {
        particles_.push_back({b, y, xi, p->mass(), 1.0 / p->mass()});
        y += 6, xi += 6;
      } else if (const auto* s = std::get_if<PlanarBody>(&bodies[i])) {
        planars_.push_back({b, y, xi, s->mass(), 1.0 / s->mass(), s->inertia_zz(), 1.0 / s->inertia_zz()});
        y += 6, xi += 6;
      } else {
        const RigidBody& r = std::get<RigidBody>(bodies[i]);
        with_euler_form(r, [&](const auto& euler) {
          using Euler = std::decay_t<decltype(euler)>;
          std::get<std::vector<detail::RigidSlot<Euler>>>(rigid_).push_back(
              {b, y, xi, r.mass(), 1.0 / r.mass(), euler, FreeRotationFlow(r.inertia_com())});
        });
        y += 13, xi += 12;
      }
    }
    t_y_ = y, t_xi_ = xi;
    kinematics_.resize(bodies.size());
    wrenches_.resize(bodies.size());
    power_.resize(terms_.size());
    element_wrenches_.assign(terms_.size(), std::vector<BodyWrench>(bodies.size()));
    body_y_.resize(bodies.size());
    body_kind_.resize(bodies.size());
    for (const auto& s : particles_) body_y_[s.body] = s.y, body_kind_[s.body] = 0;
    for (const auto& s : planars_) body_y_[s.body] = s.y, body_kind_[s.body] = 1;
    for_each_rigid([&](const auto& s) { body_y_[s.body] = s.y, body_kind_[s.body] = 2; });
  }

  Eigen::Index coordinate_count() const { return t_y_ + 1 + static_cast<Eigen::Index>(terms_.size()); }
  Eigen::Index tangent_count() const { return t_xi_ + 1 + static_cast<Eigen::Index>(terms_.size()); }
  Eigen::Index time_index() const { return t_y_; }  // where t [s] is in y
  Eigen::Index work_index(std::size_t element) const { return t_y_ + 1 + static_cast<Eigen::Index>(element); }
  std::size_t body_count() const { return kinematics_.size(); }
  std::size_t element_count() const { return terms_.size(); }
  const std::vector<Term>& terms() const { return terms_; }

  // Sets every piecewise-constant element (ScheduledLoads) to its piece at time t [s]: called by the
  // run loop at t0 and at each switch time, never per evaluation.
  void set_time(double t) {
    for (Term& term : terms_) {
      std::visit(
          [t](auto& e) {
            if constexpr (std::is_same_v<std::decay_t<decltype(e)>, ScheduledLoadsTerm>) e.set_time(t);
          },
          term);
    }
  }

  // ẏ: (v, a) per body, q̇ = ½ q ⊗ (ω_B, 0) for attitudes, dt/dt = 1, dW_e/dt = P_e.
  Coordinates rate(const Coordinates& y) const {
    evaluate(y);
    Coordinates dy(y.size());
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
    dy[t_y_] = 1.0;
    for (std::size_t e = 0; e < terms_.size(); ++e) dy[t_y_ + 1 + e] = power_[e];
    return dy;
  }

  // every attitude q ← q / |q|
  void project(Coordinates& y) const {
    for_each_rigid([&](const auto& s) {
      double* q = y.data() + s.y + 3;
      const double inverse_norm = 1.0 / std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      for (int i = 0; i < 4; ++i) q[i] *= inverse_norm;
    });
  }

  // ξ = (velocities, accelerations per body; 1; element powers)
  Tangent velocity(const Coordinates& y) const {
    evaluate(y);
    Tangent xi(tangent_count());
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
    xi[t_xi_] = 1.0;
    for (std::size_t e = 0; e < terms_.size(); ++e) xi[t_xi_ + 1 + e] = power_[e];
    return xi;
  }

  // y ⊕ Θ: vector parts added, q ← q ⊗ exp(Θ_rot) for each rigid body
  Coordinates retract(const Coordinates& y, const Tangent& theta) const {
    Coordinates out(y.size());
    for (const auto& s : particles_) for (int i = 0; i < 6; ++i) out[s.y + i] = y[s.y + i] + theta[s.xi + i];
    for (const auto& s : planars_) for (int i = 0; i < 6; ++i) out[s.y + i] = y[s.y + i] + theta[s.xi + i];
    for_each_rigid([&](const auto& s) {
      for (int i = 0; i < 3; ++i) out[s.y + i] = y[s.y + i] + theta[s.xi + i];
      times_exp(y.data() + s.y + 3, detail::three_at(theta, s.xi + 3), out.data() + s.y + 3);
      for (int i = 0; i < 6; ++i) out[s.y + 7 + i] = y[s.y + 7 + i] + theta[s.xi + 6 + i];
    });
    for (Eigen::Index i = 0; i <= static_cast<Eigen::Index>(terms_.size()); ++i) out[t_y_ + i] = y[t_y_ + i] + theta[t_xi_ + i];
    return out;
  }

  // ξ(y ⊕ Θ) (elements may read any attitude: the stage attitude is always built)
  Tangent velocity_at(const Coordinates& y, const Tangent& theta) const { return velocity(retract(y, theta)); }

  // dexp⁻¹ of each rigid body's attitude part, truncated after the second commutator (RigidBodyModel)
  Tangent dexp_inv(const Tangent& theta, const Tangent& xi) const {
    Tangent out = xi;
    for_each_rigid([&](const auto& s) {
      const Eigen::Vector3d th = detail::three_at(theta, s.xi + 3), w = detail::three_at(xi, s.xi + 3);
      const Eigen::Vector3d th_x_w = cross_3(th, w), th_x_th_x_w = cross_3(th, th_x_w);
      for (int i = 0; i < 3; ++i) out[s.xi + 3 + i] = w[i] + 0.5 * th_x_w[i] + (1.0 / 12.0) * th_x_th_x_w[i];
    });
    return out;
  }

  // velocities += h × accelerations at y (the explicit gyroscopic term); positions, work, t unchanged
  void kick(Coordinates& y, double h) const { kick_with(y, h, [](const auto& euler, const auto& w, const auto& tau, double k) {
    return euler.explicit_gyroscopic_kick(w, tau, k);
  }); }
  // the same with the implicit gyroscopic term (one Newton step, euler_equations.hpp)
  void kick_implicit_gyroscopic(Coordinates& y, double h) const {
    kick_with(y, h, [](const auto& euler, const auto& w, const auto& tau, double k) { return euler.implicit_gyroscopic_kick(w, tau, k); });
  }

  // work_e += h P_e at y; then p += h v, q ← q ⊗ exp(h ω_B) (exact for constant ω), θ += h ω, t += h
  void drift(Coordinates& y, double h) const {
    evaluate(y);
    for (std::size_t e = 0; e < terms_.size(); ++e) y[t_y_ + 1 + e] += h * power_[e];
    translate(y, h);
    for (const auto& s : planars_) y[s.y + 2] += h * y[s.y + 5];
    for_each_rigid([&](const auto& s) {
      const double q[4] = {y[s.y + 3], y[s.y + 4], y[s.y + 5], y[s.y + 6]};
      times_exp(q, Eigen::Vector3d(h * y[s.y + 10], h * y[s.y + 11], h * y[s.y + 12]), y.data() + s.y + 3);
    });
    project(y);
    y[t_y_] += h;
  }

  // The exact flow of the loads part over h [s] (model_interface.hpp): the wrenches at y (positions,
  // attitudes, velocities and t as they are), v += h f/m, ω += h I⁻¹ τ (no gyroscopic term) and each
  // element's work += h Σ_b (f_eb·v̄_b + τ_eb·ω̄_b) with the mean velocities v̄ = v + Δv/2 (exact: the
  // velocities are linear in time in this flow). Returns Σ |Δω_B| over the rigid bodies [rad/s].
  double loads_kick(Coordinates& y, double h) const {
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
    // the velocity increments; kinematics_ then holds the mean velocities (v, ω + half the increment)
    double kicked = 0.0;
    for (const auto& s : particles_) {
      const Eigen::Vector3d dv = h * detail::particle_newton_euler(s, wrenches_[s.body]);
      kinematics_[s.body].v_W += 0.5 * dv;
      for (int i = 0; i < 3; ++i) y[s.y + 3 + i] += dv[i];
    }
    for (const auto& s : planars_) {
      const Eigen::Vector3d d = h * detail::planar_newton_euler(s, wrenches_[s.body]);
      kinematics_[s.body].v_W += 0.5 * Eigen::Vector3d(d[0], d[1], 0.0);
      kinematics_[s.body].w_B[2] += 0.5 * d[2];
      for (int i = 0; i < 3; ++i) y[s.y + 3 + i] += d[i];
    }
    for_each_rigid([&](const auto& s) {
      Eigen::Vector3d a, alpha;
      detail::rigid_newton_euler(s, Eigen::Vector3d::Zero(), wrenches_[s.body], a, alpha);  // ω = 0: I⁻¹ τ alone
      const Eigen::Vector3d dv = h * a, dw = h * alpha;
      kinematics_[s.body].v_W += 0.5 * dv;
      kinematics_[s.body].w_B += 0.5 * dw;
      for (int i = 0; i < 3; ++i) y[s.y + 7 + i] += dv[i], y[s.y + 10 + i] += dw[i];
      kicked += dw.norm();
    });
    for (std::size_t e = 0; e < terms_.size(); ++e) {
      double work = 0.0;
      const std::vector<BodyWrench>& w = element_wrenches_[e];
      for (std::size_t b = 0; b < w.size(); ++b) work += w[b].f_W.dot(kinematics_[b].v_W) + w[b].tau_B.dot(kinematics_[b].w_B);
      y[t_y_ + 1 + e] += h * work;
    }
    return kicked;
  }

  // The free part over h [s]: p += h v for every body, θ += h ω for a planar body, each rigid body's
  // attitude and ω_B by the flow Rotation (DlmRotation<normalise>: dlm_free_rotation; ExactRotation: the
  // body's own FreeRotationFlow), t += h; no work (no load acts in this part).
  template <class Rotation>
  void free_flow(Coordinates& y, double h) const {
    translate(y, h);
    for (const auto& s : planars_) y[s.y + 2] += h * y[s.y + 5];
    for_each_rigid([&](const auto& s) {
      if constexpr (std::is_same_v<Rotation, ExactRotation>) {
        exact_free_rotation(s.flow, y.data() + s.y + 3, y.data() + s.y + 10, h);
      } else {
        free_dlm(Rotation{}, s.euler, y.data() + s.y + 3, y.data() + s.y + 10, h);
      }
    });
    y[t_y_] += h;
  }

  // Appends the record of y at time t [s] to `out` (scene_simulation.hpp): the bodies, energies,
  // momenta, each element's work and power.
  void record(const Coordinates& y, double t, SceneSimulation& out) const {
    evaluate(y);
    out.t.push_back(t);
    double T = 0.0, V = 0.0;
    Eigen::Vector3d L_W = Eigen::Vector3d::Zero(), H_W = Eigen::Vector3d::Zero();
    for (std::size_t b = 0; b < kinematics_.size(); ++b) {
      const BodyKinematics& k = kinematics_[b];
      out.p_W.insert(out.p_W.end(), k.p_W.data(), k.p_W.data() + 3);
      if (body_kind_[b] == 2) {
        out.q_WB.insert(out.q_WB.end(), y.data() + body_y_[b] + 3, y.data() + body_y_[b] + 7);  // as integrated
      } else {
        out.q_WB.insert(out.q_WB.end(), k.q_WB.coeffs().data(), k.q_WB.coeffs().data() + 4);
      }
      out.v_W.insert(out.v_W.end(), k.v_W.data(), k.v_W.data() + 3);
      out.w_B.insert(out.w_B.end(), k.w_B.data(), k.w_B.data() + 3);
    }
    const auto translational = [&](int body, double mass) {
      const BodyKinematics& k = kinematics_[body];
      T += 0.5 * mass * k.v_W.squaredNorm();
      L_W += mass * k.v_W;
      H_W += k.p_W.cross(mass * k.v_W);
    };
    for (const auto& s : particles_) translational(s.body, s.mass);
    for (const auto& s : planars_) {
      translational(s.body, s.mass);
      const double w = kinematics_[s.body].w_B[2];
      T += 0.5 * s.inertia_zz * w * w;
      H_W[2] += s.inertia_zz * w;  // R_WB = Rz(θ) leaves the z axis
    }
    for_each_rigid([&](const auto& s) {
      translational(s.body, s.mass);
      const BodyKinematics& k = kinematics_[s.body];
      const Eigen::Vector3d h_B = s.euler.momentum(k.w_B);
      T += 0.5 * k.w_B.dot(h_B);
      H_W += k.q_WB * h_B;
    });
    for (const Term& term : terms_) V += std::visit([&](const auto& e) { return e.potential(kinematics_); }, term);
    out.kinetic_energy.push_back(T);
    out.potential_energy.push_back(V);
    out.total_energy.push_back(T + V);
    out.linear_momentum_W.insert(out.linear_momentum_W.end(), L_W.data(), L_W.data() + 3);
    out.angular_momentum_W.insert(out.angular_momentum_W.end(), H_W.data(), H_W.data() + 3);
    for (std::size_t e = 0; e < terms_.size(); ++e) out.work.push_back(y[t_y_ + 1 + e]);
    out.power.insert(out.power.end(), power_.begin(), power_.end());
  }

  // y of the bodies' states (each of its body's kind, checked by the caller) at time t [s], work 0
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
    y[t_y_] = t;
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
    return out;
  }

 private:
  template <class F>
  void for_each_rigid(F&& f) const {
    std::apply([&](const auto&... group) { (for_each_in(group, f), ...); }, rigid_);
  }
  template <class Group, class F>
  static void for_each_in(const Group& group, F& f) {
    for (const auto& s : group) f(s);
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
  std::vector<Eigen::Index> body_y_;  // offset of each body in y
  std::vector<int> body_kind_;        // 0 particle, 1 planar, 2 rigid (for the recorder only)
  // scratch, sized here (an evaluation allocates nothing)
  mutable std::vector<BodyKinematics> kinematics_;
  mutable std::vector<BodyWrench> wrenches_;
  mutable std::vector<double> power_;
  mutable std::vector<std::vector<BodyWrench>> element_wrenches_;  // per element (loads_kick's exact work)
};

using SceneModel = BasicSceneModel<>;

}  // namespace rigiddyn
