// OpenFAST's current input syntax (issue 41, item 4): the keyword `default` with OpenFAST's default
// values (each cited where the reader reads it), vectors written one number per line, and the SeaState
// file of OpenFAST v4+, on the test decks of tests/data/openfast/v5_syntax and v4_seastate.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <regex>

#include "src/io/openfast/aerodyn/aerodyn_input.hpp"
#include "src/io/openfast/aerodyn/airfoil_input.hpp"
#include "src/io/openfast/aerodyn/inflowwind_input.hpp"
#include "src/io/openfast/elastodyn/elastodyn_input.hpp"
#include "src/io/openfast/fst_input.hpp"
#include "src/io/openfast/offshore/hydrodyn_input.hpp"
#include "src/io/openfast/offshore/seastate_input.hpp"
#include "src/io/openfast/openfast_turbine.hpp"
#include "src/io/openfast/servodyn/servodyn_input.hpp"
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
const std::filesystem::path kHywind = whirl::test::sourceDir() / "cases" / "oc3_hywind";

/// `text` with the value of the line `value  key  - …` replaced by the keyword `default` (the test
/// fails when no such line exists).
std::string withDefault(const std::string& text, const std::string& key) {
  const std::regex line("(^|\\n)([ \\t]*)\\S+([ \\t]+" + key + "[ \\t])", std::regex::icase);
  std::smatch m;
  EXPECT_TRUE(std::regex_search(text, m, line)) << key << " not found";
  if (m.empty()) return text;
  return m.prefix().str() + m[1].str() + m[2].str() + "default" + m[3].str() + m.suffix().str();
}

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
  const auto col = dir.write(
      "c.dat", replaceOnce(replaceOnce(hd, column, "           1e5   AddF0"), rows,
                           "             2\n             3\n             4\n             5\n             6\n"));
  const io::Vec6 f0 = io::readHydroDyn(col).AddF0;
  EXPECT_EQ(f0(0), 1e5);
  EXPECT_EQ(f0(1), 2.0);
  EXPECT_EQ(f0(5), 6.0);
  // HydroDyn v2 (FAST v8): six numbers on the key's line, the rows below it gone.
  const auto line = dir.write("l.dat", replaceOnce(replaceOnce(hd, column, "  1e5 2 3 4 5 6   AddF0"), rows, ""));
  EXPECT_EQ(io::readHydroDyn(line).AddF0(5), 6.0);
  // A row of the column that is not a number is refused with its line.
  const auto bad = dir.write("b.dat", replaceOnce(hd, rows, "             0\n             0\n             x\n"));
  EXPECT_THAT(inputErrorMessage([&] { io::readHydroDyn(bad); }),
              HasSubstr("b.dat:33: AddF0: row 4 of the 6 preloads (line 36)"));
  const auto three = dir.write("t.dat", replaceOnce(hd, column, "  1 2 3   AddF0"));
  EXPECT_THAT(inputErrorMessage([&] { io::readHydroDyn(three); }), HasSubstr("t.dat:33: AddF0: expected 6 numbers"));
}

TEST(OpenFastCurrentSyntax, HydroDynV35WaterDefaultsAreTheFst) {
  // OpenFAST v3.5's HydroDyn (HydroDyn_Input.f90, HydroDyn_ParseInput): WtrDens, WtrDpth and MSL2SWL by
  // ParseVarWDefault with the glue code's values, i.e. the .fst's environment block (v3.2+);
  // WavePkShp, CurrSSDir and RdtnDT are strings compared with 'DEFAULT'. cases/oc3_hywind's deck with
  // every one of them `default` and the .fst's environment block of Test24_v4.fst.
  ScratchDir dir;
  const std::filesystem::path hd_name = "NRELOffshrBsline5MW_OC3Hywind_HydroDyn.dat";
  std::string hd = readText(kHywind / "5MW_Baseline" / hd_name);
  for (const char* key : {"WtrDens", "WtrDpth", "MSL2SWL", "WavePkShp", "CurrSSDir", "RdtnDT"})
    hd = withDefault(hd, key);
  hd = replaceOnce(hd, "             1   RdtnMod", "             0   RdtnMod");  // no convolution in a linearization
  const auto hd_file = dir.write(hd_name.string(), hd);
  const io::HydroDynInput h = io::readHydroDyn(hd_file);
  EXPECT_FALSE(h.WtrDens.has_value());
  EXPECT_FALSE(h.WtrDpth.has_value());

  const std::string v4 = readText(kV4 / "Test24_v4.fst");
  const std::size_t env_from = v4.find("          0   MHK"), env_to = v4.find('\n', v4.find("MSL2SWL"));
  ASSERT_NE(env_from, std::string::npos);
  std::string fst = readText(kHywind / "Test24.fst");
  const std::size_t after_ice = fst.find('\n', fst.find("CompIce")) + 1;
  fst.insert(after_ice, v4.substr(env_from, env_to + 1 - env_from));
  fst = replaceOnce(fst, "\"5MW_Baseline/" + hd_name.string() + "\"", "\"" + hd_file.string() + "\"");
  for (std::size_t at; (at = fst.find("\"5MW_Baseline/")) != std::string::npos;)
    fst.replace(at, 1, "\"" + (kHywind.string() + "/"));
  const io::OpenFastTurbine t = io::readOpenFastTurbine(dir.write("Test24_v35.fst", fst));
  EXPECT_EQ(whirl::elastodyn::waterDensity(t), 1025.0);  // the .fst's, as the deck's own HydroDyn value
  EXPECT_EQ(whirl::elastodyn::waterDepth(t), 320.0);
  // Without the .fst's block (a FAST v8 .fst) there is no value to default to.
  const std::string v8 = replaceOnce(readText(kHywind / "Test24.fst"), "\"5MW_Baseline/" + hd_name.string() + "\"",
                                     "\"" + hd_file.string() + "\"");
  std::string v8abs = v8;
  for (std::size_t at; (at = v8abs.find("\"5MW_Baseline/")) != std::string::npos;)
    v8abs.replace(at, 1, "\"" + (kHywind.string() + "/"));
  const auto v8_deck = dir.write("Test24_v8.fst", v8abs);
  EXPECT_THAT(inputErrorMessage([&] { whirl::elastodyn::waterDensity(io::readOpenFastTurbine(v8_deck)); }),
              HasSubstr("WtrDens: not in the .fst nor in the HydroDyn or SeaState file"));
}

