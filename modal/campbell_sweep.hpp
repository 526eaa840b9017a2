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
#include "linearize/operating_point.hpp"
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
  /// Under mpirun: rank 0 only, counting its own share of the points.
  std::function<void(int, int)> progress;
  /// Called with each point's model and solved periodic operating points (the validity check of the
  /// commands, linearize/point_validity.hpp); returns the problems to keep in the point's metadata,
  /// or throws to stop the sweep.
  std::function<std::vector<std::string>(const Model&, const std::vector<OperatingPoint>&, const SweepPoint&)>
      check_point;
};

/// Points START:STEP:STOP (rpm), STOP included within round-off. InputError on a bad range.
std::vector<SweepPoint> rpmRange(const std::string& spec);

/// Modes at one operating point, sorted by frequency. Depends on the point only (each point starts
/// from the model's initial point, not from a neighbour's equilibrium), so points can be computed
/// in any order, on any rank, with the same bits.
CampbellPoint campbellPoint(const Model& model, const SweepPoint& point, const SweepOptions& opt);

/// Modes at every point (lines not yet tracked). Under mpirun the points are spread over the
/// ranks (src/parallel/parallel_map.hpp) and gathered in order on rank 0; other ranks get an
/// empty vector. The result on rank 0 is identical, bit for bit, to a run on one rank.
std::vector<CampbellPoint> campbellSweep(const Model& model, const std::vector<SweepPoint>& points,
                                         const SweepOptions& opt);

/// Sets the collective pitch on the model's frozen "blade <k> pitch" coordinates; returns how many.
int setCollectivePitch(Model& model, double pitch_deg);

}  // namespace whirl
