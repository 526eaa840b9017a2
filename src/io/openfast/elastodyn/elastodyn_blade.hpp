#pragma once
/// \file
/// ElastoDyn blade file (`BldFile(k)`): damping, stiffness tuners, distributed properties and the
/// polynomial mode shapes of the two flapwise and the edgewise blade modes.
#include <array>
#include <filesystem>
#include <vector>

#include "src/io/openfast/distributed_table.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

class OverrideSet;

/// Contents of an ElastoDyn blade input file, in the file's units (note StrcTwst in degrees).
struct ElastoDynBlade {
  OpenFastFile source;  ///< the parsed file (path, line of every key: use source.where(key, reason))

  int NBlInpSt = 0;                  ///< number of blade input stations (-)
  std::array<double, 2> BldFlDmp{};  ///< flap modes 1, 2: structural damping ratio (% of critical)
  double BldEdDmp = 0.0;             ///< edge mode 1 (key `BldEdDmp(1)`): structural damping ratio (% of critical)
  std::array<double, 2> FlStTunr{};  ///< flap modes 1, 2: modal stiffness tuner (-)
  double AdjBlMs = 1.0;              ///< factor on the blade mass density (-)
  double AdjFlSt = 1.0;              ///< factor on the flap stiffness (-)
  double AdjEdSt = 1.0;              ///< factor on the edge stiffness (-)

  /// Distributed properties, NBlInpSt stations. Always present and checked: BlFract (-), fraction of
  /// the blade length from root, 0 → 1 increasing; StrcTwst (deg, structural twist); BMassDen (kg/m)
  /// >= 0; FlpStff, EdgStff (N·m²) > 0. PitchAxis (-, chord fraction) is in v1–v3 files, AeroCent in
  /// older ones, neither from OpenFAST v4 on: see pitchAxis(). Other columns (GJStff, EAStff, FlpIner,
  /// EdgIner, PrecrvRef, PreswpRef, FlpcgOf, EdgcgOf, FlpEAOf, EdgEAOf …) are kept as read.
  /// Values are as written: ElastoDyn multiplies BMassDen by AdjBlMs, FlpStff by AdjFlSt and EdgStff by
  /// AdjEdSt, and the flap modal stiffnesses by FlStTunr; the model builder must do the same.
  DistributedTable distributed;

  ModeShapeCoeffs BldFl1Sh{};  ///< flap mode 1, coefficients of x^2..x^6 (-)
  ModeShapeCoeffs BldFl2Sh{};  ///< flap mode 2
  ModeShapeCoeffs BldEdgSh{};  ///< edge mode 1

  /// The PitchAxis column, else the AeroCent column of older files, else nullptr (OpenFAST v4+ files).
  const std::vector<double>* pitchAxis() const;
};

/// Reads and checks a blade file. `overrides` (may be null) are applied before reading values.
/// Throws InputError naming file, line and key (or table column) for anything missing or invalid.
ElastoDynBlade readElastoDynBlade(const std::filesystem::path& file, OverrideSet* overrides = nullptr);

}  // namespace whirl::io
