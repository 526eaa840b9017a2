#pragma once
/// \file
/// A Campbell diagram: modes at a sequence of operating points (rotor speed, optionally wind
/// speed and pitch), the lines that link each physical mode through the points, and their output.
#include <optional>
#include <string>
#include <vector>

#include "modal/modes.hpp"

namespace whirl {

/// The modes of one operating point. Mode shapes are in the coordinates named by
/// `coordinates` (multiblade coordinates for rotors: "flap 1 collective", "flap 1 cos", …).
struct CampbellPoint {
  double rpm = 0;
  std::optional<double> wind_speed;  ///< m/s, when the point comes from a schedule
  std::optional<double> pitch_deg;   ///< collective blade pitch of the schedule
  std::vector<std::string> coordinates;
  std::vector<Mode> modes;  ///< sorted by frequency
  /// Where the operating point leaves the model's range of validity (linearize/point_validity.hpp),
  /// kept when the command was told to go on (--allow-invalid-point); empty for a valid point.
  std::vector<std::string> validity_problems;
};

/// One physical mode followed through the points.
struct CampbellLine {
  std::string name;
  std::vector<int> mode;  ///< per point: index into points[p].modes, −1 where the line has no mode
};

struct CampbellDiagram {
  std::string title;
  std::vector<CampbellPoint> points;
  std::vector<CampbellLine> lines;
};

}  // namespace whirl
