#pragma once
/// \file
/// A rotor performance surface: a power, thrust or torque coefficient tabulated on a grid of blade
/// pitch and tip-speed ratio, evaluated the way ROSCO's tuning evaluates it (NREL/ROSCO
/// `rosco/toolbox/turbine.py`, class `RotorPerformance`):
/// - values by the bicubic not-a-knot interpolant of the table (SciPy `RectBivariateSpline`, s = 0;
///   src/aero/not_a_knot_spline.hpp);
/// - gradients by the same interpolant of the table's index differences (NumPy `gradient`: central
///   differences inside, one-sided at the edges, per grid step), divided by the first grid step
///   (ROSCO `controller.py`, `tune_controller`: `dCp_beta/np.diff(pitch_initial_rad)[0]`);
/// - the optimum at the grid point of the largest value (the last one in row-major order on ties,
///   ROSCO's `max_ind[0][-1]`, `max_ind[1][-1]`; no refinement, ROSCO's default).
#include <vector>

#include "src/aero/not_a_knot_spline.hpp"
#include "src/base/types.hpp"

namespace whirl::aero {

class PerformanceSurface {
 public:
  /// \param[in] pitch grid pitch angles [rad], increasing (table columns)
  /// \param[in] tsr grid tip-speed ratios [-], increasing (table rows)
  /// \param[in] table coefficient, tsr.size() × pitch.size() [-]
  PerformanceSurface(const std::vector<double>& pitch, const std::vector<double>& tsr, MatX table);

  /// The interpolated coefficient at pitch [rad] and tip-speed ratio [-].
  double value(double pitch, double tsr) const;
  /// The interpolant at `tsr` on every grid pitch (ROSCO's `interp_surface(pitch_initial_rad, TSR)`).
  VecX valuesAtGridPitches(double tsr) const;
  /// ∂C/∂β [1/rad] and ∂C/∂λ [-] from the interpolated index differences.
  struct Gradient {
    double pitch = 0, tsr = 0;
  };
  Gradient gradient(double pitch, double tsr) const;

  double maxValue() const { return max_; }
  double optimalPitch() const { return pitch_opt_; }  ///< [rad]
  double optimalTsr() const { return tsr_opt_; }      ///< [-]
  const std::vector<double>& pitchGrid() const { return pitch_.knots(); }

 private:
  NotAKnotSpline pitch_, tsr_;
  MatX table_, d_pitch_, d_tsr_;  ///< the table and its index differences along pitch and along tsr
  double max_ = 0, pitch_opt_ = 0, tsr_opt_ = 0;
};

/// A rotor's three surfaces on one grid (ROSCO's `Cp_Ct_Cq.*.txt`).
struct RotorPerformance {
  std::vector<double> pitch;  ///< [rad]
  std::vector<double> tsr;    ///< [-]
  MatX cp, ct, cq;            ///< tsr × pitch [-]
};

}  // namespace whirl::aero
