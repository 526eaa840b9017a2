// `whirl campbell` and `whirl modes` on 2-bladed rotors (Floquet analysis, modal/floquet.hpp): UAE
// Phase VI (cases/uae6, rigid hub) from parked to 72 rpm and AWT-27 (teetering hub, OpenFAST
// certification Test01, structure only) from 20 to 60 rpm. The frequencies are continuous in rotor
// speed: between neighbouring points a tracked line moves by at most 2.5 × the change of the rotor
// frequency plus 0.02 Hz (a whirl changes by Ω, a flap mode stiffens; a harmonic chosen wrongly jumps
// by Ω or 2Ω: 1.2 or 2.4 Hz at 72 rpm); no line starts after the first point (a mode that changes its
// harmonic or its character would start a new line). Parked, the 2-bladed modes are those of the
// plain eigenanalysis (tests/unit/test_two_bladed_modes.cpp); the first Campbell step from parked is
// left out here: parked, a 2-bladed rotor's cyclic modes depend on its azimuth, turning they see all.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;

struct Row {
  double rpm, freq;
};

// campbell.csv (rpm,wind_speed,mode,freq_hz,damping_ratio) by line.
std::map<std::string, std::vector<Row>> lines(const std::string& csv) {
  std::map<std::string, std::vector<Row>> out;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::string cell;
    std::istringstream s(line);
    while (std::getline(s, cell, ',')) f.push_back(cell);
    if (f.size() != 5) continue;
    out[f[2]].push_back({std::stod(f[0]), std::stod(f[3])});
  }
  return out;
}

void expectContinuous(const std::string& args, double first_rpm) {
  const auto dir = test::freshDir("two_bladed");
  const auto r = test::whirl("campbell " + args + " --no-plot --out " + dir.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto by_line = lines(test::slurp(dir / "campbell.csv"));
  ASSERT_GE(by_line.size(), 10u);
  for (const auto& [name, rows] : by_line) {
    EXPECT_EQ(rows.front().rpm, first_rpm) << name << " starts after the first point";
    for (std::size_t k = 1; k < rows.size(); ++k) {
      const double bound = 2.5 * (rows[k].rpm - rows[k - 1].rpm) / 60 + 0.02;
      EXPECT_LE(std::abs(rows[k].freq - rows[k - 1].freq), bound)
          << name << " from " << rows[k - 1].rpm << " to " << rows[k].rpm << " rpm";
    }
  }
}

TEST(TwoBladedSlow, UaeCampbellIsContinuous) { expectContinuous("cases/uae6/UAE6.fst --rpm 6:6:72", 6); }

TEST(TwoBladedSlow, TeeteredAwt27CampbellIsContinuous) {
  expectContinuous("tests/data/openfast/decks/certtest/Test01.fst --set CompAero=0 --rpm 20:5:60", 20);
}

// `whirl modes` on a turning 2-bladed rotor takes Floquet analysis: fixed-frame names, a teeter.
TEST(TwoBladed, ModesOfTheTurningTeeteredRotor) {
  const auto r = test::whirl("modes tests/data/openfast/decks/certtest/Test01.fst --set CompAero=0 --format csv");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr(",flap 1 collective,"));
  EXPECT_THAT(r.out, HasSubstr(",flap 1 BW,"));
  EXPECT_THAT(r.out, HasSubstr(",teeter BW,"));
}

// Parked, the AWT-27 rotor hangs 0.38 m of its centre of mass off the teeter pin on a 1 N m/rad spring:
// no operating point, and the message says what to do.
TEST(TwoBladed, ParkedFreeTeeterSaysHowToHoldIt) {
  const std::string deck = "tests/data/openfast/decks/certtest/Test01.fst --set CompAero=0 --rpm 0";
  const auto r = test::whirl("modes " + deck);
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("teeter: turned"));
  EXPECT_THAT(r.err, HasSubstr("hold it with --set TeetDOF=False"));
  const auto held = test::whirl("modes " + deck + " --set TeetDOF=False --format csv");
  EXPECT_EQ(held.code, 0) << held.err;
}

// As shipped (AeroDyn in 12 m/s, Thevenin induction generator, no brake), the parked AWT-27 of Test02
// finds an equilibrium; its slow mode is the whole rotor turning on the shaft (100 % generator azimuth)
// and is named so, not after a blade group with a share of 1e-6 ("edge 1 cos" before).
TEST(TwoBladed, ParkedUnbrakedRotorTurningIsRigidBody) {
  const auto r = test::whirl("modes tests/data/openfast/decks/certtest/Test02.fst --rpm 0 --format json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  bool found = false;
  for (const auto& m : j["modes"]) {
    if (m["freq_hz"].get<double>() > 0.5) continue;
    EXPECT_NE(m["name"], "edge 1 cos");
    if (m["name"] == "generator azimuth (rigid body)") {
      found = true;
      EXPECT_GT(m["participation"]["generator azimuth"].get<double>(), 0.99);
    }
  }
  EXPECT_TRUE(found) << r.out;
}

}  // namespace
}  // namespace whirl
