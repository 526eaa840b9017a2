#pragma once
/// \file
/// Reading back the campbell.csv that `whirl campbell` wrote (src/writers/campbell_output.hpp: columns
/// `rpm,wind_speed,mode,freq_hz,damping_ratio`, one row per point and line with a mode there, points in
/// sweep order, lines in line order), for the commands that draw or tabulate several results together
/// (`whirl report --side-by-side`, src/writers/campbell_side_by_side.hpp).
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace whirl {

/// A line's mode at one point: natural frequency [Hz] and damping ratio [-] (either may be NaN, as written).
struct CampbellCsvValue {
  double freq_hz = 0;
  double damping_ratio = 0;
};

/// One Campbell line: its name and its modes, stored where it has one (memory follows the rows of the file,
/// not points × lines).
struct CampbellCsvLine {
  std::string name;
  std::vector<std::pair<std::size_t, CampbellCsvValue>> modes;  ///< (point index, mode), points ascending
  /// The line's mode at point `p`; none where the line skips it.
  std::optional<CampbellCsvValue> at(std::size_t p) const;
};

/// One operating point: rotor speed [rpm] and wind speed [m/s] (none for an rpm sweep).
struct CampbellCsvPoint {
  double rpm = 0;
  std::optional<double> wind_speed;
};

/// A Campbell diagram as campbell.csv holds it.
struct CampbellCsvResult {
  std::string file;  ///< the path read, for messages
  std::vector<CampbellCsvPoint> points;
  std::vector<CampbellCsvLine> lines;  ///< in order of first appearance
};

/// Reads the campbell.csv at `path`. A new point starts where the row's (rpm, wind speed) text changes
/// or a line repeats within a point. \throws InputError "file:line: column: reason" when the file is
/// missing, a column is missing, rpm is not a finite number, a wind speed is neither empty nor finite,
/// a frequency or damping ratio is not a number, or a mode name is not printable UTF-8; "file: reason"
/// when it has no row.
CampbellCsvResult readCampbellCsv(const std::string& path);

}  // namespace whirl
