// The scratch vectors of a method's step (its stages, rates and tangents), sized once for a model and a
// state when a run starts and reused by every step: no step and no evaluation allocates, whatever the
// size of the model (a scene's Coordinates are Eigen::VectorXd). Each integrator names its own,
//   template <class Model> struct Workspace { Workspace(const Model&, const typename Model::Coordinates& y); };
// (NoWorkspace for the methods that work on y in place), and its step takes it:
//   static void step(const Model&, typename Model::Coordinates& y, double h, Workspace<Model>&).
// The run loop (simulate/run_loop.hpp) owns one per run, as MuJoCo takes RK4's stages from mjData's arena.
#pragma once
#include <Eigen/Core>

namespace rigiddyn {

// The workspace of a method that needs none (the splittings and the Euler kick–drift methods).
struct NoWorkspace {
  template <class Model, class Coordinates>
  NoWorkspace(const Model& /*model*/, const Coordinates& /*y*/) {}
};

template <class Integrator, class Model>
using Workspace = typename Integrator::template Workspace<Model>;

// The workspace of Integrator for `model` at a state of y's size (a run's own, or a one-off step's).
template <class Integrator, class Model>
Workspace<Integrator, Model> workspace(const Model& model, const typename Model::Coordinates& y) {
  return Workspace<Integrator, Model>(model, y);
}

// True for a model whose Coordinates are a fixed-size vector (the one-body and fast models).
template <class Model>
inline constexpr bool has_fixed_size = Model::Coordinates::RowsAtCompileTime != Eigen::Dynamic;

// A tangent vector of the model's size (uninitialised): Model::tangent_count() for a dynamic-size model.
template <class Model>
typename Model::Tangent new_tangent(const Model& model) {
  using Tangent = typename Model::Tangent;
  if constexpr (Tangent::RowsAtCompileTime == Eigen::Dynamic) {
    return Tangent(model.tangent_count());
  } else {
    return Tangent();
  }
}

}  // namespace rigiddyn
