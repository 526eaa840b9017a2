// Bad OpenFAST inputs, generated at test time from the NREL 5MW files in a scratch folder: each must give
// an InputError whose one-line message names the file, the line and the key (or table column) and says
// why. Line numbers are those of the NREL 5MW files (ElastoDyn: TowerHt 64, NacMass 77, Furling 104 …).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "src/io/openfast/openfast_overrides.hpp"
#include "src/io/openfast/openfast_support.hpp"
#include "src/io/openfast/openfast_turbine.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using testing::HasSubstr;
using testing::StartsWith;
using whirl::test::inputErrorMessage;
using whirl::test::readText;

/// The NREL 5MW case in a scratch folder; edit a file, then read the turbine.
class BadInput : public testing::Test {
 protected:
  void SetUp() override {
    for (const char* f : {kFst, kEd, kTower, kBlade}) dir_.copy(whirl::test::nrel5mwDir() / f);
  }
  /// Replaces `from` by `to` in scratch file `name`.
  void edit(const char* name, const std::string& from, const std::string& to) {
    dir_.write(name, whirl::test::replaceOnce(readText(dir_.path() / name), from, to));
  }
  /// Keeps the first `n` lines of scratch file `name`.
  void truncate(const char* name, int n) {
    const std::string text = readText(dir_.path() / name);
    std::size_t at = 0;
    for (int i = 0; i < n; ++i) at = text.find('\n', at) + 1;
    dir_.write(name, text.substr(0, at));
  }
  whirl::io::OpenFastTurbine read() { return whirl::io::readOpenFastTurbine(dir_.path() / kFst); }
  std::string readError() {
    return inputErrorMessage([&] { read(); });
  }
  std::string path(const char* name) const { return (dir_.path() / name).string(); }

  static constexpr const char* kFst = "Main_Onshore.fst";
  static constexpr const char* kEd = "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat";
  static constexpr const char* kTower = "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat";
  static constexpr const char* kBlade = "NRELOffshrBsline5MW_Blade.dat";
  whirl::test::ScratchDir dir_;
};

TEST_F(BadInput, UnchangedCopyReads) { EXPECT_NO_THROW(read()); }

TEST_F(BadInput, TruncatedTableAtEndOfFile) {
  truncate(kTower, 28);  // 9 of the 11 rows (lines 20–28)
  EXPECT_EQ(readError(),
            path(kTower) + ":28: NTwInpSt: table has 9 rows, 11 expected: the file ends (truncated table?)");
}

TEST_F(BadInput, TruncatedTableFollowedByTheNextSection) {
  edit(kTower, "2.0000000E-01  4.8857600E+03  4.6326700E+11  4.6326700E+11  \n", "");
  edit(kTower, "3.0000000E-01  4.5508700E+03  3.9913100E+11  3.9913100E+11  \n", "");
  EXPECT_EQ(readError(), path(kTower) +
                             ":29: NTwInpSt: table has 9 rows, 11 expected: line 29 is not a row "
                             "of numbers (truncated table?)");
}

TEST_F(BadInput, MoreRowsThanTheCount) {
  edit(kTower, "         11   NTwInpSt", "         10   NTwInpSt");
  EXPECT_EQ(readError(), path(kTower) + ":30: NTwInpSt: table has 11 rows, only 10 expected");
}

TEST_F(BadInput, NaNInTable) {
  edit(kTower, "4.0000000E-01  4.2277500E+03", "4.0000000E-01  NaN");
  EXPECT_EQ(readError(), path(kTower) + ":24: TMassDen: value is NaN");
}

TEST_F(BadInput, NaNScalar) {
  edit(kEd, "       87.6   TowerHt", "        NaN   TowerHt");
  EXPECT_EQ(readError(), path(kEd) + ":64: TowerHt: value is NaN");
}

TEST_F(BadInput, NonNumericScalar) {
  edit(kEd, "     240000   NacMass", "    240000a   NacMass");
  EXPECT_EQ(readError(), path(kEd) + ":77: NacMass: '240000a' is not a number");
}

