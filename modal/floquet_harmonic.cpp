#include "modal/floquet_harmonic.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace whirl {
namespace {

long harmonicOf(int index, int M) { return index <= M / 2 ? index : index - M; }
int indexOf(long harmonic, int M) { return static_cast<int>(((harmonic % M) + M) % M); }

// Harmonics near the centre of a spectrum: within 1.5 of its energy centroid Σ k E_k / Σ E_k and with
// at least a quarter of the largest harmonic's energy; the largest harmonic when none is.
std::vector<long> central(const std::vector<double>& e) {
  const int M = static_cast<int>(e.size());
  double total = 0, moment = 0, largest = 0;
  int top = 0;
  for (int k = 0; k < M; ++k) {
    total += e[k];
    moment += harmonicOf(k, M) * e[k];
    if (e[k] > largest) largest = e[k], top = k;
  }
  std::vector<long> out;
  if (total <= 0) return {0};
  const double c = moment / total;
  for (long k = static_cast<long>(std::floor(c - 1.5)); k <= static_cast<long>(std::ceil(c + 1.5)); ++k)
    if (std::abs(k - c) <= 1.5 && e[indexOf(k, M)] >= 0.25 * largest) out.push_back(k);
  if (out.empty()) out.push_back(harmonicOf(top, M));
  return out;
}

// Of harmonics `ks`, the one with the lowest |frequency| |Im η + kΩ|.
int lowest(const std::vector<long>& ks, int M, double eta_imag, double omega) {
  long best = ks.front();
  for (long k : ks)
    if (std::abs(eta_imag + k * omega) < std::abs(eta_imag + best * omega)) best = k;
  return indexOf(best, M);
}

}  // namespace

bool standingCyclicMode(const SolutionSpectrum& s, bool standing_rotor) {
  if (!standing_rotor || s.rotating.size() != s.fixed.size() || s.cyclic.size() != s.fixed.size()) return false;
  const double total = std::accumulate(s.fixed.begin(), s.fixed.end(), 0.0);
  const double cyclic = std::accumulate(s.cyclic.begin(), s.cyclic.end(), 0.0);
  return total > 0 && cyclic > 0.5 * total;
}

int floquetHarmonic(const SolutionSpectrum& s, double eta_imag, double omega, bool standing_rotor) {
  const int M = static_cast<int>(s.fixed.size());
  if (M == 0) return 0;
  if (standingCyclicMode(s, standing_rotor)) {
    // The rotating-frame carrier: the largest of the central harmonics of the rotor's own motion.
    long carrier = 0;
    double most = -1;
    for (long k : central(s.rotating))
      if (s.rotating[indexOf(k, M)] > most) most = s.rotating[indexOf(k, M)], carrier = k;
    return lowest({carrier - 1, carrier + 1}, M, eta_imag, omega);
  }
  return lowest(central(s.fixed), M, eta_imag, omega);
}

}  // namespace whirl
