// Inputs that once did harm: a case name with a newline ran a shell command when `whirl campbell`
// rendered its plot (the name ended a string in campbell.gp), and a model without an active DOF
// crashed every linearizing command (LDLᵀ of an empty mass matrix). Both now stop with one line
// and a non-zero exit before anything is written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

/// The two-DOF land-based case with `from` replaced by `to`.
std::string landbasedWith(const std::string& from, const std::string& to) {
  std::string text = test::slurp(fs::path(WHIRL_SOURCE_DIR) / "cases/landbased_2dof/landbased_2dof.yaml");
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// No file under `dir` (recursively) has "pwned" in its name.
bool nothingRan(const fs::path& dir) {
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().find("pwned") != std::string::npos) return false;
  return true;
}

void expectOneLineError(const test::Run& r, const std::string& what, const std::string& args) {
  EXPECT_EQ(r.code, 1) << args << "\n" << r.err;  // an error, not a crash (a signal gives -1)
  EXPECT_THAT(r.err, HasSubstr("whirl: error: ")) << args;
  EXPECT_THAT(r.err, HasSubstr(what)) << args;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
}

TEST(CliHostileNames, CampbellRefusesANewlineInTheCaseNameAndRunsNothing) {
  const auto dir = test::freshDir("hostile_name");
  const fs::path c = dir / "case.yaml";
  write(c, landbasedWith("name: landbased_2dof", "name: \"a\\n!touch whirl_pwned\\n#\""));
  const std::string args = "campbell case.yaml --rpm 0:5:10 --azimuths 4 --out out";
  const auto r = test::whirl(args, dir.string());
  expectOneLineError(r, "case.yaml:9: name: contains a control character (line feed", args);
  EXPECT_TRUE(nothingRan(dir)) << "the name ran as a Gnuplot command";
  EXPECT_FALSE(fs::exists(dir / "out" / "campbell.gp"));
}

TEST(CliHostileNames, ErrorMessagesStayOneLineWhateverTheyQuote) {
  // An unknown --set key with a newline is quoted in the message, escaped.
  const auto r = test::whirl("modes cases/landbased_2dof/landbased_2dof.yaml --set 'bodies.nacelle.ma\nss=1'");
  expectOneLineError(r, "ma\\nss", "--set with a newline");
}

/// `command` on `case_args` (relative to `dir`) for every linearizing command: one-line error with
/// `what`, and nothing written into `dir/out`.
void expectEveryCommandRefuses(const fs::path& dir, const std::string& case_args, const std::string& what) {
  write(dir / "sets.csv", "gravity\n9.81\n");
  const std::string out = " --out out";
  for (const std::string& cmd : {"modes " + case_args, "linearize " + case_args + out,
                                 "campbell " + case_args + " --rpm 0:5:10 --azimuths 4" + out,
                                 "export " + case_args + " --format json --azimuths 4" + out,
                                 "study " + case_args + " --params sets.csv --rpm 0:5:10 --azimuths 4" + out}) {
    const auto r = test::whirl(cmd, dir.string());
    expectOneLineError(r, what, cmd);
    EXPECT_TRUE(!fs::exists(dir / "out") || fs::is_empty(dir / "out")) << cmd << ": wrote output";
    fs::remove_all(dir / "out");
  }
}

const std::string kNoDof =
    "the model has no active degree of freedom (all frozen or none defined): nothing to linearize";

TEST(CliNoActiveDof, YamlCaseWithEveryDofFrozen) {
  const auto dir = test::freshDir("all_frozen");
  write(dir / "frozen.yaml", landbasedWith("  azimuth: {rotating: true}",
                                           "  azimuth: {rotating: true, frozen: true}\n  tower FA 1: {frozen: true}"));
  expectEveryCommandRefuses(dir, "frozen.yaml", "frozen.yaml: " + kNoDof);
}

TEST(CliNoActiveDof, RigidOnlyCase) {
  const auto dir = test::freshDir("rigid_only");
  write(dir / "rigid.yaml",
        "name: rigid only\nbodies:\n  - {name: block, type: rigid, mass: 10, inertia: [1, 1, 1]}\n");
  expectEveryCommandRefuses(dir, "rigid.yaml", "rigid.yaml: " + kNoDof);
}

TEST(CliNoActiveDof, OpenFastDeckWithEveryDofSwitchOff) {
  const auto dir = test::freshDir("openfast_no_dof");
  std::string sets;
  for (const char* s : {"FlapDOF1", "FlapDOF2", "EdgeDOF", "DrTrDOF", "GenDOF", "YawDOF", "TwFADOF1", "TwFADOF2",
                        "TwSSDOF1", "TwSSDOF2"})
    sets += std::string(" --set ") + s + "=False";
  const std::string fst = std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Onshore.fst";
  expectEveryCommandRefuses(dir, "'" + fst + "'" + sets, "Main_Onshore.fst: " + kNoDof);
}

}  // namespace
}  // namespace whirl
