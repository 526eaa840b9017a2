// The blade elements' unsteady-airfoil (UA_Mod 4) and dynamic-inflow (DBEMT_Mod 3) states in the time
// simulation (linearize/simulate_aero.hpp, issue 47 item 5), on the one-blade NREL 5MW rotor of OpenFAST's
// r-test Fake5MW_AeroLin_B1_UA4_DBEMT3 (flap DOF, UA states on elements 2-4; tests/data/openfast-lin/ua4-dbemt3),
// parked (RotSpeed 0) and pitched to 75° (angles of attack 6-15° on the UA elements): turning, the deflected
// blade's sections pitch at a steady rate (the rotor's rotation about their tilted span axis, up to 0.24
// rad/s at 12.1 rpm), which the UA loads see (α at 3/4 chord) and the quasi-steady equilibrium does not, so
// that equilibrium is no steady state of the UA equations (2 % of the flap load); parked it is one.
#include <gtest/gtest.h>

#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "linearize/simulate.hpp"
#include "linearize/simulate_aero.hpp"
#include "linearize/unsteady_aero.hpp"
#include "src/dynamics/aero_unsteady.hpp"
#include "src/dynamics/residual.hpp"
#include "src/turbine/load_model.hpp"

namespace {

using namespace whirl;

Model parkedRotor(std::vector<std::string> sets = {}) {
  const std::string deck = (std::filesystem::path(WHIRL_SOURCE_DIR) /
                            "tests/data/openfast-lin/ua4-dbemt3/case/Fake5MW_AeroLin_B1_UA4_DBEMT3.fst")
                               .string();
  for (const char* s : {"RotSpeed=0", "BlPitch(1)=75"}) sets.push_back(s);
  return loadCaseModel(deck, sets);
}

SimulationOptions aeroStates(double t_end, double dt_out, const Model& m) {
  SimulationOptions so;
  so.t_end = t_end;
  so.dt_out = dt_out;
  so.rtol = 1e-9;
  so.atol = 1e-11;
  so.prescribed = m.roles.azimuth;  // the rotor turns at its constant speed
  so.aero_states = true;
  return so;
}

int flapDof(const Model& m) {
  const auto i = m.findDof("blade 1 flap 1");
  EXPECT_TRUE(i.has_value());
  return i.value_or(0);
}

// Simulated from its steady state, the parked blade stays there: the loads with the states at their steady
// values equal the quasi-steady ones but for the HGM model's reconstruction of the static polar from the
// separation function (0.9 N of 7.9 kN on the flap, 1.1e-4), their rates vanish, and over 0.5 s the flap
// moves by 6.9e-5 m of its 0.51 m deflection and the states by 8.1e-5 (of up to 14.4): not the first step
// of a motion away from the start. Fails when the states start elsewhere
// or their loads are added to the quasi-steady ones instead of replacing them (states started at zero: the
// flap moves by 0.25 m in 0.5 s).
TEST(SimulateAeroStates, SteadyStateIsAFixedPoint) {
  for (const bool dbemt : {true, false}) {
    Model m = parkedRotor();
    if (!dbemt) removeDynamicInflow(m.aero);
    ASSERT_EQ(uaStateCount(m.aero), 12);
    const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
    const SimulationOptions so = aeroStates(0.5, 0.1, m);
    const VecX z0 = unsteadyAeroSteadyStates(m, op);
    const int flap = flapDof(m);
    {  // the start: loads and rates
      Workspace<double> ws(m);
      AeroRecord record;
      VecX e(m.ndof()), zdot(z0.size());
      residual(m, ws, op.q, op.qd, op.qdd, op.u, e, nullptr, &record);
      AeroStateLoads b(m);
      addAeroStateLoads(m, ws, op.q, op.qd, op.u, record.inflow(), AeroInflow{}, z0, b, e, zdot);
      VecX e_qs = VecX::Zero(m.ndof());
      addUnsteadyAeroLoads<double>(m, ws, op.q, op.qd, op.u, record.inflow(), nullptr, e_qs, nullptr);
      EXPECT_LT(std::abs(b.delta(flap)), 2e-4 * std::abs(e_qs(flap))) << dbemt;
      EXPECT_LT(zdot.cwiseAbs().maxCoeff(), 1e-12) << dbemt;
    }
    const Simulation sim = simulate(m, op, so);
    ASSERT_EQ(sim.z.cols(), aeroStateCount(m.aero)) << dbemt;
    EXPECT_EQ(sim.z.cols(), dbemt ? 12 + 4 * m.aero.nstations() : 12);
    EXPECT_LT((sim.z.row(0).transpose() - z0).cwiseAbs().maxCoeff(), 1e-14 * std::max(1.0, z0.cwiseAbs().maxCoeff()));
    for (Eigen::Index k = 0; k < sim.q.rows(); ++k) {
      EXPECT_LT(std::abs(sim.q(k, flap) - op.q(flap)), 2e-4 * std::abs(op.q(flap)))
          << "dbemt " << dbemt << " t " << sim.time[k];
      EXPECT_LT((sim.z.row(k).transpose() - z0).cwiseAbs().maxCoeff(), 1e-4 * std::max(1.0, z0.cwiseAbs().maxCoeff()))
          << "dbemt " << dbemt << " t " << sim.time[k];
    }
  }
}

// max over the record of |Δflap(t) − x_flap(t)|, Δflap the perturbed run minus the unperturbed one (which
// drifts as the steady-state test measures), x(t) = exp(A t) x0 the linear response.
double flapDifference(const Simulation& sim, const Simulation& base, int flap, const LinearModel& lin, const VecX& x0) {
  const auto j = std::find(lin.dofs.begin(), lin.dofs.end(), flap) - lin.dofs.begin();
  double worst = 0;
  for (std::size_t k = 0; k < sim.time.size(); ++k) {
    const VecX x = (lin.A * sim.time[k]).exp() * x0;
    const auto r = static_cast<Eigen::Index>(k);
    worst = std::max(worst, std::abs(sim.q(r, flap) - base.q(r, flap) - x(j)));
  }
  return worst;
}

struct FlapRelease {
  double with_states = 0, quasi_steady = 0, response = 0;
};

// The flap released from the equilibrium + ε: the nonlinear response with the aerodynamic states against
// the linear model with them (x0: the flap's ε and the states' steady values at the released flap minus
// the equilibrium's) and against the quasi-steady linear model (frozen wake, no states).
FlapRelease releaseFlap(const Model& m, double eps) {
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  const int flap = flapDof(m);
  OperatingPoint start = op;
  start.q(flap) += eps;
  SimulationOptions so = aeroStates(3, 0.02, m);
  so.frozen_inflow = op.inflow;  // the linear model's frozen wake
  const Simulation sim = simulate(m, start, so), base = simulate(m, op, so);
  const LinearModel ua = linearize(m, op);
  LinearizeOptions qs_options;
  qs_options.unsteady_aero = false;
  const LinearModel qs = linearize(m, op, qs_options);
  const int n = static_cast<int>(ua.dofs.size());
  EXPECT_EQ(ua.A.rows(), 2 * n + aeroStateCount(m.aero));
  const auto j = std::find(ua.dofs.begin(), ua.dofs.end(), flap) - ua.dofs.begin();
  VecX x0 = VecX::Zero(ua.A.rows()), x0_qs = VecX::Zero(qs.A.rows());
  x0(j) = x0_qs(j) = eps;
  x0.tail(ua.A.rows() - 2 * n) = simulationAeroStart(m, start, so) - ua.first_order_values;
  FlapRelease r;
  r.with_states = flapDifference(sim, base, flap, ua, x0);
  r.quasi_steady = flapDifference(sim, base, flap, qs, x0_qs);
  for (Eigen::Index k = 0; k < sim.q.rows(); ++k)
    r.response = std::max(r.response, std::abs(sim.q(k, flap) - op.q(flap)));
  return r;
}

// The linear model with the UA states predicts the nonlinear response with them: 30–45 times closer than the
// quasi-steady linear model, whose error is of first order in ε (the UA states' own dynamics it leaves out;
// measured 2.11e-2 and 1.07e-2 at ε = 0.1 and 0.05 m, the flap response's amplitude ε). The model with the
// states differs by 6.3e-4 and 2.5e-4 (order 1.3, not 2: the quasi-steady equilibrium is the UA one only to
// the 1.1e-4 of the test above). Fails when the simulation drops the states (its response is then the
// quasi-steady one) or integrates other equations than the linear model's.
TEST(SimulateAeroStates, LinearModelWithStatesPredictsTheNonlinearResponse) {
  Model m = parkedRotor();
  removeDynamicInflow(m.aero);  // the UA states alone (no induction on the parked rotor either way)
  const FlapRelease big = releaseFlap(m, 0.1), small = releaseFlap(m, 0.05);
  EXPECT_LT(big.with_states, 0.05 * big.quasi_steady);
  EXPECT_LT(small.with_states, 0.05 * small.quasi_steady);
  EXPECT_GT(std::log2(big.with_states / small.with_states), 1.1);
  EXPECT_LT(std::abs(std::log2(big.quasi_steady / small.quasi_steady) - 1), 0.1);  // first order
  EXPECT_NEAR(big.response, 0.1, 1e-3);
}

// The simulation's load outputs take the loads of the states, as its equations of motion do: with the flap
// released by 0.1 m (the UA states then lag the angle of attack), RtAeroMxh at every recorded instant equals
// the azimuth's generalized force of the states' loads (Kane's projection of the elements' loads, an
// independent sum from the output's r × F about the apex) to 1e-9 of the largest torque. The test also
// requires the states' loads to differ from the quasi-steady ones somewhere in the record by over 0.5 % of the
// largest torque (measured 7.19 kN m of 898 kN m, 0.80 %), so it fails when the recorder evaluates quasi-steady
// loads (as it did before: the mismatch was then that 0.80 %).
TEST(SimulateAeroStates, LoadOutputsTakeTheStatesLoads) {
  Model m = parkedRotor();
  removeDynamicInflow(m.aero);
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  OperatingPoint start = op;
  start.q(flapDof(m)) += 0.1;
  const Simulation sim = simulate(m, start, aeroStates(1.0, 0.05, m));
  const auto torque = std::find_if(m.outputs.begin(), m.outputs.end(),
                                   [](const Output& o) { return o.name == "RtAeroMxh"; });
  ASSERT_NE(torque, m.outputs.end());
  const auto col = static_cast<Eigen::Index>(torque - m.outputs.begin());
  ASSERT_EQ(m.roles.azimuth.size(), 1u);
  const int azimuth = m.roles.azimuth.front();
  const VecX qdd = VecX::Zero(m.ndof());  // the loads do not depend on it
  std::vector<double> recorded, with_states, quasi_steady;
  for (Eigen::Index k = 0; k < sim.q.rows(); ++k) {
    const VecX q = sim.q.row(k).transpose(), qd = sim.qd.row(k).transpose(), u = sim.u.row(k).transpose();
    const VecX z = sim.z.row(k).transpose();
    Workspace<double> ws(m);
    AeroRecord record;
    VecX e(m.ndof()), e_ua = VecX::Zero(m.ndof()), e_qs = VecX::Zero(m.ndof()), diff = VecX::Zero(m.ndof());
    residual(m, ws, q, qd, qdd, u, e, nullptr, &record);
    const AeroInflow inflow = record.inflow();
    addUnsteadyAeroLoads<double>(m, ws, q, qd, u, inflow, &z, e_ua, nullptr);
    addUnsteadyAeroLoads<double>(m, ws, q, qd, u, inflow, nullptr, e_qs, nullptr);
    // The one-pass difference the simulation adds equals the two passes' (elements without states skipped).
    addUnsteadyAeroLoads<double>(m, ws, q, qd, u, inflow, &z, diff, nullptr, nullptr, nullptr, -1, true);
    EXPECT_LT((diff - (e_ua - e_qs)).norm(), 1e-12 * e_ua.norm()) << "step " << k;
    recorded.push_back(sim.y(k, col));
    with_states.push_back(e_ua(azimuth));
    quasi_steady.push_back(e_qs(azimuth));
  }
  double scale = 0, lag = 0, mismatch = 0;
  for (std::size_t k = 0; k < recorded.size(); ++k) {
    scale = std::max(scale, std::abs(with_states[k]));
    lag = std::max(lag, std::abs(with_states[k] - quasi_steady[k]));
    mismatch = std::max(mismatch, std::abs(recorded[k] - with_states[k]));
  }
  ASSERT_GT(scale, 0);
  EXPECT_GT(lag, 5e-3 * scale) << "states' loads minus quasi-steady: " << lag << " of " << scale << " N m";
  EXPECT_LT(mismatch, 1e-9 * scale) << "RtAeroMxh minus the azimuth's generalized force: " << mismatch << " of "
                                    << scale << " N m; lag " << lag;
}

}  // namespace
