#pragma once
/// \file
/// CSV text with full precision (shortest round-trip representation, std::to_chars) and quoting
/// of names that contain separators.
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "src/base/types.hpp"

namespace whirl {

/// Shortest decimal text that reads back to exactly x; "nan"/"inf" for non-finite values.
std::string formatNumber(double x);

/// A CSV field: quoted (with doubled quotes) when it holds a comma, quote or newline, or begins or
/// ends with a blank (splitCsvLine trims unquoted fields).
std::string csvField(const std::string& s);

/// A line that is not CSV (an open quote, text after a closing quote); the reason only, the caller
/// adds file:line.
struct CsvLineError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Fields of one CSV line, the one splitter of every CSV whirl reads: unquoted fields trimmed of
/// blanks; a field that starts with `"` (after blanks) is quoted and may hold commas and doubled
/// quotes (""), kept as written. \throws CsvLineError for an unterminated quote or text after a
/// closing quote.
std::vector<std::string> splitCsvLine(std::string_view line);

/// A text CSV table: header names and rows of fields, with 1-based line numbers.
struct TextTable {
  std::string file;
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> rows;
  std::vector<int> lines;
  /// Index of the column named `name`, −1 if absent.
  int column(const std::string& name) const;
};

/// Reads a CSV with a header row; InputError naming file:line for a missing file or a row with a
/// different number of fields.
TextTable readTextCsv(const std::string& path);

/// A labelled matrix: header "corner,col1,col2,…", then one row per row name.
std::string matrixCsv(const MatX& m, const std::string& corner, const std::vector<std::string>& row_names,
                      const std::vector<std::string>& col_names);

}  // namespace whirl
