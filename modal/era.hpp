#pragma once
/// \file
/// Modes identified from a free response recorded on several channels at a constant sampling interval,
/// by the eigensystem realization algorithm (Juang and Pappa 1985): the block Hankel matrix of the
/// samples H0 = [y_{i+j}] and its one-sample shift H1 = [y_{i+j+1}] (r block rows of the p channels, s
/// columns) factor as O·X and O·A·X for a free response y_k = C A^k x0; the truncated singular value
/// decomposition H0 ≈ U Σ Vᵀ gives the discrete state matrix Â = Σ^{-1/2} Uᵀ H1 V Σ^{-1/2} of the order
/// n kept, whose eigenvalues z are the poles: λ = ln z / Δt, f = |λ|/2π, ζ = −Re λ/|λ|.
/// Unlike a zero-crossing count on one channel, modes that share the channels are separated (a tower
/// signal that carries the platform pitch mode too gives both frequencies, unbiased).
#include <vector>

#include "src/base/types.hpp"

namespace whirl {

struct IdentifiedPole {
  double freq_hz = 0;         ///< undamped f = |λ|/2π
  double damped_freq_hz = 0;  ///< |Im λ|/2π
  double damping_ratio = 0;   ///< −Re λ/|λ|
  /// Share of the response [-]: this pole's mean amplitude in the realized free response over the record
  /// (‖Cφ‖·|φ⁺x0| times the mean of |z|^k), relative to the largest pole's; a complex pair counts as one.
  double share = 0;
};

struct EraOptions {
  int block_rows = 0;            ///< r; 0: max(20, ⌈40/p⌉)
  int max_order = 0;             ///< largest n kept; 0: r·p/2
  double rank_tolerance = 1e-7;  ///< singular values below this fraction of the largest are dropped
};

/// \param[in] y   samples × channels: the deviations from the equilibrium, at t_k = k Δt
/// \param[in] dt  the sampling interval Δt [s]
/// \return one entry per real pole and one per complex pair (Im λ > 0), largest share first
/// \throws InputError when Δt ≤ 0 or there are too few samples for the Hankel matrix
std::vector<IdentifiedPole> identifyPoles(const MatX& y, double dt, const EraOptions& options = {});

/// The pole whose damped frequency |Im λ|/2π is nearest `damped_freq_hz` [Hz] (the first of equals);
/// nullptr when `poles` is empty.
const IdentifiedPole* nearestPole(const std::vector<IdentifiedPole>& poles, double damped_freq_hz);

}  // namespace whirl
