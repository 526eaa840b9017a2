#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "modal/mode_compare.hpp"
#include "src/base/error.hpp"
#include "src/cli/commands.hpp"

namespace whirl::cli {
namespace {

struct CompareOptions {
  std::string result, reference;
  double tol_rel = 0.01;
  std::optional<double> rpm;
};

void run(const CompareOptions& opt) {
  if (!std::isfinite(opt.tol_rel) || opt.tol_rel < 0)
    throw InputError("--tol-rel: must be a finite number >= 0 (is " + std::to_string(opt.tol_rel) + ")");
  if (opt.rpm && !std::isfinite(*opt.rpm)) throw InputError("--rpm: must be a finite number");
  const std::vector<NamedFrequency> modes = readResultModes(opt.result, opt.rpm);
  const std::vector<ModeComparison> rows = compareModes(modes, readReferenceModes(opt.reference), opt.tol_rel);
  int failures = 0;
  std::printf("%-46s %10s  %-26s %10s %9s\n", "reference mode", "ref [Hz]", "whirl mode", "whirl [Hz]", "rel err");
  for (const ModeComparison& c : rows) {
    const double f = c.reference.freq_hz;
    failures += c.ok ? 0 : 1;
    if (!c.match) {
      std::printf("%-46s %10.4f  %-26s %10s %9s  MISSING\n", c.reference.mode.c_str(), f, "-", "-", "-");
      continue;
    }
    std::printf("%-46s %10.4f  %-26s %10.4f %+8.2f%%%s\n", c.reference.mode.c_str(), f, c.match->name.c_str(),
                c.match->freq_hz, 100 * c.rel_error, c.ok ? "" : "  FAIL");
  }
  std::printf("%zu modes compared, %d beyond %.3g %% or missing\n", rows.size(), failures, 100 * opt.tol_rel);
  if (failures > 0) throw ComputeError(std::to_string(failures) + " reference modes beyond tolerance or missing");
}

}  // namespace

void addCompareCommand(CLI::App& app) {
  auto opt = std::make_shared<CompareOptions>();
  CLI::App* cmd =
      app.add_subcommand("compare",
                         "compare modes (CSV of `whirl modes`, or campbell.csv with --rpm) with a reference table; "
                         "exit code 1 beyond the tolerance");
  cmd->add_option("RESULT", opt->result, "whirl modes CSV (index,name,freq_hz,…) or campbell.csv")->required();
  cmd->add_option("REF", opt->reference,
                  "reference CSV: mode,freq_hz[,whirl_mode] — whirl_mode names the whirl mode, a|b compares the "
                  "rows sharing it as a set, * takes the nearest frequency")
      ->required();
  cmd->add_option("--tol-rel", opt->tol_rel, "relative tolerance on the frequency (default 0.01)");
  cmd->add_option("--rpm", opt->rpm, "operating point of a campbell.csv");
  cmd->callback([opt]() { run(*opt); });
}

}  // namespace whirl::cli
