#include "modal/mode_compare.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "src/base/error.hpp"
#include "src/io/text/csv.hpp"

namespace whirl {
namespace {

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

}  // namespace

std::vector<NamedFrequency> readResultModes(const std::string& path, std::optional<double> rpm) {
  const TextTable res = readTextCsv(path);
  const int rname = res.column("name") >= 0 ? res.column("name") : res.column("mode");
  const int rfreq = res.column("freq_hz"), rrpm = res.column("rpm");
  if (rname < 0 || rfreq < 0) throw InputError(path + ": needs columns name (or mode) and freq_hz");
  if (rrpm >= 0 && !rpm) throw InputError(path + ": a Campbell table; choose the operating point with --rpm");
  std::vector<NamedFrequency> modes;
  for (size_t r = 0; r < res.rows.size(); ++r) {
    if (rrpm >= 0 && std::abs(number(res, r, rrpm) - *rpm) > 1e-9) continue;
    modes.push_back({res.rows[r][rname], number(res, r, rfreq)});
  }
  if (modes.empty()) throw InputError(path + ": no modes" + (rpm ? " at that --rpm" : ""));
  return modes;
}

std::vector<ReferenceMode> readReferenceModes(const std::string& path) {
  const TextTable ref = readTextCsv(path);
  const int fmode = ref.column("mode"), ffreq = ref.column("freq_hz"), fwhirl = ref.column("whirl_mode");
  if (fmode < 0 || ffreq < 0) throw InputError(path + ": needs columns mode and freq_hz");
  std::vector<ReferenceMode> rows;
  for (size_t r = 0; r < ref.rows.size(); ++r)
    rows.push_back({ref.rows[r][fmode], number(ref, r, ffreq), ref.rows[r][fwhirl >= 0 ? fwhirl : fmode]});
  return rows;
}

std::vector<ModeComparison> compareModes(const std::vector<NamedFrequency>& modes,
                                         const std::vector<ReferenceMode>& ref, double tol_rel) {
  // Reference rows sharing a name set are compared as a set; "*" means the mode nearest in frequency.
  std::vector<bool> used(modes.size(), false);
  std::map<std::string, std::vector<size_t>> sets;
  for (size_t r = 0; r < ref.size(); ++r) sets[ref[r].whirl_mode].push_back(r);
  std::vector<std::optional<NamedFrequency>> match(ref.size());
  for (size_t r = 0; r < ref.size(); ++r) {
    const std::string& key = ref[r].whirl_mode;
    if (match[r]) continue;
    const auto names = splitSet(key);
    const auto& rows = sets[key];
    std::vector<size_t> cand;
    for (size_t k = 0; k < modes.size(); ++k)
      if (!used[k] && (key == "*" || std::find(names.begin(), names.end(), modes[k].name) != names.end()))
        cand.push_back(k);
    if (key == "*" || rows.size() == 1) {
      // The candidate nearest the reference frequency (a name may be carried by several modes).
      const double f = ref[r].freq_hz;
      auto best = std::min_element(cand.begin(), cand.end(), [&](size_t a, size_t b) {
        return std::abs(modes[a].freq_hz - f) < std::abs(modes[b].freq_hz - f);
      });
      if (best != cand.end()) {
        used[*best] = true;
        match[r] = modes[*best];
      }
      continue;
    }
    std::vector<size_t> rs = rows;
    std::sort(rs.begin(), rs.end(), [&](size_t a, size_t b) { return ref[a].freq_hz < ref[b].freq_hz; });
    std::sort(cand.begin(), cand.end(), [&](size_t a, size_t b) { return modes[a].freq_hz < modes[b].freq_hz; });
    for (size_t k = 0; k < rs.size() && k < cand.size(); ++k) {
      used[cand[k]] = true;
      match[rs[k]] = modes[cand[k]];
    }
  }
  std::vector<ModeComparison> out;
  for (size_t r = 0; r < ref.size(); ++r) {
    ModeComparison c{ref[r], match[r], 0, false};
    if (match[r]) {
      c.rel_error = (match[r]->freq_hz - ref[r].freq_hz) / ref[r].freq_hz;
      c.ok = std::abs(c.rel_error) <= tol_rel;
    }
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace whirl
