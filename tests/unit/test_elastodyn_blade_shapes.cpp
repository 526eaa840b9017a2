// ElastoDyn's twisted blade shapes (ElastoDyn `Coeff`) on the NREL 5MW blade with BldNodes = 17:
// generalized masses and stiffnesses against the values ElastoDyn prints for this blade, and the beam
// body whirl builds from the shapes against ElastoDyn's own formulas.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "src/io/openfast/openfast_turbine.hpp"
#include "src/turbine/elastodyn_blade_shapes.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace whirl {
namespace {

const io::ElastoDynInput& nrel5mw() {
  static const io::ElastoDynInput ed = io::readOpenFastTurbine(test::nrel5mwDir() / "Main_Onshore.fst").elastodyn;
  return ed;
}

ElastoDynBladeBeam blade(int nodes = 17) { return elastoDynBladeBeam(nrel5mw().blades[0], 61.5, nodes, 0.0); }

BeamBody body(const ElastoDynBladeBeam& b) {
  BeamOptions o;
  o.integration = {BeamIntegration::Midpoint, b.nodes};
  return buildBeamBody(b.props, b.shapes, o, "blade");
}

TEST(ElastoDynBladeShapes, GeneralizedMassAndStiffnessMatchElastoDyn) {
  // ElastoDyn's values for the NREL 5MW blade, BldNodes = 17, AdjBlMs = 1.04536, no tip mass:
  // Me = TipMass + Σ m ΔR φ² (untwisted polynomials), Ke = Σ EI ΔR φ''². ElastoDyn accumulates in
  // single precision (ReKi), so its printed values agree with double-precision sums to ~3e-7.
  const ElastoDynBladeBeam b = blade();
  const double Me[3] = {924.99, 1430.78, 561.46}, Ke[3] = {16698.18, 66822.07, 84957.47};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(b.generalized_mass(k), Me[k], 0.005 + 1e-6 * Me[k]) << b.shapes[k]->name;
    EXPECT_NEAR(b.generalized_stiffness(k, k), Ke[k], 0.005 + 1e-6 * Ke[k]) << b.shapes[k]->name;
  }
  EXPECT_EQ(b.generalized_stiffness(kFlap1, kEdge1), 0.0);  // ElastoDyn: edge uncoupled
  EXPECT_NE(b.generalized_stiffness(kFlap1, kFlap2), 0.0);  // flap 1–flap 2 coupled
}

TEST(ElastoDynBladeShapes, BeamBodyHasElastoDynsStiffnessAndMass) {
  const ElastoDynBladeBeam b = blade();
  const BeamBody bb = body(b);
  // Projecting the twisted curvatures back on the principal axes with the same twist gives ElastoDyn's
  // ∫ EI φ''² exactly (flap–edge coupling vanishes).
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(bb.elastic.K(i, j), b.generalized_stiffness(i, j), 1e-10 * b.generalized_stiffness(i, i) + 1e-9)
          << i << "," << j;
  // Mass: ElastoDyn's BldMass = Σ m ΔR. The elastic mass of the twisted shapes, Σ m ΔR (Φ² + Ψ²), is what
  // ElastoDyn's equations of motion use; it exceeds the printed untwisted Me by the in-plane part.
  EXPECT_NEAR(bb.inertia.mass, 17536.614, 1e-3);
  for (int k = 0; k < 3; ++k) {
    double mee = 0;
    for (int a = 0; a < 3; ++a) mee += bb.inertia.S[4 * a](1 + k, 1 + k);
    EXPECT_GT(mee, b.generalized_mass(k)) << b.shapes[k]->name;
    EXPECT_LT(mee, 1.02 * b.generalized_mass(k)) << b.shapes[k]->name;
  }
}

TEST(ElastoDynBladeShapes, CurvaturesAreThePolynomialRotatedByTheTwist) {
  const ElastoDynBladeBeam b = blade();
  const double L = 61.5;
  const io::ModeShapeCoeffs& f1 = nrel5mw().blades[0].BldFl1Sh;
  for (int j = 1; j <= 17; ++j) {
    const double r = (j - 0.5) * L / 17, x = r / L;
    double k2 = 0;
    for (int i = 0; i < 5; ++i) k2 += f1[i] * (i + 2) * (i + 1) * std::pow(x, i) / (L * L);
    const ShapeValue v = b.shapes[kFlap1]->eval(r);
    EXPECT_NEAR(std::hypot(v.uy2, v.uz2), std::abs(k2), 1e-12 * std::abs(k2) + 1e-15) << "node " << j;
  }
  // Root twist 13.308°: flap curvature along (cos θs, −sin θs) in (j1, j2).
  const ShapeValue root = b.shapes[kFlap1]->eval(0.0);
  EXPECT_NEAR(std::atan2(-root.uz2, root.uy2), 13.308 * M_PI / 180, 1e-12);
}

TEST(ElastoDynBladeShapes, WithoutTwistTheNodeRuleRecoversThePolynomial) {
  io::ElastoDynBlade f = nrel5mw().blades[0];
  for (std::size_t c = 0; c < f.distributed.names.size(); ++c)
    if (f.distributed.names[c] == "StrcTwst")
      std::fill(f.distributed.values[c].begin(), f.distributed.values[c].end(), 0.0);
  const ElastoDynBladeBeam b = elastoDynBladeBeam(f, 61.5, 200, 0.0);
  for (int k = 0; k < 3; ++k) {
    const ShapeValue v = b.shapes[k]->eval(61.5);
    EXPECT_EQ(k == kEdge1 ? v.uy : v.uz, 0.0) << b.shapes[k]->name;  // no coupling without twist
    // The polynomials are normalized to a unit tip deflection (coefficients sum to 1 within 1e-4);
    // ElastoDyn's node rule integrates them with an O(ΔR²) error.
    EXPECT_NEAR(k == kEdge1 ? v.uz : v.uy, 1.0, 2e-4) << b.shapes[k]->name;
  }
}

TEST(ElastoDynBladeShapes, TunersAndModalDampingAsElastoDyn) {
  io::ElastoDynBlade f = nrel5mw().blades[0];
  f.FlStTunr = {1.1, 0.9};
  const ElastoDynBladeBeam tuned = elastoDynBladeBeam(f, 61.5, 17, 0.0), plain = blade();
  EXPECT_NEAR(tuned.generalized_stiffness(kFlap1, kFlap1), 1.1 * plain.generalized_stiffness(kFlap1, kFlap1), 1e-9);
  EXPECT_NEAR(tuned.generalized_stiffness(kFlap1, kFlap2),
              std::sqrt(0.99) * plain.generalized_stiffness(kFlap1, kFlap2), 1e-9);
  EXPECT_NEAR(tuned.generalized_stiffness(kEdge1, kEdge1), plain.generalized_stiffness(kEdge1, kEdge1), 1e-9);
  // D(i, l) = 2 ζ_l K(i, l) √(M_l/K_ll): on the diagonal 2 ζ √(K M).
  const MatX K = plain.generalized_stiffness;
  const MatX D = elastoDynModalDamping(K, plain.generalized_mass, plain.damping_ratio);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(D(k, k), 2 * 0.00477465 * std::sqrt(K(k, k) * plain.generalized_mass(k)), 1e-9 * D(k, k));
  EXPECT_NEAR(D(kFlap2, kFlap1),
              2 * 0.00477465 * K(kFlap2, kFlap1) * std::sqrt(plain.generalized_mass(kFlap1) / K(kFlap1, kFlap1)),
              1e-12);
}

}  // namespace
}  // namespace whirl
