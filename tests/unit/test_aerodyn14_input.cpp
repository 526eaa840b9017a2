// AeroDyn v14 main and airfoil files (FAST v8 certification tests, CompAero = 1): read by position
// into the same description as AeroDyn v15 files; one test per malformed input. Values are those of the
// copied AWT-27 (Test01) and SWRT files in tests/data/openfast/decks/certtest.
#include <gtest/gtest.h>

#include "src/io/openfast/aerodyn/aero_deck.hpp"
#include "src/io/openfast/aerodyn/aero_deck14.hpp"
#include "src/io/openfast/aerodyn/aerodyn14_input.hpp"
#include "src/io/openfast/aerodyn/airfoil14_input.hpp"
#include "src/io/openfast/fst_input.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using whirl::io::readAeroDyn14;
using whirl::io::readAirfoil14;
using whirl::test::inputErrorMessage;
using whirl::test::readText;
using whirl::test::replaceOnce;
using whirl::test::ScratchDir;

std::filesystem::path certtest() { return whirl::test::openfastDataDir() / "decks" / "certtest"; }

TEST(AeroDyn14, ReadsTheAwt27File) {
  const auto a = readAeroDyn14(certtest() / "AWT27" / "Test01_AD.ipt");
  EXPECT_EQ(a.StallMod, "BEDDOES");
  EXPECT_FALSE(a.UseCm);
  EXPECT_EQ(a.InfModel, "DYNIN");
  EXPECT_EQ(a.IndModel, "SWIRL");
  EXPECT_EQ(a.TLModel, "PRANDTL");
  EXPECT_EQ(a.HLModel, "NONE");
  EXPECT_DOUBLE_EQ(a.TwrShad, 0.3);
  EXPECT_DOUBLE_EQ(a.AirDens, 1.225);
  ASSERT_EQ(a.FoilNm.size(), 10u);
  EXPECT_EQ(a.FoilNm[9].filename(), "AWT27_95.dat");
  EXPECT_EQ(a.FoilNm_lines[9], 26);
  ASSERT_EQ(a.RNodes.size(), 10u);
  // Element centres from the rotor centre: the first strip starts at HubRad = 1.184 m, the last ends at
  // TipRad = 13.757 m (Test01_ElastoDyn.dat).
  EXPECT_DOUBLE_EQ(a.RNodes.front(), 1.81265);
  EXPECT_NEAR(a.RNodes.front() - a.DRNodes.front() / 2, 1.184, 1e-12);
  EXPECT_NEAR(a.RNodes.back() + a.DRNodes.back() / 2, 13.757, 1e-12);
  EXPECT_DOUBLE_EQ(a.AeroTwst.front(), 5.8);
  EXPECT_DOUBLE_EQ(a.Chord.back(), 0.493);
  EXPECT_EQ(a.NFoil.back(), 10);
  EXPECT_EQ(a.row_lines.front(), 29);
}

TEST(AeroDyn14, MalformedFilesNamedWithLineAndKey) {
  const std::string text = readText(certtest() / "AWT27" / "Test01_AD.ipt");
  const struct {
    std::string from, to, message;
  } cases[] = {
      {"\"SWIRL\"       IndModel", "\"SPIRAL\"      IndModel",
       ":6: IndModel: must be one of NONE, WAKE, SWIRL (is \"SPIRAL\")"},
      {"1.225   AirDens", "-1.2    AirDens", ":13: AirDens: must be positive (is -1.2)"},
      {"         10   BldNodes", "         11   BldNodes",
       ":27: BldNodes: element table has 10 rows, 11 expected: the file ends (truncated table?)"},
      {"          1      NOPRINT", "         11      NOPRINT",
       ":29: NFoil: must be an airfoil of FoilNm, a whole number from 1 to NumFoil = 10 (is 11)"},
      {"3.0699500E+00", "1.0000000E+00", ":30: RNodes: must increase from element to element (1 after 1.81265)"},
      {"\"NONE\"        HLModel", "\"NONE\"        HubLoss", ":9: HubLoss: not a key of an OpenFAST AeroDyn v14 file"},
      {"\"PRANDtl\"     TLModel", "\"GTECH\"       TLModel", ""},  // read; refused when the deck is built
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.to);
    ScratchDir s;
    const auto p = s.write("AD.ipt", replaceOnce(text, c.from, c.to));
    if (c.message.empty()) {
      EXPECT_NO_THROW(readAeroDyn14(p));
      EXPECT_EQ(inputErrorMessage([&] { whirl::io::aerodynFromV14(readAeroDyn14(p)); }),
                p.string() +
                    ":8: TLModel: \"GTECH\" not supported by whirl (the Georgia Tech tip loss, which AeroDyn "
                    "v15 does not have; whirl supports only TLModel = PRANDtl or NONE)");
    } else {
      const std::string msg = inputErrorMessage([&] { readAeroDyn14(p); });
      EXPECT_EQ(msg.substr(0, p.string().size() + c.message.size()), p.string() + c.message) << msg;
    }
  }
}

