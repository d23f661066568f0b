// The plain method a Lie-group method is on a scene whose bodies do not turn in 3D (scene/method_twins.hpp): rkmk4 is
// rk4 and exact_flow_kick is splitting_dlm on particles and planar bodies, pivoted or not, and neither is on a scene
// with a body that turns in 3D; the other methods have no twin.
#include "rigiddyn/scene/method_twins.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace rigiddyn {
namespace {

TEST(MethodTwins, ALieGroupMethodIsItsPlainFormWhereNoBodyTurnsIn3D) {
  const std::vector<Body> flat = {Particle(1.0), PlanarBody(2.0, 0.5),
                                  PivotedPlanarBody(2.0, 0.05, Eigen::Vector2d(0.0, -0.4))};
  EXPECT_EQ(plain_twin(Method::rkmk4, flat), Method::rk4);
  EXPECT_EQ(plain_twin(Method::exact_flow_kick, flat), Method::splitting_dlm);
  for (const Method m : {Method::rk4, Method::splitting_dlm, Method::splitting_dlm_yoshida4, Method::exact,
                         Method::semi_implicit_euler_implicit_gyroscopic, Method::implicit_midpoint}) {
    EXPECT_FALSE(plain_twin(m, flat).has_value()) << method_info(m).name;
  }
  const RigidBody rigid(1.0, Eigen::Vector3d(1.0, 2.0, 3.0));
  for (const Body& turning : {Body(rigid), Body(PivotedBody(rigid, Eigen::Vector3d(0.0, 0.0, 0.5)))}) {
    std::vector<Body> bodies = flat;
    bodies.push_back(turning);
    EXPECT_FALSE(plain_twin(Method::rkmk4, bodies).has_value());
    EXPECT_FALSE(plain_twin(Method::exact_flow_kick, bodies).has_value());
  }
}

}  // namespace
}  // namespace rigiddyn
