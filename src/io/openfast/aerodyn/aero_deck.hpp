#pragma once
/// \file
/// All aerodynamic inputs of an OpenFAST deck in one call: the AeroDyn v15 main file the .fst names, its
/// blade files and airfoil files, and the InflowWind file, checked against what whirl can model.
#include <vector>

#include "src/io/openfast/aerodyn/aerodyn_blade_input.hpp"
#include "src/io/openfast/aerodyn/aerodyn_input.hpp"
#include "src/io/openfast/aerodyn/airfoil_input.hpp"
#include "src/io/openfast/aerodyn/inflowwind_input.hpp"
#include "src/io/openfast/fst_input.hpp"

namespace whirl::io {

class OverrideSet;

/// The aerodynamic inputs of a deck, as read (file units: angles deg, Re in millions).
struct AeroDeckInput {
  AeroDynInput aerodyn;                   ///< AeroDyn main file (environment "default"s resolved from the .fst)
  std::vector<AeroDynBladeInput> blades;  ///< blades[k − 1] from ADBlFile(k), as many as the file names (3)
  std::vector<AirfoilInput> airfoils;     ///< airfoils[i] from AFNames(i + 1); a station's BlAFID − 1 indexes it
  /// How the airfoils' tables are interpolated on the Reynolds number: AFTabMod = 2 (log Re), AeroDyn
  /// v14 MultiTab = RENUM (Re), else the first table only.
  aero::ReynoldsInterp reynolds = aero::ReynoldsInterp::None;
  InflowWindInput inflow;  ///< InflowWind file
  /// Time-domain options replaced by their steady counterpart (aero_support.hpp steadySubstitutes),
  /// one "file:line: key: value: what whirl does instead" each.
  std::vector<std::string> notes;
};

/// Reads the AeroDyn main file (`AeroFile`), every blade file and airfoil file it names, and the
/// InflowWind file (`InflowFile`) of `fst`; `overrides` (may be null) apply to the AeroDyn main, blade
/// and InflowWind files (not to airfoil files, whose keys repeat from file to file and table to table).
///
/// Refuses, "file:line: key: value not supported by whirl (…; whirl supports only …)", CompAero other
/// than 2 (1 AeroDyn14/AeroDisk, 3 ExtLoads, 0 none), CompInflow other than 1, and the AeroDyn and
/// InflowWind options of aero_support.hpp, before reading blade and airfoil files; notes the options it
/// replaces by their steady counterpart (`notes`). A missing file is
/// named with the line that names it ("AeroDyn.dat:52: AFNames(3): file not found: …"); a station's
/// BlAFID beyond NumAFfiles is reported at its blade-file line. Other errors as the per-file readers.
AeroDeckInput readAeroDeck(const FstInput& fst, OverrideSet* overrides = nullptr);

}  // namespace whirl::io
