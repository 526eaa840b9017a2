// PETSc takes options only from whirl's command line and WHIRL_PETSC_OPTIONS: its option files
// (`.petscrc` in the working folder) and PETSC_OPTIONS are ignored, since an option there can run
// a program (`-start_in_debugger PROG`, issue 48, item 1). src/parallel/session.hpp, petscArguments().
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "tests/cli/cli_support.hpp"

namespace whirl::test {
namespace {

namespace fs = std::filesystem;

#ifdef WHIRL_HAVE_PETSC

const std::string kCase = std::string(WHIRL_SOURCE_DIR) + "/cases/tower_topmass/tower_topmass_fem.yaml";

/// Runs `env whirl args` in `cwd`; `env` is a shell prefix such as "PETSC_OPTIONS='…'".
whirl::test::Run whirlWithEnv(const std::string& env, const std::string& args, const fs::path& cwd) {
  const fs::path out = cwd / "stdout.txt", err = cwd / "stderr.txt";
  const std::string cmd = "cd '" + cwd.string() + "' && env " + env + " '" + WHIRL_BINARY + "' " + args + " > '" +
                          out.string() + "' 2> '" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  whirl::test::Run r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

/// An executable `dir/noxterm/gdb` that creates `dir/pwned` when run, as in the reproducer.
fs::path plantDebugger(const fs::path& dir) {
  fs::create_directories(dir / "noxterm");
  const fs::path prog = dir / "noxterm" / "gdb";
  std::ofstream(prog) << "#!/bin/sh\ntouch '" << (dir / "pwned").string() << "'\n";
  ::chmod(prog.c_str(), 0755);
  return prog;
}

TEST(CliPetscOptions, APetscrcInTheWorkingFolderRunsNothing) {
  const fs::path dir = freshDir("petscrc");
  const fs::path prog = plantDebugger(dir);
  std::ofstream(dir / ".petscrc") << "-start_in_debugger " << prog.string() << "\n-eps_type arnoldi\n";
  std::ofstream(dir / "petscrc") << "-start_in_debugger " << prog.string() << "\n";
  const whirl::test::Run r = whirlWithEnv("", "modes '" + kCase + "' --solver sparse --nmodes 2", dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir / "pwned")) << "PETSc ran the program named in .petscrc";
  EXPECT_NE(r.err.find("EPS krylovschur"), std::string::npos) << "an option of .petscrc was read:\n" << r.err;
}

TEST(CliPetscOptions, PetscOptionsVariableIsIgnored) {
  const fs::path dir = freshDir("petsc_env");
  const fs::path prog = plantDebugger(dir);
  const whirl::test::Run r = whirlWithEnv("PETSC_OPTIONS='-eps_type arnoldi -start_in_debugger " + prog.string() +
                                              "' PETSC_OPTIONS_YAML='-eps_type: arnoldi'",
                                          "modes '" + kCase + "' --solver sparse --nmodes 2", dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir / "pwned")) << "PETSc ran the program named in PETSC_OPTIONS";
  EXPECT_NE(r.err.find("EPS krylovschur"), std::string::npos) << "PETSC_OPTIONS was read:\n" << r.err;
}

TEST(CliPetscOptions, WhirlPetscOptionsVariableIsRead) {
  // The documented way to give PETSc options through the environment; the command line wins.
  const fs::path dir = freshDir("whirl_petsc_env");
  const whirl::test::Run a = whirlWithEnv("WHIRL_PETSC_OPTIONS='-eps_type arnoldi'",
                                          "modes '" + kCase + "' --solver sparse --nmodes 2", dir);
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_NE(a.err.find("EPS arnoldi"), std::string::npos) << a.err;
  const whirl::test::Run b = whirlWithEnv("WHIRL_PETSC_OPTIONS='-eps_type arnoldi'",
                                          "modes '" + kCase +
                                              "' --solver sparse --nmodes 2 --petsc '-eps_type subspace'",
                                          dir);
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_NE(b.err.find("EPS subspace"), std::string::npos) << b.err;
}

#endif

}  // namespace
}  // namespace whirl::test
