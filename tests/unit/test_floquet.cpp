// Floquet analysis (modal/floquet.hpp): an isotropic 3-bladed rotor, whose multiblade model is time
// invariant, gives the multiblade eigenvalues; a time-invariant model gives its plain eigenvalues.
#include <gtest/gtest.h>

#include "linearize/mbc.hpp"
#include "linearize/periodic.hpp"
#include "modal/modes.hpp"
#include "tests/support/rotor_model.hpp"
#include "modal/eigen.hpp"
#include "modal/floquet.hpp"
#include "src/model/error.hpp"

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
  const whirl::FloquetResult f = whirl::floquetAnalysis(L, samples, 64);
  const Eigen::VectorXcd lambda = whirl::eigenStandard(Anr).values;
  ASSERT_EQ(f.exponents.size(), 8);
  // Runge–Kutta over 512 steps: exponents to ~1e-8 of their size.
  for (Eigen::Index k = 0; k < 8; ++k) EXPECT_LT(distance(f.exponents, lambda(k)), 1e-7 * std::abs(lambda(k))) << lambda(k);
}

TEST(Floquet, TimeInvariantModelGivesItsEigenvalues) {
  // Two blades (no multiblade transform), a model that does not change with azimuth.
  const whirl::MbcLayout L = whirl::secondOrderLayout(2, {-1, 0, 1, -1});
  const MatrixXd A = multibladeA();
  std::vector<whirl::MbcSample> samples(6);
  for (int j = 0; j < 6; ++j) samples[j].azimuth = 2 * M_PI * j / 6, samples[j].rotor_speed = 1.5, samples[j].A = A;
  const whirl::FloquetResult f = whirl::floquetAnalysis(L, samples, 32);
  const Eigen::VectorXcd lambda = whirl::eigenStandard(A).values;
  for (Eigen::Index k = 0; k < 8; ++k) EXPECT_LT(distance(f.exponents, lambda(k)), 1e-7 * std::abs(lambda(k))) << lambda(k);
  // Ω = 1.5 rad/s, the frequencies √eig(K) ≈ 1.5 … 2 rad/s are above Ω/2: ln μ / T alone folds them back
  // by Ω; the harmonic content moves them where they are.
  int shifted = 0;
  for (int h : f.harmonic) shifted += h != 0;
  EXPECT_GT(shifted, 0);
}

// Two blades on a rigid hub at 12 rpm (tests/support/rotor_model.hpp, the model of
// tests/unit/test_rotor_modes.cpp): each blade keeps its rotating-frame frequencies; the edge mode
// (1.28 Hz) is 6.4 revolutions' worth of cycles, folded by ln μ / T and moved back by the harmonics.
TEST(Floquet, TwoBladedRotorKeepsItsRotatingFrameFrequencies) {
  const whirl::Model m = whirl::test::rotorModel(12, 2);
  whirl::PeriodicOptions opt;
  opt.azimuths = 8;
  const whirl::PeriodicLinearization p = whirl::linearizePeriodic(m, whirl::initialPoint(m), opt);
  std::vector<int> blade;
  for (int d : p.models[0].dofs) blade.push_back(m.dofs[d].blade);
  std::vector<whirl::MbcSample> samples;
  for (size_t k = 0; k < p.models.size(); ++k) {
    whirl::MbcSample s;
    s.azimuth = p.azimuths[k];
    s.rotor_speed = p.rotor_speed;
    s.A = p.models[k].A;
    samples.push_back(s);
  }
  const whirl::FloquetResult f = whirl::floquetAnalysis(whirl::secondOrderLayout(2, blade), samples);
  const whirl::LinearModel& l = p.models[0];
  const auto single = whirl::computeModes(l.M.topLeftCorner(2, 2), l.C.topLeftCorner(2, 2), l.K.topLeftCorner(2, 2),
                                          {"flap 1", "edge 1"});
  ASSERT_EQ(single.size(), 2u);
  for (const auto& s : single) {
    int found = 0;
    for (Eigen::Index k = 0; k < f.exponents.size(); ++k)
      if (std::abs(std::abs(f.exponents(k)) / (2 * M_PI) - s.freq_hz) < 1e-7 * s.freq_hz) ++found;
    EXPECT_EQ(found, 4) << s.name;  // 2 blades × the conjugate pair
  }
}

TEST(Floquet, ParkedRotorIsRefused) {
  std::vector<whirl::MbcSample> samples(1);
  samples[0].A = MatrixXd::Identity(2, 2);
  EXPECT_THROW(whirl::floquetAnalysis(whirl::secondOrderLayout(3, {-1}), samples), whirl::InputError);
}

}  // namespace
