// Multipliers of a product of propagators from the block-cyclic eigenproblem
// (modal/floquet_multipliers.hpp): λ^G equals the eigenvalues of the product where the product can be
// formed, and keeps a multiplier the formed product loses below its round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "modal/eigen.hpp"
#include "modal/floquet_multipliers.hpp"

namespace whirl {
namespace {

std::vector<std::complex<double>> sorted(std::vector<std::complex<double>> v) {
  std::sort(v.begin(), v.end(), [](auto a, auto b) {
    return std::abs(a) != std::abs(b) ? std::abs(a) < std::abs(b) : std::arg(a) < std::arg(b);
  });
  return v;
}

TEST(FloquetMultipliers, RootsToTheGEqualTheProductsEigenvalues) {
  // Three factors with a rotation (complex multipliers), a decay and a negative direction.
  std::vector<MatX> f;
  for (int g = 0; g < 3; ++g) {
    MatX a(3, 3);
    const double t = 0.4 + 0.3 * g;
    a << std::cos(t), -std::sin(t), 0.1 * g, std::sin(t), std::cos(t), 0.2, 0.05, 0.0, -0.7 + 0.1 * g;
    f.push_back(0.9 * a);
  }
  const MatX product = f[2] * f[1] * f[0];
  const EigenDecomposition ed = eigenStandard(product);
  const LiftedMultipliers l = liftedMultipliers(f);
  ASSERT_EQ(l.groups, 3);
  std::vector<std::complex<double>> expected(ed.values.data(), ed.values.data() + 3), got;
  for (int j = 0; j < 3; ++j) {
    got.push_back(std::pow(l.root(j), 3));
    EXPECT_LE(std::abs(std::arg(l.root(j))), std::numbers::pi / 3 + 1e-12);  // the principal root
    // x_0 is an eigenvector of the product for μ = λ^G.
    const Eigen::VectorXcd x = l.blocks[0].col(j);
    EXPECT_LT((product.cast<std::complex<double>>() * x - got.back() * x).norm(), 1e-12 * x.norm());
  }
  expected = sorted(expected);
  got = sorted(got);
  for (int j = 0; j < 3; ++j) EXPECT_LT(std::abs(got[j] - expected[j]), 1e-12) << j;
}

// A direction that decays by 1e-6 per factor: over 4 factors 1e-24, below the round-off of the
// formed product (its other multiplier is 1), which returns noise; the roots keep it.
TEST(FloquetMultipliers, KeepsWhatTheFormedProductLoses) {
  const double c = std::cos(0.3), s = std::sin(0.3);
  MatX Q(2, 2);
  Q << c, -s, s, c;
  const MatX factor = Q * Eigen::Vector2d(1.0, 1e-6).asDiagonal() * Q.transpose();
  const std::vector<MatX> f(4, factor);
  const LiftedMultipliers l = liftedMultipliers(f);
  std::vector<double> mags = {std::abs(l.root(0)), std::abs(l.root(1))};
  std::sort(mags.begin(), mags.end());
  EXPECT_NEAR(mags[0], 1e-6, 1e-15);
  EXPECT_NEAR(mags[1], 1.0, 1e-12);
  const EigenDecomposition formed = eigenStandard(f[3] * f[2] * f[1] * f[0]);
  const double small = std::min(std::abs(formed.values(0)), std::abs(formed.values(1)));
  EXPECT_GT(std::abs(small - 1e-24), 1e-20);  // the formed product has lost it
}

}  // namespace
}  // namespace whirl
