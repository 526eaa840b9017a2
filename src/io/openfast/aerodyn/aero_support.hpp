#pragma once
/// \file
/// What of an OpenFAST aerodynamic description whirl's aerodynamics can represent: AeroDyn v15 with
/// blade-element momentum theory (or no induction), quasi-steady airfoil tables (first table of each
/// file), no tower influence, in steady InflowWind wind. The time-domain options whose steady state is
/// that model (dynamic BEMT, unsteady airfoils) and the tower's influence are linearized without their
/// own dynamics and said so (steadySubstitutes), as OpenFAST's own linearization requires them off;
/// anything else is refused here, explicitly, rather than ignored. Each refusal reads
/// "file:line: key: value not supported by whirl (what it is; whirl supports only …)".
#include <string>
#include <vector>

#include "src/io/openfast/aerodyn/aerodyn_input.hpp"
#include "src/io/openfast/aerodyn/inflowwind_input.hpp"
#include "src/io/openfast/fst_input.hpp"

namespace whirl::io {

/// The aerodynamics modules whirl reads, as refusals name them.
inline constexpr const char* kAeroModules = "CompAero = 1 with an AeroDyn v14 file, or 2 (AeroDyn v15)";

/// The .fst's aero switches: CompAero other than 1 and 2 (3 = ExtLoads, 0 = none), CompInflow other than
/// 1 (0 = still air, 2 = external inflow). CompAero = 1 is AeroDyn v14 up to OpenFAST v3 and AeroDisk
/// from v4: readAeroDeck tells them apart by the file.
std::vector<std::string> unsupportedAeroOptions(const FstInput& fst);

/// AeroDyn options whirl does not model: the OLAF free-vortex wake (Wake_Mod = 3), buoyancy, cavitation
/// check, aeroacoustics, nacelle drag, sector averaging, tail fin, AFTabMod != 1, and the legacy
/// "coupled" SkewMod = 3.
std::vector<std::string> unsupportedOptions(const AeroDynInput& ad);

/// AeroDyn options of a time simulation that whirl replaces by their steady counterpart, one note
/// "file:line: key: value: what whirl does instead" each: dynamic BEMT (legacy WakeMod = 2,
/// DBEMT_Mod > 0) by the quasi-steady BEMT, unsteady airfoil aerodynamics (AFAeroMod = 2, UA_Mod > 0)
/// by the static tables, tower potential flow, tower shadow and tower drag left out. OpenFAST's
/// linearization refuses the same options (AeroDyn v15's input template: "WakeMod cannot be 2 or 3
/// when linearizing"); its Campbell scripts switch them off for the linearization runs.
std::vector<std::string> steadySubstitutes(const AeroDynInput& ad);

/// True for steadySubstitutes' note on the unsteady airfoil aerodynamics (AFAeroMod = 2, UA_Mod > 0): a
/// caller that puts the model's states into the linear model (`--unsteady-aero` of linearize and
/// campbell) drops it, since there the note's "not in the linear model" would be wrong.
bool isUnsteadyAirfoilNote(const std::string& note);
/// True for steadySubstitutes' note on dynamic BEMT (DBEMT_Mod > 0): a caller whose linear model has the
/// deck's dynamic-inflow states (DBEMT_Mod 3) drops it.
bool isDynamicInflowNote(const std::string& note);

/// InflowWind: an unknown WindType (1 to 7 are OpenFAST's).
std::vector<std::string> unsupportedOptions(const InflowWindInput& wind);

/// InflowWind: a wind file (WindType 2 to 7) is replaced by the steady wind of the file's steady-wind
/// section (HWindSpeed, RefHt, PLExp), as OpenFAST's Campbell scripts do for their linearization runs
/// (they write WindType = 1 and the operating point's HWindSpeed); one note saying so and which speed.
std::vector<std::string> steadySubstitutes(const InflowWindInput& wind);

/// Throws InputError listing every refusal ("; "-separated) when there is any.
void requireSupported(const AeroDynInput& ad);
void requireSupported(const InflowWindInput& wind);

}  // namespace whirl::io
