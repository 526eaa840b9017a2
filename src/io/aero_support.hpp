#pragma once
/// \file
/// What of an OpenFAST aerodynamic description whirl's aerodynamics can represent: AeroDyn v15 with
/// blade-element momentum theory (or no induction), quasi-steady airfoil tables (first table of each
/// file), no tower influence, in steady InflowWind wind. Anything else is refused here, explicitly,
/// rather than ignored. Each message reads
/// "file:line: key: value not supported by whirl (what it is; whirl supports only …)".
#include <string>
#include <vector>

#include "src/io/aerodyn_input.hpp"
#include "src/io/fst_input.hpp"
#include "src/io/inflowwind_input.hpp"

namespace whirl::io {

/// The .fst's aero switches: CompAero other than 2 (1 = AeroDyn14 / AeroDisk, 3 = ExtLoads, 0 = none),
/// CompInflow other than 1 (0 = still air, 2 = external inflow).
std::vector<std::string> unsupportedAeroOptions(const FstInput& fst);

/// AeroDyn options whirl does not model: a wake model other than none/BEMT (legacy WakeMod = 2 DBEMT,
/// 3 OLAF), dynamic BEMT (DBEMT_Mod > 0; −1 frozen and 0 quasi-steady are fine), unsteady airfoil
/// aerodynamics (AFAeroMod = 2, UA_Mod > 0), tower potential flow, tower shadow, tower loads, buoyancy,
/// cavitation check, aeroacoustics, nacelle drag, sector averaging, tail fin, AFTabMod != 1, and the
/// legacy "coupled" SkewMod = 3.
std::vector<std::string> unsupportedOptions(const AeroDynInput& ad);

/// InflowWind: WindType other than 1 (steady wind).
std::vector<std::string> unsupportedOptions(const InflowWindInput& wind);

/// Throws InputError listing every refusal ("; "-separated) when there is any.
void requireSupported(const AeroDynInput& ad);
void requireSupported(const InflowWindInput& wind);

}  // namespace whirl::io
