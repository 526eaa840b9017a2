// whirl: linearization and stability analysis of flexible multibody systems.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <exception>

#include "src/base/text.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/error_message.hpp"
#include "src/parallel/session.hpp"

int main(int argc, char** argv) {
  // PETSc options (-eps_*, -pep_*, -st_*, …) never reach CLI11: they follow a lone "--" or come
  // in --petsc "…"; PETSc itself starts only when a command needs it (sparse solver, mpirun).
  std::vector<std::string> args, petsc_options;
  const bool root = whirl::parallel::rank() == 0;  // under mpirun only rank 0 prints
  try {
    whirl::parallel::splitCommandLine(argc, argv, args, petsc_options);
  } catch (const std::exception& e) {
    if (root) std::fprintf(stderr, "whirl: error: %s\n", whirl::escapeControlCharacters(e.what()).c_str());
    return 1;
  }
  whirl::parallel::Session session(petsc_options);
  // Under mpirun with several ranks, only the commands that split their work run; any other
  // command would do the same work K times and write the same files K times.
  if (whirl::parallel::size() > 1) {
    static const std::vector<std::string> distributed = {"campbell", "study", "export", "modes", "steady"};
    for (size_t i = 1; i < args.size(); ++i) {
      if (args[i].empty() || args[i][0] == '-') continue;
      if (std::find(distributed.begin(), distributed.end(), args[i]) == distributed.end()) {
        if (root)
          std::fprintf(
              stderr,
              "whirl: error: %s: does not run distributed; under mpirun use campbell, study, export, modes or steady\n",
              whirl::escapeControlCharacters(args[i]).c_str());
        return 1;
      }
      break;
    }
  }

  CLI::App app{"whirl " WHIRL_VERSION ": linearization and stability analysis of flexible multibody systems"};
  app.require_subcommand(1);
  app.set_version_flag("--version", WHIRL_VERSION);
  app.footer(
      "PETSc/SLEPc options (-eps_*, -pep_*, -st_*, -mat_mumps_*, …) go after a lone `--` or in --petsc \"…\", "
      "e.g. whirl modes CASE --solver sparse -- -eps_tol 1e-10. Under `mpirun -n K`, `campbell`, `study` and "
      "`export` spread their operating points over the K ranks, and a --wind trim (also `steady`'s) its wind speeds; "
      "rank 0 writes the output.");
  whirl::cli::addCommands(app);
  std::vector<char*> cargv;
  for (auto& a : args) cargv.push_back(a.data());
  cargv.push_back(nullptr);
  try {
    app.parse(static_cast<int>(args.size()), cargv.data());
  } catch (const CLI::ParseError& e) {
    if (!root) return e.get_exit_code();
    return app.exit(e);
  } catch (const std::exception& e) {
    if (root) std::fprintf(stderr, "whirl: error: %s\n", whirl::cli::errorMessage(e).c_str());
    return 1;
  }
  return 0;
}
