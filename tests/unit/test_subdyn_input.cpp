// The SubDyn reader (src/io/openfast/offshore/subdyn_input.hpp): the OC3 monopile of certification Test19
// (cases/oc3_monopile, SubDyn v1.01 layout), a tube in the v1.01 and the OpenFAST v3–v4 layouts
// (tests/data/subdyn), and one error or refusal per bad input, each one line "file:line: key: reason".
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <unistd.h>

#include "src/base/error.hpp"
#include "src/io/openfast/offshore/subdyn_input.hpp"
#include "src/io/openfast/openfast_overrides.hpp"
#include "tests/unit/test_util.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::string kMonopile = std::string(WHIRL_SOURCE_DIR) +
                              "/cases/oc3_monopile/5MW_Baseline/NRELOffshrBsline5MW_OC3Monopile_SubDyn.dat";
const std::string kV101 = std::string(WHIRL_SOURCE_DIR) + "/tests/data/subdyn/cantilever_v101.dat";
const std::string kV4 = std::string(WHIRL_SOURCE_DIR) + "/tests/data/subdyn/cantilever_v4.dat";

using test::errorOf;

std::vector<std::string> fileLines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string s; std::getline(in, s);) out.push_back(s);
  return out;
}

// A copy of `path` with line `n` (1-based) replaced by `text` (several lines if it holds '\n'; empty
// `text` with `remove` drops the line).
std::string edited(const std::string& path, int n, const std::string& text, bool remove = false) {
  std::vector<std::string> l = fileLines(path);
  if (remove) l.erase(l.begin() + (n - 1));
  else l[n - 1] = text;
  // Same file name in a folder of its own, so that messages read as for the original.
  const auto dir = std::filesystem::temp_directory_path() / ("whirl_subdyn_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string out = (dir / std::filesystem::path(path).filename()).string();
  std::ofstream o(out);
  for (const std::string& s : l) o << s << '\n';
  return out;
}

std::string errorOfEdit(const std::string& path, int n, const std::string& text, bool remove = false) {
  const std::string f = edited(path, n, text, remove);
  return errorOf([&] { io::readSubDyn(f); });
}

TEST(SubDynInput, Oc3MonopileValues) {
  const io::SubDynInput sd = io::readSubDyn(kMonopile);
  EXPECT_EQ(sd.FEMMod, 3);
  EXPECT_EQ(sd.NDiv, 3);
  EXPECT_EQ(sd.Nmodes, 0);  // CBMod = True, Nmodes = 0: Guyan
  EXPECT_TRUE(sd.JDampings.empty());
  EXPECT_EQ(sd.GuyanDampMod, 0);  // v1.01: no Guyan damping
  ASSERT_EQ(sd.joints.size(), 4u);
  EXPECT_EQ(sd.joints[0].position, Vec3(0, 0, -20.0001));
  EXPECT_EQ(sd.joints[3].position, Vec3(0, 0, 10));
  EXPECT_EQ(sd.joints[0].line, 18);
  ASSERT_EQ(sd.reactions.size(), 1u);
  EXPECT_EQ(sd.reactions[0].joint, 1);
  for (bool f : sd.reactions[0].fixed) EXPECT_TRUE(f);
  ASSERT_EQ(sd.interfaces.size(), 1u);
  EXPECT_EQ(sd.interfaces[0].joint, 4);
  ASSERT_EQ(sd.members.size(), 3u);
  EXPECT_EQ(sd.members[2].joint1, 3);
  EXPECT_EQ(sd.members[2].joint2, 4);
  ASSERT_EQ(sd.sections.size(), 4u);
  EXPECT_EQ(sd.sections[0].E, 2.1e11);
  EXPECT_EQ(sd.sections[0].G, 8.08e10);
  EXPECT_EQ(sd.sections[0].rho, 8500);
  EXPECT_EQ(sd.sections[0].D, 6);
  EXPECT_EQ(sd.sections[0].t, 0.06);
  EXPECT_TRUE(sd.masses.empty());
  EXPECT_TRUE(sd.notes.empty());
}

TEST(SubDynInput, OverridesReachTheScalars) {
  io::OverrideSet set({io::parseOverride("Nmodes=4"), io::parseOverride("JDampings=2")});
  const io::SubDynInput sd = io::readSubDyn(kMonopile, &set);
  EXPECT_EQ(sd.Nmodes, 4);
  ASSERT_EQ(sd.JDampings.size(), 4u);  // one value repeated over the modes, as SubDyn does
  for (double z : sd.JDampings) EXPECT_DOUBLE_EQ(z, 0.02);
  io::OverrideSet full({io::parseOverride("CBMod=False")});
  EXPECT_EQ(io::readSubDyn(kMonopile, &full).Nmodes, -1);
}

TEST(SubDynInput, LayoutsV101AndV4ReadTheSameStructure) {
  const io::SubDynInput a = io::readSubDyn(kV101), b = io::readSubDyn(kV4);
  EXPECT_EQ(a.Nmodes, -1);  // CBMod = False
  EXPECT_EQ(b.Nmodes, -1);  // Nmodes = -1
  EXPECT_EQ(a.JDampings, b.JDampings);
  ASSERT_EQ(a.joints.size(), b.joints.size());
  for (std::size_t k = 0; k < a.joints.size(); ++k) EXPECT_EQ(a.joints[k].position, b.joints[k].position);
  ASSERT_EQ(a.members.size(), b.members.size());
  for (std::size_t k = 0; k < a.members.size(); ++k) {
    EXPECT_EQ(a.members[k].joint1, b.members[k].joint1);
    EXPECT_EQ(a.members[k].joint2, b.members[k].joint2);
  }
  ASSERT_EQ(a.sections.size(), 1u);
  ASSERT_EQ(b.sections.size(), 1u);
  EXPECT_EQ(a.sections[0].D, b.sections[0].D);
  // The v4 file names an SSIfile for a joint whose DOFs are all locked: ignored, as in SubDyn.
  ASSERT_EQ(b.notes.size(), 1u);
  EXPECT_THAT(b.notes[0], HasSubstr("cantilever_v4.dat:35: SSIfile: ignored"));
}

TEST(SubDynInput, ZeroLengthMemberNamesItsRow) {
  // Joint 2 moved onto joint 1: member 1 has zero length.
  const std::string msg = errorOfEdit(kMonopile, 19,
                                      "   2              0.00000                0.00000              -20.00010");
  EXPECT_THAT(msg,
              HasSubstr("_SubDyn.dat:36: MJointID2: member 1 has zero length: joints 1 and 2 are at the same place"));
  EXPECT_EQ(msg.find('\n'), std::string::npos);
}

TEST(SubDynInput, TableErrorsNameFileLineAndKey) {
  // A member to a joint that does not exist.
  EXPECT_THAT(errorOfEdit(kMonopile, 38, "   3           3           7            1             1"),
              HasSubstr("_SubDyn.dat:38: MJointID2: no joint 7"));
  // A property set that does not exist.
  EXPECT_THAT(errorOfEdit(kMonopile, 38, "   3           3           4            1             9"),
              HasSubstr("_SubDyn.dat:38: MPropSetID2: no property set 9"));
  // A row missing: the count key names the line where the table stops.
  EXPECT_THAT(errorOfEdit(kMonopile, 21, "", true),
              HasSubstr("_SubDyn.dat:15: NJoints: 4 rows expected below it (after the column-name and unit rows), line "
                        "21 is a section line"));
  // A row too many.
  EXPECT_THAT(errorOfEdit(kMonopile, 21,
                          "   4              0.00000                0.00000               10.00000\n   5   0 0 20"),
              HasSubstr("_SubDyn.dat:15: NJoints: is 4 but line 22 is another row"));
  // A number that is not one.
  EXPECT_THAT(errorOfEdit(kMonopile, 43,
                          "   1        2.10000e+11     8.08000e+10       abc         6.000000        0.060000"),
              HasSubstr("_SubDyn.dat:43: PropSetID: expected PropSetID, YoungE, ShearG, MatDens, XsecD, XsecT"));
  EXPECT_THAT(errorOfEdit(kMonopile, 43,
                          "   1        2.10000e+11     8.08000e+10       -1         6.000000        0.060000"),
              HasSubstr("_SubDyn.dat:43: MatDens: must be positive"));
  // The interface joint is the reaction joint.
  EXPECT_THAT(errorOfEdit(kMonopile, 31,
                          "   1           1           1           1           1           1           1"),
              HasSubstr("_SubDyn.dat:31: IJointID: joint 1 is a reaction joint too"));
}

TEST(SubDynInput, CountsAreBoundedBeforeRowsAreRead) {
  EXPECT_THAT(errorOfEdit(kMonopile, 15, "       2000000   NJoints     - Number of joints (-)"),
              HasSubstr("_SubDyn.dat:15: NJoints: must be between 2 and 2000 (src/base/limits.hpp)"));
  EXPECT_THAT(errorOfEdit(kMonopile, 10, "           1000   NDiv        - Number of sub-elements per member"),
              HasSubstr("_SubDyn.dat:10: NDiv: must be between 1 and 100 (src/base/limits.hpp)"));
  EXPECT_THAT(errorOfEdit(kMonopile, 12, "           5000   Nmodes      - Number of internal modes"),
              HasSubstr("_SubDyn.dat:12: Nmodes: must be at most 1000 (src/base/limits.hpp)"));
  EXPECT_THAT(errorOfEdit(kMonopile, 33, "       3000   NMembers    - Number of frame members"),
              HasSubstr("_SubDyn.dat:33: NMembers: must be between 1 and 2000 (src/base/limits.hpp)"));
}

TEST(SubDynInput, RefusalsAreExplicit) {
  // Soil-structure interaction: an SSIfile with a free DOF.
  EXPECT_THAT(
      errorOfEdit(kMonopile, 26,
                  "   1           1           1           1           0           0           1   \"soil.txt\""),
      HasSubstr(
          "_SubDyn.dat:26: SSIfile: 'soil.txt' not supported by whirl (soil-structure interaction is not modelled"));
  // Tapered elements, as SubDyn.
  io::OverrideSet tapered({io::parseOverride("FEMMod=4")});
  EXPECT_THAT(errorOf([&] { io::readSubDyn(kMonopile, &tapered); }),
              HasSubstr("_SubDyn.dat:9: FEMMod: 4 not supported by whirl (tapered elements are not implemented"));
  // A floating substructure.
  const std::string noReact = edited(kMonopile, 23,
                                     "             0   NReact      - Number of Joints with reaction forces");
  EXPECT_THAT(errorOf([&] { io::readSubDyn(noReact); }),
              HasSubstr("_SubDyn.dat:23: NReact: 0 not supported by whirl (a floating substructure"));
  // Rigid links and cables in the v4 layout.
  EXPECT_THAT(errorOfEdit(kV4, 46, "   2           2           3            1             1          3          0"),
              HasSubstr("cantilever_v4.dat:46: MType: 3 not supported by whirl (rigid links are not modelled"));
  EXPECT_THAT(errorOfEdit(kV4, 28,
                          "   3              0.00000                0.00000              -30.00000        3         "
                          "0.0        1.0       0.0       0.0"),
              HasSubstr("cantilever_v4.dat:28: JointType: 3 not supported by whirl (universal, pin and ball joints"));
}

TEST(SubDynInput, KeyGivenTwiceIsRefused) {
  const std::string msg = errorOfEdit(
      kMonopile, 10,
      "             3   NDiv        - Number of sub-elements per member\n             3   NDiv        - again");
  EXPECT_THAT(msg, HasSubstr("_SubDyn.dat:11: NDiv: given twice (first on line 10)"));
}

}  // namespace
}  // namespace whirl
