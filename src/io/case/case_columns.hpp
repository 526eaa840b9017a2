#pragma once
/// \file
/// Named numeric columns of a table in a case (beam properties, table shapes), written either
/// inline as lists in a map or in a CSV file (`file: props.csv`, header row of column names).
#include <map>
#include <string>
#include <vector>

#include "src/io/case/case_node.hpp"

namespace whirl {

/// One column and where each of its values was written.
struct Column {
  VecX values;
  Where where;                   ///< the column (its key, or the CSV header)
  std::vector<int> value_lines;  ///< 1-based line of each value
  /// Fails at value i.
  [[noreturn]] void failAt(Eigen::Index i, const std::string& reason) const;
};

using Columns = std::map<std::string, Column>;

/// Reads the columns of `node`: with `file:` from that CSV file (relative to the case folder),
/// else from the keys of the map. Keys in `other_keys` are the caller's; every other key or CSV
/// column must be one of `allowed`. All columns must have the same length (≥ 2).
/// \throws InputError at the offending key, CSV line or value.
Columns readColumns(const CaseNode& node, const std::vector<std::string>& allowed,
                    const std::vector<std::string>& other_keys);

/// The stations of a table: column `x` [m], or `fraction` × length; exactly one of them, from 0
/// to length (with `to_length`) and increasing.
VecX stations(const CaseNode& node, const Columns& cols, double length, bool to_length);

/// Fails unless every value is ≥ 0 (`strict`: > 0).
void requireNonNegative(const Column& c, bool strict = false);

}  // namespace whirl
