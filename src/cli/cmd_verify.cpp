// `whirl verify`: the linear model at the equilibrium against the nonlinear equations — free decays
// of amplitude ε, ε/2, ε/4 (modal/nonlinear_check.hpp) — printing the differences, their observed
// order (at least 2 when the exported A is the nonlinear system's Jacobian) and the frequencies and damping
// identified from the decay next to the eigenvalues. With --closed-loop: the ROSCO-controlled turbine's
// response to a small wind step, nonlinear with ROSCO's discrete laws vs the linear closed loop
// (modal/closed_loop_step.hpp).
#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "linearize/trim.hpp"
#include "modal/aero_roots.hpp"
#include "modal/closed_loop_step.hpp"
#include "modal/era.hpp"
#include "modal/nonlinear_check.hpp"
#include "src/base/error.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/writers/closed_loop_step_table.hpp"
#include "src/writers/gnuplot.hpp"
#include "src/writers/output_set.hpp"

namespace whirl::cli {
namespace {

struct VerifyOptions {
  ModelOptions model;
  std::vector<std::string> dofs;
  NonlinearCheckOptions check;
  bool closed_loop = false;
  std::optional<double> wind;
  ClosedLoopStepOptions step;
  std::string out;
  bool tmax_given = false, dt_given = false, no_plot = false;
};

/// The closed loop: a wind step from the point ROSCO settles at, nonlinear vs linear.
void runClosedLoop(const VerifyOptions& opt) {
  if (!opt.wind) throw InputError("verify: --closed-loop needs --wind U (the step starts where ROSCO settles)");
  if (!opt.dofs.empty()) throw InputError("verify: --dof perturbs the open loop's coordinates, not with --closed-loop");
  ClosedLoopStepOptions so = opt.step;
  if (opt.tmax_given) so.t_end = opt.check.t_end;
  if (opt.dt_given) so.dt_out = opt.check.dt_out;
  // The library's checks again under the options' names, before the trim.
  if (!(so.wind_step != 0) || !std::isfinite(so.wind_step)) throw InputError("verify: --wind-step: must be non-zero");
  if (!(so.step_time < so.t_end))
    throw InputError("verify: --step-time: the step must come before the end (--tmax " + fmt::format("{:g}", so.t_end) +
                     " s)");
  for (size_t i = 0; i < so.outputs.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (so.outputs[i] == so.outputs[j]) throw InputError("verify: --output: " + so.outputs[i] + " given twice");
  const Model m = loadModel(opt.model);
  const RoscoController c = closedLoopController(m, opt.model);
  TrimOptions trim;
  trim.controller = &c;
  trim.azimuths = opt.step.azimuths;
  const SteadyState st = trimAtWindSpeed(m, *opt.wind, trim);
  const ClosedLoopStep r = closedLoopStep(m, c, st, so);
  const std::string dir = opt.out.empty() ? defaultOutputFolder(opt.model.case_path) : opt.out;
  prepareOutputFolder(dir);
  OutputSet files(dir);
  files.write("closed_loop_step.csv", closedLoopStepCsv(r, *opt.wind, so));
  files.write("closed_loop_step.gp", closedLoopStepGnuplot(r, *opt.wind, so));
  if (!opt.no_plot) renderGnuplot(files.stagingFolder(), "gnuplot", "closed_loop_step", dir);
  files.commit();
  std::printf(
      "wind step %g m/s at %g s from %g m/s (region %s): nonlinear with ROSCO's discrete laws (every %g s) "
      "vs the linear closed loop (%d azimuths, quasi-steady induction)\n",
      so.wind_step, so.step_time, *opt.wind, st.region.c_str(), so.controller_dt, so.azimuths);
  std::printf("  %-20s %-8s %-14s %-22s %s\n", "signal", "unit", "peak |linear|", "max |nonlinear - linear|",
              "up to t_step + 4.5 s");
  for (const ClosedLoopStepSignal& s : r.signals)
    std::printf("  %-20s %-8s %-14.5g %-12.5g (%5.1f %%)   %-12.5g (%5.1f %%)\n", s.name.c_str(), s.unit.c_str(),
                s.peak, s.max_difference, s.peak > 0 ? 100 * s.max_difference / s.peak : 0.0, s.early_difference,
                s.peak > 0 ? 100 * s.early_difference / s.peak : 0.0);
  std::printf("wrote");
  for (const auto& f : files.paths()) std::printf(" %s", f.c_str());
  std::printf("\n");
}

void run(const VerifyOptions& opt) {
  if (opt.closed_loop) return runClosedLoop(opt);
  if (opt.wind) throw InputError("verify: --wind is for --closed-loop");
  requireCheckOptions(opt.check);  // before the model is read and its operating point solved
  // The deck's unsteady-airfoil and dynamic-inflow states in both models, unless --quasi-steady-aero.
  const Model m = loadModel(opt.model, true);
  requireActiveDof(m, m.name);
  const OperatingPoint eq = solveOperatingPoint(m, startPoint(m, opt.model));
  checkSolvedPoints(opt.model, m, {eq});
  NonlinearCheckOptions co = opt.check;
  co.aero_states = true;
  for (const std::string& name : opt.dofs) {
    const auto i = m.findDof(name);
    if (!i) throw InputError("--dof: '" + name + "': no such coordinate");
    co.dofs.push_back(*i);
  }
  const NonlinearCheck c = checkAgainstLinear(m, eq, co);
  std::printf("nonlinear free decay vs the linear model at the equilibrium (%g s):\n", co.t_end);
  if (c.aero_states > 0)
    std::printf(
        "  with %d aerodynamic states (unsteady airfoil, dynamic inflow) in both, on the equilibrium's frozen "
        "wake\n",
        c.aero_states);
  std::printf("  %-12s %-16s %-16s %s\n", "amplitude", "max |q - q_lin|", "max |q_lin|", "order");
  for (size_t k = 0; k < c.levels.size(); ++k) {
    const NonlinearCheckLevel& l = c.levels[k];
    if (k == 0) std::printf("  %-12.6g %-16.6g %.6g\n", l.amplitude, l.max_difference, l.max_response);
    else
      std::printf("  %-12.6g %-16.6g %-16.6g %.3f\n", l.amplitude, l.max_difference, l.max_response, c.orders[k - 1]);
  }
  std::printf("identified from the decay (amplitude %g) vs eigenvalues:\n", co.amplitude);
  std::printf("  %-24s %-14s %-12s | %-14s %-12s | %-24s %-14s %s\n", "coordinate", "damped f [Hz]", "damping",
              "realized [Hz]", "damping", "mode", "damped f [Hz]", "damping");
  for (const IdentifiedComparison& r : compareWithModes(m, c)) {
    const Mode* best = r.mode >= 0 ? &c.modes[static_cast<size_t>(r.mode)] : nullptr;
    std::printf("  %-24s %-14.6g %-12.5g | %-14.6g %-12.5g | %-24s %-14.6g %.5g\n", r.coordinate.c_str(),
                r.decay.damped_freq_hz, r.decay.damping_ratio, r.pole ? r.pole->damped_freq_hz : NAN,
                r.pole ? r.pole->damping_ratio : NAN, best ? best->name.c_str() : "-",
                best ? best->damped_freq_hz : NAN, best ? best->damping_ratio : NAN);
  }
}

}  // namespace

void addVerifyCommand(CLI::App& app) {
  auto opt = std::make_shared<VerifyOptions>();
  CLI::App* cmd = app.add_subcommand(
      "verify",
      "check the linear model against the nonlinear equations: free decays of amplitude e, e/2, e/4 from the "
      "equilibrium (simulate) against exp(A t) x0; prints the differences, their order (at least 2 expected) and the "
      "identified frequencies next to the eigenvalues");
  addModelOptions(*cmd, opt->model, true);
  addAeroStateOptions(*cmd, opt->model);
  cmd->add_option("--dof", opt->dofs, "coordinate perturbed (repeatable; default: every non-rotating active one)");
  cmd->add_option("--amplitude", opt->check.amplitude, "largest perturbation e [m or rad], at most 1 (default 0.01)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--levels", opt->check.levels, "number of amplitudes (halved each time)")->check(CLI::Range(2, 8));
  cmd->add_option("--tmax", opt->check.t_end, "simulated time [s] (--closed-loop: default 12)")
      ->check(CLI::PositiveNumber)
      ->each([opt](const std::string&) { opt->tmax_given = true; });
  cmd->add_option("--dt-out", opt->check.dt_out, "sampling interval [s] (--closed-loop: default 0.05)")
      ->check(CLI::PositiveNumber)
      ->each([opt](const std::string&) { opt->dt_given = true; });
  cmd->add_flag("--closed-loop", opt->closed_loop,
                "instead: the deck's ROSCO controller in the loop, a wind step from the steady state at --wind, the "
                "nonlinear response (ROSCO's discrete laws) against the linear closed loop's; writes "
                "closed_loop_step.csv/.gp/.png");
  cmd->add_option("--wind", opt->wind, "with --closed-loop: the wind speed trimmed at [m/s]")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--wind-step", opt->step.wind_step, "with --closed-loop: the step [m/s] (default 0.1)");
  cmd->add_option("--step-time", opt->step.step_time, "with --closed-loop: when the step comes [s] (default 1)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--controller-dt", opt->step.controller_dt,
                  "with --closed-loop: ROSCO's time step [s] (default 0.01)")
      ->check(CLI::PositiveNumber);
  cmd->add_option(
         "--azimuths", opt->step.azimuths,
         "with --closed-loop: equilibria per blade passage of the trim, and of the linear model's multiblade average")
      ->check(CLI::Range(1, 360));
  cmd->add_option("--output", opt->step.outputs,
                  "with --closed-loop: plant output compared (repeatable; default GenSpeed and TTDspFA; the pitch "
                  "command always)");
  cmd->add_option("--out", opt->out, "with --closed-loop: output folder (default reports/<case name>)");
  cmd->add_flag("--no-plot", opt->no_plot, "with --closed-loop: write the Gnuplot script without running Gnuplot");
  cmd->callback([opt]() { runWithCaseSource(opt->model.case_path, [&] { run(*opt); }); });
}

}  // namespace whirl::cli
