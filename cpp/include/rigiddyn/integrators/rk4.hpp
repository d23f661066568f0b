// Classical Runge–Kutta 4 on the coordinates (the quaternion as a 4-vector), then the quaternion
// renormalised. Order 4 (attitude included, as a projected method); 4 derivative evaluations per
// step. Conserves nothing exactly: on a free body energy and |L| drift by O(h⁴) per unit time;
// unstable once h·2π/T_ω exceeds about 2.8.
//
// Butcher tableau (named constants, MuJoCo style):
//   c = (0, 1/2, 1/2, 1),  a21 = 1/2, a32 = 1/2, a43 = 1,  b = (1/6, 1/3, 1/3, 1/6).
#pragma once
#include "rigiddyn/integrators/workspace.hpp"
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

// out = y + a k, element by element. A plain loop rather than an Eigen expression: Eigen's 2-wide
// packets at odd offsets reload values just written as scalars by Model::rate (a store-forwarding stall
// that measured 2-15x slower per step than a hand-written loop).
template <class Vector>
RIGIDDYN_ALWAYS_INLINE void axpy(const Vector& y, double a, const Vector& k, Vector& out) {
  for (Eigen::Index i = 0; i < y.size(); ++i) out[i] = y[i] + a * k[i];
}

// out = a k, element by element (see axpy).
template <class Vector>
RIGIDDYN_ALWAYS_INLINE void scaled(double a, const Vector& k, Vector& out) {
  for (Eigen::Index i = 0; i < k.size(); ++i) out[i] = a * k[i];
}

struct Rk4 {
  // the four rates k1 … k4 and the stage state
  template <class Model>
  struct Workspace {
    typename Model::Coordinates k1, k2, k3, k4, stage;
    Workspace(const Model& /*model*/, const typename Model::Coordinates& y)
        : k1(y.size()), k2(y.size()), k3(y.size()), k4(y.size()), stage(y.size()) {}
  };

  template <class Model>
  RIGIDDYN_ALWAYS_INLINE static void step(const Model& model, typename Model::Coordinates& y, double h,
                                          Workspace<Model>& w) {
    using namespace rk4_tableau;
    model.rate(y, w.k1);
    axpy(y, a21 * h, w.k1, w.stage);
    model.rate(w.stage, w.k2);
    axpy(y, a32 * h, w.k2, w.stage);
    model.rate(w.stage, w.k3);
    axpy(y, a43 * h, w.k3, w.stage);
    model.rate(w.stage, w.k4);
    // y += h (b1 k1 + b2 k2 + b3 k3 + b4 k4) written as h/6 (k1 + 2 k2 + 2 k3 + k4): 6 operations per
    // entry instead of 9 (b = (1, 2, 2, 1)/6; the same value to a rounding)
    const double h_6 = h / 6.0;
    for (Eigen::Index i = 0; i < y.size(); ++i) y[i] += h_6 * (w.k1[i] + 2.0 * w.k2[i] + 2.0 * w.k3[i] + w.k4[i]);
    model.project(y);
  }
};

}  // namespace rigiddyn
