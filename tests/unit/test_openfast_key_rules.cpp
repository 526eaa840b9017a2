// The key rule of the structured readers in every OpenFAST reader (issue 48, item 4): a key given twice
// or a key no OpenFAST version writes in that file is refused with file:line: key (OpenFAST reads by
// position, so either line shifts every later value while whirl, reading by key, would silently read
// another turbine); two mooring rows with one id; MoorDyn's counts bounded; ElastoDyn's angle and sign
// ranges (ElastoDyn_IO.f90, ValidatePrimaryData). Each test edits one line of a file the cases ship.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "src/io/openfast/aerodyn/aerodyn_blade_input.hpp"
#include "src/io/openfast/aerodyn/aerodyn_input.hpp"
#include "src/io/openfast/aerodyn/airfoil_input.hpp"
#include "src/io/openfast/aerodyn/inflowwind_input.hpp"
#include "src/io/openfast/fst_input.hpp"
#include "src/io/openfast/offshore/hydrodyn_input.hpp"
#include "src/io/openfast/offshore/map_input.hpp"
#include "src/io/openfast/offshore/moordyn_input.hpp"
#include "src/io/openfast/offshore/seastate_input.hpp"
#include "src/io/openfast/servodyn/servodyn_input.hpp"
#include "tests/unit/nrel5mw_scratch.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using testing::HasSubstr;
using whirl::test::inputErrorMessage;
using whirl::test::nrel5mwDir;
using whirl::test::readText;
using whirl::test::replaceOnce;
using whirl::test::ScratchDir;
using whirl::test::sourceDir;
namespace io = whirl::io;

const std::filesystem::path kAero = nrel5mwDir() / "aero";
const std::filesystem::path kHywind = sourceDir() / "cases" / "oc3_hywind" / "5MW_Baseline";
const char* kAirfoil = "5MW_Baseline/Airfoils/DU21_A17.dat";
const char* kHydro = "NRELOffshrBsline5MW_OC3Hywind_HydroDyn.dat";

/// `file` with `from` replaced by `to`, written into `dir` under `name`.
std::filesystem::path edited(const ScratchDir& dir, const std::filesystem::path& file, const std::string& name,
                             const std::string& from, const std::string& to) {
  return dir.write(name, replaceOnce(readText(file), from, to));
}

// --- AeroDyn v15, blade, airfoil ------------------------------------------------------------------

TEST(OpenFastKeyRules, AeroDynKeyGivenTwiceAndUnknownKey) {
  ScratchDir dir;
  const std::string tip = "True          TipLoss";
  const auto twice = edited(dir, kAero / "AeroDyn.dat", "a.dat", tip, "False  TipLoss - again\n" + tip);
  EXPECT_THAT(inputErrorMessage([&] { io::readAeroDyn(twice); }),
              HasSubstr("a.dat:26: TipLoss: given twice (first on line 25)"));
  const auto unknown = edited(dir, kAero / "AeroDyn.dat", "b.dat", tip, "True  TipLos - typo\n" + tip);
  EXPECT_THAT(inputErrorMessage([&] { io::readAeroDyn(unknown); }),
              HasSubstr("b.dat:25: TipLos: not a key of an OpenFAST AeroDyn v15 file"));
}

TEST(OpenFastKeyRules, AeroDynBladeKeyGivenTwiceAndUnknownKey) {
  ScratchDir dir;
  const std::filesystem::path blade = nrel5mwDir() / "5MW_Baseline" / "NRELOffshrBsline5MW_AeroDyn_blade.dat";
  const std::string n = "         19   NumBlNds";
  const auto twice = edited(dir, blade, "b1.dat", n, "         19   NumBlNds - again\n" + n);
  EXPECT_THAT(inputErrorMessage([&] { io::readAeroDynBlade(twice); }), HasSubstr("b1.dat:5: NumBlNds: given twice"));
  const auto unknown = edited(dir, blade, "b2.dat", n, "          1   BlCrv - not a key\n" + n);
  EXPECT_THAT(inputErrorMessage([&] { io::readAeroDynBlade(unknown); }),
              HasSubstr("b2.dat:4: BlCrv: not a key of an OpenFAST AeroDyn blade file"));
}

