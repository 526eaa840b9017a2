// The eigensystem realization algorithm against free responses whose poles are known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "modal/era.hpp"
#include "src/base/error.hpp"

namespace whirl {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// x(t) = a e^{−ζωt} cos(ω_d t + ψ), ω_d = ω √(1 − ζ²): one damped mode of frequency f [Hz].
double mode(double t, double f, double zeta, double a, double psi) {
  const double w = kTwoPi * f;
  return a * std::exp(-zeta * w * t) * std::cos(w * std::sqrt(1 - zeta * zeta) * t + psi);
}

}  // namespace

// Two modes sharing two channels (0.1 Hz undamped, 0.8 Hz with 2 % damping) and a constant offset
// (a pole at z = 1): every pole to round-off, where a zero-crossing count on either channel is biased
// by the other mode.
TEST(Era, SeparatesModesThatShareTheChannels) {
  const double dt = 0.01;
  const int N = 6001;
  MatX y(N, 2);
  for (int k = 0; k < N; ++k) {
    const double t = k * dt;
    y(k, 0) = mode(t, 0.1, 0.0, 1.0, 0.0) + mode(t, 0.8, 0.02, 0.05, 0.3) + 0.2;
    y(k, 1) = mode(t, 0.1, 0.0, 0.3, 0.0) + mode(t, 0.8, 0.02, 1.0, 0.3);
  }
  const std::vector<IdentifiedPole> poles = identifyPoles(y, dt);
  ASSERT_EQ(poles.size(), 3u);
  const IdentifiedPole* slow = nearestPole(poles, 0.1);
  const IdentifiedPole* fast = nearestPole(poles, 0.8);
  const IdentifiedPole* still = nearestPole(poles, 0.0);
  EXPECT_NEAR(slow->freq_hz, 0.1, 1e-9);
  EXPECT_NEAR(slow->damping_ratio, 0.0, 1e-8);
  EXPECT_NEAR(fast->freq_hz, 0.8, 1e-9);
  EXPECT_NEAR(fast->damped_freq_hz, 0.8 * std::sqrt(1 - 0.02 * 0.02), 1e-9);
  EXPECT_NEAR(fast->damping_ratio, 0.02, 1e-8);
  EXPECT_NEAR(still->freq_hz, 0.0, 1e-9);
  // Shares: the slow mode's mean amplitude is the largest (it does not decay).
  EXPECT_EQ(&poles[0], slow);
  EXPECT_DOUBLE_EQ(slow->share, 1.0);
  EXPECT_LT(fast->share, 1.0);
}

// A decaying real pole (an overdamped coordinate) comes out with ζ = 1 and its rate.
TEST(Era, RealPoleHasUnitDamping) {
  const double dt = 0.02, rate = 0.7;
  const int N = 2000;
  MatX y(N, 1);
  for (int k = 0; k < N; ++k) y(k, 0) = std::exp(-rate * k * dt) + mode(k * dt, 0.5, 0.05, 0.5, 1.0);
  const std::vector<IdentifiedPole> poles = identifyPoles(y, dt);
  ASSERT_EQ(poles.size(), 2u);
  const IdentifiedPole* real = nearestPole(poles, 0.0);
  EXPECT_NEAR(real->freq_hz, rate / kTwoPi, 1e-9);
  EXPECT_NEAR(real->damping_ratio, 1.0, 1e-12);
  EXPECT_EQ(real->damped_freq_hz, 0.0);
  EXPECT_NEAR(nearestPole(poles, 0.5)->damping_ratio, 0.05, 1e-8);
}

TEST(Era, TooFewSamplesOrABadIntervalAreInputErrors) {
  EXPECT_THROW(identifyPoles(MatX::Ones(30, 1), 0.01), InputError);
  EXPECT_THROW(identifyPoles(MatX::Ones(300, 1), 0.0), InputError);
  EXPECT_THROW(identifyPoles(MatX::Ones(300, 1), NAN), InputError);
  EXPECT_THROW(identifyPoles(MatX(300, 0), 0.01), InputError);
}

}  // namespace whirl
