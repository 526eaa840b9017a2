// [Branlard2019, §5.1]: uniform tower with a top mass.
//  - u0 = 1 − cos: analytic Mq, Kq, frequency, and the geometric-stiffness ratios of the top mass
//    and of the self weight at several Mt/M (exact formulas of §5.1);
//  - the exact beam-with-tip-mass modes of eq. 32 as shapes: frequencies (β_j/L)²√(EI/m).
#include <numbers>

#include "modal/modes.hpp"
#include "src/io/case/case_file.hpp"
#include "src/shapes/shape.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double L = 100, EI = 2e12, mpl = 9e3, g = 9.81;

TEST(TowerTopMass, OneMinusCosMatchesReference) {
  const Model m = test::loadCase("tower_topmass");
  const LinearModel l = test::linearizeAtEquilibrium(m);
  const auto modes = computeModes(l.M, l.C, l.K, l.dof_names);
  test::expectMatchesReference("tower_topmass", {{"generalized_mass_kg", l.M(0, 0)},
                                                 {"generalized_stiffness_n_per_m", l.K(0, 0)},
                                                 {"freq_hz", modes.at(0).freq_hz}});
}

TEST(TowerTopMass, GeometricStiffnessRatiosAtSeveralTopMasses) {
  const double Kq = EI * std::pow(pi, 4) / (32 * std::pow(L, 3));
  const double Pcr = pi * pi * EI / (4 * L * L), M = mpl * L;
  for (double ratio : {0.0, 0.25, 1.0, 3.0}) {
    const std::string mt = "bodies.top mass.mass=" + std::to_string(ratio * M);
    const double K1 = test::linearizeAtEquilibrium(test::loadCase("tower_topmass", {mt})).K(0, 0);
    const double K0 = test::linearizeAtEquilibrium(test::loadCase("tower_topmass", {mt, "gravity=0"})).K(0, 0);
    // [Branlard2019, §5.1]: K_T/Kq = −Mt g/Pcr − (M g/Pcr)(1/2 − 2/π²), exact for u0 = 1 − cos.
    EXPECT_NEAR((K1 - K0) / Kq, -ratio * M * g / Pcr - (M * g / Pcr) * (0.5 - 2 / (pi * pi)), 1e-9) << ratio;
  }
}

TEST(TowerTopMass, ExactTipMassModesGiveBetaSquaredFrequencies) {
  const double ratio = 0.5;  // Mt/M of cases/tower_topmass/tower_topmass_eq32.yaml
  const Model m = readCase(std::string(WHIRL_SOURCE_DIR) + "/cases/tower_topmass/tower_topmass_eq32.yaml");
  const LinearModel l = test::linearizeAtEquilibrium(m);
  const auto modes = computeModes(l.M, l.C, l.K, l.dof_names);
  ASSERT_EQ(modes.size(), 4u);
  for (int j = 1; j <= 4; ++j) {
    const double b = clampedTopMassBeta(j, ratio);
    // β_j is a root of the characteristic equation of [Branlard2019, eq. 32] ...
    EXPECT_NEAR(1 + std::cosh(b) * std::cos(b) - b * ratio * (std::sin(b) * std::cosh(b) - std::cos(b) * std::sinh(b)),
                0.0, 1e-9 * std::cosh(b));
    // ... and ω_j = (β_j/L)² √(EI/m) is exact: the shapes are the modes of beam + tip mass.
    const double f = (b / L) * (b / L) * std::sqrt(EI / mpl) / (2 * pi);
    EXPECT_NEAR(modes[j - 1].freq_hz, f, 1e-7 * f) << "mode " << j;
  }
}

// The same tower with shapes computed by the beam FE from its properties and the top mass
// (cases/tower_topmass/tower_topmass_fem.yaml, `shapes: {from: fem}`): the Rayleigh–Ritz model with
// those 4 shapes against the exact eq. 32 frequencies. The FE modes themselves are exact to ~1e-9
// (tests/cli/test_cli_shapes.cpp); what remains is the `table` shape's linear interpolation between
// the nodes, an O(h²) error: measured 3e-7, 1e-4, 3e-4, 8e-4 (modes 1–4) with the case's 100
// elements, four times less with 200 — both checked, so the error is shown to be the discretization.
// Two model builds and linearizations with 100 and 200 table stations: ~2 s, hence a *Slow suite.
TEST(TowerTopMassSlow, FemShapesConvergeToEquation32Frequencies) {
  const double ratio = 0.5;  // Mt/M of the case
  const std::string path = std::string(WHIRL_SOURCE_DIR) + "/cases/tower_topmass/tower_topmass_fem.yaml";
  auto errors = [&](int elements) {
    const std::vector<CaseOverride> o = {{"bodies.tower.shapes.elements", std::to_string(elements)},
                                         {"bodies.tower.integration.n", std::to_string(2 * elements)}};
    const LinearModel l = test::linearizeAtEquilibrium(readCase(path, o));
    const auto modes = computeModes(l.M, l.C, l.K, l.dof_names);
    std::vector<double> e;
    for (int j = 1; j <= 4; ++j) {
      const double b = clampedTopMassBeta(j, ratio), f = (b / L) * (b / L) * std::sqrt(EI / mpl) / (2 * pi);
      e.push_back(modes.at(j - 1).freq_hz / f - 1);
    }
    return e;
  };
  const std::vector<double> e100 = errors(100), e200 = errors(200);
  for (int j = 0; j < 4; ++j) {
    EXPECT_LT(std::abs(e100[j]), 1e-3) << "mode " << j + 1;
    if (j > 0) {
      EXPECT_NEAR(e100[j] / e200[j], 4.0, 0.5) << "mode " << j + 1;  // O(h²)
    }
  }
}

}  // namespace
}  // namespace whirl
