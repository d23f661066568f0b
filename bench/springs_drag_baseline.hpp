// Hand-written baseline for bench_springs_drag.cpp: N rigid bodies with principal inertias under uniform
// gravity and drag, tied in a chain by springs with dampers and each hung from a world anchor, integrated
// by classic RK4 over plain arrays with no rigiddyn code: what a user writes by hand for this scene, and
// what the generic scene model is measured against.
//
// The equations are those of the library's elements (scene/elements/uniform_gravity.hpp, drag.hpp,
// spring_damper.hpp) and body (scene/scene_model.hpp, models/euler_equations.hpp), per body
//   ṗ_W = v_W,   q̇_WB = ½ q_WB ⊗ (w_B, 0),   m v̇_W = f_W,   I ẇ_B + w_B × I w_B = tau_B,
//   f_W = m g_W − (c₁ + c₂ |v_W|) v_W + Σ spring forces,   tau_B = −(d₁ + d₂ |w_B|) w_B + Σ spring moments,
// each spring between x_a = p_a + R_a r_a and x_b = p_b + R_b r_b (or a world anchor x_b):
//   d = x_a − x_b,  ℓ = |d|,  u = d/ℓ,  ℓ̇ = u·(ẋ_a − ẋ_b),  ẋ = v_W + R (w_B × r),
//   f_a = −(k (ℓ − ℓ0) + c ℓ̇) u on a at x_a (moment r_a × R_aᵀ f_a in a's B), −f_a on b at x_b.
// The rotation R_WB of a stage's quaternion (not of unit norm between RK4's stages) is that of q/|q|, as
// the library's kinematics normalise it; the quaternions are renormalised after each step, as RK4's
// projection does.
#pragma once
#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <vector>

namespace rigiddyn::bench {

// A spring with a damper from point_a_B [m] of body a (in its B, from its centre of mass) to point_b
// [m] of body b (in b's B) or, for b = −1, to the anchor point_b in W; stiffness k [N/m], rest_length ℓ0
// [m], damping c [N s/m].
struct ChainSpring {
  int a, b;
  Eigen::Vector3d point_a_B, point_b;
  double stiffness, rest_length, damping;
};

// The scene as plain numbers, from which both sides are built.
struct SpringsDragChain {
  std::vector<double> mass;                  // (N,) [kg]
  std::vector<Eigen::Vector3d> inertia;      // (N,) principal moments (I1, I2, I3) [kg m²] in B
  std::vector<double> y0;                    // (N, 13) row-major: p_W [m], q_WB xyzw, v_W [m/s], w_B [rad/s]
  Eigen::Vector3d g_W;                       // [m/s²]
  double linear, quadratic;                  // drag force c₁ [N s/m], c₂ [N s²/m²]
  double angular_linear, angular_quadratic;  // drag torque d₁ [N m s], d₂ [N m s²]
  std::vector<ChainSpring> springs;          // (2N − 1,): N − 1 links i → i + 1, then N anchors
};

// N bodies 1 m apart along x, each about 1 kg with I ≈ diag(0.1, 0.2, 0.25) kg m² (both scaled by
// 1 + 0.01 (i mod 10)), turned about a fixed axis by 0.3 + 0.1 i rad, moving and spinning; body i linked
// to body i + 1 from (0.2, 0.05, 0) m in its B to (−0.2, −0.05, 0) m in the other's (ℓ0 = 0.5 m), and
// hung from (i, 0, 1) m in W by its point (0, 0, 0.1) m (ℓ0 = 0.5 m): every spring off the centre of mass.
inline SpringsDragChain springs_drag_chain(std::size_t n) {
  SpringsDragChain c;
  c.g_W = Eigen::Vector3d(0.0, 0.0, -9.81);
  c.linear = 0.1, c.quadratic = 0.05, c.angular_linear = 0.01, c.angular_quadratic = 0.005;
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, 3.0).normalized();
  c.y0.assign(13 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i), scale = 1.0 + 0.01 * static_cast<double>(i % 10);
    c.mass.push_back(scale);
    c.inertia.push_back(scale * Eigen::Vector3d(0.1, 0.2, 0.25));
    double* y = c.y0.data() + 13 * i;
    const double half_angle = 0.5 * (0.3 + 0.1 * x);
    const double p_W[3] = {x, 0.0, 0.0};
    const double q_WB[4] = {std::sin(half_angle) * axis.x(), std::sin(half_angle) * axis.y(), std::sin(half_angle) * axis.z(),
                            std::cos(half_angle)};
    const double v_W[3] = {0.1, -0.2 + 0.01 * x, 0.3};
    const double w_B[3] = {0.3, 2.0 - 0.01 * x, 0.5};
    for (int k = 0; k < 3; ++k) y[k] = p_W[k], y[7 + k] = v_W[k], y[10 + k] = w_B[k];
    for (int k = 0; k < 4; ++k) y[3 + k] = q_WB[k];
  }
  for (std::size_t i = 0; i + 1 < n; ++i) {
    c.springs.push_back({static_cast<int>(i), static_cast<int>(i + 1), Eigen::Vector3d(0.2, 0.05, 0.0),
                         Eigen::Vector3d(-0.2, -0.05, 0.0), 20.0, 0.5, 0.2});
  }
  for (std::size_t i = 0; i < n; ++i) {
    c.springs.push_back({static_cast<int>(i), -1, Eigen::Vector3d(0.0, 0.0, 0.1),
                         Eigen::Vector3d(static_cast<double>(i), 0.0, 1.0), 50.0, 0.5, 0.5});
  }
  return c;
}

