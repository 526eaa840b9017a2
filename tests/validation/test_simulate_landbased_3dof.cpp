// [BranlardGeisler2022, §4.5, Fig. 6] in the time domain: the three-DOF land-based turbine, tower
// top displaced 1 m fore-aft and side-side, rotor free at 5 rpm, free decay integrated by
// `simulate` (IDA). The frequencies and damping ratios identified from the decay equal those of
// the linear model whirl exports at the equilibrium (the criterion: frequencies to 0.1 %).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>

#include "linearize/simulate.hpp"
#include "modal/decay_identification.hpp"
#include "modal/modes.hpp"
#include "src/model/error.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

TEST(SimulateLandbased3DofSlow, FreeDecayFrequenciesMatchEigenvalues) {
  const Model m = test::loadCase("landbased_3dof");
  OperatingCondition c;
  c.rotor_speed = 5 * std::numbers::pi / 30;  // 5 rpm [BranlardGeisler2022, §4.5]
  const OperatingPoint eq = solveOperatingPoint(m, c);
  const LinearModel lin = linearize(m, eq);
  const std::vector<Mode> modes = computeModes(lin.M, lin.C, lin.K, lin.dof_names);
  OperatingPoint start = eq;
  const int fa = *m.findDof("tower FA 1"), ss = *m.findDof("tower SS 1");
  start.q(fa) = 1.0;  // tower top 1 m (the shapes are 1 at the top)
  start.q(ss) = 1.0;
  SimulationOptions o;
  o.t_end = 60;
  o.dt_out = 0.01;
  o.rtol = 1e-8;
  o.atol = 1e-10;
  const Simulation sim = simulate(m, start, o);  // azimuth free: a state
  EXPECT_EQ(sim.states.size(), 3u);
  for (const auto& [dof, name] : {std::pair{fa, "tower FA 1"}, std::pair{ss, "tower SS 1"}}) {
    std::vector<double> x(sim.time.size());
    for (size_t k = 0; k < x.size(); ++k) x[k] = sim.q(static_cast<Eigen::Index>(k), dof);
    const IdentifiedDecay d = identifyDecay(sim.time, x, eq.q(dof));
    const Mode* mode = nullptr;
    for (const Mode& md : modes)
      if (md.name == name) mode = &md;
    ASSERT_NE(mode, nullptr) << name;
    std::printf("%s: identified %.6f Hz (damped) %.5f damping, eigenvalue %.6f Hz %.5f\n", name, d.damped_freq_hz,
                d.damping_ratio, mode->damped_freq_hz, mode->damping_ratio);
    EXPECT_NEAR(d.damped_freq_hz, mode->damped_freq_hz, 1e-3 * mode->damped_freq_hz) << name;  // 0.1 %
    EXPECT_NEAR(d.damping_ratio, mode->damping_ratio, 0.05 * mode->damping_ratio) << name;
  }
}

TEST(SimulateLandbased3Dof, DrivenRotorTurnsAtItsSpeed) {
  const Model m = test::loadCase("landbased_3dof");
  OperatingCondition c;
  c.rotor_speed = 1.0;
  const OperatingPoint start = initialPoint(m, c);
  SimulationOptions o;
  o.t_end = 1;
  o.dt_out = 0.25;
  o.prescribed = m.roles.azimuth;
  const Simulation sim = simulate(m, start, o);
  const int az = *m.findDof("azimuth");
  EXPECT_EQ(sim.states.size(), 2u);
  ASSERT_EQ(sim.time.size(), 5u);
  for (Eigen::Index k = 0; k < 5; ++k) {
    EXPECT_DOUBLE_EQ(sim.q(k, az), start.q(az) + 1.0 * sim.time[static_cast<size_t>(k)]);
    EXPECT_EQ(sim.qd(k, az), 1.0);
  }
}

TEST(SimulateLandbased3Dof, StepLimitIsAComputeErrorNamingTheTime) {
  const Model m = test::loadCase("landbased_3dof");
  OperatingPoint start = initialPoint(m);
  start.q(*m.findDof("tower FA 1")) = 1.0;
  SimulationOptions o;
  o.t_end = 10;
  o.max_steps = 3;
  try {
    simulate(m, start, o);
    FAIL() << "no error";
  } catch (const ComputeError& e) {
    EXPECT_THAT(std::string(e.what()), ::testing::HasSubstr("simulate: t = "));
    EXPECT_THAT(std::string(e.what()), ::testing::HasSubstr("IDA_TOO_MUCH_WORK"));
  }
}

}  // namespace
}  // namespace whirl
