// Beam finite elements (src/fem): element and assembly against closed forms, the mass matrix by two
// paths, reductions, geometric stiffness, and the FE body in the engine against Φᵀ M Φ.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "src/dynamics/mass_matrix.hpp"
#include "src/dynamics/workspace.hpp"
#include "src/fem/fem_body.hpp"
#include "src/model/model.hpp"
#include "src/shapes/shape.hpp"

namespace whirl::fem {
namespace {

constexpr double pi = std::numbers::pi;

// Uniform tube-like cantilever along x: L = 10 m, all six DOFs.
BeamModel cantilever(int elements, double L = 10.0, bool timoshenko = false, double kGA = 0) {
  BeamStations p;
  p.x = VecX::LinSpaced(2, 0, L);
  auto c = [](double v) { return VecX(VecX::Constant(2, v)); };
  p.m = c(100);
  p.EA = c(2e9);
  p.EIy = c(1e7);
  p.EIz = c(4e7);
  p.GJ = c(5e6);
  p.iy2 = p.iz2 = c(0.5);
  if (kGA > 0) p.kGAy = p.kGAz = c(kGA);
  BeamModel m = straightBeam(p, meshStations(0, L, elements, {}), timoshenko);
  clamp(m, 0);
  return m;
}

VecX hz(const BeamModel& m) {
  const Assembly a = assemble(m, false);
  const DofMap d = freeDofs(m);
  const GeneralizedModes g = denseModes(restrictTo(a.K, d), restrictTo(a.M, d), d.nfree());
  return g.omega2.cwiseSqrt() / (2 * pi);
}

bool near(double a, double b, double rel) { return std::abs(a - b) <= rel * std::abs(b); }

// Analytic frequencies of a uniform clamped-free beam: bending (β_j/L)² √(EI/m) with
// β = 1.8751, 4.6941; axial and torsion (2j−1)π/2 · c/L.
TEST(FemBeam, CantileverFrequenciesMatchClosedForms) {
  const VecX f = hz(cantilever(40));
  const double L = 10, m = 100, b1 = clampedTopMassBeta(1, 0), b2 = clampedTopMassBeta(2, 0);
  auto bending = [&](double b, double EI) { return (b / L) * (b / L) * std::sqrt(EI / m) / (2 * pi); };
  auto wave = [&](double stiff, double inertia) { return 0.5 * pi * std::sqrt(stiff / inertia) / L / (2 * pi); };
  // Expected, sorted: bending y/z with rotary inertia (0.5 kg m per plane, a 1e-4 effect on mode 1) ...
  const std::vector<double> expected = {bending(b1, 1e7), bending(b1, 4e7), bending(b2, 1e7), bending(b2, 4e7)};
  int found = 0;
  for (double e : expected)
    for (Eigen::Index k = 0; k < f.size(); ++k)
      if (near(f(k), e, 2e-3)) {
        ++found;
        break;
      }
  EXPECT_EQ(found, 4);
  bool axial = false, torsion = false;
  for (Eigen::Index k = 0; k < f.size(); ++k) {
    axial = axial || near(f(k), wave(2e9, 100), 1e-3);
    torsion = torsion || near(f(k), wave(5e6, 1.0), 1e-3);
  }
  EXPECT_TRUE(axial);
  EXPECT_TRUE(torsion);
  // Without rotary inertia the first bending frequency converges from above to the EB value.
  BeamModel eb = cantilever(40);
  for (Element& e : eb.elements) e.s1.iy2 = e.s1.iz2 = e.s2.iy2 = e.s2.iz2 = 0;
  keepOnly(eb, {true, true, true, false, true, true});  // no torsion inertia left: drop θ_x
  const VecX fe = hz(eb);
  EXPECT_GT(fe(0), bending(b1, 1e7));
  EXPECT_NEAR(fe(0), bending(b1, 1e7), 1e-8 * bending(b1, 1e7));
}

TEST(FemBeam, MassMatrixFromIntegralsEqualsElementMass) {
  BeamModel m = cantilever(7);
  m.nodes[7] += Vec3(0.3, 2.0, -1.0);  // a kinked, non-axial last element
  m.elements[6].y_axis = Vec3(0, 0.3, 1);
  m.masses.push_back({3, 50.0, Vec3(5, 7, 9).asDiagonal()});
  const Assembly a = assemble(m, true);
  const SpMat Ms = a.integrals.S[0] + a.integrals.S[4] + a.integrals.S[8];
  const MatX M1 = MatX(a.M), M2 = MatX(Ms).bottomRightCorner(m.ndof(), m.ndof());
  EXPECT_LT((M1 - M2).norm(), 1e-10 * M1.norm());
  // Total mass and first moment: ∫ dm and ∫ X dm.
  double mass = 50.0;
  Vec3 first = 50.0 * m.nodes[3];
  for (const Element& e : m.elements) {
    const double l = (m.nodes[e.n2] - m.nodes[e.n1]).norm();
    mass += 100 * l;
    first += 100 * l * 0.5 * (m.nodes[e.n1] + m.nodes[e.n2]);
  }
  EXPECT_NEAR(a.integrals.mass, mass, 1e-9 * mass);
  EXPECT_LT((a.integrals.m1.col(0) - first).norm(), 1e-9 * first.norm());
  // M is symmetric positive semi-definite and K annihilates rigid translations.
  EXPECT_LT((M1 - M1.transpose()).norm(), 1e-12 * M1.norm());
  VecX t = VecX::Zero(m.ndof());
  for (int i = 0; i < m.nnodes(); ++i) t(6 * i + 1) = 1.0;
  EXPECT_LT((a.K * t).norm(), 1e-6);
}

TEST(FemBeam, GuyanOfUniformCantileverIsExactTipStiffness) {
  const BeamModel m = cantilever(10);
  const Assembly a = assemble(m, false);
  const DofMap d = freeDofs(m);
  const SpMat K = restrictTo(a.K, d);
  const int tip = 10;
  const std::vector<int> iface = {d.index[6 * tip + 1], d.index[6 * tip + 5]};  // u_y, θ_z
  const Reduction r = guyan(K, iface);
  const MatX Kr = r.basis.transpose() * (K * r.basis);
  const double L = 10, EI = 1e7;  // tip (v, θz) of a cantilever: EI/L³ [[12, −6L], [−6L, 4L²]]
  Eigen::Matrix2d exact;
  exact << 12, -6 * L, -6 * L, 4 * L * L;
  exact *= EI / (L * L * L);
  EXPECT_LT((Kr - exact).norm(), 1e-8 * exact.norm());
}

TEST(FemBeam, CraigBamptonConvergesToTheFullModel) {
  const BeamModel m = cantilever(12);
  const Assembly a = assemble(m, false);
  const DofMap d = freeDofs(m);
  const SpMat K = restrictTo(a.K, d), M = restrictTo(a.M, d);
  std::vector<int> iface;
  for (int k = 0; k < 6; ++k) iface.push_back(d.index[6 * 6 + k]);  // a mid node
  const VecX full = denseModes(K, M, 8).omega2;
  auto reduced = [&](int modes) {
    const Reduction r = craigBampton(K, M, iface, modes);
    const MatX Kr = r.basis.transpose() * (K * r.basis), Mr = r.basis.transpose() * (M * r.basis);
    return denseModes(Kr.sparseView(), Mr.sparseView(), 8).omega2;
  };
  const VecX few = reduced(6), all = reduced(d.nfree() - 6);
  for (int k = 0; k < 8; ++k) {
    EXPECT_GE(few(k), full(k) * (1 - 1e-9));       // Rayleigh–Ritz: upper bounds
    EXPECT_NEAR(all(k), full(k), 1e-8 * full(k));  // all interior modes: exact
  }
}

TEST(FemBeam, TimoshenkoLowersShortBeamFrequencies) {
  const double L = 2.0;
  const VecX eb = hz(cantilever(20, L)), stiff = hz(cantilever(20, L, true, 1e15)),
             soft = hz(cantilever(20, L, true, 5e7));
  EXPECT_NEAR(stiff(0), eb(0), 1e-6 * eb(0));
  EXPECT_LT(soft(0), 0.99 * eb(0));
}

// Euler buckling of a cantilever column under a top compression P: K + K_G singular at π²EI/(4L²).
TEST(FemBeam, GeometricStiffnessGivesEulerBuckling) {
  const BeamModel m = cantilever(30);
  const double L = 10, EI = 1e7, Pcr = pi * pi * EI / (4 * L * L);
  const Assembly a = assemble(m, false);
  const DofMap d = freeDofs(m);
  const SpMat K = restrictTo(a.K, d);
  const SpMat G = restrictTo(geometricStiffness(m, VecX::Constant(m.elements.size(), -1.0)), d);
  // Lowest λ of K φ = λ (−G) φ restricted to the bending DOFs: generalized eigen with M := −G + εI.
  const MatX Kd = MatX(K), Gd = -MatX(G) + 1e-9 * MatX::Identity(d.nfree(), d.nfree());
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> es(Kd, Gd);
  double lowest = 1e300;
  for (Eigen::Index k = 0; k < es.eigenvalues().size(); ++k)
    if (es.eigenvalues()(k) > 0 && es.eigenvalues()(k) < 1e12) lowest = std::min(lowest, es.eigenvalues()(k));
  EXPECT_NEAR(lowest, Pcr, 1e-5 * Pcr);
}

TEST(FemBeam, AxialForcesOfAHangingWeight) {
  const BeamModel m = cantilever(10);
  FemBodySpec spec;
  spec.model = m;
  spec.points = {{"tip", 10}};
  const FemBody fb = buildFemBody(spec, "column");
  VecX N;
  gravityGeometricStiffness(fb, m, Vec3(-9.81, 0, 0), {{10, 1000.0}}, &N);
  // Compression below x: weight of the beam above plus the carried mass.
  for (int e = 0; e < 10; ++e) {
    const double above = 100 * (10 - (e + 0.5)) + 1000.0;
    EXPECT_NEAR(N(e), -9.81 * above, 1e-6 * 9.81 * above) << e;
  }
}

// The FE body in the engine: the elastic block of the engine's mass matrix is Φᵀ M Φ (rotary inertia
// included), for the full model and for a Craig–Bampton one.
TEST(FemBeam, EngineMassMatrixOfFemBodyEqualsProjectedMass) {
  for (ReductionKind kind : {ReductionKind::None, ReductionKind::CraigBampton}) {
    FemBodySpec spec;
    spec.model = cantilever(8);
    spec.points = {{"tip", 8}};
    spec.reduction = kind;
    spec.interface_nodes = {8};
    spec.modes = 4;
    const FemBody fb = buildFemBody(spec, "fe");
    Model model;
    Body b;
    b.name = "fe";
    b.inertia = fb.body.inertia;
    b.elastic = fb.body.elastic;
    b.points = fb.body.points;
    model.bodies.push_back(b);
    for (int k = 0; k < b.inertia.ne; ++k) {
      Dof dof;
      dof.name = "fe " + std::to_string(k);
      dof.kind = DofKind::Elastic;
      dof.body = 0;
      dof.local = k;
      model.dofs.push_back(dof);
    }
    finalize(model);
    Workspace<double> ws(model);
    MatX M;
    massMatrix(model, ws, VecX::Zero(model.ndof()), M);
    const MatX expected = fb.basis.transpose() * (fb.M * fb.basis);
    EXPECT_LT((M - expected).norm(), 1e-10 * expected.norm());
    const MatX Ke = fb.basis.transpose() * (fb.K * fb.basis);
    EXPECT_LT((model.bodies[0].elastic.K - Ke).norm(), 1e-10 * Ke.norm());
  }
}

}  // namespace
}  // namespace whirl::fem

#include "src/fem/large_model.hpp"

namespace whirl::fem {
namespace {

// The benchmark model: a coarse and a fine mesh agree on the first tower frequencies, near the
// onshore NREL 5MW tower FA 1 (0.324 Hz in ElastoDyn; here with the RNA rotary inertia), and the
// matrices have the advertised size.
TEST(FemBeam, FineTowerModelConverges) {
  const SparseModel coarse = fineTowerModel(20), fine = fineTowerModel(100);
  EXPECT_EQ(fine.K.rows(), 600);
  const VecX fc = denseModes(coarse.K, coarse.M, 4).omega2, ff = denseModes(fine.K, fine.M, 4).omega2;
  // 20 elements take the element stiffness from the mean section (EI varies 5× along the tower):
  // 7e-4 on ω², gone with the fine mesh.
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(fc(k), ff(k), 2e-3 * ff(k)) << k;
  EXPECT_NEAR(std::sqrt(ff(0)) / (2 * pi), 0.32, 0.02);  // the tower's first bending frequency range
}

}  // namespace
}  // namespace whirl::fem
