// `whirl simulate`: the nonlinear equations integrated in time (SUNDIALS IDA, linearize/simulate.hpp)
// from the model's initial point or its equilibrium, with initial displacements and input histories:
// writes timeseries.csv, timeseries.gp and PNG/SVG.
#include <unistd.h>

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "linearize/rosco_step.hpp"
#include "linearize/simulate.hpp"
#include "linearize/simulation_setup.hpp"
#include "linearize/trim.hpp"
#include "src/base/error.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/io/openfast/servodyn/discon_input.hpp"
#include "src/io/text/time_signal_reader.hpp"
#include "src/writers/output_set.hpp"
#include "src/writers/timeseries_output.hpp"

namespace whirl::cli {
namespace {

struct SimulateOptions {
  ModelOptions model;
  double tmax = 0, dt_out = 0.01, rtol = 1e-6, atol = 1e-8;
  std::vector<std::string> init, inputs, drives;
  bool free_rotor = false, equilibrium = false, no_plot = false, closed_loop = false;
  std::optional<double> wind;
  double controller_dt = 0.01;
  std::string out, plot;
};

// "NAME=v" (absolute), "NAME+=v" (offset from the start point), "NAME rate=v" (the rate).
void applyInit(const Model& m, OperatingPoint& p, const std::string& text) {
  const auto [name, value_text] = splitAssignment(text, "--init");
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(value_text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  // The name first: an unknown coordinate is named before its value is read, as it always was.
  OperatingPoint probe = p;
  applyInitialCondition(m, probe, name, 0, "--init");
  if (value_text.empty() || used != value_text.size() || !std::isfinite(v))
    throw InputError("--init: '" + text + "': '" + value_text + "' is not a finite number");
  applyInitialCondition(m, p, name, v, "--init");
}

void run(const SimulateOptions& opt) {
  // The deck's unsteady-airfoil and dynamic-inflow states in the simulation as in the linear models
  // (linearize/simulate_aero.hpp), unless --quasi-steady-aero.
  const Model m = loadModel(opt.model, true);
  requireActiveDof(m, m.name);
  OperatingPoint start = startPoint(m, opt.model);
  std::optional<RoscoController> controller;
  std::optional<SteadyState> steady;
  if (opt.closed_loop && !opt.wind)
    throw InputError("simulate: --closed-loop needs --wind U (it starts where ROSCO settles)");
  if (opt.wind) {
    // The trimmed steady state (with the deck's ROSCO controller when it names one), rotor free.
    if (opt.model.rpm || opt.equilibrium)
      throw InputError("simulate: --wind starts at the trimmed state: not with --rpm or --equilibrium");
    controller = opt.closed_loop ? closedLoopController(m, opt.model) : m.deck_controller;
    const WindStart w = windStart(m, *opt.wind, controller ? &*controller : nullptr);
    steady = w.steady;
    start = w.start;
    checkSolvedPoints(opt.model, m, {start});
  }
  if (opt.equilibrium) {
    start = solveOperatingPoint(m, start);
    checkSolvedPoints(opt.model, m, {start});
  }
  for (const std::string& s : opt.init) applyInit(m, start, s);
  SimulationOptions so;
  so.t_end = opt.tmax;
  so.dt_out = opt.dt_out;
  so.rtol = opt.rtol;
  so.atol = opt.atol;
  so.aero_states = true;
  if (!opt.free_rotor && !opt.wind) so.prescribed = m.roles.azimuth;
  if (opt.closed_loop) so.controller = roscoInTheLoop(m, *controller, *steady, opt.controller_dt, start);
  // Without --allow-invalid-point a diverging motion is an error: stop integrating at its first
  // invalid instant instead of at --tmax (docs/user/limits.md, *Blow-ups*).
  if (!opt.model.allow_invalid_point) so.stop = stopAtInvalidMotion(m);
  for (const std::string& s : opt.inputs) {
    const auto [name, signal] = splitAssignment(s, "--input");
    so.inputs.push_back({simulationInput(m, name, "--input"), parseTimeSignal(signal, "--input " + name)});
  }
  for (const std::string& s : opt.drives) {
    const auto [name, signal] = splitAssignment(s, "--drive");
    const int i = drivenCoordinate(m, name, "--drive");
    so.driven.push_back({i, parseTimeSignal(signal, "--drive " + name)});
    so.prescribed.erase(std::remove(so.prescribed.begin(), so.prescribed.end(), i), so.prescribed.end());
  }
  TimeseriesPlotOptions po;
  po.channels = splitList(opt.plot);
  po.render = !opt.no_plot;
  po.title = m.name + ": simulation";
  // Progress on a terminal only (as the sweeps: a log would depend on the timing).
  static const bool terminal = isatty(STDERR_FILENO) == 1;
  const auto t0 = std::chrono::steady_clock::now();
  auto wall = [t0] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  double shown = 0;
  so.progress = [&](double t, double t_end) {
    if (!terminal || wall() < shown + 0.5) return;
    shown = wall();
    std::fprintf(stderr, "\rsimulate: t = %.4g of %.4g s (%.1f s)", t, t_end, shown);
  };
  const Simulation sim = simulate(m, start, so);
  const double seconds = wall();
  if (shown > 0) std::fprintf(stderr, "\n");
  // The first recorded instant outside the model's range of validity (deflections, slopes:
  // linearize/point_validity.hpp) stops the command, as an operating point outside it does: a model
  // that blows up (negative damping: a 325 km tower deflection, issue 48, item 6) is no result to
  // write silently. A diverging motion can be what is studied (Kane's beam without geometric
  // stiffness): --allow-invalid-point writes it with a warning. docs/user/limits.md, *Blow-ups*.
  if (const std::optional<std::string> what = invalidMotion(m, sim)) {
    if (!opt.model.allow_invalid_point)
      throw ComputeError(*what + " (a diverging model; nothing written: --allow-invalid-point writes it anyway)");
    std::fprintf(stderr, "whirl: warning: %s: %s\n", opt.model.case_path.c_str(), what->c_str());
  }
  // Only now the output folder: a failed simulation writes nothing.
  const std::string dir = opt.out.empty() ? defaultOutputFolder(opt.model.case_path) : opt.out;
  prepareOutputFolder(dir);
  const std::vector<std::string> written = writeTimeseries(m, sim, dir, po);
  std::printf("simulated %g s in %.3g s (%.4g× real time): %ld steps, %ld residuals, %ld Jacobians, %zu states\n",
              opt.tmax, seconds, opt.tmax / std::max(seconds, 1e-9), sim.steps, sim.residual_evaluations,
              sim.jacobian_evaluations, 2 * sim.states.size() + static_cast<std::size_t>(sim.z.cols()));
  std::printf("wrote");
  for (const auto& w : written) std::printf(" %s", w.c_str());
  std::printf("\n");
}

}  // namespace

void addSimulateCommand(CLI::App& app) {
  auto opt = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "integrate the nonlinear equations in time (SUNDIALS IDA, AD Jacobians): writes timeseries.csv, "
      "timeseries.gp and PNG/SVG");
  addModelOptions(*cmd, opt->model, true);
  addAeroStateOptions(*cmd, opt->model);
  cmd->add_option("--tmax", opt->tmax, "simulated time [s]")->required()->check(CLI::PositiveNumber);
  cmd->add_option("--dt-out", opt->dt_out, "interval of the recorded instants [s]")->check(CLI::PositiveNumber);
  cmd->add_option("--init", opt->init,
                  "initial condition 'DOF=value', 'DOF+=offset' (from the start point) or 'DOF rate=value' "
                  "(SI units: m, rad, per s); repeatable");
  cmd->add_option("--input", opt->inputs,
                  "input history 'NAME=step(t0,a)', 'ramp(t0,t1,a)', 'sin(A,f)' (added to the input's value) or "
                  "'NAME=file.csv' (columns time, value); repeatable");
  cmd->add_option("--drive", opt->drives,
                  "prescribed motion of a coordinate from its start value, 'DOF=spinup(T,w)' (Kane's spin-up: "
                  "acceleration (w/T)(1 - cos 2 pi t/T), then rate w) or any --input signal; repeatable");
  cmd->add_option(
         "--wind", opt->wind,
         "start at the steady state trimmed at this wind speed [m/s] (with the deck's ROSCO controller when it "
         "names one), the rotor free")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--closed-loop", opt->closed_loop,
                "with --wind: ROSCO's controller of the deck in the loop, setting generator torque and pitch every "
                "--controller-dt");
  cmd->add_option("--controller-dt", opt->controller_dt, "the controller's time step [s] (default 0.01)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--free-rotor", opt->free_rotor,
                "the rotor azimuth is a state (starting at --rpm); otherwise the rotor turns at the constant --rpm");
  cmd->add_flag("--equilibrium", opt->equilibrium,
                "start from the solved operating point (then --init 'DOF+=offset' perturbs it)");
  cmd->add_option("--rtol", opt->rtol, "IDA relative tolerance")->check(CLI::PositiveNumber);
  cmd->add_option("--atol", opt->atol, "IDA absolute tolerance [m, rad, m/s, rad/s]")->check(CLI::PositiveNumber);
  cmd->add_option("--plot", opt->plot,
                  "columns of timeseries.csv to plot, comma-separated (default: the integrated coordinates)");
  cmd->add_option("--out", opt->out, "output folder (default reports/<case name>)");
  cmd->add_flag("--no-plot", opt->no_plot, "write the table and the Gnuplot script, do not run Gnuplot");
  cmd->callback([opt]() { runWithCaseSource(opt->model.case_path, [&] { run(*opt); }); });
}

}  // namespace whirl::cli
