// Public OpenFAST decks as users bring them (issue 16; tests/data/openfast/README.md, `decks/`): the IEA
// 3.4 MW reference turbine written by WISDEM (`BldFile1`, `BldFlDmp1`, …), a FAST v7 primary file,
// a deck with platform DOFs on, each refused on one line, and a yawed rotor with elements that have no
// BEM root.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;

const std::string kDecks = "tests/data/openfast/decks/";

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

// The structural model of the IEA deck (its AeroDyn, airfoils and InflowWind are not copied:
// `--set CompAero=0`). Before issue 16: "BldFile(1): key not found".
TEST(CliDecks, Iea34WisdemSpellingRuns) {
  const auto r = test::whirl("modes " + kDecks + "IEA-3.4-130-RWT/IEA-3.4-130-RWT.fst --set CompAero=0 --format json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("tower FA 1"));
  EXPECT_THAT(r.err, Not(HasSubstr("error")));
}

TEST(CliDecks, FastV7PrimaryFileOneLine) {
  const auto r = test::whirl("modes " + kDecks + "certtest/FAST_v7/Test01.fst");
  EXPECT_NE(r.code, 0);
  EXPECT_THAT(r.err, HasSubstr("Test01.fst:7: ADAMSPrep: this is a FAST v7 primary input file"));
  EXPECT_EQ(lines(r.err), 1) << r.err;
}

// AOC Test08 (fixed yaw error, 11 m/s) turning: at the root the in-plane wind of the yaw exceeds the
// rotation at some azimuths; those elements take the geometric inflow (AeroDyn's fallback) and a note
// per rotor speed says how many. Before: "no valid BEM inflow angle" refused the deck.
TEST(CliDecks, YawedRotorWithoutABemRootAtTheRootRunsWithOneNote) {
  const auto dir = test::freshDir("decks_test08");
  const auto r = test::whirl("campbell " + kDecks + "certtest/Test08.fst --rpm 32.07:32.07:64.14 --no-plot --out " +
                             dir.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("have no valid BEM inflow angle"));
  EXPECT_THAT(r.err, HasSubstr("they take the geometric inflow angle without induction, as AeroDyn does"));
  // One note per rotor speed, naming it.
  EXPECT_THAT(r.err, HasSubstr("Test08.fst: 32.07 rpm: "));
  EXPECT_THAT(r.err, HasSubstr("Test08.fst: 64.14 rpm: "));
  EXPECT_EQ(lines(r.err), 4) << "the two notes of the AeroDyn keys and one per rotor speed: " << r.err;
}

// AWT-27 Test03 in its steady wind section's still air (HWindSpeed = 0), turning at half its rated speed:
// with the teeter at equilibrium one blade element's normal velocity, from the rotor's own kinematics,
// sits at AeroDyn's zero-velocity limit (|Vx| = 1e-3 m/s), where its loads jump (no induction below,
// BEM above). Zero lies between the teeter loads of the two sides: the equilibrium of Filippov (1988),
// taken at the jump. Before: "did not converge in 50 Newton iterations: residual 3.509651 on DOF
// 'teeter'". Its modes are those of the nearly still air that converges without a jump (1e-4 m/s): the
// largest relative frequency difference measured is 9.1e-5 (teeter BW, 93 % damped), the rigid-body yaw
// (9e-5 Hz, a near-zero root) aside.
TEST(CliDecks, StillAirTeeterEquilibriumOnALoadJump) {
  const std::string deck = "modes " + kDecks + "certtest/Test03.fst --rpm 26.6665 --format json";
  const auto still = test::whirl(deck);
  ASSERT_EQ(still.code, 0) << still.err;
  // A teetered two-bladed rotor: Floquet analysis over 36 azimuths, most of them on the jump.
  EXPECT_THAT(still.err, HasSubstr(" of 36 operating points the equilibrium lies on a jump of the loads, taken on "
                                   "the side with the smaller residual (a Filippov equilibrium)"));
  EXPECT_THAT(still.err, HasSubstr("the load on DOF 'teeter' jumps from -3.5"));
  EXPECT_THAT(still.err, HasSubstr("crosses AeroDyn's zero-velocity limit of its normal velocity (|Vx| = 0.001 m/s"));
  const auto breeze = test::whirl(deck + " --set HWindSpeed=0.0001");
  ASSERT_EQ(breeze.code, 0) << breeze.err;
  EXPECT_THAT(breeze.err, Not(HasSubstr("jump")));
  const auto a = nlohmann::json::parse(still.out).at("modes"), b = nlohmann::json::parse(breeze.out).at("modes");
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    const std::string name = a[i].at("name");
    ASSERT_EQ(name, b[i].at("name").get<std::string>());
    if (name.find("rigid body") != std::string::npos) continue;
    const double fa = a[i].at("freq_hz"), fb = b[i].at("freq_hz");
    EXPECT_NEAR(fa, fb, 5e-4 * fb) << name;
    EXPECT_NEAR(a[i].at("damping_ratio").get<double>(), b[i].at("damping_ratio").get<double>(), 5e-4) << name;
  }
}

