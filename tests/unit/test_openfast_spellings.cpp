// The OpenFAST decks users bring (issue 16): array keys spelled `BldFile1` (WISDEM/WEIS, IEA reference
// turbines) as well as `BldFile(1)` (FAST 8, OpenFAST templates), property tables with one station
// (SWRT and AWT-27 towers), FAST v7 primary files, and one refusal line for the platform DOFs.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <regex>

#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "src/io/openfast/elastodyn/elastodyn_blade.hpp"
#include "src/io/openfast/elastodyn/elastodyn_tower.hpp"
#include "src/io/openfast/openfast_support.hpp"
#include "src/io/openfast/openfast_turbine.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/unit/nrel5mw_scratch.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using testing::HasSubstr;
using testing::Not;
using whirl::io::canonicalKey;
using whirl::io::OpenFastFile;
using whirl::io::OpenFastTurbine;
using whirl::io::readOpenFastTurbine;
using whirl::test::inputErrorMessage;
using whirl::test::nrel5mwDir;
using whirl::test::nrelEd;
using whirl::test::openfastDataDir;
using whirl::test::readText;
using whirl::test::replaceOnce;
using whirl::test::ScratchDir;
const char* kEd = whirl::test::kNrelEd;
const char* kTower = whirl::test::kNrelTower;
const char* kBlade = whirl::test::kNrelBlade;

/// Every label `Name(k)` of an OpenFAST file rewritten as `replacement` ("$1$2" → `Namek`).
std::string respell(const std::string& text, const char* replacement) {
  static const std::regex indexed(R"(([A-Za-z_][A-Za-z0-9_]*)\((\d)\))");
  return std::regex_replace(text, indexed, replacement);
}

/// The NREL 5MW case in `dir` with ElastoDyn, tower and blade files passed through `edit`.
template <class Edit>
std::filesystem::path nrelEdited(const ScratchDir& dir, Edit edit) {
  dir.write(kEd, edit(nrelEd()));
  dir.write(kTower, edit(readText(nrel5mwDir() / kTower)));
  dir.write(kBlade, edit(readText(nrel5mwDir() / kBlade)));
  return dir.copy(nrel5mwDir() / "Main_Onshore.fst");
}

// --- key spellings ---------------------------------------------------------------------------

TEST(OpenFastSpellings, CanonicalKeyIsTheOneRule) {
  EXPECT_EQ(canonicalKey("BldFile(1)"), "bldfile1");
  EXPECT_EQ(canonicalKey("BldFile1"), "bldfile1");
  EXPECT_EQ(canonicalKey("bldfile( 1 )"), "bldfile1");
  EXPECT_EQ(canonicalKey("TwFAM1Sh(2)"), "twfam1sh2");
  EXPECT_EQ(canonicalKey("NacMass"), "nacmass");
}

TEST(OpenFastSpellings, IndexWithBlanksIsOneKey) {
  const OpenFastFile f =
      OpenFastFile::parse("title\n\"blade.dat\"  BldFile( 1 )  - blade 1\n  2.5  BlPitch(2 ) - pitch\n", "x.dat");
  ASSERT_EQ(f.entries().size(), 2u);
  EXPECT_EQ(f.getString("BldFile(1)"), "blade.dat");
  EXPECT_EQ(f.getString("BldFile1"), "blade.dat");
  EXPECT_DOUBLE_EQ(f.getDouble("BlPitch(2)"), 2.5);
}

