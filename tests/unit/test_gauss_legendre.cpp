// Gauss–Legendre nodes and weights against closed-form values and the exactness of degree 2n − 1.
#include <gtest/gtest.h>

#include <cmath>

#include "src/shapes/gauss_legendre.hpp"

namespace whirl {
namespace {

// Closed form for n = 2 and 3 (x = ±1/√3; x = 0, ±√(3/5) with w = 8/9, 5/9) and the tabulated 4-point
// rule (Abramowitz and Stegun 1964, table 25.4, 15 digits).
TEST(GaussLegendre, MatchesClosedFormAndTabulatedRules) {
  VecX x, w;
  gaussLegendre(1, x, w);
  EXPECT_NEAR(x(0), 0.0, 1e-16);
  EXPECT_NEAR(w(0), 2.0, 1e-15);
  gaussLegendre(2, x, w);
  EXPECT_NEAR(x(1), 1 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(x(0), -1 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(w(0), 1.0, 1e-15);
  gaussLegendre(3, x, w);
  EXPECT_NEAR(x(0), -std::sqrt(0.6), 1e-15);
  EXPECT_NEAR(x(1), 0.0, 1e-16);
  EXPECT_NEAR(w(1), 8.0 / 9, 1e-15);
  EXPECT_NEAR(w(2), 5.0 / 9, 1e-15);
  gaussLegendre(4, x, w);
  EXPECT_NEAR(x(3), 0.861136311594053, 1e-15);
  EXPECT_NEAR(x(2), 0.339981043584856, 1e-15);
  EXPECT_NEAR(w(3), 0.347854845137454, 1e-15);
  EXPECT_NEAR(w(2), 0.652145154862546, 1e-15);
}

// n points integrate x^(2k) exactly up to 2k = 2n − 2 (∫₋₁¹ x^(2k) dx = 2/(2k + 1)) and odd powers to
// zero; nodes ascend and are symmetric. Up to the 500 points a case may ask for.
TEST(GaussLegendre, IsExactForPolynomialsOfDegreeTwoNMinusOne) {
  for (int n : {5, 40, 201, 500}) {
    VecX x, w;
    gaussLegendre(n, x, w);
    ASSERT_EQ(x.size(), n);
    EXPECT_NEAR(w.sum(), 2.0, 1e-13) << n;
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(x(i), -x(n - 1 - i), 1e-15) << n;
      if (i > 0) {
        EXPECT_LT(x(i - 1), x(i)) << n;
      }
      EXPECT_GT(w(i), 0.0) << n;
    }
    for (int k : {1, n / 2, n - 1}) {
      // A scalar loop: GCC 12 warns inside Eigen's AVX-512 pow at -march=native (warnings are errors in CI).
      double even = 0, odd = 0;
      for (int i = 0; i < n; ++i) {
        even += w(i) * std::pow(x(i), 2 * k);
        odd += w(i) * std::pow(x(i), 2 * k - 1);
      }
      EXPECT_NEAR(even, 2.0 / (2 * k + 1), 1e-13) << "n " << n << ", x^" << 2 * k;
      EXPECT_NEAR(odd, 0.0, 1e-13) << "n " << n << ", x^" << 2 * k - 1;
    }
  }
}

}  // namespace
}  // namespace whirl
