// libFuzzer harness: whirl's command line, in-process (the CLI11 app of src/cli/app.cpp, as main()
// builds it), on arguments generated from the input: a command, a case (one of the repository's small
// cases, or the rest of the input written as a YAML case file), and up to 8 options, each with a
// value that is either tame (a short sweep, a small count, a time of a second) or an edge (0, −1,
// NaN, inf, 1e308, text where a number goes, malformed ranges, huge counts that a bound must refuse).
// Files an option names (--params, --schedule, --tracking) are written from the input too.
//
// Three harnesses: fuzz_cli (every command that computes: modes, linearize, campbell, export, steady,
// bode, simulate, study, shapes, flutter, verify), fuzz_study (`study` alone) and fuzz_simulate (`simulate` alone). The
// output writers run on every success
// (--out is the sandbox's). Per-run cost stays small by construction: tame sweeps have at most 3
// points and 6 azimuths, tame simulations at most 2 s; an edge value that is valid but expensive is
// left out on purpose (it would be a timeout, not a bug): those are the edges the bounds of
// src/base/limits.hpp refuse before any work (1e9 points, 1e9 s).
//
// Never generated: --solver sparse and PETSc options (they start MPI in the fuzzing process), an
// --out outside the sandbox. Gnuplot is never run: PATH is an empty folder (the "not found" note).
#include <fuzzer/FuzzedDataProvider.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "fuzz/fuzz_cli.hpp"
#include "src/cli/commands.hpp"

