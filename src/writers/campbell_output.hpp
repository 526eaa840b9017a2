#pragma once
/// \file
/// Campbell diagram output: CSV and JSON tables, Gnuplot data and script, rendered PNG and SVG.
///
/// Files written into the output folder (together, as one OutputSet; numbers at full precision):
/// - `campbell.csv`: columns `rpm,wind_speed,mode,freq_hz,damping_ratio` (wind speed in m/s,
///   empty when the point has none; `mode` is the line name), one row per point and line that has a
///   mode there, points in sweep order, lines in line order.
/// - `campbell_modes.json`: per point its index, rpm, wind speed (m/s) and pitch (deg) (null when
///   absent), coordinates, and every mode (index, freq_hz, damped_freq_hz, damping_ratio, rigid_body,
///   name, line (null when on no line), participation per coordinate); plus the title and line names.
/// - `campbell.dat`: one Gnuplot block per line (blocks separated by two blank lines, a blank line
///   where a line skips a point), columns rpm, wind speed (NaN when absent), freq_hz, damping_ratio.
/// - `campbell.gp`: a standalone Gnuplot script that reads campbell.dat next to itself and writes
///   campbell.png (pngcairo) and campbell.svg: frequency on top, damping ratio in % below, with the
///   nP excitation lines; styles, ranges and sizes are set at its top for restyling.
/// - `mode_shapes_<point>.csv`: the node motion of every mode of point <point> (0-based), when the sweep
///   computed it (src/writers/mode_shape_tables.hpp); the same motion is in campbell_modes.json.
/// - with CampbellPlotOptions::formats: HAWCStab2's campbell.cmb/.amp/.opt ("hawcstab2"); openfast_toolbox's
///   Campbell_OP.csv, Campbell_ModesID.csv, Campbell_PointNN.csv, Campbell_Summary.txt ("openfast",
///   src/writers/openfast_campbell_files.hpp); per shown line and point with a motion, the VTK animation
///   mode_<line>_p<point>.pvd with its .vtp frames ("vtk", src/writers/mode_shape_vtk.hpp).
/// - with CampbellPlotOptions::html: campbell.html, the interactive report.
#include <string>
#include <utility>
#include <vector>

#include "modal/campbell.hpp"

namespace whirl {

/// Options of the Campbell plot.
struct CampbellPlotOptions {
  std::vector<int> harmonics = {1, 3, 6, 9};  ///< nP excitation lines drawn (grey, dashed, labelled)
  bool versus_wind_speed = false;             ///< x axis: wind speed (every point needs one) instead of rpm
  double max_freq_hz = 0;                     ///< top of the frequency axis; 0: just above the highest line
  double max_damping_percent = 0;             ///< top of the damping axis; 0: just above the highest line
  /// Draw the lines of first-order states' roots (Mode::first_order at every point, e.g. HydroDyn
  /// radiation); by default they are in the tables only.
  bool first_order_lines = false;
  /// Further formats written beside the tables: "hawcstab2" (campbell.cmb, .amp, .opt,
  /// src/writers/hawcstab2_files.hpp), "openfast" (openfast_toolbox's Campbell_*.csv), "vtk" (ParaView).
  std::vector<std::string> formats;
  /// Also write campbell.html, the interactive report (src/writers/campbell_html.hpp), with this input
  /// summary (what, value).
  bool html = false;
  std::vector<std::pair<std::string, std::string>> summary;
  bool render = true;               ///< run Gnuplot on the script when it is on PATH
  std::string gnuplot = "gnuplot";  ///< the Gnuplot program (looked up on PATH)
};

/// Whether `line` is drawn: not when it lies entirely above opt.max_freq_hz, nor when every one of its
/// modes is a first-order state's root (Mode::first_order) and !opt.first_order_lines.
bool campbellLineShown(const CampbellDiagram& d, const CampbellLine& line, const CampbellPlotOptions& opt);

/// Writes the Campbell files into `dir` (created when missing) and, when `opt.render` and Gnuplot
/// is found, renders campbell.png and campbell.svg by running the script with `dir` as working
/// directory. A failing Gnuplot only prints a warning on stderr; the tables are complete anyway.
/// \return paths of the files written (dir/name), rendered images included.
/// Throws InputError when `dir` cannot be created or written (no file of this call is left
/// behind), when a line does not match the points, or when versus_wind_speed and a point has no
/// wind speed, or a harmonic is below 1.
std::vector<std::string> writeCampbell(const CampbellDiagram& d, const std::string& dir,
                                       const CampbellPlotOptions& opt = {});

/// Text of campbell.csv.
std::string campbellCsv(const CampbellDiagram& d);

/// Text of campbell_modes.json (indented by 1).
std::string campbellModesJson(const CampbellDiagram& d);

/// Text of campbell.dat.
std::string campbellGnuplotData(const CampbellDiagram& d);

/// Text of campbell.gp.
std::string campbellGnuplotScript(const CampbellDiagram& d, const CampbellPlotOptions& opt = {});

/// Throws InputError when a line's mode list does not have one entry per point or an entry is not
/// a mode of its point, a harmonic is below 1, or (with versus_wind_speed) a point has no wind speed.
void checkCampbell(const CampbellDiagram& d, const CampbellPlotOptions& opt = {});

}  // namespace whirl
