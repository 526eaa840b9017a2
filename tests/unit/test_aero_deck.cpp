// readAeroDeck: the aerodynamic inputs of the toolbox (OpenFAST v3) and v5 decks in one call, the module
// switches it refuses, missing files named with the line that names them, BlAFID beyond NumAFfiles, and
// overrides. Line numbers: toolbox Main.fst CompInflow 14, CompAero 15, InflowFile 37, AeroFile 38;
// toolbox AeroDyn.dat NumAFfiles 49, AFNames 50–57, ADBlFile(1) 60.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "src/io/openfast/aerodyn/aero_deck.hpp"
#include "src/io/openfast/openfast_overrides.hpp"
#include "tests/unit/aero_test_util.hpp"

namespace {

using testing::HasSubstr;
using whirl::io::AeroDeckInput;
using whirl::io::readAeroDeck;
using whirl::io::readFst;
using whirl::test::aeroDir;
using whirl::test::AeroScratch;
using whirl::test::inputErrorMessage;

void expectNrel5mwDeck(const AeroDeckInput& d) {
  ASSERT_EQ(d.blades.size(), 3u);
  for (const auto& b : d.blades) {
    EXPECT_EQ(b.NumBlNds, 19);
    EXPECT_DOUBLE_EQ(b.BlSpn.back(), 61.4999);
  }
  ASSERT_EQ(d.airfoils.size(), 8u);
  const char* names[] = {"Cylinder1", "Cylinder2", "DU40_A17", "DU35_A17",
                         "DU30_A17",  "DU25_A17",  "DU21_A17", "NACA64_A17"};
  for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(d.airfoils[i].name, names[i]);
  EXPECT_EQ(d.airfoils[6].tables[0].alpha_deg.size(), 142u);
  EXPECT_EQ(d.airfoils[7].tables[0].cm.size(), 127u);  // InCol_Cm = 4
  EXPECT_DOUBLE_EQ(d.inflow.HWindSpeed, 8.0);
  EXPECT_DOUBLE_EQ(d.aerodyn.AirDens, 1.225);
  EXPECT_TRUE(d.aerodyn.frozen_wake);
}

TEST(AeroDeck, ToolboxOpenFast3Deck) {
  const AeroDeckInput d = readAeroDeck(readFst(aeroDir() / "toolbox" / "Main.fst"));
  expectNrel5mwDeck(d);
  EXPECT_EQ(d.aerodyn.layout, whirl::io::AeroDynLayout::V15);
}

TEST(AeroDeck, OpenFast5Deck) {
  const AeroDeckInput d = readAeroDeck(readFst(aeroDir() / "v5" / "main.fst"));
  expectNrel5mwDeck(d);
  EXPECT_EQ(d.aerodyn.layout, whirl::io::AeroDynLayout::V4);
}

TEST(AeroDeck, EnvironmentDefaultsComeFromTheFst) {
  AeroScratch s;
  s.edit("toolbox/Main.fst", "1.225         AirDens", "1.2           AirDens");
  const AeroDeckInput d = readAeroDeck(readFst(s.path("toolbox/Main.fst")));
  EXPECT_DOUBLE_EQ(d.aerodyn.AirDens, 1.2);  // AeroDyn says "default"
  EXPECT_TRUE(d.aerodyn.AirDens_default);
}

TEST(AeroDeck, ModuleSwitchesRefused) {
  const struct {
    std::string from, to, message;
  } cases[] = {
      {"          2   CompAero", "          1   CompAero",
       ":15: CompAero: 1 not supported by whirl (AeroDisk (OpenFAST v4+): AeroDyn.dat is not an AeroDyn v14 file (no "
       "StallMod); whirl supports only CompAero = 1 with an AeroDyn v14 file, or 2 (AeroDyn v15))"},
      {"          2   CompAero", "          3   CompAero",
       ":15: CompAero: 3 not supported by whirl (external loads (ExtLoads); whirl supports only CompAero = 1 with an "
       "AeroDyn v14 file, or 2 (AeroDyn v15))"},
      {"          2   CompAero", "          0   CompAero",
       ":15: CompAero: 0 not supported by whirl (aerodynamics are off in this deck; whirl supports only CompAero = 1 "
       "with an AeroDyn v14 file, or 2 (AeroDyn v15))"},
      {"          1   CompInflow", "          0   CompInflow",
       ":14: CompInflow: 0 not supported by whirl (still air; whirl supports only CompInflow = 1 (InflowWind))"},
      {"          1   CompInflow", "          2   CompInflow",
       ":14: CompInflow: 2 not supported by whirl (inflow from an external code; whirl supports only CompInflow = 1 "
       "(InflowWind))"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.to);
    AeroScratch s;
    s.edit("toolbox/Main.fst", c.from, c.to);
    EXPECT_EQ(inputErrorMessage([&] { readAeroDeck(readFst(s.path("toolbox/Main.fst"))); }),
              s.path("toolbox/Main.fst").string() + c.message);
  }
}

TEST(AeroDeck, MissingFilesNamedWithTheLineThatNamesThem) {
  const std::string fst = "toolbox/Main.fst";
  {
    AeroScratch s;
    s.remove("toolbox/AeroDyn.dat");
    EXPECT_EQ(inputErrorMessage([&] { readAeroDeck(readFst(s.path(fst))); }),
              s.path(fst).string() + ":38: AeroFile: file not found: " + s.path("toolbox/AeroDyn.dat").string());
  }
  {
    AeroScratch s;
    s.remove("toolbox/InflowWind.dat");
    EXPECT_EQ(inputErrorMessage([&] { readAeroDeck(readFst(s.path(fst))); }),
              s.path(fst).string() + ":37: InflowFile: file not found: " + s.path("toolbox/InflowWind.dat").string());
  }
  {
    AeroScratch s;
    s.remove("5MW_Baseline/Airfoils/DU25_A17.dat");
    EXPECT_EQ(inputErrorMessage([&] { readAeroDeck(readFst(s.path(fst))); }),
              s.path("toolbox/AeroDyn.dat").string() +
                  ":55: AFNames(6): file not found: " + s.path("5MW_Baseline/Airfoils/DU25_A17.dat").string());
  }
  {
    AeroScratch s;
    s.remove("5MW_Baseline/NRELOffshrBsline5MW_AeroDyn_blade.dat");
    EXPECT_EQ(inputErrorMessage([&] { readAeroDeck(readFst(s.path(fst))); }),
              s.path("toolbox/AeroDyn.dat").string() + ":60: ADBlFile(1): file not found: " +
                  s.path("5MW_Baseline/NRELOffshrBsline5MW_AeroDyn_blade.dat").string());
  }
}

TEST(AeroDeck, UnsupportedAeroDynOptionReportedBeforeMissingAirfoils) {
  AeroScratch s;
  s.edit("toolbox/AeroDyn.dat", "          1   WakeMod", "          3   WakeMod");
  s.remove("5MW_Baseline/Airfoils/DU25_A17.dat");
  EXPECT_THAT(inputErrorMessage([&] { readAeroDeck(readFst(s.path("toolbox/Main.fst"))); }),
              HasSubstr(":6: WakeMod: 3 not supported by whirl (OLAF free-vortex wake;"));
}

// A simulation deck's time-domain options are read and noted, each at its line, not refused; unknown
// wind types still are.
TEST(AeroDeck, TimeDomainOptionsNotedNotRefused) {
  AeroScratch s;
  s.edit("v5/InflowWind.dat", "          1   WindType", "          2   WindType");
  s.edit("v5/AeroDyn.dat", "          0   UA_Mod", "          3   UA_Mod");
  const whirl::io::AeroDeckInput deck = readAeroDeck(readFst(s.path("v5/main.fst")));
  ASSERT_EQ(deck.notes.size(), 2u);
  EXPECT_THAT(deck.notes[0], testing::StartsWith(s.path("v5/AeroDyn.dat").string() + ":48: UA_Mod: 3: "));
  EXPECT_THAT(deck.notes[1], testing::StartsWith(s.path("v5/InflowWind.dat").string() +
                                                 ":5: WindType: 2: uniform wind file wind: whirl linearizes in the "
                                                 "steady wind of the file's steady-wind section"));
  EXPECT_TRUE(readAeroDeck(readFst(s.path("toolbox/Main.fst"))).notes.empty());
  s.edit("v5/InflowWind.dat", "          2   WindType", "          8   WindType");
  EXPECT_EQ(inputErrorMessage([&] { readAeroDeck(readFst(s.path("v5/main.fst"))); }),
            s.path("v5/InflowWind.dat").string() +
                ":5: WindType: 8 not supported by whirl (unknown wind type; whirl supports only WindType = 1 to 7)");
}

TEST(AeroDeck, AirfoilIdBeyondNumAFfiles) {
  AeroScratch s;
  s.edit("toolbox/AeroDyn.dat", "          8   NumAFfiles", "          7   NumAFfiles");
  EXPECT_EQ(inputErrorMessage([&] { readAeroDeck(readFst(s.path("toolbox/Main.fst"))); }),
            s.path("5MW_Baseline/NRELOffshrBsline5MW_AeroDyn_blade.dat").string() +
                ":19: BlAFID: is 8, beyond NumAFfiles = 7 (" + s.path("toolbox/AeroDyn.dat").string() + ":49)");
}

TEST(AeroDeck, OverridesReachAeroDynBladeAndInflowFiles) {
  whirl::io::OverrideSet set({{"HWindSpeed", "11.4"}, {"SkewMod", "1"}, {"NumBlNds", "18"}});
  AeroScratch s;
  // NumBlNds = 18 is one row short of the table: the blade file saw the override.
  EXPECT_THAT(inputErrorMessage([&] { readAeroDeck(readFst(s.path("toolbox/Main.fst")), &set); }),
              HasSubstr("NRELOffshrBsline5MW_AeroDyn_blade.dat:25: NumBlNds: table has 19 rows, only 18 expected"));
  whirl::io::OverrideSet ok({{"HWindSpeed", "11.4"}, {"SkewMod", "1"}});
  const AeroDeckInput d = readAeroDeck(readFst(s.path("toolbox/Main.fst")), &ok);
  EXPECT_DOUBLE_EQ(d.inflow.HWindSpeed, 11.4);
  EXPECT_EQ(d.aerodyn.skew, whirl::io::SkewModel::None);
  EXPECT_NO_THROW(ok.requireAllUsed());
}

}  // namespace
