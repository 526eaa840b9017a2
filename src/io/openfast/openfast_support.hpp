#pragma once
/// \file
/// What of an OpenFAST description whirl's structural model can represent: a clamped tower base, a
/// flexible tower, a rigid nacelle on a yaw bearing, a drivetrain with a torsional spring, and three
/// ElastoDyn blades. Anything else is refused here, explicitly, rather than ignored while building the
/// model. Each message reads "file:line: key: value not supported by whirl (reason)".
#include <string>
#include <vector>

#include "src/io/openfast/elastodyn/elastodyn_input.hpp"
#include "src/io/openfast/fst_input.hpp"
#include "src/io/openfast/openfast_turbine.hpp"

namespace whirl::io {

/// Options of the `.fst` whirl cannot model: CompElast other than 1 or 2 (Simplified ElastoDyn),
/// CompSub = 2 (ExtPtfm) or unknown, MHK != 0 (buoyancy, added mass), NRotors > 1.
/// Load modules are not listed here: aero, inflow and controls are read on request; HydroDyn and MAP++
/// are read when a platform DOF is on and CompSub = 0 (requireSupported checks the combination).
std::vector<std::string> unsupportedOptions(const FstInput& fst);

/// Options of the ElastoDyn files whirl cannot model: NumBl != 3, TeetDOF with a 2-bladed rotor,
/// Furling, PitchDOF (v5), YawFrctMod != 0 (yaw friction, not smooth), a rigid tower base TwrRBHt != 0
/// (v1.00).
std::vector<std::string> unsupportedOptions(const ElastoDynInput& ed);

/// Any of PtfmSgDOF … PtfmYDOF is on.
bool hasPlatformDofs(const ElastoDynInput& ed);

/// Throws InputError listing every unsupported option ("; "-separated, first one first) when there is any.
/// Platform DOFs are refused (one clause) when nothing holds the platform: an ElastoDyn file alone,
/// or a deck with CompHydro = 0, CompMooring = 0 and no SubDyn; and with a mooring module other than
/// MAP++. With SubDyn (CompSub = 1), HydroDyn and moorings are refused (not modelled on a substructure).
void requireSupported(const ElastoDynInput& ed);
void requireSupported(const OpenFastTurbine& turbine);

}  // namespace whirl::io
