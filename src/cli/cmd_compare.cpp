#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>

#include "src/cli/commands.hpp"
#include "src/io/csv.hpp"
#include "src/model/error.hpp"

namespace whirl::cli {
namespace {

struct CompareOptions {
  std::string result, reference;
  double tol_rel = 0.01;
  std::optional<double> rpm;
};

struct Found {
  std::string name;
  double freq = 0;
};

double number(const TextTable& t, size_t row, int col) {
  try {
    size_t used = 0;
    const double v = std::stod(t.rows[row][col], &used);
    if (used == t.rows[row][col].size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  throw InputError(where(t.file, t.lines[row], t.names[col], "not a number: '" + t.rows[row][col] + "'"));
}

std::vector<std::string> splitSet(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string part;
  while (std::getline(in, part, '|')) out.push_back(part);
  return out;
}

void run(const CompareOptions& opt) {
  if (!std::isfinite(opt.tol_rel) || opt.tol_rel < 0)
    throw InputError("--tol-rel: must be a finite number >= 0 (is " + std::to_string(opt.tol_rel) + ")");
  if (opt.rpm && !std::isfinite(*opt.rpm)) throw InputError("--rpm: must be a finite number");
  const TextTable res = readTextCsv(opt.result), ref = readTextCsv(opt.reference);
  const int rname = res.column("name") >= 0 ? res.column("name") : res.column("mode");
  const int rfreq = res.column("freq_hz"), rrpm = res.column("rpm");
  if (rname < 0 || rfreq < 0) throw InputError(opt.result + ": needs columns name (or mode) and freq_hz");
  if (rrpm >= 0 && !opt.rpm) throw InputError(opt.result + ": a Campbell table; choose the operating point with --rpm");
  std::vector<Found> modes;
  for (size_t r = 0; r < res.rows.size(); ++r) {
    if (rrpm >= 0 && std::abs(number(res, r, rrpm) - *opt.rpm) > 1e-9) continue;
    modes.push_back({res.rows[r][rname], number(res, r, rfreq)});
  }
  if (modes.empty()) throw InputError(opt.result + ": no modes" + (opt.rpm ? " at that --rpm" : ""));
  const int fmode = ref.column("mode"), ffreq = ref.column("freq_hz"), fwhirl = ref.column("whirl_mode");
  if (fmode < 0 || ffreq < 0) throw InputError(opt.reference + ": needs columns mode and freq_hz");

  // Reference rows that share a set of names ("a|b") are compared as a set: sorted frequencies
  // against sorted frequencies. "*" means the mode nearest in frequency.
  std::vector<bool> used(modes.size(), false);
  std::map<std::string, std::vector<size_t>> sets;
  for (size_t r = 0; r < ref.rows.size(); ++r)
    sets[fwhirl >= 0 ? ref.rows[r][fwhirl] : ref.rows[r][fmode]].push_back(r);
  std::vector<std::optional<Found>> match(ref.rows.size());
  for (size_t r = 0; r < ref.rows.size(); ++r) {
    const std::string key = fwhirl >= 0 ? ref.rows[r][fwhirl] : ref.rows[r][fmode];
    if (match[r]) continue;
    const auto names = splitSet(key);
    const auto& rows = sets[key];
    std::vector<size_t> cand;
    for (size_t k = 0; k < modes.size(); ++k)
      if (!used[k] && (key == "*" || std::find(names.begin(), names.end(), modes[k].name) != names.end())) cand.push_back(k);
    if (key == "*" || rows.size() == 1) {
      // The candidate nearest the reference frequency (a name may be carried by several modes).
      const double f = number(ref, r, ffreq);
      auto best = std::min_element(cand.begin(), cand.end(), [&](size_t a, size_t b) {
        return std::abs(modes[a].freq - f) < std::abs(modes[b].freq - f);
      });
      if (best != cand.end()) {
        used[*best] = true;
        match[r] = modes[*best];
      }
      continue;
    }
    std::vector<size_t> rs = rows;
    std::sort(rs.begin(), rs.end(), [&](size_t a, size_t b) { return number(ref, a, ffreq) < number(ref, b, ffreq); });
    std::sort(cand.begin(), cand.end(), [&](size_t a, size_t b) { return modes[a].freq < modes[b].freq; });
    for (size_t k = 0; k < rs.size() && k < cand.size(); ++k) {
      used[cand[k]] = true;
      match[rs[k]] = modes[cand[k]];
    }
  }
  int failures = 0;
  std::printf("%-46s %10s  %-26s %10s %9s\n", "reference mode", "ref [Hz]", "whirl mode", "whirl [Hz]", "rel err");
  for (size_t r = 0; r < ref.rows.size(); ++r) {
    const double f = number(ref, r, ffreq);
    if (!match[r]) {
      ++failures;
      std::printf("%-46s %10.4f  %-26s %10s %9s  MISSING\n", ref.rows[r][fmode].c_str(), f, "-", "-", "-");
      continue;
    }
    const double err = (match[r]->freq - f) / f;
    const bool ok = std::abs(err) <= opt.tol_rel;
    failures += ok ? 0 : 1;
    std::printf("%-46s %10.4f  %-26s %10.4f %+8.2f%%%s\n", ref.rows[r][fmode].c_str(), f, match[r]->name.c_str(),
                match[r]->freq, 100 * err, ok ? "" : "  FAIL");
  }
  std::printf("%zu modes compared, %d beyond %.3g %% or missing\n", ref.rows.size(), failures, 100 * opt.tol_rel);
  if (failures > 0) throw ComputeError(std::to_string(failures) + " reference modes beyond tolerance or missing");
}

}  // namespace

void addCompareCommand(CLI::App& app) {
  auto opt = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "compare modes (CSV of `whirl modes`, or campbell.csv with --rpm) with a reference table; "
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
