// HydroDyn's strip-theory added mass on a beam FE model (src/turbine/hydrodyn_strip.hpp) against
// closed forms: a vertical pile, partly in the water, on a two-element model; a member ending in the
// water (the joint's axial added mass); a horizontal brace; members that do not follow the elements.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>

#include "src/turbine/hydrodyn_strip.hpp"
#include "tests/unit/test_util.hpp"

namespace whirl {
namespace {

using test::errorOf;
using ::testing::HasSubstr;
constexpr double kPi = std::numbers::pi, kRho = 1025.0;

// HydroDyn geometry of one member from a to b, diameter D, Ca and JAxCa given, simple coefficients.
io::HydroDynInput oneMember(const Vec3& a, const Vec3& b, double D, double Ca, double JAxCa) {
  io::HydroDynInput hd;
  io::HydroDynMembers& g = hd.geometry;
  g.joints = {{1, a, 10, 1}, {2, b, 11, 1}};
  g.props = {{1, D, 0.05, 12}};
  g.members = {{1, 1, 2, 1, 1, false, 13, 1}};
  g.axial = {{1, JAxCa, 14}};
  g.SimplCa = Ca;
  g.SimplAxCa = 1.0;
  return hd;
}

// Nodes along a line from a to b, `n` equal elements.
fem::BeamModel line(const Vec3& a, const Vec3& b, int n) {
  fem::BeamModel m;
  for (int k = 0; k <= n; ++k) m.nodes.push_back(a + (b - a) * (static_cast<double>(k) / n));
  for (int k = 0; k < n; ++k) {
    fem::Element e;
    e.n1 = k;
    e.n2 = k + 1;
    m.elements.push_back(e);
  }
  return m;
}

TEST(StripTheory, VerticalPileInTheWaterColumn) {
  // From just below the seabed (−20.0001 m, as the OC3 monopile deck puts it: a joint at or above the
  // seabed would have HydroDyn's end effect) to 10 m above the water, elements of 7.5 m: the wet part
  // ends inside the third element. Transverse only, ρ Ca π R² per metre over 20 m; nothing along the
  // axis (no member end in the water).
  const io::HydroDynInput hd = oneMember({0, 0, -20.0001}, {0, 0, 10}, 6.0, 1.0, 1.0);
  const fem::BeamModel m = line({0, 0, -20.0001}, {0, 0, 10}, 4);
  const MatX A = elastodyn::stripTheoryAddedMass(hd, m, kRho, 20.0);
  const double per_m = kRho * kPi * 9.0;
  double total_x = 0, total_z = 0, moment = 0;
  for (int n = 0; n < m.nnodes(); ++n) {
    total_x += A(6 * n, 6 * n);
    total_z += A(6 * n + 2, 6 * n + 2);
    moment += A(6 * n, 6 * n) * m.nodes[n](2);
    EXPECT_EQ(A(6 * n, 6 * n), A(6 * n + 1, 6 * n + 1));
  }
  EXPECT_NEAR(total_x, per_m * 20, 1e-9 * per_m * 20);
  EXPECT_NEAR(total_z, 0.0, 1e-9 * per_m);
  // Lumped with linear weights: the first moment Σ m_n z_n is the exact ∫ z dm = per_m (0² − 20²)/2.
  EXPECT_NEAR(moment, -per_m * 200, 1e-9 * per_m * 200);
  // The top node (z = 10, dry) gets nothing; the node at z = 2.5 part of the third element's wet share.
  EXPECT_EQ(A(6 * 4, 6 * 4), 0.0);
}

TEST(StripTheory, MemberEndingInTheWaterHasItsAxialAddedMass) {
  // A pile hanging from above the water down to −15 m (20 m deep water): the free end adds
  // JAxCa ρ (2π/3) R³ along the axis at its node.
  const double R = 2.0, JAxCa = 0.8;
  const io::HydroDynInput hd = oneMember({0, 0, -15}, {0, 0, 5}, 2 * R, 1.0, JAxCa);
  const fem::BeamModel m = line({0, 0, -15}, {0, 0, 5}, 2);
  const MatX A = elastodyn::stripTheoryAddedMass(hd, m, kRho, 20.0);
  EXPECT_NEAR(A(2, 2), JAxCa * kRho * 2 * kPi / 3 * R * R * R, 1e-9 * A(2, 2));
  EXPECT_EQ(A(0, 2), 0.0);
}

TEST(StripTheory, HorizontalBraceBelowTheWater) {
  // Along x at −10 m: added mass in y and z only, ρ Ca π R² × 8 m.
  const io::HydroDynInput hd = oneMember({0, 0, -10}, {8, 0, -10}, 1.0, 1.5, 0.0);
  const fem::BeamModel m = line({0, 0, -10}, {8, 0, -10}, 3);
  const MatX A = elastodyn::stripTheoryAddedMass(hd, m, kRho, 20.0);
  const double total = 1.5 * kRho * kPi * 0.25 * 8;
  double y = 0, x = 0;
  for (int n = 0; n < m.nnodes(); ++n) {
    y += A(6 * n + 1, 6 * n + 1);
    x += A(6 * n, 6 * n);
  }
  EXPECT_NEAR(y, total, 1e-9 * total);
  EXPECT_NEAR(x, 0.0, 1e-9 * total);
}

// Marine growth (0.1 m of 1100 kg/m³ from −40 to −2 m) and a flooded member (to the still-water
// level, 1025 kg/m³): their mass in every direction, and the added water on the grown radius with
// CaMG there. A vertical pile from −50.0001 m (50 m of water) to 10 m, D 2 m, t 0.05 m.
TEST(StripTheory, MarineGrowthAndFillOnAPile) {
  io::HydroDynInput hd = oneMember({0, 0, -50.0001}, {0, 0, 10}, 2.0, 1.0, 0.0);
  hd.geometry.SimplCaMG = 0.8;
  hd.geometry.growth = {{-40.0, 0.1, 1100.0, 20}, {-2.0, 0.1, 1100.0, 21}};
  hd.geometry.fills = {{{1}, 0.0, 1025.0, 22}};
  const fem::BeamModel m = line({0, 0, -50.0001}, {0, 0, 10}, 6);
  const MatX A = elastodyn::stripTheoryAddedMass(hd, m, kRho, 50.0);
  const double R = 1.0, t = 0.05, grown = (R + 0.1) * (R + 0.1) - R * R;
  const double growth = 1100 * kPi * grown * 38, fill = 1025 * kPi * (R - t) * (R - t) * 50;
  const double water = kRho * kPi * (0.8 * (R + 0.1) * (R + 0.1) * 38 + 1.0 * R * R * 12);
  double x = 0, z = 0;
  for (int n = 0; n < m.nnodes(); ++n) {
    x += A(6 * n, 6 * n);
    z += A(6 * n + 2, 6 * n + 2);
  }
  EXPECT_NEAR(z, growth + fill, 1e-9 * (growth + fill));  // along the axis: no added water
  EXPECT_NEAR(x, growth + fill + water, 1e-9 * x);
}

TEST(StripTheory, MemberOffTheElementsIsAnInputError) {
  io::HydroDynInput hd = oneMember({0, 0, -20}, {0, 0, 10}, 6.0, 1.0, 1.0);
  hd.source = io::OpenFastFile::parse("x\n", "hd.dat");
  const fem::BeamModel m = line({1, 0, -20}, {1, 0, 10}, 3);  // 1 m beside the HydroDyn member
  EXPECT_THAT(errorOf([&] { elastodyn::stripTheoryAddedMass(hd, m, kRho, 20.0); }),
              HasSubstr("hd.dat:13: MemberID: member 1: 20 m of its length in the water lie on no SubDyn "
                        "member"));
  hd.geometry.members[0].MCoefMod = 2;
  EXPECT_THAT(errorOf([&] { elastodyn::stripTheoryAddedMass(hd, m, kRho, 20.0); }),
              HasSubstr("hd.dat:13: MCoefMod: 2 not supported by whirl (depth-based coefficients"));
}

}  // namespace
}  // namespace whirl
