// `whirl modes` on the OC3-Hywind deck (cases/oc3_hywind, OpenFAST certification Test24): the six
// platform modes by name, the one-line note for the ignored waves, the one-line refusal of the
// deck's radiation convolution, and its MoorDyn file against its MAP++ file. The OC3 monopile (cases/oc3_monopile,
// Test19, a SubDyn substructure): `whirl modes` and `whirl campbell`, the refusal of HydroDyn on a substructure, and a
// bad SubDyn file stopping with its place and nothing written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;

const std::string kDeck = "cases/oc3_hywind/Test24.fst";

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

TEST(CliOffshore, Oc3HywindPlatformModes) {
  const auto r = test::whirl("modes " + kDeck +
                             " --set CompAero=0 --set RdtnMod=0 --set RotSpeed=0 --set GenDOF=False");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* name :
       {"platform surge", "platform sway", "platform heave", "platform roll", "platform pitch", "platform yaw"})
    EXPECT_THAT(r.out, HasSubstr(name));
  EXPECT_THAT(r.err, HasSubstr("HydroDyn.dat:9: WaveMod: incident waves ignored"));
  EXPECT_EQ(lines(r.err), 1) << r.err;
}

TEST(CliOffshore, RadiationConvolutionRefusedOnOneLine) {
  const auto r = test::whirl("modes " + kDeck + " --set CompAero=0");
  EXPECT_NE(r.code, 0);
  EXPECT_THAT(r.err, HasSubstr("HydroDyn.dat:53: RdtnMod: 1 not supported by whirl"));
  EXPECT_THAT(r.err, HasSubstr("--set RdtnMod=0"));
  EXPECT_EQ(lines(r.err), 1) << r.err;
}

// The platform frequencies of a `whirl modes` table, by mode name (first occurrence).
std::map<std::string, double> platformFrequencies(const std::string& table) {
  std::map<std::string, double> f;
  std::istringstream in(table);
  for (std::string row; std::getline(in, row);) {
    const auto at = row.find("platform ");
    if (at == std::string::npos) continue;
    const auto end = row.find("  ", at);
    const std::string name = row.substr(at, end - at);
    if (!f.count(name)) f[name] = std::stod(row.substr(end));
  }
  return f;
}

// The deck's MoorDyn file (the same three lines as its MAP++ file, without MAP++'s seabed friction
// CB = 0.001 and with anchors printed to 0.01 m) gives the MAP++ model's platform frequencies.
TEST(CliOffshore, Oc3HywindMoorDynFileGivesTheMapFrequencies) {
  const std::string base = "modes " + kDeck + " --set CompAero=0 --set RdtnMod=0 --set RotSpeed=0 --set GenDOF=False";
  const auto map = test::whirl(base);
  const auto md = test::whirl(
      base + " --set CompMooring=3 --set MooringFile=5MW_Baseline/NRELOffshrBsline5MW_OC3Hywind_MoorDyn.dat");
  ASSERT_EQ(map.code, 0) << map.err;
  ASSERT_EQ(md.code, 0) << md.err;
  const auto a = platformFrequencies(map.out), b = platformFrequencies(md.out);
  ASSERT_EQ(a.size(), 6u);
  for (const auto& [name, f] : a) {
    ASSERT_TRUE(b.count(name)) << name;
    EXPECT_NEAR(b.at(name), f, 1e-4 * f) << name;
  }
}

const std::string kMonopile = "cases/oc3_monopile/Test19.fst";
const std::string kMonopileSets = " --set CompAero=0 --set CompHydro=0";

TEST(CliOffshore, Oc3MonopileModesWithTheSubstructure) {
  const auto r = test::whirl("modes " + kMonopile + kMonopileSets +
                             " --set RotSpeed=0 --set GenDOF=False --format csv");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("tower FA 1"));
  EXPECT_THAT(r.out, HasSubstr("tower SS 1"));
  EXPECT_EQ(r.err, "");
}

TEST(CliOffshore, Oc3MonopileCampbell) {
  const auto dir = test::freshDir("oc3_monopile_campbell");
  const auto r = test::whirl("campbell " + kMonopile + kMonopileSets + " --rpm 0:1:12 --no-plot --out '" +
                             dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string csv = test::slurp(dir / "campbell.csv");
  EXPECT_THAT(csv, HasSubstr("tower FA 1"));
  EXPECT_THAT(csv, HasSubstr("\n0,"));   // parked
  EXPECT_THAT(csv, HasSubstr("\n12,"));  // to 12 rpm
}

// A copy of cases/oc3_monopile in `dir`/deck with `from` replaced by `to` in its file `file`.
void monopileCopyWith(const std::filesystem::path& dir, const std::string& file, const std::string& from,
                      const std::string& to) {
  std::filesystem::copy(std::string(WHIRL_SOURCE_DIR) + "/cases/oc3_monopile", dir / "deck",
                        std::filesystem::copy_options::recursive);
  const auto path = dir / "deck/5MW_Baseline" / file;
  std::filesystem::permissions(path, std::filesystem::perms::owner_write, std::filesystem::perm_options::add);
  std::string text = test::slurp(path);
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  std::ofstream(path) << text;
}

// HydroDyn's strip theory on the SubDyn pile runs as shipped (the deck's CompHydro = 1); a HydroDyn
// member that does not follow the substructure's members stops on one line naming its row.
TEST(CliOffshore, HydroDynOnASubstructure) {
  const auto r = test::whirl("modes " + kMonopile + " --set CompAero=0 --format csv");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("tower SS 1"));
  const auto dir = test::freshDir("oc3_monopile_hydro_off");
  monopileCopyWith(dir, "NRELOffshrBsline5MW_OC3Monopile_HydroDyn.dat", "    2     0.00000     0.00000    10.00000",
                   "    2     1.00000     0.00000    10.00000");
  const auto bad = test::whirl("modes " + (dir / "deck/Test19.fst").string() + " --set CompAero=0");
  EXPECT_EQ(bad.code, 1);
  EXPECT_THAT(bad.err, HasSubstr("HydroDyn.dat:120: MemberID: member 1: "));
  EXPECT_THAT(bad.err, HasSubstr("lie on no SubDyn member"));
  EXPECT_EQ(lines(bad.err), 1) << bad.err;
}

// A member of zero length in a copy of the deck: file, line and key, exit code 1, no output files.
TEST(CliOffshore, ZeroLengthSubDynMemberStopsWithItsPlace) {
  const auto dir = test::freshDir("oc3_monopile_bad");
  monopileCopyWith(dir, "NRELOffshrBsline5MW_OC3Monopile_SubDyn.dat",
                   "   2              0.00000                0.00000              -10.00000",
                   "   2              0.00000                0.00000              -20.00010");
  const auto out = dir / "out";
  const auto r = test::whirl("linearize deck/Test19.fst" + kMonopileSets + " --out '" + out.string() + "'",
                             dir.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("NRELOffshrBsline5MW_OC3Monopile_SubDyn.dat:36: MJointID2: member 1 has zero length"));
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace whirl