TEST_F(BadInput, NegativeMassDensity) {
  edit(kBlade, "4.5855000E-01  3.7500000E-01  7.3210000E+00  2.8712000E+02",
       "4.5855000E-01  3.7500000E-01  7.3210000E+00  -2.8712000E+02");
  EXPECT_EQ(readError(), path(kBlade) + ":40: BMassDen: must not be negative (is -287.12)");
}

TEST_F(BadInput, NegativeLumpedMass) {
  edit(kEd, "     240000   NacMass", "    -240000   NacMass");
  EXPECT_EQ(readError(), path(kEd) + ":77: NacMass: must not be negative (is -240000)");
}

TEST_F(BadInput, ZeroStiffness) {
  edit(kTower, "4.0000000E-01  4.2277500E+03  3.4188300E+11", "4.0000000E-01  4.2277500E+03  0");
  EXPECT_EQ(readError(), path(kTower) + ":24: TwFAStif: must be positive (is 0)");
}

TEST_F(BadInput, FractionsNotIncreasing) {
  edit(kTower, "4.0000000E-01  4.2277500E+03", "2.5000000E-01  4.2277500E+03");
  EXPECT_EQ(readError(), path(kTower) + ":24: HtFract: must increase from station to station (0.25 after 0.3)");
}

TEST_F(BadInput, FractionsNotEndingAtOne) {
  edit(kTower, "1.0000000E+00  2.5362700E+03", "9.9000000E-01  2.5362700E+03");
  EXPECT_EQ(readError(), path(kTower) + ":30: HtFract: must end at 1 (is 0.99)");
}

TEST_F(BadInput, RowWithAMissingNumber) {
  edit(kTower, "2.0000000E-01  4.8857600E+03  4.6326700E+11  4.6326700E+11",
       "2.0000000E-01  4.8857600E+03  4.6326700E+11");
  EXPECT_EQ(readError(),
            path(kTower) + ":22: row has 3 numbers, the table has 4 columns (HtFract TMassDen TwFAStif TwSSStif)");
}

TEST_F(BadInput, MissingColumn) {
  edit(kTower, "TwSSStif\n", "TwSSStff\n");
  EXPECT_THAT(readError(), StartsWith(path(kTower) + ":18: TwSSStif: column missing from the table"));
}

TEST_F(BadInput, ModeShapeNotNormalised) {
  edit(kTower, "     0.7004   TwFAM1Sh(2)", "     0.8004   TwFAM1Sh(2)");
  EXPECT_THAT(readError(),
              StartsWith(path(kTower) + ":36: TwFAM1Sh(6): mode shape coefficients TwFAM1Sh(2..6) sum to 1.1"));
}

TEST_F(BadInput, MissingKey) {
  edit(kEd, "     240000   NacMass     - Nacelle mass (kg)\n", "");
  EXPECT_EQ(readError(), path(kEd) + ": NacMass: key not found in this file");
}

TEST_F(BadInput, BadFlag) {
  edit(kEd, "True          FlapDOF2", "Yes           FlapDOF2");
  EXPECT_EQ(readError(), path(kEd) + ":9: FlapDOF2: 'Yes' is not True or False");
}

TEST_F(BadInput, MissingMainFile) {
  EXPECT_EQ(inputErrorMessage([&] { whirl::io::readOpenFastTurbine(dir_.path() / "none.fst"); }),
            path("none.fst") + ": cannot open file");
}

TEST_F(BadInput, MissingElastoDynFile) {
  edit(kFst, "\"NRELOffshrBsline5MW_Onshore_ElastoDyn.dat\"", "\"nothere/ED.dat\"");
  EXPECT_EQ(readError(), path(kFst) + ":33: EDFile: file not found: " + path("nothere/ED.dat"));
}

