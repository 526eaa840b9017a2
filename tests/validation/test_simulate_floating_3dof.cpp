// [BranlardGeisler2022, §4.6] in the time domain: the floating three-DOF turbine (no damping),
// integrated by `simulate` (IDA), frequencies identified from free decays against the linear model's
// eigenvalues at the equilibrium.
// The issue asks for 0.1 % at the paper's release state x = 0, φ = 2°, q_T = 1 m; whirl gives −0.21 %
// (pitch) and −0.38 % (tower) there by zero crossings (printed, not asserted), and the eigensystem
// realization of all three coordinates — which separates the pitch mode that q_T carries too — gives the
// same, −0.20 % and −0.39 %: the two independent identifications agree to 3e-4, so the offsets are the
// nonlinear system's own frequencies at that amplitude (they fall with the amplitude, below), not a
// bias of the identification. Released along one coordinate at a small amplitude both match to 0.1 %.
#include <gtest/gtest.h>

#include <numbers>

#include "linearize/simulate.hpp"
#include "modal/decay_identification.hpp"
#include "modal/modes.hpp"
#include "tests/support/decay_support.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

TEST(SimulateFloating3Dof, SeedReleaseStateFrequencies) {
  const Model m = test::loadCase("floating_3dof");
  const OperatingPoint eq = solveOperatingPoint(m, initialPoint(m));
  const LinearModel lin = linearize(m, eq);
  const std::vector<Mode> modes = computeModes(lin.M, lin.C, lin.K, lin.dof_names);
  OperatingPoint start = eq;
  const int pitch = *m.findDof("pitch"), fa = *m.findDof("tower FA 1");
  start.q(*m.findDof("surge")) = 0;
  start.q(pitch) = 2 * std::numbers::pi / 180;
  start.q(fa) = 1.0;
  SimulationOptions o;
  o.t_end = 100;  // 10 pitch periods
  o.dt_out = 0.01;
  o.rtol = 1e-9;
  o.atol = 1e-11;
  const Simulation sim = simulate(m, start, o);
  // Both identifications: the zero crossings of the coordinate, and the eigensystem realization of all
  // three coordinates, which separates the pitch and tower modes that share q_T.
  const std::vector<IdentifiedPole> poles = realizedPoles(sim, eq, o.dt_out);
  for (const auto& [dof, name] : {std::pair{pitch, "pitch"}, std::pair{fa, "tower FA 1"}}) {
    const IdentifiedDecay d = test::identifyDofDecay(sim, dof, eq.q(dof));
    const Mode* mode = test::modeNamed(modes, name);
    ASSERT_NE(mode, nullptr) << name;
    const IdentifiedPole* p = nearestPole(poles, mode->damped_freq_hz);
    ASSERT_NE(p, nullptr) << name;
    std::printf("%s: eigenvalue %.6f Hz; zero crossings %.6f Hz (%+.3f %%); realization %.6f Hz (%+.3f %%)\n", name,
                mode->damped_freq_hz, d.damped_freq_hz, 100 * (d.damped_freq_hz / mode->damped_freq_hz - 1),
                p->damped_freq_hz, 100 * (p->damped_freq_hz / mode->damped_freq_hz - 1));
    EXPECT_NEAR(p->damped_freq_hz, d.damped_freq_hz, 3e-4 * d.damped_freq_hz) << name;
  }
}

// One coordinate released at a time: the identified frequency's offset from the eigenvalue is an
// amplitude effect — it shrinks by more than 10× from 2° to 0.5° of pitch (measured: 45×,
// −1.1e-3 → −2.5e-5; at least the 16× of a quadratic law) — and at the small amplitudes both
// frequencies are within 0.1 %.
TEST(SimulateFloating3Dof, SmallDecaysMatchEigenvaluesAndTheOffsetShrinks) {
  const Model m = test::loadCase("floating_3dof");
  const OperatingPoint eq = solveOperatingPoint(m, initialPoint(m));
  const LinearModel lin = linearize(m, eq);
  const std::vector<Mode> modes = computeModes(lin.M, lin.C, lin.K, lin.dof_names);
  auto identified = [&](const char* name, double amplitude) {
    const int dof = *m.findDof(name);
    OperatingPoint start = eq;
    start.q(dof) += amplitude;
    SimulationOptions o;
    o.t_end = 100;
    o.dt_out = 0.01;
    o.rtol = 1e-9;
    o.atol = 1e-11;
    const Simulation sim = simulate(m, start, o);
    const Mode* md = test::modeNamed(modes, name);
    if (!md) {
      ADD_FAILURE() << "no mode " << name;
      return 0.0;
    }
    return test::identifyDofDecay(sim, dof, eq.q(dof)).damped_freq_hz / md->damped_freq_hz - 1;
  };
  const double deg = std::numbers::pi / 180;
  const double big = identified("pitch", 2 * deg), small = identified("pitch", 0.5 * deg);
  std::printf("pitch offset: %.3e at 2 deg, %.3e at 0.5 deg\n", big, small);
  EXPECT_LT(std::abs(small), 1e-3);
  EXPECT_GT(std::abs(big), 10 * std::abs(small));
  const double tower = identified("tower FA 1", 0.25);
  std::printf("tower FA 1 offset at 0.25 m: %.3e\n", tower);
  EXPECT_LT(std::abs(tower), 1e-3);
  // The realization of the 0.5° pitch release finds both modes it excites (the tower through the
  // coupling) at their eigenvalues.
  OperatingPoint start = eq;
  start.q(*m.findDof("pitch")) += 0.5 * deg;
  SimulationOptions o;
  o.t_end = 100;
  o.dt_out = 0.01;
  o.rtol = 1e-9;
  o.atol = 1e-11;
  const std::vector<IdentifiedPole> poles = realizedPoles(simulate(m, start, o), eq, o.dt_out);
  for (const char* name : {"pitch", "tower FA 1"}) {
    const Mode* md = test::modeNamed(modes, name);
    ASSERT_NE(md, nullptr) << name;
    const double f = nearestPole(poles, md->damped_freq_hz)->damped_freq_hz;
    std::printf("%s realized at 0.5 deg: %.3e\n", name, f / md->damped_freq_hz - 1);
    EXPECT_NEAR(f, md->damped_freq_hz, 1e-3 * md->damped_freq_hz) << name;
  }
}

}  // namespace
}  // namespace whirl
