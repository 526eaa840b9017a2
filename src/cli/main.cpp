// whirl: linearization and stability analysis of flexible multibody systems.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "src/cli/commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"whirl " WHIRL_VERSION ": linearization and stability analysis of flexible multibody systems"};
  app.require_subcommand(1);
  app.set_version_flag("--version", WHIRL_VERSION);
  whirl::cli::addLinearizeCommand(app);
  whirl::cli::addModesCommand(app);
  whirl::cli::addCampbellCommand(app);
  whirl::cli::addLinCommand(app);
  whirl::cli::addCompareCommand(app);
  whirl::cli::addExportCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "whirl: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
