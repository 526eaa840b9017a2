#include "modal/hungarian.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace whirl {

// Shortest augmenting paths with row/column potentials u, v (reduced cost c(i,j) − u(i) − v(j) ≥ 0).
// Rows are added one at a time; index 0 is a virtual column that holds the row being inserted.
std::vector<int> solveAssignment(const MatX& cost) {
  const int n = static_cast<int>(cost.rows()), m = static_cast<int>(cost.cols());
  if (n > m) throw std::invalid_argument("solveAssignment: more rows than columns");
  if (!cost.allFinite()) throw std::invalid_argument("solveAssignment: cost has a non-finite entry");
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(n + 1, 0.0), v(m + 1, 0.0);
  std::vector<int> row_of(m + 1, 0), way(m + 1, 0);  // row_of[j]: 1-based row assigned to column j
  for (int i = 1; i <= n; ++i) {
    row_of[0] = i;
    int j0 = 0;
    std::vector<double> minv(m + 1, inf);
    std::vector<char> used(m + 1, false);
    do {
      used[j0] = true;
      const int i0 = row_of[j0];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= m; ++j) {
        if (used[j]) continue;
        const double cur = cost(i0 - 1, j - 1) - u[i0] - v[j];
        if (cur < minv[j]) {
          minv[j] = cur;
          way[j] = j0;
        }
        if (minv[j] < delta) {
          delta = minv[j];
          j1 = j;
        }
      }
      for (int j = 0; j <= m; ++j) {
        if (used[j]) {
          u[row_of[j]] += delta;
          v[j] -= delta;
        } else {
          minv[j] -= delta;
        }
      }
      j0 = j1;
    } while (row_of[j0] != 0);
    do {  // flip the augmenting path
      const int j1 = way[j0];
      row_of[j0] = row_of[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<int> col(n, -1);
  for (int j = 1; j <= m; ++j)
    if (row_of[j] != 0) col[row_of[j] - 1] = j - 1;
  return col;
}

}  // namespace whirl
