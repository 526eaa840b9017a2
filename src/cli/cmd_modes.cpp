#include <CLI/CLI.hpp>

#include "linearize/periodic.hpp"
#include "modal/rotor_modes.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/cli/mode_output.hpp"

namespace whirl::cli {
namespace {

struct ModesOptions {
  ModelOptions model;
  std::string format = "table";
  int azimuths = 36;
};

int bladeCount(const Model& m) {
  int nb = 0;
  for (int i : m.activeDofs()) nb = std::max(nb, m.dofs[i].blade + 1);
  return nb;
}

void run(const ModesOptions& opt) {
  const Model m = loadModel(opt.model);
  nlohmann::json header;
  header["case"] = opt.model.case_path;
  const int az = findAzimuthDof(m);
  if (az >= 0 && bladeCount(m) >= 3) {
    // A rotor: periodic operating point over the revolution, multiblade coordinates.
    PeriodicOptions p;
    p.azimuths = opt.azimuths;
    const PeriodicLinearization lin = linearizePeriodic(m, initialPoint(m), p);
    const RotorModes r = rotorModes(m, lin);
    header["rotor_speed_rpm"] = lin.rotor_speed * 30 / 3.141592653589793;
    header["azimuths"] = opt.azimuths;
    header["multiblade"] = true;
    printModes(r.modes, r.coordinates, opt.format, header);
    return;
  }
  const LinearModel lin = linearize(m, solveOperatingPoint(m, initialPoint(m)));
  printModes(computeModes(lin.M, lin.C, lin.K, lin.dof_names), lin.dof_names, opt.format, header);
}

}  // namespace

void addModesCommand(CLI::App& app) {
  auto opt = std::make_shared<ModesOptions>();
  CLI::App* cmd = app.add_subcommand(
      "modes", "solve the operating point and print the modes (rotors with 3+ blades: multiblade coordinates, "
               "averaged over the azimuths)");
  addModelOptions(*cmd, opt->model);
  cmd->add_option("--format", opt->format, "table, csv or json")->check(CLI::IsMember({"table", "csv", "json"}));
  cmd->add_option("--azimuths", opt->azimuths, "azimuths per revolution for rotors (multiblade average)")
      ->check(CLI::Range(1, 3600));
  cmd->callback([opt]() { run(*opt); });
}

}  // namespace whirl::cli