TEST_F(BadInput, MissingTowerFile) {
  std::filesystem::remove(dir_.path() / kTower);
  EXPECT_EQ(readError(), path(kEd) + ":108: TwrFile: file not found: " + path(kTower));
}

TEST_F(BadInput, MissingBladeFile) {
  edit(kEd, "\"NRELOffshrBsline5MW_Blade.dat\"    BldFile(2)", "\"../blades/b2.dat\"    BldFile(2)");
  EXPECT_EQ(readError(), path(kEd) + ":87: BldFile(2): file not found: " +
                             (dir_.path().parent_path() / "blades" / "b2.dat").string());
}

TEST_F(BadInput, UnknownKeyInOverrides) {
  whirl::io::OverrideSet set(std::vector<whirl::io::KeyOverride>{{"NacMass", "1e5"}, {"TowerHeight", "90"}});
  const whirl::io::OpenFastTurbine t = whirl::io::readOpenFastTurbine(dir_.path() / kFst, &set);
  EXPECT_DOUBLE_EQ(t.elastodyn.mass.NacMass, 1e5);
  EXPECT_THAT(inputErrorMessage([&] { set.requireAllUsed(); }),
              StartsWith("TowerHeight: unknown key (not in any file read: " + path(kFst) + ", " + path(kEd)));
  whirl::io::OpenFastFile ed = whirl::io::OpenFastFile::read(dir_.path() / kEd);
  EXPECT_EQ(inputErrorMessage([&] { ed.setValue("TowerHeight", "90"); }),
            path(kEd) + ": TowerHeight: unknown key (not in this file)");
}

TEST_F(BadInput, BadOverrideValueNamesTheOverride) {
  whirl::io::OverrideSet set(std::vector<whirl::io::KeyOverride>{{"GBRatio", "-97"}});
  EXPECT_EQ(inputErrorMessage([&] { whirl::io::readOpenFastTurbine(dir_.path() / kFst, &set); }),
            path(kEd) + ":100: GBRatio: must be positive (is -97) (value set by override)");
}

TEST_F(BadInput, FurlingIsRefused) {
  edit(kEd, "False         Furling", "True          Furling");
  const whirl::io::OpenFastTurbine t = read();  // reading is fine: the furl file is never opened
  EXPECT_EQ(inputErrorMessage([&] { whirl::io::requireSupported(t); }),
            path(kEd) + ":104: Furling: True not supported by whirl (rotor and tail furl are not modelled)");
}

TEST_F(BadInput, TwoBladedTeeteringRotorIsRead) {
  edit(kEd, "          3   NumBl", "          2   NumBl");
  edit(kEd, "False         TeetDOF", "True          TeetDOF");
  const whirl::io::OpenFastTurbine t = read();
  EXPECT_EQ(t.elastodyn.blades.size(), 2u);
  EXPECT_TRUE(whirl::io::unsupportedOptions(t.elastodyn).empty());
}

// ElastoDyn ignores TeetDOF for 3 blades ("[unused for 3 blades]"); a deck that sets it expects a teeter.
TEST_F(BadInput, TeeterOnThreeBladesIsRefused) {
  edit(kEd, "False         TeetDOF", "True          TeetDOF");
  EXPECT_EQ(inputErrorMessage([&] { whirl::io::requireSupported(read()); }),
            path(kEd) +
                ":11: TeetDOF: True not supported by whirl (a teetering hub needs a 2-bladed rotor (NumBl = "
                "3); set TeetDOF = False)");
}

TEST_F(BadInput, NoOrFourBladesAreAnInputError) {
  edit(kEd, "          3   NumBl", "          0   NumBl");
  EXPECT_EQ(readError(), path(kEd) + ":44: NumBl: must be 1, 2 or 3 (is 0)");
  edit(kEd, "          0   NumBl", "          4   NumBl");
  EXPECT_EQ(readError(), path(kEd) + ":44: NumBl: must be 1, 2 or 3 (is 4)");
}

