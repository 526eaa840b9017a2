// ElastoDyn's teeter spring, stops and damper (TeetMod = 1: soft stop TeetSStP/TeetSSSp, hard stop
// TeetHStP/TeetHSSp, damper TeetDmpP/TeetDmp, each acting only beyond its angle) linearized on the
// piece of their law that holds at TeetDefl (src/turbine/elastodyn_teeter.cpp): inside a stop it
// contributes nothing; beyond it, a spring about the stop angle; an operating point that leaves the
// piece is not valid (linearize/point_validity.hpp). TeetDOF = False freezes the teeter at TeetDefl.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>

#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "linearize/point_validity.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace whirl {
namespace {

using testing::HasSubstr;
constexpr double deg = std::numbers::pi / 180;
const std::string kEd = (test::openfastDataDir() / "decks" / "certtest" / "AWT27" / "Test01_ElastoDyn.dat").string();

// AWT-27 (Test01: TeetMod = 1, soft stop from 0 deg at 1 N m/rad, hard stop at 180 deg, damper from
// 0 deg) with the rotor alone flexible: the teeter and the blades.
Model awt27(const std::vector<std::string>& extra) {
  std::vector<std::string> o = {"DrTrDOF=False",  "GenDOF=False",   "TwFADOF1=False",
                                "TwFADOF2=False", "TwSSDOF1=False", "TwSSDOF2=False"};
  o.insert(o.end(), extra.begin(), extra.end());
  return readElastoDynModel(kEd, o);
}

std::vector<DofSpring> teeterLaws(const Model& m) {
  std::vector<DofSpring> out;
  for (const DofSpring& s : m.springs)
    if (s.dof == m.roles.teeter_dof) out.push_back(s);
  return out;
}

TEST(TeeterStops, TheDeckSpringAndDamperActFromZero) {
  const Model m = awt27({});
  const std::vector<DofSpring> laws = teeterLaws(m);
  ASSERT_EQ(laws.size(), 3u);  // soft stop at 0 deg (linear), hard stop not reached, damper from 0 deg
  EXPECT_EQ(laws[0].k, 1.0);
  EXPECT_EQ(laws[0].q0, 0.0);
  EXPECT_EQ(laws[0].q_min, -std::numeric_limits<double>::infinity());
  EXPECT_EQ(laws[1].k, 0.0);
  EXPECT_DOUBLE_EQ(laws[1].q_max, 180 * deg);
  EXPECT_THAT(laws[1].law, HasSubstr("TeetHStP = 180 deg"));
  EXPECT_EQ(laws[2].c, 40000.0);
}

TEST(TeeterStops, InsideTheStopsTheyContributeNothing) {
  const std::vector<std::string> inside = {"TeetSStP=5", "TeetHStP=10", "TeetDmpP=2", "TeetDefl=0"};
  std::vector<std::string> none = inside;
  for (const char* s : {"TeetSSSp=0", "TeetHSSp=0", "TeetDmp=0"}) none.push_back(s);
  std::vector<std::string> stiff = inside;
  for (const char* s : {"TeetSSSp=1e7", "TeetHSSp=1e9", "TeetDmp=1e6"}) stiff.push_back(s);
  const Model a = awt27(stiff), b = awt27(none);
  const OperatingPoint pa = solveOperatingPoint(a, initialPoint(a)), pb = solveOperatingPoint(b, initialPoint(b));
  EXPECT_TRUE(checkPointValidity(a, pa).empty());
  const LinearModel la = linearize(a, pa), lb = linearize(b, pb);
  EXPECT_EQ(la.K, lb.K);
  EXPECT_EQ(la.C, lb.C);
}

TEST(TeeterStops, BeyondAStopItIsASpringAboutTheStopAngle) {
  const Model m = awt27({"TeetSStP=5", "TeetSSSp=1e6", "TeetHStP=20", "TeetDmpP=2", "TeetDefl=-8"});
  const std::vector<DofSpring> laws = teeterLaws(m);
  ASSERT_EQ(laws.size(), 3u);
  EXPECT_EQ(laws[0].k, 1e6);
  EXPECT_DOUBLE_EQ(laws[0].q0, -5 * deg);
  EXPECT_DOUBLE_EQ(laws[0].q_max, -5 * deg);
  EXPECT_EQ(laws[0].q_min, -std::numeric_limits<double>::infinity());
  EXPECT_EQ(laws[1].k, 0.0);      // the hard stop at 20 deg not reached
  EXPECT_EQ(laws[2].c, 40000.0);  // beyond TeetDmpP = 2 deg: damped
  EXPECT_DOUBLE_EQ(laws[2].q_max, -2 * deg);
}

// Turning, the centrifugal moment pulls the teeter back inside the soft stop the model was linearized
// beyond: that point is not valid, and the check says which law and why.
TEST(TeeterStops, APointThatLeavesThePieceIsInvalid) {
  const Model m = awt27(
      {"TeetSStP=5", "TeetSSSp=1e6", "TeetDefl=8", "FlapDOF1=False", "FlapDOF2=False", "EdgeDOF=False"});
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  EXPECT_LT(op.q(m.roles.teeter_dof), 5 * deg);
  const std::vector<std::string> problems = checkPointValidity(m, op);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_THAT(problems[0], HasSubstr("teeter: "));
  EXPECT_THAT(problems[0], HasSubstr("teeter soft-stop spring (TeetSSSp) acting beyond TeetSStP = 5 deg"));
}

TEST(TeeterStops, WithoutTeetDofTheTeeterIsFrozenAtTeetDefl) {
  const Model m = awt27({"TeetDOF=False", "TeetDefl=3"});
  ASSERT_GE(m.roles.teeter_dof, 0);
  EXPECT_TRUE(m.dofs[m.roles.teeter_dof].frozen);
  EXPECT_DOUBLE_EQ(m.dofs[m.roles.teeter_dof].value, 3 * deg);
  EXPECT_TRUE(teeterLaws(m).empty());
}

}  // namespace
}  // namespace whirl
