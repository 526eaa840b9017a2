// Participation factors (modal/participation.hpp): independent of the states' scaling, equal to the
// kinetic-energy shares with the full mass matrix for an undamped system, real roots one by one.
#include <gtest/gtest.h>

#include "modal/eigen.hpp"
#include "modal/participation.hpp"

namespace {

using whirl::MatX;

// Two masses on springs, coupled: M q̈ + K q = 0 in state form x = [q; q̇].
MatX stateMatrix(const MatX& M, const MatX& K) {
  const Eigen::Index n = M.rows();
  MatX A = MatX::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n) = MatX::Identity(n, n);
  A.bottomLeftCorner(n, n) = -M.inverse() * K;
  return A;
}

TEST(Participation, UndampedEqualsKineticEnergyShareWithFullMass) {
  MatX M(2, 2), K(2, 2);
  M << 3.0, 0.5, 0.5, 1.0;
  K << 40.0, -10.0, -10.0, 25.0;
  const std::vector<int> coord = {0, 1, 0, 1};
  const auto modes = whirl::participationModes(whirl::eigenStandard(stateMatrix(M, K), true), coord, {"a", "b"});
  ASSERT_EQ(modes.size(), 2u);
  // Reference: the generalized eigenproblem K φ = ω² M φ solved independently (Eigen).
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> ges(K, M);
  for (int k = 0; k < 2; ++k) {
    const Eigen::VectorXd phi = ges.eigenvectors().col(k), Mphi = M * phi;
    const Eigen::VectorXd share = (phi.array() * Mphi.array()).abs() / (phi.array() * Mphi.array()).abs().sum();
    EXPECT_NEAR(modes[k].freq_hz, std::sqrt(ges.eigenvalues()(k)) / (2 * M_PI), 1e-12);
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(modes[k].participation(i), share(i), 1e-10) << k << " " << i;
  }
}

TEST(Participation, StateScalingLeavesSharesUnchanged) {
  MatX M(2, 2), K(2, 2), C(2, 2);
  M << 3.0, 0.5, 0.5, 1.0;
  K << 40.0, -10.0, -10.0, 25.0;
  C << 0.4, 0.0, 0.0, 0.1;
  MatX A = stateMatrix(M, K);
  A.bottomRightCorner(2, 2) = -M.inverse() * C;
  // Coordinate b in millimetres instead of metres: x' = S x, A' = S A S⁻¹.
  const Eigen::VectorXd s = (Eigen::VectorXd(4) << 1.0, 1000.0, 1.0, 1000.0).finished();
  const MatX As = s.asDiagonal() * A * s.cwiseInverse().asDiagonal();
  const std::vector<int> coord = {0, 1, 0, 1};
  const auto m1 = whirl::participationModes(whirl::eigenStandard(A, true), coord, {"a", "b"});
  const auto m2 = whirl::participationModes(whirl::eigenStandard(As, true), coord, {"a", "b"});
  ASSERT_EQ(m1.size(), m2.size());
  for (size_t k = 0; k < m1.size(); ++k) {
    EXPECT_NEAR(m1[k].freq_hz, m2[k].freq_hz, 1e-10);
    EXPECT_EQ(m1[k].name, m2[k].name);
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(m1[k].participation(i), m2[k].participation(i), 1e-9);
  }
}

TEST(Participation, RealRootsAreModesOfTheirOwnAndFirstOrderStatesCount) {
  // An overdamped oscillator (roots −1 and −9) and a first-order lag (−3) that dominates its root.
  MatX A(3, 3);
  A << 0, 1, 0,    //
      -9, -10, 0,  //
      0, 0, -3;
  const auto modes = whirl::participationModes(whirl::eigenStandard(A, true), {0, 0, 1}, {"mass", "lag"});
  ASSERT_EQ(modes.size(), 3u);
  const double f[] = {1, 3, 9};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(modes[k].freq_hz, f[k] / (2 * M_PI), 1e-12);
    EXPECT_EQ(modes[k].damped_freq_hz, 0.0);
    EXPECT_NEAR(modes[k].damping_ratio, 1.0, 1e-12);  // −λ/|λ|, as MBC3 lists a real root
  }
  EXPECT_EQ(modes[0].name, "mass");
  EXPECT_EQ(modes[1].name, "lag");
  EXPECT_EQ(modes[2].name, "mass");
}

TEST(Participation, DoubleZeroRootIsOneRigidBodyMode) {
  // A free coordinate (angle and rate, a Jordan block at zero) beside a spring-mass.
  MatX A = MatX::Zero(4, 4);
  A(0, 2) = A(1, 3) = 1;
  A(3, 1) = -16;
  const auto modes = whirl::participationModes(whirl::eigenStandard(A, true), {0, 1, 0, 1}, {"free", "spring"});
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_TRUE(modes[0].rigid_body);
  EXPECT_EQ(modes[0].name, "free");
  EXPECT_NEAR(modes[1].freq_hz, 4 / (2 * M_PI), 1e-12);
  EXPECT_EQ(modes[1].name, "spring");
}

}  // namespace
