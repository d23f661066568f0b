// add_body and find_body (scene/scene.hpp): names are unique ("body<i>" for an unnamed body), checked through
// the scene's name index, which stays right when the scene is copied or edited field by field.
#include <gtest/gtest.h>

#include "rigiddyn/scene/scene.hpp"

#include <optional>
#include <stdexcept>
#include <string>

namespace rigiddyn {
namespace {

// EXPECT_THAT(text, HasSubstr(part)) without gmock
#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

std::string clash(Scene& scene, const std::string& name) {
  try {
    add_body(scene, Particle(1.0), name);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SceneNames, BodiesAreNamedAndFoundByName) {
  Scene scene;
  EXPECT_EQ(add_body(scene, Particle(1.0), "sun"), 0u);
  EXPECT_EQ(add_body(scene, Particle(2.0)), 1u);  // "body1"
  EXPECT_EQ(add_body(scene, Particle(3.0), "body3"), 2u);
  EXPECT_EQ(find_body(scene, "sun"), std::optional<std::size_t>(0));
  EXPECT_EQ(find_body(scene, "body1"), std::optional<std::size_t>(1));
  EXPECT_EQ(find_body(scene, "body2"), std::nullopt);  // body 2 is named body3
  EXPECT_EQ(find_body(scene, "body3"), std::optional<std::size_t>(2));
  EXPECT_EQ(scene.body_names, (std::vector<std::string>{"sun", "", "body3"}));
  EXPECT_TRUE(scene.mass_flows.empty());
}

TEST(SceneNames, ATakenNameIsRefusedNamingItsBody) {
  Scene scene;
  add_body(scene, Particle(1.0), "sun");
  add_body(scene, Particle(1.0), "body2");
  EXPECT_EQ(clash(scene, "sun"),
            "name: expected a name no other body of the scene has ('sun' is body 0's), got \"sun\"");
  // body 2's default name is taken by body 1
  EXPECT_EQ(clash(scene, ""), "name: expected a name no other body of the scene has ('body2' is body 1's), got \"\"");
  EXPECT_EQ(scene.bodies.size(), 2u);  // a refused body is not added
}

TEST(SceneNames, TheIndexFollowsEditsFieldByField) {
  Scene scene;
  add_body(scene, Particle(1.0), "a");
  scene.bodies.push_back(Particle(1.0));  // added without add_body: named "b"
  scene.body_names.push_back("b");
  EXPECT_EQ(find_body(scene, "b"), std::optional<std::size_t>(1));
  EXPECT_CONTAINS(clash(scene, "b"), "('b' is body 1's)");
  scene.body_names[0] = "c";  // renamed in place: a stale hit is rebuilt
  EXPECT_EQ(find_body(scene, "a"), std::nullopt);
  EXPECT_EQ(find_body(scene, "c"), std::optional<std::size_t>(0));
  scene.bodies.pop_back();  // removed: the index starts again
  scene.body_names.pop_back();
  EXPECT_EQ(find_body(scene, "b"), std::nullopt);
  EXPECT_EQ(add_body(scene, Particle(1.0), "b"), 1u);
}

TEST(SceneNames, ACopyFindsTheNamesOfItsOwnBodies) {
  Scene scene;
  for (int i = 0; i < 10; ++i) add_body(scene, Particle(1.0), "p" + std::to_string(i));
  Scene copy = scene;
  add_body(copy, Particle(1.0), "p10");
  EXPECT_EQ(find_body(copy, "p7"), std::optional<std::size_t>(7));
  EXPECT_EQ(find_body(copy, "p10"), std::optional<std::size_t>(10));
  EXPECT_EQ(find_body(scene, "p10"), std::nullopt);
  copy = scene;  // assigned: the copy's index is dropped and refilled
  EXPECT_EQ(find_body(copy, "p10"), std::nullopt);
  EXPECT_EQ(find_body(copy, "p9"), std::optional<std::size_t>(9));
}

TEST(SceneNames, AMassFlowIsKeptPerBody) {
  Scene scene;
  add_body(scene, Particle(1.0));
  MassFlow flow;
  flow.rate = -0.1;
  add_body(scene, Particle(1.0), "rocket", flow);
  add_body(scene, Particle(1.0));
  ASSERT_EQ(scene.mass_flows.size(), 3u);
  EXPECT_FALSE(scene.mass_flows[0].has_value());
  EXPECT_EQ(scene.mass_flows[1]->rate, -0.1);
  EXPECT_FALSE(scene.mass_flows[2].has_value());
}

TEST(SceneNames, ManyBodiesAreAddedAndAllFound) {
  // 10^5 bodies: each add_body looks its name up in O(1), so this is 10^5 hash look-ups (comparing each
  // name with every body's would be 5e9 string comparisons)
  constexpr std::size_t n = 100000;
  Scene scene;
  for (std::size_t i = 0; i < n; ++i) add_body(scene, Particle(1.0), i % 2 ? "" : "named" + std::to_string(i));
  for (std::size_t i = 0; i < n; ++i) {
    const std::string name = i % 2 ? "body" + std::to_string(i) : "named" + std::to_string(i);
    ASSERT_EQ(find_body(scene, name), std::optional<std::size_t>(i)) << name;
  }
}

}  // namespace
}  // namespace rigiddyn
