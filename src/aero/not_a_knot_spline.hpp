#pragma once
/// \file
/// Cubic interpolating splines with not-a-knot end conditions, as a linear functional of the data:
/// s(x) = w(x) · y. This is the spline FITPACK's `regrid` builds for a smoothing factor s = 0 (the
/// interior knots at the data points x₂ … x_{n−3}, 0-based, so the third derivative is continuous at
/// x₁ and x_{n−2}), which SciPy's `RectBivariateSpline` wraps and ROSCO's tuning evaluates its rotor
/// performance surface with (NREL/ROSCO `rosco/toolbox/turbine.py`, `RotorPerformance.interp_surface`).
/// A tensor-product interpolant is evaluated by weights along each axis: s(x, y) = w_y(y)ᵀ T w_x(x).
#include <vector>

#include "src/base/types.hpp"

namespace whirl::aero {

class NotAKnotSpline {
 public:
  /// \param[in] x strictly increasing abscissae, at least 4 (any unit).
  /// \throws std::invalid_argument for fewer than 4 points or abscissae not strictly increasing.
  explicit NotAKnotSpline(std::vector<double> x);

  /// The weights w(x) of the data values: s(x) = Σ_i w_i y_i; outside [x₀, x_{n−1}] the end cubic is
  /// extrapolated.
  VecX weights(double x) const;

  const std::vector<double>& knots() const { return x_; }

 private:
  std::vector<double> x_;
  /// Second derivatives at the knots as a linear map of the data: M = G y (n × n).
  MatX G_;
};

}  // namespace whirl::aero
