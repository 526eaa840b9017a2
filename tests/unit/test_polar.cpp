// Airfoil polar interpolation against AeroDyn's (AirfoilInfo.f90 + NWTC_Num.f90) algorithm.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "src/aero/polar.hpp"
#include "src/base/error.hpp"
#include "src/base/scalar.hpp"
#include "tests/unit/aero_data_util.hpp"

using namespace whirl;
using namespace whirl::aero;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

const Polar& du21(PolarInterp interp) {
  static const std::vector<Polar> lin = test::readNrel5mwPolars(PolarInterp::Linear);
  static const std::vector<Polar> cub = test::readNrel5mwPolars(PolarInterp::CubicSpline);
  return (interp == PolarInterp::Linear ? lin : cub)[6];  // BlAFID 7 = DU21_A17
}

struct Ref {
  double deg, cl, cd, cm;
};

// Reference values: NWTC_Num.f90 CubicLinSplineInitM / CubicSplineInitM / CubicSplineInterpM / LocateBin and
// MPi2Pi (OpenFAST dev, 2026-03) transcribed line by line, 1-based, into a stand-alone Python script (no code
// shared with src/aero/polar.cpp) and run on the DU21_A17 table of tests/data/aero/nrel5mw_polars.txt.
const Ref kLinear[] = {
    // 5.3 deg by hand: rows 5.00 (1.095, 0.0090, -0.1378) and 5.50 (1.145, 0.0103, -0.1369), weight 0.6.
    {5.3, 1.125, 0.00978, -0.13726},
    {-3.7, 0.054399999999996902, 0.0061800000000000101, -0.12243999999999991},
    {170.2, -0.77224000000000093, 0.094360000000000138, -0.38864800000000044},
    {-178.0, 0.1575999999999976, 0.024379999999999909, 0.079119999999998802},
    {179.5, -0.039400000000001434, 0.019990000000000053, -0.019780000000000686},
    {365.3, 1.1250000000000027, 0.0097800000000000699, -0.13725999999999994},  // wraps to 5.3 deg
    {-12.25, -0.96234939759036142, 0.029953012048192781, -0.035179518072289161},
};
const Ref kCubic[] = {
    {5.3, 1.1251599476238627, 0.0097937457327508352, -0.13729662201396325},
    {-3.7, 0.05425725145144384, 0.0061953585710337565, -0.12241888450321714},
    {170.2, -0.7784115497055869, 0.093675815900524567, -0.39228579786086615},
    {-178.0, 0.15120044847030267, 0.017878015749200692, 0.075267701032155535},    // first segment (row-1 condition)
    {179.5, -0.037060143149307855, 0.018862583548744198, -0.018372244469111638},  // last segment (M_N = 0)
    {365.3, 1.1251599476238656, 0.0097937457327509064, -0.13729662201396323},
    {-12.25, -0.96731194664302489, 0.027262566482255626, -0.035993807520838819},
};

}  // namespace

TEST(Polar, LinearMatchesAeroDynInterpOrd1) {
  const Polar& p = du21(PolarInterp::Linear);
  EXPECT_EQ(p.name, "DU21_A17");
  for (const Ref& r : kLinear) {
    const auto c = evaluate(p, r.deg * kDeg);
    EXPECT_NEAR(c.cl, r.cl, 1e-12) << r.deg;
    EXPECT_NEAR(c.cd, r.cd, 1e-12) << r.deg;
    EXPECT_NEAR(c.cm, r.cm, 1e-12) << r.deg;
  }
}

TEST(Polar, CubicMatchesAeroDynInterpOrd3) {
  const Polar& p = du21(PolarInterp::CubicSpline);
  for (const Ref& r : kCubic) {
    const auto c = evaluate(p, r.deg * kDeg);
    EXPECT_NEAR(c.cl, r.cl, 1e-12) << r.deg;
    EXPECT_NEAR(c.cd, r.cd, 1e-12) << r.deg;
    EXPECT_NEAR(c.cm, r.cm, 1e-12) << r.deg;
  }
}

