// The matching rules of `whirl compare` (modal/mode_compare.hpp) on hand-made tables: a name matches
// the nearest of the modes carrying it, rows sharing a name set are matched sorted against sorted,
// `*` takes the nearest frequency, a mode is used once, and a name left without a mode is missing.
#include <gtest/gtest.h>

#include "modal/mode_compare.hpp"

namespace whirl {
namespace {

const std::vector<NamedFrequency> kModes = {
    {"tower FA 1", 0.34}, {"tower SS 1", 0.31}, {"drivetrain", 1.70}, {"flap 1", 0.70}, {"flap 1", 0.65}};

TEST(ModeCompare, NameTakesTheNearestModeOfThatName) {
  const auto rows = compareModes(kModes, {{"1st flap", 0.66, "flap 1"}}, 0.05);
  ASSERT_TRUE(rows[0].match);
  EXPECT_EQ(rows[0].match->freq_hz, 0.65);
  EXPECT_NEAR(rows[0].rel_error, (0.65 - 0.66) / 0.66, 1e-15);
  EXPECT_TRUE(rows[0].ok);
}

TEST(ModeCompare, RowsSharingANameSetMatchSortedAgainstSorted) {
  // The reference lists the side-side mode first and the higher frequency first: the set is matched
  // by sorted frequency, whatever the names within it.
  const auto rows = compareModes(kModes, {{"FA", 0.33, "tower FA 1|tower SS 1"}, {"SS", 0.30, "tower FA 1|tower SS 1"}},
                                 0.05);
  EXPECT_EQ(rows[0].match->name, "tower FA 1");  // 0.33 ↔ the higher, 0.34
  EXPECT_EQ(rows[1].match->name, "tower SS 1");  // 0.30 ↔ the lower, 0.31
}

TEST(ModeCompare, StarNearestUsedOnceMissingAndTolerance) {
  const auto rows = compareModes(kModes, {{"drive", 1.60, "drivetrain"}, {"any", 1.69, "*"}, {"edge", 1.0, "edge 1"}},
                                 0.05);
  EXPECT_NEAR(rows[0].rel_error, 0.0625, 1e-12);  // (1.70 − 1.60)/1.60, beyond 5 %
  EXPECT_FALSE(rows[0].ok);
  EXPECT_NE(rows[1].match->name, "drivetrain");  // already used by the first row
  EXPECT_EQ(rows[1].match->freq_hz, 0.70);       // the nearest of the modes left
  EXPECT_FALSE(rows[2].match);
  EXPECT_FALSE(rows[2].ok);
}

}  // namespace
}  // namespace whirl
