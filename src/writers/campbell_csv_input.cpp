#include "src/writers/campbell_csv_input.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

#include "src/base/error.hpp"
#include "src/base/text.hpp"
#include "src/io/text/csv.hpp"

namespace whirl {
namespace {

/// The number in `field` (NaN and inf as formatNumber writes them); nullopt when it is not one.
std::optional<double> number(const std::string& field) {
  double v = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
  if (field.empty() || ec != std::errc() || end != field.data() + field.size()) return std::nullopt;
  return v;
}

/// The column `name` of `t`; InputError naming the file and the column when it is missing.
int requireColumn(const TextTable& t, const std::string& name) {
  const int c = t.column(name);
  if (c < 0) throw InputError(where(t.file, 1, name, "column missing: not a campbell.csv written by whirl campbell"));
  return c;
}

}  // namespace

std::optional<CampbellCsvValue> CampbellCsvLine::at(std::size_t p) const {
  const auto it = std::lower_bound(modes.begin(), modes.end(), p,
                                   [](const auto& m, std::size_t q) { return m.first < q; });
  if (it == modes.end() || it->first != p) return std::nullopt;
  return it->second;
}

CampbellCsvResult readCampbellCsv(const std::string& path) {
  const TextTable t = readTextCsv(path);
  const int c_rpm = requireColumn(t, "rpm"), c_wind = requireColumn(t, "wind_speed"), c_mode = requireColumn(t, "mode"),
            c_freq = requireColumn(t, "freq_hz"), c_damp = requireColumn(t, "damping_ratio");
  CampbellCsvResult r;
  r.file = path;
  std::map<std::string, std::size_t> line_of;  // name → index in r.lines
  std::string head;                            // the current point's "rpm,wind" text
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const std::vector<std::string>& row = t.rows[i];
    const int line = t.lines[i];
    auto fail = [&](int c, const std::string& reason) { throw InputError(where(path, line, t.names[c], reason)); };
    const std::optional<double> rpm = number(row[c_rpm]);
    if (!rpm || !std::isfinite(*rpm)) fail(c_rpm, "expected a finite number");
    const std::optional<double> wind = number(row[c_wind]);
    if (!row[c_wind].empty() && (!wind || !std::isfinite(*wind))) fail(c_wind, "expected a finite number or nothing");
    const std::optional<double> freq = number(row[c_freq]), damp = number(row[c_damp]);
    if (!freq) fail(c_freq, "expected a number");
    if (!damp) fail(c_damp, "expected a number");
    const std::string& name = row[c_mode];
    requirePrintable(name, path, line, "mode");
    if (const std::string reason = invalidUtf8Reason(name); !reason.empty()) fail(c_mode, reason);
    auto [it, added] = line_of.try_emplace(name, r.lines.size());
    if (added) r.lines.push_back({name, {}});
    CampbellCsvLine& l = r.lines[it->second];
    const std::string point_head = row[c_rpm] + "," + row[c_wind];
    // A new point where the speeds change, or where this line already has a mode at the current one.
    if (r.points.empty() || point_head != head || (!l.modes.empty() && l.modes.back().first + 1 == r.points.size())) {
      head = point_head;
      r.points.push_back({*rpm, row[c_wind].empty() ? std::nullopt : wind});
    }
    l.modes.emplace_back(r.points.size() - 1, CampbellCsvValue{*freq, *damp});
  }
  if (r.points.empty()) throw InputError(where(path, 0, "", "no Campbell rows: the sweep found no modes"));
  return r;
}

}  // namespace whirl
