#pragma once
/// \file
/// ROSCO's controller (NREL's Reference OpenSource Controller, the `DISCON.IN` a ServoDyn deck names with
/// `PCMode = 5`, `VSContrl = 5`, `DLL_InFile`) as plain data: the parameters a linearization and a trim
/// need, in SI units (rad, rad/s, N m, W; the generator side is the high-speed shaft as ROSCO has it),
/// read by io::readDiscon (src/io/openfast/servodyn/discon_input.hpp). Members spell ROSCO's keys; their meaning is
/// that of ROSCO's `rosco/controller/src/ReadSetParameters.f90`, `Controllers.f90` and `ControllerBlocks.f90`
/// (NREL/ROSCO v2.10). The functions below are ROSCO's table look-ups and limits, evaluated as ROSCO does
/// (`interp1d` of `Functions.f90`: linear, held constant beyond the ends).
#include <map>
#include <string>
#include <vector>

#include "src/base/error.hpp"

namespace whirl {

/// One notch filter of ROSCO's `F_NotchFreqs/BetaNum/BetaDen` (`Filters.f90`, NotchFilter):
/// H(s) = (s² + 2 β_num ω s + ω²) / (s² + 2 β_den ω s + ω²).
struct RoscoNotch {
  double freq = 0;      ///< F_NotchFreqs: natural frequency ω [rad/s], > 0
  double beta_num = 0;  ///< F_NotchBetaNum: damping of the numerator (depth) [-]
  double beta_den = 0;  ///< F_NotchBetaDen: damping of the denominator (width) [-], > 0
};

struct RoscoController {
  std::string file;  ///< the DISCON.IN read
  /// Where each key read was written (by ROSCO's spelling, e.g. "PC_GS_KP"); a key that took ROSCO's
  /// default is absent. `at(key)` gives it for messages.
  std::map<std::string, Where> where;

  // Control modes (ReadSetParameters.f90, CheckInputs for their ranges).
  int F_LPFType = 1;       ///< generator-speed low-pass filter: 1 first order, 2 second order
  int VS_ControlMode = 0;  ///< 0 no torque control, 1 k·Ω² with PI transitions, 2 TSR tracking on the wind-speed
                           ///< estimate, 3 power-based and 4 torque-based TSR tracking
  int VS_ConstPower = 0;   ///< above rated: 0 constant torque VS_RtTq, 1 constant power VS_RtPwr
  int PC_ControlMode = 0;  ///< 0 pitch fixed at fine pitch, 1 gain-scheduled PI on generator speed
  int SS_Mode = 0;         ///< setpoint smoother: 0 off, 1 on
  int PS_Mode = 0;         ///< minimum-pitch saturation from PS_WindSpeeds/PS_BldPitchMin: 0 off, 1 on
  int Fl_Mode = 0;         ///< floating feedback: 0 off, 1 nacelle translational velocity, 2 rotational velocity
  int PA_Mode = 0;         ///< ROSCO's pitch actuator model: 0 none, 1 first order, 2 second order
  int WE_Mode =
      0;  ///< wind-speed estimator (0 filtered hub wind, 1 I&I, 2 EKF): in a steady state each equals the wind

  // Filters (ReadSetParameters.f90, "FILTERS").
  double F_LPFCornerFreq = 0;                 ///< generator-speed low-pass corner frequency [rad/s], > 0
  double F_LPFDamping = 0;                    ///< its damping ratio when F_LPFType = 2 [-]
  std::vector<RoscoNotch> gen_speed_notches;  ///< the notches of F_GenSpdNotch_Ind, on generator speed
  std::vector<RoscoNotch> twr_top_notches;    ///< the notches of F_TwrTopNotch_Ind, on tower-top motion (Fl_Mode)
  double F_SSCornerFreq = 0;                  ///< setpoint-smoother low-pass corner frequency [rad/s] (SS_Mode = 1)
  double F_VSRefSpdCornerFreq = 0;  ///< low pass on the TSR-tracking speed reference [rad/s] (VS_ControlMode ≥ 2)
  double F_WECornerFreq = 0;        ///< low pass on the wind-speed estimate [rad/s]
  double F_FlCornerFreq = 0;        ///< floating feedback: second-order low-pass frequency [rad/s] (Fl_Mode > 0)
  double F_FlCornerDamp = 0;        ///< and its damping [-]
  double F_FlHighPassFreq = 0;      ///< floating feedback: first-order high-pass frequency [rad/s] (Fl_Mode > 0)

  // Pitch control (PC_ControlMode = 1).
  std::vector<double> PC_GS_angles;  ///< gain-schedule pitch angles [rad], non-decreasing
  std::vector<double>
      PC_GS_KP;  ///< proportional gains on the generator-speed error [s] (rad per rad/s·s⁻¹: rad/(rad/s))
  std::vector<double> PC_GS_KI;  ///< integral gains [-] (rad/(rad/s)/s)
  double PC_MaxPit = 0;          ///< maximum pitch [rad]
  double PC_MinPit = 0;          ///< minimum pitch [rad]
  double PC_MaxRat = 0;          ///< maximum pitch rate [rad/s], > 0
  double PC_MinRat = 0;          ///< minimum pitch rate [rad/s], < 0
  double PC_RefSpd = 0;          ///< generator-speed reference of the pitch loop [rad/s]
  double PC_FinePit = 0;         ///< below-rated pitch [rad]
  double PC_Switch = 0;          ///< pitch above the minimum at which the torque loop counts as region 3 [rad]

