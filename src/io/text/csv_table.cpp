#include "src/io/text/csv_table.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/base/text.hpp"
#include "src/io/text/csv.hpp"
#include "src/io/text/input_file.hpp"

namespace whirl {
namespace {

/// At most 40 characters of a cell, for messages (the file may not be a CSV file at all).
std::string excerpt(const std::string& s) { return s.size() <= 40 ? s : s.substr(0, 40) + "..."; }

}  // namespace

CsvTable readCsv(const std::string& path) {
  CsvTable t;
  t.file = path;
  std::istringstream in;
  std::error_code fs_ec;
  if (std::filesystem::is_directory(path, fs_ec)) throw InputError(where(path, 0, "", "is a folder, not a CSV file"));
  if (!io::openInputFile(path, in)) throw InputError(where(path, 0, "", "cannot open the file"));
  std::string raw;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    const std::string_view s = trimBlanks(raw);
    if (s.empty() || s[0] == '#') continue;
    std::vector<std::string> fields;
    try {
      fields = splitCsvLine(s);
    } catch (const CsvLineError& e) {
      throw InputError(where(path, line, "", e.what()));
    }
    if (t.names.empty()) {
      std::set<std::string> seen;
      for (const auto& f : fields) {
        const std::string& name = f;
        if (name.empty()) throw InputError(where(path, line, "", "empty column name in the header row"));
        if (!seen.insert(name).second) throw InputError(where(path, line, excerpt(name), "column given twice"));
        t.names.push_back(name);
      }
      t.header_line = line;
      t.columns.assign(t.names.size(), {});
      continue;
    }
    if (fields.size() != t.names.size())
      throw InputError(
          where(path, line, "",
                std::to_string(fields.size()) + " fields, the header has " + std::to_string(t.names.size())));
    for (size_t j = 0; j < fields.size(); ++j) {
      std::string f = fields[j];
      if (!f.empty() && f[0] == '+') f.erase(0, 1);
      double v = 0;
      const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
      if (f.empty() || ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v))
        throw InputError(
            where(path, line, excerpt(t.names[j]), "expected a finite number, got '" + excerpt(fields[j]) + "'"));
      t.columns[j].push_back(v);
    }
    if (t.row_lines.size() >= static_cast<std::size_t>(limits::kMaxTableRows))
      throw InputError(io::tooManyRows(path, line));
    t.row_lines.push_back(line);
  }
  if (t.names.empty()) throw InputError(where(path, 0, "", "no header row (the file is empty)"));
  return t;
}

}  // namespace whirl
