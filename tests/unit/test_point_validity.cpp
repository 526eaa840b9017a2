// The operating-point validity check (issue 14, item 5): deflection against body length, elastic
// slope, equilibrium residual (linearize/point_validity.hpp).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "linearize/operating_point.hpp"
#include "linearize/periodic.hpp"
#include "linearize/point_validity.hpp"
#include "src/base/error.hpp"
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

// At 100 g, at azimuth 180° of a periodic linearization, the Newton matrix of the NREL 5MW is singular along a blade's
// elastic coordinate. That coordinate has its own stiffness, so the error says the loads cancel it, not that it has "no
// stiffness (a free rigid-body motion)", the message of a joint without a spring (hardening issue, item 5: messages
// that name the wrong cause).
TEST(PointValidity, ASingularMatrixAlongAnElasticDofIsNotCalledUnrestrained) {
  const whirl::Model m = whirl::readElastoDynModel((whirl::test::nrel5mwDir() / "Main_Onshore.fst").string(),
                                                   {"gravity=1000"});
  whirl::PeriodicOptions opt;  // as `whirl modes` of the deck (12.1 rpm): azimuths 0, 90, 180, 270°
  opt.azimuths = 4;
  try {
    whirl::linearizePeriodic(m, whirl::modelCondition(m), opt);
    FAIL() << "expected a ComputeError";
  } catch (const whirl::ComputeError& e) {
    EXPECT_THAT(e.what(), HasSubstr("azimuth 180 deg: operating point: the stiffness along DOF 'blade "));
    EXPECT_THAT(e.what(), HasSubstr("' is cancelled (the Newton matrix is singular there"));
    EXPECT_THAT(e.what(), ::testing::Not(HasSubstr("no stiffness")));
  }
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
