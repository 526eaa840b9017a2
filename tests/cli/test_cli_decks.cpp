// Public OpenFAST decks as users bring them (issue 16; tests/data/openfast/README.md, `decks/`): the IEA
// 3.4 MW reference turbine written by WISDEM (`BldFile1`, `BldFlDmp1`, …), a FAST v7 primary file,
// and a deck with platform DOFs on, each refused on one line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>

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

}  // namespace
}  // namespace whirl
