#pragma once
/// \file
/// AeroDyn v15 blade file: the aerodynamic stations of one blade (span, aerodynamic-centre offsets,
/// curve angle, twist, chord, airfoil index), in the file's units (lengths m, angles deg).
///
/// Layouts read: AeroDyn v15.00–v15.04 (FAST 8, OpenFAST v1–v3: 7 columns, or 10 with BlCb, BlCenBn,
/// BlCenBt) and OpenFAST v4–v5 (columns found by name, BlCrvAng optional, more optional columns such as
/// t_c, BlCb, BlCenBn, BlCenBt, BlCpn…). Columns whirl does not use are accepted and ignored.
#include <filesystem>
#include <vector>

#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

class OverrideSet;

/// One AeroDyn blade file. Station vectors all have NumBlNds entries.
struct AeroDynBladeInput {
  OpenFastFile source;  ///< the parsed file (path, line of every key: source.where(key, reason))
  int NumBlNds = 0;     ///< number of blade nodes (stations), >= 2

  std::vector<double> BlSpn;     ///< span from the blade root along the pitch axis (m); starts at 0, increasing
  std::vector<double> BlCrvAC;   ///< out-of-plane offset of the aerodynamic centre, prebend (m)
  std::vector<double> BlSwpAC;   ///< in-plane offset of the aerodynamic centre, sweep (m)
  std::vector<double> BlCrvAng;  ///< curve angle (deg); without the column AeroDyn's (aeroDynCurveAngles)
  std::vector<double> BlTwist;   ///< aerodynamic twist (deg), positive to feather
  std::vector<double> BlChord;   ///< chord (m), > 0
  std::vector<int> BlAFID;       ///< airfoil of each station, 1-based index into AeroDyn's AFNames list
  bool has_BlCrvAng = false;     ///< the file has a BlCrvAng column
  /// AeroDyn v14 elements (readAeroDeck of a CompAero = 1 deck): BlSpn holds RNodes, the element centres
  /// measured from the rotor centre (hub radius included), and each element carries its width DRNodes (m),
  /// its loads being the centre values times the width (midpoint rule). Empty for v15 files, whose nodes
  /// start at the blade root and carry trapezoid weights.
  std::vector<double> element_width;
  std::vector<int> row_lines;  ///< file line of each station
};

/// Reads an AeroDyn blade file. Checks: NumBlNds >= 2, exactly NumBlNds rows (fewer = truncated), the
/// required columns present (BlSpn, BlCrvAC, BlSwpAC, BlTwist, BlChord, BlAFID), finite numbers, BlSpn
/// starting at 0 and strictly increasing, BlChord > 0, BlAFID a whole number >= 1 (its upper bound,
/// NumAFfiles, is checked by readAeroDeck). Throws InputError "file:line: key: reason".
/// The curve angles (deg) AeroDyn computes when the file has no BlCrvAng column (setCantAngle,
/// AeroDyn_IO.f90): atan of the mid-chord line's prebend slope, x = BlCrvAC + ¼ BlChord sin(BlTwist),
/// differentiated along BlSpn through each node and its two neighbours. AeroDyn needs three nodes;
/// with two, the slope of the line through them.
std::vector<double> aeroDynCurveAngles(const AeroDynBladeInput& b);

AeroDynBladeInput readAeroDynBlade(const std::filesystem::path& file, OverrideSet* overrides = nullptr);

}  // namespace whirl::io
