#pragma once
/// \file
/// AeroDyn v14 main input file (FAST v8 `CompAero = 1`, the `.ipt` files of the FAST 8 certification
/// tests), in the file's units (lengths m, angles deg).
///
/// The layout (AeroDyn v14.04, Laino and Hansen 2002; Jonkman 2013): two header lines, then
/// `StallMod` {BEDDOES, STEADY}, `UseCm` {USE_CM, NO_CM}, `InfModel` {DYNIN, EQUIL}, `IndModel` {NONE,
/// WAKE, SWIRL}, `AToler`, `TLModel` {PRANDtl, GTECH, NONE}, `HLModel` {PRANdtl, NONE}, `TwrShad`,
/// `ShadHWid`, `T_Shad_Refpt`, `AirDens`, `KinVisc`, `DTAero`, `NumFoil`, `FoilNm` (NumFoil names, the
/// first on the key's line, the others alone on the lines after it), `BldNodes`, then a header row
/// `RNodes AeroTwst DRNodes Chord NFoil PrnElm` and BldNodes element rows (no unit row; the last word of
/// a row is PRINT or NOPRINT), then — read by AeroDyn only when an airfoil file has several tables — the
/// multiple-table option {USER, RENUM, SINGLE} (AeroDyn v14's AD14_GetInput: at the end of the file it
/// uses the first table of each file). Switch values are matched case-insensitively, quoted or not. One
/// element table serves every blade. Older files may open with `SysUnits` (only SI is accepted).
/// `InfModel` also takes EQUILDA, EQUILDT and EQUILDB: equilibrium inflow with drag in the axial, the
/// tangential or both inductions (plain EQUIL: none).
///
/// Elements, unlike AeroDyn v15's nodes, are strips: `RNodes` is the radius of the element centre
/// measured from the rotor centre (hub radius included) along the blade, `DRNodes` its width, and the
/// loads are the strip's centre values times its width (midpoint rule).
#include <filesystem>
#include <string>
#include <vector>

#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

class OverrideSet;

/// An AeroDyn v14 main file. Element vectors all have BldNodes entries.
struct AeroDyn14Input {
  OpenFastFile source;  ///< the keys up to BldNodes (path, line of every key: source.where(key, reason))

  std::string StallMod;  ///< "BEDDOES" or "STEADY" (upper case)
  bool UseCm = false;    ///< UseCm = USE_CM: the airfoil tables carry Cm columns, used
  std::string InfModel;  ///< "DYNIN", "EQUIL", "EQUILDA", "EQUILDT" or "EQUILDB"
  std::string IndModel;  ///< "NONE", "WAKE" or "SWIRL"
  double AToler = 0.0;   ///< induction-factor tolerance (-), > 0
  std::string TLModel;   ///< "PRANDTL", "GTECH" or "NONE"
  std::string HLModel;   ///< "PRANDTL" or "NONE"
  double TwrShad = 0.0;  ///< tower-shadow velocity deficit (-), 0 = no shadow
  double AirDens = 0.0;  ///< air density (kg/m³), > 0
  double KinVisc = 0.0;  ///< kinematic viscosity (m²/s), > 0

  std::vector<std::filesystem::path> FoilNm;  ///< airfoil files (resolved against this file's folder)
  std::vector<int> FoilNm_lines;              ///< file line of each name

  std::vector<double> RNodes;    ///< element centre from the rotor centre (m), increasing
  std::vector<double> AeroTwst;  ///< aerodynamic twist (deg), positive to feather
  std::vector<double> DRNodes;   ///< element width (m), > 0
  std::vector<double> Chord;     ///< chord (m), > 0
  std::vector<int> NFoil;        ///< airfoil of each element, 1-based index into FoilNm
  std::vector<int> row_lines;    ///< file line of each element
  /// The first word after the element table, upper case ("USER", "RENUM", "SINGLE" or anything else;
  /// "" at the end of the file), and its line; whether it matters depends on the airfoil files.
  std::string MultiTab;
  int MultiTab_line = 0;
};

/// Reads an AeroDyn v14 main file. Checks: every key of the layout once and in it nothing else (as
/// OpenFAST reads it by position), the switch values, AToler > 0, AirDens > 0, KinVisc > 0, NumFoil >= 1
/// names, BldNodes >= 1 rows of 5 numbers and PRINT/NOPRINT (fewer = truncated), finite numbers, RNodes
/// increasing, DRNodes > 0, Chord > 0, NFoil a whole number from 1 to NumFoil. The airfoil files are not
/// opened. Throws InputError "file:line: key: reason".
AeroDyn14Input readAeroDyn14(const std::filesystem::path& file, OverrideSet* overrides = nullptr);

}  // namespace whirl::io
