#pragma once
/// \file
/// Frequency and damping of a free decay identified from a sampled time series, to set next to the
/// eigenvalues of the linear model (`whirl simulate`, tests of the nonlinear against the linear model):
/// the damped period from the zero crossings (a least-squares line through the crossing times, each
/// interpolated linearly between samples — exact to second order at an inflection point), the decay
/// rate σ from a least-squares line through the logarithms of the extrema (one per half period,
/// refined by a parabola through the three samples around it); ζ = σ/√(σ² + ω_d²) — the logarithmic
/// decrement method for a single dominant mode.
#include <vector>

namespace whirl {

struct IdentifiedDecay {
  double damped_freq_hz = 0;  ///< f_d = ω_d/2π
  double damping_ratio = 0;   ///< ζ
  double freq_hz = 0;         ///< undamped f = f_d/√(1 − ζ²)
  int half_periods = 0;       ///< zero crossings − 1 used
};

/// \param[in] t       sample times [s], increasing
/// \param[in] x       the signal at those times
/// \param[in] center  the value it decays to (the equilibrium); crossings are of x − center
/// \throws ComputeError "decay identification: fewer than 4 zero crossings …" when the series is too short
///         or does not oscillate.
IdentifiedDecay identifyDecay(const std::vector<double>& t, const std::vector<double>& x, double center);

}  // namespace whirl
