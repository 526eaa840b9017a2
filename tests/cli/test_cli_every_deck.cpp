// Every public OpenFAST deck of `../shared/data/decks` (issues 16 and 17; copies in
// tests/data/openfast/decks, tests/data/openfast/README.md): `whirl modes` parked and `whirl campbell`
// from 0 to rated rotor speed, as shipped and as the structural model (`--set CompAero=0`). A deck
// runs, or is refused for the documented reason listed here (docs/user/decks.md); a new refusal, a crash
// or an operating point that does not converge fails. A deck that starts to run where a refusal is
// listed passes (then its listed reason is stale: remove it).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <sstream>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;

struct Deck {
  const char* fst;        ///< relative to tests/data/openfast/decks/
  double rated_rpm;       ///< top of the Campbell sweep
  const char* shipped;    ///< expected refusal as shipped (a substring of the message), or nullptr: runs
  const char* structure;  ///< the same with --set CompAero=0
};

// Reasons whirl does not support yet, as its messages say them (docs/user/decks.md).
constexpr const char* kNoActiveDof = "the model has no active degree of freedom";
// AWT-27 parked: the rotor's centre of mass lies 0.38 m downwind of the teeter pin (coned blades, hub
// mass at HubCM) and the deck's teeter spring is 1 N m/rad (TeetSSSp from TeetSStP = 0, hard stop at
// 180 deg): without the centrifugal stiffening of a turning rotor nothing holds the 8.3 kN m weight
// moment, the teeter swings round, and whirl says so. Its Campbell sweep starts at half the rated speed.
constexpr const char* kTeeterParked = "teeter: turned";
constexpr const char* kFastV7 = "this is a FAST v7 primary input file";
// Offshore (issue 17): the radiation convolution, which has no linearization (OpenFAST refuses it too;
// --set RdtnMod=0 runs Test23–25's platforms but Test23's FEAMooring).
constexpr const char* kConvolution = "RdtnMod: 1 not supported by whirl (the radiation convolution";

// Rated rotor speeds: the ElastoDyn RotSpeed of the certification tests' operating decks (AWT-27
// Test01, AOC Test07, UAE VI Test09, WindPACT Test11, SWRT Test15, NREL 5MW Test18: constant-speed
// or rated operation); NREL 5MW 12.1 rpm [Jonkman2009, Table 1-1]; IEA 3.4 MW VS_RefSpd / GBRatio =
// 118.175 rad/s / 97 of its DISCON.IN and ElastoDyn file.
const Deck kDecks[] = {
    {"IEA-3.4-130-RWT/IEA-3.4-130-RWT.fst", 11.63, nullptr, nullptr},
    {"certtest/FAST_v7/Test01.fst", 53.333, kFastV7, kFastV7},
    {"certtest/Test01.fst", 53.333, nullptr, kTeeterParked},
    {"certtest/Test02.fst", 53.333, nullptr, kTeeterParked},
    {"certtest/Test03.fst", 53.333, kTeeterParked, kTeeterParked},
    {"certtest/Test04.fst", 53.333, kTeeterParked, kTeeterParked},
    {"certtest/Test05.fst", 53.333, kTeeterParked, kTeeterParked},
    {"certtest/Test06.fst", 64.14, nullptr, nullptr},
    {"certtest/Test07.fst", 64.14, nullptr, nullptr},
    {"certtest/Test08.fst", 64.14, nullptr, nullptr},
    {"certtest/Test09.fst", 71.9, nullptr, nullptr},
    {"certtest/Test10.fst", 71.9, kNoActiveDof, kNoActiveDof},  // every DOF switched off
    {"certtest/Test11.fst", 20, nullptr, nullptr},
    {"certtest/Test12.fst", 20, nullptr, nullptr},
    {"certtest/Test13.fst", 20, nullptr, nullptr},
    {"certtest/Test14.fst", 20, nullptr, nullptr},
    {"certtest/Test15.fst", 188, nullptr, nullptr},
    {"certtest/Test16.fst", 188, nullptr, nullptr},  // airfoil tables on the Reynolds number (RENUM)
    {"certtest/Test17.fst", 188, nullptr, nullptr},
    {"certtest/Test18.fst", 12.1, nullptr, nullptr},
    {"certtest/Test19.fst", 12.1, nullptr, nullptr},            // OC3 monopile, strip theory on SubDyn
    {"certtest/Test20.fst", 12.1, nullptr, nullptr},            // OC3 tripod, idem
    {"certtest/Test21.fst", 12.1, nullptr, nullptr},            // OC4 jacket, with marine growth and a fill
    {"certtest/Test22.fst", 12.1, nullptr, nullptr},            // ITI barge, state-space radiation
    {"certtest/Test23.fst", 12.1, kConvolution, kConvolution},  // MIT/NREL TLP
    {"certtest/Test24.fst", 12.1, kConvolution, kConvolution},  // OC3 Hywind
    {"certtest/Test25.fst", 12.1, kConvolution, kConvolution},  // OC4 DeepCwind semi
    {"certtest/Test26.fst", 12.1, nullptr, nullptr},            // BeamDyn blades
    {"toolbox-nrel5mw/5MW_Land_Lin_BladeOnly/Main.fst", 12.1, nullptr, nullptr},
    {"toolbox-nrel5mw/5MW_Land_Lin_Rotating/Main.fst", 12.1, nullptr, nullptr},
    {"toolbox-nrel5mw/5MW_Land_Lin_Templates/Main.fst", 12.1, nullptr, nullptr},
    {"toolbox-nrel5mw/Main_Onshore.fst", 12.1, nullptr, nullptr},
};

