// The two-node beam element with full 6 × 6 sections (src/fem/element6.hpp, beam6_model.hpp): a
// uniform cantilever against closed-form frequencies (extension, torsion, bending in both planes) with
// h² convergence, the straight isotropic Timoshenko beam against the element of element.hpp, bending–
// torsion coupling through the mass offset against a Rayleigh–Ritz solution with analytic modes, and a
// bend–twist stiffness coupling against the exact static solution.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/fem/beam6_model.hpp"
#include "src/fem/boundary.hpp"
#include "src/fem/fem_body.hpp"
#include "src/shapes/shape.hpp"

namespace whirl::fem {
namespace {

constexpr double pi = std::numbers::pi;

// A straight uniform beam along body x from 0 to L, `n` elements, one section (body axes).
Beam6Model uniform(const Section6& s, double L, int n) {
  Beam6Model m;
  for (int k = 0; k <= n; ++k) m.nodes.push_back(Vec3(L * k / n, 0, 0));
  for (int k = 0; k < n; ++k) m.elements.push_back({k, k + 1, s, s});
  return m;
}

VecX omegas(const Beam6Model& m, int count) { return clampedModes6(assemble6(m), 0, count).omega2.cwiseSqrt(); }

// The lowest `count` modes with the DOF family holding most of each one's kinetic energy
// (0 extension u_x, 1 torsion θ_x, 2 bending along y: u_y, θ_z, 3 bending along z: u_z, θ_y).
struct Classified {
  VecX omega;
  std::vector<int> family;
  /// ω of the j-th (1-based) mode of `family`.
  double of(int fam, int j) const {
    for (Eigen::Index k = 0; k < omega.size(); ++k)
      if (family[static_cast<std::size_t>(k)] == fam && --j == 0) return omega(k);
    return NAN;
  }
};

Classified classify(const Beam6Model& m, int count) {
  const Beam6Matrices a = assemble6(m);
  const Modes6 md = clampedModes6(a, 0, count);
  Classified c;
  c.omega = md.omega2.cwiseSqrt();
  for (int k = 0; k < count; ++k) {
    const VecX v = md.vectors.col(k), Mv = a.M * v;
    double fam[4] = {0, 0, 0, 0};
    for (Eigen::Index i = 0; i < v.size(); ++i) {
      const int kind = static_cast<int>(i % 6);
      fam[kind == 0 ? 0 : kind == 3 ? 1 : (kind == 1 || kind == 5) ? 2 : 3] += v(i) * Mv(i);
    }
    c.family.push_back(static_cast<int>(std::max_element(fam, fam + 4) - fam));
  }
  return c;
}

// Uniform cantilever, L = 10 m: EA 1e9 N, shear 1e12 N (effectively rigid: Euler–Bernoulli), GJ 5e6,
// EI about y 2e7 (deflection along z), about z 1e7 (along y); m = 10 kg/m, polar inertia 0.7 kg m,
// no rotary inertia of the bending planes (the Euler–Bernoulli closed forms leave it out).
Section6 cantileverSection() { return isotropicSection(1e9, 1e12, 1e12, 5e6, 2e7, 1e7, 10, 0.7, 0, 0); }

TEST(FemBeam6, UniformCantileverClosedForms) {
  const double L = 10, m = 10;
  const Beam6Model b = uniform(cantileverSection(), L, 100);
  // Bending: (β_j L)² / L² √(EI/m), β₁L = 1.8751040687, β₂L = 4.6940911330 (clamped-free roots of
  // 1 + cos βL cosh βL = 0); extension and torsion: (2j − 1) π / (2L) · √(stiffness/inertia).
  const double b1 = 1.8751040687, b2 = 4.6940911330;
  auto bend = [&](double bl, double EI) { return bl * bl / (L * L) * std::sqrt(EI / m); };
  auto wave = [&](int j, double k, double i) { return (2 * j - 1) * pi / (2 * L) * std::sqrt(k / i); };
  const Classified c = classify(b, 40);
  // Tolerances: the h² error of 100 elements.
  EXPECT_NEAR(c.of(2, 1) / bend(b1, 1e7), 1, 1e-4);  // along y (EI_z)
  EXPECT_NEAR(c.of(3, 1) / bend(b1, 2e7), 1, 1e-4);  // along z (EI_y)
  EXPECT_NEAR(c.of(2, 2) / bend(b2, 1e7), 1, 1e-3);
  EXPECT_NEAR(c.of(3, 2) / bend(b2, 2e7), 1, 1e-3);
  EXPECT_NEAR(c.of(1, 1) / wave(1, 5e6, 0.7), 1, 1e-4);  // torsion
  EXPECT_NEAR(c.of(1, 2) / wave(2, 5e6, 0.7), 1, 5e-4);
  EXPECT_NEAR(c.of(0, 1) / wave(1, 1e9, m), 1, 1e-4);  // extension
}

TEST(FemBeam6, ConvergesAsElementLengthSquared) {
  // No shear locking: shear stiffness 1e12 against EI 1e7 (ratio GA L²/EI = 1e7) still converges at h².
  const double exact = 1.8751040687 * 1.8751040687 / 100 * std::sqrt(1e7 / 10.0);
  auto error = [&](int n) { return std::abs(classify(uniform(cantileverSection(), 10, n), 6).of(2, 1) / exact - 1); };
  const double e25 = error(25), e50 = error(50), e100 = error(100);
  EXPECT_NEAR(e25 / e50, 4.0, 0.3);
  EXPECT_NEAR(e50 / e100, 4.0, 0.3);
  EXPECT_LT(e100, 1e-4);
}

// Richardson extrapolation of an h² method from n and 2n elements: (4 w(2n) − w(n)) / 3.
VecX extrapolated(const VecX& coarse, const VecX& fine) { return (4 * fine - coarse) / 3; }

TEST(FemBeam6, StraightIsotropicEqualsCubicElement) {
  // A Timoshenko beam with rotary inertia both ways: the element of element.hpp (cubic bending, linear
  // extension and torsion) and the 6 × 6 element, each extrapolated from 40 and 80 elements: the same
  // lowest 8 frequencies.
  const double L = 10;
  BeamStations p;
  p.x = VecX::LinSpaced(2, 0, L);
  auto c = [](double v) { return VecX(VecX::Constant(2, v)); };
  p.m = c(100);
  p.EA = c(2e9);
  p.EIy = c(1e7);  // deflection along y
  p.EIz = c(4e7);  // along z
  p.GJ = c(5e6);
  p.iy2 = c(0.5);  // ∫ y² dm: rotary inertia of θ_z
  p.iz2 = c(0.8);
  p.kGAy = c(2e7);
  p.kGAz = c(3e7);
  auto oldElement = [&](int n) {
    BeamModel old = straightBeam(p, meshStations(0, L, n, {}), true);
    clamp(old, 0);
    const Assembly a = assemble(old, false);
    const DofMap d = freeDofs(old);
    return VecX(denseModes(restrictTo(a.K, d), restrictTo(a.M, d), 8).omega2.cwiseSqrt());
  };
  const VecX w_old = extrapolated(oldElement(40), oldElement(80));
  // Body axes: [γ_x, γ_y, γ_z, κ_x, κ_y, κ_z]; κ_z bends along y (old EIy), κ_y along z (old EIz).
  const Section6 s = isotropicSection(2e9, 2e7, 3e7, 5e6, 4e7, 1e7, 100, 1.3, 0.8, 0.5);
  const VecX w_new = extrapolated(omegas(uniform(s, L, 40), 8), omegas(uniform(s, L, 80), 8));
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(w_new(k) / w_old(k), 1, 2e-4) << "mode " << k + 1;
}

TEST(FemBeam6, MassOffsetCouplesBendingAndTorsion) {
  // A uniform cantilever whose mass centre lies 0.2 m off the axis across the flap direction (the
  // classical coupled bending–torsion beam of Banerjee 1989, his Goland-wing example's layout: flap
  // along y, the offset along z): the FE frequencies against a Rayleigh–Ritz solution of the same
  // continuum with the analytic clamped-free bending modes and the torsion sines (10 each), an
  // independent discretisation that converges from above.
  const double L = 6, EI = 1e7, GJ = 1e6, m = 36, c = 0.2, Jcm = 8;
  Section6 s = isotropicSection(1e12, 1e12, 1e12, GJ, 1e12, EI, m, Jcm + m * c * c, m * c * c, 0);
  // 𝓜 = [m 1, −m c̃; m c̃, J] with c = (0, 0, c).
  const Mat3 mc = m * (Mat3() << 0, -c, 0, c, 0, 0, 0, 0, 0).finished();
  s.M.bottomLeftCorner<3, 3>() = mc;
  s.M.topRightCorner<3, 3>() = -mc;
  const VecX fe = extrapolated(omegas(uniform(s, L, 50), 4), omegas(uniform(s, L, 100), 4));
  // Ritz: u_y = Σ a_j φ_j, θ_x = Σ b_j ψ_j; the cross-section's mass centre moves by u_y − c θ_x.
  const int n = 10, nq = 400;
  std::vector<ShapePtr> bend, tors;
  for (int j = 1; j <= n; ++j) {
    bend.push_back(clampedTopMassShape("b", L, j, 0.0, 1, 0));
    tors.push_back(torsionSineShape("t", L, j));
  }
  MatX K = MatX::Zero(2 * n, 2 * n), M = K;
  for (int q = 0; q < nq; ++q) {  // midpoint rule, nq panels
    const double x = (q + 0.5) * L / nq, w = L / nq;
    VecX u(2 * n), cgu(2 * n), th(2 * n), kap(2 * n), tw(2 * n);
    u.setZero(), th.setZero(), kap.setZero(), tw.setZero();
    for (int j = 0; j < n; ++j) {
      const ShapeValue b = bend[j]->eval(x), t = tors[j]->eval(x);
      u(j) = b.uy;
      kap(j) = b.uy2;
      th(n + j) = t.tx;
      tw(n + j) = t.tx1;
    }
    cgu = u - c * th;
    K += w * (EI * kap * kap.transpose() + GJ * tw * tw.transpose());
    M += w * (m * cgu * cgu.transpose() + Jcm * th * th.transpose());
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatX> ritz(K, M);
  for (int k = 0; k < 4; ++k) {
    const double wr = std::sqrt(ritz.eigenvalues()(k));
    EXPECT_NEAR(fe(k) / wr, 1, 1e-3) << "mode " << k + 1 << ": FE " << fe(k) << ", Ritz " << wr;
  }
  // The coupling is there: the first mode sits below the uncoupled bending frequency.
  EXPECT_LT(fe(0), 1.8751040687 * 1.8751040687 / (L * L) * std::sqrt(EI / m) * 0.995);
}

TEST(FemBeam6, BendTwistStiffnessCouplingStatic) {
  // Constant tip moments on a cantilever give constant resultants, so the curvatures κ = C⁻¹ M are exact
  // and so is the linear element: tip rotation = L C_κκ⁻¹ M. With a flap–torsion stiffness coupling g
  // (entries (3,5), (5,3): torsion with bending about z) a pure bending moment twists the beam.
  Section6 s = isotropicSection(1e9, 1e8, 1e8, 5e6, 2e7, 1e7, 10, 0.7, 0.1, 0.1);
  const double g = 3e6;
  s.C(3, 5) = s.C(5, 3) = g;
  const double L = 10;
  const Beam6Model b = uniform(s, L, 7);
  const Beam6Matrices a = assemble6(b);
  const int n = b.ndof();
  VecX f = VecX::Zero(n - 6);
  f(n - 6 - 1) = 1e4;  // M_z at the tip [N m]
  const MatX K = MatX(a.K).bottomRightCorner(n - 6, n - 6);
  const VecX u = K.ldlt().solve(f);
  const Eigen::Matrix2d Ck = (Eigen::Matrix2d() << 5e6, g, g, 1e7).finished();
  const Eigen::Vector2d kappa = Ck.ldlt().solve(Eigen::Vector2d(0, 1e4));
  EXPECT_NEAR(u(n - 6 - 3), L * kappa(0), 1e-12);  // tip twist θ_x
  EXPECT_NEAR(u(n - 6 - 1), L * kappa(1), 1e-12);  // tip θ_z
  EXPECT_GT(std::abs(u(n - 6 - 3)), 1e-4);         // the coupling does twist it
}

}  // namespace
}  // namespace whirl::fem
