#pragma once
/// \file
/// Optimal assignment (Hungarian algorithm, Kuhn–Munkres with potentials, O(n²m)).
#include <vector>

#include "src/base/types.hpp"

namespace whirl {

/// Assigns each row of `cost` to a distinct column so that the summed cost is minimal.
/// \param[in] cost rows × cols, rows ≤ cols, finite entries.
/// \return per row, the index of its column (dim rows).
/// Throws std::invalid_argument when rows > cols or an entry is not finite.
std::vector<int> solveAssignment(const MatX& cost);

}  // namespace whirl
