// The harmonic that gives a Floquet mode its frequency (modal/floquet_harmonic.hpp), on spectra made
// by hand: one dominant harmonic; a standing pattern's two whirls; a slow rotor's spread of
// harmonics; a 2-bladed rotor's cyclic mode, reported at its backward whirl whichever whirl is larger.
#include <gtest/gtest.h>

#include <cmath>

#include "modal/floquet_harmonic.hpp"

namespace whirl {
namespace {

constexpr int kM = 64;
constexpr double kOmega = 2.0;  // rad/s
constexpr double kEta = 0.3;    // Im η [rad/s]

int idx(int k) { return ((k % kM) + kM) % kM; }
int harmonic(int index) { return index <= kM / 2 ? index : index - kM; }

std::vector<double> spectrum(std::initializer_list<std::pair<int, double>> entries) {
  std::vector<double> e(kM, 0.0);
  for (const auto& [k, v] : entries) e[idx(k)] = v;
  return e;
}

TEST(FloquetHarmonic, OneDominantHarmonic) {
  SolutionSpectrum s{spectrum({{5, 1.0}, {4, 0.01}, {7, 0.02}}), {}, {}};
  EXPECT_EQ(harmonic(floquetHarmonic(s, kEta, kOmega, false)), 5);
}

// Two whirls of nearly equal weight around a carrier that carries nothing: the backward (lower |f|)
// one, whichever of the two is slightly larger; a clearly larger one (4:1) wins.
TEST(FloquetHarmonic, StandingPatternTakesTheBackwardWhirl) {
  for (const double forward : {0.9, 1.0, 1.1, 2.5}) {
    SolutionSpectrum s{spectrum({{9, 1.0}, {11, forward}}), {}, {}};
    EXPECT_EQ(harmonic(floquetHarmonic(s, kEta, kOmega, false)), 9) << forward;
  }
  SolutionSpectrum s{spectrum({{9, 1.0}, {11, 4.0}}), {}, {}};
  EXPECT_EQ(harmonic(floquetHarmonic(s, kEta, kOmega, false)), 11);
  // Negative frequencies: |Im η + kΩ| decides, so the mirror image (the conjugate solution) picks the
  // mirror harmonic.
  SolutionSpectrum m{spectrum({{-9, 1.0}, {-11, 1.1}}), {}, {}};
  EXPECT_EQ(harmonic(floquetHarmonic(m, -kEta, kOmega, false)), -9);
}

// A slow rotor: a broad spread of harmonics whose largest member wanders; the centre does not.
TEST(FloquetHarmonic, SpreadIsReportedAtItsCentre) {
  SolutionSpectrum a{spectrum({{20, 0.15}, {22, 0.29}, {24, 0.25}, {26, 0.21}, {28, 0.10}}), {}, {}};
  SolutionSpectrum b{spectrum({{20, 0.15}, {22, 0.24}, {24, 0.25}, {26, 0.26}, {28, 0.10}}), {}, {}};
  // Largest 22 in a, 26 in b; centroids 23.64 and 23.84: 24 is the one central harmonic of both.
  EXPECT_EQ(harmonic(floquetHarmonic(a, kEta, kOmega, false)), 24);
  EXPECT_EQ(harmonic(floquetHarmonic(b, kEta, kOmega, false)), 24);
}

// A 2-bladed rotor's cyclic mode: the fixed frame sees the whirls k ± 1 of the rotating carrier k;
// here the forward whirl is boosted by a coupling (3:1, which alone would pick it), yet the mode is a
// standing pattern of the blades and is reported at its backward whirl. A mode carried by fixed
// coordinates on the same rotor keeps the fixed-frame rule.
TEST(FloquetHarmonic, TwoBladedCyclicModeAtItsBackwardWhirl) {
  const std::vector<double> fixed = spectrum({{13, 1.0}, {15, 3.5}});
  SolutionSpectrum s{fixed, fixed, spectrum({{14, 1.0}, {18, 0.12}})};
  EXPECT_EQ(harmonic(floquetHarmonic(s, kEta, kOmega, true)), 13);
  SolutionSpectrum notCyclic{fixed, spectrum({{13, 0.1}}), spectrum({{14, 1.0}})};
  EXPECT_EQ(harmonic(floquetHarmonic(notCyclic, kEta, kOmega, true)), 15);
  EXPECT_EQ(harmonic(floquetHarmonic(s, kEta, kOmega, false)), 15);  // 3 blades: the whirls are modes
}

// A cyclic mode slower than the rotor (ω < Ω: a soft teeter): |ω − Ω| is the lower of the two.
TEST(FloquetHarmonic, SlowCyclicModeFoldsBelowZero) {
  // Im η = 0.3, carrier 0 (ω = 0.3 < Ω = 2): whirls at −1.7 and 2.3 rad/s.
  SolutionSpectrum s{spectrum({{-1, 1.0}, {1, 1.0}}), spectrum({{-1, 1.0}, {1, 1.0}}), spectrum({{0, 1.0}})};
  const int k = harmonic(floquetHarmonic(s, kEta, kOmega, true));
  EXPECT_EQ(k, -1);
  EXPECT_NEAR(std::abs(kEta + k * kOmega), kOmega - kEta, 1e-12);
}

}  // namespace
}  // namespace whirl
