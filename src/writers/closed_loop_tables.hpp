#pragma once
/// \file
/// The tables and plot script of a closed-loop Campbell (`whirl campbell --closed-loop`):
/// - `closed_loop_modes.csv`: one row per root and wind speed, open and closed loop side by side in the
///   column `loop` (open | closed): wind speed [m/s], rotor speed [rpm], pitch [deg], mode name, natural
///   and damped frequency [Hz], damping ratio [-], eigenvalue real and imaginary parts [1/s], the
///   controller's participation [-], `unstable` (1 when Re λ ≥ 0);
/// - `margins.csv`: per wind speed the margins of the pitch loop and of the torque loop broken at
///   their actuator inputs: gain margin [-] and [dB], its frequency [rad/s], phase margin [deg], its
///   frequency [rad/s], delay margin [s], peak sensitivity Ms [-] (inf: the loop never crosses;
///   nan: the loop does not act at this point, saturated), the least closed-loop damping ratio and `stable`;
/// - `closed_loop.gp`: gnuplot script drawing frequency and damping against the wind — the open
///   loop's tracked lines (`open_loop_campbell.dat`) grey and dashed, the closed loop's
///   (`campbell.dat`) in colour, unstable closed-loop roots as red crosses — and the margins; writes
///   closed_loop.png and closed_loop.svg.
#include <string>
#include <vector>

#include "modal/closed_loop_campbell.hpp"
#include "src/writers/campbell_output.hpp"

namespace whirl {

std::string closedLoopModesCsv(const std::vector<ClosedLoopPoint>& points);
std::string closedLoopMarginsCsv(const std::vector<ClosedLoopPoint>& points);
std::string closedLoopGnuplotScript(const ClosedLoopCampbell& c, const CampbellPlotOptions& opt = {});

/// Writes the closed-loop Campbell files into `dir` as one set (src/writers/output_set.hpp): the
/// closed loop's Campbell files of writeCampbell (campbell.csv, campbell_modes.json, campbell.dat,
/// campbell.gp, images; campbell.html with opt.html), `open_loop_campbell.csv`/`.dat` (the open loop's
/// tracked lines, same columns), `closed_loop_modes.csv`, `margins.csv`, `closed_loop.gp` and its
/// images. \return the paths written.
std::vector<std::string> writeClosedLoopCampbell(const ClosedLoopCampbell& c, const std::string& dir,
                                                 const CampbellPlotOptions& opt = {});

}  // namespace whirl
