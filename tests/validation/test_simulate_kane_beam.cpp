// Kane's driver experiment [Branlard2019, §5.2] (cases/kane_beam): a cantilever on a hub spun up by
// the imposed θ̈ = (2/5)(1 − cos(πt/7.5)) for 15 s, then 6 rad/s. With the axial shortening (the
// quadratic basis, whirl's geometric-stiffness term) the in-plane tip deflection stays bounded and
// settles back near zero once the acceleration ends; without it the first frequency (3.8 rad/s) is
// below the final speed, the centrifugal softening wins and the motion diverges — the seed's
// qualitative result. The tip-deflection history against an independent lumped-segment reference
// (the seed's 0.3–0.5 % RMS): test_simulate_kane_chain.cpp. With 1 and 3 shapes the deepest tip
// deflection agrees to a few per cent (printed).
#include <gtest/gtest.h>

#include <numbers>

#include "linearize/simulate.hpp"
#include "modal/modes.hpp"
#include "src/io/case/case_file.hpp"
#include "tests/support/kane_spin_up.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

Simulation spinUp(const std::vector<std::string>& sets, Model& m) {
  std::vector<CaseOverride> o;
  for (const auto& s : sets) o.push_back(parseOverride(s));
  m = readCase(std::string(WHIRL_SOURCE_DIR) + "/cases/kane_beam/kane_beam.yaml", o);
  return test::kaneSpinUp(m);
}

// Tip deflection in the plane of rotation (the case's output), min over time and at the end.
std::pair<double, double> tip(const Model& m, const Simulation& sim) {
  const int y = *m.findOutput("tip deflection");
  return {sim.y.col(y).minCoeff(), sim.y(sim.y.rows() - 1, y)};
}

TEST(SimulateKaneBeam, BoundedWithGeometricStiffnessDivergentWithout) {
  Model m;
  const Simulation three = spinUp({}, m);
  const auto [min3, end3] = tip(m, three);
  const Simulation one = spinUp({"bodies.beam.shapes=[{name: edge 1, type: clamped_topmass, mode: 1, "
                                 "tip_mass_ratio: 0, direction: y}]"},
                                m);
  const auto [min1, end1] = tip(m, one);
  std::printf("deepest tip deflection: 3 shapes %.4f m, 1 shape %.4f m; at 20 s %.4f / %.4f m\n", min3, min1, end3,
              end1);
  for (double v : {min3, min1}) {
    EXPECT_LT(v, -0.3);  // the beam lags the acceleration …
    EXPECT_GT(v, -1.0);  // … by a bounded amount
  }
  EXPECT_LT(std::abs(end3), 0.02);  // back near zero at constant speed
  EXPECT_NEAR(min1, min3, 0.05 * std::abs(min3));
  const Simulation soft = spinUp({"bodies.beam.axial_shortening=false"}, m);
  EXPECT_GT(std::abs(tip(m, soft).second), 100.0);  // diverged
}

// The shapes are the exact clamped-free modes: the hub held, the first frequency is the beam's.
TEST(SimulateKaneBeam, ClampedFrequencyIsExact) {
  const LinearModel l = test::linearizeAtEquilibrium(test::loadCase("kane_beam", {"dofs.theta.frozen=true"}));
  const std::vector<Mode> modes = computeModes(l.M, l.C, l.K, l.dof_names);
  test::expectMatchesReference("kane_beam", {{"omega_1", 2 * std::numbers::pi * modes.at(0).freq_hz}});
}

}  // namespace
}  // namespace whirl