  // Torque control.
  double VS_GenEff = 1;       ///< generator efficiency, electrical over mechanical power [-] (DISCON.IN: %)
  double VS_ArSatTq = 0;      ///< above-rated saturation of the region-2½ PI torque [N m]
  double VS_MaxRat = 0;       ///< torque rate limit [N m/s]
  double VS_MaxTq = 0;        ///< maximum torque [N m]
  double VS_MinTq = 0;        ///< minimum torque [N m]
  double VS_MinOMSpd = 0;     ///< minimum generator speed [rad/s]
  double VS_Rgn2K = 0;        ///< region-2 torque constant [N m/(rad/s)²]
  double VS_RtPwr = 0;        ///< rated electrical power [W]
  double VS_RtTq = 0;         ///< rated torque [N m]
  double VS_RefSpd = 0;       ///< rated generator speed, top of the torque loop's speed reference [rad/s]
  std::vector<double> VS_KP;  ///< torque PI proportional gain [N m/(rad/s)] (first used, as ROSCO)
  std::vector<double> VS_KI;  ///< torque PI integral gain [N m/rad]
  double VS_TSRopt = 0;       ///< optimal tip-speed ratio of TSR tracking [-]

  // Setpoint smoother (SS_Mode = 1, ControllerBlocks.f90 SetpointSmoother).
  double SS_VSGain = 0;  ///< torque-loop reference shift per pitch above minimum, per 0.524 rad [-]
  double SS_PCGain = 0;  ///< pitch-loop reference shift per power deficit, per rated power [-]

  // Wind-speed estimator geometry (used by TSR tracking's speed reference).
  double WE_BladeRadius = 0;   ///< rotor radius of the TSR definition [m]
  double WE_GearboxRatio = 1;  ///< generator over rotor speed [-]

  // Minimum-pitch saturation (PS_Mode = 1).
  std::vector<double> PS_WindSpeeds;   ///< [m/s], non-decreasing
  std::vector<double> PS_BldPitchMin;  ///< [rad]

  // Floating feedback (Fl_Mode > 0).
  std::vector<double> Fl_Kp;  ///< nacelle-velocity gain(s) [s] (rad per m/s)
  std::vector<double> Fl_U;   ///< wind speeds scheduling Fl_Kp [m/s] (when more than one gain)

  // Pitch actuator (PA_Mode > 0).
  double PA_CornerFreq = 0;  ///< [rad/s]
  double PA_Damping = 0;     ///< [-] (PA_Mode = 2)

  /// What the linear model and the trim leave out of this file, one sentence each naming the key and
  /// what is assumed instead (e.g. "IPC_ControlMode = 1: individual pitch control not modelled; …").
  std::vector<std::string> notes;

  /// Where `key` was written, or the file alone (a default value); for messages.
  Where at(const std::string& key) const;
};

/// ROSCO's interp1d (Functions.f90): y at x by linear interpolation in the table (xs non-decreasing),
/// held at the end values outside it. xs and ys have the same size ≥ 1.
double roscoInterp(const std::vector<double>& xs, const std::vector<double>& ys, double x);

/// The minimum pitch ROSCO holds at wind speed `wind` [m/s] in a steady state, where its wind-speed
/// estimate equals the wind: max(PC_MinPit, the PS_BldPitchMin table at the wind) with PS_Mode = 1
/// (ControllerBlocks.f90 / Controllers.f90, PitchSaturation), PC_MinPit otherwise; and, below rated,
/// never under PC_FinePit (the pitch the integrator is reset to, `PC_FinePit` record 5) [rad].
double roscoMinimumPitch(const RoscoController& c, double wind);

/// Proportional and integral pitch gains at collective pitch `pitch` [rad], from the schedule
/// (PC_GS_KP, PC_GS_KI against PC_GS_angles), as ROSCO's PitchControl interpolates them.
struct RoscoPitchGains {
  double kp = 0;  ///< [s]
  double ki = 0;  ///< [-]
};
RoscoPitchGains roscoPitchGains(const RoscoController& c, double pitch);

/// The generator torque ROSCO holds in region 3 at generator speed `gen_speed` [rad/s] (Controllers.f90,
/// VariableSpeedControl): constant power VS_RtPwr/(VS_GenEff · ω) capped at VS_MaxTq with
/// VS_ConstPower = 1, VS_RtTq otherwise [N m].
double roscoAboveRatedTorque(const RoscoController& c, double gen_speed);

/// The highest torque ROSCO's torque loop gives below region 3 at generator speed `gen_speed` [rad/s]:
/// TSR tracking (VS_ControlMode 2–4) saturates at the region-3 torque (roscoAboveRatedTorque), k·Ω²
/// (VS_ControlMode 1) at VS_ArSatTq; never above VS_MaxTq [N m].
double roscoTorqueLimit(const RoscoController& c, double gen_speed);

}  // namespace whirl
