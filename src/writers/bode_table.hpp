#pragma once
/// \file
/// The Bode table of `whirl bode` (and the Python `Model.bode`): magnitude [dB] and phase [deg] of
/// each output/input pair of a frequency response (linearize/frequency_response.hpp), as bode.csv and
/// its Gnuplot script bode.gp.
#include <string>
#include <vector>

#include "linearize/state_space.hpp"

namespace whirl {

/// Column names after `freq_hz`: "Y / U dB", "Y / U deg" for each output Y, then each input U.
std::vector<std::string> bodeColumns(const StateSpaceModel& s);

/// One row per frequency, the columns of bodeColumns: 20 log10 |G| [dB of SI units] and arg G [deg]
/// in (−180, 180] of each entry G(i, j) of the responses `G` (ny × nu each).
MatX bodeValues(const std::vector<Eigen::MatrixXcd>& G);

/// Text of bode.csv: `freq_hz` and the columns of bodeColumns, numbers at full precision.
std::string bodeCsv(const StateSpaceModel& s, const std::vector<double>& freq_hz,
                    const std::vector<Eigen::MatrixXcd>& G);

/// Text of bode.gp: reads bode.csv beside it, writes bode.png and bode.svg (magnitude above, phase
/// below, `pairs` curves each, log frequency axis).
std::string bodeGnuplotScript(const std::string& title, int pairs);

}  // namespace whirl
