// `whirl shapes`: FE shapes of a YAML case and of the NREL 5MW, formats, written files, errors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <nlohmann/json.hpp>

#include "src/shapes/shape.hpp"
#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

// cases/tower_topmass/tower_topmass_fem.yaml: FE frequencies of the case's FE settings are the exact
// [Branlard2019, eq. 32] values (uniform beam, Mt/M = 0.5); its current shapes are those same FE modes.
TEST(CliShapes, TowerTopMassCaseAsJson) {
  const auto r = test::whirl("shapes cases/tower_topmass/tower_topmass_fem.yaml --format json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_EQ(doc["shapes"].size(), 4u);
  for (int j = 1; j <= 4; ++j) {
    const auto& s = doc["shapes"][j - 1];
    EXPECT_EQ(s["shape"], "tower FA " + std::to_string(j));
    EXPECT_EQ(s["direction"], "z");
    const double b = clampedTopMassBeta(j, 0.5),
                 f = (b / 100) * (b / 100) * std::sqrt(2e12 / 9000) / (2 * std::numbers::pi);
    EXPECT_NEAR(s["freq_hz"].get<double>(), f, 1e-6 * f) << j;  // 100 cubic elements: ~1e-9
    EXPECT_NEAR(s["mac"].get<double>(), 1.0, 1e-12);
    double sum = 0;
    for (double a : s["coefficients"]) sum += a;
    EXPECT_NEAR(sum, 1.0, 1e-12);  // ElastoDyn's form: the coefficients sum to 1
  }
}

TEST(CliShapes, NrelFiveMegawattTableAndFiles) {
  const fs::path out = test::freshDir("shapes_nrel");
  const auto r = test::whirl("shapes cases/nrel5mw/Main_Onshore.fst --set RotSpeed=0 --out '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* s : {"tower FA 1", "tower SS 2", "blade 1", "flap 1", "edge 1", "flap 2"})
    EXPECT_THAT(r.out, HasSubstr(s));
  EXPECT_TRUE(fs::exists(out / "shapes.csv"));
  EXPECT_TRUE(fs::exists(out / "shapes.json"));
  EXPECT_TRUE(fs::exists(out / "shape_tower_tower_FA_1.csv"));
  EXPECT_THAT(test::slurp(out / "shapes.csv"), HasSubstr("body,shape,direction,mode,freq_hz,a2,a3,a4,a5,a6"));
  // A blade at 12.1 rpm is stiffer in flap than parked (centrifugal stiffening).
  auto flap1 = [](const std::string& csv) {
    const auto p = csv.find("blade 1,flap 1,y,1,");
    return std::stod(csv.substr(p + 19));
  };
  const auto p0 = test::whirl("shapes cases/nrel5mw/Main_Onshore.fst --format csv --rpm 0");
  const auto p12 = test::whirl("shapes cases/nrel5mw/Main_Onshore.fst --format csv --rpm 12.1");
  ASSERT_EQ(p0.code, 0) << p0.err;
  ASSERT_EQ(p12.code, 0) << p12.err;
  EXPECT_GT(flap1(p12.out), 1.03 * flap1(p0.out));
}

TEST(CliShapes, HelpAndErrors) {
  const auto h = test::whirl("shapes --help");
  EXPECT_EQ(h.code, 0);
  EXPECT_THAT(h.out, HasSubstr("--format"));
  const auto missing = test::whirl("shapes cases/nope.yaml");
  EXPECT_NE(missing.code, 0);
  EXPECT_THAT(missing.err, HasSubstr("nope.yaml"));
  const auto rpm = test::whirl("shapes cases/tower_topmass/tower_topmass_fem.yaml --rpm 3");
  EXPECT_NE(rpm.code, 0);
  EXPECT_THAT(rpm.err, HasSubstr("rotor_speed_rpm"));
  const auto key = test::whirl("shapes cases/tower_topmass/tower_topmass_fem.yaml --set bodies.tower.shapes.tip_mas=3");
  EXPECT_NE(key.code, 0);
  EXPECT_THAT(key.err, HasSubstr("tip_mas"));
  EXPECT_EQ(std::count(key.err.begin(), key.err.end(), '\n'), 1) << key.err;
  const auto bad = test::whirl("modes cases/nrel5mw/Main_Onshore.fst --set shapes=splines");
  EXPECT_NE(bad.code, 0);
  EXPECT_THAT(bad.err, HasSubstr("shapes"));
  const auto fmt = test::whirl("shapes cases/tower_topmass/tower_topmass_fem.yaml --format xml");
  EXPECT_NE(fmt.code, 0);
}

}  // namespace
}  // namespace whirl
