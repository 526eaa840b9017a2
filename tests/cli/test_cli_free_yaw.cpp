// Issue 16: a deck with a free yaw (YawDOF = True, no yaw spring) gives a Campbell diagram at rotor
// speed, the yaw held and reported as a rigid-body mode; a yaw spring too weak for the loads gives
// an error naming the yaw, the load and how to hold it, and no output.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

TEST(CliFreeYaw, CampbellHoldsTheYaw) {
  const auto dir = test::freshDir("free_yaw");
  const auto r = test::whirl(
      "campbell tests/data/openfast/ws03/ws03.0.fst --set CompAero=0 --rpm 0:3.486:6.972 "
      "--azimuths 4 --no-plot --out '" +
      dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(test::slurp(dir / "campbell_modes.json"));
  ASSERT_EQ(j["points"].size(), 3u);
  for (const auto& p : j["points"]) {
    int yaw = 0;
    for (const auto& m : p["modes"])
      if (m["name"] == "yaw (rigid body)") {
        ++yaw;
        EXPECT_TRUE(m["rigid_body"].get<bool>());
      }
    EXPECT_EQ(yaw, 1);
  }
  // Rigid-body modes are not Campbell lines.
  EXPECT_THAT(test::slurp(dir / "campbell.csv"), ::testing::Not(HasSubstr("yaw")));
}

TEST(CliFreeYaw, LinearizeListsTheHeldYaw) {
  const auto dir = test::freshDir("free_yaw_lin");
  const auto r = test::whirl("linearize tests/data/openfast/ws03/ws03.0.fst --set CompAero=0 --out '" + dir.string() +
                             "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(test::slurp(dir / "linearization.json"));
  EXPECT_EQ(j["equilibrium"]["held_dofs"], nlohmann::json::array({"yaw"}));
  EXPECT_EQ(j["operating_point"]["q"]["yaw"].get<double>(), 0.0);
}

TEST(CliFreeYaw, WeakYawSpringNamesTheYaw) {
  const auto dir = test::freshDir("weak_yaw");
  const auto r = test::whirl(
      "campbell tests/data/openfast/aero/toolbox/Main.fst --set CompAero=0 --set YawDOF=True --set YawSpr=1 "
      "--set TwFADOF1=True --set TwSSDOF1=True --set TwFADOF2=True --set TwSSDOF2=True --rpm 9:1:9 --azimuths 4 "
      "--no-plot --out '" +
      dir.string() + "'");
  EXPECT_NE(r.code, 0);
  // The file, then the sweep point that failed (issue 41: errors name the operating point), then why.
  EXPECT_THAT(r.err, HasSubstr("tests/data/openfast/aero/toolbox/Main.fst: operating point 1 (9 rpm, pitch 0 deg, "
                               "azimuth 0 deg): "));
  EXPECT_THAT(r.err, HasSubstr("operating point did not converge in 50 Newton iterations"));
  EXPECT_THAT(r.err, HasSubstr("DOF 'yaw' is nearly unrestrained (stiffness 1 N m/rad) and a load of"));
  EXPECT_THAT(r.err,
              HasSubstr("hold it with --set YawDOF=False, or a yaw spring (ServoDyn YawSpr with CompServo = 1)"));
  EXPECT_FALSE(fs::exists(dir / "campbell.csv"));
}

}  // namespace
}  // namespace whirl