TEST(OpenFastKeyRules, AirfoilKeyGivenTwiceAndUnknownKey) {
  ScratchDir dir;
  const std::filesystem::path af = nrel5mwDir() / kAirfoil;
  const std::string area = "          1   NonDimArea";
  const auto twice = edited(dir, af, "f1.dat", area, area + " ! again\n" + area);
  EXPECT_THAT(inputErrorMessage([&] { io::readAirfoil(twice); }), HasSubstr("f1.dat:8: NonDimArea: given twice"));
  const auto unknown = edited(dir, af, "f2.dat", area, "          1   NonDimAera ! typo\n" + area);
  EXPECT_THAT(inputErrorMessage([&] { io::readAirfoil(unknown); }),
              HasSubstr("f2.dat:7: NonDimAera: not a key of an OpenFAST AeroDyn airfoil file"));
  // Re repeats from table to table, but not within one table.
  const std::string re = "       0.75   Re ";
  const auto table = edited(dir, af, "f3.dat", re, "       0.5    Re  ! again\n" + re);
  EXPECT_THAT(inputErrorMessage([&] { io::readAirfoil(table); }),
              HasSubstr("f3.dat:15: Re: given twice (first on line 14)"));
}

// --- InflowWind, ServoDyn, .fst -------------------------------------------------------------------

TEST(OpenFastKeyRules, InflowWindHWindSpeedGivenTwiceIsRefused) {
  // The reproducer: whirl took the first (8 m/s); OpenFAST, by position, 25 as RefHt.
  ScratchDir dir;
  const std::string ws = "          8   HWindSpeed";
  const auto twice = edited(dir, kAero / "InflowWind.dat", "w1.dat", ws, ws + " - a\n         25   HWindSpeed");
  EXPECT_THAT(inputErrorMessage([&] { io::readInflowWind(twice); }),
              HasSubstr("w1.dat:15: HWindSpeed: given twice (first on line 14)"));
  const auto unknown = edited(dir, kAero / "InflowWind.dat", "w2.dat", ws, ws + " - a\n         25   HWindSped");
  EXPECT_THAT(inputErrorMessage([&] { io::readInflowWind(unknown); }),
              HasSubstr("w2.dat:15: HWindSped: not a key of an OpenFAST InflowWind file"));
}

TEST(OpenFastKeyRules, ServoDynAndFstUnknownKeyIsRefused) {
  ScratchDir dir;
  const std::string pc = "          0   PCMode";
  const auto srv = edited(dir, kAero / "ServoDyn.dat", "s.dat", pc, "          0   PCMod - typo\n" + pc);
  EXPECT_THAT(inputErrorMessage([&] { io::readServoDyn(srv); }),
              HasSubstr("s.dat:7: PCMod: not a key of an OpenFAST ServoDyn file"));
  const std::string comp = "          0   CompHydro";
  const auto fst = edited(dir, nrel5mwDir() / "Main_Aero.fst", "m.fst", comp, "          0   CompHydr - typo\n" + comp);
  EXPECT_THAT(inputErrorMessage([&] { io::readFst(fst); }),
              HasSubstr("m.fst:17: CompHydr: not a key of an OpenFAST .fst file"));
}

