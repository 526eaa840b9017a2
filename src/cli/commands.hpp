#pragma once
/// \file
/// The subcommands of `whirl`, each registered by one function.
namespace CLI {
class App;
}

namespace whirl::cli {
void addLinearizeCommand(CLI::App& app);
void addModesCommand(CLI::App& app);
void addCampbellCommand(CLI::App& app);
void addLinCommand(CLI::App& app);
void addCompareCommand(CLI::App& app);
void addExportCommand(CLI::App& app);
void addStudyCommand(CLI::App& app);
void addShapesCommand(CLI::App& app);
void addSteadyCommand(CLI::App& app);
void addBodeCommand(CLI::App& app);
void addSimulateCommand(CLI::App& app);
void addVerifyCommand(CLI::App& app);
void addReportCommand(CLI::App& app);
void addTuneCommand(CLI::App& app);
void addFlutterCommand(CLI::App& app);
/// Every command above, in the order `whirl --help` lists them (main() and fuzz/fuzz_cli.cpp).
void addCommands(CLI::App& app);
}  // namespace whirl::cli
