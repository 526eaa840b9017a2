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

TEST(RotorModes, BladeBaseNames) {
  EXPECT_EQ(bladeBaseName("blade 2 flap 1"), "flap 1");
  EXPECT_EQ(bladeBaseName("Blade 13 edge 1"), "edge 1");
  EXPECT_EQ(bladeBaseName("tower FA 1"), "tower FA 1");
  EXPECT_EQ(bladeBaseName("blade flap"), "blade flap");
}

}  // namespace
}  // namespace whirl
