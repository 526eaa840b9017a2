// The quasi-static catenary (src/dynamics/catenary.hpp): the solution satisfies the profile
// equations, its AD derivative is the implicit-function derivative (checked here against central
// differences of the double solve, a test-only cross-check), the seabed branch is continuous, and a
// line that cannot reach its anchor is a one-line ComputeError naming it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "src/base/error.hpp"
#include "src/dynamics/catenary.hpp"

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

// One MIT/NREL TLP tendon (the MAP++ file of OpenFAST's Test23 deck set): 151.73 m, 116.027 kg/m of
// 0.127 m diameter, EA 1.5 GN, anchor 200 m deep straight below a fairlead 47.89 m deep.
MooringLine tlpTendon() {
  MooringLine l;
  l.name = "tlp tendon";
  l.length = 151.73;
  l.weight = (116.027 - 1025 * 3.14159265358979 * 0.127 * 0.127 / 4) * 9.80665;
  l.EA = 1.5e9;
  l.CB = 1.0;
  l.seabed = true;
  return l;
}

// Straight below its fairlead (span 0) the profile equations at H = 0 are closed forms: the height
// h = L + (V L − w L²/2)/EA gives V, and the pendulum stiffness H/l = 1/X(0, V),
// X(0, V) = ln(V/(V − w L))/w + L/EA.
TEST(Catenary, VerticalTendonIsTheClosedForm) {
  const MooringLine l = tlpTendon();
  const double h = 200 - 47.89, w = l.weight, L = l.length;
  const Vec3 F = mooringFairleadForce<double>(l, Vec3(0, 0, h));
  const double V = l.EA * (h - L) / L + 0.5 * w * L;
  const double q = 1.0 / (std::log(V / (V - w * L)) / w + L / l.EA);
  EXPECT_NEAR(-F(2), V, 1e-10 * V);
  EXPECT_EQ(F(0), 0.0);
  EXPECT_EQ(F(1), 0.0);
  // The AD derivative at span 0: ∂F_x/∂d_x = −H/l, ∂F_z/∂d_z by central differences of the double.
  Vec3T<ADChunk> d;
  for (int k = 0; k < 3; ++k) {
    d(k) = ADChunk(k == 2 ? h : 0.0);
    d(k).derivatives() = Eigen::Matrix<double, kChunk, 1>::Unit(k);
  }
  const Vec3T<ADChunk> Fd = mooringFairleadForce<ADChunk>(l, d);
  EXPECT_NEAR(Fd(0).derivatives()(0), -q, 1e-9 * q);
  EXPECT_NEAR(Fd(1).derivatives()(1), -q, 1e-9 * q);
  EXPECT_NEAR(Fd(0).derivatives()(2), 0.0, 1e-9 * q);
  const double dz = 1e-4;
  const double kz = (mooringFairleadForce<double>(l, Vec3(0, 0, h + dz))(2) -
                     mooringFairleadForce<double>(l, Vec3(0, 0, h - dz))(2)) /
                    (2 * dz);
  EXPECT_NEAR(Fd(2).derivatives()(2), kz, 1e-6 * std::abs(kz));
  EXPECT_NEAR(kz, -l.EA / L, 1e-3 * l.EA / L);  // nearly the axial stiffness EA/L
}

// Tilted, the same tendon solved as a catenary (span l = 2 m) and in the taut-line form (s = l²): two
// parameterizations of the same equations, one answer.
TEST(Catenary, TautLineFormIsTheCatenary) {
  const MooringLine l = tlpTendon();
  const double h = 152.11, span = 2.0;
  const CatenaryTension<double> c = catenaryTension(l, span, h);
  const CatenaryTension<double> t = tautLineTension(l, span * span, h);
  EXPECT_NEAR(t.H * span, c.H, 1e-8 * c.H);
  EXPECT_NEAR(t.V, c.V, 1e-9 * c.V);  // the two solvers' tolerances
  // Across the switch between the two forms (span² = 1e-6 L²) the force is continuous.
  const double edge = 1e-3 * l.length;
  const Vec3 a = mooringFairleadForce<double>(l, Vec3(edge * (1 - 1e-9), 0, h));
  const Vec3 b = mooringFairleadForce<double>(l, Vec3(edge * (1 + 1e-9), 0, h));
  EXPECT_LT((a - b).norm(), 1e-6 * a.norm());
}

TEST(Catenary, SlackVerticalLineIsAComputeError) {
  MooringLine l = tlpTendon();
  try {
    mooringFairleadForce<double>(l, Vec3(0, 0, 100.0));  // 151.73 m of line over 100 m
    FAIL() << "no error";
  } catch (const ComputeError& e) {
    EXPECT_THAT(e.what(), ::testing::StartsWith("tlp tendon: the line straight below its fairlead is slack"));
  }
}

}  // namespace
}  // namespace whirl
