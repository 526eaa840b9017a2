// `simulate` at its default tolerances (1e-6 / 1e-8) against the same motion at 1e-10 / 1e-12: the
// figure of the speed benchmark (bench/bench_simulate.cpp) is that of a result this close to the
// converged one — the structural free decay and the aeroelastic start-up. It guards the reuse of IDA's iteration matrix
// (linearize/ida_block_solver.hpp): a Newton iteration that accepts iterates of a stale matrix integrates something
// else (measured when the convergence test did not reset its rate estimate: blades drifting to hundreds of metres).
#include <gtest/gtest.h>

#include <numbers>

#include "linearize/simulate.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {
namespace {

// The largest difference between two runs over the coordinates and their rates, each against the
// range of its own motion in `tight` (the azimuth: against 1 rad), and the coordinate it is at.
std::pair<double, std::string> worstRelativeDifference(const Model& m, const OperatingPoint& start,
                                                       const Simulation& def, const Simulation& tight) {
  double worst = 0;
  std::string where;
  for (int i : def.states) {
    const bool azimuth = m.dofs[i].rotating;
    const double range = azimuth ? 1.0 : (tight.q.col(i).array() - start.q(i)).abs().maxCoeff();
    const double rate_range = (tight.qd.col(i).array() - (azimuth ? start.qd(i) : 0.0)).abs().maxCoeff();
    const double eq = (def.q.col(i) - tight.q.col(i)).cwiseAbs().maxCoeff() / range;
    const double er = (def.qd.col(i) - tight.qd.col(i)).cwiseAbs().maxCoeff() / rate_range;
    if (std::max(eq, er) > worst) {
      worst = std::max(eq, er);
      where = m.dofs[i].name + (eq >= er ? "" : " rate");
    }
  }
  return {worst, where};
}

// The motion from `start` over t_end at the default tolerances and at 1e-10 / 1e-12.
struct DefaultAndTight {
  Simulation def, tight;
};
DefaultAndTight simulateDefaultAndTight(const Model& m, const OperatingPoint& start, double t_end, double dt_out) {
  SimulationOptions o;
  o.t_end = t_end;
  o.dt_out = dt_out;
  DefaultAndTight r;
  r.def = simulate(m, start, o);
  o.rtol = 1e-10;
  o.atol = 1e-12;
  r.tight = simulate(m, start, o);
  return r;
}

TEST(SimulateToleranceSlow, Nrel5mwDefaultToleranceAgreesWithTightOne) {
  const Model m = readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Onshore.fst");
  OperatingCondition c;
  c.rotor_speed = 12.1 * std::numbers::pi / 30;
  OperatingPoint start = solveOperatingPoint(m, c);
  // The first tower and blade modes displaced (tower top 0.2 m, blade tips 0.5 m): a free decay inside
  // the model's range of validity, the rotor free.
  for (const char* name : {"tower FA 1", "tower SS 1"}) start.q(*m.findDof(name)) += 0.2;
  for (int b = 1; b <= 3; ++b)
    for (const char* shape : {"flap 1", "edge 1"})
      start.q(*m.findDof("blade " + std::to_string(b) + " " + shape)) += 0.5;
  const auto [def, tight] = simulateDefaultAndTight(m, start, 30, 0.05);
  ASSERT_EQ(def.time.size(), tight.time.size());
  const auto [worst, where] = worstRelativeDifference(m, start, def, tight);
  std::printf("default vs tight tolerances over 30 s: worst relative difference %.2e (%s); %ld vs %ld steps\n", worst,
              where.c_str(), def.steps, tight.steps);
  // IDA's tolerances bound the local error per step; over 30 s the global error of the
  // coordinates stays within 3e-4 of their motion (measured 2.1e-4, the rate of tower FA 2, the least
  // excited coordinate; 5009 steps against 23330 at the tight tolerances); 1e-3 leaves room for another
  // step-size history, not for a wrong Newton iteration.
  EXPECT_LT(worst, 1e-3);
}

// The aeroelastic start-up of the speed benchmark (nrel5mwAeroStartup: cases/nrel5mw/Main_Aero.fst,
// the rotor released from rest, BEM re-solved at every residual), its first 150 s (the spin-up through
// the induction's switch-on at tip-speed ratio 1 to 2 and the approach to the final speed), at the
// default tolerances and at 1e-10 / 1e-12.
TEST(SimulateToleranceSlow, AeroStartUpDefaultToleranceAgreesWithTightOne) {
  const Model m = readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Aero.fst");
  OperatingCondition parked;
  parked.rotor_speed = 0;
  const OperatingPoint start = solveOperatingPoint(m, parked);
  const auto [def, tight] = simulateDefaultAndTight(m, start, 150, 0.1);
  ASSERT_EQ(def.time.size(), tight.time.size());
  const auto [worst, where] = worstRelativeDifference(m, start, def, tight);
  double worst_out = 0, nacelle_pitch_acc = 0;
  std::string where_out;
  for (Eigen::Index k = 0; k < tight.y.cols(); ++k) {
    const double range = tight.y.col(k).maxCoeff() - tight.y.col(k).minCoeff();
    const double e = (def.y.col(k) - tight.y.col(k)).cwiseAbs().maxCoeff() / range;
    // The nacelle's angular acceleration about its lateral axis (NcIMURAys, issue 41) is the tower top's
    // rotation twice differentiated: the second fore-aft tower mode (the least excited coordinate, whose
    // rate is the coordinates' worst figure) dominates it. Measured 7.3e-4 of its range; it is held to
    // the coordinates' bound below, the other outputs to theirs.
    if (m.outputs[static_cast<std::size_t>(k)].name == "NcIMURAys") {
      nacelle_pitch_acc = e;
      continue;
    }
    if (range > 0 && e > worst_out) {
      worst_out = e;
      where_out = m.outputs[static_cast<std::size_t>(k)].name;
    }
  }
  std::printf(
      "aero start-up, default vs tight tolerances over 150 s: worst relative difference %.2e (%s), of the "
      "outputs %.2e (%s); %ld vs %ld steps\n",
      worst, where.c_str(), worst_out, where_out.c_str(), def.steps, tight.steps);
  // Over 600 s (the benchmark's run, whirl simulate … --out, compared by channel): 7.7e-5 of the
  // outputs' ranges (the tower-top accelerations), 3e-8 or less for the rotor speed and power; the
  // difference builds up in the spin-up, the first 150 s hold it all. The coordinates' figure is the
  // least excited one's (the rate of the second tower mode, measured 1.5e-3). A looser absolute
  // tolerance shows here: --atol 1e-6 gives 4.6e-3 of the tower-top side acceleration's range
  // (measured over these 150 s; README, Speed: work and precision).
  EXPECT_LT(worst, 1e-2);
  EXPECT_LT(nacelle_pitch_acc, 1e-2);
  EXPECT_LT(worst_out, 5e-4);
}

}  // namespace
}  // namespace whirl
