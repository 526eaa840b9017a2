#include "src/io/openfast/distributed_table.hpp"

#include <cmath>

#include "src/base/error.hpp"
#include "src/io/openfast/elastodyn_common.hpp"

namespace whirl::io {
namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : " ") + n;
  return s;
}

int indexOf(const DistributedTable& t, std::string_view name) {
  const std::string n = toLower(name);
  for (std::size_t i = 0; i < t.names.size(); ++i)
    if (toLower(t.names[i]) == n) return static_cast<int>(i);
  return -1;
}

/// The column's name as written in the file (for messages).
std::string writtenName(const DistributedTable& t, std::string_view name) {
  const int i = indexOf(t, name);
  return i < 0 ? std::string(name) : t.names[static_cast<std::size_t>(i)];
}

}  // namespace

const std::vector<double>* DistributedTable::find(std::string_view name) const {
  const int i = indexOf(*this, name);
  return i < 0 ? nullptr : &values[static_cast<std::size_t>(i)];
}

const std::vector<double>& DistributedTable::column(std::string_view name) const {
  if (const std::vector<double>* c = find(name)) return *c;
  throw InputError(where(file, 0, std::string(name), "no such column (columns: " + joined(names) + ")"));
}

DistributedTable readDistributedTable(const OpenFastFile& f, std::string_view count_key, std::string_view first_column,
                                      std::initializer_list<std::string_view> required) {
  const std::string file = f.path().string();
  const std::string key(count_key);
  const int count = f.getInt(count_key);
  if (count < 1) throw InputError(f.where(count_key, "must be at least 1, is " + std::to_string(count)));
  const OpenFastTable* tab = f.findTable(first_column);
  if (!tab)
    throw InputError(
        f.where(count_key, "no table with a '" + std::string(first_column) + "' column found (truncated file?)"));
  const int rows = static_cast<int>(tab->rows.size());
  if (rows < count) {
    const std::string at = tab->ends_at_eof ? "the file ends"
                                            : "line " + std::to_string(tab->end_line) + " is not a row of numbers";
    throw InputError(where(file, tab->end_line, key,
                           "table has " + std::to_string(rows) + " rows, " + std::to_string(count) +
                               " expected: " + at + " (truncated table?)"));
  }
  if (rows > count)
    throw InputError(where(file, tab->row_lines[static_cast<std::size_t>(count)], key,
                           "table has " + std::to_string(rows) + " rows, only " + std::to_string(count) + " expected"));

  DistributedTable t;
  t.file = file;
  t.names = tab->columns;
  t.row_lines = tab->row_lines;
  t.values.assign(t.names.size(), std::vector<double>(static_cast<std::size_t>(rows)));
  for (std::size_t c = 0; c < t.names.size(); ++c) t.units.push_back(c < tab->units.size() ? tab->units[c] : "");
  for (std::size_t r = 0; r < tab->rows.size(); ++r) {
    const std::vector<double>& row = tab->rows[r];
    if (row.size() != t.names.size())
      throw InputError(where(file, tab->row_lines[r], "",
                             "row has " + std::to_string(row.size()) + " numbers, the table has " +
                                 std::to_string(t.names.size()) + " columns (" + joined(t.names) + ")"));
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (!std::isfinite(row[c]))
        throw InputError(
            where(file, tab->row_lines[r], t.names[c], std::isnan(row[c]) ? "value is NaN" : "value is infinite"));
      t.values[c][r] = row[c];
    }
  }
  for (std::string_view name : required)
    if (!t.has(name))
      throw InputError(where(file, tab->header_line, std::string(name),
                             "column missing from the table (columns: " + joined(t.names) + ")"));
  if (count == 1) {
    // One station: ElastoDyn holds its properties over the whole span (InterpStp of one point; the
    // fraction must be 0, ValidateTowerData/ValidateBladeData). Two equal stations at fractions 0 and
    // 1 interpolate to the same constant everywhere, and every later use needs no special case.
    const int c = indexOf(t, first_column);
    if (t.values[static_cast<std::size_t>(c)].front() != 0.0)
      throw InputError(where(file, t.row_lines.front(), t.names[static_cast<std::size_t>(c)],
                             "the only station must be at 0 (is " +
                                 numberText(t.values[static_cast<std::size_t>(c)].front()) + ")"));
    for (std::vector<double>& v : t.values) v.push_back(v.front());
    t.values[static_cast<std::size_t>(c)].back() = 1.0;
    t.row_lines.push_back(t.row_lines.front());
    t.constant = true;
  }
  return t;
}

void requireFractionColumn(const DistributedTable& t, std::string_view name) {
  const std::vector<double>& x = t.column(name);
  const std::string n = writtenName(t, name);
  if (x.front() != 0.0)
    throw InputError(where(t.file, t.row_lines.front(), n, "must start at 0 (is " + numberText(x.front()) + ")"));
  for (std::size_t r = 1; r < x.size(); ++r)
    if (!(x[r] > x[r - 1]))
      throw InputError(
          where(t.file, t.row_lines[r], n,
                "must increase from station to station (" + numberText(x[r]) + " after " + numberText(x[r - 1]) + ")"));
  if (x.back() != 1.0)
    throw InputError(where(t.file, t.row_lines.back(), n, "must end at 1 (is " + numberText(x.back()) + ")"));
}

void requireNonnegativeColumn(const DistributedTable& t, std::string_view name) {
  const std::vector<double>& v = t.column(name);
  for (std::size_t r = 0; r < v.size(); ++r)
    if (v[r] < 0.0)
      throw InputError(
          where(t.file, t.row_lines[r], writtenName(t, name), "must not be negative (is " + numberText(v[r]) + ")"));
}

void requirePositiveColumn(const DistributedTable& t, std::string_view name) {
  const std::vector<double>& v = t.column(name);
  for (std::size_t r = 0; r < v.size(); ++r)
    if (!(v[r] > 0.0))
      throw InputError(
          where(t.file, t.row_lines[r], writtenName(t, name), "must be positive (is " + numberText(v[r]) + ")"));
}

}  // namespace whirl::io
