// AeroDyn blade files: the NREL 5MW file (19 nodes, rows on lines 7–25, then a blank line, a comment and a
// stray 20th row that AeroDyn never reads), a v4/v5 layout with optional columns, and the malformed cases.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "src/io/openfast/aerodyn/aerodyn_blade_input.hpp"
#include "tests/unit/aero_test_util.hpp"

namespace {

using testing::HasSubstr;
using whirl::io::AeroDynBladeInput;
using whirl::io::readAeroDynBlade;
using whirl::test::AeroScratch;
using whirl::test::inputErrorMessage;

const std::string kBlade = "5MW_Baseline/NRELOffshrBsline5MW_AeroDyn_blade.dat";

TEST(AeroDynBladeInput, Nrel5mwBlade) {
  const AeroDynBladeInput b = readAeroDynBlade(whirl::test::aeroBladeFile());
  EXPECT_EQ(b.NumBlNds, 19);
  ASSERT_EQ(b.BlSpn.size(), 19u);
  EXPECT_DOUBLE_EQ(b.BlSpn.front(), 0.0);
  EXPECT_DOUBLE_EQ(b.BlSpn[1], 1.3667);
  EXPECT_DOUBLE_EQ(b.BlSpn.back(), 61.4999);  // 61.5 only in the stray 20th row
  EXPECT_DOUBLE_EQ(b.BlCrvAC[1], -8.1531745e-4);
  EXPECT_DOUBLE_EQ(b.BlSwpAC[1], -3.4468858e-3);
  EXPECT_TRUE(b.has_BlCrvAng);
  EXPECT_DOUBLE_EQ(b.BlCrvAng[5], 0.0);
  EXPECT_DOUBLE_EQ(b.BlTwist.front(), 13.308);
  EXPECT_DOUBLE_EQ(b.BlTwist.back(), 0.106);
  EXPECT_DOUBLE_EQ(b.BlChord.front(), 3.542);
  EXPECT_DOUBLE_EQ(b.BlChord[5], 4.652);
  EXPECT_DOUBLE_EQ(b.BlChord.back(), 1.419);
  EXPECT_EQ(b.BlAFID.front(), 1);
  EXPECT_EQ(b.BlAFID[3], 2);
  EXPECT_EQ(b.BlAFID.back(), 8);
  EXPECT_EQ(b.row_lines.front(), 7);
  EXPECT_EQ(b.row_lines.back(), 25);
}

TEST(AeroDynBladeInput, NewerLayoutWithOptionalColumnsInAnotherOrder) {
  // OpenFAST v4/v5: columns found by name; BlCrvAng absent (AeroDyn computes it); t_c, BlCb, BlCenBn
  // accepted and ignored.
  const std::string text =
      "------- AERODYN BLADE DEFINITION INPUT FILE -------------------------------------\n"
      "v5 layout\n"
      "======  Blade Properties =================================================================\n"
      "          3   NumBlNds           - Number of blade nodes used in the analysis (-)\n"
      "  BlSpn   BlChord   BlTwist   BlAFID   BlCrvAC   BlSwpAC   t_c   BlCb   BlCenBn\n"
      "   (m)      (m)      (deg)     (-)       (m)       (m)     (-)   (-)    (m)\n"
      "   0.0      3.5      13.3      1         0.0       0.0     1.0   0.0    0.0\n"
      "  30.0      3.0       6.5      2         0.1      -0.2     0.3   0.0    0.0\n"
      "  61.5      1.4       0.1      2         0.3      -0.1     0.2   0.0    0.0\n";
  whirl::test::ScratchDir dir;
  const AeroDynBladeInput b = readAeroDynBlade(dir.write("blade.dat", text));
  EXPECT_EQ(b.NumBlNds, 3);
  EXPECT_FALSE(b.has_BlCrvAng);
  // AeroDyn computes the curve from the mid-chord line's prebend (setCantAngle, AeroDyn_IO.f90): the
  // slope of the parabola through the three nodes' x = BlCrvAC + ¼ BlChord sin(BlTwist); values from
  // numpy (polyfit of degree 2, its derivative at each node, arctan in degrees).
  ASSERT_EQ(b.BlCrvAng.size(), 3u);
  EXPECT_NEAR(b.BlCrvAng[0], -0.14924018, 1e-8);
  EXPECT_NEAR(b.BlCrvAng[1], 0.08663102, 1e-8);
  EXPECT_NEAR(b.BlCrvAng[2], 0.33429249, 1e-8);
  EXPECT_EQ(b.BlChord, (std::vector<double>{3.5, 3.0, 1.4}));
  EXPECT_EQ(b.BlTwist, (std::vector<double>{13.3, 6.5, 0.1}));
  EXPECT_EQ(b.BlAFID, (std::vector<int>{1, 2, 2}));
  EXPECT_EQ(b.BlSwpAC, (std::vector<double>{0.0, -0.2, -0.1}));
}

/// The blade file in a scratch folder, edited; the error message of reading it, its path shown as "<file>".
std::string bladeError(const std::string& from, const std::string& to) {
  AeroScratch s;
  s.edit(kBlade, from, to);
  return whirl::test::withFilePlaceholder(inputErrorMessage([&] { readAeroDynBlade(s.path(kBlade)); }), s.path(kBlade));
}

TEST(AeroDynBladeInputErrors, RowCount) {
  EXPECT_EQ(bladeError("         19   NumBlNds", "         20   NumBlNds"),
            "<file>:26: NumBlNds: table has 19 rows, 20 expected: line 26 is not a row of numbers (truncated table?)");
  EXPECT_EQ(bladeError("         19   NumBlNds", "         18   NumBlNds"),
            "<file>:25: NumBlNds: table has 19 rows, only 18 expected");
  EXPECT_EQ(bladeError("         19   NumBlNds", "          1   NumBlNds"),
            "<file>:4: NumBlNds: must be at least 2 (is 1)");
}

TEST(AeroDynBladeInputErrors, SpanMustStartAtZeroAndIncrease) {
  EXPECT_EQ(bladeError("4.1000000E+00 -2.4839790E-02", "1.0000000E+00 -2.4839790E-02"),
            "<file>:9: BlSpn: must increase from node to node (1 after 1.3667)");
  EXPECT_EQ(bladeError("0.0000000E+00  0.0000000E+00  0.0000000E+00 0.0000000E+00  1.3308000E+01",
                       "1.0000000E-01  0.0000000E+00  0.0000000E+00 0.0000000E+00  1.3308000E+01"),
            "<file>:7: BlSpn: must start at 0 (is 0.1)");
}

TEST(AeroDynBladeInputErrors, ChordAirfoilIdAndNumbers) {
  EXPECT_EQ(bladeError("1.3308000E+01  3.5420000E+00        1", "1.3308000E+01  0.0000000E+00        1"),
            "<file>:7: BlChord: must be positive (is 0)");
  EXPECT_EQ(bladeError("1.4190000E+00        8", "1.4190000E+00        8.5"),
            "<file>:24: BlAFID: must be a whole number >= 1 (an index into AFNames), is 8.5");
  EXPECT_EQ(bladeError("1.3308000E+01  3.5420000E+00        1", "1.3308000E+01  3.5420000E+00        0"),
            "<file>:7: BlAFID: must be a whole number >= 1 (an index into AFNames), is 0");
  EXPECT_EQ(bladeError("1.3308000E+01  3.5420000E+00        1", "1.3308000E+01  NaN        1"),
            "<file>:7: BlChord: value is NaN");
  EXPECT_THAT(bladeError("BlChord          BlAFID", "BlChord          BlAirfoil"),
              HasSubstr("<file>:5: BlAFID: column missing from the table"));
}

TEST(AeroDynBladeInputErrors, MissingFile) {
  const std::filesystem::path f = whirl::test::aeroDir() / "no_blade.dat";
  EXPECT_EQ(inputErrorMessage([&] { readAeroDynBlade(f); }), f.string() + ": cannot open file");
}

}  // namespace
