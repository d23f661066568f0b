// Hand-written baseline loops shared by several C++ benchmarks (plain Eigen, no rigiddyn code), so
// that every "<case>:baseline" measuring the same work is the same loop.
#pragma once
#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigiddyn::bench {

// One free rigid body as y = (ω [rad/s] in B, q_WB as (x, y, z, w)): a 7-vector.
using FreeBodyY = Eigen::Matrix<double, 7, 1>;

// n steps of size h [s] of classic RK4 on Euler's equations and quaternion kinematics for a free
// body with principal moments I [kg m²] (3), from ω0 [rad/s] (3, in B) and q_WB = identity:
//   ω̇ = I⁻¹((I ω) × ω),  q̇ = q ⊗ (0, ω)/2  (Craig, Euler's equations; Rigid-body notes, quaternion kinematics),
// q renormalised after every step. Returns the final y.
inline FreeBodyY rk4_free_body_baseline(const Eigen::Vector3d& I, const Eigen::Vector3d& w0, double h,
                                        std::int64_t n) {
  const Eigen::Vector3d I_inv = I.cwiseInverse();
  const auto f = [&](const FreeBodyY& y) {
    const Eigen::Vector3d w = y.head<3>();
    const Eigen::Quaterniond q(y(6), y(3), y(4), y(5));
    FreeBodyY d;
    d.head<3>() = I_inv.cwiseProduct(I.cwiseProduct(w).cross(w));
    const Eigen::Quaterniond q_dot = q * Eigen::Quaterniond(0.0, 0.5 * w.x(), 0.5 * w.y(), 0.5 * w.z());
    d.segment<3>(3) = q_dot.vec();
    d(6) = q_dot.w();
    return d;
  };
  FreeBodyY y;
  y << w0, 0.0, 0.0, 0.0, 1.0;
  for (std::int64_t i = 0; i < n; ++i) {
    const FreeBodyY k1 = f(y);
    const FreeBodyY k2 = f(y + 0.5 * h * k1);
    const FreeBodyY k3 = f(y + 0.5 * h * k2);
    const FreeBodyY k4 = f(y + h * k3);
    y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    y.tail<4>().normalize();
  }
  return y;
}

}  // namespace rigiddyn::bench
