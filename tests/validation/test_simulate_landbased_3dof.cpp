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
#include "modal/nonlinear_check.hpp"
#include "src/base/error.hpp"
#include "tests/support/decay_support.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

TEST(SimulateLandbased3Dof, FreeDecayFrequenciesMatchEigenvalues) {
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
    const IdentifiedDecay d = test::identifyDofDecay(sim, dof, eq.q(dof));
    const Mode* mode = test::modeNamed(modes, name);
    ASSERT_NE(mode, nullptr) << name;
    std::printf("%s: identified %.6f Hz (damped) %.5f damping, eigenvalue %.6f Hz %.5f\n", name, d.damped_freq_hz,
                d.damping_ratio, mode->damped_freq_hz, mode->damping_ratio);
    EXPECT_NEAR(d.damped_freq_hz, mode->damped_freq_hz, 1e-3 * mode->damped_freq_hz) << name;  // 0.1 %
    // Not the damping: the two tower modes (0.327, 0.323 Hz) excited together exchange energy through
    // the gyroscopic coupling, which biases each coordinate's logarithmic decrement (by ~10 %); the
    // check below perturbs one coordinate at a time.
  }
}

// `verify` (modal/nonlinear_check.hpp): the nonlinear decay minus the exported linear model's falls as
// ε² — the order observed between ε = 0.01, 0.005, 0.0025 m is 2 — and the frequency and damping
// identified from each coordinate's decay alone equal the eigenvalues' (to the zero-crossing
// identification's accuracy over 30 s sampled at 100 Hz: 1e-4 in frequency, 1 % in damping; the
// eigensystem realization of both coordinates' response to 1e-7 and 1e-4: measured 4e-9, 1.6e-6).
TEST(SimulateLandbased3Dof, LinearModelIsTheJacobianOfTheNonlinearOne) {
  const Model m = test::loadCase("landbased_3dof");
  OperatingCondition c;
  c.rotor_speed = 5 * std::numbers::pi / 30;
  const OperatingPoint eq = solveOperatingPoint(m, c);
  NonlinearCheckOptions o;
  o.t_end = 30;
  const NonlinearCheck r = checkAgainstLinear(m, eq, o);
  ASSERT_EQ(r.orders.size(), 2u);
  for (double p : r.orders) EXPECT_NEAR(p, 2.0, 0.05);
  EXPECT_LT(r.levels[0].max_difference, 1e-5 * r.levels[0].max_response);
  ASSERT_EQ(r.identified_dofs, (std::vector<std::string>{"tower FA 1", "tower SS 1"}));
  for (size_t k = 0; k < 2; ++k) {
    const Mode* mode = nullptr;
    for (const Mode& md : r.modes)
      if (md.name == r.identified_dofs[k]) mode = &md;
    ASSERT_NE(mode, nullptr);
    EXPECT_NEAR(r.identified[k].damped_freq_hz, mode->damped_freq_hz, 1e-4 * mode->damped_freq_hz);
    EXPECT_NEAR(r.identified[k].damping_ratio, mode->damping_ratio, 0.01 * mode->damping_ratio);
    const IdentifiedPole* p = nearestPole(r.poles[k], mode->damped_freq_hz);
    ASSERT_NE(p, nullptr);
    std::printf("%s realized: frequency %+.2e, damping %+.2e relative\n", mode->name.c_str(),
                p->damped_freq_hz / mode->damped_freq_hz - 1, p->damping_ratio / mode->damping_ratio - 1);
    EXPECT_NEAR(p->damped_freq_hz, mode->damped_freq_hz, 1e-7 * mode->damped_freq_hz);
    EXPECT_NEAR(p->damping_ratio, mode->damping_ratio, 1e-4 * mode->damping_ratio);
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
    // In words, with the limit and the interval; none of SUNDIALS' internal option names (issue 48).
    EXPECT_THAT(std::string(e.what()),
                ::testing::HasSubstr("more than 3 integrator steps between two output instants"));
    EXPECT_THAT(std::string(e.what()), ::testing::Not(::testing::HasSubstr("mxstep")));
  }
}

}  // namespace
}  // namespace whirl
