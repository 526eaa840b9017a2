// Mode extraction: frequencies, damping, rigid-body modes and names on systems with known answers.
#include <gtest/gtest.h>

#include <numbers>

#include "modal/modes.hpp"

namespace whirl {
namespace {

constexpr double two_pi = 2 * std::numbers::pi;

TEST(Modes, TwoMassChainMatchesClosedForm) {
  // m1 = m2 = 1, k1 = k2 = 1 (ground-m1-m2): ω² = (3 ∓ √5)/2.
  MatX M = MatX::Identity(2, 2), K(2, 2), C = MatX::Zero(2, 2);
  K << 2, -1, -1, 1;
  const auto modes = computeModes(M, C, K, {"a", "b"});
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_NEAR(modes[0].freq_hz, std::sqrt((3 - std::sqrt(5.0)) / 2) / two_pi, 1e-12);
  EXPECT_NEAR(modes[1].freq_hz, std::sqrt((3 + std::sqrt(5.0)) / 2) / two_pi, 1e-12);
  EXPECT_EQ(modes[0].name, "b");  // shape (1, 1.618): a carries 1/2.618 of b's share, below half
  EXPECT_NEAR(modes[0].participation.sum(), 1.0, 1e-12);
}

TEST(Modes, DampingRatioAndDampedFrequency) {
  MatX M = MatX::Constant(1, 1, 2.0), K = MatX::Constant(1, 1, 8.0), C = MatX::Constant(1, 1, 0.4);
  const auto modes = computeModes(M, C, K, {"x"});
  ASSERT_EQ(modes.size(), 1u);
  const double w = 2.0, zeta = 0.4 / (2 * 2.0 * w);
  EXPECT_NEAR(modes[0].freq_hz, w / two_pi, 1e-12);
  EXPECT_NEAR(modes[0].damping_ratio, zeta, 1e-12);
  EXPECT_NEAR(modes[0].damped_freq_hz, w * std::sqrt(1 - zeta * zeta) / two_pi, 1e-12);
}

TEST(Modes, OverdampedPairIsOneModeWithZetaAboveOne) {
  MatX M = MatX::Constant(1, 1, 1.0), K = MatX::Constant(1, 1, 1.0), C = MatX::Constant(1, 1, 5.0);
  const auto modes = computeModes(M, C, K, {"x"});
  ASSERT_EQ(modes.size(), 1u);
  EXPECT_NEAR(modes[0].freq_hz, 1.0 / two_pi, 1e-12);
  EXPECT_NEAR(modes[0].damping_ratio, 2.5, 1e-12);
  EXPECT_EQ(modes[0].damped_freq_hz, 0.0);
}

TEST(Modes, FreeCoordinateIsARigidBodyModeAtZeroFrequency) {
  MatX M = MatX::Identity(2, 2), C = MatX::Zero(2, 2), K = MatX::Zero(2, 2);
  K(0, 0) = 4;
  const auto modes = computeModes(M, C, K, {"spring", "azimuth"});
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_TRUE(modes[0].rigid_body);
  EXPECT_EQ(modes[0].freq_hz, 0.0);
  EXPECT_EQ(modes[0].name, "azimuth");
  EXPECT_NEAR(modes[1].freq_hz, 2 / two_pi, 1e-12);
}

}  // namespace
}  // namespace whirl
