#include "modal/tracking_overrides.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "src/base/error.hpp"
#include "src/base/text.hpp"
#include "src/io/text/csv.hpp"
#include "src/io/text/input_file.hpp"

namespace whirl {

namespace {

/// A malformed override row; the caller adds file:line.
struct RowError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The fields of an override row (splitCsvLine); a row that is not CSV is a RowError.
std::vector<std::string> splitFields(const std::string& row) {
  try {
    return splitCsvLine(row);
  } catch (const CsvLineError& e) {
    throw RowError(e.what());
  }
}

int parseIndex(const std::string& s, const std::string& what) {
  int v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size() || v < 0)
    throw RowError(what + " '" + s + "' is not a non-negative integer");
  return v;
}

int findLine(const std::vector<CampbellLine>& lines, const std::string& name) {
  for (std::size_t l = 0; l < lines.size(); ++l)
    if (lines[l].name == name) return static_cast<int>(l);
  std::string known;
  for (const auto& l : lines) known += (known.empty() ? "" : ", ") + ("'" + l.name + "'");
  throw RowError("no line named '" + name + "' (lines: " + known + ")");
}

void assignMode(const std::vector<CampbellPoint>& points, std::vector<CampbellLine>& lines, int p, int m,
                const std::string& name) {
  if (p >= static_cast<int>(points.size()))
    throw RowError("point index " + std::to_string(p) + " out of range (" + std::to_string(points.size()) + " points)");
  if (m >= static_cast<int>(points[p].modes.size()))
    throw RowError("mode index " + std::to_string(m) + " out of range (point " + std::to_string(p) + " has " +
                   std::to_string(points[p].modes.size()) + " modes)");
  const int target = findLine(lines, name);
  int holder = -1;
  for (std::size_t l = 0; l < lines.size(); ++l)
    if (lines[l].mode[p] == m) holder = static_cast<int>(l);
  if (holder < 0)
    throw RowError("mode " + std::to_string(m) + " of point " + std::to_string(p) +
                   " is on no line (rigid-body modes are not tracked)");
  if (holder == target) return;
  for (std::size_t q = p; q < points.size(); ++q) std::swap(lines[target].mode[q], lines[holder].mode[q]);
  if (std::all_of(lines[holder].mode.begin(), lines[holder].mode.end(), [](int k) { return k < 0; }))
    lines.erase(lines.begin() + holder);
}

void applyRow(const std::vector<std::string>& f, const std::vector<CampbellPoint>& points,
              std::vector<CampbellLine>& lines) {
  if (f[0] == "rename") {
    if (f.size() != 3) throw RowError("expected 'rename,<line name>,<new name>'");
    if (f[2].empty()) throw RowError("the new name is empty");
    const int l = findLine(lines, f[1]);
    for (std::size_t k = 0; k < lines.size(); ++k)
      if (static_cast<int>(k) != l && lines[k].name == f[2])
        throw RowError("another line is already named '" + f[2] + "'");
    lines[l].name = f[2];
  } else if (f[0] == "assign") {
    if (f.size() != 4) throw RowError("expected 'assign,<point index>,<mode index>,<line name>'");
    assignMode(points, lines, parseIndex(f[1], "point index"), parseIndex(f[2], "mode index"), f[3]);
  } else {
    throw RowError("unknown keyword '" + f[0] + "' (expected rename or assign)");
  }
}

}  // namespace

void applyTrackingOverridesText(const std::string& text, const std::string& file,
                                const std::vector<CampbellPoint>& points, std::vector<CampbellLine>& lines) {
  std::istringstream in(text);
  std::string row;
  for (int line_no = 1; std::getline(in, row); ++line_no) {
    const std::string t(trimBlanks(row));
    if (t.empty() || t[0] == '#') continue;
    requirePrintable(t, file, line_no, "");  // new names go into campbell.gp and the tables
    try {
      applyRow(splitFields(t), points, lines);
    } catch (const RowError& e) {
      throw InputError(where(file, line_no, "", e.what()));
    }
  }
}

void applyTrackingOverrides(const std::string& file, const std::vector<CampbellPoint>& points,
                            std::vector<CampbellLine>& lines) {
  std::string text;
  if (!io::readInputFile(file, text)) throw InputError(where(file, 0, "", "cannot open the tracking override file"));
  applyTrackingOverridesText(text, file, points, lines);
}

}  // namespace whirl
