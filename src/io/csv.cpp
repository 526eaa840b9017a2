#include "src/io/csv.hpp"

#include <charconv>
#include <cmath>

namespace whirl {

std::string formatNumber(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + "\"";
}

std::string matrixCsv(const MatX& m, const std::string& corner, const std::vector<std::string>& rows,
                      const std::vector<std::string>& cols) {
  std::string s = csvField(corner);
  for (const auto& c : cols) s += "," + csvField(c);
  s += "\n";
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    s += csvField(rows.at(r));
    for (Eigen::Index c = 0; c < m.cols(); ++c) s += "," + formatNumber(m(r, c));
    s += "\n";
  }
  return s;
}

}  // namespace whirl
