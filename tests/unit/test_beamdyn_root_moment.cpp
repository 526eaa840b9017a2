// The root bending moments of an FE blade (fem::blade6MomentGains, the elements' stress resultants) on
// certification Test26's BeamDyn blade (NREL 5MW): for the first flap and edge modes, against the moment
// of the mode's inertial loads ω² M φ about the root — the clamped blade's equilibrium, a second path
// through the mass matrix and the eigenvalue instead of the stiffness. (The deck's RootMFlp/RootMEdg
// channels sum the loads instead, as ElastoDyn: tests/unit/test_subtree_load_moment.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "src/fem/blade6_moments.hpp"
#include "src/io/openfast/beamdyn/beamdyn_input.hpp"
#include "src/turbine/beamdyn_blade.hpp"

namespace whirl {
namespace {

const std::string kDeck = std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw_beamdyn/";

int column(const fem::Blade6Body& b, const std::string& name) {
  for (std::size_t j = 0; j < b.shapes.size(); ++j)
    if (b.shapes[j]->name == name) return static_cast<int>(j);
  return -1;
}

// [toward +y, toward +z] moment at the root of the loads ω² M φ_j on the free nodes: a load along +y
// at x > 0 turns about +z, one along +z about −y (beamMomentGains' convention).
Eigen::Vector2d inertialRootMoment(const fem::Blade6Body& b, int j) {
  const fem::Beam6Matrices mats = fem::assemble6(b.model);
  const double omega = 2 * std::numbers::pi * b.freq_hz[static_cast<std::size_t>(j)];
  const VecX f = omega * omega * (mats.M * b.modes.col(j));
  Vec3 moment = Vec3::Zero();
  for (std::size_t i = 1; i < b.model.nodes.size(); ++i) {
    const Eigen::Index k = 6 * static_cast<Eigen::Index>(i);
    moment += (b.model.nodes[i] - b.model.nodes[0]).cross(Vec3(f.segment<3>(k))) + Vec3(f.segment<3>(k + 3));
  }
  return {moment.z(), -moment.y()};
}

TEST(BeamDynRootMoment, Test26BladeResultantsEqualTheInertialLoadsMoment) {
  const io::BeamDynInput bd = io::readBeamDyn(kDeck + "5MW_Baseline/NRELOffshrBsline5MW_BeamDyn.dat");
  const fem::Blade6Body b = fem::blade6Body(blade6Input(bd), {60, 8});
  const MatX G = fem::blade6MomentGains(b, 0.0);
  for (const char* mode : {"flap 1", "edge 1"}) {
    const int j = column(b, mode);
    ASSERT_GE(j, 0) << mode;
    const Eigen::Vector2d expected = inertialRootMoment(b, j);
    // Both exact for the FE model: K φ = ω² M φ at every free node, to the eigensolver's precision.
    EXPECT_NEAR(G(0, j), expected(0), 1e-6 * expected.norm()) << mode;
    EXPECT_NEAR(G(1, j), expected(1), 1e-6 * expected.norm()) << mode;
  }
  // Flap 1 bends the blade towards +y (the moment of a tip deflection of +1 m is positive), edge 1 towards +z.
  EXPECT_GT(G(0, column(b, "flap 1")), 1e6);
  EXPECT_GT(G(1, column(b, "edge 1")), 1e6);
}

}  // namespace
}  // namespace whirl