// WISDEM/WEIS write `BldFile1`, `BlPitch1`, `TwrFADmp1`, `BldFlDmp1`, `BldFl1Sh2` …: the same turbine.
TEST(OpenFastSpellings, WisdemSpellingReadsTheSameTurbine) {
  const OpenFastTurbine ref = readOpenFastTurbine(nrel5mwDir() / "Main_Onshore.fst");
  for (const char* spelling : {"$1$2", "$1( $2 )", "$1($2 )"}) {
    ScratchDir dir;
    const auto fst = nrelEdited(dir, [&](const std::string& t) { return respell(t, spelling); });
    const OpenFastTurbine t = readOpenFastTurbine(fst);
    const auto& e = t.elastodyn;
    const auto& r = ref.elastodyn;
    EXPECT_EQ(e.init.BlPitch, r.init.BlPitch) << spelling;
    EXPECT_EQ(e.config.PreCone, r.config.PreCone) << spelling;
    EXPECT_EQ(e.mass.TipMass, r.mass.TipMass) << spelling;
    ASSERT_EQ(e.BldFile.size(), 3u) << spelling;
    EXPECT_EQ(e.BldFile[2].filename(), r.BldFile[2].filename()) << spelling;
    EXPECT_EQ(e.tower.TwrFADmp, r.tower.TwrFADmp) << spelling;
    EXPECT_EQ(e.tower.SSStTunr, r.tower.SSStTunr) << spelling;
    EXPECT_EQ(e.tower.TwSSM2Sh, r.tower.TwSSM2Sh) << spelling;
    EXPECT_EQ(e.blades[1].BldFlDmp, r.blades[1].BldFlDmp) << spelling;
    EXPECT_EQ(e.blades[1].BldEdDmp, r.blades[1].BldEdDmp) << spelling;
    EXPECT_EQ(e.blades[1].FlStTunr, r.blades[1].FlStTunr) << spelling;
    EXPECT_EQ(e.blades[1].BldEdgSh, r.blades[1].BldEdgSh) << spelling;
    EXPECT_NO_THROW(whirl::io::requireSupported(t)) << spelling;
  }
}

// The IEA 3.4 MW reference turbine as its repository ships it (WISDEM spelling; before issue 16 it
// stopped at "BldFile1: not a key of an OpenFAST ElastoDyn file").
TEST(OpenFastSpellings, Iea34DeckReads) {
  const auto fst = openfastDataDir() / "decks" / "IEA-3.4-130-RWT" / "IEA-3.4-130-RWT.fst";
  const OpenFastTurbine t = readOpenFastTurbine(fst);
  const auto& e = t.elastodyn;
  EXPECT_DOUBLE_EQ(e.config.TipRad, 64.90852112228899);  // ElastoDyn.dat line 45
  ASSERT_EQ(e.blades.size(), 3u);                        // BldFile1..3, lines 86–88
  EXPECT_EQ(e.BldFile[1].filename(), "IEA-3.4-130-RWT_ElastoDyn_blade.dat");
  EXPECT_EQ(e.blades[0].BldFlDmp, (std::array<double, 2>{3.0, 3.0}));  // BldFlDmp1, BldFlDmp2
  EXPECT_DOUBLE_EQ(e.blades[0].BldEdDmp, 3.0);                         // BldEdDmp1
  EXPECT_DOUBLE_EQ(e.blades[0].BldFl1Sh[0], 0.2979932369894798);       // BldFl1Sh(2), blade line 48
  EXPECT_EQ(e.tower.NTwInpSt, 10);
  EXPECT_NO_THROW(whirl::io::requireSupported(t));
}

TEST(OpenFastSpellings, BothSpellingsOfOneKeyAreGivenTwice) {
  const std::string msg = whirl::test::turbineError(replaceOnce(
      nrelEd(), "\"NRELOffshrBsline5MW_Blade.dat\"    BldFile(2)",
      "\"NRELOffshrBsline5MW_Blade.dat\"    BldFile1 - again\n\"NRELOffshrBsline5MW_Blade.dat\"    BldFile(2)"));
  EXPECT_THAT(msg, HasSubstr(std::string(kEd) + ":87: BldFile1: given twice (first on line 86)"));
}

