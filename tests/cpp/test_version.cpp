#include <gtest/gtest.h>

#include "rigiddyn/check.hpp"
#include "rigiddyn/version.hpp"

TEST(Version, IsSemantic) { EXPECT_EQ(rigiddyn::version(), "0.1.0"); }

TEST(Check, RequireFiniteNamesTheArgument) {
  Eigen::Vector3d v(1.0, std::nan(""), 0.0);
  try {
    rigiddyn::require_finite(v, "w_B");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("w_B: expected finite values"), std::string::npos) << e.what();
  }
}
