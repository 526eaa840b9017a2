// HydroDyn's state-space radiation (RdtnMod = 2) of the ITI barge deck (cases/iti_barge, OpenFAST's
// certification Test22) through the CLI: `whirl modes` lists the modes the radiation states carry under
// their names; `whirl export --format lin` writes them as OpenFAST does ("HD RdtnPtfmSg1", derivative
// order 1), and `whirl lin` reading that file back gives the same modes to the printed digits (an
// independent path: participation factors of the exported A alone); `whirl campbell` leaves the fit's
// own roots out of the plot unless asked; `whirl simulate` refuses the states.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::ContainsRegex;
using ::testing::HasSubstr;
using ::testing::Not;

const std::string kBarge = "cases/iti_barge/Test22.fst --set CompAero=0 --set RotSpeed=0 --set GenDOF=False";

TEST(CliRadiation, BargeModesThroughTheExportedLinFile) {
  const auto modes = test::whirl("modes " + kBarge);
  ASSERT_EQ(modes.code, 0) << modes.err;
  EXPECT_THAT(modes.out, HasSubstr("HydroDyn radiation surge"));
  EXPECT_THAT(modes.out, HasSubstr("platform heave"));
  const auto dir = test::freshDir("barge_lin");
  const auto ex = test::whirl("export " + kBarge + " --rpm 0 --format lin --out " + dir.string());
  ASSERT_EQ(ex.code, 0) << ex.err;
  const std::string lin = test::slurp(dir / "statespace.1.lin");
  EXPECT_THAT(lin, HasSubstr("F                1         HD RdtnPtfmSg1\n"));
  EXPECT_THAT(lin, HasSubstr("F                1         HD RdtnPtfmY4\n"));
  const auto back = test::whirl("lin " + (dir / "statespace.1.lin").string());
  ASSERT_EQ(back.code, 0) << back.err;
  EXPECT_EQ(back.out, modes.out);
}

// `whirl linearize` writes A and B over [q; q̇; z] with the states named; M, C, K stay the coordinates'.
TEST(CliRadiation, LinearizeNamesTheRadiationStatesOfA) {
  const auto dir = test::freshDir("barge_linearize");
  const auto r = test::whirl("linearize " + kBarge + " --out " + dir.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string a = test::slurp(dir / "A.csv");
  EXPECT_THAT(a.substr(0, a.find('\n')), HasSubstr(",d(platform surge)/dt,"));
  EXPECT_THAT(a.substr(0, a.find('\n')), HasSubstr(",HydroDyn radiation surge 1,"));
  EXPECT_THAT(a, HasSubstr("\nHydroDyn radiation yaw 4,"));
  EXPECT_THAT(test::slurp(dir / "linearization.json"), HasSubstr("\"HydroDyn radiation heave 2\""));
}

// The radiation fit's own roots are Campbell lines of the tables, left out of the plot unless asked for.
TEST(CliRadiation, CampbellDrawsTheRadiationRootsOnlyWhenAskedTo) {
  const auto dir = test::freshDir("barge_campbell");
  const std::string cmd = "campbell cases/iti_barge/Test22.fst --set CompAero=0 --rpm 0:6:12 --no-plot --out ";
  const auto r = test::whirl(cmd + (dir / "a").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err,
              ContainsRegex("whirl: note: [0-9]+ lines carried by first-order states \\(e.g. .HydroDyn radiation"));
  EXPECT_THAT(test::slurp(dir / "a" / "campbell.csv"), HasSubstr(",HydroDyn radiation surge,"));
  EXPECT_THAT(test::slurp(dir / "a" / "campbell.gp"), HasSubstr("title 'platform heave'"));
  EXPECT_THAT(test::slurp(dir / "a" / "campbell.gp"), Not(HasSubstr("title 'HydroDyn radiation")));
  const auto all = test::whirl(cmd + (dir / "b").string() + " --first-order-lines");
  ASSERT_EQ(all.code, 0) << all.err;
  EXPECT_THAT(all.err, Not(HasSubstr("first-order states")));
  EXPECT_THAT(test::slurp(dir / "b" / "campbell.gp"), HasSubstr("title 'HydroDyn radiation surge'"));
}

// A 2-bladed rotor turning is analysed by Floquet, whose fixed-frame view has no place for first-order
// states yet: one line, nothing written.
TEST(CliRadiation, FloquetRefusesTheStatesOnOneLine) {
  const auto dir = test::freshDir("barge_floquet");
  const auto r = test::whirl(
      "campbell cases/iti_barge/Test22.fst --set CompAero=0 --set NumBl=2 --rpm 6:6:12 --no-plot --out " +
      (dir / "out").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("whirl: error: operating point 1 (6 rpm, pitch 0 deg, azimuth 0 deg): Floquet analysis "
                               "(fewer than 3 blades, turning) of a model with first-order states (HydroDyn "
                               "radiation, unsteady-airfoil states) is not supported: --set RdtnMod=0 leaves the "
                               "radiation out"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "campbell.csv"));
}

TEST(CliRadiation, SimulateRefusesTheStatesOfTheLinearModelOnly) {
  const auto dir = test::freshDir("barge_simulate");
  const auto r = test::whirl("simulate " + kBarge + " --tmax 1 --out " + (dir / "sim").string());
  EXPECT_NE(r.code, 0);
  EXPECT_THAT(r.err, HasSubstr("RdtnMod = 2"));
  EXPECT_THAT(r.err, HasSubstr("--set RdtnMod=0"));
  EXPECT_FALSE(std::filesystem::exists(dir / "sim"));
}

}  // namespace
}  // namespace whirl