// Classic RK4 (c = (0, ½, ½, 1), b = (1/6, 1/3, 1/3, 1/6)) on y = (per body p_W 3, q_WB xyzw 4, v_W 3,
// w_B 3): the motion only (no time slot, no per-element work as the scene model carries). Every buffer is
// sized here: a step allocates nothing.
class SpringsDragRk4Baseline {
 public:
  explicit SpringsDragRk4Baseline(const SpringsDragChain& chain)
      : chain_(chain), n_(chain.mass.size()), R_WB_(n_), f_W_(n_), tau_B_(n_), inverse_mass_(n_),
        inverse_inertia_(n_), k1_(size()), k2_(size()), k3_(size()), k4_(size()), stage_(size()) {
    for (std::size_t i = 0; i < n_; ++i) {
      inverse_mass_[i] = 1.0 / chain.mass[i];
      inverse_inertia_[i] = chain.inertia[i].cwiseInverse();
    }
  }

  std::size_t size() const { return 13 * n_; }

  // one RK4 step of size h [s], then each q_WB ← q_WB / |q_WB|
  void step(std::vector<double>& y, double h) {
    const std::size_t m = size();
    rate(y.data(), k1_.data());
    for (std::size_t i = 0; i < m; ++i) stage_[i] = y[i] + 0.5 * h * k1_[i];
    rate(stage_.data(), k2_.data());
    for (std::size_t i = 0; i < m; ++i) stage_[i] = y[i] + 0.5 * h * k2_[i];
    rate(stage_.data(), k3_.data());
    for (std::size_t i = 0; i < m; ++i) stage_[i] = y[i] + h * k3_[i];
    rate(stage_.data(), k4_.data());
    const double h_6 = h / 6.0;
    for (std::size_t i = 0; i < m; ++i) y[i] += h_6 * (k1_[i] + 2.0 * k2_[i] + 2.0 * k3_[i] + k4_[i]);
    for (std::size_t b = 0; b < n_; ++b) {
      double* q = y.data() + 13 * b + 3;
      const double inverse_norm = 1.0 / std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      for (int k = 0; k < 4; ++k) q[k] *= inverse_norm;
    }
  }

 private:
  using Vec3 = Eigen::Vector3d;
  using ConstVec3 = Eigen::Map<const Eigen::Vector3d>;

  // R_WB of q/|q| for q = (x, y, z, w): R = 1 + (2/|q|²) (w [v]× + [v]×²), v = (x, y, z)
  static Eigen::Matrix3d rotation(const double* q) {
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double s = 2.0 / (x * x + y * y + z * z + w * w);
    Eigen::Matrix3d R;
    R << 1.0 - s * (y * y + z * z), s * (x * y - z * w), s * (x * z + y * w),
         s * (x * y + z * w), 1.0 - s * (x * x + z * z), s * (y * z - x * w),
         s * (x * z - y * w), s * (y * z + x * w), 1.0 - s * (x * x + y * y);
    return R;
  }

