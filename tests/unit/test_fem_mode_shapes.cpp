// FE mode shapes for Rayleigh–Ritz beams (src/fem/mode_shapes.hpp) against closed forms: the uniform
// cantilever, the cantilever with a tip mass [Branlard2019, eq. 32], the rotating uniform beam, and the
// ElastoDyn polynomial fit.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/fem/mode_shapes.hpp"
#include "src/shapes/shape.hpp"

namespace whirl::fem {
namespace {

constexpr double pi = std::numbers::pi;

// Uniform beam: L = 10 m, m = 100 kg/m, EIy = 1e7, EIz = 4e7 N m².
ModeShapeInput uniform(int elements = 80) {
  ModeShapeInput in;
  BeamProperties& p = in.props;
  p.length = 10;
  p.x = VecX::LinSpaced(2, 0, 10);
  p.m = VecX::Constant(2, 100);
  p.EIy = VecX::Constant(2, 1e7);
  p.EIz = VecX::Constant(2, 4e7);
  in.elements = elements;
  return in;
}

double bendingHz(double beta, double EI, double L = 10, double m = 100) {
  return (beta / L) * (beta / L) * std::sqrt(EI / m) / (2 * pi);
}

// β_j L = 1.8751, 4.6941, 7.8548 of the clamped-free uniform beam (any vibration text, e.g. Blevins,
// Formulas for natural frequency and mode shape, Table 8-1; 5 significant digits: β² to 1e-4).
TEST(FemModeShapes, UniformCantileverMatchesBetaL) {
  const std::vector<BeamMode> modes = beamModes(uniform(), 3, 3);
  ASSERT_EQ(modes.size(), 6u);
  const double beta[3] = {1.8751, 4.6941, 7.8548};
  for (const BeamMode& b : modes) {
    const double EI = b.direction == 'y' ? 1e7 : 4e7;
    EXPECT_NEAR(b.freq_hz, bendingHz(beta[b.index - 1], EI), 1e-4 * bendingHz(beta[b.index - 1], EI))
        << b.direction << b.index;
    // Unit tip displacement in its direction, none in the other (no twist: planes uncoupled) but the
    // dense eigensolver's round-off, ε κ(K) with κ ~ 1e9 for 80 elements.
    const Eigen::Index n = b.table.x.size() - 1;
    EXPECT_DOUBLE_EQ(b.direction == 'y' ? b.table.uy(n) : b.table.uz(n), 1.0);
    EXPECT_LT((b.direction == 'y' ? b.table.uz : b.table.uy).cwiseAbs().maxCoeff(), 1e-6);
  }
}

// The FE shapes and slopes against the exact clamped-free shapes at the 81 nodes (between nodes the
// table interpolates linearly, an h²/8 u'' error of its own), and the tabulated curvatures (nodal
// means of the cubic elements) against the exact curvature.
TEST(FemModeShapes, UniformCantileverShapesMatchExactModes) {
  const std::vector<BeamMode> modes = beamModes(uniform(), 3, 0);
  for (const BeamMode& b : modes) {
    const ShapePtr exact = clampedTopMassShape("exact", 10, b.index, 0.0, 1, 0);
    EXPECT_GT(shapeMac(*b.shape, *exact, 10, 81), 1 - 1e-10) << b.index;
    EXPECT_LT(shapeMaxDeviation(*b.shape, *exact, 10, 81), 1e-6) << b.index;
    const double k2 = std::abs(exact->eval(0).uy2);
    for (double x : {0.0, 2.5, 5.0, 7.5}) {
      EXPECT_NEAR(b.shape->eval(x).uy1, exact->eval(x).uy1, 1e-6) << b.index << " at " << x;
      EXPECT_NEAR(b.shape->eval(x).uy2, exact->eval(x).uy2, 2e-3 * k2) << b.index << " at " << x;
    }
  }
}

// [Branlard2019, §5.1, eq. 32]: clamped-free uniform beam with a tip point mass Mt/M,
// frequencies (β_j/L)² √(EI/m) with β_j the roots of the frequency equation (clampedTopMassBeta).
TEST(FemModeShapes, TipMassMatchesSeedEquation32) {
  for (double ratio : {0.5, 2.0}) {
    ModeShapeInput in = uniform();
    in.tip.mass = ratio * 100 * 10;
    const std::vector<BeamMode> modes = beamModes(in, 4, 0);
    for (const BeamMode& b : modes) {
      const double f = bendingHz(clampedTopMassBeta(b.index, ratio), 1e7);
      EXPECT_NEAR(b.freq_hz, f, 1e-5 * f) << "Mt/M " << ratio << " mode " << b.index;
      const ShapePtr exact = clampedTopMassShape("exact", 10, b.index, ratio, 1, 0);
      EXPECT_GT(shapeMac(*b.shape, *exact, 10, 81), 1 - 1e-10);  // at the 81 nodes
    }
  }
}

// A rotary inertia J at the tip lowers every mode; a centre of mass above the tip acts like it.
TEST(FemModeShapes, TipInertiaAndOffsetLowerTheFrequencies) {
  ModeShapeInput in = uniform();
  in.tip.mass = 500;
  const double f0 = beamModes(in, 1, 0).at(0).freq_hz;
  in.tip.inertia = Mat3(Vec3(0, 0, 2000).asDiagonal());  // θ_z: rotation of bending along y
  const double fJ = beamModes(in, 1, 0).at(0).freq_hz;
  in.tip.inertia.setZero();
  in.tip.cm = Vec3(2, 0, 0);  // m d² = 2000 kg m² about the tip, with the translation coupling
  const double fd = beamModes(in, 1, 0).at(0).freq_hz;
  EXPECT_LT(fJ, f0);
  EXPECT_LT(fd, fJ);  // the offset mass also moves with the tip rotation
}

// Rotating uniform beam, hub radius 0 ([HodgesRutkowski1981, Table 1], also [Wright1982]):
// first flap ω̄ = ω √(mL⁴/EI) = 3.6816, 5.5850, 11.2018 at Ω̄ = 1, 4, 10
// (5 significant digits: 1e-4). In plane (softening −Ω² m): ω_edge² = ω_flap² − Ω² exactly when
// EIy = EIz, the same eigenproblem shifted; checked to the dense eigensolver's ε κ(K) ~ 1e-7.
TEST(FemModeShapes, RotatingUniformBeamMatchesHodgesRutkowski) {
  ModeShapeInput in = uniform();
  in.props.EIz = in.props.EIy;
  const double EI = 1e7, m = 100, L = 10, scale = std::sqrt(EI / (m * std::pow(L, 4)));
  const double speeds[3] = {1, 4, 10}, reference[3] = {3.6816, 5.5850, 11.2018};
  in.rotation_axis = Vec3::UnitY();  // flap along y (out of plane), in plane along z
  for (int k = 0; k < 3; ++k) {
    in.rotor_speed = speeds[k] * scale;
    const std::vector<BeamMode> modes = beamModes(in, 1, 1);
    const BeamMode& flap = modes[0].direction == 'y' ? modes[0] : modes[1];
    const BeamMode& edge = modes[0].direction == 'y' ? modes[1] : modes[0];
    const double wf = 2 * pi * flap.freq_hz, we = 2 * pi * edge.freq_hz;
    EXPECT_NEAR(wf / scale, reference[k], 1e-4 * reference[k]) << "Omega bar " << speeds[k];
    EXPECT_NEAR(we * we, wf * wf - in.rotor_speed * in.rotor_speed, 1e-6 * wf * wf);
  }
}

// Axial gravity buckles the cantilever where the Rayleigh quotient of mode 1 reaches zero:
// - under its own weight at q L³/EI = 7.837 (Greenhill 1881; Timoshenko & Gere, Theory of Elastic
//   Stability, §2.10: 4 digits, so ±1e-3 either side is outside the printed precision);
// - under a tip load P = M_t g at P_cr = π² EI / (4 L²) (Euler), with a light beam (0.1 kg against a
//   1000 kg tip: its own weight moves the critical load by ~3e-5, lighter still would leave M too
//   ill-conditioned for the dense eigensolver near ω² = 0), checked ±1e-3 either side.
TEST(FemModeShapes, AxialGravityBucklesAtGreenhillAndEulerLoads) {
  ModeShapeInput in = uniform();
  const double qcr = 7.837 * 1e7 / std::pow(10.0, 3);  // [N/m]
  for (double s : {0.999, 1.001}) {
    in.axial_gravity = s * qcr / 100;  // q = m g, m = 100 kg/m
    const double f = beamModes(in, 1, 0).at(0).freq_hz;
    if (s < 1) EXPECT_GT(f, 0.0);
    else EXPECT_EQ(f, 0.0);  // negative ω²: reported as 0 Hz
  }
  ModeShapeInput tip = uniform();
  tip.props.m = VecX::Constant(2, 1e-2);
  tip.tip.mass = 1000;
  const double Pcr = pi * pi * 1e7 / (4 * 100);
  for (double s : {0.999, 1.001}) {
    tip.axial_gravity = s * Pcr / 1000;
    const double f = beamModes(tip, 1, 0).at(0).freq_hz;
    if (s < 1) EXPECT_GT(f, 0.0);
    else EXPECT_EQ(f, 0.0);
  }
}

// Structural twist couples the planes: a 90° twist swaps EIy and EIz.
TEST(FemModeShapes, NinetyDegreeTwistSwapsThePlanes) {
  ModeShapeInput in = uniform();
  in.props.twist = VecX::Constant(2, pi / 2);
  const std::vector<BeamMode> modes = beamModes(in, 1, 1);
  for (const BeamMode& b : modes) {
    const double EI = b.direction == 'y' ? 4e7 : 1e7;
    EXPECT_NEAR(b.freq_hz, bendingHz(1.8751, EI), 1e-4 * bendingHz(1.8751, EI));
  }
}

TEST(FemModeShapes, PolynomialFitRecoversAnElastoDynPolynomial) {
  // NREL 5MW blade BldFl1Sh (ElastoDyn blade file), Σ = 1.
  const std::array<double, 5> a = {0.0622, 1.7254, -3.2452, 4.7131, -2.2555};
  const ShapePtr s = polynomialShape("p", 50, {0, 0, a[0], a[1], a[2], a[3], a[4]}, 0, 1);
  const PolynomialFit f = fitElastoDynPolynomial(*s, 50, 'z');
  double sum = 0;
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(f.coeffs[k], a[k], 1e-9);
    sum += f.coeffs[k];
  }
  EXPECT_NEAR(sum, 1.0, 1e-14);
  EXPECT_LT(f.rms, 1e-12);
  // A shape outside the polynomial space: the fit still ends at 1 and reports its deviation.
  const PolynomialFit g = fitElastoDynPolynomial(*clampedTopMassShape("e", 50, 3, 0.0, 0, 1), 50, 'z');
  EXPECT_NEAR(g.coeffs[0] + g.coeffs[1] + g.coeffs[2] + g.coeffs[3] + g.coeffs[4], 1.0, 1e-14);
  EXPECT_GT(g.max_deviation, 1e-3);
}

TEST(FemModeShapes, RefusesBadInput) {
  ModeShapeInput in = uniform();
  in.props.EIy(1) = -1;
  EXPECT_THROW(beamModes(in, 1, 0), InputError);
  in = uniform(4);
  EXPECT_THROW(beamModes(in, 20, 0), ComputeError);  // 4 elements: 8 bending DOFs per plane
  in = uniform();
  in.tip.mass = -1;
  EXPECT_THROW(beamModes(in, 1, 0), InputError);
}

// The dense eigenproblem is O(n³): a mesh past limits::kMaxFemShapeMesh is refused before it is
// assembled, also when the elements come from property stations rather than from `elements`
// (a fuzzed case with 686 elements took 62 s; 5000 would take hours).
TEST(FemModeShapes, RefusesAMeshTooLargeForTheDenseSolver) {
  ModeShapeInput in = uniform(4);
  const int stations = limits::kMaxFemShapeMesh + 2;
  in.props.x = VecX::LinSpaced(stations, 0, 10);
  in.props.m = VecX::Constant(stations, 100);
  in.props.EIy = VecX::Constant(stations, 1e7);
  in.props.EIz = VecX::Constant(stations, 4e7);
  try {
    beamModes(in, 1, 0);
    ADD_FAILURE() << "a mesh of " << stations - 1 << " elements was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the FE mesh has " + std::to_string(stations - 1) + " elements"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace whirl::fem
