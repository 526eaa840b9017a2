#pragma once
/// \file
/// InflowWind input file: the wind type and the steady-wind parameters (WindType = 1), in the file's
/// units (speeds m/s, heights m, angles deg). Whether whirl can use the wind type is checked by
/// aero_support.hpp; this reader only reads.
///
/// Layouts read: InflowWind v3.01 (FAST 8 certification tests: no VFlowAng, `PLexp`) through OpenFAST v3,
/// v4 and v5 (VFlowAng, VelInterpCubic, LIDAR section; the steady-wind keys unchanged). Keys are matched
/// case-insensitively, so `PLexp` and `PLExp` are the same key.
#include <filesystem>

#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

class OverrideSet;

/// InflowWind steady-wind description.
struct InflowWindInput {
  OpenFastFile source;        ///< the parsed file (path, line of every key: source.where(key, reason))
  int WindType = 1;           ///< {1 steady, 2 uniform file, 3 TurbSim, 4 Bladed FF, 5 HAWC, 6 user, 7 native Bladed}
  double PropagationDir = 0;  ///< direction of propagation (deg), meteorological: positive rotates towards −Y
  double VFlowAng = 0;        ///< upflow angle (deg); 0 when the key is absent (older layouts)
  bool has_VFlowAng = false;  ///< the file has the VFlowAng key
  double HWindSpeed = 0;      ///< horizontal wind speed at RefHt (m/s), >= 0   [WindType = 1]
  double RefHt = 0;           ///< reference height of HWindSpeed (m), > 0      [WindType = 1]
  double PLExp = 0;           ///< power-law shear exponent (-)                [WindType = 1]
};

/// Reads an InflowWind file. The steady-wind keys (HWindSpeed, RefHt, PLExp) are read whatever the
/// WindType (every layout has them). Throws InputError "file:line: key: reason" when a key is missing or
/// malformed, HWindSpeed < 0 or RefHt <= 0.
InflowWindInput readInflowWind(const std::filesystem::path& file, OverrideSet* overrides = nullptr);

}  // namespace whirl::io
