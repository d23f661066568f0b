// Classical Runge–Kutta 4 on the coordinates (the quaternion as a 4-vector), then the quaternion
// renormalised. Order 4 (attitude included, as a projected method); 4 derivative evaluations per
// step. Conserves nothing exactly: on a free body energy and |L| drift by O(h⁴) per unit time;
// unstable once h·2π/T_ω exceeds about 2.8.
//
// Butcher tableau (named constants, MuJoCo style):
//   c = (0, 1/2, 1/2, 1),  a21 = 1/2, a32 = 1/2, a43 = 1,  b = (1/6, 1/3, 1/3, 1/6).
#pragma once
#include "rigiddyn/models/model_interface.hpp"  // RIGIDDYN_ALWAYS_INLINE
#include <Eigen/Core>

namespace rigiddyn {

namespace rk4_tableau {
inline constexpr double a21 = 0.5;
inline constexpr double a32 = 0.5;
inline constexpr double a43 = 1.0;
inline constexpr double b1 = 1.0 / 6.0;
inline constexpr double b2 = 1.0 / 3.0;
inline constexpr double b3 = 1.0 / 3.0;
inline constexpr double b4 = 1.0 / 6.0;
}  // namespace rk4_tableau

// y + a k, element by element. A plain loop rather than an Eigen expression: Eigen's 2-wide packets
// at odd offsets reload values just written as scalars by Model::rate (a store-forwarding stall that
// measured 2-15x slower per step than a hand-written loop).
template <class Vector>
Vector axpy(const Vector& y, double a, const Vector& k) {
  Vector out(y.size());  // sized from y: fixed-size and dynamic-size (Eigen::VectorXd) models alike
  for (Eigen::Index i = 0; i < y.size(); ++i) out[i] = y[i] + a * k[i];
  return out;
}

// a k, element by element (see axpy).
template <class Vector>
Vector scaled(double a, const Vector& k) {
  Vector out(k.size());
  for (Eigen::Index i = 0; i < k.size(); ++i) out[i] = a * k[i];
  return out;
}

struct Rk4 {
  template <class Model>
  RIGIDDYN_ALWAYS_INLINE static void step(const Model& model, typename Model::Coordinates& y, double h) {
    using namespace rk4_tableau;
    using Coordinates = typename Model::Coordinates;
    const Coordinates k1 = model.rate(y);
    const Coordinates k2 = model.rate(axpy(y, a21 * h, k1));
    const Coordinates k3 = model.rate(axpy(y, a32 * h, k2));
    const Coordinates k4 = model.rate(axpy(y, a43 * h, k3));
    // y += h (b1 k1 + b2 k2 + b3 k3 + b4 k4) written as h/6 (k1 + 2 k2 + 2 k3 + k4): 6 operations per
    // entry instead of 9 (b = (1, 2, 2, 1)/6; the same value to a rounding)
    const double h_6 = h / 6.0;
    for (Eigen::Index i = 0; i < y.size(); ++i) y[i] += h_6 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    model.project(y);
  }
};

}  // namespace rigiddyn
