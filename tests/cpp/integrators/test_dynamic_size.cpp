// Every integrator runs on a model whose Coordinates and Tangent are Eigen::VectorXd (a scene:
// the integrators are written once for the fixed-size one-body layouts and SceneModel). The test model
// wraps a one-body layout (scene/one_body_layouts.hpp): each member converts y to the fixed size, calls the wrapped
// member and converts back, so the model arithmetic is the wrapped model's and only the integrators'
// own work (stage sums, copies, the fixed-point iteration, the loads_kick/free_flow compositions)
// runs on dynamic-size vectors. A run must then equal the fixed-size run bitwise, for every method.
#include "rigiddyn/integrators/implicit_midpoint.hpp"
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/scene/one_body_scene.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <type_traits>

namespace {

using namespace rigiddyn;

// The model interface (models/model_interface.hpp) of `Fixed` on Eigen::VectorXd.
template <class Fixed>
class DynamicSize {
 public:
  using Coordinates = Eigen::VectorXd;
  using Tangent = Eigen::VectorXd;

  explicit DynamicSize(const Fixed& model) : model_(model) {}

  Eigen::Index tangent_count() const { return typename Fixed::Tangent().size(); }
  Eigen::Index time_index() const { return model_.time_index(); }  // the implicit midpoint's stopping test reads it
  void rate(const Coordinates& y, Coordinates& dy) const {
    apply_as<typename Fixed::Coordinates>(dy, [&](auto& f) { model_.rate(fixed(y), f); });
  }
  void project(Coordinates& y) const { apply(y, [&](auto& f) { model_.project(f); }); }
  void velocity(const Coordinates& y, Tangent& xi) const {
    apply_as<typename Fixed::Tangent>(xi, [&](auto& f) { model_.velocity(fixed(y), f); });
  }
  void retract(const Coordinates& y, const Tangent& theta, Coordinates& out) const {
    apply_as<typename Fixed::Coordinates>(out, [&](auto& f) { model_.retract(fixed(y), fixed_tangent(theta), f); });
  }
  void velocity_at(const Coordinates& y, const Tangent& theta, Tangent& xi) const {
    apply_as<typename Fixed::Tangent>(xi, [&](auto& f) { model_.velocity_at(fixed(y), fixed_tangent(theta), f); });
  }
  void dexp_inv(const Tangent& theta, Tangent& xi) const {
    apply_as<typename Fixed::Tangent>(xi, [&](auto& f) { model_.dexp_inv(fixed_tangent(theta), f); });
  }
  void kick(Coordinates& y, double h) const { apply(y, [&](auto& f) { model_.kick(f, h); }); }
  void kick_implicit_gyroscopic(Coordinates& y, double h) const { apply(y, [&](auto& f) { model_.kick_implicit_gyroscopic(f, h); }); }
  void drift(Coordinates& y, double h) const { apply(y, [&](auto& f) { model_.drift(f, h); }); }
  double loads_kick(Coordinates& y, double h) const {
    double kicked = 0.0;
    apply(y, [&](auto& f) { kicked = model_.loads_kick(f, h); });
    return kicked;
  }
  template <class Rotation>
  void free_flow(Coordinates& y, double h) const {
    apply(y, [&](auto& f) { model_.template free_flow<Rotation>(f, h); });
  }
  // the implicit midpoint's correction of each iterate (a layout has it; its slot may leave the iterate as it is)
  void midpoint_newton(const Coordinates& y0, const Coordinates& mid, Coordinates& next, double h) const {
    apply(next, [&](auto& f) { model_.midpoint_newton(fixed(y0), fixed(mid), f, h); });
  }

