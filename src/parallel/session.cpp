#include "src/parallel/session.hpp"

#include <cstdlib>
#include <sstream>

#include "src/base/error.hpp"

#ifdef WHIRL_HAVE_PETSC
#include <slepcsys.h>
#endif

namespace whirl::parallel {
namespace {

int envInt(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atoi(v) : fallback;
}

/// What PETSc needs to outlive initialization: it keeps pointers into argv.
struct Runtime {
  std::vector<std::string> options;
  std::vector<std::string> argv_storage;
  std::vector<char*> argv;
  int argc = 0;
  char** argv_ptr = nullptr;
  bool started = false;  ///< by us
  bool finalized = false;
  bool session = false;  ///< a Session guard exists and will finalize
};

Runtime& runtime() {
  static Runtime r;
  return r;
}

/// PETSc's own sources of options besides argv (PetscOptionsInsert, PETSc 3.18): the files
/// `~/.petscrc`, `./.petscrc`, `./petscrc` (skipped with -skip_petscrc) and these variables (read
/// whatever the command line says). An option there such as `-start_in_debugger PROG` or
/// `-log_view ascii:FILE` runs a program or writes a file, so a `.petscrc` planted in a shared
/// working folder would act with the user's rights (issue 48, item 1). whirl takes PETSc options
/// only from its own command line and from WHIRL_PETSC_OPTIONS.
constexpr const char* kPetscEnvironment[] = {"PETSC_OPTIONS", "PETSC_OPTIONS_YAML"};

/// The words of the variable `name` (split at blanks), none when unset.
std::vector<std::string> envWords(const char* name) {
  std::vector<std::string> words;
  const char* v = std::getenv(name);
  std::istringstream in(v ? v : "");
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

void finalizePetsc() {
#ifdef WHIRL_HAVE_PETSC
  Runtime& r = runtime();
  if (!r.started || r.finalized) return;
  r.finalized = true;
  SlepcFinalize();
#endif
}

}  // namespace

Session::Session(std::vector<std::string> petsc_options) {
  Runtime& r = runtime();
  if (r.session) throw ComputeError("whirl::parallel::Session: only one session per process");
  r.session = true;
  r.options = std::move(petsc_options);
}

Session::~Session() {
  finalizePetsc();
  runtime().session = false;
}

bool petscAvailable() {
#ifdef WHIRL_HAVE_PETSC
  return true;
#else
  return false;
#endif
}

bool launchedByMpi() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK");
}

std::vector<std::string> petscArguments(const std::vector<std::string>& command_line) {
  std::vector<std::string> args = envWords(kWhirlPetscOptions);
  args.insert(args.end(), command_line.begin(), command_line.end());
  args.push_back("-skip_petscrc");  // last: no option before it can turn the files back on
  return args;
}

bool petscStarted() { return runtime().started && !runtime().finalized; }

void requirePetsc(const std::string& what) {
#ifdef WHIRL_HAVE_PETSC
  Runtime& r = runtime();
  if (r.finalized) throw ComputeError(what + ": PETSc was already finalized in this process");
  if (r.started) return;
  r.argv_storage.clear();
  r.argv_storage.push_back("whirl");
  for (const auto& o : petscArguments(r.options)) r.argv_storage.push_back(o);
  for (const char* name : kPetscEnvironment) ::unsetenv(name);
  r.argv.clear();
  for (auto& s : r.argv_storage) r.argv.push_back(s.data());
  r.argv.push_back(nullptr);
  r.argc = static_cast<int>(r.argv_storage.size());
  r.argv_ptr = r.argv.data();
  const PetscErrorCode ierr = SlepcInitialize(&r.argc, &r.argv_ptr, nullptr, nullptr);
  if (ierr) throw ComputeError(what + ": SlepcInitialize failed (error " + std::to_string(ierr) + ")");
  r.started = true;
  if (!r.session) std::atexit(finalizePetsc);  // library use without a Session guard
#else
  throw ComputeError(what + ": unavailable, whirl was built without PETSc/SLEPc/MPI (cmake -DWHIRL_WITH_PETSC=ON)");
#endif
}

int rank() {
#ifdef WHIRL_HAVE_PETSC
  if (petscStarted()) {
    PetscMPIInt r = 0;
    MPI_Comm_rank(PETSC_COMM_WORLD, &r);
    return r;
  }
#endif
  return envInt("OMPI_COMM_WORLD_RANK", envInt("PMI_RANK", envInt("PMIX_RANK", 0)));
}

int size() {
#ifdef WHIRL_HAVE_PETSC
  if (petscStarted()) {
    PetscMPIInt s = 1;
    MPI_Comm_size(PETSC_COMM_WORLD, &s);
    return s;
  }
#endif
  return envInt("OMPI_COMM_WORLD_SIZE", envInt("PMI_SIZE", 1));
}

void splitCommandLine(int argc, const char* const* argv, std::vector<std::string>& whirl_args,
                      std::vector<std::string>& petsc_options) {
  whirl_args.clear();
  petsc_options.clear();
  auto addWords = [&](const std::string& s) {
    std::istringstream in(s);
    for (std::string w; in >> w;) petsc_options.push_back(w);
  };
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (i > 0 && a == "--") {
      for (int j = i + 1; j < argc; ++j) petsc_options.push_back(argv[j]);
      break;
    }
    if (i > 0 && a == "--petsc") {
      if (i + 1 >= argc)
        throw InputError("--petsc: expects the PETSc options as one argument, e.g. --petsc \"-eps_nev 30\"");
      addWords(argv[++i]);
    } else if (i > 0 && a.rfind("--petsc=", 0) == 0) {
      addWords(a.substr(8));
    } else {
      whirl_args.push_back(a);
    }
  }
}

}  // namespace whirl::parallel
