#include "src/writers/study_table.hpp"

#include "src/io/text/csv.hpp"
#include "src/writers/campbell_output.hpp"

namespace whirl {

std::string studyCsv(const std::vector<std::string>& names, const std::vector<std::vector<std::string>>& values,
                     const std::vector<CampbellPoint>& points, const TrackingOptions& track) {
  const size_t S = values.size(), P = S == 0 ? 0 : points.size() / S;
  std::string head = "set";
  for (const auto& n : names) head += "," + csvField(n);
  std::string csv;
  for (size_t s = 0; s < S; ++s) {
    CampbellDiagram d;
    d.points.assign(points.begin() + static_cast<long>(s * P), points.begin() + static_cast<long>((s + 1) * P));
    d.lines = trackModes(d.points, track);
    const std::string table = campbellCsv(d);
    const size_t eol = table.find('\n');
    if (s == 0) csv = head + "," + table.substr(0, eol + 1);
    std::string prefix = std::to_string(s + 1);
    for (const auto& v : values[s]) prefix += "," + csvField(v);
    for (size_t a = eol + 1; a < table.size();) {
      const size_t b = table.find('\n', a);
      csv += prefix + "," + table.substr(a, b - a + 1);
      a = b + 1;
    }
  }
  return csv;
}

}  // namespace whirl