TEST(OpenFastSpellings, UnknownLabelNamesTheExpectedKey) {
  // A mistyped label in place of NacMass: OpenFAST would stop there too (ParseVar checks it).
  const std::string msg = whirl::test::turbineError(replaceOnce(nrelEd(), "240000   NacMass", "240000   NacMas"));
  EXPECT_THAT(msg, HasSubstr(std::string(kEd) + ":77: NacMas: not a key of an OpenFAST ElastoDyn file "
                                                "(expected NacMass here)"));
  // An index on a key that is no array is no spelling of it (NacMass1 is not NacMass).
  const std::string idx = whirl::test::turbineError(replaceOnce(nrelEd(), "240000   NacMass", "240000   NacMass1"));
  EXPECT_THAT(idx, HasSubstr(":77: NacMass1: not a key of an OpenFAST ElastoDyn file"));
}

// --- one-station property tables -------------------------------------------------------------

/// The NREL 5MW tower table replaced by `rows` (each "HtFract TMassDen TwFAStif TwSSStif").
std::string towerWith(const std::vector<std::string>& rows) {
  std::string t = readText(nrel5mwDir() / kTower);
  const std::size_t b = t.find("0.0000000E+00  5.5908700E+03"), e = t.find("-----", b);
  std::string table;
  for (const std::string& r : rows) table += r + "\n";
  t = t.substr(0, b) + table + t.substr(e);
  return replaceOnce(t, "         11   NTwInpSt", "         " + std::to_string(rows.size()) + "   NTwInpSt");
}

/// The NREL 5MW blade table replaced by `rows`.
std::string bladeWith(const std::vector<std::string>& rows) {
  std::string t = readText(nrel5mwDir() / kBlade);
  const std::size_t b = t.find("0.0000000E+00  2.5000000E-01"), e = t.find("-----", b);
  std::string table;
  for (const std::string& r : rows) table += r + "\n";
  t = t.substr(0, b) + table + t.substr(e);
  return replaceOnce(t, "         49   NBlInpSt", "         " + std::to_string(rows.size()) + "   NBlInpSt");
}

whirl::LinearModel linearModel(const std::string& tower, const std::string& blade) {
  ScratchDir dir;
  dir.write(kEd, nrelEd());
  dir.write(kTower, tower);
  dir.write(kBlade, blade);
  dir.copy(nrel5mwDir() / "NRELOffshrBsline5MW_Onshore_ServoDyn.dat");  // yaw spring
  const auto fst = dir.copy(nrel5mwDir() / "Main_Onshore.fst");
  const whirl::Model m = whirl::readElastoDynModel(fst.string(), {"RotSpeed=0"});
  return whirl::linearize(m, whirl::solveOperatingPoint(m, whirl::initialPoint(m)));
}

double maxDifference(const whirl::MatX& a, const whirl::MatX& b) { return (a - b).cwiseAbs().maxCoeff(); }

