// Multiblade modes of an isotropic rotor on a rigid hub at prescribed speed: collective modes at
// the rotating-frame frequency, cyclic ones exactly ∓Ω from it (BW below, FW above); names say so.
#include <gtest/gtest.h>

#include <numbers>

#include "linearize/periodic.hpp"
#include "modal/rotor_modes.hpp"
#include "tests/support/rotor_model.hpp"

namespace whirl {
namespace {

const Mode& byName(const RotorModes& r, const std::string& name) {
  for (const auto& m : r.modes)
    if (m.name == name) return m;
  throw std::runtime_error("no mode named " + name);
}

TEST(RotorModes, CyclicModesSplitByRotorSpeed) {
  const double rpm = 12;
  const double f_rotor = rpm / 60;
  const Model m = test::rotorModel(rpm);
  PeriodicOptions opt;
  opt.azimuths = 8;
  const PeriodicLinearization p = linearizePeriodic(m, initialPoint(m), opt);
  const RotorModes r = rotorModes(m, p);
  ASSERT_EQ(r.num_blades, 3);
  ASSERT_EQ(r.modes.size(), 6u);
  // Rotating-frame frequencies from blade 1 alone (its own DOFs of the azimuth-0 model).
  const LinearModel& l = p.models[0];
  const auto single = computeModes(l.M.topLeftCorner(2, 2), l.C.topLeftCorner(2, 2), l.K.topLeftCorner(2, 2),
                                   {"flap 1", "edge 1"});
  for (const auto& s : single) {
    const std::string base = s.name;
    EXPECT_NEAR(byName(r, base + " collective").freq_hz, s.freq_hz, 1e-9 * s.freq_hz) << base;
    EXPECT_NEAR(byName(r, base + " BW").freq_hz, s.freq_hz - f_rotor, 1e-9 * s.freq_hz) << base;
    EXPECT_NEAR(byName(r, base + " FW").freq_hz, s.freq_hz + f_rotor, 1e-9 * s.freq_hz) << base;
  }
}

// A slow pair that a held coordinate (a free yaw) carries almost alone is that coordinate's rigid-body
// pair even when weak couplings make it oscillate and grow, as SWRT's free yaw and free generator do
// at 188 rpm (0.0086 Hz, damping −0.26): never named after a group with a negligible share. Here a
// held "yaw" with a tiny stiffness and negative damping, weakly coupled to a 1 Hz "tower FA 1".
TEST(RotorModes, PairCarriedByAHeldCoordinateIsRigidBody) {
  const double w = 2 * std::numbers::pi;  // tower at 1 Hz
  MatX M = MatX::Identity(2, 2), C(2, 2), K(2, 2);
  C << -0.03, 0, 0, 0.02 * w;
  K << 3e-3, 1e-4, 1e-4, w * w;  // yaw "stiffness" from the averaged periodic terms: 0.0087 Hz
  MatX A = MatX::Zero(4, 4);
  A.topRightCorner(2, 2).setIdentity();
  A.bottomLeftCorner(2, 2) = -M.inverse() * K;
  A.bottomRightCorner(2, 2) = -M.inverse() * C;
  RotorCoordinates c;
  c.names = {"yaw", "tower FA 1"};
  c.blade = {-1, -1};
  c.azimuth = {false, false};
  c.held = {true, false};
  c.weights = M;
  MbcSample s;
  s.A = A;
  const RotorModes r = multibladeModes(c, secondOrderLayout(3, c.blade), {s});
  ASSERT_EQ(r.modes.size(), 2u);
  const Mode& yaw = r.modes[0];
  EXPECT_GT(yaw.freq_hz, 5e-3);  // above the slow-mode limit: named by its share, not its speed
  EXPECT_LT(yaw.damping_ratio, 0);
  EXPECT_EQ(yaw.name, "yaw (rigid body)");
  EXPECT_TRUE(yaw.rigid_body);
  EXPECT_EQ(r.modes[1].name, "tower FA 1");
}

TEST(RotorModes, BladeBaseNames) {
  EXPECT_EQ(bladeBaseName("blade 2 flap 1"), "flap 1");
  EXPECT_EQ(bladeBaseName("Blade 13 edge 1"), "edge 1");
  EXPECT_EQ(bladeBaseName("tower FA 1"), "tower FA 1");
  EXPECT_EQ(bladeBaseName("blade flap"), "blade flap");
}

}  // namespace
}  // namespace whirl
