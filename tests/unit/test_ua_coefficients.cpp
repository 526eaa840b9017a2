// Unsteady-airfoil constants and separation columns of AeroDyn airfoil tables (src/aero/ua_coefficients,
// src/io/airfoil_ua): the documented defaults, the values computed from the polar, f_st checked against
// OpenFAST's own linearization (r-test Fake5MW_AeroLin_B1_UA4_DBEMT3, tests/data/openfast-lin/ua4-dbemt3),
// and the bad-input messages.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "src/aero/ua_coefficients.hpp"
#include "src/aero/ua_span.hpp"
#include "src/io/openfast/aerodyn/airfoil_input.hpp"
#include "src/io/openfast/aerodyn/airfoil_ua.hpp"
#include "tests/unit/aero_test_util.hpp"

namespace {

using testing::HasSubstr;
using whirl::aero::separationAt;
using whirl::aero::UaTable;
using whirl::io::airfoilUa;
using whirl::io::readAirfoil;
using whirl::test::airfoilDir;
using whirl::test::inputErrorMessage;
using whirl::test::replaceOnce;
using whirl::test::ScratchDir;

constexpr double kDeg = std::numbers::pi / 180.0;

std::filesystem::path uaDeckDir() {
  return std::filesystem::path(WHIRL_SOURCE_DIR) / "tests/data/openfast-lin/ua4-dbemt3";
}

UaTable naca64Table1() { return airfoilUa(readAirfoil(uaDeckDir() / "case/NACA64_A17_2Prop.dat"), 0, 4); }

TEST(UaCoefficients, GivenConstantsInSiAndDocumentedDefaults) {
  // NACA64_A17_2Prop.dat table 1 gives alpha0 -4.432 deg, C_lalpha 7.67763, Cd0 0.0065, Cm0 -0.088 and
  // leaves T_f0, T_p, A1, A2, b1, b2, UACutout out: AeroDyn's defaults (AirfoilInfo.f90, ReadAFfile).
  const UaTable t = naca64Table1();
  ASSERT_TRUE(t.included);
  EXPECT_FALSE(t.cylinder);
  EXPECT_DOUBLE_EQ(t.c.alpha0, -4.432 * kDeg);
  EXPECT_DOUBLE_EQ(t.c.c_lalpha, 7.67763);
  EXPECT_DOUBLE_EQ(t.c.c_nalpha, 6.0031);
  EXPECT_DOUBLE_EQ(t.c.Cd0, 0.0065);
  EXPECT_DOUBLE_EQ(t.c.Cm0, -0.088);
  EXPECT_DOUBLE_EQ(*t.c.alpha1, 9 * kDeg);
  EXPECT_DOUBLE_EQ(*t.c.Cn2, -0.7945);
  EXPECT_DOUBLE_EQ(t.c.T_f0, 3.0);
  EXPECT_DOUBLE_EQ(t.c.T_p, 1.7);
  EXPECT_DOUBLE_EQ(t.c.A1, 0.3);
  EXPECT_DOUBLE_EQ(t.c.A2, 0.7);
  EXPECT_DOUBLE_EQ(t.c.b1, 0.14);
  EXPECT_DOUBLE_EQ(t.c.b2, 0.53);
  EXPECT_DOUBLE_EQ(t.c.ua_cutout, 45 * kDeg);
  EXPECT_DOUBLE_EQ(t.c.ua_cutout_blend, 40 * kDeg);
}

TEST(UaCoefficients, SeparationFunctionMatchesOpenFastLinearizationPoint) {
  // OpenFAST's UA_Mod 4 state equation dx4/dt = (f_st(alphaF) − x4) / (T_f0 Tu), alphaF = x3 / C_lalpha +
  // alpha0 (UnsteadyAero.f90, UA_CalcContStateDeriv, Get_alphaF). From the operating point x and its xdot
  // in states_inputs.txt (nodes 2–4, states 19–30; 13 digits) Tu and alpha_34 follow from the x1, x2
  // equations, then f_st(alphaF) = x4 + T_f0 Tu dx4/dt (derived to ~1e-11). whirl's f_st agrees to
  // 1.2e-7, 1.2e-7 and 8.5e-7: single-precision table arithmetic in AeroDyn (ReKi) is the likely cause
  // (relative 3e-7, amplified at node 4 where f_st = (Cl − Cl_fs)/(Cl_fa − Cl_fs) cancels). Tolerance
  // 2e-6; a wrong separation formula (e.g. without the square) is off by > 1e-2.
  const UaTable t = naca64Table1();
  struct Point {
    double x3, alphaF_expected_deg, f_st;
  };
  const Point points[] = {
      {2.279600107027, 12.579950967970305, 0.35050737116021174},    // node 2
      {2.125962675145, 11.433402303595065, 0.4054511044123443},     // node 3
      {0.5788725264974, -0.11205326586773136, 0.5204380036250699},  // node 4
  };
  for (const Point& p : points) {
    const double alphaF = p.x3 / t.c.c_lalpha + t.c.alpha0;
    EXPECT_NEAR(alphaF / kDeg, p.alphaF_expected_deg, 1e-9);
    EXPECT_NEAR(separationAt(t, alphaF).f_st, p.f_st, 2e-6) << "alphaF " << alphaF / kDeg << " deg";
  }
}

TEST(UaCoefficients, ColumnsReproduceTheStaticLiftWhereSeparated) {
  // Cl = f_st Cl_fa + (1 − f_st) Cl_fs on every knot where 0 < f_st < 1 (Hansen, Gaunaa & Madsen 2004,
  // eq. 60; AeroDyn makes it so, "in harmony"); f_st in [0, 1], 0 in deep stall with Cl_fs = Cl. Where
  // the static Cl and the line C_lalpha (α − alpha0) differ in size or sign near alpha0, AeroDyn clips
  // f_st to 1 or 0 and the identity does not hold (rows -7 to -4 deg here).
  const auto af = readAirfoil(uaDeckDir() / "case/NACA64_A17_2Prop.dat");
  const UaTable t = airfoilUa(af, 0, 4);
  const auto& tab = af.tables[0];
  int separated = 0;
  for (std::size_t k = 0; k < tab.alpha_deg.size(); ++k) {
    const auto s = separationAt(t, tab.alpha_deg[k] * std::numbers::pi / 180.0);  // the knot, as stored
    EXPECT_GE(s.f_st, 0.0);
    EXPECT_LE(s.f_st, 1.0);
    if (s.f_st == 0.0 && std::abs(tab.alpha_deg[k]) > 30) {
      EXPECT_NEAR(s.cl_fs, tab.cl[k], 1e-12);
    }
    if (s.f_st < 1e-9 || s.f_st > 1 - 1e-9) continue;  // clipped (to rounding of the knot evaluation)
    ++separated;
    EXPECT_NEAR(s.f_st * s.cl_fa + (1 - s.f_st) * s.cl_fs, tab.cl[k], 1e-12) << tab.alpha_deg[k] << " f " << s.f_st;
  }
  EXPECT_GT(separated, 10);
  EXPECT_DOUBLE_EQ(separationAt(t, 60 * kDeg).f_st, 0.0);
  EXPECT_DOUBLE_EQ(separationAt(t, -60 * kDeg).f_st, 0.0);
  EXPECT_DOUBLE_EQ(separationAt(t, -6 * kDeg).f_st, 1.0);
}

TEST(UaCoefficients, DefaultsComputedFromThePolar) {
  // DU21_A17 with its UA block dropped (InclUAdata false: AeroDyn computes everything). Checked against
  // the table itself: Cd0 = the smallest Cd within ±20 deg; the lift slope near the table's secant
  // between -4 and 4 deg ((0.996 − 0.016)/8 deg = 7.02/rad; the least-squares line spans the whole
  // linear region: within 5 %); alpha0 near the table's zero crossing (-4.125 deg by linear
  // interpolation between -4.5 and -4 deg); Cm0 = Cm(alpha0) by linear interpolation (AeroDyn's InterpStp).
  const auto full = readAirfoil(airfoilDir() / "DU21_A17.dat");
  auto af = full;
  af.tables[0].ua = {};
  const UaTable t = airfoilUa(af, 0, 4);
  const auto& tab = af.tables[0];
  double cd_min = 1e9;
  for (std::size_t k = 0; k < tab.alpha_deg.size(); ++k)
    if (std::abs(tab.alpha_deg[k]) <= 20) cd_min = std::min(cd_min, tab.cd[k]);
  EXPECT_DOUBLE_EQ(t.c.Cd0, cd_min);
  const double secant = (0.996 - 0.016) / (8 * kDeg);
  EXPECT_NEAR(t.c.c_lalpha, secant, 0.05 * secant);
  EXPECT_NEAR(t.c.c_nalpha, secant, 0.05 * secant);
  EXPECT_NEAR(t.c.alpha0 / kDeg, -4.125, 0.1);
  EXPECT_LT(t.c.alpha_lower, t.c.alpha0);
  EXPECT_GT(t.c.alpha_upper, 0.0);
  EXPECT_LT(t.c.alpha_upper, 15 * kDeg);
  std::size_t k = 0;
  while (tab.alpha_deg[k + 1] < t.c.alpha0 / kDeg) ++k;
  const double w = (t.c.alpha0 / kDeg - tab.alpha_deg[k]) / (tab.alpha_deg[k + 1] - tab.alpha_deg[k]);
  EXPECT_NEAR(t.c.Cm0, tab.cm[k] + w * (tab.cm[k + 1] - tab.cm[k]), 1e-12);
}

TEST(UaCoefficients, CylinderAndConstantTables) {
  // Cylinder1.dat: Cl = 0, Cd = 0.5 everywhere: a constant table, no UA (AeroDyn's ConstData).
  const UaTable c = airfoilUa(readAirfoil(uaDeckDir() / "5MW_Baseline/Airfoils/Cylinder1.dat"), 0, 4);
  EXPECT_FALSE(c.included);
}

TEST(UaCoefficients, TriweightSmoothingKeepsALineAndAverages) {
  const std::vector<double> x{0, 1, 2, 3, 4};
  const std::vector<double> line{1, 3, 5, 7, 9};
  const auto s = whirl::aero::triweightSmoothing(x, line, 1.5);
  EXPECT_NEAR(s[2], 5.0, 1e-14);  // symmetric window: the line's value
  EXPECT_GT(s[0], 1.0);           // one-sided at the ends: pulled inwards
  const auto wide = whirl::aero::triweightSmoothing(x, {0, 0, 10, 0, 0}, 1e-9);
  EXPECT_DOUBLE_EQ(wide[2], 10.0);  // radius below the spacing: unchanged
}

TEST(UaCoefficients, BadConstantsNameFileLineAndKey) {
  ScratchDir s;
  const std::string text = whirl::test::readText(uaDeckDir() / "case/NACA64_A17_2Prop.dat");
  auto replaced = [&](const std::string& from, const std::string& to) { return replaceOnce(text, from, to); };
  const auto bad_alpha0 = s.write("a.dat", replaced("     -4.432   alpha0", "     200   alpha0"));
  EXPECT_THAT(inputErrorMessage([&] { airfoilUa(readAirfoil(bad_alpha0), 0, 4); }),
              HasSubstr(bad_alpha0.string() + ":18: alpha0: must be within -180 to 180 deg (is 200)"));
  const auto bad_tf0 = s.write("b.dat", replaced("     0.0065   Cd0", "     0.0065   Cd0\n0   T_f0"));
  // A time constant of zero is an error where UA runs on the table, not when the file is read (AeroDyn's
  // UA_ValidateAFI checks only the airfoils of elements with UA: certtest Test10's cylinder has zeros).
  EXPECT_NO_THROW(readAirfoil(bad_tf0));
  EXPECT_THAT(inputErrorMessage([&] { airfoilUa(readAirfoil(bad_tf0), 0, 4); }),
              HasSubstr(":28: T_f0: must be > 0 (is 0)"));
  EXPECT_THAT(inputErrorMessage([&] { airfoilUa(readAirfoil(uaDeckDir() / "case/NACA64_A17_2Prop.dat"), 2, 4); }),
              HasSubstr("NumTabs: table 3 asked for, the file has 2"));
  EXPECT_THAT(inputErrorMessage([&] { airfoilUa(readAirfoil(uaDeckDir() / "case/NACA64_A17_2Prop.dat"), 0, 5); }),
              HasSubstr("NACA64_A17_2Prop.dat:14: InclUAdata: UA_Mod 5"));
}

}  // namespace

