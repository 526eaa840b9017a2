// Decks in OpenFAST's current syntax (issue 41, item 4) give the results of the old-syntax decks they
// were written from: tests/data/openfast/v5_syntax is cases/nrel5mw/Main_Aero.fst in the OpenFAST v5
// layout (the .fst's ModCoupling/NRotors/CompSeaSt/MirrorRotor/SeaStFile/SoilFile lines and DT_Out
// "default", ElastoDyn's PitchDOF/PtfmRefxt/PBrIner/BlPIner/yaw-friction block, AeroDyn's Wake_Mod,
// BEM_Mod, Skew_Mod with SkewRedistr_Mod and SkewRedistrFactor "default", sector averaging, UA_Mod,
// AFTabMod = 3, nacelle drag keys, InflowWind's VFlowAng "default", ServoDyn's PitNeut/PitSpr/PitDamp);
// tests/data/openfast/v4_seastate is cases/oc3_hywind/Test24.fst in the v4 layout (a SeaState file with
// the water properties "default", i.e. the .fst's; HydroDyn without water properties, waves and current,
// AddF0 as a column of six lines). README.md of tests/data/openfast says how they were made.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;

TEST(CliCurrentSyntax, OpenFastV5DeckGivesTheModesOfTheOldDeck) {
  const std::string opts = " --rpm 9 --format csv";
  const auto old_deck = test::whirl("modes cases/nrel5mw/Main_Aero.fst" + opts);
  const auto v5 = test::whirl("modes tests/data/openfast/v5_syntax/Main_v5.fst" + opts);
  ASSERT_EQ(old_deck.code, 0) << old_deck.err;
  ASSERT_EQ(v5.code, 0) << v5.err;
  EXPECT_EQ(v5.out, old_deck.out);
  EXPECT_EQ(v5.err, old_deck.err);
}

TEST(CliCurrentSyntax, SeaStateDeckGivesThePlatformModesOfTheOldDeck) {
  const std::string opts = " --set CompAero=0 --set RotSpeed=0 --set GenDOF=False --format csv";
  const auto old_deck = test::whirl("modes cases/oc3_hywind/Test24.fst --set RdtnMod=0" + opts);
  const auto v4 = test::whirl("modes tests/data/openfast/v4_seastate/Test24_v4.fst" + opts);
  ASSERT_EQ(old_deck.code, 0) << old_deck.err;
  ASSERT_EQ(v4.code, 0) << v4.err;
  EXPECT_EQ(v4.out, old_deck.out);
  // The waves are SeaState's now, and noted there.
  EXPECT_THAT(v4.err, HasSubstr("SeaState.dat:16: WaveMod: incident waves ignored"));
}

}  // namespace
}  // namespace whirl
