#pragma once
/// \file
/// Frequency response of a linear time-invariant state-space model: the transfer matrix
/// G(jω) = C (jω I − A)⁻¹ B + D, for Bode plots of a controller-design model.
#include <complex>
#include <vector>

#include "linearize/state_space.hpp"

namespace whirl {

/// G(j 2π f) (ny × nu, complex) at each frequency f [Hz] of `freq_hz` (> 0), by an LU of
/// (jω I − A) per frequency. Throws ComputeError when jω is an eigenvalue of A (singular).
std::vector<Eigen::MatrixXcd> frequencyResponse(const StateSpaceModel& s, const std::vector<double>& freq_hz);

/// `n` frequencies logarithmically spaced from `f0` to `f1` [Hz], both included (f1 > f0 > 0, n ≥ 2).
std::vector<double> logFrequencies(double f0, double f1, int n);

}  // namespace whirl
