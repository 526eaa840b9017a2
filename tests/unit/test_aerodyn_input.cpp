// AeroDyn v15 main files in their OpenFAST v3 (toolbox deck: WakeMod, AFAeroMod, FrozenWake, SkewMod)
// and v5 layouts (Wake_Mod, UA_Mod, DBEMT_Mod = -1, Skew_Mod, BEM_Mod), normalized into one description;
// one test per option whirl refuses and per malformed value. Line numbers are those of the copied files
// (toolbox: WakeMod 6, AFAeroMod 7, … SkewMod 23, AFTabMod 43, NumAFfiles 49, AFNames 50–57; v5:
// Wake_Mod 6, NacelleDrag 11, SectAvg 36, DBEMT_Mod 42, UA_Mod 48).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "src/io/openfast/aerodyn/aero_support.hpp"
#include "src/io/openfast/aerodyn/aerodyn_input.hpp"
#include "tests/unit/aero_test_util.hpp"

namespace {

using testing::HasSubstr;
using whirl::io::AeroDynEnvironment;
using whirl::io::AeroDynInput;
using whirl::io::AeroDynLayout;
using whirl::io::readAeroDyn;
using whirl::io::SkewModel;
using whirl::test::aeroDir;
using whirl::test::AeroScratch;
using whirl::test::inputErrorMessage;

const std::string kV3 = "toolbox/AeroDyn.dat";
const std::string kV5 = "v5/AeroDyn.dat";
const double kPi = 3.14159265358979323846;

TEST(AeroDynInput, OpenFast3ToolboxLayout) {
  const AeroDynInput a = readAeroDyn(aeroDir() / kV3);
  EXPECT_EQ(a.layout, AeroDynLayout::V15);
  EXPECT_EQ(a.wake_key, "WakeMod");
  EXPECT_EQ(a.Wake_Mod, 1);
  EXPECT_TRUE(a.frozen_wake);  // FrozenWake = True
  EXPECT_EQ(a.DBEMT_Mod, -1);
  EXPECT_EQ(a.dbemt_key, "FrozenWake");  // DBEMT_Mod = 2 in the file is unused with WakeMod = 1
  EXPECT_EQ(a.ua_key, "AFAeroMod");
  EXPECT_EQ(a.UA_Mod, 0);
  EXPECT_FALSE(a.unsteadyAero());
  EXPECT_EQ(a.TwrPotent, 0);
  EXPECT_EQ(a.TwrShadow, 0);
  EXPECT_FALSE(a.TwrAero || a.Buoyancy || a.CavitCheck || a.CompAA || a.NacelleDrag || a.SectAvg || a.TFinAero);
  EXPECT_EQ(a.BEM_Mod, 1);
  EXPECT_DOUBLE_EQ(a.AirDens, 1.225);  // "default"
  EXPECT_TRUE(a.AirDens_default);
  EXPECT_DOUBLE_EQ(a.KinVisc, 1.464e-5);
  EXPECT_TRUE(a.KinVisc_default);
  EXPECT_DOUBLE_EQ(a.SpdSound, 335.0);
  EXPECT_EQ(a.skew, SkewModel::Active);  // SkewMod = 2, Pitt/Peters
  EXPECT_EQ(a.skew_key, "SkewMod");
  EXPECT_DOUBLE_EQ(a.SkewModFactor, 15.0 * kPi / 32.0);
  EXPECT_EQ(a.SkewRedistr_Mod, 1);
  EXPECT_TRUE(a.TipLoss);
  EXPECT_TRUE(a.HubLoss);
  EXPECT_TRUE(a.TanInd);
  EXPECT_FALSE(a.AIDrag);
  EXPECT_FALSE(a.TIDrag);
  EXPECT_FALSE(a.IndToler.has_value());  // "Default"
  EXPECT_EQ(a.MaxIter, 100);
  EXPECT_EQ(a.AFTabMod, 1);
  EXPECT_EQ(a.InCol.alpha, 1);
  EXPECT_EQ(a.InCol.cl, 2);
  EXPECT_EQ(a.InCol.cd, 3);
  EXPECT_EQ(a.InCol.cm, 4);
  EXPECT_EQ(a.InCol_Cpmin, 0);
  ASSERT_EQ(a.AFNames.size(), 8u);
  const std::filesystem::path af = (aeroDir() / "5MW_Baseline" / "Airfoils").lexically_normal();
  EXPECT_EQ(a.AFNames.front(), af / "Cylinder1.dat");
  EXPECT_EQ(a.AFNames[2], af / "DU40_A17.dat");
  EXPECT_EQ(a.AFNames.back(), af / "NACA64_A17.dat");
  EXPECT_EQ(a.AFNames_lines, (std::vector<int>{50, 51, 52, 53, 54, 55, 56, 57}));
  EXPECT_TRUE(a.UseBlCm);
  ASSERT_EQ(a.ADBlFile.size(), 3u);
  for (const auto& p : a.ADBlFile) EXPECT_EQ(p, whirl::test::aeroBladeFile().lexically_normal());
  EXPECT_EQ(a.NumTwrNds, 12);
  EXPECT_EQ(a.tower.names, (std::vector<std::string>{"TwrElev", "TwrDiam", "TwrCd", "TwrTI", "TwrCb"}));
  ASSERT_EQ(a.tower.rows(), 12u);
  EXPECT_DOUBLE_EQ(a.tower.column("TwrElev").back(), 87.6);
  EXPECT_DOUBLE_EQ(a.tower.column("TwrDiam").front(), 6.0);
  EXPECT_EQ(a.tower.row_lines.front(), 76);
  EXPECT_TRUE(whirl::io::unsupportedOptions(a).empty());
}

TEST(AeroDynInput, OpenFast5Layout) {
  const AeroDynInput a = readAeroDyn(aeroDir() / kV5);
  EXPECT_EQ(a.layout, AeroDynLayout::V4);
  EXPECT_EQ(a.wake_key, "Wake_Mod");
  EXPECT_EQ(a.Wake_Mod, 1);
  EXPECT_EQ(a.DBEMT_Mod, -1);
  EXPECT_TRUE(a.frozen_wake);
  EXPECT_EQ(a.dbemt_key, "DBEMT_Mod");
  EXPECT_EQ(a.ua_key, "UA_Mod");
  EXPECT_EQ(a.UA_Mod, 0);
  EXPECT_EQ(a.BEM_Mod, 1);
  EXPECT_EQ(a.skew, SkewModel::Active);
  EXPECT_EQ(a.skew_key, "Skew_Mod");
  EXPECT_EQ(a.SkewRedistr_Mod, 1);
  EXPECT_FALSE(a.SkewMomCorr);
  EXPECT_DOUBLE_EQ(a.SkewModFactor, 15.0 * kPi / 32.0);
  EXPECT_FALSE(a.NacelleDrag);
  EXPECT_FALSE(a.SectAvg);
  EXPECT_FALSE(a.AIDrag);
  EXPECT_EQ(a.AFNames.size(), 8u);
  EXPECT_EQ(a.AFNames_lines.front(), 61);
  EXPECT_EQ(a.ADBlFile.size(), 3u);
  EXPECT_EQ(a.tower.names.size(), 7u);  // TwrElev … TwrCa
  EXPECT_EQ(a.tower.rows(), 12u);
  EXPECT_TRUE(whirl::io::unsupportedOptions(a).empty());
}

TEST(AeroDynInput, AeroDyn1503LayoutOfTheCertificationTests) {
  // AeroDyn v15.03 (FAST 8 certification tests, OpenFAST v1): TwrShadow a flag, no FrozenWake,
  // CavitCheck, Buoyancy, CompAA, Patm/Pvap, DBEMT, OLAF, AFTabMod, hub/nacelle/tail-fin sections.
  AeroScratch s;
  std::string text = whirl::test::readText(s.path(kV3));
  for (const char* key : {"FrozenWake",
                          "CavitCheck",
                          "Buoyancy",
                          "CompAA",
                          "AA_InputFile",
                          "Patm",
                          "Pvap",
                          "SkewModFactor",
                          "DBEMT_Mod",
                          "tau1_const",
                          "OLAFInputFileName",
                          "UAStartRad",
                          "UAEndRad",
                          "AFTabMod",
                          "VolHub",
                          "HubCenBx",
                          "VolNac",
                          "NacCenB",
                          "TFinAero",
                          "TFinFile"})
    text = whirl::test::removeLine(text, key);
  text = whirl::test::replaceOnce(text, "          0   TwrShadow", "False         TwrShadow");
  const AeroDynInput a = readAeroDyn(s.write(kV3, text));
  EXPECT_EQ(a.layout, AeroDynLayout::V15);
  EXPECT_EQ(a.Wake_Mod, 1);
  EXPECT_FALSE(a.frozen_wake);  // no FrozenWake key: quasi-steady BEMT
  EXPECT_EQ(a.DBEMT_Mod, 0);
  EXPECT_EQ(a.TwrShadow, 0);
  EXPECT_EQ(a.AFTabMod, 1);
  EXPECT_DOUBLE_EQ(a.Patm, 103500.0);
  EXPECT_DOUBLE_EQ(a.SkewModFactor, 15.0 * kPi / 32.0);
  EXPECT_EQ(a.AFNames.size(), 8u);
  EXPECT_EQ(a.tower.rows(), 12u);
  EXPECT_TRUE(whirl::io::unsupportedOptions(a).empty());
}

TEST(AeroDynInput, DefaultEnvironmentFromTheFstAndExplicitValues) {
  AeroDynEnvironment env;
  env.AirDens = 1.1;
  env.KinVisc = 1.5e-5;
  const AeroDynInput a = readAeroDyn(aeroDir() / kV5, env);
  EXPECT_DOUBLE_EQ(a.AirDens, 1.1);
  EXPECT_DOUBLE_EQ(a.KinVisc, 1.5e-5);
  AeroScratch s;
  s.edit(kV5, "\"default\"     AirDens", "      1.2     AirDens");
  const AeroDynInput b = readAeroDyn(s.path(kV5), env);
  EXPECT_DOUBLE_EQ(b.AirDens, 1.2);
  EXPECT_FALSE(b.AirDens_default);
  EXPECT_DOUBLE_EQ(b.KinVisc, 1.5e-5);
}

TEST(AeroDynInput, LegacyMappings) {
  AeroScratch s;
  // WakeMod = 0: no induction (allowed); FrozenWake = False: quasi-steady BEMT when WakeMod = 1.
  s.edit(kV3, "          1   WakeMod", "          0   WakeMod");
  AeroDynInput a = readAeroDyn(s.path(kV3));
  EXPECT_EQ(a.Wake_Mod, 0);
  EXPECT_TRUE(whirl::io::unsupportedOptions(a).empty());
  s.edit(kV3, "          0   WakeMod", "          1   WakeMod");
  s.edit(kV3, "True          FrozenWake", "False         FrozenWake");
  a = readAeroDyn(s.path(kV3));
  EXPECT_FALSE(a.frozen_wake);
  EXPECT_EQ(a.DBEMT_Mod, 0);
  // SkewMod 0 / 1 → orthogonal / none.
  s.edit(kV3, "          2   SkewMod", "          0   SkewMod");
  EXPECT_EQ(readAeroDyn(s.path(kV3)).skew, SkewModel::Orthogonal);
  s.edit(kV3, "          0   SkewMod", "          1   SkewMod");
  EXPECT_EQ(readAeroDyn(s.path(kV3)).skew, SkewModel::None);
  // v5: DBEMT_Mod = 0 is quasi-steady BEMT (allowed), not frozen.
  s.edit(kV5, "         -1   DBEMT_Mod", "          0   DBEMT_Mod");
  const AeroDynInput b = readAeroDyn(s.path(kV5));
  EXPECT_FALSE(b.frozen_wake);
  EXPECT_TRUE(whirl::io::unsupportedOptions(b).empty());
}

/// One option whirl refuses: file, text replaced, and the message after "<scratch file>:".
struct Refusal {
  const char* name;
  std::string file;
  std::string from;
  std::string to;
  std::string message;
};

class AeroDynRefusal : public testing::TestWithParam<Refusal> {};

TEST_P(AeroDynRefusal, NamesKeyValueAndWhatWhirlSupports) {
  const Refusal& r = GetParam();
  AeroScratch s;
  s.edit(r.file, r.from, r.to);
  const AeroDynInput a = readAeroDyn(s.path(r.file));  // reads: refusing is aero_support's job
  EXPECT_EQ(inputErrorMessage([&] { whirl::io::requireSupported(a); }), s.path(r.file).string() + ":" + r.message);
}

INSTANTIATE_TEST_SUITE_P(
    AeroDynInput, AeroDynRefusal,
    testing::Values(
        Refusal{"WakeModOlaf", kV3, "          1   WakeMod", "          3   WakeMod",
                "6: WakeMod: 3 not supported by whirl (OLAF free-vortex wake; whirl supports only WakeMod = 0 (no "
                "induction) or 1 (BEMT))"},
        Refusal{"Wake_ModOlaf", kV5, "          1   Wake_Mod", "          3   Wake_Mod",
                "6: Wake_Mod: 3 not supported by whirl (OLAF free-vortex wake; whirl supports only Wake_Mod = 0 (no "
                "induction) or 1 (BEMT))"},
        Refusal{"Cavitation", kV3, "False         CavitCheck", "True          CavitCheck",
                "12: CavitCheck: True not supported by whirl (cavitation check; whirl supports only CavitCheck = "
                "False)"},
        Refusal{"Buoyancy", kV3, "False         Buoyancy", "True          Buoyancy",
                "13: Buoyancy: True not supported by whirl (buoyancy; whirl supports only Buoyancy = False)"},
        Refusal{"AeroAcoustics", kV3, "False         CompAA", "True          CompAA",
                "14: CompAA: True not supported by whirl (aeroacoustics; whirl supports only CompAA = False)"},
        Refusal{"NacelleDrag", kV5, "False         NacelleDrag", "True          NacelleDrag",
                "11: NacelleDrag: True not supported by whirl (nacelle drag; whirl supports only NacelleDrag = "
                "False)"},
        Refusal{"SectorAveraging", kV5, "False         SectAvg ", "True          SectAvg ",
                "36: SectAvg: True not supported by whirl (sector-averaged inflow; whirl supports only SectAvg = "
                "False)"},
        Refusal{"TailFin", kV3, "False         TFinAero", "True          TFinAero",
                "70: TFinAero: True not supported by whirl (tail-fin aerodynamics; whirl supports only TFinAero = "
                "False)"},
        Refusal{"CoupledSkew", kV3, "          2   SkewMod", "          3   SkewMod",
                "23: SkewMod: 3 not supported by whirl (the coupled skewed-wake model (dropped in OpenFAST v4); "
                "whirl supports only SkewMod = 0, 1 or 2)"}),
    [](const testing::TestParamInfo<Refusal>& p) { return std::string(p.param.name); });

TEST(AeroDynInput, SeveralRefusalsListedTogether) {
  AeroScratch s;
  s.edit(kV3, "False         CavitCheck", "True          CavitCheck");
  s.edit(kV3, "False         CompAA", "True          CompAA");
  const AeroDynInput a = readAeroDyn(s.path(kV3));
  EXPECT_EQ(whirl::io::unsupportedOptions(a).size(), 2u);
  EXPECT_THAT(inputErrorMessage([&] { whirl::io::requireSupported(a); }),
              HasSubstr("CavitCheck = False); " + s.path(kV3).string() + ":14: CompAA: True not supported"));
}

// Time-domain options whose steady state whirl models (or whose effect it leaves out) are accepted with
// a note each, naming the file, line, key and value and what whirl does instead; OpenFAST's own
// linearization refuses them (AeroDyn v15 input template: "WakeMod cannot be 2 or 3 when linearizing").
struct Substitute {
  const char* name;
  std::string file;
  std::string from;
  std::string to;
  std::string note;  ///< "<line>: key: value: what whirl does" (the path in front)
};

class AeroDynSteadySubstitute : public testing::TestWithParam<Substitute> {};

TEST_P(AeroDynSteadySubstitute, AcceptedWithANote) {
  const Substitute& c = GetParam();
  AeroScratch s;
  s.edit(c.file, c.from, c.to);
  const AeroDynInput a = readAeroDyn(s.path(c.file));
  EXPECT_NO_THROW(whirl::io::requireSupported(a));
  const std::vector<std::string> notes = whirl::io::steadySubstitutes(a);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(notes[0], testing::StartsWith(s.path(c.file).string() + ":" + c.note));
}

INSTANTIATE_TEST_SUITE_P(
    AeroDynInput, AeroDynSteadySubstitute,
    testing::Values(Substitute{"WakeModDbemt", kV3, "          1   WakeMod", "          2   WakeMod",
                               "6: WakeMod: 2: dynamic BEMT: whirl solves the quasi-steady BEMT"},
                    Substitute{"DynamicBemt", kV5, "         -1   DBEMT_Mod", "          2   DBEMT_Mod",
                               "42: DBEMT_Mod: 2: dynamic BEMT: whirl solves the quasi-steady BEMT"},
                    Substitute{"AFAeroModUnsteady", kV3, "          1   AFAeroMod", "          2   AFAeroMod",
                               "7: AFAeroMod: 2: unsteady airfoil aerodynamics: whirl uses the static airfoil tables"},
                    Substitute{"UA_ModUnsteady", kV5, "          0   UA_Mod", "          3   UA_Mod",
                               "48: UA_Mod: 3: unsteady airfoil aerodynamics: whirl uses the static airfoil tables"},
                    Substitute{"TowerPotentialFlow", kV3, "          0   TwrPotent", "          1   TwrPotent",
                               "8: TwrPotent: 1: tower potential flow left out"},
                    Substitute{"TowerShadow", kV3, "          0   TwrShadow", "          2   TwrShadow",
                               "9: TwrShadow: 2: tower shadow left out"},
                    Substitute{"TowerShadowFlag", kV3, "          0   TwrShadow", "True          TwrShadow",
                               "9: TwrShadow: True: tower shadow left out"},
                    Substitute{"TowerAero", kV3, "False         TwrAero", "True          TwrAero",
                               "10: TwrAero: True: aerodynamic drag on the tower left out"}),
    [](const testing::TestParamInfo<Substitute>& p) { return std::string(p.param.name); });

TEST(AeroDynInput, SteadyDeckHasNoNotes) {
  AeroScratch s;
  EXPECT_TRUE(whirl::io::steadySubstitutes(readAeroDyn(s.path(kV3))).empty());
  EXPECT_TRUE(whirl::io::steadySubstitutes(readAeroDyn(s.path(kV5))).empty());
}

/// The toolbox or v5 file edited; the message of reading it, its path shown as "<file>".
std::string editedError(const std::string& file, const std::string& from, const std::string& to) {
  AeroScratch s;
  s.edit(file, from, to);
  return whirl::test::withFilePlaceholder(inputErrorMessage([&] { readAeroDyn(s.path(file)); }), s.path(file));
}

TEST(AeroDynInputErrors, MalformedValues) {
  EXPECT_EQ(editedError(kV3, "\"default\"     AirDens", "       -1     AirDens"),
            "<file>:17: AirDens: must be positive (is -1)");
  EXPECT_EQ(editedError(kV3, "        100   MaxIter", "          0   MaxIter"),
            "<file>:31: MaxIter: must be at least 1 (is 0)");
  EXPECT_EQ(editedError(kV3, "\"Default\"     IndToler", "          0   IndToler"),
            "<file>:30: IndToler: must be positive (is 0)");
  EXPECT_EQ(editedError(kV3, "True          TipLoss", "Maybe         TipLoss"),
            "<file>:25: TipLoss: 'Maybe' is not True or False");
  EXPECT_EQ(editedError(kV3, "          1   InCol_Alfa", "          0   InCol_Alfa"),
            "<file>:44: InCol_Alfa: must be positive (is 0)");
  EXPECT_EQ(editedError(kV3, "          2   SkewMod", "          5   SkewMod"),
            "<file>:23: SkewMod: must be 0, 1, 2 or 3, is 5");
  EXPECT_EQ(editedError(kV5, "          1   Skew_Mod", "          2   Skew_Mod"),
            "<file>:23: Skew_Mod: must be -1, 0 or 1, is 2");
  EXPECT_EQ(editedError(kV3, "          1   AFAeroMod", "          3   AFAeroMod"),
            "<file>:7: AFAeroMod: must be 1 (steady) or 2 (unsteady), is 3");
}

TEST(AeroDynInputErrors, MissingKeysAndBothSpellings) {
  AeroScratch s;
  s.write(kV3, whirl::test::removeLine(whirl::test::readText(s.path(kV3)), "TipLoss"));
  EXPECT_EQ(inputErrorMessage([&] { readAeroDyn(s.path(kV3)); }),
            s.path(kV3).string() + ": TipLoss: key not found in this file");
  EXPECT_EQ(editedError(kV5, "          1   Wake_Mod ", "          1   Wake_Mod\n          1   WakeMod "),
            "<file>:6: Wake_Mod: cannot have both Wake_Mod and its legacy spelling WakeMod (line 7)");
  EXPECT_EQ(editedError(kV5, "          1   Wake_Mod ", "          1   Wake_Model "),
            "<file>:6: Wake_Model: not a key of an OpenFAST AeroDyn v15 file (expected WakeMod or Wake_Mod or "
            "AFAeroMod here): OpenFAST reads by position, so an extra line shifts every later value; remove it (or "
            "check the file type)");
}

TEST(AeroDynInputErrors, AirfoilListShorterThanNumAFfiles) {
  EXPECT_EQ(editedError(kV3, "          8   NumAFfiles", "          9   NumAFfiles"),
            "<file>:49: NumAFfiles: announces 9 airfoil files, only 8 names follow AFNames (line 50)");
}

TEST(AeroDynInputErrors, TruncatedTowerTable) {
  EXPECT_EQ(editedError(kV3, "         12   NumTwrNds", "         13   NumTwrNds"),
            "<file>:73: NumTwrNds: table has 12 rows, 13 expected: line 88 is not a row of numbers (truncated table?)");
  EXPECT_EQ(editedError(kV3, "8.7600000E+01  3.8700000E+00  1.0000000E+00", "8.7600000E+01  nan  1.0000000E+00"),
            "<file>:87: TwrDiam: value is NaN");
}

}  // namespace

