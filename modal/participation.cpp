#include "modal/participation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/base/error.hpp"

namespace whirl {

std::vector<Mode> participationModes(const EigenDecomposition& ed, const std::vector<int>& coordinate_of,
                                     const std::vector<std::string>& names) {
  const Eigen::Index N = ed.values.size();
  const int n = static_cast<int>(names.size());
  std::vector<Mode> modes;
  if (N == 0 || n == 0) return modes;
  if (static_cast<Eigen::Index>(coordinate_of.size()) != N)
    throw ComputeError(
        where("", 0, "participationModes",
              std::to_string(coordinate_of.size()) + " coordinates for " + std::to_string(N) + " states"));
  // First state of each coordinate: where the shape is read.
  std::vector<int> first(static_cast<size_t>(n), -1);
  for (Eigen::Index i = 0; i < N; ++i) {
    const int c = coordinate_of[i];
    if (c < 0 || c >= n)
      throw ComputeError(where("", 0, "participationModes", "state " + std::to_string(i) + " has no coordinate"));
    if (first[c] < 0) first[c] = static_cast<int>(i);
  }
  if (ed.left.rows() != N || ed.left.cols() != N)
    throw ComputeError(where("", 0, "participationModes", "no left eigenvectors (eigenStandard(A, true))"));
  // Same scale for "zero" as modal/modes.cpp: rigid-body roots are numerically ~1e-8.
  const double zero = 1e-7 * std::max(1.0, ed.values.cwiseAbs().maxCoeff());
  int zero_roots = 0;
  for (Eigen::Index k = 0; k < N; ++k) {
    const std::complex<double> l = ed.values(k);
    const bool oscillating = std::abs(l.imag()) > zero && std::abs(l.imag()) > 1e-9 * std::abs(l);
    if (oscillating && l.imag() < 0) continue;  // the conjugate carries the same mode
    // A double zero root (a free azimuth: its angle and its rate) is one rigid-body mode, as whirl's
    // own modes count it; a zero root beside a real decay is one mode and the decay another.
    if (std::abs(l) <= zero && zero_roots++ % 2 == 1) continue;
    Mode mode;
    // Per coordinate, (Σ|u_i|)(Σ|v_i|) over its states: at a defective zero root (a free azimuth) the
    // right vector is the angle and the left one its rate, whose state-by-state products vanish.
    VecX left = VecX::Zero(n), right = VecX::Zero(n);
    for (Eigen::Index i = 0; i < N; ++i) {
      left(coordinate_of[i]) += std::abs(ed.left(i, k));
      right(coordinate_of[i]) += std::abs(ed.vectors(i, k));
    }
    mode.participation = left.cwiseProduct(right);
    const double total = mode.participation.sum();
    if (total > 0) mode.participation /= total;
    mode.shape.resize(n);
    for (int c = 0; c < n; ++c) mode.shape(c) = ed.vectors(first[c], k);
    Eigen::Index imax = 0;
    mode.shape.cwiseAbs().maxCoeff(&imax);
    if (std::abs(mode.shape(imax)) > 0) mode.shape /= mode.shape(imax);
    if (std::abs(l) <= zero) {
      mode.rigid_body = true;
    } else {
      const ModalFrequency f = modalFrequency(oscillating ? l : std::complex<double>(l.real(), 0));
      mode.freq_hz = f.freq_hz;
      mode.damped_freq_hz = oscillating ? f.damped_freq_hz : 0;
      mode.damping_ratio = f.damping_ratio;
    }
    mode.name = nameFromParticipation(mode.participation, names);
    std::vector<std::pair<std::string, double>> shares;
    for (Eigen::Index i = 0; i < mode.participation.size(); ++i)
      shares.emplace_back(names.at(static_cast<std::size_t>(i)), mode.participation(i));
    setNameEvidence(mode, std::move(shares));
    modes.push_back(std::move(mode));
  }
  std::stable_sort(modes.begin(), modes.end(), [](const Mode& a, const Mode& b) { return a.freq_hz < b.freq_hz; });
  return modes;
}

}  // namespace whirl