TEST(Airfoil14, ReadsOneTableWithoutCm) {
  const auto a = readAirfoil14(certtest() / "AWT27" / "AeroData" / "AWT27_05.dat", false);
  ASSERT_EQ(a.tables.size(), 1u);
  const auto& t = a.tables.front();
  EXPECT_EQ(t.alpha_deg.size(), 181u);  // -180:2:180 (lines 15-195)
  EXPECT_DOUBLE_EQ(t.alpha_deg.front(), -180.0);
  EXPECT_DOUBLE_EQ(t.alpha_deg.back(), 180.0);
  EXPECT_TRUE(t.cm.empty());
  // α = 0: Cl 0.4434, Cd 0.01072 (line 105)
  EXPECT_DOUBLE_EQ(t.cl[90], 0.4434);
  EXPECT_DOUBLE_EQ(t.cd[90], 0.01072);
  EXPECT_EQ(t.row_lines[90], 105);
  EXPECT_DOUBLE_EQ(*t.ua.alpha1, 13.0);  // stall angle
  EXPECT_DOUBLE_EQ(*t.ua.Cd0, 0.01072);  // minimum Cd
}

TEST(Airfoil14, ReadsSideBySideTables) {
  const auto a = readAirfoil14(certtest() / "SWRT" / "AeroData" / "SH3052Mod_AllRe_Hanley.dat", false);
  ASSERT_EQ(a.tables.size(), 3u);
  EXPECT_DOUBLE_EQ(a.tables[0].re, 0.3);
  EXPECT_DOUBLE_EQ(a.tables[2].re, 1.2);
  // α = -170: Cl 0.41544 / 0.42561 / 0.42471, Cd 0.1026 / 0.0855 / 0.1116 (line 16)
  EXPECT_DOUBLE_EQ(a.tables[0].cl[1], 0.41544);
  EXPECT_DOUBLE_EQ(a.tables[1].cl[1], 0.42561);
  EXPECT_DOUBLE_EQ(a.tables[2].cd[1], 0.1116);
}

TEST(Airfoil14, MalformedFilesNamedWithLine) {
  const std::string text = readText(certtest() / "AWT27" / "AeroData" / "AWT27_05.dat");
  const struct {
    std::string from, to, message;
    bool use_cm;
  } cases[] = {
      {"1       Number of airfoil tables", "x       Number of airfoil tables",
       ":3: number of tables: expected 1 number, word 1 is 'x'", false},
      {"13      Stall angle", "nan     Stall angle", ":5: stall angle: expected 1 number, word 1 is 'nan'", false},
      {"0       0.4434  0.01072", "-2      0.4434  0.01072", ":105: Alpha: must increase from row to row (-2 after -2)",
       false},
      {"0       0.4434  0.01072", "0       0.4434", ":105: row has 2 numbers, 1 table(s) without Cm (UseCm) need 3",
       false},
      {"", "", ":15: row has 3 numbers, 1 table(s) with Cm (UseCm) need 4", true},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.to);
    ScratchDir s;
    const auto p = s.write("af.dat", c.from.empty() ? text : replaceOnce(text, c.from, c.to));
    const std::string msg = inputErrorMessage([&] { readAirfoil14(p, c.use_cm); });
    EXPECT_EQ(msg, p.string() + c.message);
  }
  ScratchDir s;
  const auto p = s.write("short.dat", text.substr(0, text.find("Stall angle")));
  EXPECT_EQ(inputErrorMessage([&] { readAirfoil14(p, false); }),
            p.string() + ":6: unused: the file ends (truncated header?)");
}

// An exact repeat of the previous row (DU25_A17 of the offshore certification decks repeats -13 deg) is
// skipped; the same angle with other coefficients stays an error (MalformedFilesNamedWithLine).
TEST(Airfoil14, ExactlyRepeatedRowIsSkipped) {
  const std::string text = readText(certtest() / "AWT27" / "AeroData" / "AWT27_05.dat");
  const std::string row = "0       0.4434  0.01072";
  const std::size_t at = text.find(row);
  ASSERT_NE(at, std::string::npos);
  const std::size_t end = text.find('\n', at);
  const std::string line = text.substr(at, end - at);
  ScratchDir s;
  const auto p = s.write("af.dat", text.substr(0, end + 1) + line + text.substr(end));
  const auto with = readAirfoil14(p, false), without = readAirfoil14(s.write("b.dat", text), false);
  EXPECT_EQ(with.tables[0].alpha_deg, without.tables[0].alpha_deg);
  EXPECT_EQ(with.tables[0].cl, without.tables[0].cl);
  EXPECT_EQ(with.tables[0].cd, without.tables[0].cd);
}

