// The aeroelastic linearization of the NREL 5MW against OpenFAST's: the toolbox deck behind
// shared/data/openfast-lin/rotating-9rpm (ElastoDyn blade flap 1, edge 1, flap 2 and the generator;
// AeroDyn BEMT with frozen wake; InflowWind 8 m/s; ServoDyn simple VS torque law), 9 rpm.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "linearize/periodic.hpp"
#include "modal/rotor_modes.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {
namespace {

const std::string kDeck = std::string(WHIRL_SOURCE_DIR) + "/tests/data/openfast/aero/toolbox/Main.fst";

// Source: shared/ref/openfast_rotating_9rpm_mbc.csv (copied in tests/data/openfast-lin/README.md) —
// MBC3 of OpenFAST v3.3's Main.{1,12,24}.lin (single precision), frequency and damping ratio.
// Tolerances (the acceptance, not the reference's 4 printed digits): frequency 1 %, damping
// 10 % relative, or 0.3 percentage points where the damping ratio is below 3 %. What remains
// between the two models (AeroDyn's skewed-wake redistribution of the induction over the azimuth,
// ElastoDyn's node-based integration of the distributed loads, single precision) is discussed in
// the README section "Aerodynamics".
struct Ref {
  const char* mode;
  double freq_hz, damping;
};
constexpr Ref kRef[] = {{"1st flap BW", 0.5878, 0.6311},
                        {"1st flap collective", 0.7225, 0.5253},
                        {"1st flap FW", 0.8416, 0.4401},
                        {"1st edge BW", 0.9371, 0.0163},
                        {"1st edge FW", 1.2371, 0.0124},
                        {"2nd flap BW", 1.8373, 0.1555},
                        {"2nd flap collective", 1.9870, 0.1429},
                        {"2nd flap FW", 2.1337, 0.1338},
                        {"1st edge collective (with generator)", 2.2561, 0.0226}};

TEST(Nrel5mwAero, Rotating9rpmMatchesOpenFast) {
  const Model m = readElastoDynModel(kDeck);
  ASSERT_TRUE(m.aero.active());
  ASSERT_TRUE(m.generator.active());
  PeriodicOptions opt;
  opt.azimuths = 36;
  const PeriodicLinearization p = linearizePeriodic(m, initialPoint(m), opt);
  const RotorModes r = rotorModes(m, p);
  std::vector<Mode> modes;
  for (const Mode& md : r.modes)
    if (!md.rigid_body && md.damped_freq_hz > 0.1) modes.push_back(md);
  std::sort(modes.begin(), modes.end(), [](const Mode& a, const Mode& b) { return a.freq_hz < b.freq_hz; });
  for (const Mode& md : modes)
    std::printf("  %-28s %9.4f Hz  damping %8.4f\n", md.name.c_str(), md.freq_hz, md.damping_ratio);
  ASSERT_EQ(modes.size(), std::size(kRef));
  for (std::size_t i = 0; i < std::size(kRef); ++i) {
    const Ref& ref = kRef[i];
    EXPECT_NEAR(modes[i].freq_hz, ref.freq_hz, 0.01 * ref.freq_hz) << ref.mode;
    const double tol = ref.damping < 0.03 ? 0.003 : 0.1 * ref.damping;
    EXPECT_NEAR(modes[i].damping_ratio, ref.damping, tol) << ref.mode << " (" << modes[i].name << ")";
  }
}

}  // namespace
}  // namespace whirl
