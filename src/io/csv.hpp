#pragma once
/// \file
/// CSV text with full precision (shortest round-trip representation, std::to_chars) and quoting
/// of names that contain separators.
#include <string>
#include <vector>

#include "src/model/types.hpp"

namespace whirl {

/// Shortest decimal text that reads back to exactly x; "nan"/"inf" for non-finite values.
std::string formatNumber(double x);

/// A CSV field: quoted (with doubled quotes) when it holds a comma, quote or newline.
std::string csvField(const std::string& s);

/// A labelled matrix: header "corner,col1,col2,…", then one row per row name.
std::string matrixCsv(const MatX& m, const std::string& corner, const std::vector<std::string>& row_names,
                      const std::vector<std::string>& col_names);

}  // namespace whirl
