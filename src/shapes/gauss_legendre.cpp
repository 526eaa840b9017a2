#include "src/shapes/gauss_legendre.hpp"

#include <cmath>
#include <numbers>
#include <utility>

namespace whirl {

// Newton's method on the Legendre polynomial P_n from the cosine guesses of its roots, P_n and P_n'
// by the three-term recurrence, and w = 2 / ((1 − x²) P_n'(x)²) (Press et al. 2007, §4.6): O(n²),
// where the nodes as eigenvalues of the Jacobi matrix (Golub and Welsch 1969) cost a dense O(n³)
// eigenproblem (3210 points took minutes under the sanitizers).
void gaussLegendre(int n, VecX& x, VecX& w) {
  x.resize(n);
  w.resize(n);
  // P_n(z) and P_n'(z).
  auto legendre = [n](double z) {
    double p0 = 1, p1 = 0;  // P_j and P_{j−1} at z
    for (int j = 1; j <= n; ++j) {
      const double p2 = p1;
      p1 = p0;
      p0 = ((2 * j - 1) * z * p1 - (j - 1) * p2) / j;
    }
    return std::pair{p0, n * (z * p0 - p1) / (z * z - 1)};
  };
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    for (int it = 0; it < 100; ++it) {
      const auto [p, dp] = legendre(z);
      z -= p / dp;
      if (std::abs(p / dp) <= 1e-15) break;
    }
    const double dp = legendre(z).second;
    x(i) = -z;
    x(n - 1 - i) = z;
    w(i) = w(n - 1 - i) = 2 / ((1 - z * z) * dp * dp);
  }
}

}  // namespace whirl
