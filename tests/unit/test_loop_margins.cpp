// Loop margins (linearize/loop_margins.hpp) on a return ratio with closed-form margins, and the return
// ratio of linearize/closed_loop.hpp's broken pitch loop against the product controller × plant
// written out independently.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <complex>
#include <numbers>

#include "linearize/loop_margins.hpp"

namespace whirl {
namespace {

using cd = std::complex<double>;
constexpr double kPi = std::numbers::pi;

TEST(LoopMargins, ThirdOrderLoopHasClosedFormMargins) {
  // L = K/(s(s+1)(s+2)): ∠L = −180° at ω² = 2, |L| = K/6 there (gain margin 6/K); |L| = 1 at
  // ω²(ω²+1)(ω²+4) = K², phase margin 90° − atan ω − atan(ω/2).
  const double K = 2;
  auto S = [&](double w) {
    const cd s(0, w);
    return 1.0 / (1.0 + K / (s * (s + 1.0) * (s + 2.0)));
  };
  const LoopMargins m = loopMargins(S);
  EXPECT_NEAR(m.gain_margin, 6 / K, 1e-9);
  EXPECT_NEAR(m.gain_crossover, std::sqrt(2.0), 1e-9);
  double lo = 0.1, hi = 2;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi), x = mid * mid;
    (x * (x + 1) * (x + 4) < K * K ? lo : hi) = mid;
  }
  const double wc = 0.5 * (lo + hi);
  const double pm = 90 - (std::atan(wc) + std::atan(wc / 2)) * 180 / kPi;
  EXPECT_NEAR(m.phase_crossover, wc, 1e-9);
  EXPECT_NEAR(m.phase_margin, pm, 1e-7);
  EXPECT_NEAR(m.delay_margin, pm * kPi / 180 / wc, 1e-7);
  EXPECT_GT(m.peak_sensitivity, 1);
}

/// A rotor (state 0: generator speed / 97) with a lightly damped mode coupled to it; torque, pitch and
/// wind inputs, the generator speed as output.
StateSpaceModel rotorPlant() {
  StateSpaceModel p;
  p.A = MatX(3, 3);
  p.A << -0.05, 0.8, 0.0, 0.0, 0.0, 1.0, 3.0, -40.0, -0.3;
  p.B = MatX::Zero(3, 3);
  p.B(0, 1) = -0.45;
  p.B(2, 1) = 2.0;
  p.B(0, 0) = -2e-6;
  p.C = MatX::Zero(1, 3);
  p.C(0, 0) = 97;
  p.D = MatX::Zero(1, 3);
  p.u = {{"generator torque", "N m"}, {"collective pitch", "rad"}, {"wind speed", "m/s"}};
  p.y = {{"GenSpeed", "rad/s"}};
  p.x = {{"a", ""}, {"b", ""}, {"c", ""}};
  return p;
}

TEST(LoopMargins, BrokenPitchLoopIsControllerTimesPlant) {
  // A rotor (state 0: generator speed / 97) with a lightly damped mode coupled to it; pitch PI with a
  // first-order speed filter and a first-order actuator; torque held. L = −K(s) G(s) with
  // G = C_g (sI − A)⁻¹ B_θ and K = (−K_p − K_i/s) · ω_c/(s + ω_c) · ω_a/(s + ω_a).
  const StateSpaceModel p = rotorPlant();
  LinearController c;
  c.lpf_order = 1;
  c.lpf_freq = 1.5708;
  c.pitch_active = true;
  c.pitch_kp = -6.2e-3;
  c.pitch_ki = -3.3e-3;
  c.actuator_order = 1;
  c.actuator_freq = 5;
  const LoopSensitivity s = loopSensitivity(p, c, BrokenLoop::Pitch);
  for (double w : {0.05, 0.3, 1.0, 6.3}) {
    const cd jw(0, w);
    Eigen::MatrixXcd M = -p.A.cast<cd>();
    M.diagonal().array() += jw;
    const cd G = (p.C.cast<cd>() * M.partialPivLu().solve(p.B.col(1).cast<cd>()))(0, 0);
    const cd K = (-c.pitch_kp - c.pitch_ki / jw) * (c.lpf_freq / (jw + c.lpf_freq)) *
                 (c.actuator_freq / (jw + c.actuator_freq));
    const cd L = -K * G;
    const cd ours = 1.0 / sensitivityAt(s, w) - 1.0;
    EXPECT_LE(std::abs(ours - L), 1e-10 * std::abs(L)) << w;
  }
}

TEST(LoopMargins, ModalEvaluationEqualsTheLuPath) {
  // loopMargins(LoopSensitivity) evaluates S(jω) from one eigendecomposition; the margins equal those
  // from the LU at every frequency (the function form) to the modal path's check, 1e-7.
  const StateSpaceModel p = rotorPlant();
  LinearController c;
  c.lpf_order = 1;
  c.lpf_freq = 1.5708;
  c.pitch_active = true;
  c.pitch_kp = -6.2e-3;
  c.pitch_ki = -3.3e-3;
  c.torque = LinearController::Torque::Static;
  c.torque_slope = -300;
  for (BrokenLoop loop : {BrokenLoop::Pitch, BrokenLoop::Torque}) {
    const LoopSensitivity s = loopSensitivity(p, c, loop);
    const LoopMargins modal = loopMargins(s);
    const LoopMargins lu = loopMargins([&](double w) { return sensitivityAt(s, w); });
    for (auto [a, b] : {std::pair{modal.gain_margin, lu.gain_margin},
                        {modal.phase_margin, lu.phase_margin},
                        {modal.delay_margin, lu.delay_margin},
                        {modal.peak_sensitivity, lu.peak_sensitivity}}) {
      if (std::isinf(b)) {
        EXPECT_EQ(a, b);
      } else {
        EXPECT_NEAR(a, b, 1e-6 * std::abs(b));
      }
    }
  }
}

}  // namespace
}  // namespace whirl