class EveryDeckSlow : public testing::TestWithParam<Deck> {};

// Runs `whirl modes` parked and `whirl campbell` 0 … rated; a listed refusal may stand instead.
void check(const Deck& d, const std::string& extra, const char* refusal) {
  const std::string fst = "tests/data/openfast/decks/" + std::string(d.fst);
  const auto modes = test::whirl("modes " + fst + " --rpm 0 --format csv" + extra);
  // A rotor that cannot be parked (kTeeterParked) still runs turning: its sweep leaves out 0 rpm, and a
  // listed refusal may then come from the turning rotor.
  const bool turning_only = modes.code != 0 && refusal && modes.err.find(kTeeterParked) != std::string::npos;
  if (modes.code != 0 && refusal) {
    EXPECT_EQ(modes.code, 1) << "crash? " << modes.err;
    if (!turning_only) {
      EXPECT_THAT(modes.err, HasSubstr(refusal));
      return;
    }
  } else {
    ASSERT_EQ(modes.code, 0) << "whirl modes" << extra << ": " << modes.err;
    EXPECT_GT(std::count(modes.out.begin(), modes.out.end(), '\n'), 1) << modes.out;
  }
  std::ostringstream rpm;
  rpm << (turning_only ? d.rated_rpm / 2 : 0.0) << ":" << d.rated_rpm / 2 << ":" << d.rated_rpm;
  const auto dir = test::freshDir("every_deck");
  const auto campbell = test::whirl("campbell " + fst + " --rpm " + rpm.str() + " --no-plot --out " + dir.string() +
                                    extra);
  // A listed refusal may also come from a turning rotor only.
  if (campbell.code != 0 && refusal && campbell.err.find(refusal) != std::string::npos) {
    EXPECT_EQ(campbell.code, 1) << "crash? " << campbell.err;
    return;
  }
  ASSERT_EQ(campbell.code, 0) << "whirl campbell" << extra << ": " << campbell.err;
  EXPECT_THAT(campbell.out, HasSubstr(turning_only ? "2 operating points" : "3 operating points")) << campbell.out;
}

TEST_P(EveryDeckSlow, AsShipped) { check(GetParam(), "", GetParam().shipped); }

TEST_P(EveryDeckSlow, StructureOnly) { check(GetParam(), " --set CompAero=0", GetParam().structure); }

std::string deckName(const testing::TestParamInfo<Deck>& info) {
  std::string s = info.param.fst;
  s = s.substr(0, s.rfind('.'));
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

INSTANTIATE_TEST_SUITE_P(Decks, EveryDeckSlow, testing::ValuesIn(kDecks), deckName);

}  // namespace
}  // namespace whirl
