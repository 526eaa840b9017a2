#pragma once
/// \file
/// MoorDyn input file (the mooring file of CompMooring = 3), v1 (the certification decks: LINE TYPES,
/// CONNECTION PROPERTIES, LINE PROPERTIES) and v2 (LINE TYPES, POINTS, LINES) layouts, read into the
/// MAP++ description (map_input.hpp) that whirl's quasi-static catenaries are built from. MoorDyn's lines
/// are lumped-mass dynamic lines; for a linear model about a static point whirl takes each as the
/// elastic catenary it settles to (Hall & Goupee 2015 validate MoorDyn against such statics), with
/// seabed contact and no friction (MoorDyn v1 has none: CB = 0). Read: line types (Diam, MassDen, EA),
/// fixed (anchor) and vessel (fairlead) points, lines from one to the other. Refused, one line each:
/// connect/free points (multi-segment lines), point masses and volumes, bodies and rods (v2).
/// Every error reads "file:line: key: reason".
#include <filesystem>

#include "src/io/openfast/offshore/map_input.hpp"

namespace whirl::io {

/// \throws InputError "file:line: key: reason" on anything malformed or refused.
MapInput readMoorDyn(const std::filesystem::path& file);

}  // namespace whirl::io
