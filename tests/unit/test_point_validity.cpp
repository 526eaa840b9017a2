// The operating-point validity check (issue 14, item 5): deflection against body length, elastic
// slope, equilibrium residual (linearize/point_validity.hpp).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "linearize/operating_point.hpp"
#include "linearize/point_validity.hpp"
#include "src/io/case/case_file.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using testing::HasSubstr;

// --- operating-point validity -----------------------------------------------------------------

whirl::Model landbased(const std::string& gravity) {
  return whirl::readCase((whirl::test::sourceDir() / "cases/landbased_2dof/landbased_2dof.yaml").string(),
                         {whirl::parseOverride("gravity=" + gravity)});
}

TEST(PointValidity, NominalPointIsValid) {
  const whirl::Model m = landbased("9.80665");
  const whirl::OperatingPoint op = whirl::solveOperatingPoint(m, whirl::initialPoint(m));
  EXPECT_TRUE(whirl::checkPointValidity(m, op).empty());
}

TEST(PointValidity, HugeGravityGivesADeflectionBeyondTheBodyLength) {
  // NREL 5MW at 1000 m/s² (100 g, the limit): Newton converges to blade tip deflections beyond 0.3 L.
  const whirl::Model m = whirl::readElastoDynModel((whirl::test::nrel5mwDir() / "Main_Onshore.fst").string(),
                                                   {"gravity=1000"});
  const whirl::OperatingPoint op = whirl::solveOperatingPoint(m, whirl::initialPoint(m));
  const std::vector<std::string> problems = whirl::checkPointValidity(m, op);
  ASSERT_FALSE(problems.empty());
  EXPECT_THAT(problems.front(), HasSubstr("blade "));
  EXPECT_THAT(problems.front(), HasSubstr("elastic deflection"));
  EXPECT_THAT(problems.front(), HasSubstr("its length 61.5 m (limit 0.3)"));
  // The same turbine at Earth's gravity is valid.
  const whirl::Model nominal = whirl::readElastoDynModel((whirl::test::nrel5mwDir() / "Main_Onshore.fst").string());
  EXPECT_TRUE(
      whirl::checkPointValidity(nominal, whirl::solveOperatingPoint(nominal, whirl::initialPoint(nominal))).empty());
}

TEST(PointValidity, SlopeAndResidualAreChecked) {
  const whirl::Model m = landbased("9.80665");
  whirl::OperatingPoint op = whirl::solveOperatingPoint(m, whirl::initialPoint(m));
  // A tip deflection of 10 m on 87.6 m is within 0.3 L; its slope (about 0.2 rad) is beyond a 0.01 rad limit.
  whirl::ValidityLimits lim;
  lim.max_slope = 0.01;
  const auto tower = std::find_if(m.bodies.begin(), m.bodies.end(),
                                  [](const whirl::Body& b) { return b.name == "tower"; });
  ASSERT_NE(tower, m.bodies.end());
  op.q(tower->elastic_dof) = 10.0;
  const auto problems = whirl::checkPointValidity(m, op, lim);
  ASSERT_FALSE(problems.empty());
  EXPECT_THAT(problems.front(), HasSubstr("tower: elastic slope"));
  op.residual_norm = 1.0;
  op.load_scale = 1.0;
  const auto p2 = whirl::checkPointValidity(m, op, lim);
  EXPECT_THAT(p2.back(), HasSubstr("equilibrium residual 1 is not small"));
}

}  // namespace
