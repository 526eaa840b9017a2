// The list of whirl's subcommands, shared by main() and the command-line fuzz harnesses (fuzz/fuzz_cli.cpp).
#include <CLI/CLI.hpp>

#include "src/cli/commands.hpp"

namespace whirl::cli {

void addCommands(CLI::App& app) {
  addLinearizeCommand(app);
  addModesCommand(app);
  addCampbellCommand(app);
  addLinCommand(app);
  addCompareCommand(app);
  addExportCommand(app);
  addStudyCommand(app);
  addShapesCommand(app);
  addSteadyCommand(app);
  addBodeCommand(app);
  addSimulateCommand(app);
  addVerifyCommand(app);
  addReportCommand(app);
  addTuneCommand(app);
  addFlutterCommand(app);
}

}  // namespace whirl::cli