namespace {

namespace fs = std::filesystem;
using whirl::fuzz::sandbox;

enum class Kind { Number, Count, Range, Text, Flag, Choice, File };

struct Option {
  const char* name;
  Kind kind;
  std::vector<const char*> choices = {};  ///< Choice: the values; Text/File: templates
  double tame_max = 20.0;                 ///< Number: tame values in [tame_min, tame_max]
  double tame_min = 0.0;
};

struct Command {
  const char* name;
  std::vector<const char*> fixed;  ///< always passed (after the case)
  std::vector<Option> options;
};

// No 1 nm tower: valid, but so stiff that `simulate` needs 0.5 s to give up (IDA_TOO_MUCH_WORK), 8 s
// under ASan, a libFuzzer timeout that is not a hang.
const std::vector<const char*> kSetTemplates = {"gravity=0",
                                                "gravity=-9.81",
                                                "gravity=[0, 0, 1e9]",
                                                "gravity=[0, 0, 1000]",
                                                "bodies.tower.length=0",
                                                "bodies.0.mass=-1",
                                                "name=x",
                                                "bodies.tower.damping={ratio: [2]}",
                                                "bodies.tower.integration={method: gauss, n: 3}",
                                                "RotSpeed=0",
                                                "GenDOF=False",
                                                "ShftTilt=95",
                                                "TipRad=0",
                                                "CompAero=0",
                                                "bodies=[]",
                                                "dofs={}"};

Option setOption() { return {"--set", Kind::Text, kSetTemplates}; }

const std::vector<Command>& commands() {
  static const std::vector<Command> all = {
      {"modes",
       {},
       {{"--rpm", Kind::Number},
        {"--azimuths", Kind::Count},
        {"--format", Kind::Choice, {"table", "csv", "json"}},
        {"--nmodes", Kind::Count},
        setOption(),
        {"--allow-invalid-point", Kind::Flag}}},
      {"linearize", {"--out", ""}, {{"--rpm", Kind::Number}, setOption(), {"--allow-invalid-point", Kind::Flag}}},
      {"campbell",
       {"--out", ""},
       {{"--rpm", Kind::Range},
        {"--azimuths", Kind::Count},
        {"--versus", Kind::Choice, {"rpm", "wind", "auto"}},
        {"--max-freq", Kind::Number},
        {"--format", Kind::Choice, {"hawcstab2"}},
        {"--html", Kind::Flag},
        {"--no-plot", Kind::Flag},
        {"--first-order-lines", Kind::Flag},
        {"--wind", Kind::Range},
        {"--schedule",
         Kind::File,
         {"RotSpeed\n5\n10\n", "WindSpeed,RotSpeed,BldPitch\n8,9,0\n12,12.1,0\n", "rpm\nnan\n"}},
        {"--tracking", Kind::File, {"rename,tower FA 1,TFA\n", "assign,1,0,x\n", "rename,tower FA 1,\xff\n"}},
        setOption()}},
      {"export",
       {"--out", ""},
       {{"--format", Kind::Choice, {"mat", "lin", "json"}},
        {"--rpm", Kind::Number},
        {"--azimuths", Kind::Count},
        {"--inputs", Kind::Text, {"wind speed", "collective pitch,generator torque", "x", ""}},
        {"--outputs", Kind::Text, {"GenSpeed", "RtAeroFxh,GenPwr", "y", ","}},
        {"--drop-azimuth", Kind::Flag},
        {"--wind", Kind::Range},
        setOption()}},
      {"steady",
       {"--out", ""},
       {{"--wind", Kind::Range}, {"--azimuths", Kind::Count}, {"--no-plot", Kind::Flag}, setOption()}},
      {"bode",
       {"--out", ""},
       {{"--inputs", Kind::Text, {"wind speed", "collective pitch", "generator torque", "x"}},
        {"--outputs", Kind::Text, {"GenSpeed", "RtAeroFxh", "y"}},
        {"--from", Kind::Number},
        {"--to", Kind::Number},
        {"--points", Kind::Count},
        {"--rpm", Kind::Number},
        {"--wind", Kind::Number},
        {"--azimuths", Kind::Count},
        {"--no-plot", Kind::Flag}}},
      {"simulate",
       {"--out", ""},
       {{"--tmax", Kind::Number, {}, 2.0},
        // Tame output intervals from 0.01 s: at most 200 records of a tame run. 3e-5 s over 0.85 s (28,660
        // records of the aero rotor's outputs, 19 s under ASan) was a libFuzzer timeout, not a hang.
        {"--dt-out", Kind::Number, {}, 2.0, 0.01},
        {"--rpm", Kind::Number},
        {"--init",
         Kind::Text,
         {"tower FA 1=0.1", "tower FA 1+=0.01", "tower FA 1 rate=0.2", "azimuth=1e308", "=", "x=nan"}},
        {"--input",
         Kind::Text,
         {"wind speed=step(0,1)", "generator torque=ramp(0,1,1e3)", "wind speed=sin(1,2)", "wind speed=step(nan,1)",
          "x=sin(1,1)", "wind speed=ramp(1,0,1)"}},
        {"--drive",
         Kind::Text,
         {"azimuth=spinup(1,2)", "azimuth=spinup(0,0)", "tower FA 1=spinup(1,1)", "x=spinup(1,1)"}},
        {"--free-rotor", Kind::Flag},
        {"--equilibrium", Kind::Flag},
        {"--rtol", Kind::Number},
        {"--atol", Kind::Number},
        {"--plot", Kind::Text, {"tower FA 1", "t,x", ""}},
        {"--no-plot", Kind::Flag},
        {"--allow-invalid-point", Kind::Flag},
        setOption()}},
      {"study",
       {"--out", ""},
       {{"--params",
         Kind::File,
         {"gravity\n0\n9.80665\n", "bodies.tower.length,gravity\n80,9\n90,10\n", "gravity\nx\n",
          "gravity,gravity\n1,2\n", "\n", "TwrFADmp(1)\n1\n"}},
        {"--rpm", Kind::Range},
        {"--azimuths", Kind::Count},
        {"--schedule", Kind::File, {"RotSpeed\n5\n10\n", "WindSpeed,RotSpeed,BldPitch\n8,9,0\n"}},
        {"--tracking", Kind::File, {"rename,tower FA 1,TFA\n"}},
        setOption()}},
      {"shapes",
       {"--out", ""},
       {{"--rpm", Kind::Number}, {"--format", Kind::Choice, {"table", "csv", "json"}}, setOption()}},
      // The step and the last speed as choices: the shared number edges include valid steps (2.5e-3 rpm) whose
      // thousands of periodic linearizations are a timeout, not a bug; 1e308 and inf are refused by bounds.
      {"flutter",
       {"--out", ""},
       {{"--rpm-min", Kind::Number, {}, 15.0},
        {"--rpm-max", Kind::Choice, {"10", "20", "30", "1e308", "inf", "nan", "-1", "0", "x"}},
        {"--rpm-step", Kind::Choice, {"0.5", "1", "2", "5", "0", "-1", "nan", "1e-308", "1e4"}},
        {"--tolerance", Kind::Choice, {"0.01", "0.5", "0", "1e-9", "nan"}},
        {"--min-freq", Kind::Number},
        {"--wind", Kind::Number},
        {"--azimuths", Kind::Count},
        {"--quasi-steady-aero", Kind::Flag},
        setOption()}},
      // Free decays against the linear model, each coordinate's at two amplitudes over 0.5 s (fixed: a parked
      // NREL 5MW's 16 coordinates at the defaults, 3 amplitudes over 10 s, took 2.4 s in a release build, beyond
      // the short run's 5 s under ASan; a value given twice is CLI11's error), output every 0.01 s or more. The
      // amplitude's large edges (1e9, 0x10 = 16) are refused by limits::kMaxVerifyAmplitude.
      {"verify",
       {"--tmax", "0.5", "--levels", "2"},
       {{"--dof", Kind::Text, {"tower FA 1", "tower FA 1,tower SS 1", "x", ""}},
        {"--amplitude", Kind::Number, {}, 0.1},
        {"--dt-out", Kind::Number, {}, 0.5, 0.01},
        {"--rpm", Kind::Number},
        {"--quasi-steady-aero", Kind::Flag},
        setOption()}},
  };
  return all;
}

/// The command(s) a harness fuzzes: `only` (nullptr: every command).
std::vector<const Command*> fuzzedCommands(const char* only) {
  std::vector<const Command*> out;
  for (const Command& c : commands())
    if (!only || std::string(c.name) == only) out.push_back(&c);
  return out;
}

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string pick(FuzzedDataProvider& in, const std::vector<const char*>& list) {
  return list[in.ConsumeIntegralInRange<size_t>(0, list.size() - 1)];
}

// Edges: each either refused at once or cheap (see the file comment).
const std::vector<const char*> kNumberEdges = {"0",   "-1",  "-0", "nan", "inf",  "-inf", "1e308", "-1e308", "1e-308",
                                               "1e9", "abc", "",   " 2",  "0x10", "1,2",  "1e",    "+0.5",   "2.5e-3"};
const std::vector<const char*> kCountEdges = {"0", "-1", "3601", "100001", "2147483648", "x", "", "1e3", "2.5", "1"};
const std::vector<const char*> kRangeEdges = {"0:0:10",  "10:1:0",    "0:-1:10",   "nan:1:2",   "0:1e-9:1",
                                              "5",       "::",        "1:2",       "0:5:10:15", "inf:1:inf",
                                              "-5:1:-3", "1e9:1:1e9", "0:1:1e308", "a:b:c"};

/// Random text as an option value. Never starting with '-': CLI11 would read "--out=/x" as an option,
/// and the harness (root on a shared machine) must write nowhere but its sandbox.
std::string randomText(FuzzedDataProvider& in, size_t max) {
  std::string t = in.ConsumeRandomLengthString(max);
  if (!t.empty() && t.front() == '-') t.insert(0, "x");
  return t;
}

std::string value(FuzzedDataProvider& in, const Option& o) {
  const int mode = in.ConsumeIntegralInRange<int>(0, 7);  // 0-1: edge, 2: random text, 3-7: tame
  if (mode == 2 && o.kind != Kind::Flag) return randomText(in, 24);
  const bool edge = mode < 2;
  switch (o.kind) {
    case Kind::Number:
      return edge ? pick(in, kNumberEdges) : number(in.ConsumeFloatingPointInRange<double>(o.tame_min, o.tame_max));
    case Kind::Count: return edge ? pick(in, kCountEdges) : std::to_string(in.ConsumeIntegralInRange<int>(1, 6));
    case Kind::Range: {
      if (edge) return pick(in, kRangeEdges);
      const int a = in.ConsumeIntegralInRange<int>(0, 15), s = in.ConsumeIntegralInRange<int>(1, 10);
      return std::to_string(a) + ":" + std::to_string(s) + ":" +
             std::to_string(a + s * in.ConsumeIntegralInRange<int>(0, 2));
    }
    case Kind::Choice:
    case Kind::Text: return o.choices.empty() ? randomText(in, 24) : pick(in, o.choices);
    case Kind::File: {
      static int counter = 0;
      const fs::path p = sandbox() / ("cli_file" + std::to_string(counter++ % 4) + ".csv");
      std::ofstream(p, std::ios::binary | std::ios::trunc)
          << (edge ? in.ConsumeRandomLengthString(160) : pick(in, o.choices));
      return p.string();
    }
    case Kind::Flag: break;
  }
  return "";
}

// Small cases, each a run of well under a second when tame; "" = the rest of the input as YAML.
const std::vector<const char*> kCases = {"cases/landbased_2dof/landbased_2dof.yaml",
                                         "cases/flex_4dof/flex_4dof.yaml",
                                         "cases/tower_topmass/tower_topmass.yaml",
                                         "cases/aero_rotor/aero_rotor.yaml",
                                         "cases/floating_3dof/floating_3dof.yaml",
                                         "Main_Onshore.fst",
                                         ""};

void setUp() {
  // No chdir into the sandbox: libFuzzer reads its corpus and writes its findings by relative paths.
  static const bool done = [] {
    const fs::path bin = sandbox() / "no-programs";
    fs::create_directories(bin);
    setenv("PATH", bin.c_str(), 1);  // no gnuplot: commands print their "not found" note
    return true;
  }();
  (void)done;
}

int fuzzCommands(const std::vector<const Command*>& cmds, const uint8_t* data, size_t size) {
  setUp();
  FuzzedDataProvider in(data, size);
  const Command& cmd = *cmds[in.ConsumeIntegralInRange<size_t>(0, cmds.size() - 1)];
  std::string case_path = pick(in, kCases);
  const bool own_case = case_path.empty();
  if (!own_case && case_path.rfind("cases/", 0) == 0) case_path = (fs::path(WHIRL_SOURCE_DIR) / case_path).string();
  if (own_case) case_path = (sandbox() / "cli_case.yaml").string();
  else if (case_path.find('/') == std::string::npos) case_path = (sandbox() / case_path).string();
  std::vector<std::string> args = {cmd.name, case_path};
  // "--out" takes the sandbox's folder: every command that writes is given one.
  for (const char* f : cmd.fixed) args.push_back(*f ? std::string(f) : (sandbox() / "out").string());
  const int n = in.ConsumeIntegralInRange<int>(0, 8);
  for (int k = 0; k < n && in.remaining_bytes() > 0; ++k) {
    const Option& o = cmd.options[in.ConsumeIntegralInRange<size_t>(0, cmd.options.size() - 1)];
    args.push_back(o.name);
    if (o.kind != Kind::Flag) args.push_back(value(in, o));
  }
  if (own_case) {
    const std::string text = in.ConsumeRemainingBytesAsString();
    whirl::fuzz::writeInput("cli_case.yaml", reinterpret_cast<const uint8_t*>(text.data()), text.size());
  }
  static const bool verbose = std::getenv("WHIRL_FUZZ_VERBOSE") != nullptr;
  if (verbose) {
    std::fprintf(stderr, "whirl fuzz: whirl");
    for (const std::string& a : args) std::fprintf(stderr, " '%s'", a.c_str());
    std::fprintf(stderr, "\n");
    if (own_case) std::fprintf(stderr, "whirl fuzz: cli_case.yaml: %s\n", whirl::fuzz::sandbox().c_str());
  }
  whirl::fuzz::runCommand(whirl::cli::addCommands, args);
  return 0;
}

int fuzzEveryCommand(const uint8_t* data, size_t size) {
  static const std::vector<const Command*> cmds = fuzzedCommands(nullptr);
  return fuzzCommands(cmds, data, size);
}

int fuzzStudy(const uint8_t* data, size_t size) {
  static const std::vector<const Command*> cmds = fuzzedCommands("study");
  return fuzzCommands(cmds, data, size);
}

int fuzzSimulate(const uint8_t* data, size_t size) {
  static const std::vector<const Command*> cmds = fuzzedCommands("simulate");
  return fuzzCommands(cmds, data, size);
}

const whirl::fuzz::RegisterHarness kCli("fuzz_cli", fuzzEveryCommand);
const whirl::fuzz::RegisterHarness kStudy("fuzz_study", fuzzStudy);
const whirl::fuzz::RegisterHarness kSimulate("fuzz_simulate", fuzzSimulate);

}  // namespace
