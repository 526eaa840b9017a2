// The command line as a user meets it: `whirl modes` and `whirl linearize` on real cases, their
// outputs, and one-line errors with a non-zero exit and no partial output on bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

TEST(CliModes, TowerForeAftOfTheTwoDofCaseAsCsv) {
  const auto r = test::whirl("modes cases/landbased_2dof/landbased_2dof.yaml --format csv");
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream in(r.out);
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header, "index,name,freq_hz,damped_freq_hz,damping_ratio");
  bool found = false;
  while (std::getline(in, line)) {
    if (line.find(",tower FA 1,") == std::string::npos) continue;
    found = true;
    const double f = std::stod(line.substr(line.find(",tower FA 1,") + 12));
    EXPECT_NEAR(f, 0.3272, 0.00005);  // [BranlardGeisler2022, §4.4], 4 printed digits
  }
  EXPECT_TRUE(found) << r.out;
  EXPECT_THAT(r.out, HasSubstr("1,azimuth,0,0,0"));  // the rigid-body mode at frequency 0, sorted first
}

TEST(CliModes, TableAndJsonFormatsAndOverrides) {
  const auto t = test::whirl("modes cases/torsion_tube/torsion_tube.yaml");
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_THAT(t.out, HasSubstr("torsion 1"));
  const auto j = test::whirl("modes cases/landbased_2dof/landbased_2dof.yaml --format json --set gravity=0 --rpm 12");
  ASSERT_EQ(j.code, 0) << j.err;
  const auto doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc["modes"].size(), 2u);
  EXPECT_TRUE(doc["modes"][0]["participation"].contains("azimuth"));
}

TEST(CliLinearize, WritesMatricesAndJson) {
  const auto dir = test::freshDir("lin");
  const auto r = test::whirl("linearize cases/landbased_3dof/landbased_3dof.yaml --rpm 9 --out '" + dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"M.csv", "C.csv", "K.csv", "Q.csv", "A.csv", "B.csv", "linearization.json"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  const std::string K = test::slurp(dir / "K.csv");
  EXPECT_EQ(K.substr(0, K.find('\n')), "dof,tower FA 1,tower SS 1,azimuth");
  const std::string B = test::slurp(dir / "B.csv");
  EXPECT_EQ(B.substr(0, B.find('\n')), "state,thrust,aero torque");
  const auto j = nlohmann::json::parse(test::slurp(dir / "linearization.json"));
  EXPECT_NEAR(j["operating_point"]["qd"]["azimuth"].get<double>(), 9 * 2 * M_PI / 60, 1e-12);
  EXPECT_LT(j["equilibrium"]["residual_norm"].get<double>(), 1e-3);
  EXPECT_EQ(j["dofs"].size(), 3u);
  for (const auto& e : fs::directory_iterator(dir)) EXPECT_THAT(e.path().string(), ::testing::Not(HasSubstr(".tmp")));
}

TEST(CliErrors, OneLineReasonNonZeroExitNoOutput) {
  const auto dir = test::freshDir("bad");
  struct Case {
    std::string args, expect;
  };
  const Case cases[] = {
      {"modes cases/does_not_exist.yaml", "does_not_exist.yaml"},
      {"modes cases/landbased_2dof/landbased_2dof.yaml --set bodies.nacelle.mass=-1", "negative mass"},
      {"modes cases/landbased_2dof/landbased_2dof.yaml --set bodies.nacelle.masss=1", "masss"},
      {"modes cases/landbased_2dof/landbased_2dof.yaml --set gravity=nan", "gravity"},
      {"modes cases/torsion_tube/torsion_tube.yaml --rpm 10", "no rotating DOF"},
      {"linearize cases/landbased_2dof/landbased_2dof.yaml --set bodies.tower.uniform.m=1 --out '" + dir.string() + "'",
       "uniform"},
  };
  for (const auto& c : cases) {
    const auto r = test::whirl(c.args);
    EXPECT_NE(r.code, 0) << c.args;
    EXPECT_THAT(r.err, HasSubstr(c.expect)) << c.args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_THAT(r.err, HasSubstr("whirl: error: "));
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(CliErrors, UnwritableOutputFolder) {
  const auto r = test::whirl("linearize cases/landbased_2dof/landbased_2dof.yaml --out /proc/whirl-cannot-write");
  EXPECT_NE(r.code, 0);
  EXPECT_THAT(r.err, HasSubstr("/proc/whirl-cannot-write"));
}

TEST(CliHelp, EverySubcommandHasHelp) {
  for (const char* sub : {"", "modes ", "linearize "}) {
    const auto r = test::whirl(std::string(sub) + "--help");
    EXPECT_EQ(r.code, 0) << sub;
    EXPECT_THAT(r.out, HasSubstr("Usage")) << sub;
  }
}

}  // namespace
}  // namespace whirl
