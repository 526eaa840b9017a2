// The quasi-static catenary (src/dynamics/catenary.hpp): the solution satisfies the profile
// equations, its AD derivative is the implicit-function derivative (checked here against central
// differences of the double solve, a test-only cross-check), the seabed branch is continuous, and a
// line that cannot reach its anchor is a one-line ComputeError naming it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "src/dynamics/catenary.hpp"
#include "src/model/error.hpp"

namespace whirl {
namespace {

// One OC3-Hywind line (the MAP++ file of OpenFAST's Test24, cases/oc3_hywind): 902.2 m, 77.7066 kg/m
// of 0.09 m diameter (698.09 N/m in water), EA 384.243 MN, anchor 853.87 m from the axis at 320 m
// depth, fairlead 5.2 m from the axis at 70 m depth.
MooringLine oc3Line() {
  MooringLine l;
  l.name = "oc3 line";
  l.length = 902.2;
  l.weight = (77.7066 - 1025 * 3.14159265358979 * 0.09 * 0.09 / 4) * 9.80665;
  l.EA = 384.243e6;
  l.CB = 0.001;
  l.seabed = true;
  return l;
}

TEST(Catenary, SolvesTheProfileEquations) {
  const MooringLine l = oc3Line();
  const double x = 853.87 - 5.2, h = 250;
  const CatenaryTension<double> t = catenaryTension(l, x, h);
  EXPECT_GT(t.H, 0);
  EXPECT_GT(t.V, 0);
  EXPECT_LT(catenaryResidual(l, t.H, t.V, x, h).norm(), 1e-6);
  EXPECT_GT(catenarySeabedLength(l, t.V), 0);  // part of the OC3 line rests on the seabed
}

TEST(Catenary, AdDerivativeIsTheImplicitFunctionDerivative) {
  for (bool seabed : {true, false}) {
    MooringLine l = oc3Line();
    l.seabed = seabed;
    const double x = 848.67, h = 250, dx = 1e-3;
    ADChunk X(x), Hh(h);
    X.derivatives() = Eigen::Matrix<double, kChunk, 1>::Unit(0);
    Hh.derivatives() = Eigen::Matrix<double, kChunk, 1>::Unit(1);
    const CatenaryTension<ADChunk> t = catenaryTension(l, X, Hh);
    const auto a = catenaryTension(l, x + dx, h), b = catenaryTension(l, x - dx, h);
    const auto c = catenaryTension(l, x, h + dx), d = catenaryTension(l, x, h - dx);
    EXPECT_NEAR(t.H.derivatives()(0), (a.H - b.H) / (2 * dx), 1e-5 * std::abs(t.H.derivatives()(0))) << seabed;
    EXPECT_NEAR(t.V.derivatives()(0), (a.V - b.V) / (2 * dx), 1e-5 * std::abs(t.V.derivatives()(0)) + 1e-3) << seabed;
    EXPECT_NEAR(t.H.derivatives()(1), (c.H - d.H) / (2 * dx), 1e-5 * std::abs(t.H.derivatives()(1))) << seabed;
    EXPECT_NEAR(t.V.derivatives()(1), (c.V - d.V) / (2 * dx), 1e-5 * std::abs(t.V.derivatives()(1))) << seabed;
    // The AD value is one more Newton step from the converged double: equal to the solver's tolerance.
    EXPECT_NEAR(t.H.value(), catenaryTension(l, x, h).H, 1e-8 * t.H.value());
  }
}

TEST(Catenary, TautLineStretches) {
  MooringLine l = oc3Line();
  const double x = 900, h = 250;  // straight distance 934 m > 902.2 m: taut, stretched
  const CatenaryTension<double> t = catenaryTension(l, x, h);
  EXPECT_LT(catenaryResidual(l, t.H, t.V, x, h).norm(), 1e-6);
  EXPECT_EQ(catenarySeabedLength(l, t.V), 0.0);
  EXPECT_GT(std::hypot(t.H, t.V), 0.01 * l.EA);  // 3.5 % longer than its unstretched length
}

TEST(Catenary, LineThatCannotReachItsAnchorIsAComputeError) {
  const MooringLine l = oc3Line();
  try {
    catenaryTension(l, 2000.0, 250.0);  // would stretch the line by 125 %
    FAIL() << "no error";
  } catch (const ComputeError& e) {
    EXPECT_THAT(e.what(), ::testing::StartsWith("oc3 line: "));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("cannot reach its anchor"));
  }
  EXPECT_THROW(catenaryTension(l, 0.0, 250.0), ComputeError);
}

}  // namespace
}  // namespace whirl
