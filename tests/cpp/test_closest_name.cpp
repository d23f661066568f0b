// closest_name: the known name at the smallest edit distance, within a third of the longer name.
#include "rigiddyn/closest_name.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rigiddyn {
namespace {

const std::vector<std::string> methods = {"explicit_euler", "semi_implicit_euler", "rk4", "rkmk4",
                                          "splitting_dlm", "splitting_dlm_yoshida4", "exact"};

TEST(ClosestName, OneEditAwayIsFound) {
  EXPECT_EQ(closest_name("rk5", methods), "rk4");        // substitution
  EXPECT_EQ(closest_name("rk", methods), "rk4");         // deletion (1 <= max(1, 3 / 3))
  EXPECT_EQ(closest_name("exactt", methods), "exact");   // insertion
  EXPECT_EQ(closest_name("RK4", methods), "rk4");        // case is not an edit
  EXPECT_EQ(closest_name("spliting_dlm", methods), "splitting_dlm");
}

TEST(ClosestName, TheNearestWinsAndTiesGoToTheFirst) {
  EXPECT_EQ(closest_name("rkmk", methods), "rkmk4");  // distance 1 to rkmk4, 2 to rk4
  EXPECT_EQ(closest_name("ab", {"ac", "ad"}), "ac");  // both at distance 1
}

TEST(ClosestName, NothingCloseGivesNothing) {
  EXPECT_EQ(closest_name("verlet", methods), "");
  EXPECT_EQ(closest_name("", methods), "");
  EXPECT_EQ(closest_name("rk4", {}), "");
  EXPECT_EQ(did_you_mean("verlet", methods), "");
}

TEST(ClosestName, TheHintQuotesTheName) {
  EXPECT_EQ(did_you_mean("rk44", methods), " (did you mean 'rk4'?)");
}

}  // namespace
}  // namespace rigiddyn
