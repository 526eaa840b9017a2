// Dense eigenanalysis: closed-form 2-DOF system, second-order pencil vs state matrix, bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "modal/eigen.hpp"
#include "src/base/error.hpp"

namespace {

using cd = std::complex<double>;

std::vector<cd> sorted(const Eigen::VectorXcd& v) {
  std::vector<cd> s(v.data(), v.data() + v.size());
  std::sort(s.begin(), s.end(),
            [](cd a, cd b) { return a.imag() != b.imag() ? a.imag() < b.imag() : a.real() < b.real(); });
  return s;
}

// Two equal masses m, each on a spring k to ground, coupled by kc, with dampers c to ground:
// M = m I, K = [[k+kc, -kc], [-kc, k+kc]], C = c I. Modes (1, 1) and (1, -1) with
// ω1² = k/m, ω2² = (k + 2kc)/m and λ = -c/2m ± i sqrt(ω² - (c/2m)²).
struct TwoDof {
  double m = 2.0, k = 800.0, kc = 100.0, c = 4.0;
  Eigen::MatrixXd M() const { return m * Eigen::MatrixXd::Identity(2, 2); }
  Eigen::MatrixXd C() const { return c * Eigen::MatrixXd::Identity(2, 2); }
  Eigen::MatrixXd K() const { return (Eigen::MatrixXd(2, 2) << k + kc, -kc, -kc, k + kc).finished(); }
  Eigen::MatrixXd A() const {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(4, 4);
    a.topRightCorner(2, 2).setIdentity();
    a.bottomLeftCorner(2, 2) = -M().ldlt().solve(K());
    a.bottomRightCorner(2, 2) = -M().ldlt().solve(C());
    return a;
  }
  std::vector<cd> exact() const {
    const double s = c / (2 * m), w1 = std::sqrt(k / m - s * s), w2 = std::sqrt((k + 2 * kc) / m - s * s);
    return {{-s, -w2}, {-s, -w1}, {-s, w1}, {-s, w2}};  // sorted by imaginary part
  }
};

TEST(Eigen, TwoDofClosedFormStandard) {
  const TwoDof sys;
  const auto ev = sorted(whirl::eigenStandard(sys.A()).values);
  const auto ex = sys.exact();
  ASSERT_EQ(ev.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_LT(std::abs(ev[i] - ex[i]), 1e-12 * std::abs(ex[i])) << i;
}

TEST(Eigen, TwoDofClosedFormSecondOrder) {
  const TwoDof sys;
  const auto d = whirl::eigenSecondOrder(sys.M(), sys.C(), sys.K());
  const auto ev = sorted(d.values);
  const auto ex = sys.exact();
  ASSERT_EQ(ev.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_LT(std::abs(ev[i] - ex[i]), 1e-12 * std::abs(ex[i])) << i;
  // Mode 1 is in phase: q = (1, 1) up to scale.
  for (Eigen::Index j = 0; j < 4; ++j) {
    if (std::abs(d.values(j) - ex[2]) > 1e-9) continue;
    EXPECT_LT(std::abs(d.vectors(0, j) - d.vectors(1, j)), 1e-12);
  }
}

TEST(Eigen, ModalFrequencyOfTwoDof) {
  const TwoDof sys;
  const auto f = whirl::modalFrequency(sys.exact()[2]);  // λ = -1 + i sqrt(399): ω = 20 rad/s
  EXPECT_NEAR(f.freq_hz, 20.0 / (2 * std::numbers::pi), 1e-14);
  EXPECT_NEAR(f.damped_freq_hz, std::sqrt(399.0) / (2 * std::numbers::pi), 1e-14);
  EXPECT_NEAR(f.damping_ratio, 1.0 / 20.0, 1e-15);
  const auto zero = whirl::modalFrequency({0.0, 0.0});
  EXPECT_EQ(zero.freq_hz, 0.0);
  EXPECT_EQ(zero.damping_ratio, 0.0);
  EXPECT_NEAR(whirl::modalFrequency({-3.0, 0.0}).damping_ratio, 1.0, 1e-15);  // overdamped real root
}

// A non-proportionally damped, gyroscopic 3-DOF system with a full mass matrix.
TEST(Eigen, SecondOrderEqualsStandardOfStateMatrix) {
  Eigen::MatrixXd M(3, 3), C(3, 3), K(3, 3);
  M << 4, 1, 0.5, 1, 3, 0.2, 0.5, 0.2, 2;
  C << 0.3, 2.0, 0.0, -2.0, 0.1, 0.4, 0.1, -0.4, 0.2;
  K << 50, -10, 0, -10, 40, -5, 0, -5, 30;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(6, 6);
  A.topRightCorner(3, 3).setIdentity();
  A.bottomLeftCorner(3, 3) = -M.lu().solve(K);
  A.bottomRightCorner(3, 3) = -M.lu().solve(C);

  const auto s = whirl::eigenStandard(A);
  const auto g = whirl::eigenSecondOrder(M, C, K);
  const auto vs = sorted(s.values), vg = sorted(g.values);
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(vs[i] - vg[i]), 1e-11 * std::abs(vs[i])) << i;

  for (Eigen::Index j = 0; j < 6; ++j) {
    const cd lam = g.values(j);
    const Eigen::VectorXcd x = g.vectors.col(j);
    EXPECT_NEAR(x.norm(), 1.0, 1e-12);
    // State vector [q; λq] and the quadratic eigenproblem residual.
    EXPECT_LT((x.tail(3) - lam * x.head(3)).norm(), 1e-12 * (1 + std::abs(lam)));
    const Eigen::VectorXcd r = (lam * lam * M.cast<cd>() + lam * C.cast<cd>() + K.cast<cd>()) * x.head(3);
    EXPECT_LT(r.norm(), 1e-10 * std::abs(lam) * std::abs(lam));
    // eigenStandard gives the same vector up to a complex scale.
    for (Eigen::Index k = 0; k < 6; ++k) {
      if (std::abs(s.values(k) - lam) > 1e-9 * std::abs(lam)) continue;
      const Eigen::VectorXcd y = s.vectors.col(k);
      const cd scale = y.dot(x);  // conj(y)·x
      EXPECT_LT((x - scale * y).norm(), 1e-10);
      EXPECT_LT((A.cast<cd>() * y - s.values(k) * y).norm(), 1e-10 * std::abs(lam));
    }
  }
}

TEST(Eigen, NanInputThrows) {
  const TwoDof sys;
  Eigen::MatrixXd A = sys.A();
  A(3, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(whirl::eigenStandard(A), whirl::ComputeError);
  Eigen::MatrixXd K = sys.K();
  K(0, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(whirl::eigenSecondOrder(sys.M(), sys.C(), K), whirl::ComputeError);
  try {
    whirl::eigenStandard(A);
  } catch (const whirl::ComputeError& e) {
    EXPECT_NE(std::string(e.what()).find("A(3,1)"), std::string::npos) << e.what();
  }
}

TEST(Eigen, SingularMassIsInfiniteEigenvalue) {
  const TwoDof sys;
  Eigen::MatrixXd M = sys.M();
  M(1, 1) = 0.0;  // second DOF without inertia
  try {
    whirl::eigenSecondOrder(M, sys.C(), sys.K());
    FAIL() << "expected ComputeError";
  } catch (const whirl::ComputeError& e) {
    EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
  }
}

TEST(Eigen, NonSquareThrows) {
  EXPECT_THROW(whirl::eigenStandard(Eigen::MatrixXd::Zero(2, 3)), whirl::ComputeError);
  EXPECT_THROW(whirl::eigenSecondOrder(Eigen::MatrixXd::Identity(2, 2), Eigen::MatrixXd::Zero(3, 3),
                                       Eigen::MatrixXd::Zero(2, 2)),
               whirl::ComputeError);
}

}  // namespace
