#pragma once
/// \file
/// Pole placement of ROSCO's PI pitch and torque loops on the one-state rotor model (NREL/ROSCO
/// `rosco/toolbox/controller.py`, `Controller.tune_controller` and `ControllerTypes.second_order_PI`;
/// Abbas et al. 2022, WES 7:53, eq. 7 and 26, as cited there). With the generator speed ω_g = N Ω as the state,
///   J ω̇_g / N = Q(Ω, β, U) − N τ_g  →  δω̇_g = A δω_g + B_β δβ + B_τ δτ_g,
///   A = (∂Q/∂Ω)/J (+ P/(J Ω²) above rated with constant power: τ_g = P/ω_g), B_β = N (∂Q/∂β)/J,
///   B_τ = −N²/J,
/// a PI loop δu = K_p e + K_i ∫e on the speed error e = ω_g − ω_ref gives the characteristic
/// polynomial s² + (B K_p − A) s + B K_i; matching s² + 2ζω s + ω² gives
///   K_p = (2ζω + A)/B,  K_i = ω²/B.
/// The sensitivities come either from a rotor performance surface along ROSCO's operating schedule
/// (roscoTuningSchedule: this reproduces ROSCO's gains) or from whirl's trimmed, linearized turbine
/// (linearize/controller_tuning_whirl.hpp).
#include <optional>
#include <vector>

#include "src/aero/rotor_performance.hpp"

namespace whirl {

/// What ROSCO's tuning takes from its YAML (`turbine_params`) and the OpenFAST deck.
struct TuningTurbine {
  double inertia = 0;                        ///< J: rotor + generator · N², about the low-speed shaft [kg m²]
  double rotor_radius = 0;                   ///< R [m]
  double air_density = 0;                    ///< ρ [kg/m³]
  double gearbox_ratio = 1;                  ///< N [-]
  double rated_rotor_speed = 0;              ///< Ω_rated [rad/s]
  double rated_power = 0;                    ///< P [W]
  double v_min = 0, v_rated = 0, v_max = 0;  ///< cut-in, rated, cut-out wind speeds [m/s]
};

/// The requested closed-loop poles and ROSCO's schedule options (toolbox_schema.yaml defaults).
struct TuningGoals {
  double pc_omega = 0, pc_zeta = 0;  ///< pitch loop natural frequency [rad/s] and damping ratio [-]
  double vs_omega = 0, vs_zeta = 0;  ///< torque loop
  bool constant_power = true;        ///< VS_ConstPower: the P/(J Ω²) term above rated
  int ws_gs_n = 60;                  ///< WS_GS_n: wind speeds of the schedule
  int pc_gs_n = 30;                  ///< PC_GS_n: of them above rated (pitch gain schedule)
  /// ROSCO's `linearize=True` for the pitch loop: A and B_β replaced by their least-squares lines in
  /// the wind speed before the placement.
  bool fit_linear_in_wind = true;
  std::optional<double> min_pitch;        ///< [rad]; default the surface's optimal pitch
  std::optional<double> tsr_operational;  ///< [-]; default the surface's optimal tip-speed ratio
};

/// One point of the operating schedule with the rotor's sensitivities there.
struct TuningPoint {
  double wind_speed = 0;   ///< U [m/s]
  double tsr = 0;          ///< λ [-]
  double pitch = 0;        ///< β [rad]
  double rotor_speed = 0;  ///< Ω [rad/s]
  double dq_dpitch = 0;    ///< ∂Q/∂β, rotor aerodynamic torque [N m/rad]
  double dq_domega = 0;    ///< ∂Q/∂Ω [N m s/rad]
  double dq_dwind = 0;     ///< ∂Q/∂U [N m s/m]
  bool above_rated = false;
};

/// ROSCO's wind speeds: WS_GS_n − PC_GS_n − 1 below rated from v_min (v_rated left out), then
/// PC_GS_n + 1 from v_rated to v_max; the pitch schedule uses the last PC_GS_n.
std::vector<double> roscoWindSpeeds(const TuningTurbine& t, const TuningGoals& g);

/// ROSCO's operating schedule and its sensitivities from the Cp surface (`tune_controller`): below
/// rated λ = min(λ_op, Ω_rated R/U) at the minimum pitch; above rated Ω_rated and the pitch where the
/// surface gives Cp(β_min, λ_rated)(λ/λ_rated)³ (linear interpolation in Cp on the grid pitches at
/// and above the grid maximum); ∂Q/∂β = ½ρπR³U²/λ ∂Cp/∂β, ∂Q/∂Ω = ½ρπR⁴U (λ ∂Cp/∂λ − Cp)/λ².
std::vector<TuningPoint> roscoTuningSchedule(const aero::RotorPerformance& perf, const TuningTurbine& t,
                                             const TuningGoals& g);

/// The gains of the placement.
struct GainSchedule {
  std::vector<double> wind_speed;  ///< of the pitch schedule [m/s]
  std::vector<double> pitch;       ///< PC_GS_angles [rad]
  std::vector<double> kp, ki;      ///< PC_GS_KP [s], PC_GS_KI [-] (generator-speed error → pitch)
  std::vector<double> a, b;        ///< the placed plant's A [1/s] and B_β [1/s²] (after any fit)
  double vs_kp = 0, vs_ki = 0;     ///< VS_KP, VS_KI at the last below-rated point [N m s/rad, N m/rad]
  double vs_a = 0;                 ///< the torque loop's A there [1/s]
  /// Floating feedback (floatingFeedbackGain): ROSCO's Fl_Mode (0: none), Fl_Kp [s] at Fl_U [m/s].
  int fl_mode = 0;
  double fl_kp = 0, fl_wind = 0;
};

/// The placement on a schedule: the above-rated points (in order) give the pitch schedule, the last
/// below-rated point the torque gains (ROSCO writes `vs_gain_schedule.Kp[-1]`). \throws ComputeError
/// when the schedule has no point on either side or ∂Q/∂β = 0.
GainSchedule placePoles(const std::vector<TuningPoint>& schedule, const TuningTurbine& t, const TuningGoals& g);

/// ROSCO's floating-feedback gain (`tune_controller`, Fl_Mode 1): K_fl = (∂Q/∂U)/(∂Q/∂β) [s], the pitch
/// that cancels the change of aerodynamic torque from a tower-top velocity, interpolated in the wind
/// speed at `wind` (ROSCO's U_Fl, by default 1.05 v_rated). \throws ComputeError when `wind` is outside
/// the schedule or ∂Q/∂β = 0 there.
double floatingFeedbackGain(const std::vector<TuningPoint>& schedule, double wind);

}  // namespace whirl
