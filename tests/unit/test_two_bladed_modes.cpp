// Modes of a 2-bladed rotor (UAE Phase VI, cases/uae6: rigid hub, structure only):
//  - parked, rotorModes is the plain eigenanalysis of the one model (frequencies and damping equal
//    to computeModes on M, C, K), its blade modes named in the fixed frame (collective, cos, sin);
//  - turning slowly, the Floquet frequency of the differential flap mode (its backward whirl plus Ω,
//    modal/floquet_harmonic.hpp) lies between the parked rotor's values with the blades vertical and
//    horizontal: the slow rotor sees every azimuth, the parked one only its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "linearize/periodic.hpp"
#include "modal/rotor_modes.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {
namespace {

const std::string kUae = std::string(WHIRL_SOURCE_DIR) + "/cases/uae6/UAE6.fst";

const Mode& named(const std::vector<Mode>& modes, const std::string& name) {
  const auto m = std::find_if(modes.begin(), modes.end(), [&](const Mode& x) { return x.name == name; });
  if (m == modes.end()) throw std::runtime_error("no mode named " + name);
  return *m;
}

RotorModes periodicModes(const Model& m, double rpm) {
  OperatingCondition c;
  c.rotor_speed = rpm * std::numbers::pi / 30;
  PeriodicOptions opt;
  opt.azimuths = 36;
  return rotorModes(m, linearizePeriodic(m, c, opt));
}

TEST(TwoBladedModes, ParkedIsThePlainEigenanalysis) {
  const Model m = readElastoDynModel(kUae);
  const RotorModes r = periodicModes(m, 0);
  const LinearModel l = linearize(m, solveOperatingPoint(m, initialPoint(m, OperatingCondition{})));
  const std::vector<Mode> plain = computeModes(l.M, l.C, l.K, l.dof_names);
  ASSERT_EQ(r.modes.size(), plain.size());
  for (std::size_t k = 0; k < plain.size(); ++k) {
    EXPECT_NEAR(r.modes[k].freq_hz, plain[k].freq_hz, 1e-9 * std::max(1.0, plain[k].freq_hz)) << k;
    EXPECT_NEAR(r.modes[k].damping_ratio, plain[k].damping_ratio, 1e-8) << k;
  }
  EXPECT_NO_THROW(named(r.modes, "flap 1 collective"));
  EXPECT_NO_THROW(named(r.modes, "flap 1 cos"));  // blade 1 up: the differential pattern is the cosine
}

TEST(TwoBladedModes, SlowRotorLiesBetweenParkedAzimuths) {
  const Model up = readElastoDynModel(kUae, {"Azimuth=0"}), across = readElastoDynModel(kUae, {"Azimuth=90"});
  const double vertical = named(periodicModes(up, 0).modes, "flap 1 cos").freq_hz;
  const double horizontal = named(periodicModes(across, 0).modes, "flap 1 sin").freq_hz;
  ASSERT_GT(horizontal - vertical, 0.3);  // 7.00 and 7.60 Hz: the tower's two directions differ
  const double rpm = 3;
  const double rotating = named(periodicModes(up, rpm).modes, "flap 1 BW").freq_hz + rpm / 60;
  EXPECT_GT(rotating, vertical);
  EXPECT_LT(rotating, horizontal);
}

}  // namespace
}  // namespace whirl
