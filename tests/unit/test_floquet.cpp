// Floquet analysis (modal/floquet.hpp): an isotropic 3-bladed rotor with a fixed coordinate, whose
// multiblade model is a given coupled time-invariant one, gives that model's eigenvalues.
#include <gtest/gtest.h>

#include "linearize/mbc.hpp"
#include "linearize/periodic.hpp"
#include "modal/eigen.hpp"
#include "modal/floquet.hpp"
#include "modal/modes.hpp"
#include "src/base/error.hpp"
#include "tests/support/rotor_model.hpp"

namespace {

using Eigen::MatrixXd;

// M q̈ + C q̇ + K q = 0 in multiblade coordinates [fixed; collective; cos; sin].
MatrixXd multibladeA() {
  MatrixXd K(4, 4), C = 0.05 * MatrixXd::Identity(4, 4);
  K << 4.0, 0.3, 0.2, -0.1,  //
      0.3, 2.5, 0.0, 0.0,    //
      0.2, 0.0, 3.0, 0.4,    //
      -0.1, 0.0, 0.4, 3.5;
  MatrixXd A = MatrixXd::Zero(8, 8);
  A.topRightCorner(4, 4) = MatrixXd::Identity(4, 4);
  A.bottomLeftCorner(4, 4) = -K;
  A.bottomRightCorner(4, 4) = -C;
  return A;
}

// Nearest exponent to λ.
double distance(const Eigen::VectorXcd& eta, std::complex<double> l) {
  double d = 1e300;
  for (Eigen::Index k = 0; k < eta.size(); ++k) d = std::min(d, std::abs(eta(k) - l));
  return d;
}

TEST(Floquet, IsotropicThreeBladedGivesTheMultibladeEigenvalues) {
  const whirl::MbcLayout L = whirl::secondOrderLayout(3, {-1, 0, 1, 2});
  const MatrixXd Anr = multibladeA();
  const double omega = 2.0;
  const int N = 8;
  // Blade-frame A(ψ) whose multiblade transform is Anr at every azimuth: A = (T Anr + Ṫ) T⁻¹, with
  // T⁻¹ and −T⁻¹Ṫ from the transform of A = 0, B = I.
  std::vector<whirl::MbcSample> samples;
  for (int j = 0; j < N; ++j) {
    whirl::MbcSample zero;
    zero.azimuth = 0.3 + 2 * M_PI * j / N;
    zero.rotor_speed = omega;
    zero.A = MatrixXd::Zero(8, 8);
    zero.B = MatrixXd::Identity(8, 8);
    whirl::MbcLayout Lu = L;
    const whirl::MbcSample t = whirl::mbcTransform(Lu, zero);
    const MatrixXd T = t.B.inverse(), Tdot = -T * t.A;
    whirl::MbcSample s;
    s.azimuth = zero.azimuth;
    s.rotor_speed = omega;
    s.A = (T * Anr + Tdot) * t.B;
    // The construction holds: the multiblade transform gives Anr back.
    ASSERT_LT((whirl::mbcTransform(L, s).A - Anr).norm(), 1e-12);
    samples.push_back(s);
  }
  whirl::RotorCoordinates c;
  c.names = {"tower", "blade 1 flap", "blade 2 flap", "blade 3 flap"};
  c.blade = {-1, 0, 1, 2};
  c.azimuth = {false, false, false, false};
  c.held = c.azimuth;
  c.weights = MatrixXd::Identity(4, 4);
  whirl::FloquetOptions opt;
  opt.steps_per_sample = 32;  // Magnus error ∝ h⁴: 2e-7 relative at the default 8, 1e-9 here
  const whirl::RotorModes r = whirl::floquetModes(c, samples, opt);
  const Eigen::VectorXcd lambda = whirl::eigenStandard(Anr).values;
  ASSERT_EQ(r.modes.size(), 4u);  // one per conjugate pair
  // Every mode's λ = −ζω ± iω_d is an eigenvalue of the multiblade Anr (Magnus over 256 steps).
  for (const whirl::Mode& md : r.modes) {
    const double w = 2 * M_PI * md.freq_hz;
    const std::complex<double> l(-md.damping_ratio * w, 2 * M_PI * md.damped_freq_hz);
    EXPECT_LT(distance(lambda, l), 1e-7 * w) << md.name << " " << l;
  }
}

TEST(Floquet, ParkedOrUnevenRotorIsRefused) {
  whirl::RotorCoordinates c;
  c.names = {"tower"};
  c.blade = {-1};
  c.azimuth = {false};
  c.held = c.azimuth;
  c.weights = MatrixXd::Identity(1, 1);
  std::vector<whirl::MbcSample> samples(2);
  for (auto& s : samples) s.A = MatrixXd::Identity(2, 2);
  samples[1].azimuth = M_PI;
  EXPECT_THROW(whirl::floquetModes(c, samples), whirl::InputError);  // rotor speed 0
  for (auto& s : samples) s.rotor_speed = 1.0;
  samples[1].azimuth = 1.0;
  EXPECT_THROW(whirl::floquetModes(c, samples), whirl::InputError);  // not evenly spaced
}

}  // namespace
