// A scene for the estimate's tests: three rigid bodies under gravity and drag, linked to each other and to a world
// anchor by springs attached off their centres of mass (the generic model: works and impulses integrated, so that the
// energy balance is checked), and their states.
#pragma once
#include "rigiddyn/scene/scene.hpp"

#include <utility>
#include <vector>

namespace rigiddyn::test {

inline std::pair<Scene, std::vector<BodyState>> linked_bodies() {
  Scene scene;
  std::vector<BodyState> states;
  for (int i = 0; i < 3; ++i) {
    scene.bodies.emplace_back(RigidBody(1.0 + 0.5 * i, Eigen::Vector3d(1.0, 2.0, 3.0)));
    RigidBodyState s;
    s.p_W = Eigen::Vector3d(1.0 * i, 0.1 * i, 0.0);
    s.v_W = Eigen::Vector3d(0.0, 0.2, 0.1 * i);
    s.w_B = Eigen::Vector3d(0.1, 1.0 - 0.2 * i, 0.1);
    states.emplace_back(s);
  }
  scene.elements.emplace_back(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}});
  Drag drag;
  drag.linear = 0.1, drag.angular_linear = 0.05;
  scene.elements.emplace_back(drag);
  for (int i = 0; i < 3; ++i) {
    SpringDamper spring;
    spring.body_a = i, spring.point_a_B = Eigen::Vector3d(0.1, 0.0, 0.05);
    spring.body_b = i == 0 ? -1 : i - 1, spring.point_b = Eigen::Vector3d(0.0, 0.1, 0.0);
    spring.stiffness = 20.0, spring.rest_length = 0.8, spring.damping = 0.3;
    scene.elements.emplace_back(spring);
  }
  return {scene, states};
}

}  // namespace rigiddyn::test
