#pragma once
/// \file
/// OpenFAST main input file (`.fst`): only what whirl needs to build a model — gravity, the
/// environment of the aerodynamics, the module switches and the names of the ElastoDyn, ServoDyn,
/// InflowWind and AeroDyn files.
#include <filesystem>
#include <optional>

#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

class OverrideSet;

/// Contents of a `.fst` file used by whirl. File names are resolved against the `.fst` folder; whether
/// they exist is checked only when a file is read (see openfast_turbine.hpp).
struct FstInput {
  OpenFastFile source;  ///< the parsed file (path, line of every key: source.where(key, reason))

  std::optional<double> Gravity;  ///< gravitational acceleration (m/s²); absent before OpenFAST v3 (then in ElastoDyn)
  int CompElast = 1;           ///< structural model {1 ElastoDyn, 2 ElastoDyn + BeamDyn blades, 3 Simplified ElastoDyn}
  int CompInflow = 0;          ///< inflow {0 still air, 1 InflowWind, 2 external}
  int CompAero = 0;            ///< aerodynamics {0 none, 1 AeroDyn14 / AeroDisk (v4+), 2 AeroDyn, 3 ExtLoads}
  int CompServo = 0;           ///< controls {0 none, 1 ServoDyn}
  int CompSeaSt = 0;           ///< sea state {0 none, 1 SeaState}; OpenFAST v4+ (HydroDyn needs it there)
  int CompHydro = 0;           ///< hydrodynamics {0 none, 1 HydroDyn}
  int CompSub = 0;             ///< substructure {0 none, 1 SubDyn, 2 external platform}
  int CompMooring = 0;         ///< mooring {0 none, 1 MAP++, 2 FEAMooring, 3 MoorDyn, 4 OrcaFlex}
  std::optional<int> MHK;      ///< marine turbine {0 no, 1 fixed, 2 floating}; OpenFAST v3.1+
  std::optional<int> NRotors;  ///< number of rotors; OpenFAST v5+

  // Environmental conditions, OpenFAST v3+ (before, each module had its own); what AeroDyn's "default" means.
  std::optional<double> AirDens;   ///< air density (kg/m³)
  std::optional<double> KinVisc;   ///< kinematic viscosity of the working fluid (m²/s)
  std::optional<double> SpdSound;  ///< speed of sound in the working fluid (m/s)
  std::optional<double> Patm;      ///< atmospheric pressure (Pa)
  std::optional<double> Pvap;      ///< vapour pressure of the working fluid (Pa)

  std::filesystem::path EDFile;                    ///< ElastoDyn main file
  std::optional<std::filesystem::path> ServoFile;  ///< ServoDyn file (key `SrvDFile` in FAST 8.0x)
  std::optional<std::filesystem::path> AeroFile;   ///< AeroDyn file (key `ADFile` in FAST 8.0x); read by readAeroDeck
  std::optional<std::filesystem::path>
      InflowFile;  ///< InflowWind file (key `InflowFile` in every layout); read by readAeroDeck
  std::optional<std::filesystem::path>
      SeaStFile;  ///< SeaState file (OpenFAST v4+); read with the HydroDyn file when CompSeaSt = 1
  std::optional<std::filesystem::path> HydroFile;  ///< HydroDyn file; read with platform DOFs and CompHydro = 1
  std::optional<std::filesystem::path>
      MooringFile;                ///< mooring file; read (MAP++) with platform DOFs and CompMooring = 1
  std::optional<double> WtrDens;  ///< water density (kg/m³), OpenFAST v3.5+ (before, in HydroDyn)
  std::optional<double> WtrDpth;  ///< water depth (m), OpenFAST v3.5+ (before, in HydroDyn)
};

/// Reads a `.fst` file. Switches absent from a layout read as 0 (CompElast as 1: ElastoDyn was the only
/// structural module); FAST 8.0x True/False switches read as 1/0. `overrides` may be null.
/// Throws InputError naming file, line and key.
FstInput readFst(const std::filesystem::path& file, OverrideSet* overrides = nullptr);

}  // namespace whirl::io
