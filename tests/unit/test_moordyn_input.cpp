// MoorDyn input files (CompMooring = 3): the OC3-Hywind deck's MoorDyn v1 file (OpenFAST certification
// Test24, a copy in cases/oc3_hywind) gives the same catenary lines as its MAP++ file (the two files
// describe one mooring system) but for the seabed friction MoorDyn v1 does not have; the v2 layout (POINTS,
// LINES with AttachA/AttachB) reads into the same lines; refusals and malformed rows name file and line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <regex>

#include "src/base/error.hpp"
#include "src/io/openfast/offshore/map_input.hpp"
#include "src/io/openfast/offshore/moordyn_input.hpp"
#include "tests/unit/test_util.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;

const std::string kDir = std::string(WHIRL_SOURCE_DIR) + "/cases/oc3_hywind/5MW_Baseline/";
const std::string kMoorDyn = kDir + "NRELOffshrBsline5MW_OC3Hywind_MoorDyn.dat";
const std::string kMap = kDir + "NRELOffshrBsline5MW_OC3Hywind_MAP.dat";

using test::errorOf;

// The OC3-Hywind file with `from` replaced by `to` (once), written into `dir`.
std::string edited(const test::TempDir& dir, const std::string& from, const std::string& to) {
  std::string s = test::slurp(kMoorDyn);
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  s.replace(at, from.size(), to);
  return dir.write("moordyn.dat", s);
}

TEST(MoorDynInput, Oc3HywindLinesAreTheMapLinesWithoutFriction) {
  const io::MapInput md = io::readMoorDyn(kMoorDyn);
  ASSERT_EQ(md.types.size(), 1u);
  EXPECT_EQ(md.types[0].Diam, 0.09);
  EXPECT_EQ(md.types[0].MassDenInAir, 77.7066);
  EXPECT_EQ(md.types[0].EA, 384.243e6);
  EXPECT_EQ(md.types[0].CB, 0.0);
  ASSERT_EQ(md.nodes.size(), 6u);
  ASSERT_EQ(md.lines.size(), 3u);
  const std::vector<MooringLine> a = io::mapMooringLines(md, 0, 320, 1025, 9.80665);
  const std::vector<MooringLine> b = io::mapMooringLines(io::readMap(kMap), 0, 320, 1025, 9.80665);
  ASSERT_EQ(a.size(), b.size());
  for (const MooringLine& l : a) {
    // MAP++ writes one line and `repeat 240 120`, MoorDyn the three lines at their places (printed to
    // 0.01 m: 426.94 and 739.47 for 853.87 turned by 120°), in another order.
    const MooringLine* m = &b[0];
    for (const MooringLine& c : b)
      if ((c.anchor - l.anchor).norm() < (m->anchor - l.anchor).norm()) m = &c;
    EXPECT_LT((l.anchor - m->anchor).norm(), 0.01) << l.name;
    EXPECT_LT((l.fairlead - m->fairlead).norm(), 0.01) << l.name;
    EXPECT_EQ(l.length, m->length);
    EXPECT_EQ(l.weight, m->weight);
    EXPECT_EQ(l.EA, m->EA);
    EXPECT_TRUE(l.seabed);
    EXPECT_EQ(l.CB, 0.0);
    EXPECT_EQ(m->CB, 0.001);  // MAP++'s seabed friction
  }
}

TEST(MoorDynInput, VersionTwoLayoutReadsIntoTheSameLines) {
  const test::TempDir dir;
  std::string s = test::slurp(kMoorDyn);
  s = std::regex_replace(s, std::regex("CONNECTION PROPERTIES"), "POINTS");
  s = std::regex_replace(s, std::regex("LINE PROPERTIES"), "LINES");
  s = std::regex_replace(s, std::regex("\\d+ +N(Types|Connects|Lines) .*\\n"), "");
  // v2 rows: ID LineType AttachA AttachB UnstrLen NumSegs; line 2 names its fairlead first.
  s = std::regex_replace(s, std::regex("1 +main +902.2 +20 +1 +4"), "1 main 1 4 902.2 20");
  s = std::regex_replace(s, std::regex("2 +main +902.2 +20 +2 +5"), "2 main 5 2 902.2 20");
  s = std::regex_replace(s, std::regex("3 +main +902.2 +20 +3 +6"), "3 main 3 6 902.2 20");
  const io::MapInput v2 = io::readMoorDyn(dir.write("v2.dat", s));
  const io::MapInput v1 = io::readMoorDyn(kMoorDyn);
  ASSERT_EQ(v2.lines.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(v2.lines[k].anchor, v1.lines[k].anchor) << k;
    EXPECT_EQ(v2.lines[k].fairlead, v1.lines[k].fairlead) << k;
    EXPECT_EQ(v2.lines[k].UnstrLen, v1.lines[k].UnstrLen) << k;
  }
}

TEST(MoorDynInput, RefusalsAndMalformedRowsNameTheLine) {
  const test::TempDir dir;
  EXPECT_THAT(errorOf([&] { io::readMoorDyn(edited(dir, "4      vessel", "4      connect")); }),
              HasSubstr("moordyn.dat:16: Type: connect points (multi-segment lines) are not supported by whirl"));
  EXPECT_THAT(errorOf([&] { io::readMoorDyn(edited(dir, "-70.0    0     0", "-70.0    5     0")); }),
              HasSubstr("moordyn.dat:16: M: point masses and volumes (M, V ≠ 0) are not supported by whirl"));
  EXPECT_THAT(errorOf([&] { io::readMoorDyn(edited(dir, "384.243E6", "x")); }),
              HasSubstr("moordyn.dat:8: EA: 'x' is not a finite number"));
  EXPECT_THAT(errorOf([&] { io::readMoorDyn(edited(dir, "902.2      20        1", "-1      20        1")); }),
              HasSubstr("moordyn.dat:23: UnstrLen: must be positive"));
  // A section of bodies is refused at its first row; an empty one (its two heading rows) is fine.
  EXPECT_THAT(errorOf([&] { io::readMoorDyn(edited(dir, "---------------------- SOLVER OPTIONS", "---- BODIES")); }),
              HasSubstr("moordyn.dat:29: MoorDyn bodies and rods are not supported by whirl"));
  const std::string empty_rods = "---- ROD TYPES\nName Diam\n(-) (m)\n---------------------- SOLVER OPTIONS";
  EXPECT_EQ(io::readMoorDyn(edited(dir, "---------------------- SOLVER OPTIONS", empty_rods)).lines.size(), 3u);
  EXPECT_THAT(errorOf([&] { io::readMoorDyn(dir.path / "none.dat"); }), HasSubstr("none.dat: cannot open file"));
}

}  // namespace
}  // namespace whirl