TEST(CliDecks, PlatformDofsOneLineOneReason) {
  const auto r = test::whirl("modes " + kDecks +
                             "IEA-3.4-130-RWT/IEA-3.4-130-RWT.fst --set CompAero=0 --set PtfmSgDOF=True "
                             "--set PtfmHvDOF=True --set PtfmPDOF=True");
  EXPECT_NE(r.code, 0);
  EXPECT_THAT(r.err, HasSubstr("PtfmSgDOF: True not supported by whirl (platform DOFs are not modelled"));
  EXPECT_THAT(r.err, HasSubstr("and PtfmHvDOF, PtfmPDOF are on too: no hydrostatics or mooring"));
  EXPECT_EQ(r.err.find(';'), std::string::npos) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.find("not supported"), r.err.rfind("not supported")) << r.err;
}

// WindPACT 1.5 MW parked (certification Test14, no aero): its collective and cosine second flap
// patterns both couple with the tower fore-aft and mix; before issue 16 both modes were named
// "flap 2 cos" and none "flap 2 collective". One name per mode pattern.
TEST(CliDecks, WindPactParkedOneNamePerModePattern) {
  const auto r = test::whirl("modes " + kDecks + "certtest/Test14.fst --rpm 0 --format json");
  ASSERT_EQ(r.code, 0) << r.err;
  std::map<std::string, int> count;
  const auto j = nlohmann::json::parse(r.out);
  for (const auto& m : j["modes"]) ++count[m["name"].get<std::string>()];
  for (const auto& [name, n] : count) EXPECT_EQ(n, 1) << name;
  EXPECT_EQ(count["flap 2 collective"], 1);
  EXPECT_EQ(count["flap 2 cos"], 1);
  EXPECT_EQ(count["flap 2 sin"], 1);
}

// AeroDyn v14 (CompAero = 1) against AeroDyn v15 on the same rotor: AOC Test06 with its v14 file and with
// NREL's v15 version of it (Test06_AD15.ipt: the v14 element centres as nodes plus a root and a tip node,
// the same airfoil tables, TanInd, tip and hub loss, no drag in the inductions). Each element sees the same
// BEM inputs; the files differ in the quadrature: v14 strips (load at the centre times DRNodes) against v15
// trapezoids, whose tip node carries no load (Prandtl's tip loss is 0 there). The strips therefore give
// more, measured +4.3 to +5.9 % power and +3.6 to +4.7 % thrust at 6, 10 and 14 m/s (64.14 rpm, 1.54 deg).
// A mapping error (widths, spans from the hub instead of the rotor centre, another tip radius) moves
// these by more than the band below.
TEST(CliDecks, AeroDyn14AndItsV15VersionDifferByTheirQuadrature) {
  const auto schedule = test::freshDir("ad14_schedule") / "aoc.csv";
  std::ofstream(schedule) << "WindSpeed,RotSpeed,BldPitch\n6,64.14,1.54\n10,64.14,1.54\n14,64.14,1.54\n";
  auto table = [&](const std::string& extra) {
    const auto dir = test::freshDir("ad14_steady");
    const auto r = test::whirl("steady " + kDecks + "certtest/Test06.fst --schedule '" + schedule.string() +
                               "' --no-plot --out '" + dir.string() + "'" + extra);
    EXPECT_EQ(r.code, 0) << r.err;
    std::vector<std::vector<double>> rows;  // aero power (kW), thrust (kN) per wind speed
    std::istringstream in(test::slurp(dir / "steady.csv"));
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
      std::vector<double> v;
      std::istringstream cells(line);
      for (std::string c; std::getline(cells, c, ',') && v.size() < 7;) v.push_back(std::atof(c.c_str()));
      rows.push_back({v[3], v[6]});
    }
    return rows;
  };
  const auto v14 = table("");
  const auto v15 = table(" --set CompAero=2 AeroFile=AOC/Test06_AD15.ipt");
  ASSERT_EQ(v14.size(), 3u);
  ASSERT_EQ(v15.size(), 3u);
  for (int k = 0; k < 3; ++k)
    for (int q = 0; q < 2; ++q) {
      SCOPED_TRACE(std::to_string(k) + " " + std::to_string(q));
      EXPECT_GT(v14[k][q] / v15[k][q], 1.02);
      EXPECT_LT(v14[k][q] / v15[k][q], 1.07);
    }
}

}  // namespace
}  // namespace whirl
