// HydroDyn's member tables and the fluid of its filled members: the OC4-DeepCwind semi's tables
// (OpenFAST certification Test25, a copy in cases/oc4_semi) as read; malformed rows named by file and
// line; the ballast's mass matrix against closed forms (cylinder, inclined and tapered members,
// horizontal members above and below the fill level).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "src/io/openfast/offshore/hydrodyn_input.hpp"
#include "src/io/openfast/openfast_overrides.hpp"
#include "src/turbine/hydrodyn_ballast.hpp"
#include "tests/unit/test_util.hpp"

namespace whirl {
namespace {

using test::errorOf;
using ::testing::HasSubstr;

const std::string kSemi = std::string(WHIRL_SOURCE_DIR) +
                          "/cases/oc4_semi/5MW_Baseline/NRELOffshrBsline5MW_OC4DeepCwindSemi_HydroDyn.dat";

io::HydroDynInput read(const std::string& file) {
  io::OverrideSet sets({io::parseOverride("RdtnMod=0")});
  return io::readHydroDyn(file, &sets);
}

TEST(HydroDynMembers, Oc4SemiTables) {
  const io::HydroDynMembers m = read(kSemi).geometry;
  ASSERT_EQ(m.joints.size(), 44u);
  ASSERT_EQ(m.props.size(), 4u);
  ASSERT_EQ(m.members.size(), 25u);
  ASSERT_EQ(m.fills.size(), 2u);
  EXPECT_EQ(m.joint(42)->position, Vec3(14.43376, 25.0, -19.94));
  EXPECT_EQ(m.prop(3)->D, 24.0);
  EXPECT_EQ(m.prop(3)->thickness, 0.06);
  const io::HydroDynMember& base1 = *m.member(5);
  EXPECT_EQ(base1.joint1, 42);
  EXPECT_EQ(base1.joint2, 3);
  EXPECT_TRUE(base1.PropPot);
  EXPECT_EQ(m.fills[0].members, (std::vector<int>{2, 3, 4}));
  EXPECT_EQ(m.fills[0].FillFSLoc, -6.17);
  EXPECT_EQ(m.fills[1].FillDens, 1025.0);
  ASSERT_EQ(m.member_coefs.size(), 25u);
  EXPECT_EQ(m.memberCoef(23)->line, 169);
  EXPECT_EQ(m.SimplCa, 0.0);
  EXPECT_EQ(m.axialCoef(2)->AxCa, 0.0);
}

// OpenFAST v4.1 names the member-based table's count NCoefMembersCyl: the same rows.
TEST(HydroDynMembers, MemberCoefficientsUnderTheV41Key) {
  const test::TempDir dir;
  const std::string f = test::editedCopy(dir, kSemi, "hd.dat", "NCoefMembers       - Number",
                                         "NCoefMembersCyl    - Number");
  EXPECT_EQ(read(f).geometry.member_coefs.size(), 25u);
}

TEST(HydroDynMembers, MalformedRowsNameTheirLine) {
  const test::TempDir dir;
  auto error = [&](const std::string& from, const std::string& to) {
    const std::string f = test::editedCopy(dir, kSemi, "hd.dat", from, to);
    return errorOf([&] { read(f); });
  };
  const std::string member5 = "    5        42          3           3";
  EXPECT_THAT(error(member5, "    5        99          3           3"),
              HasSubstr("hd.dat:195: MJointID1: joint 99 is not in the joint table"));
  EXPECT_THAT(error(member5, "    5         3          3           3"),
              HasSubstr("hd.dat:195: MemberID: member 5 has zero length (its two joints coincide)"));
  EXPECT_THAT(error(member5, "    5        42          3           9"),
              HasSubstr("hd.dat:195: MPropSetID1: property set 9 is not in the property table"));
  EXPECT_THAT(error("    4        1.60000        0.01750", "    4        1.60000        0.90000"),
              HasSubstr("hd.dat:149: PropThck: must be between 0 and half the diameter PropD"));
  EXPECT_THAT(error("    3       24.00000        0.06000", "    3       -24.00000        0.06000"),
              HasSubstr("hd.dat:148: PropD: must be positive"));
  const std::string group2 = "    3   5   6   7   -14.89           1025";
  EXPECT_THAT(error(group2, "    3   5   6   2   -14.89           1025"),
              HasSubstr("hd.dat:221: FillMList: member 2 is already in a fill group"));
  EXPECT_THAT(error(group2, "    3   5   6   77   -14.89           1025"),
              HasSubstr("hd.dat:221: FillMList: member 77 is not in the member table"));
  EXPECT_THAT(error(group2, "    3   5   6   7   -14.89           -5"),
              HasSubstr("hd.dat:221: FillDens: must be positive (or DEFAULT)"));
  EXPECT_THAT(error(group2, "    4   5   6   7   -14.89           1025"),
              HasSubstr("hd.dat:221: FillMList: expected FillNumM = 4 member ids, then FillFSLoc and FillDens"));
  EXPECT_THAT(error(group2, "    3   5   6   7   deep           1025"),
              HasSubstr("hd.dat:221: FillFSLoc: 'deep' is not a finite number"));
  EXPECT_THAT(error("             2   NFillGroups", "             3   NFillGroups"),
              HasSubstr("hd.dat:217: NFillGroups: 3 rows expected below it"));
  EXPECT_THAT(error("            44   NJoints", "         99999   NJoints"),
              HasSubstr("NJoints: must be between 0 and 10000"));
  EXPECT_THAT(error("    1         1          2           1            1         1.0000      3        TRUE",
                    "    1         1          2           1            1         1.0000      3        maybe"),
              HasSubstr("hd.dat:191: PropPot: 'maybe' is not True or False"));
  // A strip-theory member is read (a floating platform refuses it: OffshoreModel tests).
  EXPECT_EQ(error("    1         1          2           1            1         1.0000      3        TRUE",
                  "    1         1          2           1            1         1.0000      3        FALSE"),
            "no error");
  EXPECT_THAT(error("    1         1          2           1            1         1.0000      3        TRUE",
                    "    1         1          2           1            1         1.0000      7        TRUE"),
              HasSubstr("hd.dat:191: MCoefMod: must be 1 (simple), 2 (depth-based) or 3 (member-based)"));
  const std::string f = test::editedCopy(dir, kSemi, "default.dat", group2, "    3   5   6   7   -14.89   DEFAULT");
  EXPECT_FALSE(read(f).geometry.fills[1].FillDens.has_value());
}

// One member as a fill group of its own, ρ = 1000 kg/m³ unless given.
io::HydroDynMembers oneMember(const Vec3& a, const Vec3& b, double Da, double Db, double t, double fill_level) {
  io::HydroDynMembers m;
  m.joints = {{1, a, 1}, {2, b, 2}};
  m.props = {{1, Da, t, 3}, {2, Db, t, 4}};
  m.members = {{7, 1, 2, 1, 2, true, 5}};
  m.fills = {{{7}, fill_level, std::nullopt, 6}};
  return m;
}

constexpr double kRho = 1000.0, kG = 9.81;

TEST(HydroDynBallast, VerticalCylinderFilledToItsLevel) {
  // R = 5 − 0.1 inside, from z = −20 up to the fill level −10, at x = 10, y = −4.
  const io::HydroDynMembers m = oneMember({10, -4, -20}, {10, -4, 0}, 10.0, 10.0, 0.1, -10.0);
  const elastodyn::Ballast b = elastodyn::ballastOf(m, kRho, kG, Vec3::Zero());
  const double mass = kRho * M_PI * 4.9 * 4.9 * 10.0, zc = -15.0, h = 10.0;
  EXPECT_NEAR(b.mass, mass, 1e-9 * mass);
  EXPECT_LT((b.centre - Vec3(10, -4, zc)).norm(), 1e-9);
  // A line mass: about the origin Σ m (y² + z²) for roll, (x² + z²) for pitch, (x² + y²) for yaw.
  EXPECT_NEAR(b.M(3, 3), mass * (16 + zc * zc + h * h / 12), 1e-9 * b.M(3, 3));
  EXPECT_NEAR(b.M(4, 4), mass * (100 + zc * zc + h * h / 12), 1e-9 * b.M(4, 4));
  EXPECT_NEAR(b.M(5, 5), mass * (100 + 16), 1e-9 * b.M(5, 5));
  EXPECT_NEAR(b.M(3, 4), mass * 10 * 4, 1e-9 * b.M(4, 4));  // −Σ m x y = +40 m (y = −4)
  EXPECT_NEAR(b.M(0, 4), mass * zc, 1e-9 * mass * 15);      // surge–pitch: Σ m z
  EXPECT_NEAR(b.M(2, 4), -mass * 10, 1e-9 * mass * 15);     // heave–pitch: −Σ m x
  EXPECT_LT((b.M - b.M.transpose()).norm(), 1e-9 * b.M.norm());
  const double W = mass * kG;
  EXPECT_NEAR(b.weight(2), -W, 1e-9 * W);
  EXPECT_NEAR(b.weight(3), -W * -4, 1e-9 * W * 4);
  EXPECT_NEAR(b.weight(4), W * 10, 1e-9 * W * 10);
  // About another origin: the same body, the parallel-axis shift.
  const elastodyn::Ballast c = elastodyn::ballastOf(m, kRho, kG, Vec3(0, 0, -15));
  EXPECT_NEAR(c.M(4, 4), mass * (100 + h * h / 12), 1e-9 * c.M(4, 4));
}

TEST(HydroDynBallast, InclinedTaperedAndHorizontalMembers) {
  // Inclined at 45° from (0,0,−20) to (20,0,0), filled to −10: half its length, joint 2 end up.
  const double r = 2.0;
  const io::HydroDynMembers inc = oneMember({0, 0, -20}, {20, 0, 0}, 2 * r, 2 * r, 0.0, -10.0);
  const elastodyn::Ballast a = elastodyn::ballastOf(inc, kRho, kG, Vec3::Zero());
  const double L = std::sqrt(2.0) * 10.0;
  EXPECT_NEAR(a.mass, kRho * M_PI * r * r * L, 1e-9 * a.mass);
  EXPECT_LT((a.centre - Vec3(5, 0, -15)).norm(), 1e-9);
  // The same member given from its top end: the filled part is the same.
  const io::HydroDynMembers flipped = oneMember({20, 0, 0}, {0, 0, -20}, 2 * r, 2 * r, 0.0, -10.0);
  EXPECT_LT((elastodyn::ballastOf(flipped, kRho, kG, Vec3::Zero()).M - a.M).norm(), 1e-9 * a.M.norm());
  // A frustum filled whole (level above it): π h (r1² + r1 r2 + r2²) / 3.
  const io::HydroDynMembers cone = oneMember({0, 0, -30}, {0, 0, -10}, 8.0, 4.0, 0.0, 0.0);
  const double vol = M_PI * 20.0 * (16.0 + 8.0 + 4.0) / 3.0;
  EXPECT_NEAR(elastodyn::ballastOf(cone, kRho, kG, Vec3::Zero()).mass, kRho * vol, 1e-9 * kRho * vol);
  // Horizontal: all or nothing. FillDens given overrides the water density.
  io::HydroDynMembers low = oneMember({0, 0, -10}, {10, 0, -10}, 2.0, 2.0, 0.0, -9.0);
  low.fills[0].FillDens = 2000.0;
  EXPECT_NEAR(elastodyn::ballastOf(low, kRho, kG, Vec3::Zero()).mass, 2000.0 * M_PI * 10.0, 1e-9);
  const io::HydroDynMembers high = oneMember({0, 0, -10}, {10, 0, -10}, 2.0, 2.0, 0.0, -11.0);
  EXPECT_EQ(elastodyn::ballastOf(high, kRho, kG, Vec3::Zero()).mass, 0.0);
}

}  // namespace
}  // namespace whirl
