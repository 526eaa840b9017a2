#pragma once
/// \file
/// Time series of a simulation (linearize/simulate.hpp): table, Gnuplot script, rendered PNG and SVG.
///
/// Files written into the output folder (together, as one OutputSet; numbers at full precision):
/// - `timeseries.csv`: columns `time_s`, then for every coordinate `NAME` and `NAME rate` (model
///   order; m or rad, per s for the rates; elastic coordinates in the units of their shapes), every
///   input `input: NAME` and every output `NAME [unit]`; one row per recorded instant.
/// - `timeseries.gp`: a standalone Gnuplot script that reads timeseries.csv next to itself and
///   writes timeseries.png and timeseries.svg, one panel per plotted channel against time.
#include <string>
#include <vector>

#include "linearize/simulate.hpp"

namespace whirl {

struct TimeseriesPlotOptions {
  /// Column names of timeseries.csv to plot, one panel each; empty: every integrated coordinate (up to 6; the rate of a
  /// rotating one).
  std::vector<std::string> channels;
  std::string title;
  bool render = true;               ///< run Gnuplot on the script when it is on PATH
  std::string gnuplot = "gnuplot";  ///< the Gnuplot program
};

/// The column names of timeseries.csv, in order.
std::vector<std::string> timeseriesColumns(const Model& model);

/// Text of timeseries.csv.
std::string timeseriesCsv(const Model& model, const Simulation& sim);

/// Text of timeseries.gp. \throws InputError "--plot: 'NAME': no such column (…)" for an unknown channel.
std::string timeseriesGnuplotScript(const Model& model, const Simulation& sim, const TimeseriesPlotOptions& opt = {});

/// Writes the files into `dir` (prepareOutputFolder first) as one set; renders the images when
/// `opt.render` and Gnuplot is found (a failing Gnuplot is a warning). \return the paths written.
std::vector<std::string> writeTimeseries(const Model& model, const Simulation& sim, const std::string& dir,
                                         const TimeseriesPlotOptions& opt = {});

}  // namespace whirl
