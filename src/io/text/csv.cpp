#include "src/io/text/csv.hpp"

#include <charconv>
#include <cmath>
#include <fstream>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/base/text.hpp"
#include "src/io/text/input_file.hpp"

namespace whirl {

std::string formatNumber(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos && trimBlanks(s).size() == s.size()) return s;
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + "\"";
}

std::vector<std::string> splitCsvLine(std::string_view line) {
  std::vector<std::string> out;
  std::string field;
  bool quoted = false, was_quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"' && trimBlanks(field).empty() && !was_quoted) {
      quoted = was_quoted = true;
      field.clear();
    } else if (c == ',') {
      out.emplace_back(was_quoted ? std::string_view(field) : trimBlanks(field));
      field.clear();
      was_quoted = false;
    } else if (!was_quoted) {
      field += c;
    } else if (!trimBlanks(std::string_view(&c, 1)).empty()) {
      throw CsvLineError("text after a closing quote");
    }
  }
  if (quoted) throw CsvLineError("unterminated quote");
  out.emplace_back(was_quoted ? std::string_view(field) : trimBlanks(field));
  return out;
}

int TextTable::column(const std::string& name) const {
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  return -1;
}

TextTable readTextCsv(const std::string& path) {
  std::istringstream in;
  if (!io::openInputFile(path, in)) throw InputError(path + ": cannot open");
  TextTable t;
  t.file = path;
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty() || line == "\r") continue;
    std::vector<std::string> f;
    try {
      f = splitCsvLine(line);
    } catch (const CsvLineError& e) {
      throw InputError(where(path, n, "", e.what()));
    }
    // Fields become mode names, --set keys and values: one printable line each.
    for (size_t c = 0; c < f.size(); ++c)
      requirePrintable(f[c], path, n, t.names.empty() || c >= t.names.size() ? "" : t.names[c]);
    if (t.names.empty()) {
      t.names = f;
      continue;
    }
    if (f.size() != t.names.size())
      throw InputError(
          where(path, n, "",
                "expected " + std::to_string(t.names.size()) + " fields, found " + std::to_string(f.size())));
    if (t.rows.size() >= static_cast<std::size_t>(limits::kMaxTableRows)) throw InputError(io::tooManyRows(path, n));
    t.rows.push_back(std::move(f));
    t.lines.push_back(n);
  }
  if (t.names.empty()) throw InputError(path + ": empty file (no header row)");
  return t;
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
