#pragma once
/// \file
/// Several Campbell diagrams side by side (`whirl report DIR... --side-by-side`): the same turbine under
/// different models (quasi-steady, unsteady airfoil, dynamic inflow, …), one column per result, so the
/// models' frequencies and damping can be read across at one glance.
///
/// Files written into the output folder (together, as one OutputSet):
/// - `campbell_side_by_side_<k>.dat` (k = 1, 2, …): column k's data, one Gnuplot block per line (blocks
///   separated by two blank lines, a blank line where a line skips a point), columns rpm, wind speed [m/s]
///   (NaN when absent), frequency [Hz], damping ratio [-] — campbell.dat's layout;
/// - `campbell_side_by_side.gp`: Gnuplot script drawing frequency (top row) and damping ratio in % (bottom
///   row) against wind speed or rotor speed, one column per result titled with its label, the same axes
///   ranges in every column, a line of the same name in the same colour everywhere, one key; rendered to
///   `campbell_side_by_side.png` and `.svg`;
/// - `aero_models.csv`: per x value (wind speed [m/s] or rotor speed [rpm]) and tabulated mode (the first
///   tower, flapwise and edgewise modes: `tower FA 1`, `tower SS 1`, `flap 1 BW|FW|collective`,
///   `edge 1 BW|FW|collective`) the frequency [Hz] and damping ratio [-] under each label side by side,
///   empty where a result has no such mode at that x.
#include <string>
#include <vector>

#include "src/writers/campbell_csv_input.hpp"

namespace whirl {

/// One column of the figure: a Campbell result and its title.
struct SideBySideColumn {
  std::string label;  ///< printable UTF-8 (checked by writeCampbellSideBySide)
  CampbellCsvResult result;
};

/// Options of the side-by-side figure.
struct SideBySideOptions {
  bool versus_wind_speed = true;   ///< x axis: wind speed (every point needs one) instead of rpm
  double max_freq_hz = 0;          ///< top of the frequency axis; 0: just above the highest line drawn
  double max_damping_percent = 0;  ///< top of the damping axis [%]; 0: just above the highest line drawn
  bool render = true;              ///< run Gnuplot on the script when it is on PATH
  std::string gnuplot = "gnuplot";
};

/// The tabulated modes of aero_models.csv, in their order.
const std::vector<std::string>& sideBySideTabulatedModes();

/// Text of campbell_side_by_side_<k>.dat for one result.
std::string sideBySideData(const CampbellCsvResult& r);

/// Text of campbell_side_by_side.gp.
std::string sideBySideGnuplotScript(const std::vector<SideBySideColumn>& columns, const SideBySideOptions& opt = {});

/// Text of aero_models.csv.
std::string aeroModelsCsv(const std::vector<SideBySideColumn>& columns, bool versus_wind_speed = true);

/// Writes the files above into `dir` (created when missing) as one set, renders the figure when
/// opt.render and Gnuplot is found. \throws InputError, writing nothing, when there is no column, a label
/// is empty, repeated, or not printable UTF-8 on one line, or versus wind speed a point has no wind speed.
/// \return the paths written.
std::vector<std::string> writeCampbellSideBySide(const std::vector<SideBySideColumn>& columns, const std::string& dir,
                                                 const SideBySideOptions& opt = {});

}  // namespace whirl