namespace {

TEST(UaSpan, ElementsWithStatesAsAeroDynDecides) {
  // The r-test deck (AD_blade_4stations.dat: node 1 Cylinder1.dat, nodes 2–4 NACA64_A17_2Prop.dat; no
  // UAStartRad/UAEndRad): OpenFAST's .lin lists UA states at nodes 2–4 only (states 19–30).
  const UaTable cyl = airfoilUa(readAirfoil(uaDeckDir() / "5MW_Baseline/Airfoils/Cylinder1.dat"), 0, 4);
  const UaTable naca = naca64Table1();
  EXPECT_FALSE(whirl::aero::uaPossible(cyl));
  EXPECT_TRUE(whirl::aero::uaPossible(naca));
  // Span rule: frac = r/rMax; off up to the last element below UAStartRad and from the first above UAEndRad.
  const std::vector<double> r{1.5, 24.05, 44.55, 63.0};
  using whirl::aero::uaSpanMask;
  EXPECT_EQ(uaSpanMask(r, 63.0, 0.0, 1.0), (std::vector<bool>{true, true, true, true}));
  EXPECT_EQ(uaSpanMask(r, 63.0, 0.3, 1.0), (std::vector<bool>{false, true, true, true}));
  EXPECT_EQ(uaSpanMask(r, 63.0, 0.4, 0.9), (std::vector<bool>{false, false, true, false}));
  // AeroDyn's rule is by index, not by each element's own fraction: an element above UAStartRad that lies
  // inside of one below it (a non-monotonic r) is off too.
  EXPECT_EQ(uaSpanMask({1.5, 30.0, 20.0, 63.0}, 63.0, 0.4, 1.0), (std::vector<bool>{false, false, false, true}));
}

}  // namespace

namespace {

TEST(UaCoefficients, SmallAndOddTablesDoNotBreak) {
  // Three rows (-180, 0, 180 deg) and a coarse table: every constant finite, f_st within [0, 1].
  using whirl::aero::uaTable;
  const double pi = std::numbers::pi;
  for (const std::vector<double>& a :
       {std::vector<double>{-pi, 0.0, pi}, std::vector<double>{-pi, -0.5, 0.1, 0.5, pi}}) {
    std::vector<double> cl, cd, cm;
    for (double x : a) {
      cl.push_back(std::sin(2 * x) + 0.3 * std::sin(x));
      cd.push_back(0.02 + std::sin(x) * std::sin(x));
      cm.push_back(0.0);
    }
    const UaTable t = uaTable({}, a, cl, cd, cm, whirl::aero::PolarInterp::Linear, 4, "t");
    EXPECT_TRUE(std::isfinite(t.c.c_lalpha) && std::isfinite(t.c.alpha0) && std::isfinite(t.c.Cm0));
    for (double f : t.columns.cl) {
      EXPECT_GE(f, 0.0);
      EXPECT_LE(f, 1.0);
    }
  }
}

}  // namespace
