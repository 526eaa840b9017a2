#pragma once
/// \file
/// Piecewise-linear interpolation in a table of stations, as ElastoDyn and BModes interpolate
/// distributed properties.
#include <algorithm>

#include "src/base/types.hpp"

namespace whirl {

/// v at xi from stations x (increasing) and values v (same size): linear between stations, the end
/// value outside them; 0 for an empty column (a property not given).
inline double interpolateStations(const VecX& x, const VecX& v, double xi) {
  if (v.size() == 0) return 0.0;
  const Eigen::Index n = x.size();
  if (n == 1) return v(0);
  Eigen::Index i = 0;
  while (i < n - 2 && xi > x(i + 1)) ++i;
  const double w = std::clamp((xi - x(i)) / (x(i + 1) - x(i)), 0.0, 1.0);
  return (1 - w) * v(i) + w * v(i + 1);
}

}  // namespace whirl
