#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>

#include "linearize/periodic.hpp"
#include "modal/mode_shapes.hpp"
#include "modal/rotor_modes.hpp"
#include "modal/sparse_modes.hpp"
#include "src/base/error.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/cli/mode_output.hpp"
#include "src/parallel/session.hpp"

namespace whirl::cli {
namespace {

struct ModesOptions {
  ModelOptions model;
  std::string format = "table";
  int azimuths = 36;
  std::string solver = "auto";
  int nmodes = 20;
};

int bladeCount(const Model& m) {
  int nb = 0;
  for (int i : m.activeDofs()) nb = std::max(nb, m.dofs[i].blade + 1);
  return nb;
}

// A rotor is analysed over the revolution: with 3 or more blades in multiblade coordinates; with fewer
// (or a teeter) by Floquet when it turns, parked by the plain eigenanalysis with the shapes seen from
// the fixed frame (modal/rotor_modes.hpp).
bool rotorPath(const Model& m, int az) {
  if (az < 0) return false;
  const int teeter = m.roles.teeter_dof;
  return bladeCount(m) > 0 || (teeter >= 0 && !m.dofs[teeter].frozen);
}

void run(const ModesOptions& opt) {
  const Model m = loadModel(opt.model, true);
  nlohmann::json header;
  header["case"] = opt.model.case_path;
  const int az = findAzimuthDof(m);
  const OperatingPoint start = startPoint(m, opt.model);
  if (rotorPath(m, az)) {
    if (opt.solver == "sparse")
      throw InputError(
          "--solver sparse: a rotor's multiblade model is a small averaged state matrix, solved dense; "
          "use --solver dense or auto");
    // A rotor: periodic operating point over the revolution, multiblade coordinates.
    PeriodicOptions p;
    p.azimuths = opt.azimuths;
    const PeriodicLinearization lin = linearizePeriodic(m, start, p);
    const std::vector<std::string> problems = checkSolvedPoints(opt.model, m, lin.points);
    header["validity"] = {{"valid", problems.empty()}, {"problems", problems}};
    RotorModes r = rotorModes(m, lin);
    addModeMotions(m, lin, r.num_blades, r.coordinates, r.modes);
    header["rotor_speed_rpm"] = lin.rotor_speed * 30 / 3.141592653589793;
    header["azimuths"] = opt.azimuths;
    header["multiblade"] = bladeCount(m) >= 3;
    // Fewer blades, turning: modal/floquet.hpp; a single blade without fixed-frame coordinates (a
    // blade-only deck) needs no transform.
    bool fixed_frame = false;
    for (int i : m.activeDofs()) fixed_frame = fixed_frame || m.dofs[i].blade < 0;
    header["floquet"] = bladeCount(m) < 3 && (bladeCount(m) != 1 || fixed_frame);
    printModes(r.modes, r.coordinates, opt.format, header);
    return;
  }
  const OperatingPoint op = solveOperatingPoint(m, start);
  const std::vector<std::string> problems = checkSolvedPoints(opt.model, m, {op});
  header["validity"] = {{"valid", problems.empty()}, {"problems", problems}};
  const LinearModel lin = linearize(m, op);
  const int n = static_cast<int>(lin.M.rows());
  if (!lin.first_order_names.empty()) {
    if (opt.solver == "sparse")
      throw InputError(
          "--solver sparse: a model with first-order states (HydroDyn radiation) is solved dense; "
          "use --solver dense or auto");
    RotorModes r = linearModelModes(m, lin, op.held);
    addModeMotions(m, op, lin, r.modes);
    printModes(r.modes, r.coordinates, opt.format, header);
    return;
  }
  if (!useSparseSolver(opt.solver, n)) {
    std::vector<Mode> modes = computeModes(lin.M, lin.C, lin.K, lin.dof_names);
    addModeMotions(m, op, lin, modes);
    printModes(modes, lin.dof_names, opt.format, header);
    return;
  }
  // SLEPc: the lowest --nmodes modes; under mpirun the solve is spread over the ranks.
  SparseEigenOptions so;
  so.distributed = true;
  SparseModesInfo info;
  std::vector<Mode> modes = computeModesSparse(lin.M.sparseView(), lin.C.sparseView(), lin.K.sparseView(),
                                               lin.dof_names, std::min(opt.nmodes, n), so, &info);
  if (parallel::rank() != 0) return;
  addModeMotions(m, op, lin, modes);
  std::fprintf(stderr, "modes: %s, target %.6g, %d iterations, %zu modes of %d coordinates\n", info.method.c_str(),
               info.target, info.iterations, modes.size(), n);
  header["solver"] = {{"method", info.method}, {"target", info.target}, {"iterations", info.iterations}};
  printModes(modes, lin.dof_names, opt.format, header);
}

}  // namespace

void addModesCommand(CLI::App& app) {
  auto opt = std::make_shared<ModesOptions>();
  CLI::App* cmd = app.add_subcommand(
      "modes",
      "solve the operating point and print the modes (rotors with 3+ blades: multiblade coordinates, "
      "averaged over the azimuths)");
  addModelOptions(*cmd, opt->model);
  addAeroStateOptions(*cmd, opt->model);
  cmd->add_option("--format", opt->format, "table, csv or json")->check(CLI::IsMember({"table", "csv", "json"}));
  addMultibladeAzimuths(*cmd, opt->azimuths);
  cmd->add_option("--solver", opt->solver,
                  "eigensolver: dense (LAPACK, all modes), sparse (SLEPc, the lowest --nmodes, each with its "
                  "residual) or auto (sparse from " +
                      std::to_string(kSparseSolverThreshold) + " coordinates)")
      ->check(CLI::IsMember({"auto", "dense", "sparse"}));
  cmd->add_option("--nmodes", opt->nmodes, "modes computed by the sparse solver (lowest frequencies)")
      ->check(CLI::Range(1, 100000));
  cmd->callback([opt]() { runWithCaseSource(opt->model.case_path, [&] { run(*opt); }); });
}

}  // namespace whirl::cli
