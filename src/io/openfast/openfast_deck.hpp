#pragma once
/// \file
/// An OpenFAST deck read in one pass: every file a run needs, each opened once, in one parsed value
/// that the turbine builder (src/turbine) turns into a model without reading anything itself.
#include <filesystem>
#include <optional>

#include "src/io/openfast/aerodyn/aero_deck.hpp"
#include "src/io/openfast/openfast_turbine.hpp"
#include "src/io/openfast/servodyn/servodyn_input.hpp"
#include "src/model/rosco_controller.hpp"

namespace whirl::io {

class OverrideSet;

/// Everything of a deck whirl reads.
struct OpenFastDeck {
  OpenFastTurbine turbine;                    ///< the `.fst` and the structural files (readOpenFastTurbine)
  std::optional<ServoDynInput> servodyn;      ///< CompServo = 1, read when the yaw spring or aerodynamics need it
  std::optional<AeroDeckInput> aero;          ///< CompAero ≠ 0: AeroDyn, its blades and airfoils, InflowWind
  std::optional<RoscoController> controller;  ///< with aerodynamics: ServoDyn's ROSCO DISCON.IN, if it names one
};

struct OpenFastDeckOptions {
  /// Read ServoDyn for its yaw spring when the yaw DOF is on (ElastoDynModelOptions::yaw_spring_from_servodyn).
  bool servodyn_for_yaw = true;
};

/// Reads a `.fst` and the files it names, or (any other extension) an ElastoDyn main file alone: the
/// structure (readOpenFastTurbine) with a floating platform's WAMIT files (OpenFastTurbine::wamit,
/// ::radiation); ServoDyn when CompServo = 1 and the yaw DOF (with
/// `servodyn_for_yaw`) or the aerodynamics need it; with CompAero ≠ 0 AeroDyn, InflowWind and the
/// controller of ServoDyn's DISCON.IN. `overrides` (may be null) apply to every file; call
/// overrides->requireAllUsed() afterwards. Throws InputError naming file, line and key.
OpenFastDeck readOpenFastDeck(const std::filesystem::path& fst_or_elastodyn, OverrideSet* overrides = nullptr,
                              const OpenFastDeckOptions& opt = {});

}  // namespace whirl::io
