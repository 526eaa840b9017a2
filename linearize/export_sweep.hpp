#pragma once
/// \file
/// The sweep of `whirl export`: the state-space models of every operating point, one task per
/// point spread over the MPI ranks (linearize/sweep.hpp). Each point starts from the model's own
/// initial point at the point's condition, never from its neighbour's equilibrium: the result then
/// depends on the point alone, so K ranks give the bytes of one process.
#include <vector>

#include "linearize/export_point.hpp"
#include "linearize/sweep.hpp"

namespace whirl {

/// exportOperatingPoint at each of `points`, labelled with the point's rpm, wind speed and pitch as
/// given (the wind speed also on the model and on every azimuth's model). `sweep.check_point`, when
/// set, is called with each point's solved equilibrium (it throws to stop the sweep).
/// \return the points in order on rank 0, an empty vector on the other ranks.
std::vector<ExportPoint> exportSweep(const Model& model, const std::vector<SweepPoint>& points,
                                     const ExportOptions& opt, const SweepOptions& sweep);

}  // namespace whirl
