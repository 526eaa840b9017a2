#pragma once
/// \file
/// The table of `whirl study` (study.csv): parameter sets × operating points, each set its own
/// Campbell diagram, tracked on its own; its rows are the campbell.csv rows (src/writers/
/// campbell_output.hpp) prefixed by the set number and the set's values.
#include <string>
#include <vector>

#include "modal/campbell.hpp"
#include "modal/tracking.hpp"

namespace whirl {

/// study.csv text. `points` holds the sets one after another, each with the same number of points;
/// `names` are the parameter (--set key) columns, `values[s]` set s's values (dim names.size()).
std::string studyCsv(const std::vector<std::string>& names, const std::vector<std::vector<std::string>>& values,
                     const std::vector<CampbellPoint>& points, const TrackingOptions& track);

}  // namespace whirl