  // dy = ẏ at y (the equations in the header)
  void rate(const double* y, double* dy) {
    const SpringsDragChain& c = chain_;
    // gravity and drag on each body, its rotation for the springs
    for (std::size_t b = 0; b < n_; ++b) {
      const double* s = y + 13 * b;
      const ConstVec3 v_W(s + 7), w_B(s + 10);
      R_WB_[b] = rotation(s + 3);
      f_W_[b] = c.mass[b] * c.g_W - (c.linear + c.quadratic * v_W.norm()) * v_W;
      tau_B_[b] = -(c.angular_linear + c.angular_quadratic * w_B.norm()) * w_B;
    }
    // each spring: f_a on a at x_a, −f_a on b at x_b
    for (const ChainSpring& k : c.springs) {
      const double* s_a = y + 13 * k.a;
      const Vec3 r_a_W = R_WB_[k.a] * k.point_a_B;
      Vec3 d = ConstVec3(s_a) + r_a_W;
      Vec3 relative_velocity = ConstVec3(s_a + 7) + R_WB_[k.a] * ConstVec3(s_a + 10).cross(k.point_a_B);
      if (k.b >= 0) {
        const double* s_b = y + 13 * k.b;
        d -= ConstVec3(s_b) + R_WB_[k.b] * k.point_b;
        relative_velocity -= ConstVec3(s_b + 7) + R_WB_[k.b] * ConstVec3(s_b + 10).cross(k.point_b);
      } else {
        d -= k.point_b;
      }
      const double l = d.norm();
      if (l == 0.0) continue;  // u undefined: no force (as the library's element)
      const Vec3 u = d / l;
      const Vec3 f_a = -(k.stiffness * (l - k.rest_length) + k.damping * u.dot(relative_velocity)) * u;
      f_W_[k.a] += f_a;
      tau_B_[k.a] += k.point_a_B.cross(R_WB_[k.a].transpose() * f_a);
      if (k.b >= 0) {
        f_W_[k.b] -= f_a;
        tau_B_[k.b] -= k.point_b.cross(R_WB_[k.b].transpose() * f_a);
      }
    }
    // Newton–Euler per body; Euler's equations in principal axes: I1 ẇ1 = τ1 + (I2 − I3) w2 w3, and cyclic
    for (std::size_t b = 0; b < n_; ++b) {
      const double* s = y + 13 * b;
      double* ds = dy + 13 * b;
      const double *q = s + 3, *w = s + 10;
      const Vec3& I = c.inertia[b];
      const Vec3& inverse_I = inverse_inertia_[b];
      const Vec3& tau = tau_B_[b];
      for (int k = 0; k < 3; ++k) ds[k] = s[7 + k], ds[7 + k] = inverse_mass_[b] * f_W_[b][k];
      // q̇ = ½ q ⊗ (w_B, 0)
      ds[3] = 0.5 * (q[3] * w[0] + q[1] * w[2] - q[2] * w[1]);
      ds[4] = 0.5 * (q[3] * w[1] + q[2] * w[0] - q[0] * w[2]);
      ds[5] = 0.5 * (q[3] * w[2] + q[0] * w[1] - q[1] * w[0]);
      ds[6] = -0.5 * (q[0] * w[0] + q[1] * w[1] + q[2] * w[2]);
      ds[10] = inverse_I[0] * (tau[0] + (I[1] - I[2]) * w[1] * w[2]);
      ds[11] = inverse_I[1] * (tau[1] + (I[2] - I[0]) * w[2] * w[0]);
      ds[12] = inverse_I[2] * (tau[2] + (I[0] - I[1]) * w[0] * w[1]);
    }
  }

  SpringsDragChain chain_;
  std::size_t n_;
  std::vector<Eigen::Matrix3d> R_WB_;     // (N,) per evaluation
  std::vector<Eigen::Vector3d> f_W_;      // (N,) [N] per evaluation
  std::vector<Eigen::Vector3d> tau_B_;    // (N,) [N m] per evaluation
  std::vector<double> inverse_mass_;      // (N,) [1/kg]
  std::vector<Eigen::Vector3d> inverse_inertia_;  // (N,) [1/(kg m²)]
  std::vector<double> k1_, k2_, k3_, k4_, stage_;  // (13 N,)
};

}  // namespace rigiddyn::bench
