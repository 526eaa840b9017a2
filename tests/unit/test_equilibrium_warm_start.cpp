// The equilibrium solver's warm starts (linearize/operating_point.hpp): the residual and blade-element
// record it returns are those of its solution, a start from a neighbouring condition's equilibrium
// keeps the cold start's tolerance, and chord steps with a neighbour's Newton matrix reach the same
// equilibrium. Cross-checked against an independent evaluation and against cold solves.
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "linearize/operating_point.hpp"
#include "linearize/periodic.hpp"
#include "src/dynamics/residual.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/support/aero_rotor_model.hpp"

namespace whirl {
namespace {

// The rotor at `wind` [m/s], every coordinate at its undeflected value (the cold start).
OperatingPoint coldStart(const Model& m, double wind) {
  OperatingCondition c;
  c.rotor_speed = m.dofs[*m.findDof("azimuth")].rate;
  c.wind_speed = wind;
  c.azimuth = 0.3;
  return initialPoint(m, c);
}

// The deflections of `from` on the solved coordinates of `to`'s cold start.
OperatingPoint warmStart(const OperatingPoint& cold, const OperatingPoint& from) {
  OperatingPoint w = cold;
  for (int i : from.solved) w.q(i) = from.q(i);
  return w;
}

TEST(EquilibriumWarmStart, SolutionCarriesItsResidualAndElementRecord) {
  const Model m = test::aeroRotorModel();
  const OperatingPoint op = solveOperatingPoint(m, coldStart(m, 9.0));
  ASSERT_GT(op.iterations, 0);
  // An independent evaluation at the solution, with a fresh workspace (no BEM roots to start from).
  Workspace<double> ws(m);
  VecX e(m.ndof());
  AeroRecord rec;
  residual(m, ws, op.q, op.qd, op.qdd, op.u, e, nullptr, &rec);
  ASSERT_EQ(op.e.size(), e.size());
  // The BEM roots agree to the root finder's tolerance (|R| < 1e-13), the loads to ~1e-12 relative.
  const double scale = e.cwiseAbs().maxCoeff();
  EXPECT_LT((op.e - e).cwiseAbs().maxCoeff(), 1e-10 * scale);
  ASSERT_EQ(op.aero.elements.size(), rec.elements.size());
  for (std::size_t k = 0; k < rec.elements.size(); ++k) {
    EXPECT_NEAR(op.aero.elements[k].phi, rec.elements[k].phi, 1e-11) << "element " << k;
    EXPECT_NEAR(op.aero.elements[k].fx, rec.elements[k].fx, 1e-9 * std::abs(rec.elements[k].fx) + 1e-9) << k;
  }
  EXPECT_NEAR(op.aero.thrust, rec.thrust, 1e-10 * std::abs(rec.thrust));
  EXPECT_NEAR(op.aero.torque, rec.torque, 1e-10 * std::abs(rec.torque));
  EXPECT_EQ(op.inflow.axial.size(), static_cast<Eigen::Index>(rec.elements.size()));
}

TEST(EquilibriumWarmStart, NeighbourStartKeepsTheColdToleranceAndFindsTheSameEquilibrium) {
  const Model m = test::aeroRotorModel();
  EquilibriumOptions first;
  MatX newton;
  first.newton_matrix = &newton;
  const OperatingPoint at8 = solveOperatingPoint(m, coldStart(m, 8.0), first);
  ASSERT_EQ(newton.rows(), static_cast<Eigen::Index>(at8.solved.size()));

  const OperatingPoint cold9 = coldStart(m, 9.0);
  const OperatingPoint ref = solveOperatingPoint(m, cold9);
  for (bool chord : {false, true}) {
    EquilibriumOptions warm;
    warm.scale_from = &cold9;
    if (chord) warm.chord_matrix = &newton;
    const OperatingPoint op = solveOperatingPoint(m, warmStart(cold9, at8), warm);
    // The tolerance's reference is the cold start's residual, not the (much smaller) warm start's.
    EXPECT_NEAR(op.load_scale, ref.load_scale, 1e-12 * ref.load_scale) << "chord " << chord;
    EXPECT_LT(op.residual_norm, 1e-10 * ref.load_scale * std::sqrt(op.solved.size())) << "chord " << chord;
    // Both solutions satisfy |e| < 1e-10 of the load scale; the stiffness turns that into ~1e-10 of a
    // deflection of ~1 (flap, edge tip deflections of the 40 m blade at 9 m/s).
    for (int i : ref.solved) EXPECT_NEAR(op.q(i), ref.q(i), 1e-8 * (1 + std::abs(ref.q(i)))) << m.dofs[i].name;
  }
  // Without scale_from the warm start's own residual would be the reference: a tighter solve, which
  // shows that the option is what keeps the cold tolerance.
  const OperatingPoint own = solveOperatingPoint(m, warmStart(cold9, at8));
  EXPECT_LT(own.load_scale, 0.5 * ref.load_scale);
}

// A periodic linearization whose first azimuth starts at a trim's equilibrium (PeriodicOptions::
// deflections, what a trimmed sweep point carries) needs no iteration there, keeps the cold start's
// tolerance and gives the cold start's linear models.
TEST(EquilibriumWarmStart, PeriodicLinearizationFromATrimmedEquilibrium) {
  const Model m = test::aeroRotorModel();
  const OperatingPoint cold = coldStart(m, 9.0);
  const OperatingPoint solved = solveOperatingPoint(m, cold);
  PeriodicOptions opt;
  opt.azimuths = 4;
  const PeriodicLinearization ref = linearizePeriodic(m, cold, opt);
  opt.deflections = &solved.q;
  const PeriodicLinearization warm = linearizePeriodic(m, cold, opt);
  EXPECT_GT(ref.points.front().iterations, 0);
  EXPECT_EQ(warm.points.front().iterations, 0);
  EXPECT_NEAR(warm.points.front().load_scale, ref.points.front().load_scale, 1e-12 * ref.points.front().load_scale);
  ASSERT_EQ(warm.models.size(), ref.models.size());
  for (std::size_t k = 0; k < ref.models.size(); ++k) {
    // Two equilibria within the solver's tolerance (1e-10 of the load scale): K and C agree to ~1e-9.
    const double scale = ref.models[k].K.cwiseAbs().maxCoeff();
    EXPECT_LT((warm.models[k].K - ref.models[k].K).cwiseAbs().maxCoeff(), 1e-8 * scale) << "azimuth " << k;
    EXPECT_LT((warm.models[k].C - ref.models[k].C).cwiseAbs().maxCoeff(), 1e-8 * ref.models[k].C.cwiseAbs().maxCoeff())
        << "azimuth " << k;
  }
}

// Each azimuth of a periodic sweep starts from the previous ones extrapolated along the revolution
// (mean and first two harmonics, linearize/periodic.cpp) and takes chord steps with the previous
// azimuth's stiffness (inverted once, Broyden-updated by Sherman–Morrison): the equilibria of cold
// Newton solves at the same azimuths, on the aeroelastic NREL 5MW at 8 m/s and 9 rpm.
TEST(EquilibriumWarmStart, PeriodicGuessFollowsTheHarmonicsOfTheRevolution) {
  const Model m = readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Aero.fst");
  OperatingCondition c;
  c.wind_speed = 8.0;
  c.rotor_speed = 9.0 * std::numbers::pi / 30;
  c.collective_pitch = 0.0;
  const OperatingPoint cold = initialPoint(m, c);
  PeriodicOptions opt;
  opt.azimuths = 36;
  const PeriodicLinearization p = linearizePeriodic(m, cold, opt);
  for (std::size_t k = 1; k < p.points.size(); ++k) EXPECT_GT(p.points[k].iterations, 0) << "azimuth " << k;
  for (std::size_t k : {5u, 17u, 30u}) {
    OperatingPoint at = cold;
    at.q(p.azimuth_dof) = p.azimuths[k];
    const OperatingPoint ref = solveOperatingPoint(m, at);
    for (int i : ref.solved) EXPECT_NEAR(p.points[k].q(i), ref.q(i), 1e-8 * (1 + std::abs(ref.q(i)))) << m.dofs[i].name;
  }
}

}  // namespace
}  // namespace whirl
