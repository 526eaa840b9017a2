// SLEPc sparse eigen (modal/sparse_eigen.hpp) against analytic spectra and against the dense
// LAPACK path (modal/eigen.hpp) on problems both can solve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "modal/eigen.hpp"
#include "modal/modes.hpp"
#include "modal/sparse_eigen.hpp"
#include "modal/sparse_modes.hpp"
#include "src/base/error.hpp"
#include "src/parallel/session.hpp"
#include "tests/support/sparse_models.hpp"

namespace whirl {
namespace {

using test::SparseModel;

#define REQUIRE_PETSC() \
  if (!parallel::petscAvailable()) GTEST_SKIP() << "built without PETSc/SLEPc"

std::vector<double> sortedValues(const SparseEigenResult& r) {
  std::vector<double> v;
  for (const auto& p : r.pairs) v.push_back(p.value.real());
  std::sort(v.begin(), v.end());
  return v;
}

TEST(SparseEigen, SpringChainMatchesAnalytic) {
  REQUIRE_PETSC();
  const int n = 2000;
  const double k = 3.0e5, m = 12.0;
  const SparseModel s = test::springChain(n, k, m);
  SparseEigenOptions opt;
  opt.nev = 10;
  const SparseEigenResult r = sparseGeneralizedEigen(s.K, s.M, opt);
  ASSERT_EQ(r.pairs.size(), 10u);
  const std::vector<double> w2 = sortedValues(r);
  for (int j = 1; j <= 10; ++j) {
    // ω_j² = (4k/m) sin²(jπ/(2(n+1))), exact for the discrete chain.
    const double exact = 4 * k / m * std::pow(std::sin(j * std::numbers::pi / (2 * (n + 1))), 2);
    EXPECT_NEAR(w2[j - 1], exact, 1e-9 * exact) << "mode " << j;
  }
  for (const auto& p : r.pairs) {
    EXPECT_LT(p.residual, 1e-12);
    EXPECT_EQ(p.value.imag(), 0.0);
    // the backward error recomputed here, independently of SLEPc (1-norms of the matrices)
    const Eigen::VectorXd x = p.vector.real();
    const double knorm = 4 * k, mnorm = m;  // largest column sums of K and M
    const double backward = (s.K * x - p.value.real() * (s.M * x)).norm() /
                            ((knorm + p.value.real() * mnorm) * x.norm());
    EXPECT_LT(backward, 1e-13);
  }
}

TEST(SparseEigen, SpringGridMatchesAnalytic) {
  REQUIRE_PETSC();
  const int nx = 40, ny = 57;  // incommensurate sides: no repeated eigenvalues among the lowest
  const double k = 1.0e4, m = 2.0;
  const SparseModel s = test::springGrid(nx, ny, k, m);
  std::vector<double> exact;
  for (int i = 1; i <= nx; ++i)
    for (int j = 1; j <= ny; ++j)
      exact.push_back(4 * k / m *
                      (std::pow(std::sin(i * std::numbers::pi / (2 * (nx + 1))), 2) +
                       std::pow(std::sin(j * std::numbers::pi / (2 * (ny + 1))), 2)));
  std::sort(exact.begin(), exact.end());
  SparseEigenOptions opt;
  opt.nev = 12;
  const std::vector<double> w2 = sortedValues(sparseGeneralizedEigen(s.K, s.M, opt));
  ASSERT_EQ(w2.size(), 12u);
  for (int j = 0; j < 12; ++j) EXPECT_NEAR(w2[j], exact[j], 1e-9 * exact[j]) << "mode " << j + 1;
}

/// Undamped cantilever: SLEPc ω² equal the dense LAPACK pencil's |λ|² to 1e-8, and the first
/// mode is the analytic (1.875104)⁴ EI/(ρA L⁴) within the FE discretization error.
/// Non-dimensional, as the dense reference needs: dggev does not scale the pencil, and on a
/// 90 m steel tower of 100 elements (‖K‖ ~ 1e13) its mode 1 drifts by 2e-8.
TEST(SparseEigen, CantileverEqualsDenseLapack) {
  REQUIRE_PETSC();
  const double L = 1, EI = 1, rhoA = 1;
  const SparseModel s = test::cantilever(30, L, EI, rhoA);
  const int n = static_cast<int>(s.K.rows());
  SparseEigenOptions opt;
  opt.nev = 8;
  const SparseEigenResult r = sparseGeneralizedEigen(s.K, s.M, opt);
  const std::vector<double> w2 = sortedValues(r);

  const EigenDecomposition d = eigenSecondOrder(Eigen::MatrixXd(s.M), Eigen::MatrixXd::Zero(n, n),
                                                Eigen::MatrixXd(s.K));
  std::vector<double> dense;
  for (int j = 0; j < d.values.size(); ++j)
    if (d.values(j).imag() > 0) dense.push_back(std::norm(d.values(j)));
  std::sort(dense.begin(), dense.end());
  ASSERT_EQ(w2.size(), 8u);
  for (int j = 0; j < 8; ++j) EXPECT_NEAR(w2[j], dense[j], 1e-8 * dense[j]) << "mode " << j + 1;

  // β₁L = 1.875104069 (clamped–free); 30 cubic elements: the FE frequency is high by ~(β₁h)⁴/2880 ≈ 2e-9.
  const double w1 = std::pow(1.875104069 / L, 2) * std::sqrt(EI / rhoA);
  EXPECT_NEAR(std::sqrt(w2[0]), w1, 1e-6 * w1);
}

/// A spinning shaft-like system: two bending planes (slightly different stiffness), Rayleigh
/// damping and a skew gyroscopic coupling Ω G between the planes. SLEPc PEP (TOAR on the n × n
/// matrices) against the dense 2n state-space pencil: every computed λ within 1e-8 relative.
/// Non-dimensional (L = EI = ρA = 1) so that the dense path is exact to ~1e-12: LAPACK's dggev
/// does not scale the pencil, and on a dimensional shaft (‖K‖ ~ 1e11) its lowest λ drifts by
/// 1e-7 with an eigenvector residual of 0.3, while SLEPc's pair keeps a residual of 1e-9.
TEST(SparseEigen, DampedGyroscopicPepEqualsDenseStateSpace) {
  REQUIRE_PETSC();
  const SparseModel b = test::cantilever(12, 1.0, 1.0, 1.0);
  const int nb = static_cast<int>(b.K.rows()), n = 2 * nb;
  test::Triplets mt, kt, ct;
  auto addBlock = [](test::Triplets& t, const Eigen::SparseMatrix<double>& A, int r0, int c0, double s) {
    for (int k = 0; k < A.outerSize(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it)
        t.emplace_back(r0 + it.row(), c0 + it.col(), s * it.value());
  };
  const double omega = 2.0;  // spin; the first bending frequency is 3.516
  addBlock(mt, b.M, 0, 0, 1);
  addBlock(mt, b.M, nb, nb, 1);
  addBlock(kt, b.K, 0, 0, 1);
  addBlock(kt, b.K, nb, nb, 1.15);
  addBlock(ct, b.M, 0, 0, 0.02);  // Rayleigh α M
  addBlock(ct, b.M, nb, nb, 0.02);
  addBlock(ct, b.K, 0, 0, 1e-4);  // Rayleigh β K
  addBlock(ct, b.K, nb, nb, 1.15e-4);
  addBlock(ct, b.M, 0, nb, -0.3 * omega);  // gyroscopic: skew
  addBlock(ct, b.M, nb, 0, 0.3 * omega);
  const auto M = test::fromTriplets(n, mt), K = test::fromTriplets(n, kt), C = test::fromTriplets(n, ct);

  SparseEigenOptions opt;
  opt.nev = 16;
  const SparseEigenResult r = sparseQuadraticEigen(M, C, K, opt);
  ASSERT_GE(r.pairs.size(), 16u);
  EXPECT_LT(r.target, 0.0);

  const EigenDecomposition d = eigenSecondOrder(Eigen::MatrixXd(M), Eigen::MatrixXd(C), Eigen::MatrixXd(K));
  std::vector<std::complex<double>> dense(d.values.data(), d.values.data() + d.values.size());
  std::sort(dense.begin(), dense.end(),
            [&](auto a, auto c) { return std::abs(a - r.target) < std::abs(c - r.target); });
  int complex_pairs = 0;
  for (const auto& p : r.pairs) {
    const auto nearest = *std::min_element(dense.begin(), dense.end(), [&](auto a, auto c) {
      return std::abs(a - p.value) < std::abs(c - p.value);
    });
    EXPECT_NEAR(std::abs(p.value - nearest) / std::abs(nearest), 0.0, 1e-8) << p.value << " vs " << nearest;
    EXPECT_LT(p.residual, 1e-10);
    if (p.value.imag() > 0) ++complex_pairs;
    // ‖(λ²M + λC + K) x‖ recomputed here: small against the terms' size
    const Eigen::VectorXcd x = p.vector;
    const std::complex<double> l = p.value;
    const Eigen::VectorXcd Mx = M * x, Cx = C * x, Kx = K * x;
    const Eigen::VectorXcd res = l * l * Mx + l * Cx + Kx;
    EXPECT_LT(res.norm() / (std::norm(l) * Mx.norm() + std::abs(l) * Cx.norm() + Kx.norm()), 1e-9);
  }
  EXPECT_EQ(complex_pairs, 8);  // underdamped: eight whirling modes, each a conjugate pair
  // and SLEPc found exactly the 16 nearest the target, none skipped
  for (int j = 0; j < 16; ++j) {
    bool found = false;
    for (const auto& p : r.pairs) found = found || std::abs(p.value - dense[j]) <= 1e-8 * std::abs(dense[j]);
    EXPECT_TRUE(found) << "dense eigenvalue " << dense[j] << " missing";
  }
}

/// computeModesSparse (PEP path: C ≠ 0) against computeModes (dense): the same lowest modes, with
/// the same frequencies, damping ratios and names, and a residual on each.
TEST(SparseEigen, SparseModesEqualDenseModes) {
  REQUIRE_PETSC();
  const SparseModel b = test::cantilever(40, 1.0, 1.0, 1.0);
  const int n = static_cast<int>(b.K.rows());
  const Eigen::SparseMatrix<double> C = 0.05 * b.M + 2e-5 * b.K;
  std::vector<std::string> names;
  for (int i = 0; i < n; ++i) names.push_back((i % 2 ? "slope " : "deflection ") + std::to_string(i / 2 + 1));
  SparseModesInfo info;
  const std::vector<Mode> sparse = computeModesSparse(b.M, C, b.K, names, 6, {}, &info);
  const std::vector<Mode> dense = computeModes(MatX(b.M), MatX(C), MatX(b.K), names);
  EXPECT_EQ(info.method.rfind("PEP toar", 0), 0u) << info.method;
  ASSERT_EQ(sparse.size(), 6u);
  for (size_t k = 0; k < 6; ++k) {
    EXPECT_NEAR(sparse[k].freq_hz, dense[k].freq_hz, 1e-8 * dense[k].freq_hz) << k;
    EXPECT_NEAR(sparse[k].damping_ratio, dense[k].damping_ratio, 1e-8) << k;
    EXPECT_EQ(sparse[k].name, dense[k].name);
    ASSERT_TRUE(sparse[k].residual.has_value());
    EXPECT_LT(*sparse[k].residual, 1e-10);
    EXPECT_FALSE(dense[k].residual.has_value());
  }
}

TEST(SparseEigen, RigidBodyModesNeedNoUserShift) {
  REQUIRE_PETSC();
  // Free–free chain: K singular (a rigid translation). The automatic target below zero keeps
  // K − σM non-singular; the rigid mode comes out at ω² ≈ 0.
  const int n = 300;
  SparseModel s = test::springChain(n, 1e3, 1.0);
  s.K.coeffRef(0, 0) = 1e3;
  s.K.coeffRef(n - 1, n - 1) = 1e3;
  SparseEigenOptions opt;
  opt.nev = 3;
  const std::vector<double> w2 = sortedValues(sparseGeneralizedEigen(s.K, s.M, opt));
  ASSERT_EQ(w2.size(), 3u);
  EXPECT_NEAR(w2[0], 0.0, 1e-9);
  // free–free chain: ω_j² = (4k/m) sin²(jπ/(2n)), j = 0, 1, …
  for (int j = 1; j < 3; ++j) {
    const double exact = 4e3 * std::pow(std::sin(j * std::numbers::pi / (2 * n)), 2);
    EXPECT_NEAR(w2[j], exact, 1e-8 * exact);
  }
}

TEST(SparseEigen, BadInputIsAnError) {
  REQUIRE_PETSC();
  const SparseModel s = test::springChain(10, 1, 1);
  const SparseModel t = test::springChain(11, 1, 1);
  SparseEigenOptions opt;
  opt.nev = 2;
  EXPECT_THROW(sparseGeneralizedEigen(s.K, t.M, opt), ComputeError);
  Eigen::SparseMatrix<double> bad = s.K;
  bad.coeffRef(3, 3) = std::nan("");
  EXPECT_THROW(sparseGeneralizedEigen(bad, s.M, opt), ComputeError);
  EXPECT_THROW(sparseQuadraticEigen(s.M, t.M, s.K, opt), ComputeError);
}

}  // namespace
}  // namespace whirl
