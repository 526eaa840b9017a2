// Issue 43, item 6: the NREL 5MW with ROSCO's controller in the loop of the nonlinear simulation
// (linearize/rosco_step.hpp: ROSCO's discrete laws every 0.01 s, quasi-steady BEM) against the linear
// closed loop (linearize/rosco_linear.hpp, the continuous controller; quasi-steady induction to match the
// simulation's BEM, multiblade average over 12 azimuths) for a small wind step at 14 m/s (0.1 m/s at 1 s).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "linearize/rosco_linear.hpp"
#include "linearize/rosco_step.hpp"
#include "linearize/simulate.hpp"
#include "linearize/trim.hpp"
#include "modal/closed_loop_modes.hpp"
#include "src/io/discon_input.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/support/test_paths.hpp"

namespace whirl {
namespace {

int indexOf(const std::vector<StateSpaceVariable>& v, const std::string& name) {
  for (size_t i = 0; i < v.size(); ++i)
    if (v[i].name == name) return static_cast<int>(i);
  ADD_FAILURE() << name;
  return 0;
}

TEST(ClosedLoopSimulationSlow, WindStepAgreesWithTheLinearClosedLoop) {
  const std::string deck = std::string(whirl_test_paths::sourceDir()) + "/cases/nrel5mw/Main_ROSCO.fst";
  const Model m = readElastoDynModel(deck);
  const RoscoController c = *io::readDeckController(deck, {});
  TrimOptions trim;
  trim.controller = &c;
  const SteadyState st = trimAtWindSpeed(m, 14, trim);
  OperatingCondition cond = st.condition;
  cond.generator_torque = st.generator_torque;
  const OperatingPoint start = solveOperatingPoint(m, initialPoint(m, cond));

  const double step = 0.1, t0 = 1, t_end = 12;  // m/s, s
  SimulationOptions so;
  so.t_end = t_end;
  so.dt_out = 0.05;
  TimeSignal wind;
  wind.kind = TimeSignal::Kind::Step;
  wind.parameters = {t0, step};
  so.inputs.push_back({m.roles.wind_speed_input, wind});
  so.controller = roscoInTheLoop(m, c, st, 0.01, start);
  const Simulation sim = simulate(m, start, so);

  ClosedLoopOptions lo;
  lo.azimuths = 12;
  lo.frozen_wake = false;
  const StateSpaceModel cl = closedLoopPoint(m, st, linearRosco(c, st), lo).closed;
  const int iw = indexOf(cl.u, "wind speed"), ig = indexOf(cl.y, "GenSpeed"), ip = indexOf(cl.y, "controller: collective pitch");
  int gen = 0;
  for (size_t i = 0; i < m.outputs.size(); ++i)
    if (m.outputs[i].name == "GenSpeed") gen = static_cast<int>(i);
  const int pitch_in = so.controller.inputs[1];

  // The linear response by RK4 (h = 1 ms against the fastest root's 40 rad/s) to the same step.
  VecX x = VecX::Zero(cl.A.rows());
  const double h = 1e-3;
  double t = 0, err_speed = 0, err_pitch = 0, peak_speed = 0, peak_pitch = 0, early_speed = 0, early_pitch = 0;
  for (size_t k = 0; k < sim.time.size(); ++k) {
    for (; t < sim.time[k] - 1e-12; t += h) {
      const double u = t >= t0 ? step : 0;
      auto f = [&](const VecX& z) -> VecX { return cl.A * z + cl.B.col(iw) * u; };
      const VecX k1 = f(x), k2 = f(x + h / 2 * k1), k3 = f(x + h / 2 * k2), k4 = f(x + h * k3);
      x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    const double lin_speed = cl.C.row(ig).dot(x), lin_pitch = cl.C.row(ip).dot(x);
    const double nl_speed = sim.y(static_cast<Eigen::Index>(k), gen) - sim.y(0, gen);
    const double nl_pitch = sim.u(static_cast<Eigen::Index>(k), pitch_in) - sim.u(0, pitch_in);
    peak_speed = std::max(peak_speed, std::abs(lin_speed));
    peak_pitch = std::max(peak_pitch, std::abs(lin_pitch));
    err_speed = std::max(err_speed, std::abs(nl_speed - lin_speed));
    err_pitch = std::max(err_pitch, std::abs(nl_pitch - lin_pitch));
    if (sim.time[k] <= 5.5) {
      early_speed = std::max(early_speed, std::abs(nl_speed - lin_speed));
      early_pitch = std::max(early_pitch, std::abs(nl_pitch - lin_pitch));
    }
  }
  std::printf("peak speed %.4g rad/s, difference %.4g (to 5.5 s %.4g); peak pitch %.4g rad, difference %.4g (%.4g)\n",
              peak_speed, err_speed, early_speed, peak_pitch, err_pitch, early_pitch);
  // Measured: speed 0.285 rad/s peak, the two apart by 0.044 over 11 s and 0.021 up to 5.5 s;
  // pitch 6.0e-3 rad, 7.6e-4 and 1.6e-4. The rise and the first swing agree to 7 %; later the linear
  // loop's lightly damped rotor-speed pair (ζ ≈ 0.12 at 0.18 Hz) rings longer than the nonlinear one,
  // whose 3P ripple (±0.006 rad/s before the step) and discrete controller (0.01 s) are not in the
  // multiblade-averaged continuous model.
  EXPECT_LT(early_speed, 0.08 * peak_speed);
  EXPECT_LT(early_pitch, 0.08 * peak_pitch);
  EXPECT_LT(err_speed, 0.2 * peak_speed);
  EXPECT_LT(err_pitch, 0.2 * peak_pitch);

}

}  // namespace
}  // namespace whirl