// A line without a key between two key lines (a lone value or word) in a file whose every value line carries
// its key: OpenFAST's ParseVar stops there or takes it for the next key's value; whirl skipped it. A blank line
// (ProcessComFile drops it) and text after the last key (not read) stay accepted.
TEST(OpenFastKeyRules, LinesWithoutAKeyAreRefusedWhereEveryLineHasOne) {
  using whirl::test::nrelEd;
  using whirl::test::turbineError;
  const std::string ed = nrelEd(), rot = "       10.0   RotSpeed";
  EXPECT_THAT(turbineError(replaceOnce(ed, rot, "   3.0\n" + rot)),
              HasSubstr(":33: 3.0: a line without a key in an OpenFAST ElastoDyn file"));
  EXPECT_THAT(turbineError(replaceOnce(ed, rot, "hello\n" + rot)),
              HasSubstr(":33: hello: a line without a key in an OpenFAST ElastoDyn file"));
  EXPECT_THAT(turbineError(replaceOnce(ed, rot, std::string(100, 'x') + "\n" + rot)),
              HasSubstr(":33: " + std::string(37, 'x') + "...: a line without a key"));
  ScratchDir dir;
  EXPECT_NO_THROW(io::readOpenFastTurbine(whirl::test::nrelWith(dir, replaceOnce(ed, rot, "\n" + rot))));
  EXPECT_NO_THROW(io::readOpenFastTurbine(whirl::test::nrelWith(dir, ed + "\n3.0\nnotes\n")));
  const std::string ws = "          8   HWindSpeed";
  const auto wind = edited(dir, kAero / "InflowWind.dat", "w.dat", ws, "         25\n" + ws);
  EXPECT_THAT(inputErrorMessage([&] { io::readInflowWind(wind); }),
              HasSubstr("w.dat:14: 25: a line without a key in an OpenFAST InflowWind file"));
  const std::string pc = "          0   PCMode";
  const auto srv = edited(dir, kAero / "ServoDyn.dat", "s.dat", pc, "          0\n" + pc);
  EXPECT_THAT(inputErrorMessage([&] { io::readServoDyn(srv); }), HasSubstr("s.dat:7: 0: a line without a key"));
  const std::string comp = "          0   CompHydro";
  const auto fst = edited(dir, nrel5mwDir() / "Main_Aero.fst", "m.fst", comp, "CompHydro\n" + comp);
  EXPECT_THAT(inputErrorMessage([&] { io::readFst(fst); }), HasSubstr("m.fst:17: CompHydro: a line without a key"));
  // AeroDyn keeps its keyless lines (AFNames continuation lines): the shipped file reads.
  EXPECT_NO_THROW(io::readAeroDyn(kAero / "AeroDyn.dat"));
}

TEST(OpenFastKeyRules, CommentLinesAndTableRowsAreNotKeys) {
  // A '!' comment line (ProcessComFile skips it) and a column-name row followed by its unit row.
  ScratchDir dir;
  const std::string ws = "          8   HWindSpeed";
  const auto f = edited(dir, kAero / "InflowWind.dat", "w.dat", ws, "! 25   HWindSpeed was 25 in an old run\n" + ws);
  EXPECT_EQ(io::readInflowWind(f).HWindSpeed, 8.0);
}

// --- HydroDyn, SeaState ---------------------------------------------------------------------------

TEST(OpenFastKeyRules, HydroDynKeyGivenTwiceAndUnknownKey) {
  ScratchDir dir;
  const std::string dens = "          1025   WtrDens";
  const auto twice = edited(dir, kHywind / kHydro, "h1.dat", dens, dens + " - a\n          1000   WtrDens");
  EXPECT_THAT(inputErrorMessage([&] { io::readHydroDyn(twice); }), HasSubstr("h1.dat:6: WtrDens: given twice"));
  const auto unknown = edited(dir, kHywind / kHydro, "h2.dat", dens, dens + " - a\n          1000   WtrDen");
  EXPECT_THAT(inputErrorMessage([&] { io::readHydroDyn(unknown); }),
              HasSubstr("h2.dat:6: WtrDen: not a key of an OpenFAST HydroDyn file"));
}

/// A SeaState file of OpenFAST v4 (layout of SeaState_Input.f90, SeaSt_ParseInput), still water.
std::string seaState(const std::string& dens, const std::string& extra = "") {
  return "------- SeaState Input File ----------------------------------------------------\n"
         "OC3 Hywind, still water\n"
         "False         Echo           - Echo the input file data (flag)\n"
         "---------------------- ENVIRONMENTAL CONDITIONS --------------------------------\n" +
         dens + "   WtrDens        - Water density (kg/m^3)\n" + extra +
         "\"default\"     WtrDpth        - Water depth (meters) relative to MSL\n"
         "default       MSL2SWL        - Offset between still-water level and mean sea level (meters)\n"
         "---------------------- WAVES ---------------------------------------------------\n"
         "0             WaveMod        - Incident wave kinematics model {0: none=still water}\n"
         "0             CurrMod        - Current profile model {0: none=no current}\n";
}