namespace {

// Dynamic inflow and unsteady-airfoil keys (issue 47): tau1_const, UAStartRad, UAEndRad, AoA34 as read,
// AeroDyn's fallbacks when the lines are missing, and the refusals.
TEST(AeroDynInput, DynamicInflowAndUnsteadyAirfoilKeys) {
  const AeroDynInput v3 = readAeroDyn(aeroDir() / kV3);
  EXPECT_EQ(v3.tau1_const, std::optional<double>(4.0));
  EXPECT_DOUBLE_EQ(v3.UAStartRad, 0.15);
  EXPECT_DOUBLE_EQ(v3.UAEndRad, 1.0);
  EXPECT_TRUE(v3.AoA34);  // no AoA34 line before OpenFAST v4: true, as AeroDyn
  const AeroDynInput v5 = readAeroDyn(aeroDir() / kV5);
  EXPECT_FALSE(v5.AoA34);
  EXPECT_DOUBLE_EQ(v5.UAStartRad, 0.0);
  // The r-test deck with UA_Mod 4 and DBEMT_Mod 3 (tests/data/openfast-lin/ua4-dbemt3/case/AD.dat):
  // no UAStartRad/UAEndRad lines, 0 and 1 (AeroDyn_IO.f90).
  const AeroDynInput ua = readAeroDyn(whirl::test::sourceDir() / "tests/data/openfast-lin/ua4-dbemt3/case/AD.dat");
  EXPECT_EQ(ua.UA_Mod, 4);
  EXPECT_EQ(ua.DBEMT_Mod, 3);
  EXPECT_EQ(ua.tau1_const, std::optional<double>(100.0));
  EXPECT_DOUBLE_EQ(ua.UAStartRad, 0.0);
  EXPECT_DOUBLE_EQ(ua.UAEndRad, 1.0);
}

TEST(AeroDynInputErrors, DynamicInflowAndUnsteadyAirfoilKeys) {
  const std::string dbemt3 = "          3   DBEMT_Mod";
  {
    AeroScratch s;
    s.edit(kV5, "         -1   DBEMT_Mod", dbemt3);
    EXPECT_EQ(readAeroDyn(s.path(kV5)).tau1_const, std::optional<double>(4.0));  // accepted
    s.edit(kV5, "          4   tau1_const", "          0   tau1_const");
    EXPECT_EQ(whirl::test::withFilePlaceholder(inputErrorMessage([&] { readAeroDyn(s.path(kV5)); }), s.path(kV5)),
              "<file>:43: tau1_const: must be > 0 with DBEMT_Mod 3 (is 0)");
  }
  EXPECT_EQ(editedError(kV5, "          0   UAStartRad", "        1.5   UAStartRad"),
            "<file>:51: UAStartRad: must be a fraction of the rotor radius in [0, 1] (is 1.5)");
  EXPECT_EQ(editedError(kV5, "          1   UAEndRad", "       -0.1   UAEndRad"),
            "<file>:52: UAEndRad: must be a fraction of the rotor radius in [0, 1] (is -0.1)");
  EXPECT_EQ(editedError(kV3, "1.0           UAEndRad", "0.1           UAEndRad"),
            "<file>:41: UAEndRad: must not be below UAStartRad (0.1 < 0.15): no element would have UA");
}

}  // namespace
