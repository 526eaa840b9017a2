// `whirl lin` on the OpenFAST `.lin` files of `../shared/data/decks/lin` (issue 16; copies in
// tests/data/openfast/decks/lin): mode names from state descriptions and participation factors
// (modal/participation.hpp), outputs that do not pair across blades, BeamDyn state ordering,
// HydroDyn first-order states, real roots; and whirl's own `.lin` files read back into the names of
// `whirl modes`.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

const std::string kLin = "tests/data/openfast/decks/lin/";

nlohmann::json linJson(const std::string& args, test::Run* run = nullptr) {
  const auto r = test::whirl("lin " + args + " --format json");
  if (run) *run = r;
  EXPECT_EQ(r.code, 0) << r.err;
  return r.code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

std::map<std::string, int> nameCounts(const nlohmann::json& j) {
  std::map<std::string, int> n;
  for (const auto& m : j["modes"]) ++n[m["name"].get<std::string>()];
  return n;
}

// The 14 ElastoDyn DOFs of these standstill turbines (tower 2 FA + 2 SS, drivetrain, 3 blades × flap
// 1, edge 1, flap 2), one mode each: each name once. Before issue 16, 9 of these 14 modes were misnamed
// (tower FA 1 called flap 1 collective, drivetrain flap 1 collective, flap 1 BW twice, …).
const std::map<std::string, int> kStandstillNames = {{"tower FA 1", 1}, {"tower SS 1", 1}, {"tower FA 2", 1},
                                                     {"tower SS 2", 1}, {"drivetrain", 1}, {"flap 1 collective", 1},
                                                     {"flap 1 cos", 1}, {"flap 1 sin", 1}, {"edge 1 collective", 1},
                                                     {"edge 1 cos", 1}, {"edge 1 sin", 1}, {"flap 2 collective", 1},
                                                     {"flap 2 cos", 1}, {"flap 2 sin", 1}};

TEST(CliLinDecks, StandstillElastoDynOneNamePerDof) {
  // Linearized at Ω = 2e-4 rad/s: named as parked (cos / sin, not a whirl direction).
  EXPECT_EQ(nameCounts(linJson(kLin + "Standstill_ForID_ED.1.lin")), kStandstillNames);
}

TEST(CliLinDecks, UnpairedOutputsLeftOutAndSaid) {
  test::Run r;
  const auto j = linJson(kLin + "Standstill.1.lin", &r);
  EXPECT_EQ(nameCounts(j), kStandstillNames);
  // RootFxc1 is listed twice for blade 1: the RootFxc set of the three blades does not pair.
  EXPECT_THAT(r.err, HasSubstr("whirl: note: tests/data/openfast/decks/lin/Standstill.1.lin: 4 rotating outputs do "
                               "not pair across blades and were left out of the multiblade transform"));
  EXPECT_THAT(r.err, HasSubstr("ED RootFxc1 (line 118), ED RootFxc1 (line 119), ED RootFxc2 (line 125), ED RootFxc3 "
                               "(line 131)"));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(CliLinDecks, BeamDynStatesAfterElastoDynPairByDescription) {
  // ED q, ED q̇, then per blade BD q, BD q̇ (before: "displacement states must come first").
  const auto j = linJson(kLin + "BAR_URC_EDBD.1.lin");
  const auto n = nameCounts(j);
  EXPECT_EQ(j["modes"][0]["name"], "tower SS 1");
  EXPECT_EQ(j["modes"][1]["name"], "tower FA 1");
  EXPECT_EQ(n.count("BD node 2 translation X collective"), 1u);
  EXPECT_EQ(n.count("BD node 2 translation Y BW"), 1u);
  EXPECT_EQ(n.count("BD node 2 translation Y FW"), 1u);
  const auto& c = j["coordinates"];
  EXPECT_EQ(c.size(), 22u);  // 4 tower + 3 blades × 6 node DOFs
  EXPECT_EQ(c[4], "BD node 2 translation X collective");
}

TEST(CliLinDecks, HydroDynFirstOrderStatesNameTheirModes) {
  const auto j = linJson(kLin + "StandstillSemi_ForID_EDHD.1.lin");
  std::map<std::string, double> lowest;  // name → lowest frequency with that name
  int real_roots = 0;
  for (const auto& m : j["modes"]) {
    const std::string name = m["name"];
    if (!lowest.count(name)) lowest[name] = m["freq_hz"];
    if (m["damped_freq_hz"] == 0.0 && m["freq_hz"] > 0.0) {
      ++real_roots;
      EXPECT_NEAR(std::abs(m["damping_ratio"].get<double>()), 1.0, 1e-12) << name;  // one real root, as MBC3
    }
  }
  for (const char* dof : {"surge", "sway", "heave", "roll", "pitch", "yaw"})
    EXPECT_TRUE(lowest.count(std::string("platform ") + dof)) << dof;
  EXPECT_GT(real_roots, 0);
  // The wave-excitation filter's zero root is no rigid-body motion.
  EXPECT_EQ(j["modes"][0]["name"], "HydroDyn wave excitation yaw (zero root)");
  EXPECT_FALSE(j["modes"][0]["rigid_body"].get<bool>());
  EXPECT_TRUE(lowest.count("HydroDyn radiation surge"));
  // The floater's modes are below 0.1 Hz; the first tower modes above 0.4 Hz (before: "tower FA 1"
  // at 0.035 Hz, the platform pitch).
  EXPECT_LT(lowest["platform pitch"], 0.1);
  EXPECT_GT(lowest["tower FA 1"], 0.4);
  EXPECT_GT(lowest["tower SS 1"], 0.4);
  for (const char* blade : {"flap 1 collective", "flap 1 cos", "flap 1 sin", "edge 1 collective", "flap 2 collective"})
    EXPECT_TRUE(lowest.count(blade)) << blade;
}

// whirl's own .lin files read back: the names of `whirl modes` on the same model (before: mode 3,
// the tower fore-aft, came back as "flap 1 BW").
void expectSameNames(const std::string& rpm, int azimuths) {
  const std::string fst = "cases/nrel5mw/Main_Onshore.fst";
  const auto dir = test::freshDir("lin_names_" + rpm);
  const auto r = test::whirl("export " + fst + " --rpm " + rpm + " --azimuths " + std::to_string(azimuths) +
                             " --format lin --out " + dir.string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::string files;
  for (const auto& e : fs::directory_iterator(dir)) files += " " + e.path().string();
  const auto back = linJson(files);
  const auto own = test::whirl("modes " + fst + " --rpm " + rpm + " --azimuths " + std::to_string(azimuths) +
                               " --format json");
  ASSERT_EQ(own.code, 0) << own.err;
  const auto jo = nlohmann::json::parse(own.out);
  ASSERT_EQ(back["modes"].size(), jo["modes"].size());
  for (size_t i = 0; i < jo["modes"].size(); ++i) EXPECT_EQ(back["modes"][i]["name"], jo["modes"][i]["name"]) << i;
}

TEST(CliLinDecks, OwnLinFilesNamedAsWhirlModesAt9Rpm) { expectSameNames("9", 12); }

// OpenFAST's own 9 rpm files of the toolbox NREL 5MW deck (ElastoDyn + AeroDyn + ServoDyn) and
// `whirl modes` on that deck: the same mode names (whirl's aerodynamics differ a little, so the
// frequencies are not compared here; tests/unit/test_mbc_openfast.cpp checks them against MBC3).
TEST(CliLinDecks, OpenFastLinFilesNamedAsWhirlModesOnTheirDeck) {
  const std::string d = "tests/data/openfast-lin/rotating-9rpm/";
  const auto lin = linJson(d + "Main.1.lin " + d + "Main.12.lin " + d + "Main.24.lin");
  const auto own = test::whirl(
      "modes tests/data/openfast/decks/toolbox-nrel5mw/5MW_Land_Lin_Rotating/Main.fst --rpm 9 "
      "--format json");
  ASSERT_EQ(own.code, 0) << own.err;
  const auto jo = nlohmann::json::parse(own.out);
  EXPECT_EQ(nameCounts(lin), nameCounts(jo));
  ASSERT_EQ(lin["modes"].size(), jo["modes"].size());
  for (size_t i = 0; i < jo["modes"].size(); ++i) EXPECT_EQ(lin["modes"][i]["name"], jo["modes"][i]["name"]) << i;
}

TEST(CliLinDecks, OwnLinFilesNamedAsWhirlModesParked) { expectSameNames("0", 1); }

// The OpenFAST toolbox's blade-only deck (NumBl = 1: flap 1, edge 1, flap 2 of one NREL 5MW blade,
// parked, everything else off) and OpenFAST's linearization of it (its Main.1.lin): the same names,
// and frequencies within 0.05 % — whirl's structural model reproduces ElastoDyn's to a few hundredths
// of a percent where it reads the deck (issue 16); measured 0.012 %, 0.000 %, 0.008 %.
TEST(CliLinDecks, BladeOnlyDeckMatchesOpenFastLinearization) {
  const std::string d = "tests/data/openfast/decks/toolbox-nrel5mw/5MW_Land_Lin_BladeOnly/";
  const auto lin = linJson(d + "Main.1.lin");
  const auto own = test::whirl("modes " + d + "Main.fst --format json");
  ASSERT_EQ(own.code, 0) << own.err;
  const auto jo = nlohmann::json::parse(own.out);
  EXPECT_FALSE(jo["floquet"].get<bool>());
  ASSERT_EQ(jo["modes"].size(), 3u);
  ASSERT_EQ(lin["modes"].size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(lin["modes"][i]["name"], jo["modes"][i]["name"]) << i;
    const double f_of = lin["modes"][i]["freq_hz"].get<double>(), f = jo["modes"][i]["freq_hz"].get<double>();
    EXPECT_NEAR(f, f_of, 5e-4 * f_of) << jo["modes"][i]["name"];
  }
  EXPECT_EQ(jo["modes"][0]["name"], "blade 1 flap 1");
}

}  // namespace
}  // namespace whirl
