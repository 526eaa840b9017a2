// The pre-bent beam of [Branlard2019, §5.4] (cases/prebent_beam): Kane's spin-up with the beam bent
// along the rotation axis, z0 = −0.5 [1 − cos(πx/2L)] m. The centrifugal load pulls the tip towards
// the plane of rotation — the seed: "from its initial pre-bended position of −0.5 m to about −0.13 m"
// (BeamDyn and its Rayleigh–Ritz model, read off a figure) — through the axial motion a bent curved
// beam makes (src/shapes/beam.cpp, meanLineAxialMotion). Independent check: the same beam as a
// geometrically exact chain of rigid bars along the pre-bent line with torsion springs about their
// flap axes, at rest in the pre-bent shape (Huston and Wang's lumped segments, as for
// test_simulate_kane_chain.cpp), its steady deflection at 6 rad/s.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "linearize/simulate.hpp"
#include "src/dynamics/outputs.hpp"
#include "tests/support/kane_spin_up.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

constexpr double kLength = 10, kEI = 14000, kMassPerLength = 1.2, kSpeed = 6;  // [m, N m², kg/m, rad/s]

double prebend(double x) { return -0.5 * (1 - std::cos(x / kLength * std::numbers::pi / 2)); }

// N bars with their nodes on (x_i, z0(x_i)), x_i = iL/N, each carrying the beam's mass between its
// nodes (m L/N) as a uniform bar; flap joints about body y with springs EI/Δ (2 EI/Δ at the clamp)
// at rest at the pre-bend angles.
std::string flapChainYaml(int n) {
  const double d = kLength / n;
  std::ostringstream y;
  y.precision(17);
  y << "name: prebent_chain\ngravity: 0\nbodies:\n"
    << "  - {name: hub, type: rigid, mass: 0, joint: {type: revolute, axis: [0, 0, 1], dof: theta}}\n";
  std::vector<double> rest(n + 1);
  double before = 0;
  for (int i = 1; i <= n; ++i) {
    const double dz = prebend(i * d) - prebend((i - 1) * d), len = std::hypot(d, dz);
    const double angle = std::atan2(dz, d), mass = kMassPerLength * d, j = mass * len * len / 12;
    rest[i] = -(angle - before);  // about +y, a positive angle turns x towards −z
    before = angle;
    y << "  - {name: bar" << i
      << ", type: rigid, parent: " << (i == 1 ? std::string("hub") : "bar" + std::to_string(i - 1));
    if (i > 1) y << ", at: end";
    y << ", joint: {type: revolute, axis: [0, 1, 0], dof: a" << i << "}, mass: " << mass << ", cog: [" << len / 2
      << ", 0, 0], inertia: [0, " << j << ", " << j << "], points: [{name: end, position: [" << len << ", 0, 0]}]}\n";
  }
  y << "loads:\n";
  for (int i = 1; i <= n; ++i)
    y << "  - {type: spring, dof: a" << i << ", k: " << (i == 1 ? 2 : 1) * kEI / d << ", q0: " << rest[i] << "}\n";
  y << "outputs:\n  - {name: tip flapwise, type: point, body: bar" << n
    << ", point: end, direction: [0, 0, 1], frame: hub, unit: m}\ndofs:\n  theta: {frozen: true}\n";
  for (int i = 1; i <= n; ++i) y << "  a" << i << ": {value: " << rest[i] << "}\n";
  return y.str();
}

Model flapChain(int n) {
  const auto path = std::filesystem::path(::testing::TempDir()) / ("prebent_chain_" + std::to_string(n) + ".yaml");
  std::ofstream(path) << flapChainYaml(n);
  return readCase(path.string());
}

// The tip's flapwise position at the equilibrium of the hub turning at `speed`.
double steadyTip(const Model& m, double speed) {
  OperatingPoint op = initialPoint(m);
  op.qd(*m.findDof("theta")) = speed;
  const OperatingPoint eq = solveOperatingPoint(m, op);
  Workspace<double> ws(m);
  VecX y(m.noutput());
  evaluateOutputs(m, ws, eq.q, eq.qd, eq.qdd, y, &eq.u);
  return y(*m.findOutput("tip flapwise"));
}

Model beamAtRest() { return test::loadCase("prebent_beam", {"dofs.theta.frozen=true"}); }

TEST(SimulatePrebentBeam, AtRestTheTipIsAtThePrebend) {
  const Model chain = flapChain(20);
  EXPECT_NEAR(steadyTip(chain, 0), -0.5, 1e-12);
  EXPECT_NEAR(steadyTip(beamAtRest(), 0), -0.5, 1e-12);
}

// Turning at 6 rad/s: the Rayleigh–Ritz beam (3 flap shapes of the straight beam) against the chain
// extrapolated to N → ∞ from N = 40 and 80, and against the seed's "about −0.13 m".
TEST(SimulatePrebentBeam, CentrifugalStraighteningMatchesTheChain) {
  const double c40 = steadyTip(flapChain(40), kSpeed), c80 = steadyTip(flapChain(80), kSpeed);
  const double chain = c80 + (c80 - c40) / 3;
  const double beam = steadyTip(beamAtRest(), kSpeed);
  std::printf("tip flapwise at 6 rad/s: chain N = 40 %.5f, 80 %.5f, extrapolated %.5f m; beam %.5f m\n", c40, c80,
              chain, beam);
  EXPECT_NEAR(c80, chain, 5e-4);           // the reference is converged
  EXPECT_NEAR(beam, chain, 0.002 * 0.37);  // 0.2 % of the tip's travel (0.37 m); measured 0.09 %
  EXPECT_NEAR(beam, -0.13, 0.005);         // [Branlard2019, §5.4]: "to about −0.13 m" (two decimals)
}

// The spin-up itself: starts at the pre-bend and ends, at constant speed, at the steady deflection.
TEST(SimulatePrebentBeam, SpinUpSettlesAtTheSteadyDeflection) {
  const Model m = test::loadCase("prebent_beam");
  const Simulation sim = test::kaneSpinUp(m);
  const VecX tip = sim.y.col(*m.findOutput("tip flapwise"));
  const double steady = steadyTip(beamAtRest(), kSpeed);
  std::printf("tip flapwise: %.4f m at 0 s, %.4f m at 20 s, steady %.4f m\n", tip(0), tip(tip.size() - 1), steady);
  EXPECT_NEAR(tip(0), -0.5, 1e-9);
  EXPECT_NEAR(tip(tip.size() - 1), steady, 0.005);
}

}  // namespace
}  // namespace whirl
