#pragma once
/// \file
/// Mode tracking: links the modes of neighbouring Campbell points into CampbellLines.
///
/// Points p−1 and p are matched by an optimal assignment (modal/hungarian.hpp) on the cost
///   c(a, b) = 1 − MAC(φa, φb) + w · |fa − fb| / max(fa, fb, fmin),
///   MAC(φa, φb) = |φaᴴ φb|² / (|φa|² |φb|²)   (complex shapes, Mode::shape),
/// so a line follows the mode shape first and the frequency second: two modes whose frequencies
/// cross keep their lines. A pair is linked only when its cost is below `max_cost`; otherwise, and
/// when the points have different numbers of modes, lines end and new lines start.
///
/// Each line is named by the name its modes carry most often (ties: the name at the highest rpm
/// among the tied ones); repeated names get " (2)", " (3)", … in line order. Lines are ordered by
/// their mean frequency.
///
/// Optionally a user override file (see modal/tracking_overrides.hpp and modal/README-campbell.md)
/// renames lines and pins modes to lines.
#include <string>
#include <vector>

#include "modal/campbell.hpp"

namespace whirl {

/// Options of trackModes.
struct TrackingOptions {
  double frequency_weight = 0.5;    ///< w: weight of the relative frequency change in the cost
  double fmin_hz = 0.05;            ///< fmin: floor of the frequency scale (keeps f ≈ 0 modes finite)
  double max_cost = 1.0;            ///< pairs costing this or more are not linked (orthogonal shapes cost ≥ 1)
  bool include_rigid_body = false;  ///< track rigid-body modes (f = 0, e.g. a free azimuth) too
  std::string overrides_file;       ///< CSV of renames and pins applied after tracking; empty: none
};

/// Modal assurance criterion of two complex shapes of equal dimension, in [0, 1]; 0 when one is zero.
double modalAssurance(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b);

/// Cost of linking mode a (at one point) to mode b (at the next), as in the file comment.
double trackingCost(const Mode& a, const Mode& b, const TrackingOptions& opt = {});

/// Lines through points[0..P−1] (each CampbellLine::mode has dim P).
/// Every tracked mode belongs to exactly one line. Throws InputError when the mode shapes of two
/// neighbouring points have different dimensions, or (naming file:line) on a bad override file.
std::vector<CampbellLine> trackModes(const std::vector<CampbellPoint>& points, const TrackingOptions& opt = {});

/// Names lines from their modes' names (rule in the file comment) and makes the names unique.
void nameLines(const std::vector<CampbellPoint>& points, std::vector<CampbellLine>& lines);

}  // namespace whirl
