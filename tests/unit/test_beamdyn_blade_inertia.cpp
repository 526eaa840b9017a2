// The BeamDyn blade body's inertia (src/turbine/beamdyn_blade.hpp) against the FE model it comes from
// (src/fem/beam6_model.hpp): the body's elastic mass block (the shape integrals of
// src/shapes/beam.cpp, as the multibody equations use them for a clamped, parked, non-rotating blade)
// with the FE modes' exact modal stiffness gives the FE model's clamped frequencies, which the FE model
// gets from its consistent 6 × 6 mass (Beam6 elements). The two paths share the mode vectors only: the
// body integrates the tabulated shapes' displacements, slopes and twist over the sections' mass and
// inertia tensor (BeamProperties::J); the FE model assembles N^T 𝓜 N. With the sections' flap and edge
// rotary inertia left out (the thin-beam convention, J empty) the body's frequencies are too high.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "src/io/openfast/beamdyn/beamdyn_input.hpp"
#include "src/shapes/beam.hpp"
#include "src/turbine/beamdyn_blade.hpp"

namespace whirl {
namespace {

// Frequencies [Hz] of the blade body clamped at its root, not rotating: K q = ω² M_ee q with M_ee the
// body's elastic mass block Σ_k S_kk (the integration the rotor uses: 4 trapezoid points per element).
VecX bodyFrequencies(const BeamDynBladeBody& fe, int elements) {
  BeamOptions o;
  o.integration = {BeamIntegration::Trapezoid, 4 * elements};
  const BeamBody bb = buildBeamBody(fe.beam.props, fe.beam.shapes, o, "blade");
  const int ne = static_cast<int>(fe.beam.shapes.size());
  MatX Mee = MatX::Zero(ne, ne);
  for (int k = 0; k < 3; ++k) Mee += bb.inertia.S[4 * k].block(1, 1, ne, ne);
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> es(fe.K, 0.5 * (Mee + Mee.transpose()));
  return es.eigenvalues().cwiseMax(0).cwiseSqrt() / (2 * std::numbers::pi);
}

// Largest |f_body / f_FE − 1| over the lowest `count` kept modes.
double worstRelative(const BeamDynBladeBody& fe, const VecX& f, Eigen::Index count) {
  double worst = 0;
  for (Eigen::Index k = 0; k < std::min(count, f.size()); ++k)
    worst = std::max(worst, std::abs(f(k) / fe.freq_hz[static_cast<std::size_t>(k)] - 1));
  return worst;
}

// A straight, untwisted 20 m blade of uniform sections with a large flap and edge rotary inertia
// (m = 100 kg/m, i_flap = i_edge = 100 kg m: radius of gyration 1 m against the 20 m length), stiff in
// shear (GA L²/EI = 5e5) so that the shapes' slopes, which the body turns the sections with, are the
// element rotations, which the FE model turns them with.
io::BeamDynInput thickBlade() {
  io::BeamDynInput bd;
  for (int k = 0; k < 4; ++k) bd.key_points.push_back({Vec3(0, 0, 20.0 * k / 3), 0.0, 0});
  for (double eta : {0.0, 1.0}) {
    io::BeamDynStation s;
    s.eta = eta;
    s.K.diagonal() << 5e13, 5e13, 2e10, 4e9, 6e9, 1e9;
    s.M.diagonal() << 100, 100, 100, 100, 100, 200;
    bd.blade.stations.push_back(s);
  }
  return bd;
}

TEST(BeamDynBladeInertia, RotaryInertiaOfThickSectionsMatchesTheFeModel) {
  const int elements = 40;
  BeamDynBladeBody fe = beamDynBladeBody(thickBlade(), {elements, 8});
  // Measured: worst 9.6e-4 (edge 3, 142.837 against 142.701 Hz; edge 1 −1.0e-5): the shapes' slopes by
  // finite differences of the 40 elements' nodal values.
  EXPECT_LT(worstRelative(fe, bodyFrequencies(fe, elements), 8), 2e-3);
  // Without the flap and edge rotary inertia (the thin-beam convention) the bending modes are too
  // stiff: measured edge 1 +0.58 %, edge 2 +4.0 %, edge 3 +9.4 %.
  fe.beam.props.J.clear();
  EXPECT_GT(worstRelative(fe, bodyFrequencies(fe, elements), 8), 3e-2);
}

// The NREL 5MW blade of certification Test26 (60 elements, 8 modes). Measured (Hz, body / FE):
// flap 1 0.685838 / 0.685816, edge 1 1.080561 / 1.080618, flap 2 1.947443 / 1.947472, edge 2 3.736508 /
// 3.739466, flap 3 4.388454 / 4.389575, torsion 1 5.580355 / 5.580202, flap 4 7.490023 / 7.497351,
// edge 3 7.934917 / 7.959526 (−3.1e-3). The body turns its sections with the slopes, which include the
// shear angle of the file's soft shear (0.1 EA): the rotary inertia is a little high in the higher edge
// modes. Without the flap and edge rotary inertia: edge 2 3.746982 (+2.0e-3), edge 3 +2.9e-3.
TEST(BeamDynBladeInertia, Nrel5mwBladeMatchesTheFeModel) {
  const io::BeamDynInput bd = io::readBeamDyn(std::filesystem::path(WHIRL_SOURCE_DIR) /
                                              "cases/nrel5mw_beamdyn/5MW_Baseline/NRELOffshrBsline5MW_BeamDyn.dat");
  const int elements = 60;
  BeamDynBladeBody fe = beamDynBladeBody(bd, {elements, 8});
  const VecX f = bodyFrequencies(fe, elements);
  EXPECT_LT(worstRelative(fe, f, 4), 1.2e-3);
  EXPECT_LT(worstRelative(fe, f, 8), 5e-3);
  fe.beam.props.J.clear();
  EXPECT_GT(worstRelative(fe, bodyFrequencies(fe, elements), 4), 1.5e-3);
}

}  // namespace
}  // namespace whirl