// `default` where OpenFAST has no default (ParseVar, not ParseVarWDefault, in the module's reader)
// stops OpenFAST; whirl says so with file, line and key, one key per module file.
TEST(OpenFastCurrentSyntax, DefaultIsRefusedWhereOpenFastHasNone) {
  ScratchDir dir;
  const std::string tail = ": 'default' is not a number (OpenFAST has no default value for this key)";
  const std::string tail_int = ": 'default' is not an integer (OpenFAST has no default value for this key)";
  auto edited = [&](const std::filesystem::path& from, const std::string& key) {
    return dir.write(from.filename().string(), withDefault(readText(from), key));
  };
  // FAST_Subs.f90, FAST_ReadPrimaryFile: the environment block by ParseVar.
  EXPECT_EQ(inputErrorMessage([&] { io::readFst(edited(kV5 / "Main_v5.fst", "AirDens")); }),
            (dir.path() / "Main_v5.fst").string() + ":32: AirDens" + tail);
  // ElastoDyn_IO.f90, ReadPrimaryFile: only DT takes "default".
  EXPECT_EQ(inputErrorMessage([&] { io::readElastoDyn(edited(kV5 / "ElastoDyn.dat", "TipRad")); }),
            (dir.path() / "ElastoDyn.dat").string() + ":46: TipRad" + tail);
  // InflowWind_Subs.f90: only VFlowAng and XOffset.
  EXPECT_EQ(inputErrorMessage([&] { io::readInflowWind(edited(kV5 / "InflowWind.dat", "HWindSpeed")); }),
            (dir.path() / "InflowWind.dat").string() + ":14: HWindSpeed" + tail);
  // AeroDyn_IO.f90, ParsePrimaryFileInfo: the switches by ParseVar.
  EXPECT_EQ(inputErrorMessage([&] { io::readAeroDyn(edited(kV5 / "AeroDyn.dat", "Wake_Mod")); }),
            (dir.path() / "AeroDyn.dat").string() + ":6: Wake_Mod" + tail_int);
  // ServoDyn_IO.f90, ParseInputFileInfo: only DT and DLL_DT.
  EXPECT_EQ(inputErrorMessage([&] { io::readServoDyn(edited(kV5 / "ServoDyn.dat", "VS_RtGnSp")); }),
            (dir.path() / "ServoDyn.dat").string() + ":37: VS_RtGnSp" + tail);
  // HydroDyn_Input.f90: PotMod by ParseVar.
  EXPECT_EQ(inputErrorMessage([&] { io::readHydroDyn(edited(kV4 / "HydroDyn.dat", "PotMod")); }),
            (dir.path() / "HydroDyn.dat").string() + ":5: PotMod" + tail_int);
  // SeaState_Input.f90, SeaSt_ParseInput: CurrMod by ParseVar.
  const std::string sea = withDefault(readText(kV4 / "SeaState.dat"), "CurrMod");
  EXPECT_THAT(inputErrorMessage([&] { io::readSeaState(dir.write("SeaState.dat", sea)); }),
              HasSubstr(": CurrMod" + tail_int));
  // AirfoilInfo.f90, ParseAFFile: NumAlf by ParseVar (a UA coefficient it cannot read is computed instead:
  // CalcDefaults).
  EXPECT_THAT(inputErrorMessage([&] {
                io::readAirfoil(
                    edited(whirl::test::nrel5mwDir() / "5MW_Baseline" / "Airfoils" / "DU21_A17.dat", "NumAlf"));
              }),
              HasSubstr("DU21_A17.dat:52: NumAlf: 'default' is not"));
}

}  // namespace
