#pragma once
/// \file
/// The turbine with its controller as one linear model: the open-loop plant (a state-space model
/// with the generator torque, the collective pitch and the wind among its inputs and the generator
/// speed among its outputs) closed by the linearized ROSCO controller at the operating point, whose
/// states become first-order states beside the structural ones.
///
/// The controller in continuous time (ROSCO's discrete filters and integrators are Tustin and
/// forward-Euler forms of these at DT = 0.00625 s for the NREL 5MW: a factor 30 above the fastest
/// structural mode of interest, so the continuous equivalents' phase differs by ω·DT/2 < 2° up to
/// 15 Hz; the sample-and-hold delay is left out):
/// - generator-speed filter on ω_g (Filters.f90): first-order low pass ω_c/(s + ω_c) or second-order
///   ω_c²/(s² + 2ζω_c s + ω_c²), then the notches (s² + 2β_n ω s + ω²)/(s² + 2β_d ω s + ω²): ω_f;
/// - pitch loop (region 3; Controllers.f90 PitchControl, Functions.f90 PIController): with the error
///   e = ω_ref − ω_f, the integral state stores ∫K_i e dt (ROSCO's ITerm), θ_c = K_p e + I. With gains
///   scheduled on the pitch, δθ_c = K_p δe + δI + (∂K_p/∂θ) e₀ δθ and δİ = K_i δe + (∂K_i/∂θ) e₀ δθ:
///   at a steady point e₀ = 0, so the schedule's slope drops out (it would not for a controller that
///   stores ∫e and multiplies by K_i(θ) afterwards: docs/theory/closed-loop.md);
/// - pitch actuator (PA_Mode 1, 2): first- or second-order low pass of θ_c;
/// - torque: region 3 constant power τ = P/(η ω_f) (δτ = −P/(η ω_f²) δω_f) or constant torque
///   (δτ = 0); below rated ROSCO's PI (VS_KP, VS_KI) on ω_ref − ω_f with TSR tracking's reference
///   ω_ref = λ_opt N U / R (the wind-speed estimate taken equal to the wind, through the reference's
///   first-order low pass), held at VS_RefSpd in
///   region 2½; or the k ω_f² law (δτ = 2 k ω_f δω_f);
/// - floating feedback (ROSCO's Fl_Mode; Controllers.f90 FloatingFeedback, Filters.f90): ROSCO
///   integrates the tower top's fore-aft acceleration (Fl_Mode 1) or the nacelle's pitch acceleration
///   (Fl_Mode 2) after a second-order low pass, a first-order high pass s/(s + ω_h) and the tower-top
///   notches, and adds −K_fl times it to the pitch command. The filters are linear, so integrating the
///   filtered acceleration equals filtering the velocity: the linear model feeds the velocity back
///   (outputs YawBrTVxp, NcIMURVys) through the same filters and leaves out the integrator's pole at 0,
///   which the acceleration's zero at 0 cancels (a minimal realization of the same transfer function).
#include <string>
#include <vector>

#include "linearize/state_space.hpp"

namespace whirl {

/// One notch filter on the generator speed.
struct SpeedNotch {
  double freq = 0;      ///< ω [rad/s]
  double beta_num = 0;  ///< numerator damping [-]
  double beta_den = 0;  ///< denominator damping [-]
};

/// The controller linearized at one operating point (gains already scheduled there).
struct LinearController {
  int lpf_order = 1;       ///< generator-speed low pass: 0 none, 1 first, 2 second order
  double lpf_freq = 0;     ///< its corner frequency [rad/s]
  double lpf_damping = 0;  ///< second order [-]
  std::vector<SpeedNotch> notches;

  bool pitch_active = false;  ///< the pitch PI loop acts (region 3); otherwise pitch held
  double pitch_kp = 0;        ///< [s] (rad per rad/s of generator-speed error)
  double pitch_ki = 0;        ///< [-] (rad/s per rad/s)
  int actuator_order = 0;     ///< pitch actuator: 0 none, 1 first, 2 second order
  double actuator_freq = 0;   ///< [rad/s]
  double actuator_damping = 0;

