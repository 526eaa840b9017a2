#pragma once
/// \file
/// Stability margins of one loop broken at a point, from the sensitivity there with every other loop
/// closed (linearize/closed_loop.hpp, loopSensitivity): the return ratio L = 1/S − 1, then on a
/// logarithmic frequency grid refined at each crossing (bisection on the sampled interval):
/// - gain margin: 1/|L| where the phase of L crosses −180° (Im L = 0, Re L < 0), the smallest;
/// - phase margin: 180° + ∠L where |L| crosses 1, the smallest; delay margin: that angle [rad] over
///   its crossover frequency, the smallest over the crossings;
/// - peak sensitivity Ms = max |S| over the grid.
/// No crossing: the margin is infinite (+inf).
#include <complex>
#include <functional>

#include "linearize/closed_loop.hpp"

namespace whirl {

struct LoopMargins {
  double gain_margin = 0;       ///< [-] (linear; dB = 20 log10)
  double gain_crossover = 0;    ///< frequency of the gain margin's phase crossing [rad/s]
  double phase_margin = 0;      ///< [deg]
  double phase_crossover = 0;   ///< frequency of the phase margin's gain crossing [rad/s]
  double delay_margin = 0;      ///< [s]
  double peak_sensitivity = 0;  ///< Ms [-]
  double peak_frequency = 0;    ///< where |S| peaks [rad/s]
};

struct MarginOptions {
  double min_frequency = 1e-3;  ///< [rad/s]
  double max_frequency = 200;   ///< [rad/s]
  int points = 1500;            ///< logarithmically spaced
};

/// S(jω) of a loop sensitivity.
std::complex<double> sensitivityAt(const LoopSensitivity& s, double omega);

/// The margins from S(jω) given as a function of ω [rad/s].
LoopMargins loopMargins(const std::function<std::complex<double>(double)>& sensitivity, const MarginOptions& opt = {});

/// The margins of a loop sensitivity.
LoopMargins loopMargins(const LoopSensitivity& s, const MarginOptions& opt = {});

/// An eigendecomposition of the loop's state matrix already at hand (the closed loop's, whose modes
/// are named anyway): eigenvalues, right and left eigenvectors (columns, any scaling).
struct ModalBasis {
  Eigen::VectorXcd values;
  Eigen::MatrixXcd right, left;
};
/// As above, the sensitivity evaluated from `basis` (checked against the LU as without it).
LoopMargins loopMargins(const LoopSensitivity& s, const ModalBasis& basis, const MarginOptions& opt = {});

}  // namespace whirl
