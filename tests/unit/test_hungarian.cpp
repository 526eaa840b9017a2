// Optimal assignment: the Hungarian algorithm against brute force over all permutations.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "modal/hungarian.hpp"

namespace whirl {
namespace {

double bruteForce(const MatX& c) {
  std::vector<int> cols(c.cols());
  std::iota(cols.begin(), cols.end(), 0);
  double best = INFINITY;
  do {  // the first rows() entries of every permutation cover every injective assignment
    double s = 0;
    for (int i = 0; i < c.rows(); ++i) s += c(i, cols[i]);
    best = std::min(best, s);
  } while (std::next_permutation(cols.begin(), cols.end()));
  return best;
}

TEST(Hungarian, MatchesBruteForceOnRandomSquareAndRectangularCosts) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 50; ++trial) {
    const int rows = 1 + trial % 6, cols = rows + trial % 3;
    MatX c(rows, cols);
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j) c(i, j) = trial % 5 == 0 ? std::round(4 * u(rng)) : u(rng);  // ties too
    const auto a = solveAssignment(c);
    ASSERT_EQ(a.size(), static_cast<std::size_t>(rows));
    double s = 0;
    std::vector<int> seen;
    for (int i = 0; i < rows; ++i) {
      ASSERT_GE(a[i], 0);
      ASSERT_LT(a[i], cols);
      seen.push_back(a[i]);
      s += c(i, a[i]);
    }
    std::sort(seen.begin(), seen.end());
    EXPECT_EQ(std::adjacent_find(seen.begin(), seen.end()), seen.end()) << "a column used twice";
    EXPECT_NEAR(s, bruteForce(c), 1e-12) << "trial " << trial;
  }
}

TEST(Hungarian, EmptyAndInvalidInput) {
  EXPECT_TRUE(solveAssignment(MatX(0, 0)).empty());
  EXPECT_THROW(solveAssignment(MatX::Zero(3, 2)), std::invalid_argument);
  MatX c = MatX::Zero(2, 2);
  c(1, 0) = NAN;
  EXPECT_THROW(solveAssignment(c), std::invalid_argument);
}

}  // namespace
}  // namespace whirl
