#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "linearize/sweep.hpp"
#include "linearize/trim.hpp"
#include "modal/campbell_diagram.hpp"
#include "modal/closed_loop_campbell.hpp"
#include "modal/tracking.hpp"
#include "src/base/error.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/io/openfast/servodyn/discon_input.hpp"
#include "src/io/text/schedule.hpp"
#include "src/parallel/session.hpp"
#include "src/writers/campbell_output.hpp"
#include "src/writers/closed_loop_tables.hpp"
#include "src/writers/output_set.hpp"

namespace whirl::cli {
namespace {

struct CampbellOptions {
  ModelOptions model;
  std::string rpm_range, schedule, wind_range, out, tracking;
  int azimuths = 36;
  std::string versus = "auto";
  double max_freq = 0;
  bool no_plot = false;
  bool first_order_lines = false;
  std::vector<std::string> formats;
  bool html = false;
  bool closed_loop = false, without_speed_filter = false;
};

/// `campbell --closed-loop`: the deck's ROSCO controller in the loop at each trimmed wind speed
/// (modal/closed_loop_campbell.hpp), the closed loop's Campbell files, the open loop's beside them,
/// the roots and the loop margins (src/writers/closed_loop_tables.hpp).
void runClosedLoop(const CampbellOptions& opt) {
  if (opt.wind_range.empty())
    throw InputError(
        "campbell: --closed-loop needs --wind START:STEP:STOP (the controller's steady states along the wind)");
  if (!opt.formats.empty() || !opt.schedule.empty() || !opt.rpm_range.empty())
    throw InputError("campbell: --closed-loop goes with --wind alone, without --rpm, --schedule or --format");
  const Model m = loadModel(opt.model, true);
  const std::optional<RoscoController> controller = closedLoopController(m, opt.model);
  for (const std::string& n : controller->notes) std::fprintf(stderr, "whirl: note: %s\n", n.c_str());
  for (const std::string& n : linearRoscoNotes(*controller))
    std::fprintf(stderr, "whirl: note: %s: linear model: %s\n", controller->file.c_str(), n.c_str());
  const std::string dir = opt.out.empty() ? defaultOutputFolder(opt.model.case_path) : opt.out;
  prepareOutputFolder(dir);
  const auto start = std::chrono::steady_clock::now();
  TrimOptions trim;
  trim.controller = &*controller;
  const std::vector<SteadyState> schedule = trimSchedule(m, parseRange(opt.wind_range, "--wind"), trim);
  ClosedLoopCampbellOptions clo;
  clo.point.azimuths = opt.azimuths;
  clo.controller.without_speed_filter = opt.without_speed_filter;
  clo.tracking.overrides_file = opt.tracking;
  clo.progress = sweepProgress("campbell");
  ClosedLoopCampbell c = closedLoopCampbell(m, *controller, schedule, clo);
  c.closed.title = "Closed-loop " + campbellTitle(m, opt.model.case_path);
  c.open.title = "Open-loop " + campbellTitle(m, opt.model.case_path);
  for (const ClosedLoopPoint& p : c.points)
    if (!p.stable)
      std::fprintf(stderr, "whirl: warning: the closed loop is unstable at %g m/s (least damping ratio %.3g %%)\n",
                   p.steady.condition.wind_speed.value_or(0), 100 * p.least_damping);
  CampbellPlotOptions plot;
  plot.versus_wind_speed = opt.versus != "rpm";
  plot.max_freq_hz = opt.max_freq;
  plot.render = !opt.no_plot;
  plot.first_order_lines = true;
  plot.html = opt.html;
  plot.summary = {{"case", opt.model.case_path},
                  {"sweep", "--wind " + opt.wind_range + " --closed-loop"},
                  {"controller", controller->file},
                  {"azimuths", std::to_string(opt.azimuths)},
                  {"operating points", std::to_string(c.points.size())}};
  const auto files = writeClosedLoopCampbell(c, dir, plot);
  std::printf("wrote");
  for (const auto& f : files) std::printf(" %s", f.c_str());
  int stable = 0;
  for (const ClosedLoopPoint& p : c.points) stable += p.stable ? 1 : 0;
  std::printf(
      "\n%zu operating points (%d with a stable closed loop), %zu closed-loop lines, %d azimuths each, %.2f s\n",
      c.points.size(), stable, c.closed.lines.size(), opt.azimuths,
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

void run(const CampbellOptions& opt) {
  if (opt.closed_loop) return runClosedLoop(opt);
  if (opt.without_speed_filter) throw InputError("campbell: --without-speed-filter goes with --closed-loop");
  if (opt.rpm_range.empty() + opt.schedule.empty() + opt.wind_range.empty() != 2)
    throw InputError("campbell: give exactly one of --rpm START:STEP:STOP, --schedule FILE and --wind START:STEP:STOP");
  const Model m = loadModel(opt.model, true);
  // Along the wind: trimmed with the deck's ROSCO controller when it has one (docs/user/controller.md).
  auto trimmed = [&] {
    const std::optional<RoscoController>& controller = m.deck_controller;
    TrimOptions trim;
    if (controller) trim.controller = &*controller;
    return trimmedPoints(m, opt.wind_range, trim);
  };
  const std::vector<SweepPoint> points = !opt.rpm_range.empty()  ? rpmRange(opt.rpm_range)
                                         : !opt.schedule.empty() ? readSchedule(opt.schedule)
                                                                 : trimmed();
  const std::string dir = opt.out.empty() ? defaultOutputFolder(opt.model.case_path) : opt.out;
  prepareOutputFolder(dir);

  if (parallel::launchedByMpi()) parallel::requirePetsc("mpirun");  // start-up outside the timing
  CampbellDiagramOptions cd;
  cd.sweep.azimuths = opt.azimuths;
  cd.sweep.check_point = [&opt](const Model& pm, const std::vector<OperatingPoint>& ops, const SweepPoint& sp) {
    return checkSolvedPoints(opt.model, pm, ops, fmt::format("{:g} rpm", sp.rpm));
  };
  const auto start = std::chrono::steady_clock::now();
  cd.sweep.progress = sweepProgress("campbell");
  cd.tracking.overrides_file = opt.tracking;
  cd.title = campbellTitle(m, opt.model.case_path);
  const CampbellDiagram d = campbellDiagram(m, points, cd);
  if (parallel::rank() != 0) return;  // under mpirun: rank 0 writes
  // Negative damping is an instability: say where, one line per tracked mode.
  for (const LineInstability& u : lineInstabilities(d)) {
    const CampbellPoint& p = d.points[u.at];
    const std::string where = p.wind_speed ? fmt::format("{:g} m/s", *p.wind_speed) : fmt::format("{:g} rpm", p.rpm);
    std::fprintf(stderr,
                 "whirl: warning: %s is unstable (negative damping) at %d of %zu points; lowest %.3g %% at %s\n",
                 u.name.c_str(), u.points, d.points.size(), 100 * u.lowest_damping, where.c_str());
  }

  CampbellPlotOptions plot;
  plot.versus_wind_speed = opt.versus == "wind" || (opt.versus == "auto" && opt.rpm_range.empty());
  plot.max_freq_hz = opt.max_freq;
  plot.render = !opt.no_plot;
  plot.first_order_lines = opt.first_order_lines;
  plot.formats = opt.formats;
  plot.html = opt.html;
  plot.summary = {{"case", opt.model.case_path},
                  {"sweep", !opt.rpm_range.empty()  ? "--rpm " + opt.rpm_range
                            : !opt.schedule.empty() ? "--schedule " + opt.schedule
                                                    : "--wind " + opt.wind_range},
                  {"azimuths", std::to_string(opt.azimuths)},
                  {"operating points", std::to_string(d.points.size())},
                  {"lines", std::to_string(d.lines.size())}};
  for (const auto& s : opt.model.sets) plot.summary.emplace_back("--set", s);
  noteHiddenFirstOrderLines(d, plot);
  const auto files = writeCampbell(d, dir, plot);
  std::printf("wrote");
  for (const auto& f : files) std::printf(" %s", f.c_str());
  std::printf("\n%zu operating points, %zu lines, %d azimuths each, %.2f s", d.points.size(), d.lines.size(),
              opt.azimuths, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  if (parallel::size() > 1) std::printf(" on %d MPI ranks", parallel::size());
  std::printf("\n");
}

}  // namespace

void addCampbellCommand(CLI::App& app) {
  auto opt = std::make_shared<CampbellOptions>();
  CLI::App* cmd = app.add_subcommand(
      "campbell",
      "Campbell diagram: periodic linearization at each rotor speed, multiblade transform, modes named and "
      "tracked; writes campbell.csv, campbell_modes.json, campbell.gp/.dat and PNG/SVG");
  addModelOptions(*cmd, opt->model, false);
  cmd->add_option("--rpm", opt->rpm_range, "rotor speeds START:STEP:STOP [rpm]");
  cmd->add_option("--schedule", opt->schedule, "operating schedule CSV (wind speed, RotSpeed, BldPitch columns)");
  cmd->add_option("--wind", opt->wind_range,
                  "wind speeds START:STEP:STOP [m/s], each trimmed (rotor speed below rated, pitch above; needs "
                  "aerodynamics and a generator torque law)");
  addMultibladeAzimuths(*cmd, opt->azimuths);
  cmd->add_option("--out", opt->out, "output folder (default reports/<case name>)");
  cmd->add_option("--tracking", opt->tracking,
                  "mode-tracking overrides file (rename, assign; docs/theory/mode-tracking.md)");
  cmd->add_option("--versus", opt->versus, "x axis: rpm, wind or auto (wind with --schedule or --wind)")
      ->check(CLI::IsMember({"rpm", "wind", "auto"}));
  cmd->add_option("--max-freq", opt->max_freq, "top of the frequency axis [Hz] (default: automatic)");
  cmd->add_flag("--no-plot", opt->no_plot, "write the tables and the Gnuplot script, do not run Gnuplot");
  cmd->add_flag(
      "--first-order-lines", opt->first_order_lines,
      "also draw the lines of first-order states' roots (HydroDyn radiation), which are in the tables anyway");
  cmd->add_option("--format", opt->formats,
                  "also write these formats (repeatable or comma-separated): hawcstab2 (campbell.cmb, .amp, .opt), "
                  "openfast (openfast_toolbox's Campbell_ModesID.csv, Campbell_OP.csv, Campbell_PointNN.csv, "
                  "Campbell_Summary.txt), vtk (mode_<line>_p<point>.pvd animations of .vtp polylines for ParaView)")
      ->delimiter(',')
      ->check(CLI::IsMember({"hawcstab2", "openfast", "vtk"}));
  cmd->add_flag("--closed-loop", opt->closed_loop,
                "with --wind: the deck's ROSCO controller in the loop (its states beside the structure's); writes the "
                "closed loop's Campbell files, open_loop_campbell.csv, closed_loop_modes.csv, margins.csv and "
                "closed_loop.gp/.png");
  cmd->add_flag(
      "--without-speed-filter", opt->without_speed_filter,
      "with --closed-loop: leave the controller's generator-speed low pass out (as ROSCO's own linear tools do)");
  addAeroStateOptions(*cmd, opt->model);
  cmd->add_flag(
      "--html", opt->html,
      "also write campbell.html: the interactive report (diagram, mode shapes, tables), one file, no network");
  cmd->callback([opt]() { runWithCaseSource(opt->model.case_path, [&] { run(*opt); }); });
}

}  // namespace whirl::cli
