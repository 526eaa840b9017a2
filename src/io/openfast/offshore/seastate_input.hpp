#pragma once
/// \file
/// SeaState input file (OpenFAST v4+, `SeaStFile` of the `.fst` with `CompSeaSt = 1`): the water
/// properties that left HydroDyn in OpenFAST v4 (modules/seastate/src/SeaState_Input.f90,
/// SeaSt_ParseInput). whirl linearizes about still water, so of the waves and currents it only notes
/// that they are ignored.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

class OverrideSet;

/// What whirl reads of a SeaState file.
struct SeaStateInput {
  OpenFastFile source;             ///< the parsed file (path, line of every key)
  std::optional<double> WtrDens;   ///< water density (kg/m³), > 0; nullopt for `default` (the .fst's)
  std::optional<double> WtrDpth;   ///< water depth (m), > 0; nullopt for `default` (the .fst's)
  std::optional<double> MSL2SWL;   ///< offset of the still water level from mean sea level (m); nullopt for `default`
  std::vector<std::string> notes;  ///< "file:line: key: …" for waves and currents, which whirl ignores
};

/// Reads a SeaState file: checks its keys (seaStateLayout: a key twice or a key no SeaState version has
/// is refused), reads WtrDens, WtrDpth and MSL2SWL (`default`: OpenFAST takes the `.fst`'s, SeaSt_ParseInput's
/// defWtrDens, defWtrDpth, defMSL2SWL), and notes WaveMod ≠ 0 and CurrMod ≠ 0. Throws InputError
/// "file:line: key: reason".
SeaStateInput readSeaState(const std::filesystem::path& file, OverrideSet* overrides = nullptr);

}  // namespace whirl::io
