#include "src/io/case/case_columns.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "src/io/text/csv_table.hpp"
#include "src/io/text/input_file.hpp"

namespace whirl {
namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& k : v) s += (s.empty() ? "" : ", ") + k;
  return s;
}

Columns fromCsv(const CaseNode& file_node, const std::vector<std::string>& allowed) {
  const std::string path = file_node.source().resolve(file_node.text());
  if (const std::string outside = file_node.source().outsideReason(path); !outside.empty()) file_node.fail(outside);
  std::string probe;  // through the readers' preamble: a FIFO is refused, not opened and waited on
  if (!io::readInputFile(path, probe))
    file_node.fail("cannot open '" + path + "' (relative paths start at the case folder)");
  const CsvTable t = readCsv(path);
  Columns cols;
  for (size_t j = 0; j < t.names.size(); ++j) {
    const Where w{t.file, t.header_line, t.names[j], ""};
    if (!contains(allowed, t.names[j])) w.fail("unknown column (allowed: " + join(allowed) + ")");
    Column c{VecX(Eigen::Map<const VecX>(t.columns[j].data(), static_cast<Eigen::Index>(t.columns[j].size()))), w,
             t.row_lines};
    cols.emplace(t.names[j], std::move(c));
  }
  return cols;
}

}  // namespace

void Column::failAt(Eigen::Index i, const std::string& reason) const {
  Where w = where;
  if (i >= 0 && i < static_cast<Eigen::Index>(value_lines.size())) w.line = value_lines[i];
  w.fail(reason);
}

Columns readColumns(const CaseNode& node, const std::vector<std::string>& allowed,
                    const std::vector<std::string>& other_keys) {
  std::vector<std::string> keys = other_keys;
  keys.push_back("file");
  keys.insert(keys.end(), allowed.begin(), allowed.end());
  node.allowKeys(keys);
  Columns cols;
  std::string first;
  if (const auto file = node.find("file")) {
    for (const MapEntry& e : node.entries())
      if (contains(allowed, e.key)) e.key_where.fail("give the columns either inline or in 'file', not both");
    cols = fromCsv(*file, allowed);
    if (cols.empty() || cols.begin()->second.values.size() < 2)
      file->fail("the table needs a header and at least 2 rows");
    return cols;
  }
  for (const MapEntry& e : node.entries()) {
    if (contains(other_keys, e.key)) continue;
    Column c{VecX(), e.value.where(), {}};
    const std::vector<double> v = e.value.numbers();
    c.values = Eigen::Map<const VecX>(v.data(), static_cast<Eigen::Index>(v.size()));
    for (const CaseNode& item : e.value.items()) c.value_lines.push_back(item.line());
    if (first.empty()) {
      first = e.key;
      if (v.size() < 2) c.where.fail("a table needs at least 2 values per column, got " + std::to_string(v.size()));
    } else if (c.values.size() != cols.at(first).values.size()) {
      c.where.fail("has " + std::to_string(v.size()) + " values, " + first + " has " +
                   std::to_string(cols.at(first).values.size()) + " (all columns must have the same length)");
    }
    cols.emplace(e.key, std::move(c));
  }
  if (first.empty()) node.fail("no columns given (expected " + join(allowed) + ", or file)");
  return cols;
}

VecX stations(const CaseNode& node, const Columns& cols, double length, bool to_length) {
  const bool hx = cols.count("x") > 0, hf = cols.count("fraction") > 0;
  if (hx && hf) cols.at("fraction").where.fail("give the stations as x or as fraction, not both");
  if (!hx && !hf) node.fail("missing the stations: a column x [m] or fraction (of the length)");
  const Column& c = cols.at(hx ? "x" : "fraction");
  const VecX x = hx ? c.values : VecX(c.values * length);
  const double tol = 1e-9 * std::max(1.0, length);
  for (Eigen::Index i = 1; i < x.size(); ++i)
    if (!(x(i) > x(i - 1))) c.failAt(i, "stations must increase (value " + std::to_string(i + 1) + ")");
  if (to_length && (std::abs(x(0)) > tol || std::abs(x(x.size() - 1) - length) > tol))
    c.where.fail(hx ? "stations must run from 0 to the length " + num(length) + " m"
                    : std::string("fractions must run from 0 to 1"));
  return x;
}

void requireNonNegative(const Column& c, bool strict) {
  for (Eigen::Index i = 0; i < c.values.size(); ++i)
    if (c.values(i) < 0 || (strict && c.values(i) == 0))
      c.failAt(i, std::string(strict ? "must be positive" : "must not be negative") + ", value " +
                      std::to_string(i + 1) + " is " + num(c.values(i)));
}

}  // namespace whirl
