// Issue 48, items 3 and 5: every input file goes through one preamble (src/io/text/input_file.hpp) that
// refuses a file larger than limits::kMaxInputFileBytes before reading it and anything but a regular
// file (a FIFO blocked forever); `study` sets, `simulate` records and rotor revolutions are bounded
// before anything is allocated; names that are not UTF-8 are refused where they are read with
// `file:line: key`. Every message is one `whirl: error:` line without a library's text
// (cli_support.hpp checks that for every run).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <fstream>

#include "tests/cli/cli_support.hpp"

namespace whirl::test {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

const fs::path kSource = WHIRL_SOURCE_DIR;

/// `whirl args` in `cwd` under `timeout 60`: a refusal that regressed to blocking (a FIFO) fails the
/// test instead of hanging the suite (exit 124).
whirl::test::Run whirlTimed(const std::string& args, const fs::path& cwd) {
  const fs::path out = cwd / "stdout.txt", err = cwd / "stderr.txt";
  const std::string cmd = "cd '" + cwd.string() + "' && timeout 60 '" + WHIRL_BINARY + "' " + args + " > '" +
                          out.string() + "' 2> '" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  whirl::test::Run r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  expectNoLibraryText(r.err, args);
  return r;
}

void expectOneLineError(const whirl::test::Run& r, const std::string& what, const std::string& args) {
  EXPECT_EQ(r.code, 1) << args << "\n" << r.err;  // 124: timed out; -1: a signal
  EXPECT_THAT(r.err, HasSubstr("whirl: error: ")) << args;
  EXPECT_THAT(r.err, HasSubstr(what)) << args;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
}

/// A copy of the case folder `cases/<name>` in a fresh scratch folder.
fs::path copyCase(const std::string& name, const std::string& scratch) {
  const fs::path dir = freshDir(scratch);
  fs::copy(kSource / "cases" / name, dir / name, fs::copy_options::recursive);
  return dir / name;
}

/// Extends `file` with NUL bytes (a sparse file: no disk space) to 200 MB, above the 128 MB bound.
void inflate(const fs::path& file) { fs::resize_file(file, 200'000'000); }

const std::string kTooLarge = "is 200 MB, more than the 128 MB an input file may have";

// ---- input file size: one bound, every reader, before reading ---------------------------------------

TEST(CliInputFileSize, OpenFastFilesAreRefusedFromTheirSize) {
  const fs::path dir = copyCase("nrel5mw", "size_openfast");
  for (const std::string file :
       {"NRELOffshrBsline5MW_Onshore_ElastoDyn.dat", "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat",
        "NRELOffshrBsline5MW_Blade.dat", "Main_Onshore.fst"}) {
    const fs::path f = dir / file;
    const std::string keep = slurp(f);
    inflate(f);
    const std::string args = "linearize Main_Onshore.fst --out out";
    expectOneLineError(whirlTimed(args, dir), file + ": " + kTooLarge, args + " (" + file + ")");
    std::ofstream(f, std::ios::binary | std::ios::trunc) << keep;
  }
  EXPECT_FALSE(fs::exists(dir / "out" / "A.csv"));
}

TEST(CliInputFileSize, CaseTablesLinAndTrackingFilesAreRefusedFromTheirSize) {
  const fs::path dir = freshDir("size_other");
  // A YAML case.
  fs::copy(kSource / "cases/landbased_2dof/landbased_2dof.yaml", dir / "case.yaml");
  inflate(dir / "case.yaml");
  expectOneLineError(whirlTimed("modes case.yaml", dir), "case.yaml: " + kTooLarge, "YAML case");
  // A property table of a YAML case.
  const fs::path mono = copyCase("nrel5mw_monopile", "size_table");
  inflate(mono / "tower_properties.csv");
  expectOneLineError(whirlTimed("modes nrel5mw_monopile.yaml", mono), "tower_properties.csv: " + kTooLarge,
                     "property table");
  // An OpenFAST .lin file.
  fs::copy(kSource / "tests/data/openfast-lin/rotating-9rpm/Main.1.lin", dir / "Main.1.lin");
  inflate(dir / "Main.1.lin");
  expectOneLineError(whirlTimed("lin Main.1.lin", dir), "Main.1.lin: " + kTooLarge, ".lin");
  // study --params and campbell --tracking.
  std::ofstream(dir / "sets.csv") << "gravity\n9.81\n";
  inflate(dir / "sets.csv");
  const std::string yaml = (kSource / "cases/landbased_2dof/landbased_2dof.yaml").string();
  expectOneLineError(whirlTimed("study " + yaml + " --params sets.csv --rpm 0:5:10 --azimuths 4 --out out", dir),
                     "sets.csv: " + kTooLarge, "study --params");
  std::ofstream(dir / "t.csv") << "rename,tower FA 1,tower\n";
  inflate(dir / "t.csv");
  expectOneLineError(whirlTimed("campbell " + yaml + " --rpm 0:5:10 --azimuths 4 --no-plot --tracking t.csv --out out",
                                dir),
                     "t.csv: " + kTooLarge, "campbell --tracking");
}

TEST(CliInputFileSize, AerodynamicControllerAndOffshoreFilesAreRefusedFromTheirSize) {
  // Issue 48: the readers beyond the main OpenFAST files: AeroDyn and its blade and airfoil files,
  // InflowWind, ServoDyn and ROSCO's DISCON.IN (the ROSCO deck), HydroDyn, MAP++ and WAMIT (the OC3
  // spar), and a Cp surface (tune --cp-surface) — each refused from its size before it is read.
  const fs::path dir = copyCase("nrel5mw", "size_aero");
  for (const std::string file :
       {"aero/AeroDyn.dat", "aero/InflowWind.dat", "5MW_Baseline/NRELOffshrBsline5MW_AeroDyn_blade.dat",
        "5MW_Baseline/Airfoils/Cylinder1.dat", "rosco/ServoDyn.dat", "rosco/DISCON.IN"}) {
    const fs::path f = dir / file;
    const std::string keep = slurp(f);
    inflate(f);
    const std::string args = "steady Main_ROSCO.fst --wind 10 --out out";
    expectOneLineError(whirlTimed(args, dir), fs::path(file).filename().string() + ": " + kTooLarge,
                       args + " (" + file + ")");
    std::ofstream(f, std::ios::binary | std::ios::trunc) << keep;
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
  const std::string cp = "rosco/Cp_Ct_Cq.NREL5MW.txt";
  inflate(dir / cp);
  const std::string tune =
      "tune Main_Aero.fst --cp-surface " + cp +
      " --inertia 4e7 --rotor-radius 63 --rated-rotor-speed 1.267 --rated-power 5e6 --pc-omega 0.6 "
      "--pc-zeta 0.7 --vs-omega 0.2 --vs-zeta 0.7 --v-min 3 --v-rated 11.4 --v-max 25 --out out";
  expectOneLineError(whirlTimed(tune, dir), "Cp_Ct_Cq.NREL5MW.txt: " + kTooLarge, "tune --cp-surface");
  const fs::path spar = copyCase("oc3_hywind", "size_offshore");
  for (const std::string file :
       {"5MW_Baseline/NRELOffshrBsline5MW_OC3Hywind_HydroDyn.dat", "5MW_Baseline/NRELOffshrBsline5MW_OC3Hywind_MAP.dat",
        "5MW_Baseline/HydroData/spar.1", "5MW_Baseline/HydroData/spar.hst"}) {
    const fs::path f = spar / file;
    const std::string keep = slurp(f);
    inflate(f);
    const std::string args = "modes Test24.fst --set CompAero=0 --set RdtnMod=0";
    expectOneLineError(whirlTimed(args, spar), fs::path(file).filename().string() + ": " + kTooLarge,
                       args + " (" + file + ")");
    std::ofstream(f, std::ios::binary | std::ios::trunc) << keep;
  }
}

// ---- only regular files ------------------------------------------------------------------------------

TEST(CliInputFileKind, AFifoOrADeviceIsRefusedNotWaitedOn) {
  const fs::path mono = copyCase("nrel5mw_monopile", "fifo_table");
  fs::remove(mono / "tower_properties.csv");
  ASSERT_EQ(::mkfifo((mono / "tower_properties.csv").c_str(), 0600), 0);
  expectOneLineError(whirlTimed("modes nrel5mw_monopile.yaml", mono),
                     "tower_properties.csv: is a FIFO (named pipe), not a regular file", "FIFO property table");
  const fs::path dir = copyCase("nrel5mw", "fifo_elastodyn");
  fs::remove(dir / "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat");
  ASSERT_EQ(::mkfifo((dir / "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat").c_str(), 0600), 0);
  expectOneLineError(whirlTimed("modes Main_Onshore.fst", dir),
                     "Main_Onshore.fst:33: EDFile: not a regular file (a folder, FIFO or device)",
                     "FIFO ElastoDyn file");
  expectOneLineError(whirlTimed("modes /dev/zero", dir), "/dev/zero: is a character device", "/dev/zero as a case");
}

// ---- study and simulate: sizes and times estimated before they are spent -----------------------------

TEST(CliRunBounds, StudyRefusesMoreParameterSetsThanTheBound) {
  const fs::path dir = freshDir("study_rows");
  {
    std::ofstream sets(dir / "sets.csv");
    sets << "gravity\n";
    for (int k = 0; k <= 10000; ++k) sets << "9.81\n";  // 10 001 sets, the bound is 10 000
  }
  const std::string args = "study " + (kSource / "cases/landbased_2dof/landbased_2dof.yaml").string() +
                           " --params sets.csv --rpm 0:5:10 --azimuths 4 --out out";
  expectOneLineError(whirlTimed(args, dir), "sets.csv:10002: more than 10000 parameter sets", args);
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(CliRunBounds, SimulateRefusesRecordsItCannotHold) {
  const fs::path dir = freshDir("simulate_records");
  const std::string yaml = (kSource / "cases/landbased_2dof/landbased_2dof.yaml").string();
  // The two: std::bad_alloc before, 1 GB of records before.
  expectOneLineError(whirlTimed("simulate " + yaml + " --tmax 1e9 --no-plot --out out", dir),
                     "simulate: tmax: 1e+09 s recorded every 0.01 s (dt-out) are 1e+11 instants, more than 1000000",
                     "--tmax 1e9");
  expectOneLineError(whirlTimed("simulate " + yaml + " --tmax 30000 --no-plot --out out", dir),
                     "give a larger --dt-out or a shorter --tmax", "--tmax 30000");
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(CliRunBounds, SimulateRefusesARotorSpeedWhoseStepsExplode) {
  const fs::path dir = freshDir("simulate_rpm");
  const std::string args = "simulate " + (kSource / "cases/nrel5mw/Main_Onshore.fst").string() +
                           " --tmax 2 --rpm 1e9 --free-rotor --no-plot --out out";
  expectOneLineError(whirlTimed(args, dir), "revolutions in tmax = 2 s at 1e+09 rpm, more than 100000", args);
}

// ---- names: UTF-8 where they are read -----------------------------------------------------------------

TEST(CliNamesUtf8, ANameThatIsNotUtf8IsRefusedWhereItIsRead) {
  const fs::path dir = freshDir("utf8");
  std::string yaml = slurp(kSource / "cases/landbased_2dof/landbased_2dof.yaml");
  yaml.replace(yaml.find("name: landbased_2dof"), 20, "name: \"bad\xff name\"");
  std::ofstream(dir / "case.yaml", std::ios::binary) << yaml;
  expectOneLineError(whirlTimed("modes case.yaml --format json", dir),
                     "case.yaml:9: name: contains a byte that is not UTF-8 text (0xFF) at byte 4", "YAML name");
  // The first audit's reproducer: a tracking rename.
  std::ofstream(dir / "t.csv", std::ios::binary) << "rename,tower FA 1,bad\xffname\n";
  const std::string args = "campbell " + (kSource / "cases/nrel5mw/Main_Onshore.fst").string() +
                           " --rpm 0:3:12 --azimuths 4 --no-plot --tracking t.csv --out out";
  expectOneLineError(whirlTimed(args, dir), "t.csv:1: contains a byte that is not UTF-8 text (0xFF) at byte 22",
                     "tracking rename");
  // A .lin description.
  std::string lin = slurp(kSource / "tests/data/openfast-lin/rotating-9rpm/Main.1.lin");
  lin.replace(lin.find("ED 1st flapwise"), 2, "E\xc3");  // a lead byte without its continuation
  std::ofstream(dir / "Main.1.lin", std::ios::binary) << lin;
  expectOneLineError(whirlTimed("lin Main.1.lin --format json", dir), "Main.1.lin:23: ", ".lin description");
  EXPECT_TRUE(!fs::exists(dir / "out") || fs::is_empty(dir / "out")) << "a file was written";
}

// ---- table rows ------------------------------------------------------------------------------------------

TEST(CliTableRowsSlow, APropertyTableOfMoreRowsThanTheBoundIsRefused) {
  const fs::path mono = copyCase("nrel5mw_monopile", "table_rows");
  {
    std::ofstream t(mono / "tower_properties.csv");
    t << "fraction,m,EIy,EIz\n";
    for (int k = 0; k <= 1000000; ++k) t << k * 1e-6 << ",5590.87,6.14343e11,6.14343e11\n";
  }
  expectOneLineError(whirlTimed("modes nrel5mw_monopile.yaml", mono),
                     "tower_properties.csv:1000002: more than 1000000 rows", "1 000 001 rows");
}

}  // namespace
}  // namespace whirl::test
