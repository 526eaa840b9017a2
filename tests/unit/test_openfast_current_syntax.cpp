// OpenFAST's current input syntax (issue 41, item 4): the keyword `default` with OpenFAST's default
// values (each cited where the reader reads it), vectors written one number per line, and the SeaState
// file of OpenFAST v4+, on the test decks of tests/data/openfast/v5_syntax and v4_seastate.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "src/io/aerodyn_input.hpp"
#include "src/io/hydrodyn_input.hpp"
#include "src/io/inflowwind_input.hpp"
#include "src/io/openfast_turbine.hpp"
#include "src/turbine/elastodyn_parts.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using testing::HasSubstr;
using whirl::test::inputErrorMessage;
using whirl::test::openfastDataDir;
using whirl::test::readText;
using whirl::test::replaceOnce;
using whirl::test::ScratchDir;
namespace io = whirl::io;

const std::filesystem::path kV5 = openfastDataDir() / "v5_syntax";
const std::filesystem::path kV4 = openfastDataDir() / "v4_seastate";

TEST(OpenFastCurrentSyntax, AeroDynV5DefaultsAndSwitches) {
  const io::AeroDynInput a = io::readAeroDyn(kV5 / "AeroDyn.dat");
  EXPECT_EQ(a.layout, io::AeroDynLayout::V4);
  // SkewRedistr_Mod `default` is 1 (AeroDyn_IO.f90, ParsePrimaryFileInfo), the Glauert/Pitt/Peters
  // redistribution the old deck's SkewMod = 2 meant.
  EXPECT_EQ(a.SkewRedistr_Mod, 1);
  EXPECT_EQ(a.skew, io::SkewModel::Active);
  EXPECT_EQ(a.DBEMT_Mod, -1);  // frozen wake
  EXPECT_EQ(a.UA_Mod, 0);
  EXPECT_EQ(a.AFTabMod, 3);
  // 0 is not the default: a number is read as written.
  ScratchDir dir;
  const auto zero = dir.write("a.dat", replaceOnce(readText(kV5 / "AeroDyn.dat"), "default       SkewRedistr_Mod",
                                                   "0             SkewRedistr_Mod"));
  EXPECT_EQ(io::readAeroDyn(zero).SkewRedistr_Mod, 0);
}

TEST(OpenFastCurrentSyntax, InflowWindVFlowAngDefaultIsZero) {
  // InflowWind_Subs.f90, InflowWind_ParseInputFileInfo: ParseVarWDefault "VFlowAng", 0.0.
  ScratchDir dir;
  const io::InflowWindInput w = io::readInflowWind(kV5 / "InflowWind.dat");
  EXPECT_TRUE(w.has_VFlowAng);
  EXPECT_EQ(w.VFlowAng, 0.0);
  const auto five = dir.write("w.dat", replaceOnce(readText(kV5 / "InflowWind.dat"), "\"default\"     VFlowAng",
                                                   "        5     VFlowAng"));
  EXPECT_EQ(io::readInflowWind(five).VFlowAng, 5.0);
  const auto bad = dir.write("b.dat", replaceOnce(readText(kV5 / "InflowWind.dat"), "\"default\"     VFlowAng",
                                                  "\"defaults\"    VFlowAng"));
  EXPECT_THAT(inputErrorMessage([&] { io::readInflowWind(bad); }), HasSubstr("b.dat:7: VFlowAng:"));
}

TEST(OpenFastCurrentSyntax, SeaStateWaterPropertiesDefaultToTheFst) {
  const io::OpenFastTurbine t = io::readOpenFastTurbine(kV4 / "Test24_v4.fst");
  ASSERT_TRUE(t.seastate.has_value());
  ASSERT_TRUE(t.hydrodyn.has_value());
  EXPECT_FALSE(t.seastate->WtrDens.has_value());  // "default" (SeaState_Input.f90, SeaSt_ParseInput)
  EXPECT_FALSE(t.hydrodyn->WtrDens.has_value());  // not in HydroDyn since OpenFAST v4
  // The .fst's values, those HydroDyn v2 gave in cases/oc3_hywind (1025 kg/m³, 320 m).
  EXPECT_EQ(whirl::elastodyn::waterDensity(t), 1025.0);
  EXPECT_EQ(whirl::elastodyn::waterDepth(t), 320.0);
  // A SeaState value, where given, wins over the .fst's: the deck in a scratch folder, its other files
  // named by absolute path.
  ScratchDir dir;
  const auto ss = dir.write("SeaState.dat", replaceOnce(readText(kV4 / "SeaState.dat"), "\"default\"        WtrDens",
                                                        "1000             WtrDens"));
  std::string fst = readText(kV4 / "Test24_v4.fst");
  fst = replaceOnce(fst, "\"SeaState.dat\"", "\"" + ss.string() + "\"");
  fst = replaceOnce(fst, "\"HydroDyn.dat\"", "\"" + (kV4 / "HydroDyn.dat").string() + "\"");
  const std::string rel = "\"../../../../cases/", abs = "\"" + (whirl::test::sourceDir() / "cases").string() + "/";
  for (std::size_t at; (at = fst.find(rel)) != std::string::npos;) fst.replace(at, rel.size(), abs);
  const auto deck = dir.write("t.fst", fst);
  EXPECT_EQ(whirl::elastodyn::waterDensity(io::readOpenFastTurbine(deck)), 1000.0);
}

TEST(OpenFastCurrentSyntax, HydroDynAddF0OnOneLineOrAsAColumn) {
  ScratchDir dir;
  const std::string hd = readText(kV4 / "HydroDyn.dat");
  const std::string column = "             0   AddF0";
  const std::string rows = "             0\n             0\n             0\n             0\n             0\n";
  const auto col = dir.write("c.dat", replaceOnce(replaceOnce(hd, column, "           1e5   AddF0"),
                                                   rows, "             2\n             3\n             4\n             5\n             6\n"));
  const io::Vec6 f0 = io::readHydroDyn(col).AddF0;
  EXPECT_EQ(f0(0), 1e5);
  EXPECT_EQ(f0(1), 2.0);
  EXPECT_EQ(f0(5), 6.0);
  // HydroDyn v2 (FAST v8): six numbers on the key's line, the rows below it gone.
  const auto line = dir.write("l.dat", replaceOnce(replaceOnce(hd, column, "  1e5 2 3 4 5 6   AddF0"), rows, ""));
  EXPECT_EQ(io::readHydroDyn(line).AddF0(5), 6.0);
  // A row of the column that is not a number is refused with its line.
  const auto bad = dir.write("b.dat", replaceOnce(hd, rows, "             0\n             0\n             x\n"));
  EXPECT_THAT(inputErrorMessage([&] { io::readHydroDyn(bad); }), HasSubstr("b.dat:33: AddF0: row 4 of the 6 preloads (line 36)"));
  const auto three = dir.write("t.dat", replaceOnce(hd, column, "  1 2 3   AddF0"));
  EXPECT_THAT(inputErrorMessage([&] { io::readHydroDyn(three); }), HasSubstr("t.dat:33: AddF0: expected 6 numbers"));
}

}  // namespace
