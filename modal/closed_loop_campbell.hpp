#pragma once
/// \file
/// The closed-loop Campbell diagram along the wind (issue 43, item 4): at each point of a schedule
/// trimmed with ROSCO's controller the open-loop plant and the closed loop (modal/closed_loop_modes.hpp,
/// the controller linearized by linearize/rosco_linear.hpp), and the roots of each tracked from wind
/// speed to wind speed into named lines as the open-loop Campbell's are (modal/tracking.hpp: MAC of
/// the eigenvectors and frequency). The eigenvectors are compared on the plant's states only: those are
/// the same at every point, while the controller's change with the region (a torque PI below rated, a
/// pitch PI above) and its states' scale (rad of pitch integral against m of deflection) would
/// dominate the comparison. A controller root's plant part is its imprint on the structure.
#include <string>
#include <vector>

#include "linearize/rosco_linear.hpp"
#include "modal/campbell.hpp"
#include "modal/closed_loop_modes.hpp"
#include "modal/tracking.hpp"

namespace whirl {

struct ClosedLoopCampbellOptions {
  /// Azimuths, frozen wake, margins, port names; the plant's outputs (default here: the speed output
  /// alone, what the loop and the margins need).
  ClosedLoopOptions point;
  RoscoLinearOptions controller;
  TrackingOptions tracking;
  /// Called after each point with (points done, points in all); may throw to stop.
  std::function<void(int, int)> progress;
};

struct ClosedLoopCampbell {
  std::vector<ClosedLoopPoint> points;  ///< one per steady state, in the schedule's order
  /// The open and the closed loop as Campbell diagrams: points[p].modes are the roots of
  /// points[p].open_modes / closed_modes (same order), the lines tracked along the wind.
  CampbellDiagram open, closed;
};

/// The closed-loop Campbell of `model` with `controller` at the trimmed points `schedule` (trimmed
/// with that controller: SteadyState::region set). Points are independent and computed in order.
ClosedLoopCampbell closedLoopCampbell(const Model& model, const RoscoController& controller,
                                      const std::vector<SteadyState>& schedule,
                                      const ClosedLoopCampbellOptions& opt = {});

}  // namespace whirl
