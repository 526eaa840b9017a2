#pragma once
/// \file
/// Trimmed operating points of a turbine at a given wind speed, as HAWCStab2 computes its operational
/// data: the rotor in torque balance between the aerodynamic torque and the generator torque law.
/// - Below rated: the rotor speed at which the azimuth-averaged generalized force on the rotor
///   azimuth vanishes (aero torque = gear ratio × generator torque of the law), pitch at its minimum.
/// - Above rated (the balance at rated speed and minimum pitch has excess aerodynamic torque): rotor
///   speed held at rated generator speed / gear ratio, the pitch that balances the torque there.
/// Each evaluation solves the equilibrium of the structure with the induction solved on the deflected
/// geometry (quasi-steady BEM) at a few azimuths spanning a third of a revolution, so the 3P torque
/// ripple averages out; the scalar root is bracketed (Brent), so a trim either converges or says
/// why not.
#include <functional>
#include <string>

#include <vector>

#include "linearize/operating_point.hpp"
#include "linearize/sweep.hpp"
#include "src/model/operating_condition.hpp"
#include "src/model/rosco_controller.hpp"

namespace whirl {

struct TrimOptions {
  int azimuths = 3;         ///< equilibria per torque evaluation, spread over one blade passage
  double min_tsr = 2.0;     ///< lower end of the rotor-speed bracket, as a tip-speed ratio [-]
  double min_pitch = 0.0;   ///< fine pitch [rad]
  double max_pitch = 0.7;   ///< upper end of the pitch bracket [rad] (40°)
  double tolerance = 1e-9;  ///< on the torque balance, relative to the rated generator torque × gear ratio
  /// ROSCO's controller of the deck (Model::deck_controller; io::readDeckController), or null. When set,
  /// the trim settles where that controller does (docs/theory/controller.md), with the generator torque
  /// it commands as the condition's generator torque (the model's torque law, if any, is not used).
  const RoscoController* controller = nullptr;
  /// Called by trimSchedule after each wind speed with (done, total); it may throw to stop the schedule
  /// (the Python module's progress callback and Ctrl-C).
  std::function<void(int, int)> progress;
};

/// A steady operating point, averaged over the azimuths of one blade passage.
struct SteadyState {
  OperatingCondition condition;  ///< wind speed, rotor speed and pitch (at the balance, when trimmed)
  bool above_rated = false;      ///< pitch trimmed at rated speed
  /// With a controller (Model::controller): the branch of its laws the point is on, "1.5" (minimum
  /// generator speed), "2" (speed tracks the optimal tip-speed ratio, or k·Ω² in balance), "2.5" (rated
  /// speed of the torque loop, torque below its limit), "2.5 saturated" (torque at its limit, pitch at
  /// its minimum, speed between the two loops' references) or "3" (pitch loop at PC_RefSpd); a
  /// "+ min pitch" suffix when the pitch sits on ROSCO's minimum-pitch schedule above fine pitch
  /// (PS_Mode). Empty without a controller.
  std::string region;
  double min_pitch = 0;  ///< the controller's minimum pitch at this wind speed [rad] (0 without one)
  /// Electrical over mechanical power of the generator: the controller's VS_GenEff; 1 otherwise (a torque
  /// law's efficiency is GeneratorTorqueLaw::efficiency).
  double generator_efficiency = 1;
  double aero_torque = 0;       ///< azimuth average of the rotor aerodynamic torque [N m]
  double thrust = 0;            ///< azimuth average of the rotor aerodynamic thrust [N]
  double generator_torque = 0;  ///< of the torque law at the generator speed [N m, high-speed shaft]
  double generator_speed = 0;   ///< [rad/s]
  double imbalance = 0;         ///< azimuth-averaged generalized force on the rotor azimuth [N m]
  double tip_deflection = 0;    ///< blade 1 tip, out of the (coned) rotor plane, downwind positive [m]
  double tower_top_fa = 0;      ///< tower-top displacement downwind (output TTDspFA) [m], 0 without it
  int evaluations = 0;          ///< torque evaluations (each: `azimuths` equilibria)
  /// ∂f/∂(pitch) above rated [N m/rad], ∂f/∂Ω below [N m s/rad], f the azimuth-averaged force on the
  /// rotor azimuth, from the first two points of a search started next to a guess (0 otherwise): a
  /// neighbouring wind speed's first step (TrimGuess).
  double search_slope = 0;
  /// The equilibria at the azimuths k·2π/(B n) of the last evaluation (all coordinates), and the last
  /// Newton matrix of each (K on its solved coordinates): warm starts for a neighbouring wind speed.
  std::vector<VecX> azimuth_q;
  std::vector<MatX> azimuth_stiffness;
};

/// The steady state at a given condition (wind speed, rotor speed, pitch; no trim).
SteadyState steadyState(const Model& model, const OperatingCondition& condition, const TrimOptions& opt = {});

/// The trimmed point at `wind_speed` [m/s]. Needs aerodynamics, a rotating coordinate and a generator
/// torque law (ServoDyn VSContrl = 1, or an induction generator: then the speed on its torque-slip curve
/// at fine pitch) or ROSCO's controller (TrimOptions::controller: the point its laws settle at, with the
/// generator torque it commands as the condition's generator_torque; docs/theory/controller.md). Throws ComputeError
/// saying what was tried when no balance exists (wind too low to turn the rotor, rated power not reachable below the
/// maximum pitch, torque beyond the pull-out torque).
SteadyState trimAtWindSpeed(const Model& model, double wind_speed, const TrimOptions& opt = {});

/// Where the trim at a wind speed is expected, from its neighbours in a schedule: the search brackets
/// the root next to it first (a few torque evaluations instead of a dozen) and falls back to the whole
/// range when the balance is not there.
struct TrimGuess {
  double rotor_speed = 0;  ///< [rad/s], used below rated
  double pitch = 0;        ///< [rad], used above rated
  /// The neighbour's SteadyState::search_slope, by the variable it was searched in (0: unknown): the
  /// first step is aimed at the root with it instead of a fixed step of 1 % (0.01 rad).
  double speed_slope = 0, pitch_slope = 0;
  /// The neighbour's equilibria and Newton matrices (SteadyState::azimuth_q, azimuth_stiffness): each
  /// equilibrium starts from the deflections there instead of the undeflected turbine, its tolerance
  /// still that of the cold start. Empty: cold starts.
  std::vector<VecX> q;
  std::vector<MatX> stiffness;
};

/// As above, the search starting next to `guess`. The result equals the unguessed trim to the trim's
/// tolerance (not bit for bit).
SteadyState trimAtWindSpeed(const Model& model, double wind_speed, const TrimGuess& guess, const TrimOptions& opt = {});

/// The trimmed points at increasing or decreasing wind speeds, each search started from its
/// predecessors (tip-speed ratio held, pitch extrapolated linearly in the wind speed) and each
/// equilibrium from the predecessor's at the same azimuth (TrimGuess::q, stiffness).
std::vector<SteadyState> trimSchedule(const Model& model, const std::vector<double>& wind_speeds,
                                      const TrimOptions& opt = {});

/// The sweep point of a trimmed point: its rotor speed [rpm], wind speed and pitch [deg] as labels,
/// and its condition.
SweepPoint sweepPointOf(const SteadyState& t);

/// The trimmed sweep points at the wind speeds START:STEP:STOP of `spec` (the `--wind` option); a
/// controller's torque is in each point's condition.generator_torque.
std::vector<SweepPoint> trimmedPoints(const Model& model, const std::string& spec, const TrimOptions& opt = {});

}  // namespace whirl
