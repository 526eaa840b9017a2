// `whirl steady`: the steady performance table of an aeroelastic model along the wind, trimmed
// (--wind) or at a schedule's rotor speeds and pitches (--schedule).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "linearize/sweep.hpp"
#include "linearize/trim.hpp"
#include "src/base/error.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/io/openfast/servodyn/discon_input.hpp"
#include "src/io/text/csv.hpp"
#include "src/io/text/schedule.hpp"
#include "src/parallel/session.hpp"
#include "src/writers/gnuplot.hpp"
#include "src/writers/output_set.hpp"
#include "src/writers/steady_table.hpp"

namespace whirl::cli {
namespace {

constexpr double kPi = std::numbers::pi;

struct SteadyOptions {
  ModelOptions model;
  std::string wind_range, schedule, out;
  int azimuths = 3;
  bool no_plot = false;
};

std::string scriptOf(const std::string& title) {
  return "# Steady operating points written by whirl: gnuplot steady.gp (from this folder)\n"
         "if (!exists('png_out')) png_out = 'steady.png'\n"
         "if (!exists('svg_out')) svg_out = 'steady.svg'\n"
         "set datafile separator ','\n"
         "set key autotitle columnhead noenhanced top left\n"
         "set grid\n"
         "set xlabel 'Wind speed [m/s]' noenhanced\n"
         "do for [out = 1:2] {\n"
         "  if (out == 1) { set terminal pngcairo size 1200,900 noenhanced; set output png_out }\n"
         "  else { set terminal svg size 1200,900 noenhanced; set output svg_out }\n"
         "  set multiplot layout 2,2 title " +
         gnuplotQuoted(title) +
         "\n"
         "  set ylabel 'Rotor speed [rpm], pitch [deg]'\n"
         "  plot 'steady.csv' using 1:2 with linespoints, '' using 1:3 with linespoints\n"
         "  set ylabel 'Power [kW]'\n"
         "  plot 'steady.csv' using 1:4 with linespoints, '' using 1:5 with linespoints\n"
         "  set ylabel 'Thrust [kN]'\n"
         "  plot 'steady.csv' using 1:7 with linespoints\n"
         "  set ylabel 'Cp, Ct [-]'\n"
         "  plot 'steady.csv' using 1:8 with linespoints, '' using 1:9 with linespoints\n"
         "  unset multiplot\n"
         "}\n";
}

void run(const SteadyOptions& opt) {
  if (opt.wind_range.empty() == opt.schedule.empty())
    throw InputError("steady: give exactly one of --wind START:STEP:STOP and --schedule FILE");
  const Model m = loadModel(opt.model);
  if (!m.aero.active())
    throw InputError(opt.model.case_path + ": the model has no aerodynamics (an OpenFAST deck with CompAero = 2)");
  const std::string dir = opt.out.empty() ? defaultOutputFolder(opt.model.case_path) : opt.out;
  prepareOutputFolder(dir);
  TrimOptions trim;
  trim.azimuths = opt.azimuths;
  // The deck's ROSCO controller, when it names one: the trim settles where it does (docs/user/controller.md).
  const std::optional<RoscoController>& controller = m.deck_controller;
  if (controller) trim.controller = &*controller;
  if (parallel::launchedByMpi()) parallel::requirePetsc("mpirun");  // start-up outside the timing
  const auto start = std::chrono::steady_clock::now();
  std::vector<SteadyState> rows;
  if (!opt.wind_range.empty()) {
    rows = trimSchedule(m, parseRange(opt.wind_range, "--wind"), trim);
  } else {
    const std::vector<SweepPoint> points = readSchedule(opt.schedule);
    for (size_t k = 0; k < points.size(); ++k) {
      const SweepPoint& p = points[k];
      if (!p.wind_speed) throw InputError(opt.schedule + ": the schedule has no wind speed column");
      OperatingCondition c = sweepCondition(m, p);
      // A failing row names itself and its point (issue 41), as the sweeps of campbell and export do.
      const std::string at = opt.schedule + ": operating point " + std::to_string(k + 1) + " (" +
                             sweepPointLabel(m, p) + "): ";
      try {
        rows.push_back(steadyState(m, c, trim));
      } catch (const InputError& e) {
        throw InputError(at + e.what());
      } catch (const ComputeError& e) {
        throw ComputeError(at + e.what());
      }
    }
  }
  if (parallel::rank() != 0) return;  // under mpirun (the trim spread over the ranks): rank 0 writes
  OutputSet files(dir);               // table, script and images together
  files.write("steady.csv", steadyCsv(m, rows));
  files.write("steady.gp", scriptOf("Steady operating points: " + m.name.substr(0, 60)));
  if (!opt.no_plot) renderGnuplot(files.stagingFolder(), "gnuplot", "steady", dir);
  files.commit();
  const std::vector<std::string> written = files.paths();
  std::printf("%8s %9s %8s %10s %10s %9s %7s %7s %6s\n", "wind", "rpm", "pitch", "P_aero kW", "P_gen kW", "T kN", "Cp",
              "Ct", "TSR");
  for (const SteadyState& s : rows) {
    const SteadyRow r = steadyRow(m, s);
    std::printf("%8.2f %9.4f %8.4f %10.1f %10.1f %9.2f %7.4f %7.4f %6.3f\n", *s.condition.wind_speed,
                s.condition.rotor_speed * 30 / kPi, s.condition.collective_pitch.value_or(0) * 180 / kPi,
                s.aero_torque * s.condition.rotor_speed / 1e3, r.values[4], s.thrust / 1e3, r.cp, r.ct, r.tsr);
  }
  std::printf("wrote");
  for (const auto& f : written) std::printf(" %s", f.c_str());
  std::printf("\n%zu operating points, %.2f s", rows.size(),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  if (parallel::size() > 1) std::printf(" on %d MPI ranks", parallel::size());
  std::printf("\n");
}

}  // namespace

void addSteadyCommand(CLI::App& app) {
  auto opt = std::make_shared<SteadyOptions>();
  CLI::App* cmd = app.add_subcommand(
      "steady",
      "Steady operating points of an aeroelastic model: trimmed along the wind (rotor speed below rated, pitch "
      "above) or at a schedule; writes steady.csv (power, torque, thrust, Cp, Ct, TSR, deflections) and a plot");
  addModelOptions(*cmd, opt->model, false);
  cmd->add_option("--wind", opt->wind_range, "wind speeds START:STEP:STOP [m/s], trimmed");
  cmd->add_option("--schedule", opt->schedule, "operating schedule CSV (WindSpeed, RotSpeed, BldPitch columns)");
  addTrimAzimuths(*cmd, opt->azimuths);
  cmd->add_option("--out", opt->out, "output folder (default reports/<case name>)");
  cmd->add_flag("--no-plot", opt->no_plot, "write the table and the Gnuplot script, do not run Gnuplot");
  cmd->callback([opt]() { run(*opt); });
}

}  // namespace whirl::cli
