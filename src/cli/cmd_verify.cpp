// `whirl verify`: the linear model at the equilibrium against the nonlinear equations — free decays
// of amplitude ε, ε/2, ε/4 (modal/nonlinear_check.hpp) — printing the differences, their observed
// order (at least 2 when the exported A is the nonlinear system's Jacobian) and the frequencies and damping
// identified from the decay next to the eigenvalues.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "modal/era.hpp"
#include "modal/nonlinear_check.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/model/error.hpp"

namespace whirl::cli {
namespace {

struct VerifyOptions {
  ModelOptions model;
  std::vector<std::string> dofs;
  NonlinearCheckOptions check;
};

void run(const VerifyOptions& opt) {
  const Model m = loadModel(opt.model);
  requireActiveDof(m, m.name);
  const OperatingPoint eq = solveOperatingPoint(m, startPoint(m, opt.model));
  checkSolvedPoints(opt.model, m, {eq});
  NonlinearCheckOptions co = opt.check;
  for (const std::string& name : opt.dofs) {
    const auto i = m.findDof(name);
    if (!i) throw InputError("--dof: '" + name + "': no such coordinate");
    co.dofs.push_back(*i);
  }
  const NonlinearCheck c = checkAgainstLinear(m, eq, co);
  std::printf("nonlinear free decay vs the linear model at the equilibrium (%g s):\n", co.t_end);
  std::printf("  %-12s %-16s %-16s %s\n", "amplitude", "max |q - q_lin|", "max |q_lin|", "order");
  for (size_t k = 0; k < c.levels.size(); ++k) {
    const NonlinearCheckLevel& l = c.levels[k];
    if (k == 0)
      std::printf("  %-12.6g %-16.6g %.6g\n", l.amplitude, l.max_difference, l.max_response);
    else
      std::printf("  %-12.6g %-16.6g %-16.6g %.3f\n", l.amplitude, l.max_difference, l.max_response, c.orders[k - 1]);
  }
  std::printf("identified from the decay (amplitude %g) vs eigenvalues:\n", co.amplitude);
  std::printf("  %-24s %-14s %-12s | %-14s %-12s | %-24s %-14s %s\n", "coordinate", "damped f [Hz]", "damping",
              "realized [Hz]", "damping", "mode", "damped f [Hz]", "damping");
  const std::vector<int> active = m.activeDofs();  // the coordinates of the modes' participations
  for (size_t k = 0; k < c.identified.size(); ++k) {
    // The mode with the largest participation of this coordinate.
    const Mode* best = nullptr;
    const auto j = static_cast<Eigen::Index>(
        std::find_if(active.begin(), active.end(), [&](int i) { return m.dofs[i].name == c.identified_dofs[k]; }) -
        active.begin());
    for (const Mode& md : c.modes)
      if (!md.rigid_body && j < md.participation.size() &&
          (!best || md.participation(j) > best->participation(j)))
        best = &md;
    const IdentifiedDecay& d = c.identified[k];
    // The realized pole of this decay nearest the mode's damped frequency.
    const IdentifiedPole* pole = best ? nearestPole(c.poles[k], best->damped_freq_hz) : nullptr;
    std::printf("  %-24s %-14.6g %-12.5g | %-14.6g %-12.5g | %-24s %-14.6g %.5g\n", c.identified_dofs[k].c_str(),
                d.damped_freq_hz, d.damping_ratio, pole ? pole->damped_freq_hz : NAN, pole ? pole->damping_ratio : NAN,
                best ? best->name.c_str() : "-", best ? best->damped_freq_hz : NAN, best ? best->damping_ratio : NAN);
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
  cmd->add_option("--dof", opt->dofs, "coordinate perturbed (repeatable; default: every non-rotating active one)");
  cmd->add_option("--amplitude", opt->check.amplitude, "largest perturbation e [m or rad]")->check(CLI::PositiveNumber);
  cmd->add_option("--levels", opt->check.levels, "number of amplitudes (halved each time)")->check(CLI::Range(2, 8));
  cmd->add_option("--tmax", opt->check.t_end, "simulated time [s]")->check(CLI::PositiveNumber);
  cmd->add_option("--dt-out", opt->check.dt_out, "sampling interval [s]")->check(CLI::PositiveNumber);
  cmd->callback([opt]() { runWithCaseSource(opt->model.case_path, [&] { run(*opt); }); });
}

}  // namespace whirl::cli
