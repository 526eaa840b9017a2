#pragma once
/// \file
/// Steady operating schedule: wind speed → rotor speed, collective pitch, as a CSV with a header
/// row (e.g. cases/nrel5mw/NREL5MW_Oper.csv). Columns are recognized by name, case-insensitive:
/// rotor speed [rpm] "RotSpeed…" (or a column named "rpm"), wind speed [m/s] "WS…" or "Wind…",
/// pitch [deg] "BldPitch…" or "Pitch…"; other columns are ignored.
#include <string>
#include <vector>

#include "src/model/operating_condition.hpp"

namespace whirl {

/// One sweepPoint(rpm, wind speed, pitch) per row. InputError naming the file (and line) when it
/// cannot be read or has no rotor-speed column.
std::vector<SweepPoint> readSchedule(const std::string& path);

}  // namespace whirl
