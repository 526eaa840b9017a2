#pragma once
/// \file
/// campbell_aero.csv: the aerodynamic roots of a Campbell diagram (modal/aero_roots.hpp), which are on
/// no line. Columns `rpm,wind_speed,mode,freq_hz,damped_freq_hz,damping_ratio,aero_share,dominant_state`:
/// one row per point and aerodynamic root, points in sweep order, roots by frequency (`aero 1`, …);
/// wind speed in m/s (empty when the point has none), `aero_share` the roots' participation in the
/// aerodynamic states, `dominant_state` the coordinate of the largest participation (a multiblade UA
/// coordinate, e.g. `UA x4 element 12 collective`).
#include <string>

#include "modal/campbell.hpp"

namespace whirl {

/// Whether any point of `d` has an aerodynamic root.
bool hasAeroRoots(const CampbellDiagram& d);

/// Text of campbell_aero.csv.
std::string campbellAeroCsv(const CampbellDiagram& d);

}  // namespace whirl