// A 2-bladed rotor needs the ROTOR-TEETER section, with ElastoDyn's ranges (ValidatePrimaryData).
TEST_F(BadInput, TwoBladedRotorTeeterKeys) {
  edit(kEd, "          3   NumBl", "          2   NumBl");
  edit(kEd, "          0   TeetMod ", "          0   TeetMd ");
  EXPECT_THAT(readError(), StartsWith(path(kEd) + ":90: TeetMd: not a key of an OpenFAST ElastoDyn file"));
  std::string text = readText(dir_.path() / kEd);  // the line gone altogether
  const std::size_t at = text.find("          0   TeetMd ");
  text.erase(at, text.find('\n', at) - at + 1);
  dir_.write(kEd, text);
  EXPECT_THAT(readError(), StartsWith(path(kEd) + ": TeetMod: key not found: a 2-bladed rotor (NumBl = 2) needs the "
                                                  "ROTOR-TEETER section"));
}

TEST_F(BadInput, TwoBladedRotorTeeterRanges) {
  edit(kEd, "          3   NumBl", "          2   NumBl");
  auto with = [&](const std::string& from, const std::string& to) {
    edit(kEd, from, to);
    const std::string msg = readError();
    edit(kEd, to, from);
    return msg;
  };
  EXPECT_EQ(with("          0   TeetMod ", "          3   TeetMod "),
            path(kEd) + ":90: TeetMod: must be 0 (none), 1 (standard) or 2 (user-defined) (is 3)");
  EXPECT_EQ(with("          0   TeetHStP", "         -1   TeetHStP"),
            path(kEd) + ":95: TeetHStP: must be in [TeetSStP, 180] deg = [0, 180] (is -1)");
  EXPECT_EQ(with("          0   TeetSStP", "        200   TeetSStP"),
            path(kEd) + ":94: TeetSStP: must be in [0, 180] deg (is 200)");
  EXPECT_EQ(with("          0   TeetCDmp", "         10   TeetCDmp"),
            path(kEd) + ":93: TeetCDmp: must be 0, as ElastoDyn requires (Coulomb teeter damping is not modelled)");
  EXPECT_THAT(with("          0   TeetSSSp", "         -5   TeetSSSp"), StartsWith(path(kEd) + ":96: TeetSSSp: "));
  EXPECT_EQ(with("          0   Delta3", "         90   Delta3"),
            path(kEd) + ":52: Delta3: must be in (-90, 90) deg (is 90)");
  EXPECT_EQ(with("          0   TeetDefl", "        181   TeetDefl"),
            path(kEd) + ":31: TeetDefl: must be in (-180, 180] deg (is 181)");
}

TEST_F(BadInput, UserDefinedTeeterIsRefused) {
  edit(kEd, "          3   NumBl", "          2   NumBl");
  edit(kEd, "False         TeetDOF", "True          TeetDOF");
  edit(kEd, "          0   TeetMod ", "          2   TeetMod ");
  EXPECT_EQ(inputErrorMessage([&] { whirl::io::requireSupported(read()); }),
            path(kEd) +
                ":90: TeetMod: 2 not supported by whirl (a user-defined teeter spring/damper (routine "
                "UserTeet) is not modelled; whirl supports only TeetMod = 0 or 1)");
}

TEST_F(BadInput, PlatformDofAndSimplifiedElastoDynAreRefused) {
  edit(kEd, "False         PtfmPDOF", "True          PtfmPDOF");
  edit(kFst, "          1   CompElast", "          3   CompElast");
  const std::string msg = inputErrorMessage([&] { whirl::io::requireSupported(read()); });
  EXPECT_THAT(msg, StartsWith(path(kFst) + ":13: CompElast: 3 not supported by whirl (only ElastoDyn (CompElast = 1) "
                                           "and ElastoDyn with BeamDyn blades (2) are modelled)"));
  EXPECT_THAT(msg, HasSubstr(path(kEd) + ":23: PtfmPDOF: True not supported by whirl (platform DOFs"));
}

}  // namespace