// The NWTC spline's defining equations: interpolation, C1 and C2 continuity at the interior knots, M_N = 0 at
// the last knot, and 2(h1+h2) M1 + h1 M2 = 6(s2 - s1) at the first (neither natural nor not-a-knot).
TEST(Polar, CubicIsTheNwtcSpline) {
  const Polar& p = du21(PolarInterp::CubicSpline);
  const auto& x = p.alpha;
  const auto& y = p.cl;
  const auto& c = p.ccl;
  const std::size_t n = x.size();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double h = x[i + 1] - x[i];
    EXPECT_NEAR(c[i][0], y[i], 1e-14);
    EXPECT_NEAR(c[i][0] + h * (c[i][1] + h * (c[i][2] + h * c[i][3])), y[i + 1], 1e-9);
    if (i + 2 < n) {
      EXPECT_NEAR(c[i][1] + h * (2 * c[i][2] + 3 * h * c[i][3]), c[i + 1][1], 1e-8) << i;  // y'
      EXPECT_NEAR(2 * c[i][2] + 6 * h * c[i][3], 2 * c[i + 1][2], 1e-6) << i;              // y''
    }
  }
  const double hl = x[n - 1] - x[n - 2];
  EXPECT_NEAR(2 * c[n - 2][2] + 6 * hl * c[n - 2][3], 0.0, 1e-6);  // M_N = 0
  const double h1 = x[1] - x[0], h2 = x[2] - x[1];
  const double s1 = (y[1] - y[0]) / h1, s2 = (y[2] - y[1]) / h2;
  const double M1 = 2 * c[0][2], M2 = 2 * c[1][2];
  EXPECT_NEAR(2 * (h1 + h2) * M1 + h1 * M2, 6 * (s2 - s1), 1e-8);
  // ... which is not the natural condition M1 = 0 on this table.
  EXPECT_GT(std::abs(M1), 1e-3);
}

