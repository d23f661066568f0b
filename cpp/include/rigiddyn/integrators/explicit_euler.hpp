// Explicit (forward) Euler: y1 = y0 + h ẏ(y0), then the quaternion is renormalised.
// Order 1; 1 derivative evaluation per step. Conserves nothing of the dynamics: on a free rigid
// body |L|² and the energy grow every step (the map is expansive), so it blows up; kept as the
// textbook reference. Unit |q| holds only through the renormalisation.
#pragma once
#include "rigiddyn/integrators/workspace.hpp"
#include "rigiddyn/models/model_interface.hpp"  // RIGIDDYN_ALWAYS_INLINE

namespace rigiddyn {

struct ExplicitEuler {
  // the rate ẏ
  template <class Model>
  struct Workspace {
    typename Model::Coordinates dy;
    Workspace(const Model& /*model*/, const typename Model::Coordinates& y) : dy(y.size()) {}
  };

  template <class Model>
  RIGIDDYN_ALWAYS_INLINE static void step(const Model& model, typename Model::Coordinates& y, double h,
                                          Workspace<Model>& w) {
    model.rate(y, w.dy);
    for (Eigen::Index i = 0; i < y.size(); ++i) y[i] += h * w.dy[i];  // element by element: see rk4.hpp's axpy
    model.project(y);
  }
};

}  // namespace rigiddyn