TEST(AeroDyn14, DeckBecomesV15Elements) {
  const auto deck = whirl::io::readAeroDeck(whirl::io::readFst(certtest() / "Test01.fst"));
  EXPECT_EQ(deck.aerodyn.Wake_Mod, 1);
  EXPECT_TRUE(deck.aerodyn.TanInd);    // SWIRL
  EXPECT_FALSE(deck.aerodyn.HubLoss);  // HLModel = NONE
  EXPECT_FALSE(deck.aerodyn.UseBlCm);  // NO_CM
  EXPECT_FALSE(deck.aerodyn.AIDrag);   // as NREL's v15 version of the file, Test01_AD15.ipt
  EXPECT_FALSE(deck.aerodyn.TIDrag);
  ASSERT_EQ(deck.blades.size(), 3u);
  EXPECT_EQ(deck.blades[1].element_width.size(), 10u);
  EXPECT_EQ(deck.airfoils.size(), 10u);
  // A missing airfoil file is named with the line that names it.
  {
    ScratchDir s;
    const auto fst = s.copy(certtest() / "Test06.fst");
    for (const char* f : {"AOC/Test06_ElastoDyn.dat", "AOC/AOC_Blade.dat", "AOC/AOC_Tower.dat", "AOC/Test06_AD.ipt",
                          "AOC/Test06_InflowWind.dat", "AOC/Test06_ServoDyn.dat", "AOC/AeroData/S814_1.dat"})
      s.copy(certtest() / f, f);
    EXPECT_EQ(inputErrorMessage([&] { whirl::io::readAeroDeck(whirl::io::readFst(fst)); }),
              (s.path() / "AOC/Test06_AD.ipt").string() +
                  ":18: FoilNm(2): file not found: " + (s.path() / "AOC/AeroData/S814_15.dat").string());
  }
  // Notes: the BEMT, dynamic inflow, dynamic stall, tower shadow, then the wind file.
  ASSERT_GE(deck.notes.size(), 4u);
  EXPECT_NE(deck.notes[1].find(":5: InfModel: \"DYNIN\": dynamic inflow"), std::string::npos) << deck.notes[1];
}

TEST(AeroDyn14, DragInTheInductionsAsInfModelSays) {
  const std::string text = readText(certtest() / "AWT27" / "Test01_AD.ipt");
  const struct {
    const char* inf;
    bool axial, tangential;
  } cases[] = {{"EQUIL", false, false}, {"EQUILDA", true, false}, {"EQUILDT", false, true}, {"EQUILDB", true, true}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.inf);
    ScratchDir s;
    const auto p = s.write("AD.ipt", replaceOnce(text, "\"DYNIN\" ", std::string("\"") + c.inf + "\""));
    const auto a = whirl::io::aerodynFromV14(readAeroDyn14(p));
    EXPECT_EQ(a.AIDrag, c.axial);
    EXPECT_EQ(a.TIDrag, c.tangential);
  }
}

// SWRT: three Reynolds tables per airfoil file and RENUM after the element table (SWRT_AeroDyn.dat:38):
// interpolated on the Reynolds number (no note); USER (a user value) is refused.
TEST(AeroDyn14, InterpolationBetweenTablesOnReynoldsUserRefusedFirstTableOtherwise) {
  const auto swrt = certtest() / "SWRT" / "SWRT_AeroDyn.dat";
  const auto v14 = readAeroDyn14(swrt);
  EXPECT_EQ(v14.MultiTab, "RENUM");
  const auto af = readAirfoil14(certtest() / "SWRT" / "AeroData" / "SH3052Mod_AllRe_Hanley.dat", false);
  EXPECT_FALSE(whirl::io::multipleTables(v14, {af}));
  ScratchDir s;
  const std::string text = readText(swrt);
  const auto user_file = s.write("user.dat", replaceOnce(text, "ReNum", "USER"));
  const auto user = readAeroDyn14(user_file);
  EXPECT_EQ(inputErrorMessage([&] { whirl::io::multipleTables(user, {af}); }),
            user_file.string() + ":" + std::to_string(user.MultiTab_line) +
                ": MultiTab: USER not supported by whirl (interpolation between airfoil tables on a user value, for "
                "SH3052Mod_AllRe_Hanley.dat; whirl supports SINGLE, the first table of each file, and RENUM)");
  const auto single = s.write("single.dat", replaceOnce(text, "ReNum", "SINGLE"));
  EXPECT_FALSE(whirl::io::multipleTables(readAeroDyn14(single), {af}));
  const auto absent = s.write("absent.dat", replaceOnce(text, "ReNum", ""));
  const auto note = whirl::io::multipleTables(readAeroDyn14(absent), {af});
  ASSERT_TRUE(note);
  EXPECT_NE(note->find("MultiTab: absent at the end of the file: the first table"), std::string::npos) << *note;
  // One table per file: the option does not matter.
  const auto one = readAirfoil14(certtest() / "AWT27" / "AeroData" / "AWT27_05.dat", false);
  EXPECT_FALSE(whirl::io::multipleTables(v14, {one}));
}

}  // namespace
