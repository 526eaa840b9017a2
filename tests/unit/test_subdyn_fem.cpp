// The SubDyn substructure on whirl's FE bodies (src/turbine/subdyn_fem.hpp, src/fem/rigid_interface.hpp)
// against closed forms computed from the same member properties, and the reductions against each other.
//
// The tube of tests/data/subdyn (D 0.5 m, t 0.01 m, 60 m, clamped at its base, the interface joint at
// its top) is slender on purpose: the closed forms are Euler–Bernoulli without rotary inertia, which the
// FE mass has; with r² = I/A = 0.030 m² the rotary inertia lowers the first frequencies by about
// r² ∫φ'²/(2∫φ²) ≈ 2e-5 (cantilever) and 6e-5 (clamped–clamped), the 20 cubic elements' discretization
// error is below 1e-7: the tolerance 2e-4 covers both and nothing else.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "modal/modes.hpp"
#include "src/fem/fem_body.hpp"
#include "src/fem/rigid_interface.hpp"
#include "src/io/openfast/openfast_overrides.hpp"
#include "src/turbine/subdyn_fem.hpp"

namespace whirl {
namespace {

constexpr double pi = std::numbers::pi;
const std::string kTube = std::string(WHIRL_SOURCE_DIR) + "/tests/data/subdyn/cantilever_v101.dat";
const std::string kTubeV4 = std::string(WHIRL_SOURCE_DIR) + "/tests/data/subdyn/cantilever_v4.dat";

io::SubDynInput tube(const std::vector<std::string>& sets = {}) {
  std::vector<io::KeyOverride> o;
  for (const std::string& s : sets) o.push_back(io::parseOverride(s));
  io::OverrideSet set(o);
  return io::readSubDyn(kTube, &set);
}

// EI/m of the tube, from its section: r_o = D/2, r_i = r_o − t.
double tubeEIoverM() {
  const double ro = 0.25, ri = 0.24, E = 2.1e11, rho = 7850;
  const double A = pi * (ro * ro - ri * ri), I = pi / 4 * (std::pow(ro, 4) - std::pow(ri, 4));
  return E * I / (rho * A);
}

// Natural frequencies [Hz] of the body's elastic coordinates with its TP free (K_e, M_e), ascending.
VecX bodyHz(const SubDynBody& b, int count) {
  const MatX Me = fem::elasticMass(b.fem.body.inertia);
  const fem::GeneralizedModes g = fem::denseModes(b.fem.body.elastic.K.sparseView(), Me.sparseView(), count);
  return g.omega2.cwiseMax(0.0).cwiseSqrt() / (2 * pi);
}

// Uniform cantilever, Euler–Bernoulli: f₁ = β₁² √(EI/m) / (2π L²), β₁ = 1.875104068711961.
TEST(SubDynFem, ClampedTubeFirstBendingIsTheEulerBernoulliCantilever) {
  const SubDynBody b = buildSubDynBody(tube(), Vec3::Zero());  // CBMod = False: every mode (full FE)
  const VecX f = bodyHz(b, 4);
  const double L = 60, beta = 1.875104068711961;
  const double expected = beta * beta * std::sqrt(tubeEIoverM()) / (2 * pi * L * L);
  std::printf("cantilever: whirl %.6f %.6f Hz, closed form %.6f Hz\n", f(0), f(1), expected);
  EXPECT_NEAR(f(0), expected, 2e-4 * expected);  // bending about x and y: a double root
  EXPECT_NEAR(f(1), expected, 2e-4 * expected);
}

// With the TP held, the fixed-interface modes of the Craig–Bampton reduction are those of the beam
// clamped at both ends: f₁ = β₁² √(EI/m) / (2π L²), β₁ = 4.730040744862704.
TEST(SubDynFem, FixedInterfaceModesAreTheClampedClampedBeam) {
  const SubDynBody b = buildSubDynBody(tube({"CBMod=True", "Nmodes=4"}), Vec3::Zero());
  ASSERT_EQ(b.fem.fixed_interface_hz.size(), 4);
  const double L = 60, beta = 4.730040744862704;
  const double expected = beta * beta * std::sqrt(tubeEIoverM()) / (2 * pi * L * L);
  EXPECT_NEAR(b.fem.fixed_interface_hz(0), expected, 2e-4 * expected);
  EXPECT_NEAR(b.fem.fixed_interface_hz(1), expected, 2e-4 * expected);
}

// Guyan ⊂ Craig–Bampton(2) ⊂ Craig–Bampton(8) ⊂ full: by the Rayleigh–Ritz principle each frequency
// can only fall as the basis grows, and the reduced ones converge to the full model's.
TEST(SubDynFem, GuyanCraigBamptonAndFullConverge) {
  const VecX full = bodyHz(buildSubDynBody(tube(), Vec3::Zero()), 6);
  const VecX guyan = bodyHz(buildSubDynBody(tube({"CBMod=True", "Nmodes=0"}), Vec3::Zero()), 6);
  const VecX cb2 = bodyHz(buildSubDynBody(tube({"CBMod=True", "Nmodes=2"}), Vec3::Zero()), 6);
  const VecX cb8 = bodyHz(buildSubDynBody(tube({"CBMod=True", "Nmodes=8"}), Vec3::Zero()), 6);
  for (int k = 0; k < 6; ++k) {
    std::printf("mode %d: Guyan %.5f  CB2 %.5f  CB8 %.5f  full %.5f Hz\n", k + 1, guyan(k), cb2(k), cb8(k), full(k));
    EXPECT_GE(guyan(k), cb2(k) * (1 - 1e-10));
    EXPECT_GE(cb2(k), cb8(k) * (1 - 1e-10));
    EXPECT_GE(cb8(k), full(k) * (1 - 1e-10));
    EXPECT_NEAR(cb8(k), full(k), 0.005 * full(k));  // issue 17's 0.5 %
  }
  // Beyond the first bending pair the error falls strictly with every mode added.
  for (int k = 2; k < 6; ++k) {
    EXPECT_GT(guyan(k) - full(k), cb2(k) - full(k));
    EXPECT_GT(cb2(k) - full(k), cb8(k) - full(k));
  }
}

// Guyan reduction of a cantilever to its tip is one cubic (Hermite) element over the whole length:
// its first frequency is that of the 2×2 problem K = EI/L³ [[12, −6L], [−6L, 4L²]],
// M = mL/420 [[156, −22L], [−22L, 4L²]] (tip deflection and slope), 0.48 % above the exact cantilever.
TEST(SubDynFem, GuyanTubeIsOneCubicElement) {
  const VecX guyan = bodyHz(buildSubDynBody(tube({"CBMod=True", "Nmodes=0"}), Vec3::Zero()), 2);
  Eigen::Matrix2d K, M;
  K << 12, -6, -6, 4;
  M << 156, -22, -22, 4;
  M /= 420;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> es(K, M);
  const double L = 60, expected = std::sqrt(es.eigenvalues()(0)) * std::sqrt(tubeEIoverM()) / (2 * pi * L * L);
  std::printf("Guyan %.6f Hz, one cubic element %.6f Hz\n", guyan(0), expected);
  EXPECT_NEAR(guyan(0), expected, 2e-4 * expected);
  EXPECT_NEAR(guyan(1), expected, 2e-4 * expected);
}

// Damping. With the TP held, the Craig–Bampton coordinates are the fixed-interface modes, and each
// damped mode of (M, C, K) restricted to them has the ratio JDampings gives it (2 %, SubDyn's C_MM).
TEST(SubDynFem, CraigBamptonModesHaveTheirJDampings) {
  const SubDynBody b = buildSubDynBody(tube({"CBMod=True", "Nmodes=5", "JDampings=2"}), Vec3::Zero());
  const MatX M = fem::elasticMass(b.fem.body.inertia).bottomRightCorner(5, 5);
  const MatX K = b.fem.body.elastic.K.bottomRightCorner(5, 5), C = b.damping.bottomRightCorner(5, 5);
  const std::vector<Mode> modes = computeModes(M, C, K, {"a", "b", "c", "d", "e"});
  ASSERT_EQ(modes.size(), 5u);
  for (const Mode& m : modes) EXPECT_NEAR(m.damping_ratio, 0.02, 1e-10);
  for (int j = 0; j < 5; ++j) EXPECT_NEAR(modes[j].freq_hz, b.fem.fixed_interface_hz(j), 1e-9 * modes[j].freq_hz);
}

// Rayleigh Guyan damping (GuyanDampMod = 1, OpenFAST v3+ layout): C_BB = α M_BB + β K_BB gives each
// mode of the Guyan model the ratio ζ = α/(2ω) + βω/2 (Rayleigh damping's classical result).
TEST(SubDynFem, RayleighGuyanDampingGivesTheClassicalRatios) {
  io::OverrideSet set({io::parseOverride("Nmodes=0"), io::parseOverride("GuyanDampMod=1"),
                       io::parseOverride("RayleighDamp=0.05,0.002")});
  const SubDynBody b = buildSubDynBody(io::readSubDyn(kTubeV4, &set), Vec3::Zero());
  const MatX M = fem::elasticMass(b.fem.body.inertia);
  const std::vector<Mode> modes = computeModes(M, b.damping, b.fem.body.elastic.K,
                                               {"ux", "uy", "uz", "rx", "ry", "rz"});
  ASSERT_EQ(modes.size(), 6u);
  for (const Mode& m : modes) {
    const double w = 2 * pi * m.freq_hz;
    EXPECT_NEAR(m.damping_ratio, 0.05 / (2 * w) + 0.002 * w / 2, 1e-9) << m.freq_hz << " Hz";
  }
}

// The rigid tie: with every node tied to R, T spans the rigid-body motions of the whole structure:
// no strain energy (Tᵀ K T = 0), and Tᵀ M T is the rigid-body mass matrix about R — its translation
// block the total mass, its coupling block m·(x_G − R)~ with the centre of mass x_G.
TEST(SubDynFem, RigidTieSpansRigidBodyMotion) {
  SubDynFem f = subDynFem(tube(), Vec3::Zero());
  fem::BeamModel m = f.spec.model;
  m.fixed.assign(m.nodes.size(), {false, false, false, false, false, false});
  m.nodes[0] += Vec3(3, -2, 0);  // bend the tube's base node off the axis: a non-trivial geometry
  const fem::Assembly a = fem::assemble(m, true);
  const fem::DofMap map = fem::freeDofs(m);
  std::vector<int> all(m.nodes.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
  const Vec3 R(1, 2, 5);
  const MatX T = fem::rigidTie(m, map, all, R);
  const MatX K = fem::restrictTo(a.K, map), M = fem::restrictTo(a.M, map);
  const MatX KT = T.transpose() * K * T, MT = T.transpose() * M * T;
  EXPECT_LT(KT.cwiseAbs().maxCoeff(), 1e-9 * MatX(K).cwiseAbs().maxCoeff());
  const double mass = a.integrals.mass;
  const Vec3 d = a.integrals.m1.col(0) / mass - R;
  Mat3 skew;
  skew << 0, -d(2), d(1), d(2), 0, -d(0), -d(1), d(0), 0;
  EXPECT_NEAR((MT.topLeftCorner(3, 3) - mass * Mat3::Identity()).norm(), 0, 1e-9 * mass);
  EXPECT_NEAR((MT.block(0, 3, 3, 3) + mass * skew).norm(), 0, 1e-9 * mass * d.norm());
}

}  // namespace
}  // namespace whirl