TEST(Polar, WrapsLikeMPi2PiAndClampsAtTheEnds) {
  const Polar& p = du21(PolarInterp::Linear);
  EXPECT_DOUBLE_EQ(wrapMPi2Pi(std::numbers::pi), std::numbers::pi);   // pi stays pi: (-pi, pi]
  EXPECT_DOUBLE_EQ(wrapMPi2Pi(-std::numbers::pi), std::numbers::pi);  // modulo(-pi, 2pi) = pi
  EXPECT_NEAR(wrapMPi2Pi(3 * std::numbers::pi / 2), -std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(evaluate(p, std::numbers::pi).cd, 0.0185, 1e-15);  // last row
  EXPECT_NEAR(evaluate(p, -std::numbers::pi).cd, 0.0185, 1e-15);
  const auto a = evaluate(p, 0.3), b = evaluate(p, 0.3 + 4 * std::numbers::pi),
             d = evaluate(p, 0.3 - 2 * std::numbers::pi);
  EXPECT_NEAR(a.cl, b.cl, 1e-12);
  EXPECT_NEAR(a.cl, d.cl, 1e-12);
}

TEST(Polar, AutoDiffDerivativeIsTheSegmentSlope) {
  const Polar& lin = du21(PolarInterp::Linear);
  ADChunk al(5.3 * kDeg);
  al.derivatives()[2] = 1.0;
  const auto c = evaluate(lin, al);
  EXPECT_NEAR(c.cl.value(), 1.125, 1e-12);
  EXPECT_NEAR(c.cl.derivatives()[2], (1.145 - 1.095) / (0.5 * kDeg), 1e-9);
  EXPECT_NEAR(c.cl.derivatives()[0], 0.0, 0.0);
  const Polar& cub = du21(PolarInterp::CubicSpline);
  for (double d : {-178.0, -3.7, 5.3, 170.2, 725.3}) {
    ADChunk x(d * kDeg);
    x.derivatives()[0] = 1.0;
    const auto e = evaluate(cub, x);
    const double h = 1e-7;
    const double fd = (evaluate(cub, d * kDeg + h).cm - evaluate(cub, d * kDeg - h).cm) / (2 * h);
    EXPECT_NEAR(e.cm.derivatives()[0], fd, 1e-6) << d;
    EXPECT_NEAR(e.cm.value(), evaluate(cub, d * kDeg).cm, 1e-15);
  }
}

TEST(Polar, ConstantTableIsConstant) {
  const std::vector<Polar> all = test::readNrel5mwPolars();
  const Polar& cyl = all[0];  // Cylinder1: 3 rows, AeroDyn ConstData
  EXPECT_TRUE(cyl.constant);
  ADChunk x(0.4);
  x.derivatives()[0] = 1.0;
  const auto c = evaluate(cyl, x);
  EXPECT_DOUBLE_EQ(c.cd.value(), 0.5);
  EXPECT_DOUBLE_EQ(c.cd.derivatives()[0], 0.0);
}

TEST(Polar, BadTablesThrowInputErrorNamingTheSource) {
  const double pi = std::numbers::pi;
  auto expectError = [](auto&& f, const std::string& part) {
    try {
      f();
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.rfind("af.dat:12: ", 0), 0u) << m;
      EXPECT_NE(m.find(part), std::string::npos) << m;
    }
  };
  const std::string src = "af.dat:12";
  expectError(
      [&] {
        makePolar("x", {-pi, 0.0, 0.0, pi}, {0, 1, 1, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}, PolarInterp::Linear, src);
      },
      "strictly increasing");
  expectError(
      [&] {
        makePolar("x", {-pi, 0.0, pi}, {0, 1}, {0, 0, 0}, {0, 0, 0}, PolarInterp::Linear, src);
      },
      "different lengths");
  expectError(
      [&] {
        makePolar("x", {-pi, 0.0, pi}, {0, NAN, 0}, {0, 0, 0}, {0, 0, 0}, PolarInterp::Linear, src);
      },
      "non-finite");
  expectError(
      [&] {
        makePolar("x", {-pi + 0.01, 0.0, pi}, {0, 1, 0}, {0, 0, 0}, {0, 0, 0}, PolarInterp::Linear, src);
      },
      "cover -180..180");
  expectError([&] { makePolar("x", {}, {}, {}, {}, PolarInterp::Linear, src); }, "empty");
  EXPECT_NO_THROW(
      makePolar("x", {-pi + 5e-4, 0.0, pi - 5e-4}, {0, 1, 0}, {0, 0, 0}, {0, 0, 0}, PolarInterp::CubicSpline, src));
}

// Tables on the Reynolds number (AeroDyn AFI_ComputeAirfoilCoefs2D: linear in log Re between the
// bracketing tables, the end tables outside; AeroDyn v14 RENUM: linear in Re): three linear tables
// whose coefficients differ by a constant per table, so each interpolated value is known by hand.
namespace {

Polar shifted(double dcl, double dcd, double dcm) {
  const std::vector<double> a = {-std::numbers::pi, 0.0, std::numbers::pi};
  return makePolar("t", a, {dcl - 1, dcl, dcl + 1}, {dcd, dcd + 0.01, dcd}, {dcm, dcm, dcm}, PolarInterp::Linear, "t");
}

Polar threeTables(ReynoldsInterp interp) {
  return reynoldsPolar({shifted(0.0, 0.01, 0.0), shifted(0.2, 0.02, -0.1), shifted(0.5, 0.05, -0.3)}, {3e5, 5e5, 1.2e6},
                       interp, {"f:4", "f:4", "f:4"});
}

}  // namespace

