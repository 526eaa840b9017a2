#pragma once
/// \file
/// The process's PETSc/SLEPc (and through them MPI) runtime. PETSc is started lazily, the first
/// time something needs it (a sparse eigensolve, a sweep launched by mpirun), so commands that
/// stay dense do not pay MPI's start-up (~0.5 s for a singleton); it is finalized once, by the
/// Session guard in main (or at exit when a library user never made one).
///
/// MPI is process-wide state by nature; this file is the one place that holds it. No PETSc or
/// MPI header is included here: everything compiles the same with WHIRL_WITH_PETSC=OFF, where
/// requirePetsc() throws "not built with PETSc".
#include <string>
#include <vector>

namespace whirl::parallel {

/// RAII guard for main(): records the PETSc options (e.g. "-eps_nev", "30", "-st_type",
/// "sinvert") that go into PETSc's options database when PETSc starts, and finalizes PETSc/SLEPc
/// (and MPI, if PETSc started it) when destroyed. At most one Session may exist.
class Session {
 public:
  explicit Session(std::vector<std::string> petsc_options);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

/// True when whirl was built with PETSc/SLEPc/MPI (WHIRL_WITH_PETSC=ON).
bool petscAvailable();

/// True when the process was started by an MPI launcher (mpirun/mpiexec/srun), read from the
/// launcher's environment (OMPI_COMM_WORLD_SIZE, PMI_SIZE, PMIX_RANK) without starting MPI.
bool launchedByMpi();

/// Starts PETSc and SLEPc if not yet started. Throws ComputeError when whirl was built without
/// PETSc, naming `what` ("--solver sparse", "mpirun") as the feature that is unavailable.
void requirePetsc(const std::string& what);

/// The variable whose words (split at blanks) go to PETSc before the command line's options.
inline constexpr const char* kWhirlPetscOptions = "WHIRL_PETSC_OPTIONS";

/// The options PETSc is started with (after argv[0]): the words of WHIRL_PETSC_OPTIONS, then
/// `command_line` (from `--petsc` and after `--`), then `-skip_petscrc`. PETSc's option files
/// (`.petscrc`, `petscrc`, `~/.petscrc`) and variables (`PETSC_OPTIONS`, `PETSC_OPTIONS_YAML`, which
/// requirePetsc() removes from the environment) are never read: an option there can run a program
/// (`-start_in_debugger`) or write a file (`-log_view ascii:FILE`), and a folder shared with others
/// may hold such a file (docs/user/limits.md).
std::vector<std::string> petscArguments(const std::vector<std::string>& command_line);

/// True once PETSc has been started (and not yet finalized).
bool petscStarted();

/// Rank in PETSC_COMM_WORLD; before PETSc starts, the launcher's rank from the environment, else 0.
int rank();
/// Number of ranks in PETSC_COMM_WORLD; before PETSc starts, the launcher's size, else 1.
int size();

/// Splits whirl's command line: everything after a lone "--", and the value of every
/// `--petsc "OPTS"` / `--petsc=OPTS` (split at blanks), are PETSc options; the rest is returned in
/// `whirl_args` (argv[0] first) for CLI11.
void splitCommandLine(int argc, const char* const* argv, std::vector<std::string>& whirl_args,
                      std::vector<std::string>& petsc_options);

}  // namespace whirl::parallel