  enum class Torque { Held, Static, PI } torque = Torque::Held;
  /// Torque::Static: δτ = torque_slope δω_f [N m s/rad] (constant power: −P/(η ω_f²); k ω²: 2 k ω_f).
  double torque_slope = 0;
  double torque_kp = 0;           ///< Torque::PI: VS_KP [N m s/rad]
  double torque_ki = 0;           ///< VS_KI [N m/rad]
  double reference_per_wind = 0;  ///< Torque::PI: ∂ω_ref/∂U [rad/m] (TSR tracking; 0 when held)
  /// Torque::PI with reference_per_wind ≠ 0: first-order low pass on the reference [rad/s] (ROSCO's
  /// F_VSRefSpdCornerFreq; 0: none). Driven by the wind alone, its root is the corner frequency.
  double reference_filter_freq = 0;

  /// Floating feedback on the pitch (with pitch_active): 0 none, 1 the tower top's fore-aft velocity
  /// [m/s], 2 the nacelle's pitch rate [rad/s]; δθ_c += −floating_kp · F(s) v.
  int floating_mode = 0;
  double floating_kp = 0;                    ///< ROSCO's Fl_Kp scheduled at the point [s] (rad per m/s; per rad/s)
  double floating_lpf_freq = 0;              ///< second-order low pass [rad/s] (F_FlCornerFreq)
  double floating_lpf_damping = 0;           ///< its damping [-]
  double floating_hpf_freq = 0;              ///< first-order high pass [rad/s] (F_FlHighPassFreq; 0: none)
  std::vector<SpeedNotch> floating_notches;  ///< F_TwrTopNotch_Ind
};

/// Names of the roles the plant must have.
struct ClosedLoopPorts {
  std::string torque_input = "generator torque";
  std::string pitch_input = "collective pitch";
  std::string wind_input = "wind speed";  ///< may be absent when reference_per_wind = 0
  std::string speed_output = "GenSpeed";
  std::string tower_top_velocity_output = "YawBrTVxp";  ///< floating_mode 1
  std::string nacelle_pitch_rate_output = "NcIMURVys";  ///< floating_mode 2
};

/// The plant output the floating feedback reads (empty when floating_mode is 0).
std::string floatingFeedbackOutput(const LinearController& c, const ClosedLoopPorts& ports = {});

/// The closed loop: states [plant x; controller states] (the controller's named "controller: speed
/// filter", "controller: pitch PI integral", …, first-order), the plant's inputs kept as disturbances
/// added to the controller's commands (generator torque, pitch) or acting directly (wind), the plant's
/// outputs and then the controller's commands, "controller: generator torque" [N m] and "controller:
/// collective pitch" [rad] (after the actuator). \throws InputError when the plant lacks an input or output named in
/// `ports`, or when the generator speed depends directly on the torque or the pitch (D ≠ 0, an algebraic loop).
StateSpaceModel closeLoop(const StateSpaceModel& plant, const LinearController& c, const ClosedLoopPorts& ports = {});

/// The controller alone as a state-space model: u = [δω_g; δU; d_τ; d_θ; δv] (d_τ added to the torque
/// command, d_θ at the actuator input, v the floating feedback's velocity), y = [δτ; δθ; the actuator
/// input]. Its states are named as closeLoop names them.
StateSpaceModel controllerStateSpace(const LinearController& c);

/// Where a loop is broken for its margins: at the actuator input of the pitch loop, or at the
/// generator-torque command.
enum class BrokenLoop { Pitch, Torque };

/// The sensitivity at the break point with every loop closed: S(s) = cᵀ(sI − A)⁻¹b + d from a
/// disturbance added there to the signal there, S = 1/(1 + L) with L the return ratio of the loop
/// broken at that point (the other loop closed).
struct LoopSensitivity {
  MatX A;
  VecX b, c;
  double d = 1;
};
LoopSensitivity loopSensitivity(const StateSpaceModel& plant, const LinearController& c, BrokenLoop loop,
                                const ClosedLoopPorts& ports = {});

}  // namespace whirl