TEST(Polar, ReynoldsTablesInterpolateInLogReAsAeroDyn) {
  const Polar p = threeTables(ReynoldsInterp::Log);
  ASSERT_EQ(p.re_tables.size(), 3u);
  const double alpha = 0.3;  // cl = dcl + alpha/π, cd = dcd + 0.01 (1 − alpha/π), cm = dcm
  const double base_cl = alpha / std::numbers::pi, base_cd = 0.01 * (1 - alpha / std::numbers::pi);
  auto at = [&](double re) { return evaluate(p, alpha, re); };
  // At a table's Reynolds number: that table.
  EXPECT_NEAR(at(5e5).cl, 0.2 + base_cl, 1e-14);
  EXPECT_NEAR(at(5e5).cd, 0.02 + base_cd, 1e-14);
  // Log midpoint of 3e5 and 5e5 (√(3e5·5e5)): the mean of the two tables.
  const Coefficients<double> mid = at(std::sqrt(3e5 * 5e5));
  EXPECT_NEAR(mid.cl, 0.1 + base_cl, 1e-14);
  EXPECT_NEAR(mid.cd, 0.015 + base_cd, 1e-14);
  EXPECT_NEAR(mid.cm, -0.05, 1e-14);
  // A quarter of the way from 5e5 to 1.2e6 in log Re.
  const double re = std::exp(std::log(5e5) + 0.25 * (std::log(1.2e6) - std::log(5e5)));
  EXPECT_NEAR(at(re).cl, 0.2 + 0.25 * 0.3 + base_cl, 1e-14);
  EXPECT_NEAR(at(re).cm, -0.1 - 0.25 * 0.2, 1e-14);
  // Outside the tables: the end tables.
  EXPECT_NEAR(at(1e3).cl, base_cl, 1e-14);
  EXPECT_NEAR(at(1e8).cl, 0.5 + base_cl, 1e-14);
  // Linear in Re (AeroDyn v14): the arithmetic midpoint gives the mean.
  const Polar q = threeTables(ReynoldsInterp::Linear);
  EXPECT_NEAR(evaluate(q, alpha, 4e5).cl, 0.1 + base_cl, 1e-14);
  EXPECT_NEAR(evaluate(q, alpha, std::sqrt(3e5 * 5e5)).cl, (std::sqrt(3e5 * 5e5) - 3e5) / 2e5 * 0.2 + base_cl, 1e-14);
  // One table only, or None: the first table at every Reynolds number.
  const Polar first = threeTables(ReynoldsInterp::None);
  EXPECT_TRUE(first.re_tables.empty());
  EXPECT_NEAR(evaluate(first, alpha, 1e6).cl, base_cl, 1e-14);
}

TEST(Polar, ReynoldsDerivativesEqualCentralDifferences) {
  const Polar p = threeTables(ReynoldsInterp::Log);
  for (double re : {4e5, 8e5}) {
    ADChunk a(0.3), r(re);
    a.derivatives().setZero();
    r.derivatives().setZero();
    a.derivatives()(0) = 1.0;
    r.derivatives()(1) = 1.0;
    const Coefficients<ADChunk> c = evaluate(p, a, r);
    const double ha = 1e-6, hr = 1e-3 * re;
    const double dcl_da = (evaluate(p, 0.3 + ha, re).cl - evaluate(p, 0.3 - ha, re).cl) / (2 * ha);
    const double dcl_dre = (evaluate(p, 0.3, re + hr).cl - evaluate(p, 0.3, re - hr).cl) / (2 * hr);
    const double dcd_dre = (evaluate(p, 0.3, re + hr).cd - evaluate(p, 0.3, re - hr).cd) / (2 * hr);
    EXPECT_NEAR(c.cl.derivatives()(0), dcl_da, 1e-8) << re;
    EXPECT_NEAR(c.cl.derivatives()(1), dcl_dre, 1e-6 * std::abs(dcl_dre)) << re;
    EXPECT_NEAR(c.cd.derivatives()(1), dcd_dre, 1e-6 * std::abs(dcd_dre)) << re;
  }
}

TEST(Polar, ReynoldsTablesMustIncrease) {
  auto error = [](std::vector<double> re) {
    try {
      reynoldsPolar({shifted(0, 0.01, 0), shifted(0.1, 0.01, 0)}, re, ReynoldsInterp::Log, {"a.dat:4", "a.dat:9"});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error({5e5, 3e5}),
            "a.dat:9: Re: the tables' Reynolds numbers must increase strictly (300000 follows "
            "500000), as AeroDyn requires for interpolating on them");
  EXPECT_EQ(
      error({0.0, 3e5}).rfind("a.dat:4: Re: the Reynolds number of a table interpolated on it must be positive", 0),
      0u);
}
