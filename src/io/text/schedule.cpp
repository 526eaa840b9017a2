#include "src/io/text/schedule.hpp"

#include <algorithm>
#include <cctype>
#include <optional>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/io/text/csv_table.hpp"

namespace whirl {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

int findColumn(const CsvTable& t, bool (*match)(const std::string&)) {
  for (size_t i = 0; i < t.names.size(); ++i)
    if (match(lower(t.names[i]))) return static_cast<int>(i);
  return -1;
}

}  // namespace

std::vector<SweepPoint> readSchedule(const std::string& path) {
  const CsvTable t = readCsv(path);
  int rpm = findColumn(t, [](const std::string& n) { return n.rfind("rotspeed", 0) == 0; });
  if (rpm < 0) rpm = findColumn(t, [](const std::string& n) { return n == "rpm" || n.rfind("rpm_", 0) == 0; });
  if (rpm < 0)
    throw InputError(where(path, t.header_line, "", "no rotor-speed column (a column named RotSpeed… or rpm)"));
  const int ws = findColumn(t, [](const std::string& n) { return n.rfind("ws", 0) == 0 || n.rfind("wind", 0) == 0; });
  const int pitch = findColumn(t, [](const std::string& n) {
    return n.rfind("bldpitch", 0) == 0 || n.rfind("pitch", 0) == 0;
  });
  std::vector<SweepPoint> pts;
  for (size_t r = 0; r < t.columns[rpm].size(); ++r) {
    const double speed = t.columns[rpm][r];
    if (speed < 0) throw InputError(where(path, t.row_lines[r], t.names[rpm], "negative rotor speed"));
    std::optional<double> wind, pitch_deg;
    if (ws >= 0) wind = t.columns[ws][r];
    if (pitch >= 0) pitch_deg = t.columns[pitch][r];
    pts.push_back(sweepPoint(speed, wind, pitch_deg));
  }
  if (pts.empty()) throw InputError(where(path, 0, "", "the schedule has no rows"));
  if (pts.size() > static_cast<size_t>(limits::kMaxSweepPoints))
    throw InputError(where(path, t.row_lines[limits::kMaxSweepPoints], "",
                           "more than " + std::to_string(limits::kMaxSweepPoints) + " rows (src/base/limits.hpp)"));
  return pts;
}

}  // namespace whirl
