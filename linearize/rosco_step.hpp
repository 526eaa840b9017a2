#pragma once
/// \file
/// ROSCO's controller as it runs in time (src/model/rosco_controller.hpp's parameters), one call per
/// controller step: the generator-speed low pass, the gain-scheduled pitch PI (PC_ControlMode 1) and the
/// TSR-tracking torque PI with its constant-power or constant-torque limit above rated
/// (VS_ControlMode 2), with ROSCO's saturations and anti-windup (Functions.f90, PIController: the
/// integral term clipped to the output's limits), the minimum-pitch schedule (PS_Mode) and the pitch
/// and torque rate limits (Controllers.f90, ControllerBlocks.f90). Filters are discretized exactly
/// for a held input (ROSCO: Tustin, the same to O(ω dt)²). The wind-speed estimate is the wind
/// (a perfect estimator), the setpoint smoother is left out, as in the linear model
/// (linearize/rosco_linear.hpp). The floating feedback (Fl_Mode 1, 2) runs the linear model's filter
/// chain on the tower-top velocity or the nacelle pitch rate (linearize/closed_loop.hpp: ROSCO's
/// integral of the filtered acceleration), discretized by Tustin's rule at the step, as ROSCO's filters.
#include "linearize/simulate.hpp"
#include "linearize/trim.hpp"
#include "src/model/rosco_controller.hpp"

namespace whirl {

/// The controller's memory between calls.
struct RoscoState {
  double speed = 0;            ///< filtered generator speed ω_f [rad/s]
  double reference = 0;        ///< the torque loop's low-passed TSR reference, before its limits [rad/s]
  double pitch_integral = 0;   ///< ROSCO's ITerm of the pitch PI [rad]
  double torque_integral = 0;  ///< ITerm of the torque PI [N m]
  double pitch = 0;            ///< the last pitch command [rad] (schedules the gains, rate limit)
  double torque = 0;           ///< the last torque command [N m]
  /// Floating feedback (Fl_Mode > 0): the filter chain x⁺ = A_d x + B_d (v + v⁻)/2, its pitch
  /// δθ = C x + D v, and the last velocity v⁻.
  MatX fl_A;
  VecX fl_B, fl_C, fl_x;
  double fl_D = 0, fl_last = 0;
};

struct RoscoCommand {
  double torque = 0;  ///< generator torque [N m]
  double pitch = 0;   ///< collective pitch [rad]
};

/// The memory at a steady state trimmed with `c` (every error zero, integrators at the commands).
/// \throws InputError naming the file for what this step does not model (VS_ControlMode other than 2,
/// F_LPFType 2, notch filters, PA_Mode > 0). `dt` [s] discretizes the floating feedback's filters.
RoscoState roscoSteadyMemory(const RoscoController& c, const SteadyState& steady, double dt = 0.01);

/// One call: the measured generator speed [rad/s] and wind [m/s], the step [s] (the one the memory's
/// filters were discretized at), and with Fl_Mode > 0 the floating feedback's velocity [m/s or rad/s].
RoscoCommand roscoStep(const RoscoController& c, RoscoState& s, double gen_speed, double wind, double dt,
                       double floating_velocity = 0);

/// ROSCO in the loop of a simulation (linearize/simulate.hpp) started at `start`, the operating point of
/// `steady` (trimmed with `c`): every `dt` it reads the generator speed (the model's GenSpeed output) and
/// the wind input and sets the generator torque and the collective pitch input (an increment from the
/// start's pitch, as the input moves the frozen pitch coordinates). \throws InputError when the model
/// lacks the output or the inputs, or for what roscoSteadyMemory refuses.
DiscreteController roscoInTheLoop(const Model& m, const RoscoController& c, const SteadyState& steady, double dt,
                                  const OperatingPoint& start);

}  // namespace whirl
