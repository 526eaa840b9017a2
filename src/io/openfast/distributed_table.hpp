#pragma once
/// \file
/// Distributed (station-wise) beam properties of an ElastoDyn tower or blade file: a table of columns
/// kept by header name, with the checks every such table needs (row count, finite numbers, fractions
/// from 0 to 1, non-negative mass, positive stiffness). Values stay in the file's units.
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

/// Columns of a distributed-property table, looked up by header name (case-insensitive).
struct DistributedTable {
  std::string file;                         ///< file it was read from (for messages)
  std::vector<std::string> names;           ///< column names as written, e.g. "HtFract"
  std::vector<std::string> units;           ///< unit of each column as written, e.g. "(kg/m)"; "" if not given
  std::vector<std::vector<double>> values;  ///< values[column][station]
  std::vector<int> row_lines;               ///< file line of each station
  bool constant = false;                    ///< one station in the file, stored as two equal rows at 0 and 1

  std::size_t rows() const { return row_lines.size(); }
  /// Column by name, or nullptr.
  const std::vector<double>* find(std::string_view name) const;
  bool has(std::string_view name) const { return find(name) != nullptr; }
  /// Column by name; InputError "file: name: no such column (columns: …)" when absent.
  const std::vector<double>& column(std::string_view name) const;
};

/// Reads the table of `f` that has a column `first_column` and checks it against the integer key
/// `count_key`: at least 1 station, exactly `count_key` rows (fewer = truncated file), one number per
/// column in every row, no NaN or inf, and every column of `required` present. Errors name file, line
/// and key or column. One station (constant properties, which ElastoDyn accepts: SWRT and AWT-27
/// towers) must sit at 0 in `first_column`; it is returned as two equal rows at 0 and 1 (`constant`).
DistributedTable readDistributedTable(const OpenFastFile& f, std::string_view count_key, std::string_view first_column,
                                      std::initializer_list<std::string_view> required);

/// Checks a station fraction column: starts at 0, ends at 1, strictly increasing.
void requireFractionColumn(const DistributedTable& t, std::string_view name);
/// Checks that every value of the column is >= 0 (mass densities).
void requireNonnegativeColumn(const DistributedTable& t, std::string_view name);
/// Checks that every value of the column is > 0 (stiffnesses).
void requirePositiveColumn(const DistributedTable& t, std::string_view name);

}  // namespace whirl::io
