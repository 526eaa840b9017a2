#pragma once
/// \file
/// ElastoDyn tower file (`TwrFile`): damping, stiffness tuners, distributed properties and the
/// polynomial mode shapes of the two fore-aft and two side-to-side tower modes.
#include <array>
#include <filesystem>

#include "src/io/openfast/distributed_table.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

class OverrideSet;

/// Contents of an ElastoDyn tower input file, in the file's units.
struct ElastoDynTower {
  OpenFastFile source;  ///< the parsed file (path, line of every key: use source.where(key, reason))

  int NTwInpSt = 0;                  ///< number of tower input stations (-)
  std::array<double, 2> TwrFADmp{};  ///< fore-aft modes 1, 2: structural damping ratio (% of critical)
  std::array<double, 2> TwrSSDmp{};  ///< side-to-side modes 1, 2: structural damping ratio (% of critical)
  std::array<double, 2> FAStTunr{};  ///< fore-aft modes 1, 2: modal stiffness tuner (-)
  std::array<double, 2> SSStTunr{};  ///< side-to-side modes 1, 2: modal stiffness tuner (-)
  double AdjTwMa = 1.0;              ///< factor on the tower mass density (-)
  double AdjFASt = 1.0;              ///< factor on the fore-aft stiffness (-)
  double AdjSSSt = 1.0;              ///< factor on the side-to-side stiffness (-)

  /// Distributed properties, NTwInpSt stations. Always present and checked: HtFract (-), fraction of the
  /// flexible tower height, 0 → 1 increasing; TMassDen (kg/m) >= 0; TwFAStif, TwSSStif (N·m²) > 0.
  /// Other columns of older/longer layouts are kept as read (e.g. TwGJStif, TwEAStif (N·m², N),
  /// TwFAIner, TwSSIner (kg·m), TwFAcgOf, TwSScgOf (m)); ElastoDyn does not use them.
  /// Values are as written: ElastoDyn multiplies TMassDen by AdjTwMa, TwFAStif by AdjFASt and TwSSStif
  /// by AdjSSSt, and the modal stiffnesses by FAStTunr/SSStTunr; the model builder must do the same.
  DistributedTable distributed;

  ModeShapeCoeffs TwFAM1Sh{};  ///< fore-aft mode 1, coefficients of x^2..x^6 (-)
  ModeShapeCoeffs TwFAM2Sh{};  ///< fore-aft mode 2
  ModeShapeCoeffs TwSSM1Sh{};  ///< side-to-side mode 1
  ModeShapeCoeffs TwSSM2Sh{};  ///< side-to-side mode 2
};

/// Reads and checks a tower file. `overrides` (may be null) are applied before reading values.
/// Throws InputError naming file, line and key (or table column) for anything missing or invalid.
ElastoDynTower readElastoDynTower(const std::filesystem::path& file, OverrideSet* overrides = nullptr);

}  // namespace whirl::io