TEST(OpenFastKeyRules, SeaStateDefaultsKeyGivenTwiceAndUnknownKey) {
  ScratchDir dir;
  const io::SeaStateInput s = io::readSeaState(dir.write("s.dat", seaState("1025")));
  EXPECT_EQ(s.WtrDens, 1025.0);
  EXPECT_FALSE(s.WtrDpth.has_value());  // "default": the .fst's (SeaState_Input.f90, defWtrDpth)
  EXPECT_FALSE(s.MSL2SWL.has_value());
  EXPECT_TRUE(s.notes.empty());
  const auto twice = dir.write("s2.dat", seaState("1025", "1000 WtrDens - again\n"));
  EXPECT_THAT(inputErrorMessage([&] { io::readSeaState(twice); }), HasSubstr("s2.dat:6: WtrDens: given twice"));
  const auto unknown = dir.write("s3.dat", seaState("1025", "1000 WaterDens - typo\n"));
  EXPECT_THAT(inputErrorMessage([&] { io::readSeaState(unknown); }),
              HasSubstr("s3.dat:6: WaterDens: not a key of an OpenFAST SeaState file"));
  EXPECT_THAT(inputErrorMessage([&] { io::readSeaState(dir.write("s4.dat", seaState("-1"))); }),
              HasSubstr("s4.dat:5: WtrDens: must be positive"));
}

// --- MAP++, MoorDyn -------------------------------------------------------------------------------

TEST(OpenFastKeyRules, MapTwoNodesWithOneIdAreRefused) {
  ScratchDir dir;
  const auto map = edited(dir, kHywind / "NRELOffshrBsline5MW_OC3Hywind_MAP.dat", "map.dat", "2    Vessel",
                          "1    Vessel");
  EXPECT_THAT(inputErrorMessage([&] { io::readMap(map); }),
              HasSubstr("map.dat:9: Node: '1' given twice (first on line 8)"));
}

TEST(OpenFastKeyRules, MoorDynCountsAreBoundedAndIdsUnique) {
  ScratchDir dir;
  const std::filesystem::path md = kHywind / "NRELOffshrBsline5MW_OC3Hywind_MoorDyn.dat";
  const auto huge = edited(dir, md, "m1.dat", "3        NLines", "2e9      NLines");
  EXPECT_THAT(inputErrorMessage([&] { io::readMoorDyn(huge); }), HasSubstr("m1.dat:20: NLines: must be in [0, 10000]"));
  const auto twice = edited(dir, md, "m2.dat", "2         main", "1         main");
  EXPECT_THAT(inputErrorMessage([&] { io::readMoorDyn(twice); }),
              HasSubstr("m2.dat:24: Line: '1' given twice (first on line 23)"));
}

// --- ElastoDyn ranges -----------------------------------------------------------------------------

TEST(OpenFastKeyRules, ElastoDynShaftTiltPreconeAndRotorSpeedRanges) {
  using whirl::test::nrelEd;
  using whirl::test::turbineError;
  const std::string ed = nrelEd();
  EXPECT_THAT(turbineError(replaceOnce(ed, "         -5   ShftTilt", "         95   ShftTilt")),
              HasSubstr(":56: ShftTilt: must be in [-90, 90] deg (is 95)"));
  EXPECT_THAT(turbineError(replaceOnce(ed, "       -2.5   PreCone(1)", "         95   PreCone(1)")),
              HasSubstr(":47: PreCone(1): must be in (-90, 90) deg (is 95)"));
  EXPECT_THAT(turbineError(replaceOnce(ed, "       10.0   RotSpeed", "        -10   RotSpeed")),
              HasSubstr(":33: RotSpeed: must not be negative"));
  // The bounds themselves: OpenFAST accepts |ShftTilt| = 90 and refuses |PreCone| = 90.
  EXPECT_THAT(turbineError(replaceOnce(ed, "       -2.5   PreCone(1)", "        -90   PreCone(1)")),
              HasSubstr("PreCone(1): must be in (-90, 90) deg"));
  ScratchDir dir;
  const auto fst = whirl::test::nrelWith(dir, replaceOnce(ed, "         -5   ShftTilt", "        -90   ShftTilt"));
  EXPECT_EQ(io::readOpenFastTurbine(fst).elastodyn.config.ShftTilt, -90.0);
}

}  // namespace
