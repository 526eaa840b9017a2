#pragma once
/// \file
/// Campbell sweep: for each operating point (rotor speed, optionally wind speed and collective
/// pitch) the periodic operating point is solved and linearized at N azimuths, transformed to
/// multiblade coordinates and analysed (modal/rotor_modes.hpp).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "modal/campbell.hpp"
#include "src/model/model.hpp"

namespace whirl {

struct SweepPoint {
  double rpm = 0;
  std::optional<double> wind_speed;  ///< m/s
  std::optional<double> pitch_deg;   ///< collective pitch, set on the frozen "blade k pitch" coordinates
};

struct SweepOptions {
  int azimuths = 36;
  /// Called after each point with (points done, points total); used for progress on stderr.
  std::function<void(int, int)> progress;
};

/// Points START:STEP:STOP (rpm), STOP included within round-off. InputError on a bad range.
std::vector<SweepPoint> rpmRange(const std::string& spec);

/// Modes at every point, sorted by frequency (lines not yet tracked).
std::vector<CampbellPoint> campbellSweep(const Model& model, const std::vector<SweepPoint>& points,
                                         const SweepOptions& opt);

/// Sets the collective pitch on the model's frozen "blade <k> pitch" coordinates; returns how many.
int setCollectivePitch(Model& model, double pitch_deg);

}  // namespace whirl
