#pragma once
/// \file
/// The one-state pole placement of linearize/controller_tuning.hpp checked on the whole linear model
/// (issue 43, item 5): at each point of the pitch schedule the trimmed turbine's open-loop plant
/// (modal/closed_loop_modes.hpp) is closed by the PI with the placed gains — and the constant-power
/// torque law when the placement assumed it, and a generator-speed low pass when one is given — and the
/// closed-loop root nearest the target −ζω + iω√(1 − ζ²) is reported with how far it lands from it.
#include <complex>
#include <vector>

#include "linearize/controller_tuning.hpp"
#include "modal/closed_loop_modes.hpp"

namespace whirl {

struct PlacementCheck {
  double wind_speed = 0;        ///< [m/s]
  std::complex<double> target;  ///< the one-state model's closed-loop root [1/s]
  std::complex<double> pole;    ///< the whole model's closed-loop root nearest it [1/s]
  double omega = 0, zeta = 0;   ///< its natural frequency [rad/s] and damping ratio [-]
  bool stable = true;           ///< every closed-loop root of the whole model in the left half-plane
};

struct PlacementCheckOptions {
  int azimuths = 36;        ///< of the plant's periodic linearization
  double speed_filter = 0;  ///< first-order generator-speed low pass [rad/s] (ROSCO's F_LPFCornerFreq); 0: none
};

/// One check per pitch-schedule point of `g`; `trimmed[k]` is the trimmed state at g.wind_speed[k].
/// \throws InputError when the sizes differ.
std::vector<PlacementCheck> checkPlacement(const Model& model, const std::vector<SteadyState>& trimmed,
                                           const GainSchedule& g, const TuningTurbine& t, const TuningGoals& goals,
                                           const PlacementCheckOptions& opt = {});

/// The placement on the whole linear model: at each point the PI gains (K_p, K_i) that put the
/// closed-loop root nearest the target exactly on it, by Newton's method on Re and Im of (root − target)
/// with derivatives by central differences, started from the one-state gains of `g` (the root followed
/// as the one nearest the previous iterate). The plant is linearized once per point; each iterate closes
/// it again. `g`'s pitch-loop gains are replaced where Newton converges (|root − target| < 1e-9 |target|
/// within 30 iterates); `converged[k]` says where (elsewhere the one-state gains stay).
struct FullModelPlacement {
  GainSchedule gains;
  std::vector<bool> converged;
  std::vector<PlacementCheck> checks;  ///< of the returned gains
};
FullModelPlacement placeOnFullModel(const Model& model, const std::vector<SteadyState>& trimmed, const GainSchedule& g,
                                    const TuningTurbine& t, const TuningGoals& goals,
                                    const PlacementCheckOptions& opt = {});

}  // namespace whirl
