#pragma once
/// \file
/// Reading a turbine from its OpenFAST `.fst` file: the `.fst`, then the structural files it names
/// (ElastoDyn, BeamDyn, SubDyn, HydroDyn, the mooring). The whole deck, with
/// ServoDyn, AeroDyn and the controller, is readOpenFastDeck (openfast_deck.hpp); ServoDyn is read only
/// when something needs it, so a case whose ServoDyn file is absent still reads as long as nothing does.
#include <filesystem>
#include <optional>

#include "src/io/openfast/beamdyn/beamdyn_input.hpp"
#include "src/io/openfast/elastodyn/elastodyn_input.hpp"
#include "src/io/openfast/fst_input.hpp"
#include "src/io/openfast/offshore/hydrodyn_input.hpp"
#include "src/io/openfast/offshore/map_input.hpp"
#include "src/io/openfast/offshore/seastate_input.hpp"
#include "src/io/openfast/offshore/subdyn_input.hpp"
#include "src/io/openfast/offshore/wamit_input.hpp"
#include "src/io/openfast/offshore/wamit_state_space.hpp"
#include "src/io/openfast/servodyn/servodyn_input.hpp"

namespace whirl::io {

class OverrideSet;

/// The structural inputs of a turbine as OpenFAST describes them.
struct OpenFastTurbine {
  FstInput fst;
  ElastoDynInput elastodyn;
  std::optional<HydroDynInput> hydrodyn;  ///< with CompHydro = 1 and a platform DOF on or SubDyn
  std::optional<SeaStateInput> seastate;  ///< with the HydroDyn file when CompSeaSt = 1 (OpenFAST v4+)
  std::optional<MapInput> mooring;        ///< with a platform DOF on: MAP++ (CompMooring = 1) or MoorDyn (3)
  std::optional<SubDynInput> subdyn;      ///< with CompSub = 1 (then a mooring is not read)
  /// A floating platform's WAMIT coefficients (HydroDyn PotMod = 1) and its state-space radiation
  /// (RdtnMod = 2, the `.ss` file): read by readOpenFastDeck (openfast_deck.hpp), not by readOpenFastTurbine.
  std::optional<WamitCoefficients> wamit;
  std::optional<RadiationStateSpace> radiation;
  /// With CompElast = 2: the BeamDyn file of each blade (BDBldFile(k), k = 1 … NumBl).
  std::vector<BeamDynInput> beamdyn;
};

/// Reads `fst` and the ElastoDyn files it names, the BeamDyn files with CompElast = 2, its SubDyn file (CompSub = 1),
/// and otherwise, with a platform DOF on, its HydroDyn (CompHydro = 1) and MAP++ (CompMooring = 1) or MoorDyn (3)
/// files. `overrides` (may be null) apply to every file read; call overrides->requireAllUsed() once all the files the
/// run needs are read. Throws InputError naming file, line and key, e.g. "a.fst:33: EDFile: file not found: …".
OpenFastTurbine readOpenFastTurbine(const std::filesystem::path& fst, OverrideSet* overrides = nullptr);

/// The ServoDyn file when CompServo = 1, nullopt when ServoDyn is off (no yaw spring). Throws
/// InputError("a.fst:39: ServoFile: file not found: …") when ServoDyn is on and its file is missing.
std::optional<ServoDynInput> readServoDynIfEnabled(const FstInput& fst, OverrideSet* overrides = nullptr);

/// Gravity (m/s²): from the `.fst` when it has it (OpenFAST v3+), else from ElastoDyn (older layouts).
/// Throws InputError when neither file gives it.
double gravity(const OpenFastTurbine& turbine);

}  // namespace whirl::io
