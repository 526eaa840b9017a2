#pragma once
/// \file
/// User corrections to tracked Campbell lines, read from a small CSV file and applied in file order.
///
///     # whirl tracking overrides (comments start with #, blank lines are ignored)
///     rename,flap 1 BW / drivetrain,flap 1 BW
///     assign,7,4,drivetrain
///
/// - `rename,<line name>,<new name>` renames a line; the new name must not be taken by another line.
/// - `assign,<point index>,<mode index>,<line name>` pins mode `<mode index>` of point `<point index>`
///   (both 0-based: points in sweep order, modes sorted by frequency, as `index` in
///   campbell_modes.json) to the line: from that point on, the line continues with that mode and
///   the line that held the mode continues the way the named line did (the two lines are cut at the
///   point and their tails exchanged). This undoes a swap the tracker made at that point; a line
///   left with no mode at all is removed.
///
/// Fields are separated by commas and trimmed; a field may be "quoted" (a doubled "" inside is a quote).
/// Names refer to the lines as they are when the row is read, so a rename applies to later rows.
/// Any error (unknown keyword, wrong number of fields, bad or out-of-range index, unknown line, a
/// mode not on any line) throws InputError naming file:line.
#include <string>
#include <vector>

#include "modal/campbell.hpp"

namespace whirl {

/// Reads `file` and applies it to `lines` (tracked through `points`).
void applyTrackingOverrides(const std::string& file, const std::vector<CampbellPoint>& points,
                            std::vector<CampbellLine>& lines);

/// Applies override rows from `text`; `file` only names the source in error messages.
void applyTrackingOverridesText(const std::string& text, const std::string& file,
                                const std::vector<CampbellPoint>& points, std::vector<CampbellLine>& lines);

}  // namespace whirl
