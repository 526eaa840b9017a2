#pragma once
/// \file
/// The tables and plot script of a closed-loop Campbell (`whirl campbell --closed-loop`):
/// - `closed_loop_modes.csv`: one row per root and wind speed, open and closed loop side by side in the
///   column `loop` (open | closed): wind speed [m/s], rotor speed [rpm], pitch [deg], mode name, natural
///   and damped frequency [Hz], damping ratio [-], eigenvalue real and imaginary parts [1/s], the
///   controller's participation [-], `unstable` (1 when Re λ ≥ 0);
/// - `margins.csv`: per wind speed the margins of the pitch loop and of the torque loop broken at
///   their actuator inputs: gain margin [-] and [dB], its frequency [rad/s], phase margin [deg], its
///   frequency [rad/s], delay margin [s], peak sensitivity Ms [-] (inf: the loop is open or never
///   crosses), the least closed-loop damping ratio and `stable`;
/// - `closed_loop.gp`: gnuplot script drawing frequency and damping against the wind (open and
///   closed), and the margins.
#include <string>
#include <vector>

#include "modal/closed_loop_modes.hpp"

namespace whirl {

std::string closedLoopModesCsv(const std::vector<ClosedLoopPoint>& points);
std::string closedLoopMarginsCsv(const std::vector<ClosedLoopPoint>& points);
std::string closedLoopGnuplotScript(const std::string& title);

}  // namespace whirl
