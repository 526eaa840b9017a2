#pragma once
/// \file
/// ROSCO's rotor performance text file (`Cp_Ct_Cq.<turbine>.txt`, written by ROSCO's
/// `write_rotor_performance`, read by `load_from_txt` in NREL/ROSCO `rosco/toolbox/utilities.py`):
/// comment lines starting with '#' announce each block, the line after "Pitch angle vector" holds the
/// pitch angles [deg], the line after "TSR vector" the tip-speed ratios, and after "Power",
/// "Thrust" and "Torque" (and one more line, blank in ROSCO's files) one row per tip-speed ratio with
/// one value per pitch angle.
#include <string>

#include "src/aero/rotor_performance.hpp"

namespace whirl::io {

/// \throws InputError `file:line: key: reason` for a missing block, a row of the wrong length, a value
/// that is not a number, fewer than 4 grid values or a grid that does not increase.
aero::RotorPerformance readRotorPerformance(const std::string& path);

}  // namespace whirl::io
