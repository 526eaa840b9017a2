// [Branlard2019, §5.5, Table 1]: the uniform beam of §5.1 (L = 100 m, EI = 2e12 N m²,
// m = 9 t/m, no top mass, gravity off) split into a lower FE body (50 Euler–Bernoulli elements, full,
// Guyan or Craig–Bampton) and an upper Rayleigh–Ritz beam (analytic clamped-free modes of its own
// length, 50 trapezoid sections); relative errors of modes 2 and 4 against eq. 32.
//
// whirl vs the paper (δf in %; cases/mixed_fem_rr/README.md explains the gaps):
//   case              δf2 whirl  paper   δf4 whirl  paper
//   RR4               -0.0004    0.00     0.0013    0.00
//   FEM50-RR2          0.0144    0.02     1.2525    1.18
//   FEM50-RR4         -0.0152   -0.01     0.0107   -0.03
//   GY2-RR2            0.7129    0.71    51.4544   50.08
//   GY2-RR4            0.6817    0.68    36.0560   35.28
//   GY2-RR4c (0.4 L)   0.1136    0.14    12.7779   12.06
//   CB2+2-RR4         -0.0102   -0.01     0.1566    0.11
// The values printed to 2 decimals that whirl reproduces at that precision are in reference.csv; the
// pattern of the table (Guyan fails on mode 4, Craig–Bampton matches the full FE model) is checked
// below for every case, and the FE–RR coupling [Branlard2019, eq. 19] against an independent assembly.
#include <cmath>
#include <map>
#include <numbers>

#include "modal/modes.hpp"
#include "src/fem/reduction.hpp"
#include "src/shapes/shape.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double L = 100, EI = 2e12, mpl = 9e3;

double analyticHz(int j) {
  const double b = clampedTopMassBeta(j, 0.0);
  return (b / L) * (b / L) * std::sqrt(EI / mpl) / (2 * pi);
}

std::vector<double> frequencies(const std::string& file, const std::vector<std::string>& sets = {}) {
  std::vector<CaseOverride> o;
  for (const auto& s : sets) o.push_back(parseOverride(s));
  const Model m = readCase(std::string(WHIRL_SOURCE_DIR) + "/cases/mixed_fem_rr/" + file, o);
  const LinearModel l = test::linearizeAtEquilibrium(m);
  std::vector<double> f;
  for (const Mode& md : computeModes(l.M, l.C, l.K, l.dof_names)) f.push_back(md.freq_hz);
  return f;
}

struct Errors {
  double df2, df4;  // [%]
};

Errors errors(const std::string& file) {
  const std::vector<double> f = frequencies(file);
  return {100 * (f.at(1) / analyticHz(2) - 1), 100 * (f.at(3) / analyticHz(4) - 1)};
}

TEST(MixedFemRR, Table1ValuesAtPrintedPrecision) {
  const Errors rr4 = errors("rr4.yaml"), gy2 = errors("gy2_rr2.yaml"), gy4 = errors("gy2_rr4.yaml"),
               cb = errors("cb22_rr4.yaml");
  test::expectMatchesReference("mixed_fem_rr", {{"RR4_df2_percent", rr4.df2},
                                                {"RR4_df4_percent", rr4.df4},
                                                {"GY2-RR2_df2_percent", gy2.df2},
                                                {"GY2-RR4_df2_percent", gy4.df2},
                                                {"CB2+2-RR4_df2_percent", cb.df2}});
}

TEST(MixedFemRR, Table1Pattern) {
  const Errors fem2 = errors("fem50_rr2.yaml"), fem4 = errors("fem50_rr4.yaml"), gy2 = errors("gy2_rr2.yaml"),
               gy4 = errors("gy2_rr4.yaml"), gy4c = errors("gy2_rr4c.yaml"), cb = errors("cb22_rr4.yaml");
  // Mode 2 is captured by every mixed model (paper: |δf2| ≤ 0.71 %).
  for (const Errors& e : {fem2, fem4, gy2, gy4, gy4c, cb}) EXPECT_LT(std::abs(e.df2), 0.75);
  // Guyan cannot capture mode 4 (paper: 50.08, 35.28, 12.06 %) ...
  EXPECT_GT(gy2.df4, 30.0);
  EXPECT_GT(gy4.df4, 30.0);
  EXPECT_GT(gy4c.df4, 10.0);
  // ... and depends on where the beam is split (paper: 35.28 % at L/2, 12.06 % at 0.4 L).
  EXPECT_LT(gy4c.df4, gy4.df4 / 2);
  // Two RR shapes on the upper half miss mode 4 by about 1 % (paper 1.18 %); four capture it.
  EXPECT_GT(fem2.df4, 1.0);
  EXPECT_LT(std::abs(fem4.df4), 0.05);
  // Craig–Bampton with 2 fixed-interface modes matches the full FE model (paper: 0.11 vs −0.03 %).
  EXPECT_LT(std::abs(cb.df4), 0.2);
  EXPECT_LT(std::abs(cb.df4 - fem4.df4), 0.2);
  EXPECT_LT(std::abs(cb.df2 - fem4.df2), 0.01);
}

