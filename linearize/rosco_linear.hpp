#pragma once
/// \file
/// ROSCO's controller (src/model/rosco_controller.hpp) linearized at one of its steady states
/// (linearize/trim.hpp, SteadyState::region): which of its loops act there, with the gains scheduled at
/// the point, as a LinearController (linearize/closed_loop.hpp). At a steady state every integrator
/// has removed its error and exactly one loop per actuator acts, the other saturated (ROSCO's
/// Controllers.f90, VariableSpeedControl and PitchControl; ControllerBlocks.f90,
/// ComputeVariablesSetpoints):
/// - region "3": the pitch PI at PC_RefSpd with PC_GS_KP/KI at the point's pitch; the torque saturated at
///   the region-3 value, constant power VS_RtPwr/(η ω_f) (VS_ConstPower = 1, below VS_MaxTq: it moves
///   with the filtered speed) or constant torque;
/// - "2.5 saturated": the pitch at its minimum, the torque at its limit (constant power moves with ω_f);
/// - "2.5" and "1.5": the torque PI (VS_KP, VS_KI) on a held reference (VS_RefSpd, VS_MinOMSpd);
/// - "2": VS_ControlMode 1 the law τ = VS_Rgn2K ω_f²; VS_ControlMode 2 the torque PI on the TSR reference
///   VS_TSRopt·N·Û/R through its low pass F_VSRefSpdCornerFreq, the wind-speed estimate Û taken equal
///   to the wind;
/// - a "+ min pitch" point: the pitch held on the minimum-pitch schedule (PS_Mode), the loop saturated.
/// The generator-speed filter (F_LPFType, F_LPFCornerFreq, F_LPFDamping) and the notches on the
/// generator speed (F_GenSpdNotch_Ind) act on every loop; ROSCO's pitch actuator (PA_Mode) on the pitch.
#include <string>
#include <vector>

#include "linearize/closed_loop.hpp"
#include "linearize/trim.hpp"
#include "src/model/rosco_controller.hpp"

namespace whirl {

struct RoscoLinearOptions {
  /// Leave the generator-speed low pass out (the loop ROSCO's own linear tools close: issue 43's
  /// instability at 12–16 m/s); the notches stay.
  bool without_speed_filter = false;
};

/// ROSCO's controller linearized at `steady` (a point trimmed with it: steady.region set).
/// \throws InputError naming the controller file when the point has no region (trimmed without the
/// controller) or the region is not one of ROSCO's.
LinearController linearRosco(const RoscoController& c, const SteadyState& steady, const RoscoLinearOptions& opt = {});

/// What the linear model assumes in place of the parts of this controller it leaves out, one
/// sentence each naming the key (wind-speed estimator dynamics, setpoint smoother, floating feedback,
/// VS_ControlMode 3/4 references, …); empty when nothing is left out.
std::vector<std::string> linearRoscoNotes(const RoscoController& c);

}  // namespace whirl
