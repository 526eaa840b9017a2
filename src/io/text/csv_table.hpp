#pragma once
/// \file
/// A small reader for numeric CSV tables: a header row of column names, then rows of numbers
/// separated by commas. Blank lines and lines starting with '#' are skipped; spaces around
/// fields are ignored. Every value must be a finite number.
#include <string>
#include <vector>

namespace whirl {

struct CsvTable {
  std::string file;                          ///< as shown in messages
  int header_line = 0;                       ///< 1-based line of the header row
  std::vector<std::string> names;            ///< column names, in order
  std::vector<std::vector<double>> columns;  ///< one per name, all of the same length
  std::vector<int> row_lines;                ///< 1-based line of each row
};

/// Reads `path`. \throws InputError "file:line: column: reason" when the file cannot be opened,
/// has no header, a row has the wrong number of fields, or a field is not a finite number.
CsvTable readCsv(const std::string& path);

}  // namespace whirl