TEST(OpenFastOneStation, TowerTableIsHeldConstant) {
  ScratchDir dir;
  const auto p = dir.write("t.dat", towerWith({"0.0  4.0E+03  3.0E+11  2.5E+11"}));
  const whirl::io::ElastoDynTower t = whirl::io::readElastoDynTower(p);
  EXPECT_EQ(t.NTwInpSt, 1);
  EXPECT_TRUE(t.distributed.constant);
  EXPECT_EQ(t.distributed.column("HtFract"), (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(t.distributed.column("TwSSStif"), (std::vector<double>{2.5e11, 2.5e11}));
}

// ElastoDyn holds one station's properties over the span: the model equals that of a two-station
// table with equal rows at 0 and 1.
TEST(OpenFastOneStation, SameModelAsTwoEqualStations) {
  const std::string blade = readText(nrel5mwDir() / kBlade);
  const std::string row = "  4.0E+03  3.0E+11  2.5E+11";
  const whirl::LinearModel one = linearModel(towerWith({"0.0" + row}), blade);
  const whirl::LinearModel two = linearModel(towerWith({"0.0" + row, "1.0" + row}), blade);
  EXPECT_EQ(maxDifference(one.M, two.M), 0.0);
  EXPECT_EQ(maxDifference(one.K, two.K), 0.0);
  EXPECT_EQ(maxDifference(one.C, two.C), 0.0);

  const std::string tower = readText(nrel5mwDir() / kTower);
  const std::string brow = "  2.5E-01  1.0E+01  3.0E+02  4.0E+09  6.0E+09";
  const whirl::LinearModel bone = linearModel(tower, bladeWith({"0.0" + brow}));
  const whirl::LinearModel btwo = linearModel(tower, bladeWith({"0.0" + brow, "1.0" + brow}));
  EXPECT_EQ(maxDifference(bone.M, btwo.M), 0.0);
  EXPECT_EQ(maxDifference(bone.K, btwo.K), 0.0);
  EXPECT_GT(maxDifference(one.K, bone.K), 0.0);  // the tables do change the model
}

TEST(OpenFastOneStation, TheStationMustBeAtZero) {
  ScratchDir dir;
  const auto p = dir.write("t.dat", towerWith({"0.5  4.0E+03  3.0E+11  2.5E+11"}));
  EXPECT_THAT(inputErrorMessage([&] { whirl::io::readElastoDynTower(p); }),
              HasSubstr("t.dat:20: HtFract: the only station must be at 0 (is 0.5)"));
  const auto none = dir.write("n.dat", replaceOnce(towerWith({"0.0  4.0E+03  3.0E+11  2.5E+11"}),
                                                   "         1   NTwInpSt", "         0   NTwInpSt"));
  EXPECT_THAT(inputErrorMessage([&] { whirl::io::readElastoDynTower(none); }),
              HasSubstr("n.dat:4: NTwInpSt: must be at least 1, is 0"));
}

// The SWRT tower as the certification test ships it (Test15–17): one station.
TEST(OpenFastOneStation, SwrtTowerFileReads) {
  const auto p = openfastDataDir() / "decks" / "certtest" / "SWRT" / "SWRT_Tower.dat";
  const whirl::io::ElastoDynTower t = whirl::io::readElastoDynTower(p);
  EXPECT_EQ(t.NTwInpSt, 1);
  EXPECT_EQ(t.distributed.column("TMassDen"), (std::vector<double>{879.16, 879.16}));  // SWRT_Tower.dat line 20
}

// --- FAST v7 and one-line refusals -------------------------------------------------------------

TEST(OpenFastDecks, FastV7PrimaryFileIsNamed) {
  const auto p = openfastDataDir() / "decks" / "certtest" / "FAST_v7" / "Test01.fst";
  const std::string msg = inputErrorMessage([&] { readOpenFastTurbine(p); });
  EXPECT_THAT(msg, HasSubstr("Test01.fst:7: ADAMSPrep: this is a FAST v7 primary input file"));
  EXPECT_THAT(msg, HasSubstr("ConvertFAST7to8"));
  EXPECT_THAT(msg, Not(HasSubstr("key not found")));
  EXPECT_EQ(msg.find('\n'), std::string::npos);
}

TEST(OpenFastDecks, PlatformDofsAreOneRefusal) {
  std::string ed = nrelEd();
  for (const char* key : {"PtfmSgDOF", "PtfmSwDOF", "PtfmHvDOF", "PtfmRDOF", "PtfmPDOF", "PtfmYDOF"})
    ed = replaceOnce(ed, std::string("False         ") + key, std::string("True          ") + key);
  ScratchDir dir;
  const auto fst = whirl::test::nrelWith(dir, ed);
  const std::string msg = inputErrorMessage([&] { whirl::io::requireSupported(readOpenFastTurbine(fst)); });
  EXPECT_THAT(msg, HasSubstr(std::string(kEd) + ":19: PtfmSgDOF: True not supported by whirl (platform DOFs are not "
                                                "modelled, and PtfmSwDOF, PtfmHvDOF, PtfmRDOF, PtfmPDOF, PtfmYDOF are "
                                                "on too: no hydrostatics or mooring (CompHydro = 0, CompMooring = 0) "
                                                "holds the platform)"));
  EXPECT_EQ(msg.find("not supported"), msg.rfind("not supported"));  // one clause
  EXPECT_EQ(msg.find(';'), std::string::npos);                       // refusals are joined by "; ": none
}

}  // namespace