 private:
  static typename Fixed::Coordinates fixed(const Coordinates& y) {
    EXPECT_EQ(y.size(), typename Fixed::Coordinates().size());
    return y;
  }
  static typename Fixed::Tangent fixed_tangent(const Tangent& x) {
    EXPECT_EQ(x.size(), typename Fixed::Tangent().size());
    return x;
  }
  // x ← f(x) on a fixed-size copy of x, of type Vector (Fixed's Coordinates or Tangent)
  template <class Vector, class F>
  static void apply_as(Eigen::VectorXd& x, F&& f) {
    EXPECT_EQ(x.size(), Vector().size());
    Vector x_fixed = x;
    f(x_fixed);
    x = x_fixed;
  }
  template <class F>
  static void apply(Coordinates& y, F&& f) { apply_as<typename Fixed::Coordinates>(y, f); }
  Fixed model_;
};

// n steps of Integrator from y0 on `model`; the message of the first exception (ExactFreeFlow under a torque)
template <class Integrator, class Model>
std::string run(const Model& model, typename Model::Coordinates& y, int n, double h) {
  try {
    auto work = workspace<Integrator>(model, y);
    for (int k = 0; k < n; ++k) Integrator::step(model, y, h, work);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

template <class Fixed>
void expect_dynamic_equals_fixed(const Fixed& model, const typename Fixed::Coordinates& y0, const std::string& name) {
  for (const MethodInfo& info : method_table()) {
    visit_method(info.method, [&](auto integrator) {
      using Integrator = decltype(integrator);
      typename Fixed::Coordinates y_fixed = y0;
      Eigen::VectorXd y_dynamic = y0;
      const std::string fixed_error = run<Integrator>(model, y_fixed, 50, 0.02);
      const std::string dynamic_error = run<Integrator>(DynamicSize<Fixed>(model), y_dynamic, 50, 0.02);
      EXPECT_EQ(fixed_error, dynamic_error) << name << ' ' << info.name;
      ASSERT_EQ(y_dynamic.size(), y_fixed.size());
      // bitwise: the same arithmetic in the same order on both (see the top of this file)
      for (Eigen::Index i = 0; i < y_fixed.size(); ++i) EXPECT_EQ(y_dynamic[i], y_fixed[i]) << name << ' ' << info.name << " y[" << i << ']';
      if (fixed_error.empty()) {
        EXPECT_NE(y_fixed, y0) << name << ' ' << info.name;  // it moved
      } else {                                               // 'exact' refused a torque at the first step
        EXPECT_EQ(y_fixed, y0) << name << ' ' << info.name;
      }
    });
  }
}

// Loads in both frames, forces and (with torque) torques, the second switching on inside the run (t = 0.37 s)
std::vector<AppliedLoad> some_loads(bool torque) {
  AppliedLoad world, body;
  world.force = Eigen::Vector3d(0.7, -1.3, 2.1);
  body.frame = Frame::body, body.force = Eigen::Vector3d(-0.4, 0.9, 0.5), body.t_start = 0.37;
  if (torque) world.torque = Eigen::Vector3d(-0.1, 0.45, -0.25), body.torque = Eigen::Vector3d(0.3, -0.2, 0.35);
  return {world, body};
}

template <class Layout>
void expect_layout(const Body& body, const BodyState& state, const Eigen::Vector3d& g_W, bool torque,
                   const std::string& name) {
  const Layout layout = one_body_layout_as<Layout>(body, g_W, some_loads(torque), 0.5);
  expect_dynamic_equals_fixed(layout, layout.coordinates({state}, 0.5), name);
}

template <class Slot>
using LoadedLayout = OneBodySceneModel<Slot, OneBodyElements::gravity_and_loads>;
static_assert(has_midpoint_newton<DynamicSize<LoadedLayout<detail::RigidSlot<FullEuler, detail::FirstPlace>>>>::value);

RigidBodyState rigid_state() {
  RigidBodyState s;
  s.p_W = Eigen::Vector3d(0.1, -0.2, 0.3);
  s.q_WB = Eigen::Quaterniond(0.9, 0.1, 0.2, 0.3).normalized();
  s.v_W = Eigen::Vector3d(1.0, -0.5, 2.0);
  s.w_B = Eigen::Vector3d(0.3, 2.0, -0.7);
  return s;
}

template <class Euler>
void expect_rigid(const RigidBody& body, const std::string& name) {
  using Layout = LoadedLayout<detail::RigidSlot<Euler, detail::FirstPlace>>;
  for (const bool torque : {false, true}) {
    expect_layout<Layout>(body, rigid_state(), Eigen::Vector3d(0.0, 0.0, -9.81), torque,
                          name + (torque ? " with torques" : " forces only"));
  }
}

TEST(DynamicSize, ParticleStepsAsItsLayout) {
  ParticleState s{Eigen::Vector3d(0.1, -0.2, 0.3), Eigen::Vector3d(1.0, -0.5, 2.0)};
  expect_layout<LoadedLayout<detail::ParticleSlot<detail::FirstPlace>>>(Particle(2.0), s, Eigen::Vector3d(0.0, 0.0, -9.81),
                                                                       false, "particle");
}

TEST(DynamicSize, PlanarBodyStepsAsItsLayout) {
  // in-plane forces and torques about z only (what a planar body takes)
  AppliedLoad world, body;
  world.force = Eigen::Vector3d(0.7, -1.3, 0.0), world.torque = Eigen::Vector3d(0.0, 0.0, 0.45);
  body.frame = Frame::body, body.force = Eigen::Vector3d(-0.4, 0.9, 0.0), body.torque = Eigen::Vector3d(0.0, 0.0, -0.2);
  body.t_start = 0.37;
  using Layout = LoadedLayout<detail::PlanarSlot<detail::FirstPlace>>;
  const Layout layout = one_body_layout_as<Layout>(PlanarBody(2.0, 0.6), Eigen::Vector3d(0.0, -9.81, 0.0), {world, body}, 0.5);
  PlanarBodyState s{Eigen::Vector2d(0.1, -0.2), 0.4, Eigen::Vector2d(1.0, -0.5), 1.7};
  expect_dynamic_equals_fixed(layout, layout.coordinates({s}, 0.5), "planar body");
}

TEST(DynamicSize, RigidBodyStepsAsItsLayoutInEveryEulerForm) {
  Eigen::Matrix3d full;
  full << 1.1, 0.12, -0.05, 0.12, 2.3, 0.08, -0.05, 0.08, 2.9;
  expect_rigid<SphericalEuler>(RigidBody(1.5, Eigen::Vector3d(0.8, 0.8, 0.8)), "sphere");
  expect_rigid<PrincipalEuler>(RigidBody(1.5, Eigen::Vector3d(1.1, 2.3, 2.9)), "principal");
  expect_rigid<FullEuler>(RigidBody(1.5, full), "full");
}

}  // namespace
