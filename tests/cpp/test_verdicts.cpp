// The verdicts of an estimate's records (simulate/verdicts.hpp): each record reads the text it was given, equal
// texts are stored once, whatever order they come in.
#include "rigiddyn/simulate/verdicts.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace rigiddyn {
namespace {

TEST(Verdicts, EachRecordReadsTheTextItWasGiven) {
  Verdicts v{"reliable", "interpolated", "interpolated", "reliable", "not asymptotic"};
  ASSERT_EQ(v.size(), 5u);
  EXPECT_EQ(v[0], "reliable");
  EXPECT_EQ(v[1], "interpolated");
  EXPECT_EQ(v[2], "interpolated");
  EXPECT_EQ(v[3], "reliable");
  EXPECT_EQ(v[4], "not asymptotic");
}

TEST(Verdicts, EqualTextsAreStoredOnceAndShareTheirIndex) {
  Verdicts v{"reliable", "interpolated", "interpolated", "reliable", "interpolated", "not asymptotic", "reliable"};
  EXPECT_EQ(v.texts().size(), 3u);
  EXPECT_EQ(v.text_index(0), v.text_index(3));
  EXPECT_EQ(v.text_index(0), v.text_index(6));
  EXPECT_EQ(v.text_index(1), v.text_index(4));
  EXPECT_NE(v.text_index(0), v.text_index(1));
  EXPECT_EQ(v.texts()[v.text_index(5)], "not asymptotic");
}

// Texts that differ in one character (a number in the text) are distinct; many of them, then the first again.
TEST(Verdicts, ManyDistinctTextsEachKeepTheirOwn) {
  Verdicts v;
  for (int k = 0; k < 300; ++k) v.push_back("observed order " + std::to_string(k));
  v.push_back("observed order 7");
  ASSERT_EQ(v.size(), 301u);
  EXPECT_EQ(v.texts().size(), 300u);
  for (int k = 0; k < 300; ++k) EXPECT_EQ(v[static_cast<std::size_t>(k)], "observed order " + std::to_string(k));
  EXPECT_EQ(v.text_index(300), v.text_index(7));
}

TEST(Verdicts, SetAndAssignReplaceRecordsTexts) {
  Verdicts v;
  v.assign(4, "reliable");
  v.set(2, "step beyond the stability limit");
  EXPECT_EQ(v[1], "reliable");
  EXPECT_EQ(v[2], "step beyond the stability limit");
  EXPECT_EQ(v[3], "reliable");
  const std::uint32_t k = v.add_text("interpolated");
  v.push_back_text(k);
  EXPECT_EQ(v[4], "interpolated");
  EXPECT_EQ(v.add_text("reliable"), v.text_index(0));
  EXPECT_TRUE(is_reliable(v[0]));
  EXPECT_FALSE(is_reliable(v[4]));
  EXPECT_FALSE(is_reliable("reliable "));
  EXPECT_THROW(v.push_back_text(static_cast<std::uint32_t>(v.texts().size())), std::out_of_range);
  EXPECT_EQ(v.size(), 5u);  // the bad index appended nothing
  v.set_text(1, k);
  EXPECT_EQ(v[1], "interpolated");
  EXPECT_THROW(v.set_text(1, static_cast<std::uint32_t>(v.texts().size())), std::out_of_range);
  EXPECT_EQ(v[1], "interpolated");  // the bad index changed nothing
}

}  // namespace
}  // namespace rigiddyn
