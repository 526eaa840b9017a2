#include "src/aero/ua_span.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace whirl::aero {

std::vector<bool> uaSpanMask(const std::vector<double>& r_local, double r_max, double start, double end) {
  const int n = static_cast<int>(r_local.size());
  int inner = -1, outer = n;  // 0-based: off for j <= inner and j >= outer
  for (int j = 0; j < n; ++j) {
    const double frac = r_local[static_cast<std::size_t>(j)] / r_max;
    if (frac < start) inner = std::max(inner, j);
    else if (frac > end) outer = std::min(outer, j);
  }
  std::vector<bool> on(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) on[static_cast<std::size_t>(j)] = j > inner && j < outer;
  return on;
}

bool uaPossible(const UaTable& t) {
  if (!t.included) return false;
  // AeroDyn's EqualRealNos(C_lalpha, 0) (double): |C_lalpha| <= 50 ε.
  if (std::abs(t.c.c_lalpha) <= 50.0 * std::numeric_limits<double>::epsilon()) return false;
  const std::vector<double>& f = t.columns.cl;  // f_st on the knots
  return !f.empty() && *std::max_element(f.begin(), f.end()) > 0.0;
}

}  // namespace whirl::aero