// Independent path for [Branlard2019, eq. 19]: the planar beam as one global Rayleigh–Ritz model. Lower part
// [0, a]: Hermite cubics of `nel` equal elements clamped at the root (one element = the Guyan static
// modes, exact for a uniform cantilever); upper part: rigid motion of B (w_B, slope −θ_B) plus the
// clamped-free modes of length L − a. M = ∫ m N Nᵀ, K = ∫ EI N''ᵀ N''.
std::vector<double> globalRitzHz(double a, int nel, int nrr) {
  const int nl = 2 * nel, n = nl + nrr;
  const double h = a / nel;
  std::vector<ShapePtr> shapes;
  for (int j = 1; j <= nrr; ++j) shapes.push_back(clampedTopMassShape("s", L - a, j, 0.0, 0.0, 1.0));
  MatX M = MatX::Zero(n, n), K = MatX::Zero(n, n);
  static const double gx[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  static const double gw[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                               0.2369268850561891};
  auto accumulate = [&](const VecX& N, const VecX& N2, double w) {
    M += w * mpl * N * N.transpose();
    K += w * EI * N2 * N2.transpose();
  };
  for (int e = 0; e < nel; ++e)  // DOFs of node k (1..nel): w at 2(k−1), θ_y at 2(k−1)+1, slope = −θ_y
    for (int g = 0; g < 5; ++g) {
      const double xi = 0.5 + 0.5 * gx[g], x2 = xi * xi, x3 = x2 * xi;
      const double hN[4] = {1 - 3 * x2 + 2 * x3, h * (xi - 2 * x2 + x3), 3 * x2 - 2 * x3, h * (x3 - x2)};
      const double hN2[4] = {(-6 + 12 * xi) / (h * h), (-4 + 6 * xi) / h, (6 - 12 * xi) / (h * h), (6 * xi - 2) / h};
      VecX N = VecX::Zero(n), N2 = VecX::Zero(n);
      const int nodes[2] = {e, e + 1};
      for (int k = 0; k < 2; ++k) {
        if (nodes[k] == 0) continue;  // clamped root
        const int d = 2 * (nodes[k] - 1);
        N(d) += hN[2 * k];
        N2(d) += hN2[2 * k];
        N(d + 1) -= hN[2 * k + 1];
        N2(d + 1) -= hN2[2 * k + 1];
      }
      accumulate(N, N2, 0.5 * h * gw[g]);
    }
  const int panels = 400;
  const double hb = (L - a) / panels;
  for (int p = 0; p < panels; ++p)
    for (int g = 0; g < 5; ++g) {
      const double x = (p + 0.5 + 0.5 * gx[g]) * hb;
      VecX N = VecX::Zero(n), N2 = VecX::Zero(n);
      N(nl - 2) = 1;
      N(nl - 1) = -x;
      for (int j = 0; j < nrr; ++j) {
        const ShapeValue v = shapes[j]->eval(x);
        N(nl + j) = v.uz;
        N2(nl + j) = v.uz2;
      }
      accumulate(N, N2, 0.5 * hb * gw[g]);
    }
  const fem::GeneralizedModes gm = fem::denseModes(K.sparseView(), M.sparseView(), n);
  std::vector<double> f;
  for (int k = 0; k < n; ++k) f.push_back(std::sqrt(gm.omega2(k)) / (2 * pi));
  return f;
}

TEST(MixedFemRR, CouplingEqualsGlobalRitzModel) {
  const std::vector<std::string> gauss = {"bodies.upper.integration.method=gauss", "bodies.upper.integration.n=100"};
  struct Check {
    std::string file;
    double a;
    int nel, nrr;
  };
  for (const Check& c :
       {Check{"gy2_rr4.yaml", 50, 1, 4}, Check{"gy2_rr4c.yaml", 40, 1, 4}, Check{"fem50_rr2.yaml", 50, 50, 2}}) {
    const std::vector<double> whirl_hz = frequencies(c.file, gauss), ref = globalRitzHz(c.a, c.nel, c.nrr);
    ASSERT_EQ(whirl_hz.size(), ref.size()) << c.file;
    for (size_t k = 0; k < std::min<size_t>(6, ref.size()); ++k)
      EXPECT_NEAR(whirl_hz[k], ref[k], 1e-8 * ref[k]) << c.file << " mode " << k + 1;
  }
}

}  // namespace
}  // namespace whirl
