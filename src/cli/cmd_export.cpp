#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <sstream>

#include "linearize/export_sweep.hpp"
#include "linearize/rosco_linear.hpp"
#include "linearize/state_space.hpp"
#include "linearize/sweep.hpp"
#include "linearize/trim.hpp"
#include "modal/closed_loop_modes.hpp"
#include "src/base/error.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/io/openfast/servodyn/discon_input.hpp"
#include "src/io/text/schedule.hpp"
#include "src/parallel/session.hpp"
#include "src/writers/output_set.hpp"
#include "src/writers/state_space_files.hpp"

namespace whirl::cli {
namespace {

struct CliOptions {
  ModelOptions model;
  std::string schedule, wind_range, format, out, inputs, outputs;
  int azimuths = 36;
  bool drop_azimuth = false;
  bool closed_loop = false, without_speed_filter = false;
};

/// `export --closed-loop`: at each trimmed wind speed the turbine with the deck's ROSCO controller as
/// one model (linearize/closed_loop.hpp): the open-loop plant's states (multiblade average, azimuth
/// dropped), then the controller's, named "controller: …"; the plant's inputs and outputs.
std::vector<ExportPoint> closedLoopPoints(const Model& base, const CliOptions& opt) {
  if (opt.wind_range.empty()) throw InputError("export: --closed-loop needs --wind START:STEP:STOP");
  if (opt.format == "lin")
    throw InputError(
        "export: --closed-loop writes --format mat or json (a .lin file holds OpenFAST's open-loop plant)");
  if (!opt.inputs.empty() || !opt.outputs.empty())
    throw InputError(
        "export: --closed-loop keeps every input and output (--inputs/--outputs select the open-loop plant's)");
  const std::optional<RoscoController> controller = closedLoopController(base, opt.model);
  TrimOptions trim;
  trim.controller = &*controller;
  ClosedLoopOptions clo;
  clo.azimuths = opt.azimuths;
  RoscoLinearOptions ro;
  ro.without_speed_filter = opt.without_speed_filter;
  std::vector<ExportPoint> points;
  std::string first_region;
  std::vector<std::string> first_states;
  for (const SteadyState& s : trimSchedule(base, parseRange(opt.wind_range, "--wind"), trim)) {
    // One file holds models of one set of states (ROSCO's reader interpolates them along the wind);
    // the controller's states change where a loop saturates.
    const LinearController k = linearRosco(*controller, s, ro);
    std::vector<std::string> states;
    for (const StateSpaceVariable& v : controllerStateSpace(k).x) states.push_back(v.name);
    if (points.empty()) first_region = s.region, first_states = states;
    if (states != first_states)
      throw InputError(
          fmt::format("export: --closed-loop: the controller's states differ between {:g} m/s (region {}) "
                      "and {:g} m/s (region {}): export each region's wind speeds separately",
                      *points.front().wind_speed, first_region, *s.condition.wind_speed, s.region));
    ExportPoint e;
    e.rpm = s.condition.rotor_speed * 30 / std::numbers::pi;
    e.wind_speed = s.condition.wind_speed;
    e.pitch_deg = s.condition.collective_pitch.value_or(0) * 180 / std::numbers::pi;
    e.model = closedLoopPoint(base, s, k, clo).closed;
    points.push_back(std::move(e));
  }
  return points;
}

// Fails before any computation when a name is unknown.
void checkNames(const Model& m, const std::vector<std::string>& inputs, const std::vector<std::string>& outputs) {
  auto list = [](const auto& items) {
    std::string s;
    for (const auto& i : items) s += (s.empty() ? "" : ", ") + i.name;
    return s.empty() ? std::string("none") : s;
  };
  for (const auto& n : inputs)
    if (!m.findInput(n)) throw InputError("--inputs: unknown input '" + n + "' (inputs: " + list(m.inputs) + ")");
  if (!outputs.empty() && m.outputs.empty())
    throw InputError("--outputs: the model defines no outputs (add an `outputs:` section to the case file)");
  for (const auto& n : outputs)
    if (!m.findOutput(n)) throw InputError("--outputs: unknown output '" + n + "' (outputs: " + list(m.outputs) + ")");
}

// "<schedule>: operating point <k> ", what an error at schedule row k starts with (whichever rank runs
// it, the user sees which point failed; the sweep adds its rotor speed, wind speed, pitch and azimuth).
std::string scheduleContext(const std::string& schedule, int k) {
  return schedule + ": operating point " + std::to_string(k + 1) + " ";
}

void run(const CliOptions& opt) {
  if (opt.without_speed_filter && !opt.closed_loop)
    throw InputError("export: --without-speed-filter goes with --closed-loop");
  if (bool(opt.model.rpm) + !opt.schedule.empty() + !opt.wind_range.empty() > 1)
    throw InputError("export: give at most one of --rpm, --schedule and --wind");
  const std::vector<std::string> in = splitList(opt.inputs), out = splitList(opt.outputs);
  const Model base = loadModel(opt.model, true);
  checkNames(base, in, out);
  const std::string dir = opt.out.empty() ? defaultOutputFolder(opt.model.case_path) : opt.out;
  prepareOutputFolder(dir);

  StateSpaceExport e;
  e.source = opt.model.case_path;
  e.model_name = base.name;
  std::vector<SweepPoint> points;
  if (opt.closed_loop) {
    e.points = closedLoopPoints(base, opt);
  } else if (!opt.schedule.empty()) {
    points = readSchedule(opt.schedule);
    if (base.roles.azimuth.empty())
      throw InputError("--rpm: the model has no rotating DOF (mark the azimuth with `rotating: true`)");
  } else if (!opt.wind_range.empty()) {
    // Each wind speed trimmed, as `whirl steady` (with the deck's ROSCO controller when it has one).
    const std::optional<RoscoController>& controller = base.deck_controller;
    TrimOptions trim;
    if (controller) trim.controller = &*controller;
    points = trimmedPoints(base, opt.wind_range, trim);
  } else {
    SweepPoint p;  // the model's own rotor speed, or --rpm
    p.condition = operatingCondition(base, opt.model);
    p.rpm = p.condition.rotor_speed * 30 / std::numbers::pi;
    points.push_back(p);
  }
  ExportOptions eo;
  eo.azimuths = opt.azimuths;
  eo.inputs = in;
  eo.outputs = out;
  eo.drop_azimuth = opt.drop_azimuth;
  // One task per operating point, spread over the ranks under mpirun (linearize/export_sweep.hpp).
  if (parallel::launchedByMpi()) parallel::requirePetsc("mpirun");  // start-up before the progress clock
  SweepOptions sweep;
  sweep.azimuths = opt.azimuths;
  sweep.progress = sweepProgress("export");
  if (!opt.schedule.empty()) sweep.context = [&](int k) { return scheduleContext(opt.schedule, k); };
  sweep.check_point = [&opt](const Model& m, const std::vector<OperatingPoint>& ops, const SweepPoint& sp) {
    const bool labelled = !opt.schedule.empty() || !opt.wind_range.empty();
    return checkSolvedPoints(opt.model, m, ops, labelled ? fmt::format("{:g} rpm", sp.rpm) : "");
  };
  if (!opt.closed_loop) e.points = exportSweep(base, points, eo, sweep);
  if (parallel::rank() != 0) return;  // under mpirun: rank 0 writes

  OutputSet files(dir);  // every file of the run appears at once, or none
  std::string title = e.model_name.substr(0, e.model_name.find(". "));  // ElastoDyn headers run long
  if (title.empty()) title = opt.model.case_path;
  writeStateSpaceFiles(e, opt.format, title, files);
  files.commit();
  const StateSpaceModel& m = e.points.front().model;
  const std::string mbc =
      opt.closed_loop
          ? " (closed loop: the multiblade-averaged plant without its azimuth, then the controller's states)"
      : m.multiblade ? " (multiblade average over " + std::to_string(e.points.front().azimuths.size()) + " azimuths)"
                     : "";
  const std::string ranks = parallel::size() > 1 ? ", on " + std::to_string(parallel::size()) + " MPI ranks" : "";
  std::printf("wrote %zu file%s in %s: %zu operating point%s, %zu states, %zu inputs, %zu outputs%s%s\n",
              files.paths().size(), files.paths().size() == 1 ? "" : "s", dir.c_str(), e.points.size(),
              e.points.size() == 1 ? "" : "s", m.x.size(), m.u.size(), m.y.size(), mbc.c_str(), ranks.c_str());
}

}  // namespace

void addExportCommand(CLI::App& app) {
  auto opt = std::make_shared<CliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "export",
      "state-space model(s) A, B, C, D with named inputs and outputs for controller design: MATLAB .mat, "
      "OpenFAST-style .lin (one per azimuth) or JSON");
  addModelOptions(*cmd, opt->model);
  addAeroStateOptions(*cmd, opt->model);
  cmd->add_option("--schedule", opt->schedule, "operating schedule CSV (wind speed, RotSpeed, BldPitch columns)");
  cmd->add_option("--wind", opt->wind_range,
                  "wind speeds START:STEP:STOP [m/s], each trimmed as `whirl steady` (aerodynamic models with a "
                  "generator torque law)");
  addMultibladeAzimuths(*cmd, opt->azimuths);
  cmd->add_option("--format", opt->format, "mat, lin or json")
      ->required()
      ->check(CLI::IsMember({"mat", "lin", "json"}));
  cmd->add_option("--out", opt->out, "output folder (default reports/<case name>)");
  cmd->add_option("--inputs", opt->inputs, "keep these inputs, comma-separated, in this order (default: all)");
  cmd->add_option("--outputs", opt->outputs, "keep these outputs, comma-separated, in this order (default: all)");
  cmd->add_flag("--closed-loop", opt->closed_loop,
                "with --wind: the turbine with the deck's ROSCO controller as one model, the controller's states named "
                "'controller: ...' after the plant's (azimuth dropped); --format mat or json");
  cmd->add_flag("--without-speed-filter", opt->without_speed_filter,
                "with --closed-loop: leave the controller's generator-speed low pass out");
  cmd->add_flag("--drop-azimuth", opt->drop_azimuth, "remove the rotor azimuth state (keep the rotor speed)");
  cmd->callback([opt]() { runWithCaseSource(opt->model.case_path, [&] { run(*opt); }); });
}

}  // namespace whirl::cli
