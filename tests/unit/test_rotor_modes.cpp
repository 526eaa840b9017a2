// Multiblade modes of an isotropic rotor on a rigid hub at prescribed speed: collective modes at
// the rotating-frame frequency, cyclic ones exactly ∓Ω from it (BW below, FW above); names say so.
#include <gtest/gtest.h>

#include <numbers>

#include "linearize/periodic.hpp"
#include "modal/floquet.hpp"
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

std::vector<MbcSample> samplesOf(const PeriodicLinearization& p) {
  std::vector<MbcSample> out;
  for (std::size_t k = 0; k < p.models.size(); ++k) {
    MbcSample s;
    s.azimuth = p.azimuths[k];
    s.rotor_speed = p.rotor_speed;
    s.A = p.models[k].A;
    out.push_back(s);
  }
  return out;
}

RotorCoordinates coordinatesOf(const Model& m, const PeriodicLinearization& p) {
  RotorCoordinates c;
  const LinearModel& l = p.models.front();
  c.names = l.dof_names;
  for (int d : l.dofs) {
    c.blade.push_back(m.dofs[d].blade);
    c.azimuth.push_back(m.dofs[d].rotating);
    c.held.push_back(false);
  }
  c.weights = l.M.diagonal().asDiagonal();
  return c;
}

// Floquet analysis of an isotropic 3-bladed rotor (time-invariant after the multiblade transform)
// gives the multiblade modes: the equal multipliers of each collective/BW/FW triple are split by
// harmonic, each mode's frequency is the fixed-frame one. Tolerance: the Magnus integration over 8
// steps per azimuth interval (measured 1e-12 here: A is constant in blade coordinates).
TEST(Floquet, IsotropicThreeBladedRotorEqualsMultiblade) {
  const Model m = test::rotorModel(12);
  PeriodicOptions opt;
  opt.azimuths = 8;
  const PeriodicLinearization p = linearizePeriodic(m, initialPoint(m), opt);
  const RotorModes mbc = rotorModes(m, p);
  const RotorModes fl = floquetModes(coordinatesOf(m, p), samplesOf(p));
  ASSERT_EQ(fl.modes.size(), mbc.modes.size());
  for (std::size_t k = 0; k < mbc.modes.size(); ++k) {
    EXPECT_NEAR(fl.modes[k].freq_hz, mbc.modes[k].freq_hz, 1e-8 * mbc.modes[k].freq_hz) << mbc.modes[k].name;
    EXPECT_NEAR(fl.modes[k].damping_ratio, mbc.modes[k].damping_ratio, 1e-8) << mbc.modes[k].name;
    EXPECT_EQ(fl.modes[k].name, mbc.modes[k].name);
  }
}

// Two blades on a rigid hub: no multiblade transform applies, rotorModes takes Floquet. Each blade
// vibrates at its rotating-frame frequency; the collective pattern is seen at that frequency in the
// fixed frame, the differential (cyclic) one at the rotating-frame frequency ± Ω. Parked, the modes
// are the plain eigenanalysis of the first azimuth.
TEST(Floquet, TwoBladedRotorTurningAndParked) {
  const double rpm = 12, f_rotor = rpm / 60;
  const Model m = test::rotorModel(rpm, 2);
  PeriodicOptions opt;
  opt.azimuths = 8;
  const PeriodicLinearization p = linearizePeriodic(m, initialPoint(m), opt);
  const RotorModes r = rotorModes(m, p);
  const LinearModel& l = p.models[0];
  const auto single = computeModes(l.M.topLeftCorner(2, 2), l.C.topLeftCorner(2, 2), l.K.topLeftCorner(2, 2),
                                   {"flap 1", "edge 1"});
  ASSERT_EQ(r.modes.size(), 4u);
  for (const auto& s : single) {
    EXPECT_NEAR(byName(r, s.name + " collective").freq_hz, s.freq_hz, 1e-8 * s.freq_hz) << s.name;
    int cyclic = 0;
    for (const Mode& md : r.modes)
      if (md.name == s.name + " BW" || md.name == s.name + " FW") {
        ++cyclic;
        EXPECT_NEAR(std::abs(md.freq_hz - s.freq_hz), f_rotor, 1e-8 * s.freq_hz) << md.name;
      }
    EXPECT_EQ(cyclic, 1) << s.name;
  }
  const Model parked = test::rotorModel(0, 2);
  const PeriodicLinearization pp = linearizePeriodic(parked, initialPoint(parked), opt);
  const RotorModes rp = rotorModes(parked, pp);
  const LinearModel& lp = pp.models[0];
  const auto plain = computeModes(lp.M, lp.C, lp.K, lp.dof_names);
  ASSERT_EQ(rp.modes.size(), plain.size());
  for (std::size_t k = 0; k < plain.size(); ++k) EXPECT_NEAR(rp.modes[k].freq_hz, plain[k].freq_hz, 1e-12);
}

TEST(RotorModes, BladeBaseNames) {
  EXPECT_EQ(bladeBaseName("blade 2 flap 1"), "flap 1");
  EXPECT_EQ(bladeBaseName("Blade 13 edge 1"), "edge 1");
  EXPECT_EQ(bladeBaseName("tower FA 1"), "tower FA 1");
  EXPECT_EQ(bladeBaseName("blade flap"), "blade flap");
}

}  // namespace
}  // namespace whirl
