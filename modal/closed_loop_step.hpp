#pragma once
/// \file
/// The linear closed loop checked against the nonlinear turbine with its controller (issue 43, item 6;
/// what `whirl verify` does for the open loop): from the steady state a ROSCO controller settles at, a
/// small wind step simulated twice — the nonlinear equations with ROSCO's discrete laws in the loop
/// (linearize/rosco_step.hpp) and the linear closed loop (modal/closed_loop_modes.hpp, the continuous
/// controller) by RK4 — and the responses compared output by output.
///
/// The linear model is linearized with quasi-steady induction (the simulation's BEM solves the
/// induction at every step; a frozen wake would not match it) and averaged over the azimuths, so the
/// nonlinear response's blade-passing ripple and the discrete controller's sampling are what separate
/// the two besides the nonlinearity.
#include <string>
#include <vector>

#include "linearize/trim.hpp"
#include "src/model/rosco_controller.hpp"

namespace whirl {

struct ClosedLoopStepOptions {
  double wind_step = 0.1;       ///< [m/s]
  double step_time = 1;         ///< [s]
  double t_end = 12;            ///< [s]
  double dt_out = 0.05;         ///< sampling of the compared responses [s]
  double controller_dt = 0.01;  ///< ROSCO's sampling in the nonlinear simulation [s]
  int azimuths = 12;            ///< of the linear model's multiblade average
  /// The "first swing" window after the step: the differences are also reported up to
  /// step_time + early_window [s].
  double early_window = 4.5;
  /// Plant outputs compared, besides the controller's pitch command (names of Model::outputs).
  std::vector<std::string> outputs = {"GenSpeed", "TTDspFA"};
};

/// One compared signal: the change from the steady value, nonlinear and linear, at ClosedLoopStep::time.
struct ClosedLoopStepSignal {
  std::string name, unit;
  std::vector<double> nonlinear, linear;
  double peak = 0;              ///< max |linear|
  double max_difference = 0;    ///< max |nonlinear − linear| over the whole run
  double early_difference = 0;  ///< the same up to step_time + early_window
};

struct ClosedLoopStep {
  std::vector<double> time;                   ///< [s]
  std::vector<ClosedLoopStepSignal> signals;  ///< the outputs asked for, then "collective pitch" [rad]
};

/// \param steady a point trimmed with `controller` (SteadyState::region set).
/// \throws InputError for an output the model does not have, options out of range, or a controller
/// mode the time step does not run (rosco_step.hpp); ComputeError when the simulation fails.
ClosedLoopStep closedLoopStep(const Model& model, const RoscoController& controller, const SteadyState& steady,
                              const ClosedLoopStepOptions& opt = {});

}  // namespace whirl
